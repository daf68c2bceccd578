#include "core/image/ToneMap.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

namespace facet::tonemap {

namespace {

// Row-major 3x3 product: out_i = sum_j m[i][j] v_j (the matrices below are written as the
// sources print them, rows first).
glm::dvec3 mulRows(const double (&m)[3][3], const glm::dvec3& v)
{
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
        m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

glm::dvec3 clamp01(const glm::dvec3& v)
{
    return glm::clamp(v, glm::dvec3(0.0), glm::dvec3(1.0));
}

glm::dvec3 nonNegative(const glm::dvec3& v)
{
    return glm::max(v, glm::dvec3(0.0));
}

} // namespace

glm::dvec3 toneMapNone(const glm::dvec3& color)
{
    return clamp01(color);
}

glm::dvec3 toneMapReinhard(const glm::dvec3& color)
{
    const glm::dvec3 c = nonNegative(color);
    return c / (glm::dvec3(1.0) + c);
}

glm::dvec3 toneMapExposure(const glm::dvec3& color)
{
    const glm::dvec3 c = nonNegative(color);
    return glm::dvec3(1.0) - glm::exp(-c);
}

glm::dvec3 toneMapAcesHill(const glm::dvec3& color)
{
    // sRGB -> (RRT_SAT * ACES AP1), then back, from BakingLab's ACES.hlsl (Hill 2016).
    static constexpr double kInput[3][3]
        = {{0.59719, 0.35458, 0.04823}, {0.07600, 0.90834, 0.01566}, {0.02840, 0.13383, 0.83777}};
    static constexpr double kOutput[3][3]
        = {{1.60475, -0.53108, -0.07367}, {-0.10208, 1.10813, -0.00605}, {-0.00327, -0.07276, 1.07602}};
    glm::dvec3 v = mulRows(kInput, nonNegative(color));
    // RRTAndODTFit: the rational fit of the RRT + ODT curve.
    const glm::dvec3 a = v * (v + 0.0245786) - 0.000090537;
    const glm::dvec3 b = v * (0.983729 * v + 0.4329510) + 0.238081;
    v = a / b;
    return clamp01(mulRows(kOutput, v));
}

glm::dvec3 toneMapKhronosPbrNeutral(const glm::dvec3& color)
{
    // Khronos PBR Neutral specification, reference implementation (constants named as there).
    constexpr double startCompression = 0.8 - 0.04;
    constexpr double desaturation = 0.15;
    glm::dvec3 c = nonNegative(color);
    const double x = std::min(c.r, std::min(c.g, c.b));
    const double offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
    c -= offset;
    const double peak = std::max(c.r, std::max(c.g, c.b));
    if (peak < startCompression)
        return clamp01(c);
    constexpr double d = 1.0 - startCompression;
    const double newPeak = 1.0 - d * d / (peak + d - startCompression);
    c *= newPeak / peak;
    const double g = 1.0 - 1.0 / (desaturation * (peak - newPeak) + 1.0);
    return clamp01(glm::mix(c, glm::dvec3(newPeak), g));
}

glm::dvec3 toneMapAgx(const glm::dvec3& color)
{
    // Wrensch 2023, "Minimal AgX Implementation": the GLSL mat3 columns, written here as rows of
    // the transposed product (kInset[i][j] = column j's i-th entry).
    static constexpr double kInset[3][3] = {{0.842479062253094, 0.0784335999999992, 0.0792237451477643},
        {0.0423282422610123, 0.878468636469772, 0.0791661274605434},
        {0.0423756549057051, 0.0784336, 0.879142973793104}};
    static constexpr double kOutset[3][3] = {{1.19687900512017, -0.0980208811401368, -0.0990297440797205},
        {-0.0528968517574562, 1.15190312990417, -0.0989611768448433},
        {-0.0529716355144438, -0.0980434501171241, 1.15107367264116}};
    constexpr double minEv = -12.47393;
    constexpr double maxEv = 4.026069;
    glm::dvec3 v = mulRows(kInset, nonNegative(color));
    v = glm::max(v, glm::dvec3(1e-10)); // log2 of 0 is -inf: start at the bottom of the range
    v = glm::clamp(glm::log2(v), glm::dvec3(minEv), glm::dvec3(maxEv));
    v = (v - minEv) / (maxEv - minEv);
    // agxDefaultContrastApprox: 6th-order polynomial fit of the default contrast sigmoid.
    const glm::dvec3 x2 = v * v;
    const glm::dvec3 x4 = x2 * x2;
    v = 15.5 * x4 * x2 - 40.14 * x4 * v + 31.96 * x4 - 6.868 * x2 * v + 0.4298 * x2 + 0.1191 * v - 0.00232;
    v = mulRows(kOutset, v);
    // The curve's output is display-encoded for a 2.2 display; decode it to display-linear.
    v = glm::pow(nonNegative(v), glm::dvec3(2.2));
    return clamp01(v);
}

glm::dvec3 toneMap(ToneMapper mapper, const glm::dvec3& color)
{
    switch (mapper) {
    case ToneMapper::None:
        return toneMapNone(color);
    case ToneMapper::Reinhard:
        return toneMapReinhard(color);
    case ToneMapper::Exposure:
        return toneMapExposure(color);
    case ToneMapper::Aces:
        return toneMapAcesHill(color);
    case ToneMapper::KhronosNeutral:
        return toneMapKhronosPbrNeutral(color);
    case ToneMapper::AgX:
        return toneMapAgx(color);
    }
    return toneMapNone(color);
}

double linearToSrgb(double x)
{
    x = std::clamp(x, 0.0, 1.0);
    return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

double srgbToLinear(double x)
{
    x = std::clamp(x, 0.0, 1.0);
    return x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4);
}

glm::dvec3 encodeDisplay(const glm::dvec3& displayLinear, DisplayEncoding encoding, double gamma)
{
    const glm::dvec3 c = clamp01(displayLinear);
    if (encoding == DisplayEncoding::SRGB)
        return {linearToSrgb(c.r), linearToSrgb(c.g), linearToSrgb(c.b)};
    const double inverse = 1.0 / std::max(gamma, 1e-3);
    return glm::pow(c, glm::dvec3(inverse));
}

glm::dvec3 displayTransform(
    const glm::dvec3& radiance, double exposureEV, ToneMapper mapper, DisplayEncoding encoding, double gamma)
{
    const glm::dvec3 exposed = radiance * std::exp2(exposureEV);
    return encodeDisplay(toneMap(mapper, exposed), encoding, gamma);
}

} // namespace facet::tonemap
