#include "core/shading/Transmission.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

#include "core/shading/Brdf.h"
#include "core/shading/Sampling.h"

namespace facet::shading {

glm::dvec3 refractionHalfVector(
    const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, double etaV, double etaL)
{
    const glm::dvec3 sum = etaV * v + etaL * l;
    const double length = glm::length(sum);
    if (!(length > 1e-12))
        return glm::dvec3(0.0);
    const glm::dvec3 h = -sum / length;
    return glm::dot(h, n) < 0.0 ? -h : h;
}

bool refractThrough(const glm::dvec3& v, const glm::dvec3& h, double etaV, double etaL, glm::dvec3* l)
{
    const double eta = etaV / etaL;
    const double cosI = glm::dot(v, h);
    const double sin2T = eta * eta * std::max(0.0, 1.0 - cosI * cosI);
    if (sin2T >= 1.0)
        return false;
    const double cosT = std::sqrt(1.0 - sin2T);
    *l = glm::normalize(-eta * v + (eta * cosI - cosT) * h);
    return true;
}

double refractionJacobianFactor(double VoH, double LoH, double etaV, double etaL)
{
    // v and l must lie on opposite sides of the microfacet.
    if (VoH * LoH >= 0.0)
        return 0.0;
    const double denominator = etaV * VoH + etaL * LoH;
    if (!(denominator * denominator > kMinDenominator))
        return 0.0;
    return 4.0 * std::abs(VoH) * std::abs(LoH) * etaV * etaV / (denominator * denominator);
}

double pdfVNDFRefraction(
    double NoV, double NoH, double VoH, double LoH, double alpha, double etaV, double etaL)
{
    if (NoV <= 0.0 || NoH <= 0.0 || VoH <= 0.0 || LoH >= 0.0)
        return 0.0;
    const double denominator = etaV * VoH + etaL * LoH;
    if (!(denominator * denominator > kMinDenominator))
        return 0.0;
    const double pdfH = sampling::G1_SmithGGX(NoV, alpha) * D_GGX(NoH, alpha) * VoH / NoV;
    return pdfH * etaL * etaL * std::abs(LoH) / (denominator * denominator);
}

double interfaceFresnel(double VoH, double etaV, double etaL, bool exact)
{
    const double cosI = std::clamp(VoH, 0.0, 1.0);
    const double eta = etaL / etaV;
    if (exact)
        return F_Dielectric(cosI, eta);
    // Schlick at the rarer side's angle: the incident one entering a denser medium, the refracted
    // one leaving it (1 past the critical angle).
    double cosRarer = cosI;
    if (eta < 1.0) {
        const double sin2T = (1.0 - cosI * cosI) / (eta * eta);
        if (sin2T >= 1.0)
            return 1.0;
        cosRarer = std::sqrt(1.0 - sin2T);
    }
    const double r = (etaL - etaV) / (etaL + etaV);
    return F_Schlick(r * r, 1.0, cosRarer);
}

double dispersedIor(double ior, double dispersion, double lambda)
{
    return std::max(ior + (ior - 1.0) * dispersion / 20.0 * (523655.0 / (lambda * lambda) - 1.5168), 1.0);
}

glm::dvec3 attenuationCoefficient(const glm::dvec3& attenuationColor, double attenuationDistance)
{
    if (!std::isfinite(attenuationDistance) || attenuationDistance <= 0.0)
        return glm::dvec3(0.0);
    glm::dvec3 sigma;
    for (int c = 0; c < 3; ++c)
        sigma[c] = attenuationColor[c] > 0.0
            ? -std::log(std::min(attenuationColor[c], 1.0)) / attenuationDistance
            : std::numeric_limits<double>::infinity();
    return sigma;
}

glm::dvec3 beerLambert(const glm::dvec3& sigma, double distance)
{
    glm::dvec3 t;
    for (int c = 0; c < 3; ++c)
        t[c] = sigma[c] == 0.0 ? 1.0 : std::exp(-sigma[c] * distance);
    return t;
}

InterfaceAlbedoTable::InterfaceAlbedoTable(double etaV, double etaL, bool exactFresnel, int size, int samples)
    : m_size(std::max(size, 2))
    , m_texels(std::size_t(m_size) * std::size_t(m_size))
{
    const auto count = std::uint32_t(std::max(samples, 1));
    for (int y = 0; y < m_size; ++y) {
        const double alpha = alphaFromRoughness(double(y) / double(m_size - 1));
        for (int x = 0; x < m_size; ++x) {
            const double NoV = std::max(double(x) / double(m_size - 1), 1e-4);
            const glm::dvec3 v(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
            const double g1 = sampling::G1_SmithGGX(NoV, alpha);
            Value sum;
            for (std::uint32_t i = 0; i < count; ++i) {
                const glm::dvec3 h = sampling::importanceSampleVNDF(sampling::hammersley(i, count), v, alpha);
                const double VoH = glm::dot(v, h);
                if (VoH <= 0.0)
                    continue;
                const double fresnel = interfaceFresnel(VoH, etaV, etaL, exactFresnel);
                const glm::dvec3 r = sampling::reflectAbout(v, h);
                if (r.z > 0.0)
                    sum.reflected += fresnel * 4.0 * NoV * r.z * V_SmithGGXCorrelated(NoV, r.z, alpha) / g1;
                glm::dvec3 t;
                if (fresnel < 1.0 && refractThrough(v, h, etaV, etaL, &t) && t.z < 0.0)
                    sum.transmitted
                        += (1.0 - fresnel) * 4.0 * NoV * -t.z * V_SmithGGXCorrelated(NoV, -t.z, alpha) / g1;
            }
            sum.reflected /= double(count);
            sum.transmitted /= double(count);
            m_texels[std::size_t(y) * std::size_t(m_size) + std::size_t(x)] = sum;
        }
    }
}

InterfaceAlbedoTable::Value InterfaceAlbedoTable::sample(double NoV, double perceptualRoughness) const
{
    const double fx = std::clamp(NoV, 0.0, 1.0) * double(m_size - 1);
    const double fy = std::clamp(perceptualRoughness, 0.0, 1.0) * double(m_size - 1);
    const int x0 = std::min(int(fx), m_size - 2);
    const int y0 = std::min(int(fy), m_size - 2);
    const double tx = fx - double(x0);
    const double ty = fy - double(y0);
    const auto at
        = [this](int x, int y) { return m_texels[std::size_t(y) * std::size_t(m_size) + std::size_t(x)]; };
    const auto mix = [](const Value& a, const Value& b, double t) {
        return Value {a.reflected + (b.reflected - a.reflected) * t,
            a.transmitted + (b.transmitted - a.transmitted) * t};
    };
    return mix(mix(at(x0, y0), at(x0 + 1, y0), tx), mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), tx), ty);
}

} // namespace facet::shading
