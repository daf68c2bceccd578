#include "core/shading/SplitSum.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/shading/Brdf.h"
#include "core/shading/Sampling.h"
#include "core/shading/Sheen.h"

namespace facet {

using namespace shading;

glm::dvec3 specularDominantDirection(const glm::dvec3& n, const glm::dvec3& R, double alpha)
{
    const double smoothness = std::clamp(1.0 - alpha, 0.0, 1.0);
    const double lerpFactor = smoothness * (std::sqrt(smoothness) + alpha);
    return glm::normalize(glm::mix(n, R, lerpFactor));
}

namespace {

// The specular lobe's multiple-scattering factor: the isotropic lobe's, or where the lighting says
// the lobe is anisotropic, its compensation's (shading::anisotropicCompensation).
glm::dvec3 compensation(const MaterialBrdf& brdf, const glm::dvec3& f0, double NoV, double roughness,
    const SplitSumLighting& lighting)
{
    if (const auto& c = lighting.anisotropicCompensation)
        return brdf.multiScatterFactor(f0, NoV, c->perceptualRoughness, c->weight);
    return brdf.multiScatterFactor(f0, NoV, roughness);
}

// The glTF composition's lobes: (1 - m) spec(F0_d, F90_d) + m spec(c), and the diffuse weight.
// Without KHR_materials_specular F90_d = 1 and the weight is (1 - F0_d) W; with it the base keeps
// 1 - max_value(F(v.h)), whose mean over the cosine lobe is (1 - F90) + (F90 - max F0) W.
BrdfLobes gltfLobes(const MaterialBrdf& brdf, const MaterialInfo& material, double NoV,
    const SplitSumLighting& lighting, const DfgValue& dfg)
{
    const ShadingModel& model = brdf.model();
    const double roughness = clampRoughness(material.perceptualRoughness);
    const double metallic = std::clamp(material.metallic, 0.0, 1.0);
    const glm::dvec3 baseColor = glm::max(material.baseColor, glm::dvec3(0.0));
    const DielectricReflectance layer = dielectricReflectance(material);
    BrdfLobes lobes;
    const glm::dvec3 msDielectric = compensation(brdf, layer.f0, NoV, roughness, lighting);
    const glm::dvec3 msMetal = compensation(brdf, baseColor, NoV, roughness, lighting);
    glm::dvec3 specularDielectric = (layer.f0 * dfg.scale + layer.f90 * dfg.bias) * msDielectric;
    glm::dvec3 specularMetal = (baseColor * dfg.scale + dfg.bias) * msMetal;
    const double f0 = layer.maxF0();
    double diffuseWeight = model.coupling == DielectricCoupling::EnergyPreserving
        ? std::max(0.0, 1.0 - brdf.dielectricSpecularAlbedo(f0, NoV, roughness, layer.f90))
        : (1.0 - layer.f90) + (layer.f90 - f0) * dfg.diffuseFresnelWeight;
    const double iridescence = std::clamp(material.iridescence, 0.0, 1.0);
    if (iridescence > 0.0) {
        // KHR_materials_iridescence: the film's Fresnel averaged over the lobe times the lobe's
        // albedo with F = 1, mixed in by its strength; the base keeps the mean of rgb_mix's
        // 1 - max_value(Firid) over the cosine lobe, or (energy-preserving) what the film's Schlick
        // layer leaves (docs/shading.md, "Iridescence").
        const double lobeAlbedo = dfg.scale + dfg.bias;
        if (metallic < 1.0) {
            specularDielectric = glm::mix(specularDielectric,
                filmLobeFresnel(material, layer.f0, NoV, roughness) * lobeAlbedo * msDielectric, iridescence);
            const DielectricReflectance film = filmLayer(material, layer.f0);
            const double filmWeight = model.coupling == DielectricCoupling::EnergyPreserving
                ? std::max(0.0, 1.0 - brdf.dielectricSpecularAlbedo(film.maxF0(), NoV, roughness, film.f90))
                : 1.0 - filmDiffuseFresnel(material, layer.f0, NoV).meanMax;
            diffuseWeight = glm::mix(diffuseWeight, filmWeight, iridescence);
        }
        if (metallic > 0.0)
            specularMetal = glm::mix(specularMetal,
                filmLobeFresnel(material, baseColor, NoV, roughness) * lobeAlbedo * msMetal, iridescence);
    }
    lobes.specular = lighting.prefilteredRadiance * glm::mix(specularDielectric, specularMetal, metallic);
    lobes.diffuse = lighting.irradiance * kInvPi * baseColor * (diffuseWeight * (1.0 - metallic));
    return lobes;
}

// LearnOpenGL's: F0 = mix(F0_d, c, m), F90 = mix(F90_d, 1, m), spec(F0, F90), kD from F or E_s.
BrdfLobes learnOpenGlLobes(const MaterialBrdf& brdf, const MaterialInfo& material, double NoV,
    const SplitSumLighting& lighting, const DfgValue& dfg)
{
    const double roughness = clampRoughness(material.perceptualRoughness);
    const double metallic = std::clamp(material.metallic, 0.0, 1.0);
    const glm::dvec3 baseColor = glm::max(material.baseColor, glm::dvec3(0.0));
    const DielectricReflectance layer = dielectricReflectance(material);
    const glm::dvec3 f0 = glm::mix(layer.f0, baseColor, metallic);
    const double f90 = layer.f90 + (1.0 - layer.f90) * metallic;
    BrdfLobes lobes;
    const glm::dvec3 ms = compensation(brdf, f0, NoV, roughness, lighting);
    glm::dvec3 specular = (f0 * dfg.scale + f90 * dfg.bias) * ms;
    const bool energyPreserving = brdf.model().coupling == DielectricCoupling::EnergyPreserving;
    glm::dvec3 kD = energyPreserving
        ? glm::dvec3((1.0 - brdf.dielectricSpecularAlbedo(layer.maxF0(), NoV, roughness, layer.f90))
            * (1.0 - metallic))
        : ((1.0 - f90) + (f90 - f0) * dfg.diffuseFresnelWeight) * (1.0 - metallic);
    const double iridescence = std::clamp(material.iridescence, 0.0, 1.0);
    if (iridescence > 0.0) {
        // The film's Fresnel mixed into F (and so into kD = (1 - F)(1 - m)), each averaged over its
        // lobe.
        specular = glm::mix(
            specular, filmLobeFresnel(material, f0, NoV, roughness) * (dfg.scale + dfg.bias) * ms, iridescence);
        if (!energyPreserving)
            kD = glm::mix(kD, (1.0 - filmDiffuseFresnel(material, f0, NoV).mean) * (1.0 - metallic), iridescence);
    }
    lobes.specular = lighting.prefilteredRadiance * specular;
    lobes.diffuse = lighting.irradiance * kInvPi * baseColor * kD;
    return lobes;
}

} // namespace

glm::dvec3 filmLobeFresnel(
    const MaterialInfo& material, const glm::dvec3& f0, double NoV, double perceptualRoughness, int samples)
{
    NoV = std::clamp(NoV, 1e-4, 1.0);
    const double alpha = alphaFromRoughness(perceptualRoughness);
    const glm::dvec3 v(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
    const double lambdaV = 1.0 / sampling::G1_SmithGGX(NoV, alpha) - 1.0;
    const auto count = std::uint32_t(std::max(samples, 1));
    glm::dvec3 sum(0.0);
    double weights = 0.0;
    for (std::uint32_t i = 0; i < count; ++i) {
        const glm::dvec3 h = sampling::importanceSampleVNDF(sampling::hammersley(i, count), v, alpha);
        const glm::dvec3 l = sampling::reflectAbout(v, h);
        if (l.z <= 0.0)
            continue;
        // G2 / G1(v) of the height-correlated Smith: (1 + Lambda_v) / (1 + Lambda_v + Lambda_l).
        const double lambdaL = 1.0 / sampling::G1_SmithGGX(l.z, alpha) - 1.0;
        const double weight = (1.0 + lambdaV) / (1.0 + lambdaV + lambdaL);
        sum += weight * filmFresnel(material, f0, glm::dot(v, h));
        weights += weight;
    }
    return weights > 0.0 ? sum / weights : filmFresnel(material, f0, NoV);
}

FilmDiffuseFresnel filmDiffuseFresnel(const MaterialInfo& material, const glm::dvec3& f0, double NoV, int samples)
{
    NoV = std::clamp(NoV, 1e-4, 1.0);
    const glm::dvec3 v(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
    const auto count = std::uint32_t(std::max(samples, 1));
    FilmDiffuseFresnel result;
    for (std::uint32_t i = 0; i < count; ++i) {
        const glm::dvec3 l = sampling::sampleCosineHemisphere(sampling::hammersley(i, count));
        const glm::dvec3 firid = filmFresnel(material, f0, glm::dot(v, glm::normalize(v + l)));
        result.mean += firid;
        result.meanMax += std::max({firid.r, firid.g, firid.b});
    }
    result.mean /= double(count);
    result.meanMax /= double(count);
    return result;
}

BrdfLobes splitSumRadiance(const MaterialBrdf& brdf, const DfgTable& table, const MaterialInfo& material,
    double NoV, const SplitSumLighting& lighting)
{
    // Mirrors splitSumEnvironmentLobes() in resources/shaders/environment_lighting.glsl line by
    // line; the tables are looked up as the shader's dfgLookup() does (the same table, bilinear).
    NoV = std::clamp(NoV, 0.0, 1.0);
    const DfgValue dfg = table.sample(NoV, clampRoughness(material.perceptualRoughness));
    BrdfLobes lobes = brdf.model().composition == BrdfComposition::LearnOpenGL
        ? learnOpenGlLobes(brdf, material, NoV, lighting, dfg)
        : gltfLobes(brdf, material, NoV, lighting, dfg);
    if (material.hasSheen()) {
        // The sheen: its albedo E(n.v, r_s) times its lobe's light; the base keeps its lobes' mean
        // scaling: 1 - max3(c) E(n.v) for the specular, 1 - max3(c) Emax(n.v) for the diffuse.
        const shading::SheenAlbedoTable& sheenTable = shading::sheenAlbedoTable();
        const double r = std::clamp(material.sheenRoughness, 0.0, 1.0);
        const double e = sheenTable.sample(NoV, r);
        const glm::dvec3 color = glm::max(material.sheenColor, glm::dvec3(0.0));
        const double strength = std::max({color.r, color.g, color.b});
        lobes.diffuse *= std::max(1.0 - strength * sheenTable.sampleDiffuse(NoV, r), 0.0);
        lobes.specular *= std::max(1.0 - strength * e, 0.0);
        lobes.sheen = lighting.sheenRadiance * color * e;
    }
    if (material.clearcoat > 0.0) {
        // The coat: its prefiltered light times its lobe's albedo with F = 1, weighted by w_c.
        const double coatNoV = std::clamp(lighting.coatNoV, 0.0, 1.0);
        const double weight = clearcoatWeight(material, coatNoV);
        lobes.diffuse *= 1.0 - weight;
        lobes.specular *= 1.0 - weight;
        lobes.sheen *= 1.0 - weight;
        lobes.coat = lighting.coatPrefilteredRadiance
            * (table.sample(coatNoV, clampRoughness(material.clearcoatRoughness)).albedo() * weight);
    }
    return lobes;
}

} // namespace facet
