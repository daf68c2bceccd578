#include "core/shading/BrdfSampler.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/shading/Brdf.h"
#include "core/shading/Sampling.h"
#include "core/shading/Transmission.h"

namespace facet {

namespace {

double luminance(const glm::dvec3& c)
{
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

} // namespace

double powerHeuristic(double pdfA, double pdfB)
{
    const double a = pdfA * pdfA;
    const double b = pdfB * pdfB;
    return a + b > 0.0 ? a / (a + b) : 0.0;
}

BrdfSampler::BrdfSampler(const MaterialInfo& material, const MaterialBrdf& brdf, const glm::dvec3& n,
    const glm::dvec3& v, Mode mode)
    : m_material(material)
    , m_brdf(brdf)
    , m_n(n)
    , m_v(v)
    , m_NoV(std::clamp(glm::dot(n, v), 0.0, 1.0))
    , m_mode(mode)
    , m_specular(n, v, material.perceptualRoughness, material.anisotropy, material.anisotropyDirection)
    , m_t(m_specular.frame().t)
    , m_b(m_specular.frame().b)
    , m_vLocal(sampling::worldToTangent(v, m_t, m_b, n))
    , m_coatAlpha(shading::alphaFromRoughness(material.clearcoatRoughness))
    , m_alpha(shading::alphaFromRoughness(material.perceptualRoughness))
    , m_ior(std::max(material.ior, kMinRefractiveIor))
    , m_layer(dielectricReflectance(material))
{
    if (mode == Mode::Interior) {
        // The interface's multiple scattering given back in the shape of its single scattering
        // (both lobes scaled by 1 / E, E what the table says they keep; Turquin 2019's form).
        const shading::InterfaceAlbedoTable* table = brdf.leavingTable();
        if (table && brdf.model().multiScatter)
            m_interiorCompensation
                = 1.0 / std::max(table->sample(m_NoV, material.perceptualRoughness).total(), 0.25);
        return;
    }
    if (mode != Mode::Full)
        return;
    const double metallic = std::clamp(material.metallic, 0.0, 1.0);
    const glm::dvec3 f0 = glm::mix(m_layer.f0, material.baseColor, metallic);
    const double specular = luminance(shading::F_Schlick(f0, glm::mix(m_layer.f90, 1.0, metallic), m_NoV));
    // The cosine strategy also serves the sheen, a broad lobe (KHR_materials_sheen), which a
    // metal would otherwise leave to the environment strategy alone.
    const double sheen
        = material.hasSheen() ? luminance(glm::max(material.sheenColor, glm::dvec3(0.0))) : 0.0;
    const double base = luminance(material.baseColor) * (1.0 - metallic) * (1.0 - specular);
    const double transmission
        = material.hasTransmission() ? std::clamp(material.transmission, 0.0, 1.0) : 0.0;
    const double diffuse = base * (1.0 - transmission) + sheen;
    const double transmitted = base * transmission;
    if (transmitted > 0.0) {
        // A transmitting material's specular reflection and transmission share one visible normal,
        // split by what each carries at it (reflectShare): a smooth glass's reflection and
        // refraction then weigh 1 each, where lobes picked by the Fresnel at n.v gave rough
        // glass's rare microfacets far from it weights of 50.
        const double split = specular + transmitted;
        m_pSplit = diffuse <= 0.0 ? 1.0 : std::clamp(split / (split + diffuse), 0.1, 0.9);
    } else {
        const double rest = diffuse;
        m_pSpecular = rest <= 0.0 ? 1.0 : std::clamp(specular / (specular + rest), 0.1, 0.9);
    }
    if (material.clearcoat > 0.0) {
        const double coat = clearcoatWeight(material, m_NoV);
        const double under = (1.0 - coat) * (specular + std::max(diffuse + transmitted, 0.0));
        m_pCoat = std::clamp(coat / std::max(coat + under, 1e-12), 0.1, 0.9);
        m_pSpecular *= 1.0 - m_pCoat;
        m_pSplit *= 1.0 - m_pCoat;
    }
}

glm::dvec3 BrdfSampler::f(const glm::dvec3& l, LightingKind kind) const
{
    switch (m_mode) {
    case Mode::LambertOnly:
        return glm::dot(m_n, l) > 0.0 ? m_material.baseColor * shading::kInvPi : glm::dvec3(0.0);
    case Mode::Interior:
        return interiorF(l);
    case Mode::Full:
        break;
    }
    return m_brdf.evaluate(m_material, m_n, m_v, l, kind).total();
}

double BrdfSampler::pdf(const glm::dvec3& l) const
{
    if (m_mode == Mode::Interior)
        return interiorPdf(l);
    const double NoL = glm::dot(m_n, l);
    if (NoL < 0.0 && m_pSplit > 0.0) {
        double VoH = 0.0;
        const double pdf = transmissionPdf(l, &VoH);
        return pdf > 0.0 ? m_pSplit * pdf * (1.0 - reflectShare(VoH)) : 0.0;
    }
    if (NoL <= 0.0)
        return 0.0;
    double pdf = (1.0 - m_pSpecular - m_pCoat - m_pSplit) * sampling::pdfCosineHemisphere(NoL);
    if (m_pSpecular > 0.0)
        pdf += m_pSpecular * m_specular.pdf(l);
    if (m_pCoat > 0.0)
        pdf += m_pCoat
            * sampling::pdfVNDFReflection(m_NoV, glm::dot(m_n, glm::normalize(m_v + l)), m_coatAlpha);
    if (m_pSplit > 0.0) {
        const glm::dvec3 h = glm::normalize(m_v + l);
        pdf += m_pSplit * sampling::pdfVNDFReflection(m_NoV, glm::dot(m_n, h), m_alpha)
            * reflectShare(glm::dot(m_v, h));
    }
    return pdf;
}

glm::dvec3 BrdfSampler::sample(glm::dvec2 u, double uFresnel) const
{
    if (m_mode == Mode::Interior)
        return interiorSample(u, uFresnel);
    const double belowOne = std::nextafter(1.0, 0.0);
    // A reflection lobe's direction below the surface (or a transmission lobe's above it) is no
    // direction of that lobe: pdf() counts each side's lobes only, so such a draw is returned as
    // the zero vector, which pdf() gives 0 (a below-surface direction is a transmitting
    // material's transmission otherwise, which the draw's density would not match).
    const auto above = [this](const glm::dvec3& l) { return glm::dot(m_n, l) > 0.0 ? l : glm::dvec3(0.0); };
    if (u.x < m_pCoat) {
        u.x = std::min(u.x / m_pCoat, belowOne);
        const glm::dvec3 h = sampling::importanceSampleVNDF(u, m_vLocal, m_coatAlpha);
        return above(sampling::tangentToWorld(sampling::reflectAbout(m_vLocal, h), m_t, m_b, m_n));
    }
    if (u.x < m_pCoat + m_pSpecular) {
        u.x = std::min((u.x - m_pCoat) / m_pSpecular, belowOne);
        return above(m_specular.sample(u));
    }
    if (u.x < m_pCoat + m_pSpecular + m_pSplit) {
        u.x = std::min((u.x - m_pCoat - m_pSpecular) / m_pSplit, belowOne);
        return splitSample(u, uFresnel);
    }
    const double pDiffuse = 1.0 - m_pCoat - m_pSpecular - m_pSplit;
    u.x = std::min((u.x - m_pCoat - m_pSpecular - m_pSplit) / pDiffuse, belowOne);
    return sampling::tangentToWorld(sampling::sampleCosineHemisphere(u), m_t, m_b, m_n);
}

double BrdfSampler::reflectShare(double VoH) const
{
    const double metallic = std::clamp(m_material.metallic, 0.0, 1.0);
    const glm::dvec3 fresnel = m_brdf.dielectricFresnel(m_material, m_layer, std::clamp(VoH, 0.0, 1.0));
    const double dielectric = std::max({fresnel.r, fresnel.g, fresnel.b});
    const double metal = metallic > 0.0 ? luminance(shading::F_Schlick(
                             glm::max(m_material.baseColor, glm::dvec3(0.0)), 1.0, std::clamp(VoH, 0.0, 1.0)))
                                        : 0.0;
    const double reflected = (1.0 - metallic) * dielectric + metallic * metal;
    const double transmitted = (1.0 - metallic) * std::clamp(m_material.transmission, 0.0, 1.0)
        * (1.0 - dielectric) * std::max(luminance(m_material.baseColor), 0.0);
    return reflected + transmitted > 0.0 ? reflected / (reflected + transmitted) : 1.0;
}

double BrdfSampler::transmissionPdf(const glm::dvec3& l, double* VoH) const
{
    glm::dvec3 h;
    double pdf = 0.0;
    if (m_material.isThinWalled()) {
        h = glm::normalize(m_v + (l - 2.0 * glm::dot(m_n, l) * m_n));
        pdf = sampling::pdfVNDFReflection(m_NoV, glm::dot(m_n, h), m_alpha);
    } else {
        h = shading::refractionHalfVector(m_n, m_v, l, 1.0, m_ior);
        pdf = shading::pdfVNDFRefraction(
            m_NoV, glm::dot(m_n, h), glm::dot(m_v, h), glm::dot(l, h), m_alpha, 1.0, m_ior);
    }
    *VoH = glm::dot(m_v, h);
    return pdf;
}

glm::dvec3 BrdfSampler::splitSample(const glm::dvec2& u, double uFresnel) const
{
    const glm::dvec3 h = sampling::importanceSampleVNDF(u, m_vLocal, m_alpha);
    glm::dvec3 l = sampling::reflectAbout(m_vLocal, h);
    if (uFresnel < reflectShare(glm::dot(m_vLocal, h)))
        return l.z > 0.0 ? sampling::tangentToWorld(l, m_t, m_b, m_n) : glm::dvec3(0.0);
    if (m_material.isThinWalled())
        l.z = -l.z; // a thin wall's transmission: the reflection mirrored through the surface
    else if (!shading::refractThrough(m_vLocal, h, 1.0, m_ior, &l))
        return glm::dvec3(0.0); // not reached: nothing is totally reflected entering a denser medium
    // Through the microfacet but back above the surface: no direction of this lobe (sample()).
    return l.z < 0.0 ? sampling::tangentToWorld(l, m_t, m_b, m_n) : glm::dvec3(0.0);
}

double BrdfSampler::interiorFresnel(double VoH) const
{
    return shading::interfaceFresnel(VoH, m_ior, 1.0, m_brdf.model().fresnel == Fresnel::Dielectric);
}

glm::dvec3 BrdfSampler::interiorF(const glm::dvec3& l) const
{
    const double NoL = glm::dot(m_n, l);
    if (m_NoV <= 0.0 || NoL == 0.0)
        return glm::dvec3(0.0);
    if (NoL > 0.0) {
        const glm::dvec3 h = glm::normalize(m_v + l);
        return glm::dvec3(interiorFresnel(glm::dot(m_v, h)) * shading::D_GGX(glm::dot(m_n, h), m_alpha)
            * shading::V_SmithGGXCorrelated(m_NoV, std::min(NoL, 1.0), m_alpha) * m_interiorCompensation);
    }
    const glm::dvec3 h = shading::refractionHalfVector(m_n, m_v, l, m_ior, 1.0);
    const double VoH = glm::dot(m_v, h);
    if (VoH <= 0.0)
        return glm::dvec3(0.0);
    return glm::max(m_material.baseColor, glm::dvec3(0.0))
        * ((1.0 - interiorFresnel(VoH)) * shading::D_GGX(glm::dot(m_n, h), m_alpha)
            * shading::V_SmithGGXCorrelated(m_NoV, std::min(-NoL, 1.0), m_alpha)
            * shading::refractionJacobianFactor(VoH, glm::dot(l, h), m_ior, 1.0) * m_interiorCompensation);
}

double BrdfSampler::interiorPdf(const glm::dvec3& l) const
{
    const double NoL = glm::dot(m_n, l);
    if (m_NoV <= 0.0 || NoL == 0.0)
        return 0.0;
    if (NoL > 0.0) {
        const glm::dvec3 h = glm::normalize(m_v + l);
        return interiorFresnel(glm::dot(m_v, h))
            * sampling::pdfVNDFReflection(m_NoV, glm::dot(m_n, h), m_alpha);
    }
    const glm::dvec3 h = shading::refractionHalfVector(m_n, m_v, l, m_ior, 1.0);
    const double VoH = glm::dot(m_v, h);
    return (1.0 - interiorFresnel(VoH))
        * shading::pdfVNDFRefraction(m_NoV, glm::dot(m_n, h), VoH, glm::dot(l, h), m_alpha, m_ior, 1.0);
}

glm::dvec3 BrdfSampler::interiorSample(const glm::dvec2& u, double uFresnel) const
{
    const glm::dvec3 h = sampling::importanceSampleVNDF(u, m_vLocal, m_alpha);
    glm::dvec3 l;
    const bool reflected = uFresnel < interiorFresnel(glm::dot(m_vLocal, h))
        || !shading::refractThrough(m_vLocal, h, m_ior, 1.0, &l);
    if (reflected)
        l = sampling::reflectAbout(m_vLocal, h);
    // A reflection below the surface or a refraction above it: no direction of its lobe (sample()).
    if ((l.z > 0.0) != reflected)
        return glm::dvec3(0.0);
    return sampling::tangentToWorld(l, m_t, m_b, m_n);
}

} // namespace facet
