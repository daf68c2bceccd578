#include "core/shading/GroundTruth.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <mutex>
#include <tuple>

#include <glm/geometric.hpp>

#include "core/ibl/EnvironmentSampler.h"
#include "core/project/Project.h"
#include "core/project/ProjectAssets.h"
#include "core/shading/Anisotropy.h"
#include "core/shading/Brdf.h"
#include "core/shading/BrdfSampler.h"
#include "core/shading/LightIrradiance.h"
#include "core/shading/MaterialInputs.h"
#include "core/shading/Punctual.h"
#include "core/shading/ReferenceView.h"
#include "core/shading/Sampling.h"
#include "core/support/Parallel.h"

namespace facet {

std::shared_ptr<const DfgTable> albedoTable(int size, int samples, Visibility visibility)
{
    // Computing a 64 x 64 table at 2048 samples takes about a second: keep the ones made.
    static std::mutex mutex;
    static std::map<std::tuple<int, int, Visibility>, std::shared_ptr<const DfgTable>> cache;
    const std::lock_guard lock(mutex);
    auto& slot = cache[{size, samples, visibility}];
    if (!slot)
        slot = std::make_shared<const DfgTable>(DfgTable::compute(size, samples, visibility));
    return slot;
}

glm::dvec3 integrateOutgoingRadiance(const GroundTruthScene& scene, const MaterialBrdf& brdf,
    const EnvironmentSampler& sampler, const glm::dvec3& n, const glm::dvec3& v, int samples,
    std::uint64_t seed, std::uint64_t stream, GroundTruthSettings::Lobes lobes)
{
    if (scene.unlit)
        return scene.material.baseColor;
    // An anisotropic material without a direction of its own takes the sphere's tangent frame,
    // the mesh's the real-time renderer draws (ReferenceView.h sphereTangent).
    MaterialInfo material = scene.material;
    if (material.anisotropy > 0.0 && material.anisotropyDirection == glm::dvec3(0.0))
        material.anisotropyDirection = surfaceAnisotropyDirection(
            n, referenceview::sphereTangent(n), material.anisotropyTangentDirection);
    const Environment& environment = scene.environment;
    const bool lambertOnly = lobes == GroundTruthSettings::Lobes::LambertOnly;
    const double NoV = std::clamp(glm::dot(n, v), 0.0, 1.0);
    const BrdfSampler strategy(
        material, brdf, n, v, lambertOnly ? BrdfSampler::Mode::LambertOnly : BrdfSampler::Mode::Full);

    // Randomised quasi-Monte Carlo: the N Hammersley points, shifted per pixel and strategy by a
    // random offset modulo 1 (Cranley-Patterson rotation). Unbiased like plain Monte Carlo, and
    // its error falls faster than 1/sqrt(N) on these smooth integrands (docs/accuracy.md).
    sampling::Pcg32 rng(seed, stream);
    const glm::dvec2 brdfShift = rng.next2D();
    const glm::dvec2 environmentShift = rng.next2D();
    const auto count = std::uint32_t(std::max(samples, 1));
    auto point = [count](std::uint32_t i, const glm::dvec2& shift) {
        return sampling::shiftedHammersley(i, count, shift);
    };
    glm::dvec3 sum(0.0);
    for (std::uint32_t s = 0; s < count; ++s) {
        // BRDF strategy.
        {
            const glm::dvec3 l = strategy.sample(point(s, brdfShift));
            const double NoL = glm::dot(n, l);
            const double pdf = strategy.pdf(l);
            if (NoL > 0.0 && pdf > 0.0) {
                const double weight = powerHeuristic(pdf, sampler.pdf(l));
                const glm::dvec3 contribution = strategy.f(l, LightingKind::Environment)
                    * environment.radiance(l) * (NoL * weight / pdf);
                if (sampling::isFinite(contribution))
                    sum += contribution;
            }
        }
        // Environment strategy.
        {
            double pdf = 0.0;
            const glm::dvec3 l = sampler.sample(point(s, environmentShift), &pdf);
            const double NoL = glm::dot(n, l);
            if (NoL > 0.0 && pdf > 0.0) {
                const double weight = powerHeuristic(pdf, strategy.pdf(l));
                const glm::dvec3 contribution = strategy.f(l, LightingKind::Environment)
                    * environment.radiance(l) * (NoL * weight / pdf);
                if (sampling::isFinite(contribution))
                    sum += contribution;
            }
        }
    }
    glm::dvec3 radiance = sum / double(count);
    // Emission is part of the outgoing radiance (the rendering equation's L_e term); a coat lets
    // through 1 - clearcoatWeight of it (KHR_materials_clearcoat's coated_emission).
    if (!lambertOnly)
        radiance += material.emissive * (1.0 - clearcoatWeight(material, NoV));

    // Punctual lights: the position on the unit sphere is its normal.
    for (const Light& light : scene.lights) {
        LightIrradiance arriving;
        if (!lightIrradiance(light, n, &arriving))
            continue;
        const double NoL = glm::dot(n, arriving.toLight);
        if (NoL > 0.0)
            radiance += strategy.f(arriving.toLight, LightingKind::Punctual) * arriving.irradiance * NoL;
    }
    return radiance;
}

Image renderGroundTruth(
    const GroundTruthScene& scene, const GroundTruthSettings& settings, GroundTruthStats* stats)
{
    const auto start = std::chrono::steady_clock::now();
    const std::shared_ptr<const DfgTable> table
        = albedoTable(settings.albedoTableSize, settings.albedoTableSamples, scene.model.visibility);
    const MaterialBrdf brdf(scene.model, *table);
    const EnvironmentSampler sampler(scene.environment);
    Image image(settings.width, settings.height, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));

    parallelFor(
        std::size_t(settings.height),
        [&](std::size_t row) {
            const int y = int(row);
            for (int x = 0; x < settings.width; ++x) {
                const glm::dvec3 direction
                    = referenceview::rayDirection(x, y, settings.width, settings.height);
                glm::dvec3 radiance;
                // A masked-out material (constant alpha below the cutoff) lets the environment through.
                const bool culled
                    = scene.alphaMode == AlphaMode::Mask && scene.material.alpha < scene.alphaCutoff;
                const auto hit = culled ? std::nullopt : referenceview::intersectSphere(direction);
                if (hit) {
                    const std::uint64_t stream
                        = std::uint64_t(y) * std::uint64_t(settings.width) + std::uint64_t(x);
                    radiance = integrateOutgoingRadiance(scene, brdf, sampler, *hit, -direction,
                        settings.samplesPerPixel, settings.seed, stream, settings.lobes);
                } else if (scene.transparentBackground) {
                    image.at(x, y) = glm::vec4(0.0f);
                    continue;
                } else {
                    radiance = scene.environment.radiance(direction);
                }
                image.at(x, y) = glm::vec4(glm::vec3(radiance), 1.0f);
            }
        },
        settings.threads);

    if (stats) {
        stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::uint64_t hits = 0;
        for (int y = 0; y < settings.height; ++y)
            for (int x = 0; x < settings.width; ++x)
                hits += referenceview::intersectSphere(
                            referenceview::rayDirection(x, y, settings.width, settings.height))
                    ? 1
                    : 0;
        stats->samples = hits * std::uint64_t(settings.samplesPerPixel) * 2u;
    }
    return image;
}

} // namespace facet

namespace facet {

std::optional<GroundTruthScene> groundTruthSceneFromProject(
    const Project& project, std::string* error, std::string* warning)
{
    const Material& material = project.material();
    for (MapSlot slot : kAllMapSlots) {
        if (material.map(slot).hasTexture() && material.usesSlot(slot)) {
            if (error)
                *error = std::string(
                             "groundTruthSceneFromProject: the ground truth renders constant materials only, "
                             "but the ")
                    + toString(slot) + " map uses '" + material.map(slot).path + "'";
            return std::nullopt;
        }
    }
    if (material.alphaMode == AlphaMode::Blend) {
        if (error)
            *error = "groundTruthSceneFromProject: the ground truth renders opaque and masked materials, not "
                     "alpha "
                     "mode \"blend\"";
        return std::nullopt;
    }
    GroundTruthScene scene;
    // No textures: the inputs are the factors, as materialInputs reads them anywhere.
    scene.material = materialInputs(material, MaterialMapImages {}, glm::dvec2(0.0));
    scene.alphaMode = material.alphaMode;
    scene.alphaCutoff = material.alphaCutoff;
    scene.unlit = material.unlit;
    scene.transparentBackground = project.view.background == BackgroundMode::Transparent;
    scene.model = material.shading;
    std::string environmentError;
    auto environment = Environment::fromSpec(project.environment.source, &environmentError, warning);
    if (!environment) {
        if (error)
            *error = environmentError;
        return std::nullopt;
    }
    placeEnvironment(*environment, project.environment);
    scene.environment = std::move(*environment);
    scene.lights = project.lights;
    return scene;
}

} // namespace facet
