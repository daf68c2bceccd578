#include "core/shading/BrdfSampler.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/shading/Brdf.h"
#include "core/shading/Sampling.h"

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
    const glm::dvec3& v, bool lambertOnly)
    : m_material(material)
    , m_brdf(brdf)
    , m_n(n)
    , m_v(v)
    , m_NoV(std::clamp(glm::dot(n, v), 0.0, 1.0))
    , m_lambertOnly(lambertOnly)
    , m_specular(n, v, material.perceptualRoughness, material.anisotropy, material.anisotropyDirection)
    , m_t(m_specular.frame().t)
    , m_b(m_specular.frame().b)
    , m_vLocal(sampling::worldToTangent(v, m_t, m_b, n))
    , m_coatAlpha(shading::alphaFromRoughness(material.clearcoatRoughness))
{
    if (lambertOnly)
        return;
    const double metallic = std::clamp(material.metallic, 0.0, 1.0);
    const DielectricReflectance layer = dielectricReflectance(material);
    const glm::dvec3 f0 = glm::mix(layer.f0, material.baseColor, metallic);
    const double specular = luminance(shading::F_Schlick(f0, glm::mix(layer.f90, 1.0, metallic), m_NoV));
    // The cosine strategy also serves the sheen, a broad lobe (KHR_materials_sheen), which a
    // metal would otherwise leave to the environment strategy alone.
    const double sheen
        = material.hasSheen() ? luminance(glm::max(material.sheenColor, glm::dvec3(0.0))) : 0.0;
    const double diffuse = luminance(material.baseColor) * (1.0 - metallic) * (1.0 - specular) + sheen;
    m_pSpecular = diffuse <= 0.0 ? 1.0 : std::clamp(specular / (specular + diffuse), 0.1, 0.9);
    if (material.clearcoat > 0.0) {
        const double coat = clearcoatWeight(material, m_NoV);
        const double base = (1.0 - coat) * (specular + std::max(diffuse, 0.0));
        m_pCoat = std::clamp(coat / std::max(coat + base, 1e-12), 0.1, 0.9);
        m_pSpecular *= 1.0 - m_pCoat;
    }
}

glm::dvec3 BrdfSampler::f(const glm::dvec3& l, LightingKind kind) const
{
    if (m_lambertOnly)
        return glm::dot(m_n, l) > 0.0 ? m_material.baseColor * shading::kInvPi : glm::dvec3(0.0);
    return m_brdf.evaluate(m_material, m_n, m_v, l, kind).total();
}

double BrdfSampler::pdf(const glm::dvec3& l) const
{
    const double NoL = glm::dot(m_n, l);
    if (NoL <= 0.0)
        return 0.0;
    double pdf = (1.0 - m_pSpecular - m_pCoat) * sampling::pdfCosineHemisphere(NoL);
    if (m_pSpecular > 0.0)
        pdf += m_pSpecular * m_specular.pdf(l);
    if (m_pCoat > 0.0)
        pdf += m_pCoat
            * sampling::pdfVNDFReflection(m_NoV, glm::dot(m_n, glm::normalize(m_v + l)), m_coatAlpha);
    return pdf;
}

glm::dvec3 BrdfSampler::sample(glm::dvec2 u) const
{
    const double belowOne = std::nextafter(1.0, 0.0);
    if (u.x < m_pCoat) {
        u.x = std::min(u.x / m_pCoat, belowOne);
        const glm::dvec3 h = sampling::importanceSampleVNDF(u, m_vLocal, m_coatAlpha);
        return sampling::tangentToWorld(sampling::reflectAbout(m_vLocal, h), m_t, m_b, m_n);
    }
    if (u.x < m_pCoat + m_pSpecular) {
        u.x = std::min((u.x - m_pCoat) / m_pSpecular, belowOne);
        return m_specular.sample(u);
    }
    const double pDiffuse = 1.0 - m_pCoat - m_pSpecular;
    u.x = std::min((u.x - m_pCoat - m_pSpecular) / pDiffuse, belowOne);
    return sampling::tangentToWorld(sampling::sampleCosineHemisphere(u), m_t, m_b, m_n);
}

} // namespace facet
