#include "core/shading/Anisotropy.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/common.hpp>
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

glm::dvec3 AnisotropyFrame::toLocal(const glm::dvec3& w) const
{
    return {glm::dot(w, t), glm::dot(w, b), glm::dot(w, n)};
}

glm::dvec3 AnisotropyFrame::toWorld(const glm::dvec3& w) const
{
    return w.x * t + w.y * b + w.z * n;
}

std::optional<AnisotropyFrame> anisotropyFrame(const glm::dvec3& n, const glm::dvec3& direction)
{
    const glm::dvec3 inPlane = direction - n * glm::dot(n, direction);
    const double length = glm::length(inPlane);
    if (!(length > 1e-9))
        return std::nullopt;
    AnisotropyFrame frame;
    frame.n = n;
    frame.t = inPlane / length;
    frame.b = glm::cross(n, frame.t);
    return frame;
}

SpecularLobeSampler::SpecularLobeSampler(const glm::dvec3& n, const glm::dvec3& v, double perceptualRoughness,
    double anisotropy, const glm::dvec3& direction)
    : m_v(v)
{
    const std::optional<AnisotropyFrame> frame
        = anisotropy > 0.0 ? anisotropyFrame(n, direction) : std::optional<AnisotropyFrame>();
    m_anisotropic = frame.has_value();
    if (m_anisotropic) {
        m_frame = *frame;
        m_alpha = anisotropicAlpha(perceptualRoughness, anisotropy);
    } else {
        m_frame.n = n;
        sampling::buildOrthonormalBasis(n, m_frame.t, m_frame.b);
        const double alpha = alphaFromRoughness(perceptualRoughness);
        m_alpha = {alpha, alpha};
    }
    m_vLocal = m_frame.toLocal(v);
}

glm::dvec3 SpecularLobeSampler::sample(const glm::dvec2& u) const
{
    const glm::dvec3 h = sampling::importanceSampleVNDF(u, m_vLocal, m_alpha.t, m_alpha.b);
    return m_frame.toWorld(sampling::reflectAbout(m_vLocal, h));
}

double SpecularLobeSampler::pdf(const glm::dvec3& l) const
{
    const glm::dvec3 h = glm::normalize(m_v + l);
    if (!m_anisotropic)
        return sampling::pdfVNDFReflection(m_vLocal.z, glm::dot(m_frame.n, h), m_alpha.b);
    return pdfVNDFReflectionAnisotropic(m_vLocal, m_frame.toLocal(h), m_alpha);
}

AnisotropicCompensation anisotropicCompensation(
    const glm::dvec3& vLocal, double perceptualRoughness, double strength)
{
    const AnisotropicAlpha alpha = anisotropicAlpha(perceptualRoughness, strength);
    const double tv2 = std::min(vLocal.x * vLocal.x, 1.0);
    const double alphaV = std::sqrt(alpha.t * alpha.t * tv2 + alpha.b * alpha.b * (1.0 - tv2));
    const double fade = 1.0 - std::clamp(strength, 0.0, 1.0);
    return {std::sqrt(alphaV), fade * fade};
}

glm::dvec3 anisotropicBentNormal(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& t,
    double perceptualRoughness, double strength)
{
    const glm::dvec3 b = glm::cross(n, t);
    const glm::dvec3 across = glm::cross(glm::cross(b, v), b);
    double bend = 1.0 - std::clamp(strength, 0.0, 1.0) * (1.0 - clampRoughness(perceptualRoughness));
    bend *= bend;
    const glm::dvec3 bent = glm::mix(across, n, bend * bend);
    const double length = glm::length(bent);
    return length > 1e-6 ? bent / length : n;
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
