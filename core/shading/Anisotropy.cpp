#include "core/shading/Anisotropy.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>

#include "core/shading/Brdf.h"
#include "core/shading/Sampling.h"

namespace facet::shading {

AnisotropicAlpha anisotropicAlpha(double perceptualRoughness, double strength)
{
    const double alpha = alphaFromRoughness(perceptualRoughness);
    const double s = std::clamp(strength, 0.0, 1.0);
    return {alpha + (1.0 - alpha) * s * s, alpha};
}

double D_GGXAnisotropic(const glm::dvec3& h, const AnisotropicAlpha& alpha)
{
    if (h.z <= 0.0)
        return 0.0;
    const double x = h.x / alpha.t;
    const double y = h.y / alpha.b;
    const double f = x * x + y * y + h.z * h.z;
    return 1.0 / std::max(kPi * alpha.t * alpha.b * f * f, kMinDenominator);
}

double Lambda_GGXAnisotropic(const glm::dvec3& w, const AnisotropicAlpha& alpha)
{
    const double z2 = std::max(w.z * w.z, kMinDenominator);
    const double projected = alpha.t * alpha.t * w.x * w.x + alpha.b * alpha.b * w.y * w.y;
    return 0.5 * (-1.0 + std::sqrt(1.0 + projected / z2));
}

double G1_GGXAnisotropic(const glm::dvec3& w, const AnisotropicAlpha& alpha)
{
    return 1.0 / (1.0 + Lambda_GGXAnisotropic(w, alpha));
}

double V_GGXAnisotropic(const glm::dvec3& v, const glm::dvec3& l, const AnisotropicAlpha& alpha)
{
    const double NoV = std::max(v.z, 0.0);
    const double NoL = std::max(l.z, 0.0);
    const double lambdaV = NoL * glm::length(glm::dvec3(alpha.t * v.x, alpha.b * v.y, NoV));
    const double lambdaL = NoV * glm::length(glm::dvec3(alpha.t * l.x, alpha.b * l.y, NoL));
    return 0.5 / std::max(lambdaV + lambdaL, kMinDenominator);
}

glm::dvec3 importanceSampleVNDFAnisotropic(
    const glm::dvec2& u, const glm::dvec3& v, const AnisotropicAlpha& alpha)
{
    return sampling::importanceSampleVNDF(u, v, alpha.t, alpha.b);
}

double pdfVNDFReflectionAnisotropic(const glm::dvec3& v, const glm::dvec3& h, const AnisotropicAlpha& alpha)
{
    if (v.z <= 0.0 || h.z <= 0.0)
        return 0.0;
    return G1_GGXAnisotropic(v, alpha) * D_GGXAnisotropic(h, alpha) / (4.0 * v.z);
}

glm::dvec2 anisotropyDirection(const glm::dvec2& textureDirection, double rotation)
{
    const double length = glm::length(textureDirection);
    const glm::dvec2 d = length > 1e-12 ? textureDirection / length : glm::dvec2(1.0, 0.0);
    const double c = std::cos(rotation);
    const double s = std::sin(rotation);
    return {c * d.x - s * d.y, s * d.x + c * d.y};
}

double anisotropicDirectionalAlbedo(const glm::dvec3& v, const AnisotropicAlpha& alpha, int sampleCount)
{
    if (v.z <= 0.0)
        return 0.0;
    // Each visible-normal sample weighs f (n.l) / pdf = D V (n.l) 4 (n.v) / (G1(v) D) = G2 / G1(v).
    const auto count = std::uint32_t(std::max(sampleCount, 1));
    const double g1 = G1_GGXAnisotropic(v, alpha);
    double sum = 0.0;
    for (std::uint32_t i = 0; i < count; ++i) {
        const glm::dvec3 h = importanceSampleVNDFAnisotropic(sampling::hammersley(i, count), v, alpha);
        const glm::dvec3 l = sampling::reflectAbout(v, h);
        if (l.z <= 0.0)
            continue;
        sum += 4.0 * v.z * l.z * V_GGXAnisotropic(v, l, alpha) / g1;
    }
    return sum / double(count);
}

} // namespace facet::shading
