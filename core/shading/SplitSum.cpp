#include "core/shading/SplitSum.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/shading/Brdf.h"
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

// The glTF composition's lobes: (1 - m) spec(F0_d) + m spec(c), and the diffuse weight.
BrdfLobes gltfLobes(const MaterialBrdf& brdf, const MaterialInfo& material, double NoV,
    const SplitSumLighting& lighting, const DfgValue& dfg)
{
    const ShadingModel& model = brdf.model();
    const double roughness = clampRoughness(material.perceptualRoughness);
    const double metallic = std::clamp(material.metallic, 0.0, 1.0);
    const glm::dvec3 baseColor = glm::max(material.baseColor, glm::dvec3(0.0));
    const auto albedoSingleScatter = [&dfg](const glm::dvec3& f0) { return f0 * dfg.scale + dfg.bias; };
    const double f0Dielectric = f0FromIor(material.ior);
    BrdfLobes lobes;
    const double specularDielectric = albedoSingleScatter(glm::dvec3(f0Dielectric)).x
        * brdf.multiScatterFactor(glm::dvec3(f0Dielectric), NoV, roughness).x;
    const glm::dvec3 specularMetal
        = albedoSingleScatter(baseColor) * brdf.multiScatterFactor(baseColor, NoV, roughness);
    lobes.specular
        = lighting.prefilteredRadiance * glm::mix(glm::dvec3(specularDielectric), specularMetal, metallic);
    const double diffuseWeight = model.coupling == DielectricCoupling::EnergyPreserving
        ? std::max(0.0, 1.0 - brdf.dielectricSpecularAlbedo(f0Dielectric, NoV, roughness))
        : (1.0 - f0Dielectric) * dfg.diffuseFresnelWeight;
    lobes.diffuse = lighting.irradiance * kInvPi * baseColor * (diffuseWeight * (1.0 - metallic));
    return lobes;
}

// LearnOpenGL's: F0 = mix(F0_d, c, m), spec(F0), kD from F0 or E_s.
BrdfLobes learnOpenGlLobes(const MaterialBrdf& brdf, const MaterialInfo& material, double NoV,
    const SplitSumLighting& lighting, const DfgValue& dfg)
{
    const double roughness = clampRoughness(material.perceptualRoughness);
    const double metallic = std::clamp(material.metallic, 0.0, 1.0);
    const glm::dvec3 baseColor = glm::max(material.baseColor, glm::dvec3(0.0));
    const double f0Dielectric = f0FromIor(material.ior);
    const glm::dvec3 f0 = glm::mix(glm::dvec3(f0Dielectric), baseColor, metallic);
    BrdfLobes lobes;
    lobes.specular = lighting.prefilteredRadiance * (f0 * dfg.scale + dfg.bias)
        * brdf.multiScatterFactor(f0, NoV, roughness);
    const glm::dvec3 kD = brdf.model().coupling == DielectricCoupling::EnergyPreserving
        ? glm::dvec3((1.0 - brdf.dielectricSpecularAlbedo(f0Dielectric, NoV, roughness)) * (1.0 - metallic))
        : (glm::dvec3(1.0) - f0) * (dfg.diffuseFresnelWeight * (1.0 - metallic));
    lobes.diffuse = lighting.irradiance * kInvPi * baseColor * kD;
    return lobes;
}

} // namespace

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
