#include "core/shading/SplitSum.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/shading/Brdf.h"

namespace facet {

using namespace shading;

glm::dvec3 specularDominantDirection(const glm::dvec3& n, const glm::dvec3& R, double alpha)
{
    const double smoothness = std::clamp(1.0 - alpha, 0.0, 1.0);
    const double lerpFactor = smoothness * (std::sqrt(smoothness) + alpha);
    return glm::normalize(glm::mix(n, R, lerpFactor));
}

BrdfLobes splitSumRadiance(const MaterialBrdf& brdf, const DfgTable& table, const MaterialInfo& material,
    double NoV, const SplitSumLighting& lighting)
{
    // Mirrors environmentLobes() in resources/shaders/environment_lighting.glsl line by line.
    const ShadingModel& model = brdf.model();
    NoV = std::clamp(NoV, 0.0, 1.0);
    const double roughness = clampRoughness(material.perceptualRoughness);
    const double metallic = std::clamp(material.metallic, 0.0, 1.0);
    const glm::dvec3 baseColor = glm::max(material.baseColor, glm::dvec3(0.0));
    const glm::dvec3 diffuseLight = lighting.irradiance * kInvPi;
    const DfgValue dfg = table.sample(NoV, roughness);
    const auto albedoSingleScatter = [&dfg](const glm::dvec3& f0) { return f0 * dfg.scale + dfg.bias; };
    const double f0Dielectric = f0FromIor(material.ior);
    // The table lookup the shader does through dfgLookup(): the same table, bilinear.
    const double es = brdf.dielectricSpecularAlbedo(f0Dielectric, NoV, roughness);

    BrdfLobes lobes;
    if (model.composition == BrdfComposition::LearnOpenGL) {
        const glm::dvec3 f0 = glm::mix(glm::dvec3(f0Dielectric), baseColor, metallic);
        const glm::dvec3 albedo = albedoSingleScatter(f0);
        lobes.specular = lighting.prefilteredRadiance * albedo * brdf.multiScatterFactor(f0, NoV, roughness);
        const glm::dvec3 kD = model.coupling == DielectricCoupling::EnergyPreserving
            ? glm::dvec3((1.0 - es) * (1.0 - metallic))
            : (glm::dvec3(1.0) - f0) * (dfg.diffuseFresnelWeight * (1.0 - metallic));
        lobes.diffuse = diffuseLight * baseColor * kD;
        return lobes;
    }
    const double specularDielectric = albedoSingleScatter(glm::dvec3(f0Dielectric)).x
        * brdf.multiScatterFactor(glm::dvec3(f0Dielectric), NoV, roughness).x;
    const glm::dvec3 specularMetal
        = albedoSingleScatter(baseColor) * brdf.multiScatterFactor(baseColor, NoV, roughness);
    lobes.specular
        = lighting.prefilteredRadiance * glm::mix(glm::dvec3(specularDielectric), specularMetal, metallic);
    const double diffuseWeight = model.coupling == DielectricCoupling::EnergyPreserving
        ? std::max(0.0, 1.0 - es)
        : (1.0 - f0Dielectric) * dfg.diffuseFresnelWeight;
    lobes.diffuse = diffuseLight * baseColor * (diffuseWeight * (1.0 - metallic));
    return lobes;
}

} // namespace facet
