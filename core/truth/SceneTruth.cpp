#include "core/truth/SceneTruth.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

#include <glm/geometric.hpp>

#include "core/ibl/EnvironmentSampler.h"
#include "core/shading/BrdfSampler.h"
#include "core/shading/GroundTruth.h" // albedoTable
#include "core/shading/LightIrradiance.h"
#include "core/shading/MaterialInputs.h" // surfaceAnisotropyDirection
#include "core/shading/ReferenceView.h"
#include "core/shading/Sampling.h"
#include "core/support/Parallel.h"

namespace facet {

namespace {

// Bounces before Russian roulette may end a path.
constexpr int kRouletteDepth = 3;

bool isUsable(const glm::dvec3& c)
{
    return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
}

// How far along its geometric normal a ray leaving a hit starts, so that it does not meet the
// surface it leaves (Embree intersects in single precision).
double offsetFor(const glm::dvec3& position)
{
    return 1e-4 * (1.0 + std::max({std::abs(position.x), std::abs(position.y), std::abs(position.z)}));
}

struct Tracer {
    const SceneTruthScene& scene;
    const SceneTruthSettings& settings;
    std::vector<std::unique_ptr<MaterialBrdf>> brdfs; // per surface
    std::vector<std::shared_ptr<const DfgTable>> tables; // what the brdfs read
    EnvironmentSampler environment;

    Tracer(const SceneTruthScene& s, const SceneTruthSettings& t)
        : scene(s)
        , settings(t)
        , environment(s.environment)
    {
        for (const SceneTruthSurface& surface : scene.surfaces) {
            tables.push_back(
                albedoTable(settings.albedoTableSize, settings.albedoTableSamples, surface.model.visibility));
            brdfs.push_back(std::make_unique<MaterialBrdf>(surface.model, *tables.back()));
        }
    }

    // `first`: the points the first surface's environment and BRDF strategies draw with (the
    // pixel's stratified ones); deeper surfaces draw from rng.
    glm::dvec3 radiance(glm::dvec3 origin, glm::dvec3 direction, const std::array<glm::dvec2, 2>& first,
        sampling::Pcg32& rng, std::uint64_t& traced) const
    {
        glm::dvec3 sum(0.0);
        glm::dvec3 throughput(1.0);
        // The BRDF strategy's density of the direction that led here; 0 for the camera's ray,
        // which no other strategy could have drawn.
        double previousPdf = 0.0;
        for (int bounce = 0; bounce <= settings.maxBounces; ++bounce) {
            ++traced;
            const std::optional<RayHit> hit = scene.geometry.intersect(origin, direction);
            if (!hit) {
                const double weight
                    = previousPdf > 0.0 ? powerHeuristic(previousPdf, environment.pdf(direction)) : 1.0;
                const glm::dvec3 contribution = throughput * scene.environment.radiance(direction) * weight;
                if (isUsable(contribution))
                    sum += contribution;
                break;
            }
            if (hit->surface < 0 || std::size_t(hit->surface) >= scene.surfaces.size())
                break;
            const SceneTruthSurface& surface = scene.surfaces[std::size_t(hit->surface)];
            const MaterialBrdf& brdf = *brdfs[std::size_t(hit->surface)];
            const glm::dvec3 v = -direction;
            // The shading normal, unless it turns away from the viewer (an interpolated normal can
            // near a silhouette): the geometric one then.
            glm::dvec3 n = hit->shadingNormal;
            if (glm::dot(n, v) <= 0.0)
                n = hit->geometricNormal;
            MaterialInfo material = surface.material;
            if (material.anisotropy > 0.0 && material.anisotropyDirection == glm::dvec3(0.0))
                material.anisotropyDirection
                    = surfaceAnisotropyDirection(n, hit->tangent, material.anisotropyTangentDirection);
            const double NoV = std::clamp(glm::dot(n, v), 0.0, 1.0);
            // Emission, where the path meets it (nothing samples emitters directly).
            sum += throughput * material.emissive * (1.0 - clearcoatWeight(material, NoV));

            const BrdfSampler brdfSampler(material, brdf, n, v);
            const glm::dvec3 leave = hit->position + offsetFor(hit->position) * hit->geometricNormal;

            // The environment, by its own distribution and a shadow ray.
            {
                double pdf = 0.0;
                const glm::dvec3 l = environment.sample(bounce == 0 ? first[0] : rng.next2D(), &pdf);
                const double NoL = glm::dot(n, l);
                if (NoL > 0.0 && pdf > 0.0 && glm::dot(hit->geometricNormal, l) > 0.0) {
                    ++traced;
                    if (!scene.geometry.occluded(leave, l)) {
                        const double weight = powerHeuristic(pdf, brdfSampler.pdf(l));
                        const glm::dvec3 contribution = throughput
                            * brdfSampler.f(l, LightingKind::Environment) * scene.environment.radiance(l)
                            * (NoL * weight / pdf);
                        if (isUsable(contribution))
                            sum += contribution;
                    }
                }
            }
            // Every punctual light, a shadow ray each.
            for (const Light& light : scene.lights) {
                LightIrradiance arriving;
                if (!lightIrradiance(light, hit->position, &arriving))
                    continue;
                const glm::dvec3 l = arriving.toLight;
                const double NoL = glm::dot(n, l);
                if (NoL <= 0.0 || glm::dot(hit->geometricNormal, l) <= 0.0)
                    continue;
                ++traced;
                if (scene.geometry.occluded(leave, l, 0.0, arriving.distance))
                    continue;
                const glm::dvec3 contribution
                    = throughput * brdfSampler.f(l, LightingKind::Punctual) * arriving.irradiance * NoL;
                if (isUsable(contribution))
                    sum += contribution;
            }

            // The path goes on in a direction of the BRDF strategy.
            const glm::dvec3 l = brdfSampler.sample(bounce == 0 ? first[1] : rng.next2D());
            const double pdf = brdfSampler.pdf(l);
            const double NoL = glm::dot(n, l);
            if (pdf <= 0.0 || NoL <= 0.0 || glm::dot(hit->geometricNormal, l) <= 0.0)
                break;
            throughput *= brdfSampler.f(l, LightingKind::Environment) * (NoL / pdf);
            if (!isUsable(throughput) || throughput == glm::dvec3(0.0))
                break;
            if (bounce >= kRouletteDepth) {
                const double survive = std::min(std::max({throughput.r, throughput.g, throughput.b}), 0.95);
                if (survive <= 0.0 || rng.nextDouble() >= survive)
                    break;
                throughput /= survive;
            }
            previousPdf = pdf;
            origin = leave;
            direction = l;
        }
        return sum;
    }
};

} // namespace

Image renderSceneTruth(
    const SceneTruthScene& scene, const SceneTruthSettings& settings, SceneTruthStats* stats)
{
    const auto start = std::chrono::steady_clock::now();
    const Tracer tracer(scene, settings);
    Image image(settings.width, settings.height, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    std::atomic<std::uint64_t> rays {0};
    const int samples = std::max(settings.samplesPerPixel, 1);
    parallelFor(
        std::size_t(settings.height),
        [&](std::size_t row) {
            const int y = int(row);
            std::uint64_t traced = 0;
            for (int x = 0; x < settings.width; ++x) {
                const glm::dvec3 direction
                    = referenceview::rayDirection(x, y, settings.width, settings.height);
                sampling::Pcg32 rng(
                    settings.seed, std::uint64_t(y) * std::uint64_t(settings.width) + std::uint64_t(x));
                // Randomised quasi-Monte Carlo at the first surface, as the sphere's truth draws
                // (core/shading/GroundTruth.cpp): the N Hammersley points, shifted per pixel and
                // strategy modulo 1; the bounces after it draw independent points.
                const glm::dvec2 environmentShift = rng.next2D();
                const glm::dvec2 brdfShift = rng.next2D();
                const auto point = [samples](int i, const glm::dvec2& shift) {
                    const glm::dvec2 u
                        = sampling::hammersley(std::uint32_t(i), std::uint32_t(samples)) + shift;
                    return glm::dvec2(u.x - std::floor(u.x), u.y - std::floor(u.y));
                };
                glm::dvec3 sum(0.0);
                for (int s = 0; s < samples; ++s)
                    sum += tracer.radiance(referenceview::kEye, direction,
                        {point(s, environmentShift), point(s, brdfShift)}, rng, traced);
                image.at(x, y) = glm::vec4(glm::vec3(sum / double(samples)), 1.0f);
            }
            rays += traced;
        },
        settings.threads);
    if (stats) {
        stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        stats->rays = rays;
    }
    return image;
}

} // namespace facet
