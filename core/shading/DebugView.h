#pragma once
// The debug views of the surface pass: which intermediate value a frame shows instead of the
// shaded image (the glTF Sample Viewer's DEBUG_* views). Here in core, not render/, so that a
// project naming an unknown view is refused when it loads (Project::validate), like any other bad
// value; render/ShaderVariant turns the view into the shader's DEBUG_VIEW define.

#include <optional>
#include <string>

namespace facet {

// What the surface pass writes. None is the shaded image; the others show one intermediate value
// (glTF Sample Viewer's DEBUG_* views). Values are linear and go through the tone-mapping pass
// like the image (use ToneMapper::None, exposure 0 to see them raw).
enum class DebugView : int {
    None = 0,
    BaseColor, // linear base colour
    ShadingNormal, // n * 0.5 + 0.5, after normal mapping
    GeometricNormal, // interpolated vertex normal * 0.5 + 0.5
    Metallic,
    Roughness, // perceptual roughness as used (after the clamp)
    Occlusion,
    Distribution, // D(n.h) for the first light (or l = reflect(-v, n) without lights)
    Visibility, // V = G / (4 n.l n.v), same l
    Fresnel, // F(v.h) of the composition, same l
    Irradiance, // E(n) / pi: the irradiance map or SH, rotated, times intensity
    IblDiffuse, // diffuse image-based light
    PrefilteredRadiance, // prefiltered(R, lodFromRoughness(r))
    BrdfLut, // the DFG table at (n.v, r): RGB = scale, bias, E
    IblSpecular, // specular image-based light
    IblTotal, // IBL diffuse + specular (with occlusion)
    DirectLight, // punctual lights only
    WhiteFurnace, // white material (base colour 1) under a uniform environment of radiance 1
    Uv, // texture coordinate 0 as it reaches the maps' UV transforms: (u, v, 0), not wrapped
    Tangent, // the unit tangent (after Gram-Schmidt against the geometric normal) * 0.5 + 0.5;
             // 0.5 grey without a normal map (no tangent frame in that variant)
    Emissive, // emitted radiance
    Alpha, // base colour alpha (factor x texture)
    NonFinite, // 1 where the shaded radiance is NaN, Inf or negative before the output guard, else 0
    UvChecker, // a checker of 8 x 8 squares per unit of texture coordinate 0 (red rises with u, green
               // with v), shaded by n.v: seams, stretching, flips and scale at a glance
    TexelDensity, // texels of the material's map per unit of surface (the source file's unit, a metre for
                  // glTF) against ViewSettings::texelDensityTarget: green on target, blue at 1/4 or less,
                  // red at 4x or more (log2 between), shaded by n.v (docs/rendering.md, "Texel density")
    Clearcoat, // KHR_materials_clearcoat's strength (factor x texture); 0 without a coat
    ClearcoatRoughness, // the coat's perceptual roughness (factor x texture); 0 without a coat
    ClearcoatNormal, // the coat's normal * 0.5 + 0.5 (its normal map's, or the geometric normal)
    SheenColor, // KHR_materials_sheen's colour (factor x texture, linear); black without a sheen
    SheenRoughness, // the sheen's perceptual roughness (factor x texture); 0 without a sheen
    Specular, // KHR_materials_specular's strength (factor x texture); 1 without the extension
    SpecularColor, // its F0 tint (factor x texture, linear, may exceed 1); white without it
    Anisotropy, // KHR_materials_anisotropy's strength (factor x texture B); 0 without it
    AnisotropyDirection, // its direction in world space * 0.5 + 0.5; 0.5 grey without it
    Iridescence, // KHR_materials_iridescence's strength (factor x texture R); 0 without it
    IridescenceThickness, // the film's thickness / 1000 nm (white: 1 micrometre); 0 without it
    IridescenceFresnel, // the film's Fresnel Firid at n.v over the base's F0 (the dielectric's and the
                        // metal's mixed by metallic); 0 without it
};
inline constexpr int kDebugViewCount = 37;
// "none", "base-color", "shading-normal", "geometric-normal", "metallic", "roughness",
// "occlusion", "distribution", "visibility", "fresnel", "irradiance", "ibl-diffuse",
// "prefiltered-radiance", "brdf-lut", "ibl-specular", "ibl-total", "direct-light",
// "white-furnace", "uv", "tangent", "emissive", "alpha", "non-finite", "uv-checker",
// "texel-density", "clearcoat", "clearcoat-roughness", "clearcoat-normal", "sheen-color",
// "sheen-roughness", "specular", "specular-color", "anisotropy", "anisotropy-direction",
// "iridescence", "iridescence-thickness", "iridescence-fresnel"
// (ViewSettings::debugView,
// facet render --view).
const char* toString(DebugView view);
// What the window shows: "Off (shaded image)", "Base colour", ..., "Distribution D", ...
const char* debugViewLabel(DebugView view);
// Also accepts the older "d", "v" and "f" for distribution, visibility and fresnel.
std::optional<DebugView> debugViewFromString(const std::string& name);
// "none, base-color, ..., distribution (or d), ...": the accepted names, for messages.
std::string debugViewNameList();
// Whether the view shows the environment's light as the IBL method integrates it (None,
// IblDiffuse, IblSpecular, IblTotal, WhiteFurnace, NonFinite): a converging method's samples
// change it. Every other view is the same after one sample, so it is drawn once.
bool debugViewShowsIntegratedLight(DebugView view);

} // namespace facet
