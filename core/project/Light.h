#pragma once
// A punctual light, as KHR_lights_punctual defines it (glTF 2.0 extension):
//   directional  intensity in lux (lm/m^2), illuminance on a surface facing the light
//   point, spot  intensity in candela (lm/sr), luminous intensity; falloff 1/d^2
// Facet renders in linear Rec.709 radiance and takes these photometric numbers as they are
// (1 lux of white light on a white Lambertian surface gives radiance 1/pi), like the glTF Sample
// Viewer does; exposure brings a real-world scene's values into range.
// Unlike glTF, the light is not attached to a node: position and direction are in world space
// (+Y up, right-handed). docs/project-format.md lists the fields with their units and defaults.

#include <numbers>
#include <optional>
#include <string>
#include <string_view>

#include <glm/vec3.hpp>

namespace facet {

enum class LightType { Directional, Point, Spot };
const char* toString(LightType type); // "directional", "point", "spot" (KHR_lights_punctual's names)
std::optional<LightType> lightTypeFromString(std::string_view name);
// The unit of Light::intensity for `type`: "lx" or "cd".
const char* intensityUnit(LightType type);

// Linear Rec.709 RGB of a blackbody radiator at `kelvin`, normalised so its largest component is
// 1 (so the colour carries no intensity; intensity stays the light's). Chromaticity from the
// cubic-spline fit of the Planckian locus by Kim et al., "Design of Advanced Color Temperature
// Control System for HDTV Applications", J. Korean Physical Society 41(6), 2002 (valid 1667 K to
// 25000 K; kelvin is clamped to that range), then CIE XYZ -> linear Rec.709 with the sRGB (IEC
// 61966-2-1) matrix; negative components (outside the Rec.709 gamut, below ~1900 K) clip to 0.
// Note that 6504 K on the Planckian locus sits slightly off D65 (which lies on the daylight
// locus), so it is white to within a few percent, a touch magenta, not exactly (1, 1, 1).
glm::dvec3 colorFromKelvin(double kelvin);
inline constexpr double kMinKelvin = 1667.0;
inline constexpr double kMaxKelvin = 25000.0;

// The most lights a project holds: the surface shader's light loop has a fixed size, and the
// ground truth must see exactly the lights the renderer draws (Project::validate refuses more).
inline constexpr int kMaxLights = 8;

struct Light {
    std::string name = "Light";
    LightType type = LightType::Directional;
    bool enabled = true;
    // Linear Rec.709 colour in [0, 1] (KHR_lights_punctual "color"), used unless useTemperature.
    glm::dvec3 color {1.0};
    bool useTemperature = false;
    double kelvin = 6504.0; // colour temperature, used when useTemperature; [kMinKelvin, kMaxKelvin]
    // Directional: lux; point and spot: candela (intensityUnit()). >= 0. KHR's default is 1.
    double intensity = 1.0;
    // Distance in metres beyond which a point or spot light contributes nothing; 0 means infinite
    // (KHR_lights_punctual: range undefined = infinite). Ignored by directional lights.
    double range = 0.0;
    // Spot cone half-angles in RADIANS from the spot direction (KHR_lights_punctual's unit and
    // defaults: inner 0, outer pi/4), 0 <= inner < outer <= pi/2. Intensity falls off smoothly
    // between them (KHR's reference implementation).
    double innerConeAngle = 0.0;
    double outerConeAngle = std::numbers::pi / 4.0;
    glm::dvec3 position {0.0, 0.0, 0.0}; // point and spot, world space
    // The direction light travels (from the light into the scene), world space, for directional
    // and spot lights; need not be unit length (normalised when used), must not be zero. The
    // default is KHR's -Z (a light on an untransformed node).
    glm::dvec3 direction {0.0, 0.0, -1.0};

    // color, or colorFromKelvin(kelvin) when useTemperature.
    glm::dvec3 linearColor() const;

    // Checks the ranges above. On failure returns false and sets *problem to "<field>: <problem>",
    // the field named as the project file names it (the caller prefixes "lights[i].").
    bool validate(std::string* problem) const;

    // A key light from the upper left front, 3 lux: on a white diffuse surface about as bright as
    // the built-in studio environment (radiance 3/pi), so adding it neither vanishes nor blinds.
    static Light defaultDirectional();

    bool operator==(const Light&) const = default;
};

} // namespace facet
