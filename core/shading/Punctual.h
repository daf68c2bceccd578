#pragma once
// Falloff of punctual lights (KHR_lights_punctual), with the names of the glTF Sample Viewer's
// punctual.glsl that resources/shaders/lights_punctual.glsl mirrors.

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace facet::shading {

// Smooth window to zero at `range` on top of inverse-square falloff, as KHR_lights_punctual
// recommends: clamp(1 - (d / range)^4, 0, 1)^2 / d^2. range <= 0 means no range (1 / d^2).
inline double getRangeAttenuation(double range, double distance)
{
    const double d2 = std::max(distance * distance, 1e-12);
    if (range <= 0.0)
        return 1.0 / d2;
    const double ratio = distance / range;
    const double window = std::clamp(1.0 - ratio * ratio * ratio * ratio, 0.0, 1.0);
    return window * window / d2;
}

// KHR_lights_punctual's spot cone: a smoothstep-like (squared linear) ramp between the outer and
// inner cone cosines. `pointToLight` is unit, from the surface towards the light; `spotDirection`
// is unit, the direction the light travels.
inline double getSpotAttenuation(
    const glm::dvec3& pointToLight, const glm::dvec3& spotDirection, double outerConeCos, double innerConeCos)
{
    const double actualCos = glm::dot(spotDirection, -pointToLight);
    if (actualCos <= outerConeCos)
        return 0.0;
    if (actualCos >= innerConeCos)
        return 1.0;
    const double t = (actualCos - outerConeCos) / std::max(innerConeCos - outerConeCos, 1e-12);
    return t * t;
}

} // namespace facet::shading
