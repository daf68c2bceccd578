#include "core/shading/MaterialBrdf.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/shading/Anisotropy.h"
#include "core/shading/Brdf.h"
#include "core/shading/Sampling.h"
#include "core/shading/Sheen.h"
#include "core/shading/Transmission.h"

namespace facet {

using namespace shading;

MaterialBrdf::MaterialBrdf(const ShadingModel& model, const DfgTable& albedoTable)
    : m_model(model)
    , m_table(&albedoTable)
{
    assert(!albedoTable.isEmpty());
    // Precompute the moments of each roughness row with the trapezoid rule over the n.v texels.
    const int size = albedoTable.size();
    m_moments.resize(std::size_t(size));
    for (int y = 0; y < size; ++y) {
        RowMoments m;
        for (int x = 0; x < size; ++x) {
            const double w = 2.0 * DfgTable::texelPosition(x, size) * DfgTable::trapezoidWeight(x, size);
            const DfgValue t = albedoTable.texel(x, y);
            const double e = std::max(t.albedo(), 1e-6);
            const double gain = (1.0 - e) / e;
            m.bias += t.bias * w;
            m.scale += t.scale * w;
            m.scaleGain += t.scale * gain * w;
            m.biasGain += t.bias * gain * w;
        }
        m_moments[std::size_t(y)] = m;
    }
}

double MaterialBrdf::distribution(double NoH, double alpha) const
{
    switch (m_model.distribution) {
    case Distribution::GGX:
        return D_GGX(NoH, alpha);
    case Distribution::Beckmann:
        return D_Beckmann(NoH, alpha);
    }
    return 0.0;
}

double MaterialBrdf::visibility(
    double NoV, double NoL, double alpha, double perceptualRoughness, LightingKind kind) const
{
    switch (m_model.visibility) {
    case Visibility::SmithGGXCorrelated:
        return V_SmithGGXCorrelated(NoV, NoL, alpha);
    case Visibility::SmithGGXUncorrelated:
        return V_SmithGGX(NoV, NoL, alpha);
    case Visibility::SchlickGGX: {
        const double k = kind == LightingKind::Punctual ? k_SchlickGGX_direct(perceptualRoughness)
                                                        : k_SchlickGGX_ibl(alpha);
        return V_SmithSchlickGGX(NoV, NoL, k);
    }
    }
    return 0.0;
}

glm::dvec3 MaterialBrdf::multiScatterFactor(
    const glm::dvec3& f0, double NoV, double perceptualRoughness, double weight) const
{
    if (!m_model.multiScatter)
        return glm::dvec3(1.0);
    // E is the albedo of the lobe with F = 1; a lobe of reflectance f0 loses f0 (1 - E) of the
    // light to paths of more than one bounce, which the factor adds back in proportion.
    const double e = std::max(m_table->sample(NoV, clampRoughness(perceptualRoughness)).albedo(), 1e-6);
    return glm::dvec3(1.0) + f0 * (weight * (1.0 - e) / e);
}

double MaterialBrdf::dielectricSpecularAlbedo(
    double f0, double NoV, double perceptualRoughness, double f90) const
{
    const DfgValue t = m_table->sample(NoV, clampRoughness(perceptualRoughness));
    return (f0 * t.scale + f90 * t.bias) * multiScatterFactor(glm::dvec3(f0), NoV, perceptualRoughness).x;
}

double MaterialBrdf::dielectricSpecularAverageAlbedo(double f0, double perceptualRoughness, double f90) const
{
    // E_s = (f0 A + f90 B)(1 + f0 (1 - E) / E) = f0 A + f90 B + f0^2 A (1 - E)/E + f0 f90 B (1 - E)/E,
    // so its average is a quadratic in f0 whose coefficients are per-row moments, interpolated
    // between rows as sample() interpolates the table.
    const int size = m_table->size();
    const double fy = clampRoughness(perceptualRoughness) * double(size - 1);
    const auto y0 = std::size_t(fy);
    const std::size_t y1 = std::min<std::size_t>(y0 + 1, std::size_t(size - 1));
    const double t = fy - double(y0);
    auto at = [&](const RowMoments& m) {
        double avg = f0 * m.scale + f90 * m.bias;
        if (m_model.multiScatter)
            avg += f0 * f0 * m.scaleGain + f0 * f90 * m.biasGain;
        return avg;
    };
    return at(m_moments[y0]) * (1.0 - t) + at(m_moments[y1]) * t;
}

BrdfLobes MaterialBrdf::evaluate(const MaterialInfo& material, const glm::dvec3& n, const glm::dvec3& v,
    const glm::dvec3& l, LightingKind kind) const
{
    const double NoL = glm::dot(n, l);
    const double NoVraw = glm::dot(n, v);
    if (NoVraw < 0.0)
        return {};
    const double NoV = std::min(NoVraw, 1.0);
    if (NoL <= 0.0) {
        BrdfLobes lobes;
        if (NoL < 0.0 && material.hasTransmission())
            lobes.transmission = transmissionLobe(material, n, v, l, NoV, kind);
        return lobes;
    }
    const glm::dvec3 hSum = v + l;
    const double hLength = glm::length(hSum);
    // v = -l (grazing from both sides) has no half vector; the lobe is zero there anyway.
    const glm::dvec3 h = hLength > 0.0 ? hSum / hLength : n;
    const double NoH = std::clamp(glm::dot(n, h), 0.0, 1.0);
    const double VoH = std::clamp(glm::dot(v, h), 0.0, 1.0);

    const double roughness = clampRoughness(material.perceptualRoughness);
    const double metallic = std::clamp(material.metallic, 0.0, 1.0);
    const glm::dvec3 baseColor = glm::max(material.baseColor, glm::dvec3(0.0));
    const SpecularShape shape = specularShape(material, n, v, l, h, NoV, NoL, NoH, kind);
    const double microfacet = shape.microfacet;
    const auto compensation = [&](const glm::dvec3& f0) {
        return multiScatterFactor(f0, NoV, shape.compensationRoughness, shape.compensationWeight);
    };
    const DielectricReflectance layer = dielectricReflectance(material);

    // Diffuse of the dielectric base, before coupling with the specular layer; a transmitting
    // material's base is that much BTDF instead (KHR_materials_transmission's
    // mix(diffuse_brdf, specular_btdf, transmission)).
    const glm::dvec3 lambert
        = baseColor * (Fd_Lambert() * (1.0 - std::clamp(material.transmission, 0.0, 1.0)));

    // KHR_materials_iridescence: the film's Fresnel seen at v.h (docs/shading.md, "Iridescence").
    const double iridescence = std::clamp(material.iridescence, 0.0, 1.0);
    const auto maxValue = [](const glm::dvec3& c) { return std::max({c.r, c.g, c.b}); };

    BrdfLobes lobes;
    if (m_model.composition == BrdfComposition::Gltf) {
        // glTF 2.0 Appendix B: material = mix(dielectric_brdf, metal_brdf, metallic).
        glm::dvec3 fDielectric = dielectricFresnel(material, layer, VoH);
        glm::dvec3 fMetal = F_Schlick(baseColor, 1.0, VoH);
        const glm::dvec3 msDielectric = compensation(layer.f0);
        const glm::dvec3 msMetal = compensation(baseColor);

        // fresnel_mix(ior, base, layer): the base keeps 1 - max_value(F(v.h)) (one number for all
        // channels: KHR_materials_specular's rule; 1 - F without a tint). The energy-preserving
        // coupling scales it by what the layer's albedo leaves instead.
        double diffuseWeight = m_model.coupling == DielectricCoupling::FresnelMix
            ? 1.0 - maxValue(fDielectric)
            : couplingFactor(layer, NoV, NoL, roughness);
        if (iridescence > 0.0) {
            // dielectric_brdf = mix(fresnel_mix(...), rgb_mix(diffuse, specular, Firid(f0)),
            // iridescence), metal_brdf = specular mix(F(baseColor), Firid(baseColor), iridescence).
            if (metallic < 1.0) {
                const glm::dvec3 firid = filmFresnel(material, layer.f0, VoH);
                // The energy-preserving coupling couples the base to the film as to a Schlick
                // layer over the film's Fresnel (filmLayer; docs/shading.md).
                const double filmWeight = m_model.coupling == DielectricCoupling::FresnelMix
                    ? 1.0 - maxValue(firid)
                    : couplingFactor(filmLayer(material, layer.f0), NoV, NoL, roughness);
                diffuseWeight = glm::mix(diffuseWeight, filmWeight, iridescence);
                fDielectric = glm::mix(fDielectric, firid, iridescence);
            }
            if (metallic > 0.0)
                fMetal = glm::mix(fMetal, filmFresnel(material, baseColor, VoH), iridescence);
        }
        lobes.diffuse = (1.0 - metallic) * lambert * diffuseWeight;
        lobes.specular
            = (1.0 - metallic) * microfacet * fDielectric * msDielectric + metallic * microfacet * fMetal * msMetal;
    } else {
        // LearnOpenGL / UE4: F0 = mix(0.04, albedo, metallic), kS = F, kD = (1 - kS)(1 - metallic);
        // the specular layer's F0 and F90 mixed as the dielectric's, the film's Fresnel mixed in by
        // its strength.
        const glm::dvec3 f0 = glm::mix(layer.f0, baseColor, metallic);
        glm::dvec3 F = F_Schlick(f0, layer.f90 + (1.0 - layer.f90) * metallic, VoH);
        if (iridescence > 0.0)
            F = glm::mix(F, filmFresnel(material, f0, VoH), iridescence);
        lobes.specular = microfacet * F * compensation(f0);
        const glm::dvec3 kD = m_model.coupling == DielectricCoupling::FresnelMix
            ? (glm::dvec3(1.0) - F) * (1.0 - metallic)
            : glm::dvec3(couplingFactor(layer, NoV, NoL, roughness) * (1.0 - metallic));
        lobes.diffuse = kD * lambert;
    }
    if (material.hasSheen()) {
        // KHR_materials_sheen: sheen_brdf + scaling x material, the scaling reciprocal (the min of
        // its n.v and n.l terms); no Fresnel in the lobe (docs/shading.md, "Sheen").
        const double scaling = sheenAlbedoScaling(material.sheenColor, material.sheenRoughness, NoV, NoL);
        lobes.diffuse *= scaling;
        lobes.specular *= scaling;
        const double sheenRoughness = std::clamp(material.sheenRoughness, 0.0, 1.0);
        const double sheenAlpha = sheenRoughness * sheenRoughness;
        lobes.sheen = glm::max(material.sheenColor, glm::dvec3(0.0)) * D_Charlie(NoH, sheenAlpha)
            * V_Charlie(NoV, std::min(NoL, 1.0), sheenAlpha);
    }
    if (material.clearcoat > 0.0) {
        // KHR_materials_clearcoat: mix(material, clearcoat_brdf, clearcoat x Fc(n.v)), the coat a
        // specular lobe of its own roughness with no Fresnel inside (docs/shading.md, "Clearcoat").
        const glm::dvec3 nc = material.clearcoatNormal == glm::dvec3(0.0) ? n : material.clearcoatNormal;
        const double NcoL = glm::dot(nc, l);
        const double NcoV = std::clamp(glm::dot(nc, v), 0.0, 1.0);
        const double weight = clearcoatWeight(material, NcoV);
        lobes.diffuse *= 1.0 - weight;
        lobes.specular *= 1.0 - weight;
        lobes.sheen *= 1.0 - weight; // the coat lies over the sheen
        if (NcoL > 0.0) {
            const double coatRoughness = clampRoughness(material.clearcoatRoughness);
            const double coatAlpha = coatRoughness * coatRoughness;
            const double NcoH = std::clamp(glm::dot(nc, h), 0.0, 1.0);
            lobes.coat = glm::dvec3(weight * distribution(NcoH, coatAlpha)
                * visibility(NcoV, std::min(NcoL, 1.0), coatAlpha, coatRoughness, kind));
        }
    }
    return lobes;
}

glm::dvec3 MaterialBrdf::transmissionLobe(const MaterialInfo& material, const glm::dvec3& n,
    const glm::dvec3& v, const glm::dvec3& l, double NoV, LightingKind kind) const
{
    const double metallic = std::clamp(material.metallic, 0.0, 1.0);
    const double transmission = std::clamp(material.transmission, 0.0, 1.0) * (1.0 - metallic);
    const double roughness = clampRoughness(material.perceptualRoughness);
    const double alpha = roughness * roughness;
    const double NoL = -glm::dot(n, l); // > 0: l is below the surface
    double shape = 0.0;
    double VoH = 1.0;
    if (material.isThinWalled()) {
        // A thin wall bends nothing: its BTDF is the reflection lobe mirrored through the surface.
        const glm::dvec3 mirrored = l + 2.0 * NoL * n;
        const glm::dvec3 hSum = v + mirrored;
        const double hLength = glm::length(hSum);
        const glm::dvec3 h = hLength > 0.0 ? hSum / hLength : n;
        VoH = std::clamp(glm::dot(v, h), 0.0, 1.0);
        shape = distribution(std::clamp(glm::dot(n, h), 0.0, 1.0), alpha)
            * visibility(NoV, std::min(NoL, 1.0), alpha, roughness, kind);
    } else {
        // The volume's interface, from the outside (index 1) into the material's index.
        const double ior = std::max(material.ior, kMinRefractiveIor);
        const glm::dvec3 h = refractionHalfVector(n, v, l, 1.0, ior);
        if (h == glm::dvec3(0.0))
            return glm::dvec3(0.0);
        VoH = glm::dot(v, h);
        if (VoH <= 0.0)
            return glm::dvec3(0.0);
        shape = distribution(glm::dot(n, h), alpha)
            * visibility(NoV, std::min(NoL, 1.0), alpha, roughness, kind)
            * refractionJacobianFactor(VoH, glm::dot(l, h), 1.0, ior);
    }
    // The light the specular layer (and the film over it) does not reflect, as fresnel_mix leaves
    // the base, with its multiple scattering compensated.
    const DielectricReflectance layer = dielectricReflectance(material);
    glm::dvec3 fresnel = dielectricFresnel(material, layer, VoH);
    if (material.iridescence > 0.0)
        fresnel = glm::mix(
            fresnel, filmFresnel(material, layer.f0, VoH), std::clamp(material.iridescence, 0.0, 1.0));
    const double passed = 1.0 - std::max({fresnel.r, fresnel.g, fresnel.b});
    glm::dvec3 lobe = glm::max(material.baseColor, glm::dvec3(0.0))
        * (transmission * passed * shape * transmissionCompensation(material, NoV));
    if (material.hasSheen())
        lobe *= sheenAlbedoScaling(material.sheenColor, material.sheenRoughness, NoV, std::min(NoL, 1.0));
    if (material.clearcoat > 0.0) {
        const glm::dvec3 nc = material.clearcoatNormal == glm::dvec3(0.0) ? n : material.clearcoatNormal;
        lobe *= 1.0 - clearcoatWeight(material, std::clamp(glm::dot(nc, v), 0.0, 1.0));
    }
    return lobe;
}

void MaterialBrdf::setInterfaceTables(
    std::shared_ptr<const InterfaceAlbedoTable> entering, std::shared_ptr<const InterfaceAlbedoTable> leaving)
{
    m_entering = std::move(entering);
    m_leaving = std::move(leaving);
}

double MaterialBrdf::transmissionCompensation(const MaterialInfo& material, double NoV) const
{
    if (!m_model.multiScatter)
        return 1.0;
    const double roughness = clampRoughness(material.perceptualRoughness);
    const DielectricReflectance layer = dielectricReflectance(material);
    const double reflected = dielectricSpecularAlbedo(layer.maxF0(), NoV, roughness, layer.f90);
    double transmitted = 0.0;
    if (material.isThinWalled()) {
        // The mirrored reflection lobe weighed by 1 - F: the lobe's albedo less the layer's.
        const DfgValue t = m_table->sample(NoV, roughness);
        transmitted = (1.0 - layer.maxF0()) * t.scale + (1.0 - layer.f90) * t.bias;
    } else if (m_entering) {
        transmitted = m_entering->sample(NoV, roughness).transmitted;
    } else {
        return 1.0;
    }
    if (transmitted <= 1e-6)
        return 1.0;
    return std::clamp((1.0 - reflected) / transmitted, 1.0, 4.0);
}

MaterialBrdf::SpecularShape MaterialBrdf::specularShape(const MaterialInfo& material, const glm::dvec3& n,
    const glm::dvec3& v, const glm::dvec3& l, const glm::dvec3& h, double NoV, double NoL, double NoH,
    LightingKind kind) const
{
    const double roughness = clampRoughness(material.perceptualRoughness);
    // KHR_materials_anisotropy: the base's specular lobes (dielectric and metal) take the
    // extension's anisotropic GGX D and its height-correlated Smith V, whatever the model's D and V,
    // and a compensation of their own (docs/shading.md, "Anisotropy"); no frame (no direction):
    // the isotropic lobe.
    if (material.anisotropy > 0.0)
        if (const std::optional<AnisotropyFrame> frame = anisotropyFrame(n, material.anisotropyDirection)) {
            const AnisotropicAlpha alpha = anisotropicAlpha(roughness, material.anisotropy);
            const glm::dvec3 vLocal = frame->toLocal(v);
            const AnisotropicCompensation c = anisotropicCompensation(vLocal, roughness, material.anisotropy);
            return {D_GGXAnisotropic(frame->toLocal(h), alpha) * V_GGXAnisotropic(vLocal, frame->toLocal(l), alpha),
                c.perceptualRoughness, c.weight};
        }
    const double alpha = roughness * roughness;
    return {distribution(NoH, alpha) * visibility(NoV, NoL, alpha, roughness, kind), roughness, 1.0};
}

double DielectricReflectance::maxF0() const
{
    return std::max({f0.r, f0.g, f0.b});
}

DielectricReflectance dielectricReflectance(const MaterialInfo& material)
{
    const double specular = std::clamp(material.specular, 0.0, 1.0);
    const glm::dvec3 tinted = glm::min(
        f0FromIor(material.ior) * glm::max(material.specularColor, glm::dvec3(0.0)), glm::dvec3(1.0));
    return {tinted * specular, specular};
}

glm::dvec3 MaterialBrdf::dielectricFresnel(
    const MaterialInfo& material, const DielectricReflectance& layer, double VoH) const
{
    if (m_model.fresnel != Fresnel::Dielectric)
        return F_Schlick(layer.f0, layer.f90, VoH);
    // The exact curve, shifted by the tint's change of F0 with Schlick's weight and scaled by the
    // strength: F_Dielectric itself for the default layer (docs/shading.md, "Specular").
    const double specular = layer.f90;
    const double f0 = f0FromIor(material.ior);
    const glm::dvec3 tinted = specular > 0.0 ? layer.f0 / specular : glm::dvec3(f0);
    const double weight = 1.0 - pow5(1.0 - std::clamp(VoH, 0.0, 1.0));
    return glm::clamp(specular * (F_Dielectric(VoH, material.ior) + (tinted - f0) * weight), 0.0, 1.0);
}

glm::dvec3 filmFresnel(const MaterialInfo& material, const glm::dvec3& f0, double cosTheta)
{
    const ThinFilm film {material.iridescenceIor, material.iridescenceThickness};
    return glm::clamp(iridescenceFresnel(film, f0, cosTheta), 0.0, 1.0);
}

DielectricReflectance filmLayer(const MaterialInfo& material, const glm::dvec3& f0)
{
    // The smallest Schlick F0 whose curve lies on or above the film's Fresnel at these angles (its
    // interference peaks may lie away from normal incidence).
    double envelope = 0.0;
    for (const double cosTheta : kFilmLayerAngles) {
        const glm::dvec3 firid = filmFresnel(material, f0, cosTheta);
        const double weight = pow5(1.0 - cosTheta);
        envelope = std::max(envelope, (std::max({firid.r, firid.g, firid.b}) - weight) / (1.0 - weight));
    }
    return {glm::dvec3(std::clamp(envelope, 0.0, 1.0)), 1.0};
}

double clearcoatWeight(const MaterialInfo& material, double NoV)
{
    const double clearcoat = std::clamp(material.clearcoat, 0.0, 1.0);
    return clearcoat * F_Schlick(f0FromIor(kClearcoatIor), 1.0, std::clamp(NoV, 0.0, 1.0));
}

double MaterialBrdf::couplingFactor(
    const DielectricReflectance& layer, double NoV, double NoL, double perceptualRoughness) const
{
    // Energy-preserving coupling [Kelemen & Szirmay-Kalos 2001; Kulla & Conty 2017]: the diffuse
    // base sees what the specular layer leaves on the way in and on the way out,
    //     f_d = c / pi * (1 - E_s(mu_o)) (1 - E_s(mu_i)) / (1 - E_s,avg),
    // which is reciprocal and whose albedo is exactly c (1 - E_s(mu_o)): a white material's
    // albedo is E_s + (1 - E_s) = 1. A tinted layer (KHR_materials_specular) couples through its
    // largest channel, as fresnel_mix's max_value does.
    const double f0 = layer.maxF0();
    const double avg = dielectricSpecularAverageAlbedo(f0, perceptualRoughness, layer.f90);
    const double eo = dielectricSpecularAlbedo(f0, NoV, perceptualRoughness, layer.f90);
    const double ei = dielectricSpecularAlbedo(f0, NoL, perceptualRoughness, layer.f90);
    return std::max(0.0, (1.0 - eo)) * std::max(0.0, (1.0 - ei)) / std::max(1.0 - avg, 1e-6);
}

} // namespace facet

namespace facet {

glm::dvec3 directionalAlbedo(
    const MaterialBrdf& brdf, const MaterialInfo& material, double NoV, int sampleCount, LightingKind kind)
{
    NoV = std::clamp(NoV, 1e-6, 1.0);
    const glm::dvec3 n(0.0, 0.0, 1.0);
    const glm::dvec3 v(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
    // The specular strategy is the anisotropic lobe's where the material is (its direction in
    // the space of n = +Z).
    const SpecularLobeSampler specular(
        n, v, material.perceptualRoughness, material.anisotropy, material.anisotropyDirection);
    // A coat adds its own lobe as a third strategy (the balance heuristic over all three).
    const bool coated = material.clearcoat > 0.0;
    const double coatAlpha = alphaFromRoughness(material.clearcoatRoughness);
    const auto count = std::uint32_t(std::max(sampleCount, 1));
    auto mixturePdf = [&](const glm::dvec3& l) {
        const glm::dvec3 h = glm::normalize(v + l);
        double pdf = sampling::pdfCosineHemisphere(l.z) + specular.pdf(l);
        if (coated)
            pdf += sampling::pdfVNDFReflection(NoV, h.z, coatAlpha);
        return pdf;
    };
    glm::dvec3 sum(0.0);
    for (std::uint32_t i = 0; i < count; ++i) {
        const glm::dvec2 u = sampling::hammersley(i, count);
        const glm::dvec3 candidates[3] = {
            sampling::sampleCosineHemisphere(u),
            specular.sample(u),
            coated ? sampling::reflectAbout(v, sampling::importanceSampleVNDF(u, v, coatAlpha))
                   : glm::dvec3(0.0, 0.0, -1.0),
        };
        for (const glm::dvec3& l : candidates) {
            if (l.z <= 0.0)
                continue;
            const double pdf = mixturePdf(l);
            if (pdf > 0.0)
                sum += brdf.evaluate(material, n, v, l, kind).total() * (l.z / pdf);
        }
    }
    return sum / double(count);
}

} // namespace facet
