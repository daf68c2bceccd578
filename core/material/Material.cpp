#include "core/material/Material.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <utility>

#include "core/material/MaterialProperties.h"
#include "core/support/EnumNames.h"
#include "core/support/Failure.h"

namespace facet {

namespace {
constexpr std::pair<MapSlot, const char*> kSlots[] = {{MapSlot::BaseColor, "baseColor"},
    {MapSlot::Normal, "normal"}, {MapSlot::Metallic, "metallic"}, {MapSlot::Roughness, "roughness"},
    {MapSlot::Occlusion, "occlusion"}, {MapSlot::Emissive, "emissive"}, {MapSlot::Clearcoat, "clearcoat"},
    {MapSlot::ClearcoatRoughness, "clearcoatRoughness"}, {MapSlot::ClearcoatNormal, "clearcoatNormal"},
    {MapSlot::SheenColor, "sheenColor"}, {MapSlot::SheenRoughness, "sheenRoughness"},
    {MapSlot::Specular, "specular"}, {MapSlot::SpecularColor, "specularColor"},
    {MapSlot::Anisotropy, "anisotropy"}, {MapSlot::Iridescence, "iridescence"},
    {MapSlot::IridescenceThickness, "iridescenceThickness"}};
constexpr std::pair<AlphaMode, const char*> kAlphaModes[]
    = {{AlphaMode::Opaque, "opaque"}, {AlphaMode::Mask, "mask"}, {AlphaMode::Blend, "blend"}};
constexpr std::pair<MapChannel, const char*> kChannels[] = {{MapChannel::Rgb, "rgb"}, {MapChannel::R, "r"},
    {MapChannel::G, "g"}, {MapChannel::B, "b"}, {MapChannel::A, "a"}};
constexpr std::pair<ColorEncoding, const char*> kEncodings[]
    = {{ColorEncoding::SRGB, "srgb"}, {ColorEncoding::Linear, "linear"}};
constexpr std::pair<TextureWrap, const char*> kWraps[] = {{TextureWrap::Repeat, "repeat"},
    {TextureWrap::ClampToEdge, "clampToEdge"}, {TextureWrap::MirroredRepeat, "mirroredRepeat"}};
constexpr std::pair<TextureFilter, const char*> kFilters[]
    = {{TextureFilter::Auto, "auto"}, {TextureFilter::Nearest, "nearest"}, {TextureFilter::Linear, "linear"},
        {TextureFilter::NearestMipmapNearest, "nearestMipmapNearest"},
        {TextureFilter::LinearMipmapNearest, "linearMipmapNearest"},
        {TextureFilter::NearestMipmapLinear, "nearestMipmapLinear"},
        {TextureFilter::LinearMipmapLinear, "linearMipmapLinear"}};

std::string number(double value)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", value);
    return buffer;
}

bool validateMap(MapSlot slot, const MaterialMap& map, std::string* problem)
{
    // The factors' ranges are the property registry's (Material::validate checks them first).
    const std::string key = toString(slot);
    if (isColorSlot(slot) && slot != MapSlot::BaseColor) { // emissive, the sheen's and specular colour
        // Carried, never used: still a number a file can hold.
        if (!checkRange(map.factor.a, 0.0, 1.0, key + ".factor.a", problem))
            return false;
    } else if (!isColorSlot(slot)) {
        if (map.factor.y != map.factor.x || map.factor.z != map.factor.x || map.factor.w != map.factor.x)
            return fail(key + ".factor: a scalar factor must have equal components (use Material::setFactor)",
                problem);
    }
    if (readsRgbOnly(slot) && map.channel != MapChannel::Rgb)
        return fail(key + ".channel: " + (isNormalSlot(slot) ? "a normal map" : "the " + key + " map")
                + " reads \"rgb\"",
            problem);
    if (isScalarSlot(slot) && map.channel == MapChannel::Rgb)
        return fail(
            key + ".channel: a " + key + " map reads one channel (\"r\", \"g\", \"b\" or \"a\"), not \"rgb\"",
            problem);
    if (map.invert && !isScalarSlot(slot))
        return fail(key
                + ".invert: only scalar maps (metallic, roughness, occlusion, the coat's strength and "
                  "roughness, the sheen's roughness, specular, the iridescence's factor and thickness) can be "
                  "inverted",
            problem);
    if (map.flipGreen && !isNormalSlot(slot))
        return fail(key + ".flipGreen: only normal maps have a green-channel convention", problem);
    // A zero scale collapses the texture to one texel, which is never what was meant.
    for (int i = 0; i < 2; ++i) {
        const char* axis = i == 0 ? "u" : "v";
        if (!std::isfinite(map.uv.scale[i]) || map.uv.scale[i] == 0.0)
            return fail(
                key + ".uv.scale." + axis + ": " + number(map.uv.scale[i]) + " must be finite and non-zero",
                problem);
        if (!std::isfinite(map.uv.offset[i]))
            return fail(key + ".uv.offset." + axis + ": must be finite", problem);
    }
    if (!std::isfinite(map.uv.rotationDegrees))
        return fail(key + ".uv.rotationDegrees: must be finite", problem);
    if (map.texCoord < 0 || map.texCoord >= kTexCoordSets)
        return fail(
            key + ".texCoord: " + std::to_string(map.texCoord) + " is not a texture-coordinate set (0 or 1)",
            problem);
    const TextureFilter mag = map.sampler.magFilter;
    if (mag != TextureFilter::Auto && mag != TextureFilter::Nearest && mag != TextureFilter::Linear)
        return fail(key + ".sampler.magFilter: \"" + std::string(toString(mag))
                + "\" is a minification filter (magnification is \"auto\", \"nearest\" or \"linear\")",
            problem);
    return true;
}
} // namespace

const char* toString(MapSlot slot)
{
    return enumName(kSlots, slot);
}
std::optional<MapSlot> mapSlotFromString(std::string_view name)
{
    return enumFromName(kSlots, name);
}
const char* toString(AlphaMode mode)
{
    return enumName(kAlphaModes, mode);
}
std::optional<AlphaMode> alphaModeFromString(std::string_view name)
{
    return enumFromName(kAlphaModes, name);
}
const char* toString(MapChannel channel)
{
    return enumName(kChannels, channel);
}
std::optional<MapChannel> mapChannelFromString(std::string_view name)
{
    return enumFromName(kChannels, name);
}
const char* toString(ColorEncoding encoding)
{
    return enumName(kEncodings, encoding);
}
std::optional<ColorEncoding> colorEncodingFromString(std::string_view name)
{
    return enumFromName(kEncodings, name);
}

const char* toString(TextureWrap wrap)
{
    return enumName(kWraps, wrap);
}
std::optional<TextureWrap> textureWrapFromString(std::string_view name)
{
    return enumFromName(kWraps, name);
}
const char* toString(TextureFilter filter)
{
    return enumName(kFilters, filter);
}
std::optional<TextureFilter> textureFilterFromString(std::string_view name)
{
    return enumFromName(kFilters, name);
}

glm::dmat3 UvTransform::matrix() const
{
    // KHR_texture_transform's GLSL, verbatim in meaning: matrix = translation * rotation * scale,
    // glm and GLSL both take the columns in order.
    const double r = rotationDegrees * std::numbers::pi / 180.0;
    const double c = std::cos(r);
    const double s = std::sin(r);
    const glm::dmat3 translation(1.0, 0.0, 0.0, 0.0, 1.0, 0.0, offset.x, offset.y, 1.0);
    const glm::dmat3 rotation(c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0);
    const glm::dmat3 scaling(scale.x, 0.0, 0.0, 0.0, scale.y, 0.0, 0.0, 0.0, 1.0);
    return translation * rotation * scaling;
}

glm::dvec2 UvTransform::apply(const glm::dvec2& uv) const
{
    const glm::dvec3 p = matrix() * glm::dvec3(uv, 1.0);
    return {p.x, p.y};
}

std::array<MaterialMap, kMapSlotCount> Material::defaultMaps()
{
    std::array<MaterialMap, kMapSlotCount> maps;
    MaterialMap& baseColor = maps[std::size_t(MapSlot::BaseColor)];
    baseColor.factor = glm::dvec4(0.8, 0.8, 0.8, 1.0);
    baseColor.colorSpace
        = ColorEncoding::SRGB; // colour textures are sRGB-encoded (docs/architecture.md, "Textures")
    // Scalar maps default to the channels of an ORM / glTF metallicRoughness texture; a greyscale
    // texture has the same value in every channel, so the defaults suit it too.
    maps[std::size_t(MapSlot::Metallic)].factor = glm::dvec4(0.0);
    maps[std::size_t(MapSlot::Metallic)].channel = MapChannel::B;
    maps[std::size_t(MapSlot::Roughness)].factor = glm::dvec4(0.5);
    maps[std::size_t(MapSlot::Roughness)].channel = MapChannel::G;
    maps[std::size_t(MapSlot::Occlusion)].factor = glm::dvec4(1.0);
    maps[std::size_t(MapSlot::Occlusion)].channel = MapChannel::R;
    maps[std::size_t(MapSlot::Normal)].factor = glm::dvec4(1.0);
    // glTF's emissiveFactor default: no emission until a colour (or a texture and factor) is given.
    MaterialMap& emissive = maps[std::size_t(MapSlot::Emissive)];
    emissive.factor = glm::dvec4(0.0, 0.0, 0.0, 1.0);
    emissive.colorSpace = ColorEncoding::SRGB;
    // KHR_materials_clearcoat: no coat; its textures' channels are the extension's (strength in
    // R, roughness in G, so one packed texture can feed both).
    maps[std::size_t(MapSlot::Clearcoat)].factor = glm::dvec4(0.0);
    maps[std::size_t(MapSlot::Clearcoat)].channel = MapChannel::R;
    maps[std::size_t(MapSlot::ClearcoatRoughness)].factor = glm::dvec4(0.0);
    maps[std::size_t(MapSlot::ClearcoatRoughness)].channel = MapChannel::G;
    maps[std::size_t(MapSlot::ClearcoatNormal)].factor = glm::dvec4(1.0);
    // KHR_materials_sheen: no sheen; the colour texture is sRGB-encoded RGB, the roughness is its
    // texture's alpha (the extension's channels: one RGBA texture can feed both).
    MaterialMap& sheenColor = maps[std::size_t(MapSlot::SheenColor)];
    sheenColor.factor = glm::dvec4(0.0, 0.0, 0.0, 1.0);
    sheenColor.colorSpace = ColorEncoding::SRGB;
    maps[std::size_t(MapSlot::SheenRoughness)].factor = glm::dvec4(0.0);
    maps[std::size_t(MapSlot::SheenRoughness)].channel = MapChannel::A;
    // KHR_materials_specular: the default layer (strength 1, white); the strength is its
    // texture's alpha, the colour the sRGB RGB of its own (the extension's channels).
    maps[std::size_t(MapSlot::Specular)].factor = glm::dvec4(1.0);
    maps[std::size_t(MapSlot::Specular)].channel = MapChannel::A;
    MaterialMap& specularColor = maps[std::size_t(MapSlot::SpecularColor)];
    specularColor.factor = glm::dvec4(1.0);
    specularColor.colorSpace = ColorEncoding::SRGB;
    // KHR_materials_anisotropy: none; its texture is linear RGB (direction RG, strength B).
    maps[std::size_t(MapSlot::Anisotropy)].factor = glm::dvec4(0.0);
    // KHR_materials_iridescence: none; the factor's texture is R, the thickness's G (the
    // extension's channels: one texture can feed both), the thickness the extension's maximum.
    maps[std::size_t(MapSlot::Iridescence)].factor = glm::dvec4(0.0);
    maps[std::size_t(MapSlot::Iridescence)].channel = MapChannel::R;
    maps[std::size_t(MapSlot::IridescenceThickness)].factor
        = glm::dvec4(shading::kDefaultIridescenceThicknessMaximum);
    maps[std::size_t(MapSlot::IridescenceThickness)].channel = MapChannel::G;
    return maps;
}

double Material::dielectricF0() const
{
    return f0FromIor(ior);
}

bool Material::validate(std::string* problem) const
{
    for (const MaterialPropertyInfo& info : materialProperties())
        if (!checkProperty(*this, info.property, problem))
            return false;
    for (MapSlot slot : kAllMapSlots)
        if (!validateMap(slot, map(slot), problem))
            return false;
    return true;
}

} // namespace facet
