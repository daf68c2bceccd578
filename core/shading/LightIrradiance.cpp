#include "core/shading/LightIrradiance.h"

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "core/project/Light.h"
#include "core/shading/Punctual.h"

namespace facet {

bool lightIrradiance(const Light& light, const glm::dvec3& position, LightIrradiance* out)
{
    if (!light.enabled)
        return false;
    const glm::dvec3 color = light.linearColor();
    if (light.type == LightType::Directional) {
        out->toLight = -glm::normalize(light.direction);
        out->irradiance = color * light.intensity;
        out->distance = std::numeric_limits<double>::infinity();
        return true;
    }
    // KHR_lights_punctual: point and spot lights in candela (lm/sr), intensity / distance^2 of
    // irradiance, through the extension's smooth range window.
    const glm::dvec3 offset = light.position - position;
    const double distance = glm::length(offset);
    if (distance <= 0.0)
        return false;
    out->toLight = offset / distance;
    out->distance = distance;
    double attenuation = shading::getRangeAttenuation(light.range, distance);
    if (light.type == LightType::Spot)
        attenuation *= shading::getSpotAttenuation(out->toLight, glm::normalize(light.direction),
            std::cos(light.outerConeAngle), std::cos(light.innerConeAngle));
    out->irradiance = color * (light.intensity * attenuation);
    return attenuation > 0.0;
}

} // namespace facet
