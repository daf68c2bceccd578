#pragma once
// The material being authored: glTF 2.0 metallic-roughness (glTF 2.0 specification, section 3.9
// "Materials", and Appendix B for the BRDF) with Facet's per-map texture options.
//
// Every input is a MaterialMap: a constant factor, optionally multiplied by one texture (as glTF
// does: "the factor multiplies the texture"). The maps are addressed by MapSlot. The factor's
// meaning depends on the slot:
//   baseColor  linear RGBA (glTF baseColorFactor); alpha is carried but Facet renders opaque
//   normal     strength in x (glTF normalTexture.scale: scales the tangent-space X and Y)
//   metallic   scalar in x (glTF metallicFactor)
//   roughness  perceptual roughness in x (glTF roughnessFactor); alpha = roughness^2
//   occlusion  strength in x (glTF occlusionTexture.strength: mix(1, ao, strength), not a multiplier)
//   emissive   linear RGB in [0, 1] (glTF emissiveFactor), alpha unused; the emitted radiance is
//              factor x texture x Material::emissiveStrength (KHR_materials_emissive_strength)
//   clearcoat           scalar in x, [0, 1] (KHR_materials_clearcoat clearcoatFactor; texture R)
//   clearcoatRoughness  perceptual roughness in x (clearcoatRoughnessFactor; texture G)
//   clearcoatNormal     strength in x (clearcoatNormalTexture.scale), as the normal slot's
//   sheenColor          linear RGB in [0, 1] (KHR_materials_sheen sheenColorFactor; texture RGB,
//                       sRGB), alpha unused; black: no sheen
//   sheenRoughness      perceptual roughness in x (sheenRoughnessFactor; texture A)
//   specular            scalar in x, [0, 1] (KHR_materials_specular specularFactor; texture A)
//   specularColor       linear RGB in [0, kMaxSpecularColor] (specularColorFactor; texture RGB,
//                       sRGB), alpha unused; a tint of the dielectric F0 (values above 1 allowed)
//   anisotropy          strength in x, [0, 1] (KHR_materials_anisotropy anisotropyStrength);
//                       texture RGB, linear: RG the direction in the tangent plane (x 2 - 1), B
//                       the strength's multiplier; the rotation is Material::anisotropyRotationDegrees
//   iridescence         scalar in x, [0, 1] (KHR_materials_iridescence iridescenceFactor; texture R)
//   iridescenceThickness the film's thickness in nanometres in x (iridescenceThicknessMaximum), not a
//                       multiplier: the texture (G) picks mix(Material::iridescenceThicknessMinimum,
//                       factor, texel); without a texture the film is this thick
// For the scalar slots (and the normal maps' strength) the factor is kept as (v, v, v, v) (setFactor(slot, v)
// does that) so that a vec4 uniform reads the same from any component and operator== compares what matters.
// docs/project-format.md lists every field with its unit and default.

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "core/image/Image.h" // ColorEncoding
#include "core/shading/Brdf.h"
#include "core/shading/ShadingModel.h"
#include "core/shading/ThinFilm.h"

namespace facet {

enum class MapSlot {
    BaseColor,
    Normal,
    Metallic,
    Roughness,
    Occlusion,
    Emissive,
    // KHR_materials_clearcoat's three textures (clearcoatTexture, clearcoatRoughnessTexture,
    // clearcoatNormalTexture); they count only while the coat is on (Material::usesSlot).
    Clearcoat,
    ClearcoatRoughness,
    ClearcoatNormal,
    // KHR_materials_sheen's two textures (sheenColorTexture, sheenRoughnessTexture); they count
    // only while the sheen is on (its colour is not black).
    SheenColor,
    SheenRoughness,
    // KHR_materials_specular's two textures (specularTexture, specularColorTexture); they count
    // only while the specular layer differs from the glTF default (Material::hasSpecular).
    Specular,
    SpecularColor,
    // KHR_materials_anisotropy's texture (anisotropyTexture: direction RG, strength B); it counts
    // only while the strength is not 0.
    Anisotropy,
    // KHR_materials_iridescence's two textures (iridescenceTexture R, iridescenceThicknessTexture
    // G); they count only while the factor is not 0.
    Iridescence,
    IridescenceThickness,
};
inline constexpr int kMapSlotCount = 16;
inline constexpr std::array<MapSlot, kMapSlotCount> kAllMapSlots
    = {MapSlot::BaseColor, MapSlot::Normal, MapSlot::Metallic, MapSlot::Roughness, MapSlot::Occlusion,
        MapSlot::Emissive, MapSlot::Clearcoat, MapSlot::ClearcoatRoughness, MapSlot::ClearcoatNormal,
        MapSlot::SheenColor, MapSlot::SheenRoughness, MapSlot::Specular, MapSlot::SpecularColor,
        MapSlot::Anisotropy, MapSlot::Iridescence, MapSlot::IridescenceThickness};

// "baseColor", "normal", "metallic", "roughness", "occlusion", "emissive", "clearcoat",
// "clearcoatRoughness", "clearcoatNormal", "sheenColor", "sheenRoughness", "specular",
// "specularColor", "anisotropy", "iridescence", "iridescenceThickness" (the project file's keys).
const char* toString(MapSlot slot);
std::optional<MapSlot> mapSlotFromString(std::string_view name);
// Metallic, roughness, occlusion, the coat's strength and roughness, the sheen's roughness, the
// specular strength and the iridescence's factor and thickness hold one number; the colours, the
// normal maps and the anisotropy map (direction and strength) hold a vector.
inline bool isScalarSlot(MapSlot slot)
{
    return slot == MapSlot::Metallic || slot == MapSlot::Roughness || slot == MapSlot::Occlusion
        || slot == MapSlot::Clearcoat || slot == MapSlot::ClearcoatRoughness
        || slot == MapSlot::SheenRoughness || slot == MapSlot::Specular || slot == MapSlot::Iridescence
        || slot == MapSlot::IridescenceThickness;
}
// Base colour, emissive, the sheen's colour and the specular colour hold colours: sRGB-encoded
// textures by default, an RGB factor.
inline bool isColorSlot(MapSlot slot)
{
    return slot == MapSlot::BaseColor || slot == MapSlot::Emissive || slot == MapSlot::SheenColor
        || slot == MapSlot::SpecularColor;
}
// Tangent-space normal maps (the base's and the coat's): read "rgb", a strength as the factor
// (glTF normalTexture.scale), a green-channel convention (MaterialMap::flipGreen).
inline bool isNormalSlot(MapSlot slot)
{
    return slot == MapSlot::Normal || slot == MapSlot::ClearcoatNormal;
}

// Slots whose texture is read as a whole colour or vector, channel "rgb": the normal maps, emissive,
// the sheen's and the specular colour, the anisotropy map (base colour may also read one channel of
// a greyscale texture).
inline bool readsRgbOnly(MapSlot slot)
{
    return isNormalSlot(slot) || (isColorSlot(slot) && slot != MapSlot::BaseColor) || slot == MapSlot::Anisotropy;
}

// The part of the material a slot belongs to: the glTF 2.0 core model, or a layered lobe whose
// slots count only while the lobe is on (Material::usesSlot).
enum class MaterialLobe { Core, Clearcoat, Sheen, Specular, Anisotropy, Iridescence };
inline MaterialLobe lobeOf(MapSlot slot)
{
    switch (slot) {
    case MapSlot::Clearcoat:
    case MapSlot::ClearcoatRoughness:
    case MapSlot::ClearcoatNormal:
        return MaterialLobe::Clearcoat;
    case MapSlot::SheenColor:
    case MapSlot::SheenRoughness:
        return MaterialLobe::Sheen;
    case MapSlot::Specular:
    case MapSlot::SpecularColor:
        return MaterialLobe::Specular;
    case MapSlot::Anisotropy:
        return MaterialLobe::Anisotropy;
    case MapSlot::Iridescence:
    case MapSlot::IridescenceThickness:
        return MaterialLobe::Iridescence;
    default:
        return MaterialLobe::Core;
    }
}

// How the base colour's alpha is used (glTF 2.0 material.alphaMode).
enum class AlphaMode {
    Opaque, // alpha ignored
    Mask, // fragments with alpha < alphaCutoff are discarded, the rest are opaque
    Blend, // composited over what is behind with the "over" operator (premultiplied by alpha)
};
const char* toString(AlphaMode mode); // "opaque", "mask", "blend"
std::optional<AlphaMode> alphaModeFromString(std::string_view name);

// Which channel(s) of the texture a map reads. Scalar maps read one channel, so a packed texture
// can feed several maps (ORM: R occlusion, G roughness, B metallic; glTF's metallicRoughness
// texture: G roughness, B metallic). Rgb reads the colour (base colour, normal); base colour may
// also read one channel of a greyscale texture, replicated.
enum class MapChannel { Rgb, R, G, B, A };
const char* toString(MapChannel channel); // "rgb", "r", "g", "b", "a"
std::optional<MapChannel> mapChannelFromString(std::string_view name);

// The names of ColorEncoding in files: "srgb", "linear".
const char* toString(ColorEncoding encoding);
std::optional<ColorEncoding> colorEncodingFromString(std::string_view name);

// Texture coordinate transform, as KHR_texture_transform defines it, but with the rotation in
// degrees (what the UI shows): uv' = T(offset) * R(rotation) * S(scale) * uv, where the rotation
// turns counter-clockwise in UV space.
struct UvTransform {
    glm::dvec2 scale {1.0, 1.0};
    glm::dvec2 offset {0.0, 0.0};
    double rotationDegrees = 0.0;

    bool isIdentity() const { return *this == UvTransform {}; }
    // The 3x3 matrix of KHR_texture_transform (column-major, for a uniform or glm).
    glm::dmat3 matrix() const;
    glm::dvec2 apply(const glm::dvec2& uv) const;
    bool operator==(const UvTransform&) const = default;
};

// How a texture is read beyond [0, 1] and between texels: glTF 2.0's sampler (section 3.8.4,
// "Samplers"), per map. Auto filters are Facet's choice, which is also what glTF leaves to the
// implementation when the sampler says nothing: linear magnification, trilinear (the View's
// setting) and anisotropic minification.
enum class TextureWrap { Repeat, ClampToEdge, MirroredRepeat };
const char* toString(TextureWrap wrap); // "repeat", "clampToEdge", "mirroredRepeat"
std::optional<TextureWrap> textureWrapFromString(std::string_view name);
enum class TextureFilter {
    Auto,
    Nearest,
    Linear,
    // Minification only:
    NearestMipmapNearest,
    LinearMipmapNearest,
    NearestMipmapLinear,
    LinearMipmapLinear,
};
// "auto", "nearest", "linear", "nearestMipmapNearest", "linearMipmapNearest",
// "nearestMipmapLinear", "linearMipmapLinear".
const char* toString(TextureFilter filter);
std::optional<TextureFilter> textureFilterFromString(std::string_view name);

struct TextureSampler {
    TextureWrap wrapS = TextureWrap::Repeat; // along u
    TextureWrap wrapT = TextureWrap::Repeat; // along v
    TextureFilter magFilter = TextureFilter::Auto; // Auto, Nearest or Linear
    TextureFilter minFilter = TextureFilter::Auto;

    bool isDefault() const { return *this == TextureSampler {}; }
    bool operator==(const TextureSampler&) const = default;
};

// Texture-coordinate sets a map can read (glTF textureInfo.texCoord: TEXCOORD_0, TEXCOORD_1).
inline constexpr int kTexCoordSets = 2;

struct MaterialMap {
    std::string path; // texture file (absolute in memory); empty: none, the factor alone
    glm::dvec4 factor {1.0}; // see the table at the top of this file
    MapChannel channel = MapChannel::Rgb;
    ColorEncoding colorSpace = ColorEncoding::Linear; // how the texture's numbers are encoded
    bool invert = false; // scalar maps: use 1 - value (e.g. a smoothness or gloss map as roughness)
    bool flipGreen = false; // normal map only: DirectX convention (-Y green); Facet's is OpenGL (+Y)
    UvTransform uv;
    int texCoord = 0; // which texture-coordinate set the map reads: 0 or 1 (core/mesh/Mesh.h Vertex::uv, uv1)
    TextureSampler sampler;

    bool hasTexture() const { return !path.empty(); }
    bool operator==(const MaterialMap&) const = default;
};

struct Material {
    // Smallest perceptual roughness used in shading (Filament's MIN_PERCEPTUAL_ROUGHNESS, desktop:
    // alpha = 0.045^2 ~ 0.002 keeps the GGX peak within half-float range). The stored roughness
    // may be 0; the clamp happens when shading (alpha()).
    static constexpr double kMinPerceptualRoughness = shading::kMinPerceptualRoughness;
    static constexpr double kDefaultIor = 1.5; // glTF 2.0 / KHR_materials_ior default: F0 = 0.04
    // The ranges validate() accepts, for callers that offer a value range (wedge axes, sliders).
    // IOR: 1 is vacuum; 5 is above every transparent dielectric an artist might want (diamond
    // 2.42, rutile 2.9, germanium ~4 in the infrared).
    static constexpr double kMinIor = 1.0;
    static constexpr double kMaxIor = 5.0;
    // Normal strength scales tangent-space X and Y; beyond 10 the map is noise, below 0 it would
    // flip both axes, which flipGreen and the texture itself express better.
    static constexpr double kMaxNormalStrength = 10.0;
    // KHR_materials_specular's colour may exceed 1 (it scales F0 = ((n - 1) / (n + 1))^2, and the
    // product is clamped to 1): at IOR 1.5 a colour of 25 already reaches F0 = 1, and 100 covers an
    // IOR down to 1.22. The extension sets no bound; beyond this a file is refused with its field named.
    static constexpr double kMaxSpecularColor = 100.0;
    // KHR_materials_anisotropy's rotation, in degrees here (the extension's radians, converted on
    // import and export): one turn either way covers every direction.
    static constexpr double kMaxAnisotropyRotationDegrees = 180.0;
    // KHR_materials_iridescence's film thickness, in nanometres (the extension's unit), any
    // value >= 0 there: beyond a few micrometres the film's interference averages out over the
    // visible band (its reflectance is then the incoherent one, core/shading/ThinFilm.h), and a
    // file beyond 100 micrometres is refused with its field named.
    static constexpr double kMaxIridescenceThickness = 100000.0;

    std::string name = "Material";
    // Index of refraction of the dielectric layer (KHR_materials_ior); metals ignore it and take
    // F0 from the base colour.
    double ior = kDefaultIor;
    ShadingModel shading;
    // Multiplies the emissive colour (KHR_materials_emissive_strength): emitted radiance in the
    // scene's linear units, so values above 1 make a light source. [0, kMaxEmissiveStrength].
    double emissiveStrength = 1.0;
    static constexpr double kMaxEmissiveStrength = 10000.0; // RGBA16F holds 65504
    AlphaMode alphaMode = AlphaMode::Opaque;
    double alphaCutoff = 0.5; // AlphaMode::Mask threshold, [0, 1]
    // False: faces seen from behind are culled (glTF default). Facet's own materials default to
    // true so an open mesh shows its inside.
    bool doubleSided = true;
    // KHR_materials_unlit: the surface shows its base colour (factor x texture x vertex colour)
    // as radiance, with no light, environment or emission (the glTF Sample Viewer's
    // MATERIAL_UNLIT). For baked lighting, stylised assets and photogrammetry.
    bool unlit = false;
    // KHR_materials_anisotropy: the anisotropy direction's turn from the tangent (counter-clockwise
    // in the tangent plane, towards the bitangent), in degrees, [-180, 180].
    double anisotropyRotationDegrees = 0.0;
    // KHR_materials_iridescence: the film's index of refraction (iridescenceIor, [kMinIor,
    // kMaxIor]) and its thickness where the thickness texture reads 0
    // (iridescenceThicknessMinimum, nanometres); the thickness where it reads 1, and without a
    // texture, is the IridescenceThickness slot's factor.
    double iridescenceIor = shading::kDefaultIridescenceIor;
    double iridescenceThicknessMinimum = shading::kDefaultIridescenceThicknessMinimum;
    // Indexed by MapSlot. Defaults: base colour 0.8 grey (sRGB texture), metallic 0, roughness
    // 0.5, occlusion 1, normal strength 1, emissive black, no coat (strength 0, roughness 0,
    // coat normal strength 1), no sheen (black, roughness 0), specular 1 and white (the default layer),
    // no anisotropy (strength 0), no iridescence (factor 0; thickness 400 nm).
    // (glTF's defaults, metallic 1 and roughness 1, describe a rough white metal: fine as texture
    // multipliers, poor as a starting material.)
    std::array<MaterialMap, kMapSlotCount> maps = defaultMaps();

    MaterialMap& map(MapSlot slot) { return maps[std::size_t(slot)]; }
    const MaterialMap& map(MapSlot slot) const { return maps[std::size_t(slot)]; }

    glm::dvec4 baseColorFactor() const { return map(MapSlot::BaseColor).factor; }
    double metallic() const { return map(MapSlot::Metallic).factor.x; }
    double roughness() const { return map(MapSlot::Roughness).factor.x; }
    double occlusionStrength() const { return map(MapSlot::Occlusion).factor.x; }
    double normalStrength() const { return map(MapSlot::Normal).factor.x; }
    // Emitted radiance of an untextured point: the emissive factor times the strength.
    glm::dvec3 emissive() const { return glm::dvec3(map(MapSlot::Emissive).factor) * emissiveStrength; }
    // KHR_materials_clearcoat: a clear dielectric coat (IOR 1.5) over the whole material, with its
    // own GGX roughness and normal; the base keeps what the coat's Fresnel lets through
    // (docs/shading.md, "Clearcoat"). Strength 0: no coat, and no shader cost.
    double clearcoat() const { return map(MapSlot::Clearcoat).factor.x; }
    double clearcoatRoughness() const { return map(MapSlot::ClearcoatRoughness).factor.x; } // perceptual
    bool hasClearcoat() const { return clearcoat() > 0.0; }
    void setClearcoat(double strength, double roughness)
    {
        setFactor(MapSlot::Clearcoat, strength);
        setFactor(MapSlot::ClearcoatRoughness, roughness);
    }
    // KHR_materials_sheen: a Charlie microfacet lobe of its own colour and roughness over the
    // material (cloth, velvet, dust), which keeps what the sheen's albedo leaves it
    // (docs/shading.md, "Sheen"). Black: no sheen, and no shader cost.
    glm::dvec3 sheenColor() const { return glm::dvec3(map(MapSlot::SheenColor).factor); }
    double sheenRoughness() const { return map(MapSlot::SheenRoughness).factor.x; } // perceptual
    bool hasSheen() const
    {
        const glm::dvec3 c = sheenColor();
        return c.r > 0.0 || c.g > 0.0 || c.b > 0.0;
    }
    void setSheen(const glm::dvec3& linearRgb, double roughness)
    {
        map(MapSlot::SheenColor).factor = glm::dvec4(linearRgb, 1.0);
        setFactor(MapSlot::SheenRoughness, roughness);
    }
    // KHR_materials_specular: the strength of the dielectric's specular reflection (0: none, a
    // purely diffuse dielectric) and a tint of its F0; metals ignore both (docs/shading.md,
    // "Specular"). The glTF defaults, 1 and white, change nothing and cost no shader code.
    double specular() const { return map(MapSlot::Specular).factor.x; }
    glm::dvec3 specularColor() const { return glm::dvec3(map(MapSlot::SpecularColor).factor); }
    // Whether the layer differs from the default: a factor other than 1 or a texture on either slot
    // (a texture with factor 1 still modulates).
    bool hasSpecular() const
    {
        return specular() != 1.0 || specularColor() != glm::dvec3(1.0) || map(MapSlot::Specular).hasTexture()
            || map(MapSlot::SpecularColor).hasTexture();
    }
    void setSpecular(double strength, const glm::dvec3& linearRgb)
    {
        setFactor(MapSlot::Specular, strength);
        map(MapSlot::SpecularColor).factor = glm::dvec4(linearRgb, 1.0);
    }
    // KHR_materials_anisotropy: the base's specular highlight stretched along a direction in the
    // tangent plane (brushed metal), the texture's turned by the rotation (docs/shading.md,
    // "Anisotropy"). Strength 0: isotropic, and no shader cost.
    double anisotropy() const { return map(MapSlot::Anisotropy).factor.x; }
    bool hasAnisotropy() const { return anisotropy() > 0.0; }
    void setAnisotropy(double strength, double rotationDegrees)
    {
        setFactor(MapSlot::Anisotropy, strength);
        anisotropyRotationDegrees = rotationDegrees;
    }
    // KHR_materials_iridescence: a thin film over the base (soap bubbles, oil, coated lenses,
    // heat-tinted metal) whose interference colours the base's specular reflection by angle and
    // thickness (docs/shading.md, "Iridescence"). Factor 0: none, and no shader cost.
    double iridescence() const { return map(MapSlot::Iridescence).factor.x; }
    double iridescenceThicknessMaximum() const { return map(MapSlot::IridescenceThickness).factor.x; } // nm
    bool hasIridescence() const { return iridescence() > 0.0; }
    void setIridescence(double factor, double filmIor, double thicknessMinimum, double thicknessMaximum)
    {
        setFactor(MapSlot::Iridescence, factor);
        iridescenceIor = filmIor;
        iridescenceThicknessMinimum = thicknessMinimum;
        setFactor(MapSlot::IridescenceThickness, thicknessMaximum);
    }
    // Whether `lobe` is on: the core always, a layered lobe while its strength or colour is not 0
    // (the specular layer: while it differs from the default).
    bool hasLobe(MaterialLobe lobe) const
    {
        switch (lobe) {
        case MaterialLobe::Clearcoat:
            return hasClearcoat();
        case MaterialLobe::Sheen:
            return hasSheen();
        case MaterialLobe::Specular:
            return hasSpecular();
        case MaterialLobe::Anisotropy:
            return hasAnisotropy();
        case MaterialLobe::Iridescence:
            return hasIridescence();
        case MaterialLobe::Core:
            break;
        }
        return true;
    }
    // Whether `slot` can change how the material looks: a core slot always, a lobe's slot while
    // the lobe is on. Loading, binding, the Texture Maps dock and exports skip the others.
    bool usesSlot(MapSlot slot) const { return hasLobe(lobeOf(slot)); }
    // Scalar slots: stores (v, v, v, v). Base colour: use map(MapSlot::BaseColor).factor.
    void setFactor(MapSlot slot, double value) { map(slot).factor = glm::dvec4(value); }
    void setBaseColor(const glm::dvec3& linearRgb, double alpha = 1.0)
    {
        map(MapSlot::BaseColor).factor = glm::dvec4(linearRgb, alpha);
    }

    // alpha = clamp(roughness, kMinPerceptualRoughness, 1)^2 (glTF 2.0 Appendix B; Burley 2012).
    double alpha() const { return shading::alphaFromRoughness(roughness()); }
    // Normal-incidence reflectance of the dielectric layer from ior.
    double dielectricF0() const;

    // Checks ranges and per-slot rules. On failure returns false and sets *problem to
    // "<field>: <problem>" with the field named as the project file names it, e.g.
    // "roughness.factor: 1.5 is outside [0, 1]" (the caller prefixes "material.").
    bool validate(std::string* problem) const;

    static std::array<MaterialMap, kMapSlotCount> defaultMaps();
    bool operator==(const Material&) const = default;
};

// Schlick's F0 for a dielectric of index `ior` against air, and the inverse (core/shading/Brdf.h):
// f0FromIor(1.5) = 0.04.
using shading::f0FromIor;
using shading::iorFromF0;

} // namespace facet
