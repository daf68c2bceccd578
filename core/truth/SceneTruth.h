#pragma once
// The ground truth of staged scenes: a path tracer over a RayScene (core/truth/RayScene.h; the
// reference sphere, meshes, a floor), lit by the environment and the punctual lights, that sees
// occlusion (shadow rays) and light between surfaces (bounces). The convex-object truth
// (core/shading/GroundTruth.h) is its special case: one sphere and nothing else, which this
// integrator renders within its noise (SceneTruthTest).
//
// Estimator (docs/accuracy.md, "Scenes"): from the reference view's camera, one ray through each
// pixel centre; at each hit, next-event estimation of the environment (one direction from its
// luminance distribution, a shadow ray, weighed against the BRDF strategy by the power heuristic)
// and of every punctual light (a shadow ray each); then a direction from the BRDF strategy
// (core/shading/BrdfSampler.h) continues the path, and where it escapes the environment it sees is
// weighed against the environment strategy. Emission counts where a path meets it. Paths end by
// Russian roulette after 3 bounces (survival from the path's throughput, unbiased) or
// at maxBounces. Deterministic: pixel i draws from PCG32 stream i of `seed`.

#include <cstdint>
#include <vector>

#include "core/ibl/Environment.h"
#include "core/image/Image.h"
#include "core/project/Light.h"
#include "core/shading/MaterialBrdf.h"
#include "core/truth/RayScene.h"

namespace facet {

struct SceneTruthSurface {
    // Constant inputs (a texture-mapped material is not a ground truth's input yet).
    MaterialInfo material;
    ShadingModel model;
};

struct SceneTruthScene {
    RayScene geometry; // committed
    std::vector<SceneTruthSurface> surfaces; // one per geometry surface, in its numbering
    Environment environment; // must not be empty
    std::vector<Light> lights;
};

struct SceneTruthSettings {
    int width = 256;
    int height = 256;
    int samplesPerPixel = 256;
    std::uint64_t seed = 1;
    int threads = 0; // 0: all cores
    // Surfaces a path may meet after the camera's. Light inside glass bounces long: a rough glass
    // sphere's rim lost 1.8% of a uniform environment's light at 16, none measurable at 64.
    int maxBounces = 64;
    int albedoTableSize = 64; // the albedo tables of compensation and coupling, as GroundTruthSettings
    int albedoTableSamples = 2048;
};

struct SceneTruthStats {
    double seconds = 0.0;
    std::uint64_t rays = 0; // intersection and shadow rays traced
};

// Linear radiance (alpha 1); a pixel that sees no surface shows the environment.
Image renderSceneTruth(
    const SceneTruthScene& scene, const SceneTruthSettings& settings, SceneTruthStats* stats = nullptr);

} // namespace facet
