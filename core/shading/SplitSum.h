#pragma once
// The image-based lighting of the real-time renderer, on the CPU: the split sum [Karis 2013]
// with the composition of the material model, exactly as resources/shaders/
// environment_lighting.glsl environmentLobes() computes it, so tests can compare GPU pixels
// against it. With a uniform environment the prefiltered radiance and the irradiance are exact
// (L and pi L), so the only approximations left are the split sum's own (see
// docs/rendering.md, "Image-based lighting").

#include <optional>

#include <glm/vec3.hpp>

#include "core/shading/Anisotropy.h"
#include "core/shading/MaterialBrdf.h"

namespace facet {

struct SplitSumLighting {
    glm::dvec3 prefilteredRadiance {0.0}; // prefiltered(R, lodFromRoughness(r)), intensity applied
    glm::dvec3 irradiance {0.0}; // E(n), not divided by pi, intensity applied
    // The clear coat's, read only when the material has a coat: prefiltered(R_c, lod(r_c)) about
    // the coat's normal n_c, and n_c.v (the geometric normal's unless a coat normal map perturbs
    // it; the base's NoV may come from its own normal map).
    glm::dvec3 coatPrefilteredRadiance {0.0};
    double coatNoV = 1.0;
    // The sheen's, read only when the material has a sheen: the mean radiance under its lobe (the
    // window's split sum averages filtered samples, resources/shaders/ibl_fis.glsl
    // sheenLobeRadiance; a swatch takes the irradiance's mean).
    glm::dvec3 sheenRadiance {0.0};
    // KHR_materials_anisotropy: where the specular lobe's compensation reads the table, for an
    // anisotropic material (its frame and view: shading::anisotropicCompensation); the isotropic
    // lobe's otherwise. The caller also reads prefilteredRadiance about the bent normal.
    std::optional<shading::AnisotropicCompensation> anisotropicCompensation;
};

// Outgoing radiance lobes towards a viewer at n.v = NoV (before ambient occlusion):
//   specular = prefiltered * (F0 scale + bias) * M(F0)      per lobe (glTF: dielectric F0 and
//                                                            base colour, mixed by metallic)
//   diffuse  = E / pi * c * w_d, with w_d:
//     glTF, fresnel_mix         (1 - m) (1 - F0_d) W(n.v)       W = DfgValue::diffuseFresnelWeight
//     glTF, energy preserving   (1 - m) (1 - E_s(n.v))          E_s = dielectricSpecularAlbedo
//     LearnOpenGL, fresnel_mix  (1 - m) (1 - F0) W(n.v)
//     LearnOpenGL, energy pres. (1 - m) (1 - E_s(n.v))
//   sheen    = sheenLight * sheenColor * E_sheen(n.v, r_s), and the base's lobes times
//              1 - max3(sheenColor) E_sheen(n.v, r_s) (docs/shading.md, "Sheen")
//   coat     = prefiltered_c * (scale_c + bias_c) * w_c, w_c = clearcoatWeight (the coat's lobe has
//              no Fresnel inside: its DFG albedo with F = 1), and the lobes above times 1 - w_c
// fresnel_mix's weights are the albedo of its base c / pi (1 - F(v.h)), the ground truth's model
// (a white dielectric's albedo reaches 1.86 at grazing view: docs/energy.md); the split sum only
// separates it from the irradiance, as it does the specular lobe from the prefiltered radiance.
// `brdf`'s model selects the composition and multi-scatter; `table` is the DFG LUT the renderer
// samples (the one `brdf` was made with), looked up bilinearly as GL_LINEAR does.
// The direction the renderer reads the prefiltered map at for normal n, mirror direction R
// (both unit) and alpha = roughness^2: normalize(lerp(n, R, s (sqrt(s) + alpha))), s = 1 - alpha
// [Lagarde & de Rousiers 2014, "Moving Frostbite to PBR", listing 22]. The peak of a rough lobe
// leans from R towards n; docs/ibl.md ("Dominant direction") has the measurement behind the
// choice. GLSL twin: resources/shaders/ibl_lookup.glsl.
glm::dvec3 specularDominantDirection(const glm::dvec3& n, const glm::dvec3& R, double alpha);

BrdfLobes splitSumRadiance(const MaterialBrdf& brdf, const DfgTable& table, const MaterialInfo& material,
    double NoV, const SplitSumLighting& lighting);

// KHR_materials_iridescence under the split sum (docs/shading.md, "Iridescence"). The film's
// Fresnel swings with the angle, so one value at n.v stands poorly for a lobe (measured up to 47%
// under uniform light): the split sum averages it over the lobe instead, with a few fixed points
// (deterministic: no noise), GLSL twins in environment_lighting.glsl.
inline constexpr int kSplitSumFilmSamples = 8;
// The film's Fresnel over a base of F0 `f0` averaged over the base's specular lobe seen at n.v: the
// visible-normal estimate sum Firid(v.h_i) w_i / sum w_i, w_i = G2(v, l_i) / G1(v) (Smith, height
// correlated), h_i drawn by Heitz's sampler from `samples` Hammersley points; the lobe's albedo
// with F = 1 times it is the film's share of the specular albedo.
glm::dvec3 filmLobeFresnel(
    const MaterialInfo& material, const glm::dvec3& f0, double NoV, double perceptualRoughness,
    int samples = kSplitSumFilmSamples);
// The film's Fresnel averaged over the cosine lobe of l (h = normalize(v + l)): per channel
// (`mean`, LearnOpenGL's kD) and its largest channel's (`meanMax`, glTF's rgb_mix weight).
struct FilmDiffuseFresnel {
    glm::dvec3 mean {0.0};
    double meanMax = 0.0;
};
FilmDiffuseFresnel filmDiffuseFresnel(
    const MaterialInfo& material, const glm::dvec3& f0, double NoV, int samples = kSplitSumFilmSamples);

} // namespace facet
