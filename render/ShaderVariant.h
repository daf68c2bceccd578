#pragma once
// Surface shader variants (after Magnum's PhongGL flags and the glTF Sample Viewer's
// shader_cache.js): an enum class flag set, one `#define` per bit, plus the debug view as
// `#define DEBUG_VIEW <n>`. A variant key (flags + debug view) names one compiled program; the
// cache compiles each key once and counts compiles so tests can see skipped work.
//
// What the flags remove (docs/architecture.md, "Shader permutations"): without a Has*Map bit the input is
// the constant factor and the shader declares no sampler for it; without HasNormalMap there is no
// tangent frame and surface.vert reads no tangent attribute (nor without HasClearcoatNormalMap or
// Anisotropy);
// without HasPunctualLights there is no light loop. A lobe's maps come only with the lobe.

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/material/Material.h"
#include "core/project/Light.h"
#include "core/shading/DebugView.h"
#include "core/shading/ShadingModel.h"

namespace facet {

class ShaderProgram;

// 64 bits: the layered lobes (clearcoat, sheen, specular, anisotropy, iridescence) and their maps
// take a bit each, as Filament gltfio's MaterialKey gives every extension and texture its own.
enum class SurfaceFeature : uint64_t {
    None = 0,
    HasBaseColorMap = 1ull << 0, // HAS_BASE_COLOR_MAP
    HasNormalMap = 1ull << 1, // HAS_NORMAL_MAP (tangent frame, aTangent)
    HasMetallicMap = 1ull << 2, // HAS_METALLIC_MAP
    HasRoughnessMap = 1ull << 3, // HAS_ROUGHNESS_MAP
    HasOcclusionMap = 1ull << 4, // HAS_OCCLUSION_MAP
    HasPunctualLights = 1ull << 5, // HAS_PUNCTUAL_LIGHTS (the light loop)
    IrradianceSH = 1ull << 6, // IRRADIANCE_SH: 9 SH uniforms instead of the irradiance cubemap
    MultiScatter = 1ull << 7, // MULTI_SCATTER: Turquin 2019 compensation
    CompositionLearnOpenGL = 1ull << 8, // COMPOSITION_LEARNOPENGL (else glTF 2.0 Appendix B)
    EnergyPreservingCoupling = 1ull << 9, // COUPLING_ENERGY_PRESERVING (else fresnel_mix)
    Beckmann = 1ull << 10, // DISTRIBUTION_BECKMANN (else GGX)
    VisibilityUncorrelated = 1ull << 11, // VISIBILITY_UNCORRELATED (separable Smith-GGX)
    VisibilitySchlick = 1ull << 12, // VISIBILITY_SCHLICK (Smith with Schlick-GGX G1)
    FresnelDielectric = 1ull << 13, // FRESNEL_DIELECTRIC (exact dielectric Fresnel, lights only)
    HasEmissiveMap = 1ull << 14, // HAS_EMISSIVE_MAP
    AlphaMask = 1ull << 15, // ALPHA_MASK: discard below uAlphaCutoff (glTF alphaMode MASK)
    AlphaBlend = 1ull << 16, // ALPHA_BLEND: premultiplied colour and alpha out (glTF BLEND)
    // One fetch for scalar maps that read the same texture (a packed occlusion-roughness-metallic
    // file; same file, colour space and UV transform): the later slot reuses the earlier one's
    // texel and declares no sampler (sharedTexelFeatures).
    RoughnessTexelFromMetallic = 1ull << 17, // ROUGHNESS_TEXEL_FROM_METALLIC
    OcclusionTexelFromMetallic = 1ull << 18, // OCCLUSION_TEXEL_FROM_METALLIC
    OcclusionTexelFromRoughness = 1ull << 19, // OCCLUSION_TEXEL_FROM_ROUGHNESS
    // IBL_REFERENCE: the environment by Monte Carlo (IblMethod::Reference, ibl_reference.glsl)
    // from the source equirect and its sampling tables, instead of the split sum's cubes.
    IblReference = 1ull << 20,
    // ANALYTIC_SPHERE_NORMAL: docs/architecture.md's reference view of the unit sphere, shaded at the exact
    // hit of the pixel's ray (n = hit, v = -ray) instead of the mesh's interpolated normal, as the
    // CPU ground truth does (RenderScene::analyticSphere).
    AnalyticSphereNormal = 1ull << 21,
    // IBL_FIS: the environment by filtered importance sampling of the pixel's own lobe
    // (IblMethod::Fis, ibl_fis.glsl) from the environment cube's mip chain and the source equirect.
    IblFis = 1ull << 22,
    // SPLIT_SUM_SHARP_LOBES: the split sum integrates lobes sharper than the prefiltered level 1
    // by a few fis samples (IblSampling::sharpLobeSamples). Only for materials whose roughness
    // (factor times its map's smallest value) reaches below level 1: the loop's mere presence cost
    // llvmpipe a third of a textured frame where no pixel took it.
    SplitSumSharpLobes = 1ull << 23,
    // HAS_VERTEX_COLOR: the mesh has glTF COLOR_0 (Mesh::hasVertexColors), which multiplies the
    // base colour and alpha; meshes without it read no colour attribute.
    HasVertexColors = 1ull << 24,
    // MATERIAL_UNLIT: KHR_materials_unlit, the base colour is the radiance (Material::unlit).
    Unlit = 1ull << 25,
    // HAS_TEXCOORD_1: a sampled map reads the mesh's second UV set (MaterialMap::texCoord 1 and
    // Mesh::hasTexCoord1); without it every map reads set 0 and no second UV is interpolated.
    HasTexCoord1 = 1ull << 26,
    // MATERIAL_CLEARCOAT: KHR_materials_clearcoat's coat lobe (Material::clearcoat factor > 0);
    // without it no coat code is compiled and the material pays nothing for the lobe.
    Clearcoat = 1ull << 27,
    // The coat's maps (only with Clearcoat): HAS_CLEARCOAT_MAP, HAS_CLEARCOAT_ROUGHNESS_MAP,
    // HAS_CLEARCOAT_NORMAL_MAP (which, like HasNormalMap, brings the tangent frame).
    HasClearcoatMap = 1ull << 28,
    HasClearcoatRoughnessMap = 1ull << 29,
    HasClearcoatNormalMap = 1ull << 30,
    // CLEARCOAT_ROUGHNESS_TEXEL_FROM_CLEARCOAT: the extension's packing (strength R, roughness G
    // of one texture) read with one fetch, as the ORM slots are.
    ClearcoatRoughnessTexelFromClearcoat = 1ull << 31,
    // MATERIAL_SHEEN: KHR_materials_sheen's lobe (Material::hasSheen: a colour that is not black)
    // and the base's albedo scaling under it; the sheen's albedo table is bound only with it.
    Sheen = 1ull << 32,
    // The sheen's maps (only with Sheen): HAS_SHEEN_COLOR_MAP, HAS_SHEEN_ROUGHNESS_MAP.
    HasSheenColorMap = 1ull << 33,
    HasSheenRoughnessMap = 1ull << 34,
    // SHEEN_ROUGHNESS_TEXEL_FROM_SHEEN_COLOR: the extension's packing (colour RGB, roughness A of
    // one texture) read with one fetch.
    SheenRoughnessTexelFromSheenColor = 1ull << 35,
    // MATERIAL_SPECULAR: KHR_materials_specular's strength and F0 tint of the dielectric layer
    // (Material::hasSpecular: not the default layer); without it the layer is (F0(ior), 1).
    Specular = 1ull << 36,
    // Its maps (only with Specular): HAS_SPECULAR_MAP, HAS_SPECULAR_COLOR_MAP.
    HasSpecularMap = 1ull << 37,
    HasSpecularColorMap = 1ull << 38,
    // SPECULAR_TEXEL_FROM_SPECULAR_COLOR: the extension's packing (colour RGB, strength A of one
    // texture) read with one fetch.
    SpecularTexelFromSpecularColor = 1ull << 39,
    // MATERIAL_ANISOTROPY: KHR_materials_anisotropy's stretched specular lobes of the base
    // (Material::hasAnisotropy: a strength above 0); it brings the tangent frame, as a normal map does.
    Anisotropy = 1ull << 40,
    // HAS_ANISOTROPY_MAP: its texture (direction RG, strength B), only with Anisotropy.
    HasAnisotropyMap = 1ull << 41,
    // MATERIAL_IRIDESCENCE: KHR_materials_iridescence's thin film over the base's specular Fresnel
    // (Material::hasIridescence: a factor above 0).
    Iridescence = 1ull << 42,
    // Its maps (only with Iridescence): HAS_IRIDESCENCE_MAP (R), HAS_IRIDESCENCE_THICKNESS_MAP (G).
    HasIridescenceMap = 1ull << 43,
    HasIridescenceThicknessMap = 1ull << 44,
    // IRIDESCENCE_THICKNESS_TEXEL_FROM_IRIDESCENCE: the extension's packing (strength R, thickness
    // G of one texture) read with one fetch.
    IridescenceThicknessTexelFromIridescence = 1ull << 45,
};
inline constexpr int kSurfaceFeatureBits = 46;
static_assert(kSurfaceFeatureBits <= 64);

using SurfaceFeatures = uint64_t;
inline constexpr SurfaceFeatures operator|(SurfaceFeature a, SurfaceFeature b)
{
    return uint64_t(a) | uint64_t(b);
}
inline constexpr SurfaceFeatures operator|(SurfaceFeatures a, SurfaceFeature b)
{
    return a | uint64_t(b);
}
inline constexpr bool hasFeature(SurfaceFeatures set, SurfaceFeature f)
{
    return (set & uint64_t(f)) != 0;
}

struct SurfaceVariantKey {
    SurfaceFeatures features = 0;
    DebugView debugView = DebugView::None;
    bool operator==(const SurfaceVariantKey&) const = default;
    auto operator<=>(const SurfaceVariantKey&) const = default;
};

// The flags a material + scene need: map bits from the material's textures (only where an image
// is given, and not where the factor makes the texture irrelevant: metallic, roughness or
// emission at 0, occlusion or normal strength 0, a lobe's maps while the lobe is off or the
// material unlit), model bits from its ShadingModel, the alpha mode, the lobes, lights when any
// enabled light exists.
SurfaceFeatures surfaceFeaturesFor(const Material& material, const bool (&hasMapImage)[kMapSlotCount],
                                   bool hasPunctualLights, bool irradianceFromSH);
SurfaceFeatures surfaceFeaturesFor(const ShadingModel& model);
// The Has*Map bit of a slot.
SurfaceFeature mapFeature(MapSlot slot);
// The *TexelFrom* bits for `features` (its Has*Map bits set): a scalar slot whose texture is the
// same as an earlier scalar slot's (`textures`: the slots' images, null for none; equal pointers
// are one decoded file, core/image/MapImageCache.h) in the same colour space, UV set, UV transform and
// sampler reads that slot's texel. On llvmpipe each texture fetch of a 2K map costs 7-10% of the untextured
// frame (docs/benchmarks.md, "Texture maps").
SurfaceFeatures sharedTexelFeatures(const Material& material, SurfaceFeatures features,
                                    const std::array<const void*, kMapSlotCount>& textures);
// Whether the variant samples the slot's own texture (a Has*Map bit and no *TexelFrom* bit for it).
bool samplesOwnTexture(SurfaceFeatures features, MapSlot slot);
// HasTexCoord1 when the mesh has a second UV set and a map the variant samples reads it.
SurfaceFeatures texCoordFeatures(const Material& material, SurfaceFeatures features, bool meshHasTexCoord1);

// The shader's name for a debug view's id: "DEBUG_" and its name upper-cased, '-' as '_'
// (DebugView::BaseColor, "base-color": DEBUG_BASE_COLOR).
std::string debugViewDefine(DebugView view);
// The shader's name for a map slot's index: "SLOT_" and its name in upper snake case
// (MapSlot::ClearcoatRoughness, "clearcoatRoughness": SLOT_CLEARCOAT_ROUGHNESS).
std::string mapSlotDefine(MapSlot slot);
// One "#define NAME" per set bit, in bit order, then "DEBUG_<VIEW> <n>" for every debug view (the
// ids debug_views.glsl compares, made from core/shading/DebugView's table so the two cannot disagree),
// "DEBUG_VIEW <n>", "MAX_LIGHTS <n>", HAS_TANGENT_FRAME with either normal map or anisotropy, "SLOT_<NAME> <n>"
// for every map slot and "MAP_SLOT_COUNT <n>".
std::vector<std::string> surfaceDefines(const SurfaceVariantKey& key);
inline constexpr int kMaxPunctualLights = kMaxLights; // core/project/Light.h

// Compiled surface programs by key. Needs the GL context current for get() and destruction.
class SurfaceProgramCache {
public:
    SurfaceProgramCache();
    ~SurfaceProgramCache();
    SurfaceProgramCache(const SurfaceProgramCache&) = delete;
    SurfaceProgramCache& operator=(const SurfaceProgramCache&) = delete;

    // The program for `key`, compiling it on first use (surface.vert + surface.frag). nullptr on
    // a compile or link error, with *error set (ShaderProgram's message, which names the file and
    // line); a failed key is remembered and not recompiled every frame.
    const ShaderProgram* get(const SurfaceVariantKey& key, std::string* error);
    int compileCount() const { return m_compileCount; }
    std::size_t size() const { return m_programs.size(); }
    void clear();

private:
    std::map<SurfaceVariantKey, std::unique_ptr<ShaderProgram>> m_programs; // null: failed
    std::map<SurfaceVariantKey, std::string> m_errors;
    int m_compileCount = 0;
};

} // namespace facet
