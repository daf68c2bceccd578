#pragma once
// The choices that select how a material is shaded. Shared by the material (what the user
// picked), the CPU BRDF (core/shading/MaterialBrdf.h) and the GLSL variants (one #define per choice).
// docs/shading.md holds the equations behind each.

#include <optional>
#include <string_view>

namespace facet {

// How the lobes are put together.
enum class BrdfComposition {
    Gltf, // glTF 2.0 Appendix B: fresnel_mix for dielectrics, conductor Fresnel for metals
    LearnOpenGL, // kS = F, kD = (1 - F)(1 - metallic) with Schlick-GGX geometry (UE4 / LearnOpenGL)
};

// Normal distribution function.
enum class Distribution { GGX, Beckmann };

// Geometry / visibility term. Visibility V = G / (4 N.L N.V).
enum class Visibility {
    SmithGGXCorrelated, // height-correlated Smith-GGX (Heitz 2014), the glTF default
    SmithGGXUncorrelated, // separable Smith-GGX
    SchlickGGX, // separable Smith with the Schlick-GGX G1 (k = (r+1)^2/8 lights, alpha/2 IBL)
};
// Every Visibility, in declaration order (int(v) indexes arrays of per-visibility data, e.g. the
// split-sum tables of render/RenderScene.h EnvironmentLighting).
inline constexpr int kVisibilityCount = 3;
inline constexpr Visibility kAllVisibilities[kVisibilityCount]
    = {Visibility::SmithGGXCorrelated, Visibility::SmithGGXUncorrelated, Visibility::SchlickGGX};

// Fresnel term for the specular lobe.
enum class Fresnel {
    Schlick, // Schlick 1994
    Dielectric, // exact unpolarised dielectric Fresnel from the IOR (dielectric lobe only)
};

// How a dielectric's diffuse lobe shares energy with its specular lobe.
enum class DielectricCoupling {
    FresnelMix, // glTF fresnel_mix: gains energy at grazing angles (measured in docs/energy.md)
    EnergyPreserving // diffuse scaled by what the specular layer leaves (albedo table), reciprocal
};

struct ShadingModel {
    BrdfComposition composition = BrdfComposition::Gltf;
    Distribution distribution = Distribution::GGX;
    Visibility visibility = Visibility::SmithGGXCorrelated;
    Fresnel fresnel = Fresnel::Schlick;
    DielectricCoupling coupling = DielectricCoupling::FresnelMix;
    bool multiScatter = true; // Kulla-Conty / Turquin specular energy compensation

    // The LearnOpenGL/UE4 composition with its own terms (Schlick-GGX geometry).
    static ShadingModel learnOpenGL()
    {
        ShadingModel m;
        m.composition = BrdfComposition::LearnOpenGL;
        m.visibility = Visibility::SchlickGGX;
        return m;
    }
    bool operator==(const ShadingModel&) const = default;
};

// Stable lower-case names used by project files and the command line.
const char* toString(BrdfComposition value);
const char* toString(Distribution value);
const char* toString(Visibility value);
const char* toString(Fresnel value);
const char* toString(DielectricCoupling value);
std::optional<BrdfComposition> brdfCompositionFromString(std::string_view name);
std::optional<Distribution> distributionFromString(std::string_view name);
std::optional<Visibility> visibilityFromString(std::string_view name);
std::optional<Fresnel> fresnelFromString(std::string_view name);
std::optional<DielectricCoupling> dielectricCouplingFromString(std::string_view name);

} // namespace facet
