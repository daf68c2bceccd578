#pragma once
// One case of the sampled IBL methods' GL tests (ReferenceGLTest, FisGLTest): a material of one
// BRDF composition on docs/architecture.md's reference sphere under an environment, as the project that
// both the GPU method and the CPU ground truth render.

#include <cstdint>
#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "core/image/Image.h"
#include "core/project/Project.h"
#include "core/shading/ShadingModel.h"

namespace facet::test {

struct IblMethodCase {
    const char* name;
    BrdfComposition composition = BrdfComposition::Gltf;
    Visibility visibility = Visibility::SmithGGXCorrelated;
    Distribution distribution = Distribution::GGX;
    Fresnel fresnel = Fresnel::Schlick;
    DielectricCoupling coupling = DielectricCoupling::FresnelMix;
    bool multiScatter = true;
    glm::dvec3 baseColor {0.8, 0.3, 0.1};
    double metallic = 0.0;
    double roughness = 0.4;
    const char* environment = "studio";
    double rotationDegrees = 40.0;
    bool light = false; // one directional light (intensity 2) besides the environment
    // KHR_materials_clearcoat: the coat's strength (0: none) and perceptual roughness.
    double clearcoat = 0.0;
    double clearcoatRoughness = 0.0;
    // KHR_materials_sheen: the sheen's colour (black: none) and perceptual roughness.
    glm::dvec3 sheenColor {0.0};
    double sheenRoughness = 0.0;
    // KHR_materials_specular: the dielectric's specular strength and F0 tint (1 and white: none).
    double specular = 1.0;
    glm::dvec3 specularColor {1.0};
    // KHR_materials_anisotropy: the strength (0: none) and the direction's turn in degrees.
    double anisotropy = 0.0;
    double anisotropyRotationDegrees = 0.0;
    // KHR_materials_iridescence: the film's strength (0: none), index and thickness in nm.
    double iridescence = 0.0;
    double iridescenceIor = 1.3;
    double iridescenceThickness = 400.0;
};

// The default project with the case's environment, material and light, the sphere, no debug
// view, lit by `method` at `samples` per pixel.
Project iblMethodCaseProject(const IblMethodCase& c, IblMethod method, int samples);

// The CPU ground truth (core/shading/GroundTruth) of `project`'s reference view, size x size at
// `samplesPerPixel`, seed `seed`. nullopt with *error when the project has what the truth refuses.
std::optional<Image> groundTruthImage(
    const Project& project, int size, int samplesPerPixel, std::uint64_t seed, std::string* error);

// The first pixel whose RGB is not finite or is negative, "(x, y): value"; empty when none is.
std::string firstUnusablePixel(const Image& image);

} // namespace facet::test
