#include "render/ShaderVariant.h"

#include <array>
#include <cctype>

#include "render/ShaderProgram.h"

namespace facet {

namespace {

constexpr std::array<const char*, kSurfaceFeatureBits> kFeatureDefines = {
    "HAS_BASE_COLOR_MAP",
    "HAS_NORMAL_MAP",
    "HAS_METALLIC_MAP",
    "HAS_ROUGHNESS_MAP",
    "HAS_OCCLUSION_MAP",
    "HAS_PUNCTUAL_LIGHTS",
    "IRRADIANCE_SH",
    "MULTI_SCATTER",
    "COMPOSITION_LEARNOPENGL",
    "COUPLING_ENERGY_PRESERVING",
    "DISTRIBUTION_BECKMANN",
    "VISIBILITY_UNCORRELATED",
    "VISIBILITY_SCHLICK",
    "FRESNEL_DIELECTRIC",
    "HAS_EMISSIVE_MAP",
    "ALPHA_MASK",
    "ALPHA_BLEND",
    "ROUGHNESS_TEXEL_FROM_METALLIC",
    "OCCLUSION_TEXEL_FROM_METALLIC",
    "OCCLUSION_TEXEL_FROM_ROUGHNESS",
    "IBL_REFERENCE",
    "ANALYTIC_SPHERE_NORMAL",
    "IBL_FIS",
    "SPLIT_SUM_SHARP_LOBES",
    "HAS_VERTEX_COLOR",
    "MATERIAL_UNLIT",
    "HAS_TEXCOORD_1",
    "MATERIAL_CLEARCOAT",
    "HAS_CLEARCOAT_MAP",
    "HAS_CLEARCOAT_ROUGHNESS_MAP",
    "HAS_CLEARCOAT_NORMAL_MAP",
    "CLEARCOAT_ROUGHNESS_TEXEL_FROM_CLEARCOAT",
    "MATERIAL_SHEEN",
    "HAS_SHEEN_COLOR_MAP",
    "HAS_SHEEN_ROUGHNESS_MAP",
    "SHEEN_ROUGHNESS_TEXEL_FROM_SHEEN_COLOR",
    "MATERIAL_SPECULAR",
    "HAS_SPECULAR_MAP",
    "HAS_SPECULAR_COLOR_MAP",
    "SPECULAR_TEXEL_FROM_SPECULAR_COLOR",
    "MATERIAL_ANISOTROPY",
    "HAS_ANISOTROPY_MAP",
    "MATERIAL_IRIDESCENCE",
    "HAS_IRIDESCENCE_MAP",
    "HAS_IRIDESCENCE_THICKNESS_MAP",
    "IRIDESCENCE_THICKNESS_TEXEL_FROM_IRIDESCENCE",
};

} // namespace

SurfaceFeature mapFeature(MapSlot slot)
{
    switch (slot) {
    case MapSlot::BaseColor:
        return SurfaceFeature::HasBaseColorMap;
    case MapSlot::Normal:
        return SurfaceFeature::HasNormalMap;
    case MapSlot::Metallic:
        return SurfaceFeature::HasMetallicMap;
    case MapSlot::Roughness:
        return SurfaceFeature::HasRoughnessMap;
    case MapSlot::Occlusion:
        return SurfaceFeature::HasOcclusionMap;
    case MapSlot::Clearcoat:
        return SurfaceFeature::HasClearcoatMap;
    case MapSlot::ClearcoatRoughness:
        return SurfaceFeature::HasClearcoatRoughnessMap;
    case MapSlot::ClearcoatNormal:
        return SurfaceFeature::HasClearcoatNormalMap;
    case MapSlot::SheenColor:
        return SurfaceFeature::HasSheenColorMap;
    case MapSlot::SheenRoughness:
        return SurfaceFeature::HasSheenRoughnessMap;
    case MapSlot::Specular:
        return SurfaceFeature::HasSpecularMap;
    case MapSlot::SpecularColor:
        return SurfaceFeature::HasSpecularColorMap;
    case MapSlot::Anisotropy:
        return SurfaceFeature::HasAnisotropyMap;
    case MapSlot::Iridescence:
        return SurfaceFeature::HasIridescenceMap;
    case MapSlot::IridescenceThickness:
        return SurfaceFeature::HasIridescenceThicknessMap;
    case MapSlot::Emissive:
        break;
    }
    return SurfaceFeature::HasEmissiveMap;
}

SurfaceFeatures surfaceFeaturesFor(const ShadingModel& model)
{
    SurfaceFeatures f = 0;
    if (model.multiScatter)
        f = f | SurfaceFeature::MultiScatter;
    if (model.composition == BrdfComposition::LearnOpenGL)
        f = f | SurfaceFeature::CompositionLearnOpenGL;
    if (model.coupling == DielectricCoupling::EnergyPreserving)
        f = f | SurfaceFeature::EnergyPreservingCoupling;
    if (model.distribution == Distribution::Beckmann)
        f = f | SurfaceFeature::Beckmann;
    if (model.visibility == Visibility::SmithGGXUncorrelated)
        f = f | SurfaceFeature::VisibilityUncorrelated;
    if (model.visibility == Visibility::SchlickGGX)
        f = f | SurfaceFeature::VisibilitySchlick;
    if (model.fresnel == Fresnel::Dielectric)
        f = f | SurfaceFeature::FresnelDielectric;
    return f;
}

namespace {

// Whether a slot's texture can change the result: at factor 0 metallic, roughness and emission
// are 0 whatever the texture says, occlusion at strength 0 is 1, and a normal map at strength 0
// is the geometric normal; a lobe's maps change nothing while the lobe is off or the material
// unlit. Such a map is not sampled (docs/architecture.md: a constant map samples no
// texture); the CPU twin gives the same values (core/shading/MaterialInputs.h).
bool textureMatters(const Material& material, MapSlot slot)
{
    if (!material.usesSlot(slot) || (material.unlit && lobeOf(slot) != MaterialLobe::Core))
        return false;
    switch (slot) {
    case MapSlot::Clearcoat:
    case MapSlot::SheenColor:
    case MapSlot::Specular:
    case MapSlot::Anisotropy:
    case MapSlot::Iridescence:
        return true; // usesSlot: the factor is above 0 (the specular layer: it is on)
    case MapSlot::IridescenceThickness: // mix(minimum, maximum, texel): nothing to pick between
        return material.iridescenceThicknessMinimum != material.iridescenceThicknessMaximum();
    case MapSlot::SpecularColor:
        return material.specular() != 0.0; // a tint of no reflection is none
    case MapSlot::SheenRoughness:
        return material.sheenRoughness() != 0.0;
    case MapSlot::ClearcoatRoughness:
        return material.clearcoatRoughness() != 0.0;
    case MapSlot::ClearcoatNormal:
        return material.map(slot).factor.x != 0.0;
    case MapSlot::Metallic:
        return material.metallic() != 0.0;
    case MapSlot::Roughness:
        return material.roughness() != 0.0;
    case MapSlot::Occlusion:
        return material.occlusionStrength() != 0.0;
    case MapSlot::Normal:
        return material.normalStrength() != 0.0;
    case MapSlot::Emissive:
        return material.emissive() != glm::dvec3(0.0);
    case MapSlot::BaseColor:
        break;
    }
    return true;
}

} // namespace

SurfaceFeatures surfaceFeaturesFor(const Material& material, const bool (&hasMapImage)[kMapSlotCount],
                                   bool hasPunctualLights, bool irradianceFromSH)
{
    SurfaceFeatures f = surfaceFeaturesFor(material.shading);
    for (int i = 0; i < kMapSlotCount; ++i)
        if (hasMapImage[i] && material.maps[std::size_t(i)].hasTexture() && textureMatters(material, MapSlot(i)))
            f = f | mapFeature(MapSlot(i));
    if (material.alphaMode == AlphaMode::Mask)
        f = f | SurfaceFeature::AlphaMask;
    else if (material.alphaMode == AlphaMode::Blend)
        f = f | SurfaceFeature::AlphaBlend;
    if (hasPunctualLights)
        f = f | SurfaceFeature::HasPunctualLights;
    if (irradianceFromSH)
        f = f | SurfaceFeature::IrradianceSH;
    if (material.unlit)
        f = f | SurfaceFeature::Unlit;
    else {
        if (material.hasClearcoat())
            f = f | SurfaceFeature::Clearcoat;
        if (material.hasSheen())
            f = f | SurfaceFeature::Sheen;
        if (material.hasSpecular())
            f = f | SurfaceFeature::Specular;
        if (material.hasAnisotropy())
            f = f | SurfaceFeature::Anisotropy;
        if (material.hasIridescence())
            f = f | SurfaceFeature::Iridescence;
    }
    return f;
}

SurfaceFeatures sharedTexelFeatures(const Material& material, SurfaceFeatures features,
                                    const std::array<const void*, kMapSlotCount>& textures)
{
    const auto same = [&](MapSlot earlier, MapSlot later) {
        const auto a = std::size_t(earlier);
        const auto b = std::size_t(later);
        // An sRGB texture's alpha is linear (GL_SRGB8_ALPHA8), so a map that reads alpha can share
        // the texel of one that reads the colour as sRGB (the sheen's packing).
        const bool sameEncoding = material.maps[a].colorSpace == material.maps[b].colorSpace
            || material.maps[b].channel == MapChannel::A;
        return hasFeature(features, mapFeature(earlier)) && hasFeature(features, mapFeature(later))
            && textures[a] && textures[a] == textures[b] && sameEncoding
            && material.maps[a].uv == material.maps[b].uv
            && material.maps[a].texCoord == material.maps[b].texCoord
            && material.maps[a].sampler == material.maps[b].sampler;
    };
    SurfaceFeatures f = 0;
    if (same(MapSlot::Metallic, MapSlot::Roughness))
        f = f | SurfaceFeature::RoughnessTexelFromMetallic;
    if (same(MapSlot::Metallic, MapSlot::Occlusion))
        f = f | SurfaceFeature::OcclusionTexelFromMetallic;
    else if (same(MapSlot::Roughness, MapSlot::Occlusion))
        f = f | SurfaceFeature::OcclusionTexelFromRoughness;
    if (same(MapSlot::Clearcoat, MapSlot::ClearcoatRoughness))
        f = f | SurfaceFeature::ClearcoatRoughnessTexelFromClearcoat;
    if (same(MapSlot::SheenColor, MapSlot::SheenRoughness))
        f = f | SurfaceFeature::SheenRoughnessTexelFromSheenColor;
    if (same(MapSlot::SpecularColor, MapSlot::Specular))
        f = f | SurfaceFeature::SpecularTexelFromSpecularColor;
    if (same(MapSlot::Iridescence, MapSlot::IridescenceThickness))
        f = f | SurfaceFeature::IridescenceThicknessTexelFromIridescence;
    return f;
}

bool samplesOwnTexture(SurfaceFeatures features, MapSlot slot)
{
    if (!hasFeature(features, mapFeature(slot)))
        return false;
    if (slot == MapSlot::Roughness)
        return !hasFeature(features, SurfaceFeature::RoughnessTexelFromMetallic);
    if (slot == MapSlot::Occlusion)
        return !hasFeature(features, SurfaceFeature::OcclusionTexelFromMetallic)
            && !hasFeature(features, SurfaceFeature::OcclusionTexelFromRoughness);
    if (slot == MapSlot::ClearcoatRoughness)
        return !hasFeature(features, SurfaceFeature::ClearcoatRoughnessTexelFromClearcoat);
    if (slot == MapSlot::SheenRoughness)
        return !hasFeature(features, SurfaceFeature::SheenRoughnessTexelFromSheenColor);
    if (slot == MapSlot::Specular)
        return !hasFeature(features, SurfaceFeature::SpecularTexelFromSpecularColor);
    if (slot == MapSlot::IridescenceThickness)
        return !hasFeature(features, SurfaceFeature::IridescenceThicknessTexelFromIridescence);
    return true;
}

SurfaceFeatures texCoordFeatures(const Material& material, SurfaceFeatures features, bool meshHasTexCoord1)
{
    if (!meshHasTexCoord1)
        return 0;
    for (MapSlot slot : kAllMapSlots)
        if (samplesOwnTexture(features, slot) && material.map(slot).texCoord == 1)
            return SurfaceFeatures(SurfaceFeature::HasTexCoord1);
    return 0;
}

std::string debugViewDefine(DebugView view)
{
    std::string define = "DEBUG_";
    for (const char* c = toString(view); *c; ++c)
        define += *c == '-' ? '_' : char(std::toupper(static_cast<unsigned char>(*c)));
    return define;
}

std::string mapSlotDefine(MapSlot slot)
{
    std::string define = "SLOT_";
    for (const char* c = toString(slot); *c; ++c) {
        if (std::isupper(static_cast<unsigned char>(*c)))
            define += '_';
        define += char(std::toupper(static_cast<unsigned char>(*c)));
    }
    return define;
}

std::vector<std::string> surfaceDefines(const SurfaceVariantKey& key)
{
    std::vector<std::string> defines;
    for (int bit = 0; bit < kSurfaceFeatureBits; ++bit)
        if (key.features & (SurfaceFeatures(1) << bit))
            defines.emplace_back(kFeatureDefines[std::size_t(bit)]);
    // The debug views' ids, from core/shading/DebugView's one table (debug_views.glsl compares names,
    // never numbers), and the view this variant shows.
    for (int view = 0; view < kDebugViewCount; ++view)
        defines.push_back(debugViewDefine(DebugView(view)) + ' ' + std::to_string(view));
    defines.push_back("DEBUG_VIEW " + std::to_string(int(key.debugView)));
    defines.push_back("MAX_LIGHTS " + std::to_string(kMaxPunctualLights));
    // The vertex tangent frame, for whichever normal map the variant samples.
    if (hasFeature(key.features, SurfaceFeature::HasNormalMap)
        || hasFeature(key.features, SurfaceFeature::HasClearcoatNormalMap)
        || hasFeature(key.features, SurfaceFeature::Anisotropy))
        defines.emplace_back("HAS_TANGENT_FRAME");
    // The map slots' indices into material_inputs.glsl's per-slot uniform arrays, from MapSlot.
    for (MapSlot slot : kAllMapSlots)
        defines.push_back(mapSlotDefine(slot) + ' ' + std::to_string(int(slot)));
    defines.push_back("MAP_SLOT_COUNT " + std::to_string(kMapSlotCount));
    return defines;
}

SurfaceProgramCache::SurfaceProgramCache() = default;
SurfaceProgramCache::~SurfaceProgramCache() = default;

void SurfaceProgramCache::clear()
{
    m_programs.clear();
    m_errors.clear();
}

const ShaderProgram* SurfaceProgramCache::get(const SurfaceVariantKey& key, std::string* error)
{
    if (auto found = m_programs.find(key); found != m_programs.end()) {
        if (!found->second && error)
            *error = m_errors[key];
        return found->second.get();
    }
    ++m_compileCount;
    std::string message;
    std::optional<ShaderProgram> program = ShaderProgram::create(
        "surface", {{ShaderStageSource::Stage::Vertex, "surface.vert"}, {ShaderStageSource::Stage::Fragment, "surface.frag"}},
        surfaceDefines(key), &message);
    if (!program) {
        m_errors[key] = "SurfaceProgramCache::get: " + message;
        if (error)
            *error = m_errors[key];
        m_programs[key] = nullptr;
        return nullptr;
    }
    auto stored = std::make_unique<ShaderProgram>(std::move(*program));
    const ShaderProgram* result = stored.get();
    m_programs[key] = std::move(stored);
    return result;
}

} // namespace facet
