#pragma once
// The ground truth: a brute-force Monte Carlo integrator of the rendering equation for the
// reference view (core/shading/ReferenceView.h) of one material on the unit sphere, lit by an
// environment and punctual lights. It is slow on purpose and it is what every real-time
// approximation in Facet is measured against (docs/accuracy.md).
//
// Estimator: for each pixel, `samplesPerPixel` iterations, each taking one direction from the
// BRDF (visible-normal GGX sampling for the specular lobe, cosine sampling for the diffuse lobe,
// picked by their approximate albedos) and one from the environment's luminance distribution,
// combined by multiple importance sampling with the power heuristic [Veach 1997, ch. 9]. The
// sample points are Hammersley points with a random per-pixel shift (randomised quasi-Monte
// Carlo), so the estimate is unbiased and converges faster than independent random samples.
// Punctual lights are delta lights, added exactly once per pixel. The sphere is convex, so
// nothing is occluded. Deterministic: pixel i draws from PCG32 stream i of `seed`, so the image
// does not depend on the thread count.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/ibl/Environment.h"
#include "core/image/Image.h"
#include "core/material/Material.h" // AlphaMode
#include "core/project/Light.h"
#include "core/shading/MaterialBrdf.h"

namespace facet {

struct GroundTruthSettings {
    int width = 256;
    int height = 256;
    int samplesPerPixel = 256;
    std::uint64_t seed = 1;
    int threads = 0; // 0: all cores
    // LambertOnly replaces the material by a pure Lambert lobe of the base colour (tests of the
    // diffuse integral against brute-force irradiance).
    enum class Lobes { Material, LambertOnly } lobes = Lobes::Material;
    // Size and sample count of the albedo table used by multi-scatter compensation and the
    // energy-preserving coupling; high enough that its own error is far below the test bounds.
    int albedoTableSize = 64;
    int albedoTableSamples = 2048;
};

struct GroundTruthScene {
    MaterialInfo material; // material.emissive adds to every hit; alpha counts for AlphaMode::Mask
    ShadingModel model;
    AlphaMode alphaMode = AlphaMode::Opaque; // Mask: alpha < alphaCutoff shows the environment
    double alphaCutoff = 0.5;
    // KHR_materials_unlit: the hit's radiance is material.baseColor, nothing integrated (the
    // shader's MATERIAL_UNLIT twin).
    bool unlit = false;
    // BackgroundMode::Transparent: pixels that miss the sphere are (0, 0, 0, 0) instead of the
    // environment, so alpha is the object's coverage.
    bool transparentBackground = false;
    Environment environment; // must not be empty
    std::vector<Light> lights;
};

struct GroundTruthStats {
    double seconds = 0.0;
    std::uint64_t samples = 0; // BRDF + environment samples taken
};

// The albedo table the integrator uses for `visibility`, computed once per process and shared.
std::shared_ptr<const DfgTable> albedoTable(int size, int samples, Visibility visibility);

// Renders linear radiance (alpha 1). Background pixels show the environment (bilinear), as the
// real-time renderer's reference view does, or nothing with alpha 0 (transparentBackground).
Image renderGroundTruth(
    const GroundTruthScene& scene, const GroundTruthSettings& settings, GroundTruthStats* stats = nullptr);

// The radiance leaving the sphere's point `n` (unit, also the position) towards `v` (unit):
// the integrand of one pixel, exposed for tests that need a single shading point.
glm::dvec3 integrateOutgoingRadiance(const GroundTruthScene& scene, const MaterialBrdf& brdf,
    const class EnvironmentSampler& sampler, const glm::dvec3& n, const glm::dvec3& v, int samples,
    std::uint64_t seed, std::uint64_t stream,
    GroundTruthSettings::Lobes lobes = GroundTruthSettings::Lobes::Material);

} // namespace facet

namespace facet {

struct Project;

// The ground-truth scene for a project: its material's constant inputs (factors, IOR, shading
// model), its environment (Environment::fromSpec of the project's source, with rotation and
// intensity) and its lights. The integrator renders the reference sphere with constant inputs:
// a material with texture maps is refused with a message saying so.
std::optional<GroundTruthScene> groundTruthSceneFromProject(
    const Project& project, std::string* error, std::string* warning = nullptr);

} // namespace facet
