#pragma once
// What a punctual light (core/project/Light.h, KHR_lights_punctual) delivers at a point: the
// ground truths' twin of lights_punctual.glsl (core/shading/GroundTruth, core/truth/SceneTruth).

#include <glm/vec3.hpp>

namespace facet {

struct Light;

struct LightIrradiance {
    glm::dvec3 toLight {0.0, 1.0, 0.0}; // unit direction from the point towards the light
    // On a surface facing the light: colour x lux for a directional light; colour x cd x the
    // extension's range attenuation (x its cone falloff for a spot) for point and spot lights.
    glm::dvec3 irradiance {0.0};
    double distance = 0.0; // to the light; infinite for a directional one (how far a shadow ray goes)
};

// False when the light delivers nothing at `position`: disabled, beyond its range, outside its
// cone, or at the light's own position.
bool lightIrradiance(const Light& light, const glm::dvec3& position, LightIrradiance* out);

} // namespace facet
