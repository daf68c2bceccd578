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
#include "core/shading/ThinFilm.h" // wavelengthRgbWeight
#include "core/shading/Transmission.h"
#include "core/support/Parallel.h"

namespace facet {

namespace {

// Bounces before Russian roulette may end a path.
constexpr int kRouletteDepth = 3;
constexpr double kGoldenRatioFraction = 0.61803398874989484820; // (sqrt(5) - 1) / 2
constexpr double kSilverRatioFraction = 0.41421356237309504880; // sqrt(2) - 1

// How far along its geometric normal a ray leaving a hit starts, so that it does not meet the
// surface it leaves (Embree intersects in single precision).
double offsetFor(const glm::dvec3& position)
{
    return 1e-4 * (1.0 + std::max({std::abs(position.x), std::abs(position.y), std::abs(position.z)}));
}

// The points a pixel's sample draws its first surface's strategies with.
struct PathPoints {
    glm::dvec2 environment {0.5};
    glm::dvec2 brdf {0.5};
    double wavelength = 0.5; // in [0, 1): across the visible band
    double fresnel = 0.5; // in [0, 1): a transmitting surface's choice between reflection and transmission
};

struct Tracer {
    const SceneTruthScene& scene;
    const SceneTruthSettings& settings;
    std::vector<std::unique_ptr<MaterialBrdf>> brdfs; // per surface
    std::vector<std::shared_ptr<const DfgTable>> tables; // what the brdfs read
    EnvironmentSampler environment;
    std::vector<glm::dvec3> sigmas; // per surface: its volume's absorption coefficient

    Tracer(const SceneTruthScene& s, const SceneTruthSettings& t)
        : scene(s)
        , settings(t)
        , environment(s.environment)
    {
        for (const SceneTruthSurface& surface : scene.surfaces) {
            tables.push_back(
                albedoTable(settings.albedoTableSize, settings.albedoTableSamples, surface.model.visibility));
            brdfs.push_back(std::make_unique<MaterialBrdf>(surface.model, *tables.back()));
            // A volume's interface, both ways, for the compensation of its multiple scattering
            // (at the material's index: a dispersive one's wavelengths share it).
            const MaterialInfo& material = surface.material;
            if (material.hasTransmission() && !material.isThinWalled() && surface.model.multiScatter) {
                const double ior = std::max(material.ior, kMinRefractiveIor);
                const bool exact = surface.model.fresnel == Fresnel::Dielectric;
                brdfs.back()->setInterfaceTables(
                    std::make_shared<shading::InterfaceAlbedoTable>(1.0, ior, exact),
                    std::make_shared<shading::InterfaceAlbedoTable>(ior, 1.0, exact));
            }
            sigmas.push_back(shading::attenuationCoefficient(
                surface.material.attenuationColor, surface.material.attenuationDistance));
        }
    }

    // `first`: the points the first surface's environment and BRDF strategies draw with, and the
    // wavelength's (the pixel's stratified ones); deeper surfaces draw from rng.
    glm::dvec3 radiance(glm::dvec3 origin, glm::dvec3 direction, const PathPoints& first,
        sampling::Pcg32& rng, std::uint64_t& traced) const
    {
        glm::dvec3 sum(0.0);
        glm::dvec3 throughput(1.0);
        // The BRDF strategy's density of the direction that led here; 0 where no other strategy
        // could have drawn it (the camera's ray, a reflection inside a volume).
        double previousPdf = 0.0;
        // The surface whose volume the path travels through (-1: the air), and the wavelength
        // (nm) it carries once a dispersive surface drew one (0: none yet, all of them).
        int medium = -1;
        double lambda = 0.0;
        double etaScale = 1.0; // the product of the refractions' radiance scales, undone
        for (int bounce = 0; bounce <= settings.maxBounces; ++bounce) {
            ++traced;
            const std::optional<RayHit> hit = scene.geometry.intersect(origin, direction);
            if (medium >= 0 && hit)
                throughput *= shading::beerLambert(sigmas[std::size_t(medium)], hit->distance);
            if (!hit) {
                const double weight
                    = previousPdf > 0.0 ? powerHeuristic(previousPdf, environment.pdf(direction)) : 1.0;
                const glm::dvec3 contribution = throughput * scene.environment.radiance(direction) * weight;
                if (sampling::isFinite(contribution))
                    sum += contribution;
                break;
            }
            if (hit->surface < 0 || std::size_t(hit->surface) >= scene.surfaces.size())
                break;
            const SceneTruthSurface& surface = scene.surfaces[std::size_t(hit->surface)];
            const MaterialBrdf& brdf = *brdfs[std::size_t(hit->surface)];
            MaterialInfo material = surface.material;
            const bool volume = material.hasTransmission() && !material.isThinWalled();
            // Inside the volume this surface bounds, the path meets its boundary from behind.
            const bool interior = volume && medium == hit->surface && hit->backFace;
            if (volume && material.dispersion > 0.0) {
                // KHR_materials_dispersion: the path takes one wavelength from here on, weighted by
                // the colour it stands for (white on average over the band).
                if (lambda == 0.0) {
                    const double u = bounce == 0 ? first.wavelength : rng.nextDouble();
                    lambda = shading::kVisibleShortest
                        + (shading::kVisibleLongest - shading::kVisibleShortest) * u;
                    throughput *= shading::wavelengthRgbWeight(lambda);
                }
                material.ior = shading::dispersedIor(material.ior, material.dispersion, lambda);
            }
            const glm::dvec3 v = -direction;
            // The shading normal, unless it turns away from the viewer (an interpolated normal can
            // near a silhouette): the geometric one then.
            glm::dvec3 n = hit->shadingNormal;
            if (glm::dot(n, v) <= 0.0)
                n = hit->geometricNormal;
            const glm::dvec3& ng = hit->geometricNormal; // on v's side
            if (material.anisotropy > 0.0 && material.anisotropyDirection == glm::dvec3(0.0))
                material.anisotropyDirection
                    = surfaceAnisotropyDirection(n, hit->tangent, material.anisotropyTangentDirection);
            const double NoV = std::clamp(glm::dot(n, v), 0.0, 1.0);
            // Emission, where the path meets it (nothing samples emitters directly).
            if (!interior)
                sum += throughput * material.emissive * (1.0 - clearcoatWeight(material, NoV));

            const BrdfSampler brdfSampler(
                material, brdf, n, v, interior ? BrdfSampler::Mode::Interior : BrdfSampler::Mode::Full);
            // A direction the shading point can send light along: on one side of both normals, and
            // below only where the surface transmits; inside a volume the light next-event
            // estimation looks for lies outside it.
            const auto reaches = [&](const glm::dvec3& l, bool estimating) {
                const double NoL = glm::dot(n, l);
                if (NoL == 0.0 || (NoL > 0.0) != (glm::dot(ng, l) > 0.0))
                    return false;
                if (NoL < 0.0)
                    return brdfSampler.transmits();
                return !(estimating && interior);
            };
            const auto leaving = [&](const glm::dvec3& l) {
                const double offset = offsetFor(hit->position);
                return hit->position + (glm::dot(ng, l) > 0.0 ? offset : -offset) * ng;
            };

            // The environment, by its own distribution and a shadow ray.
            {
                double pdf = 0.0;
                const glm::dvec3 l = environment.sample(bounce == 0 ? first.environment : rng.next2D(), &pdf);
                if (pdf > 0.0 && reaches(l, true)) {
                    const glm::dvec3 f = brdfSampler.f(l, LightingKind::Environment);
                    if (f != glm::dvec3(0.0)) {
                        ++traced;
                        if (!scene.geometry.occluded(leaving(l), l)) {
                            const double weight = powerHeuristic(pdf, brdfSampler.pdf(l));
                            const glm::dvec3 contribution = throughput * f * scene.environment.radiance(l)
                                * (std::abs(glm::dot(n, l)) * weight / pdf);
                            if (sampling::isFinite(contribution))
                                sum += contribution;
                        }
                    }
                }
            }
            // Every punctual light, a shadow ray each.
            for (const Light& light : scene.lights) {
                LightIrradiance arriving;
                if (!lightIrradiance(light, hit->position, &arriving))
                    continue;
                const glm::dvec3 l = arriving.toLight;
                if (!reaches(l, true))
                    continue;
                const glm::dvec3 f = brdfSampler.f(l, LightingKind::Punctual);
                if (f == glm::dvec3(0.0))
                    continue;
                ++traced;
                if (scene.geometry.occluded(leaving(l), l, 0.0, arriving.distance))
                    continue;
                const glm::dvec3 contribution
                    = throughput * f * arriving.irradiance * std::abs(glm::dot(n, l));
                if (sampling::isFinite(contribution))
                    sum += contribution;
            }

            // The path goes on in a direction of the BRDF strategy.
            const glm::dvec3 l = bounce == 0 ? brdfSampler.sample(first.brdf, first.fresnel)
                                             : brdfSampler.sample(rng.next2D(), rng.nextDouble());
            const double pdf = brdfSampler.pdf(l);
            if (pdf <= 0.0 || !reaches(l, false))
                break;
            throughput *= brdfSampler.f(l, LightingKind::Environment) * (std::abs(glm::dot(n, l)) / pdf);
            if (!sampling::isFinite(throughput) || throughput == glm::dvec3(0.0))
                break;
            const bool crossed = glm::dot(n, l) < 0.0;
            if (crossed && volume) {
                medium = interior ? -1 : hit->surface;
                // Radiance refracted from index a into b is scaled by (a / b)^2 (docs/shading.md,
                // "Transmission"); the roulette looks past it, or every path inside glass would be
                // cut as if it carried 1 / n^2 of its light [PBRT 4th ed., 14.1.2].
                const double ratio
                    = interior ? material.ior : 1.0 / std::max(material.ior, kMinRefractiveIor);
                etaScale /= ratio * ratio;
            }
            if (bounce >= kRouletteDepth) {
                // Survival from the largest channel's magnitude (a wavelength's colour weight can
                // be negative in one channel), no roulette while it is 1 or more.
                const glm::dvec3 carried = throughput * etaScale;
                const double survive = std::min(
                    std::max({std::abs(carried.r), std::abs(carried.g), std::abs(carried.b)}), 1.0);
                if (survive <= 0.0 || rng.nextDouble() >= survive)
                    break;
                throughput /= survive;
            }
            previousPdf = interior && !crossed ? 0.0 : pdf;
            origin = leaving(l);
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
                const double wavelengthShift = rng.nextDouble();
                const double fresnelShift = rng.nextDouble();
                const auto point = [samples](int i, const glm::dvec2& shift) {
                    return sampling::shiftedHammersley(std::uint32_t(i), std::uint32_t(samples), shift);
                };
                glm::dvec3 sum(0.0);
                for (int s = 0; s < samples; ++s) {
                    // The wavelengths by the golden ratio's sequence, shifted per pixel: even over
                    // the band and, with the Hammersley points' first coordinate s / N, a lattice
                    // (not a diagonal that would tie each wavelength to one lobe).
                    // The choice between reflection and transmission alike, by another irrational
                    // (sqrt(2) - 1), so that it is no function of the wavelength's.
                    const double k = wavelengthShift + double(s) * kGoldenRatioFraction;
                    const double f = fresnelShift + double(s) * kSilverRatioFraction;
                    sum += tracer.radiance(referenceview::kEye, direction,
                        {point(s, environmentShift), point(s, brdfShift), k - std::floor(k),
                            f - std::floor(f)},
                        rng, traced);
                }
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
