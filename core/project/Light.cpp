#include "core/project/Light.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/support/Failure.h"
#include "core/support/Finite.h"

namespace facet {

namespace {
constexpr std::pair<LightType, const char*> kTypes[]
    = {{LightType::Directional, "directional"}, {LightType::Point, "point"}, {LightType::Spot, "spot"}};

std::string number(double value)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", value);
    return buffer;
}

} // namespace

const char* toString(LightType type)
{
    for (const auto& [value, text] : kTypes)
        if (value == type)
            return text;
    return "";
}

std::optional<LightType> lightTypeFromString(std::string_view name)
{
    for (const auto& [value, text] : kTypes)
        if (name == text)
            return value;
    return std::nullopt;
}

const char* intensityUnit(LightType type)
{
    return type == LightType::Directional ? "lx" : "cd";
}

glm::dvec3 colorFromKelvin(double kelvin)
{
    const double t = std::isfinite(kelvin) ? std::clamp(kelvin, kMinKelvin, kMaxKelvin) : 6504.0;
    const double t2 = t * t;
    const double t3 = t2 * t;
    // Kim et al. 2002, Planckian locus chromaticity x_c(T) then y_c(x_c), piecewise cubic.
    const double x = t <= 4000.0 ? -0.2661239e9 / t3 - 0.2343589e6 / t2 + 0.8776956e3 / t + 0.179910
                                 : -3.0258469e9 / t3 + 2.1070379e6 / t2 + 0.2226347e3 / t + 0.240390;
    const double x2 = x * x;
    const double x3 = x2 * x;
    double y;
    if (t <= 2222.0)
        y = -1.1063814 * x3 - 1.34811020 * x2 + 2.18555832 * x - 0.20219683;
    else if (t <= 4000.0)
        y = -0.9549476 * x3 - 1.37418593 * x2 + 2.09137015 * x - 0.16748867;
    else
        y = 3.0817580 * x3 - 5.87338670 * x2 + 3.75112997 * x - 0.37001483;

    // xyY (Y = 1) -> XYZ -> linear Rec.709 (IEC 61966-2-1 matrix, D65 white).
    const double X = x / y;
    const double Y = 1.0;
    const double Z = (1.0 - x - y) / y;
    glm::dvec3 rgb(3.2404542 * X - 1.5371385 * Y - 0.4985314 * Z,
        -0.9692660 * X + 1.8760108 * Y + 0.0415560 * Z, 0.0556434 * X - 0.2040259 * Y + 1.0572252 * Z);
    rgb = glm::max(rgb, glm::dvec3(0.0));
    const double peak = std::max({rgb.x, rgb.y, rgb.z});
    return peak > 0.0 ? rgb / peak : glm::dvec3(1.0);
}

glm::dvec3 Light::linearColor() const
{
    return useTemperature ? colorFromKelvin(kelvin) : color;
}

bool Light::validate(std::string* problem) const
{
    if (!std::isfinite(intensity) || intensity < 0.0)
        return fail("intensity: " + number(intensity) + " must be a finite number >= 0", problem);
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(color[i]) || color[i] < 0.0 || color[i] > 1.0)
            return fail("color: " + number(color[i]) + " is outside [0, 1] (brightness belongs in intensity)",
                problem);
    if (!std::isfinite(kelvin) || kelvin < kMinKelvin || kelvin > kMaxKelvin)
        return fail("kelvin: " + number(kelvin) + " is outside [" + number(kMinKelvin) + ", "
                + number(kMaxKelvin) + "]",
            problem);
    if (!std::isfinite(range) || range < 0.0)
        return fail("range: " + number(range) + " must be >= 0 (0 means infinite)", problem);
    // KHR_lights_punctual: 0 <= innerConeAngle < outerConeAngle <= pi/2.
    if (!std::isfinite(innerConeAngle) || innerConeAngle < 0.0)
        return fail("innerConeAngle: " + number(innerConeAngle) + " must be >= 0 (radians)", problem);
    if (!std::isfinite(outerConeAngle) || outerConeAngle > std::numbers::pi / 2.0)
        return fail("outerConeAngle: " + number(outerConeAngle) + " must be <= pi/2 (radians)", problem);
    if (!(innerConeAngle < outerConeAngle))
        return fail("innerConeAngle: " + number(innerConeAngle) + " must be less than outerConeAngle ("
                + number(outerConeAngle) + ")",
            problem);
    if (!isFinite(position))
        return fail("position: must be finite", problem);
    if (!isFinite(direction) || glm::length(direction) <= 1e-12)
        return fail("direction: must be a finite, non-zero vector", problem);
    return true;
}

Light Light::defaultDirectional()
{
    Light light;
    light.name = "Key light";
    light.type = LightType::Directional;
    light.intensity = 3.0;
    light.direction = glm::normalize(glm::dvec3(1.0, -1.0, -1.0)); // from the upper left front
    return light;
}

} // namespace facet
