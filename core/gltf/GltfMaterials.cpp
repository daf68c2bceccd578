// glTF materials -> Facet materials (core/gltf/GltfSupport.h). docs/gltf.md lists the mapping.

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <QDir>
#include <QFileInfo>
#include <QUrl>

#include "core/gltf/GltfImport.h"
#include "core/gltf/GltfSupport.h"
#include "core/gltf/TinyGltf.h"
#include "core/material/MaterialProperties.h"

namespace facet::gltfsupport {

void Notes::add(const std::string& note)
{
    if (note.empty())
        return;
    for (auto& [text, count] : m_notes)
        if (text == note) {
            ++count;
            return;
        }
    m_notes.emplace_back(note, 1);
}

std::string Notes::joined() const
{
    std::string result;
    for (const auto& [text, count] : m_notes) {
        if (!result.empty())
            result += "; ";
        result += text;
        if (count > 1)
            result += " (" + std::to_string(count) + " times)";
    }
    return result;
}

namespace {

std::string number(double value)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", value);
    return buffer;
}

// Clamps `value` into [lo, hi], noting what was changed and why.
double clamped(double value, double lo, double hi, const std::string& what, Notes& notes)
{
    if (!std::isfinite(value)) {
        notes.add(what + " is not a finite number: " + number(lo) + " used");
        return lo;
    }
    if (value < lo || value > hi) {
        const double result = std::clamp(value, lo, hi);
        notes.add(what + " " + number(value) + " is outside Facet's [" + number(lo) + ", " + number(hi)
            + "]: " + number(result) + " used");
        return result;
    }
    return value;
}

// The path a map names for image `imageIndex`: the external file, or an embedded reference.
std::string imagePath(
    const tinygltf::Model& model, int imageIndex, const std::string& assetPath, Notes& notes)
{
    const tinygltf::Image& image = model.images[std::size_t(imageIndex)];
    if (image.bufferView >= 0 || image.uri.empty())
        return gltfImageReference(assetPath, imageIndex);
    // A URI is percent-encoded (RFC 3986) and relative to the asset's folder.
    const QString decoded = QUrl::fromPercentEncoding(QByteArray::fromStdString(image.uri));
    const QDir folder = QFileInfo(QString::fromStdString(assetPath)).absoluteDir();
    const QString resolved = QDir::cleanPath(folder.absoluteFilePath(decoded));
    if (!QFileInfo(resolved).isFile())
        notes.add("image '" + decoded.toStdString() + "' is missing (" + resolved.toStdString()
            + "): its maps keep the path, to relink or restore");
    return resolved.toStdString();
}

// The image a texture reads: its source, or EXT_texture_webp's (OpenImageIO reads WebP).
int textureImage(
    const tinygltf::Model& model, const tinygltf::Texture& texture, const std::string& where, Notes& notes)
{
    int source = texture.source;
    const auto webp = texture.extensions.find("EXT_texture_webp");
    if (webp != texture.extensions.end() && webp->second.Has("source") && webp->second.Get("source").IsInt())
        source = webp->second.Get("source").GetNumberAsInt();
    if (texture.extensions.count("KHR_texture_basisu") && source < 0)
        notes.add(where + " uses a KTX2/Basis texture, which Facet does not read: its factor is used alone");
    if (source >= 0 && std::size_t(source) >= model.images.size()) {
        notes.add(where + " names image " + std::to_string(source)
            + ", which does not exist: its factor is used alone");
        return -1;
    }
    return source;
}

// Reads a textureInfo's index, texCoord and KHR_texture_transform into `map`. False when there is
// no usable texture (the map then keeps its factor alone).
bool readTexture(const tinygltf::Model& model, int textureIndex, int texCoord,
    const tinygltf::ExtensionMap& extensions, const std::string& assetPath, const std::string& where,
    MaterialMap& map, Notes& notes)
{
    if (textureIndex < 0)
        return false;
    if (std::size_t(textureIndex) >= model.textures.size()) {
        notes.add(where + " names texture " + std::to_string(textureIndex)
            + ", which does not exist: its factor is used alone");
        return false;
    }
    const tinygltf::Texture& texture = model.textures[std::size_t(textureIndex)];
    const int image = textureImage(model, texture, where, notes);
    if (image < 0)
        return false;
    map.path = imagePath(model, image, assetPath, notes);

    // No sampler: repeat, filters left to the implementation (glTF 2.0 section 3.8.4).
    if (texture.sampler >= 0 && std::size_t(texture.sampler) < model.samplers.size()) {
        const tinygltf::Sampler& sampler = model.samplers[std::size_t(texture.sampler)];
        map.sampler
            = textureSamplerFromGltf(sampler.magFilter, sampler.minFilter, sampler.wrapS, sampler.wrapT);
    } else if (texture.sampler >= 0) {
        notes.add(where + " names sampler " + std::to_string(texture.sampler)
            + ", which does not exist: the default sampler is used");
    }
    int set = texCoord;
    const auto transform = extensions.find("KHR_texture_transform");
    if (transform != extensions.end()) {
        const tinygltf::Value& t = transform->second;
        glm::dvec2 offset(0.0), scale(1.0);
        double rotation = 0.0;
        const auto vec2 = [](const tinygltf::Value& value, glm::dvec2& out) {
            if (value.IsArray() && value.ArrayLen() == 2 && value.Get(0).IsNumber()
                && value.Get(1).IsNumber())
                out = {value.Get(0).GetNumberAsDouble(), value.Get(1).GetNumberAsDouble()};
        };
        if (t.Has("offset"))
            vec2(t.Get("offset"), offset);
        if (t.Has("scale"))
            vec2(t.Get("scale"), scale);
        if (t.Has("rotation") && t.Get("rotation").IsNumber())
            rotation = t.Get("rotation").GetNumberAsDouble();
        if (t.Has("texCoord") && t.Get("texCoord").IsInt())
            set = t.Get("texCoord").GetNumberAsInt();
        const bool finite = std::isfinite(offset.x) && std::isfinite(offset.y) && std::isfinite(scale.x)
            && std::isfinite(scale.y) && std::isfinite(rotation);
        if (!finite || scale.x == 0.0 || scale.y == 0.0)
            notes.add(where + " has a texture transform with a zero or non-finite value: ignored");
        else
            map.uv = gltfTextureTransform(offset, rotation, scale);
    }
    if (set == 0 || set == 1) {
        map.texCoord = set;
    } else {
        notes.add(where + " reads texture coordinate set " + std::to_string(set)
            + ": Facet reads sets 0 and 1, and reads set 0");
    }
    return true;
}

// The textureInfo `field` of an extension's object (`extensionObject`, the extension
// `extension`): index, texCoord, KHR_texture_transform and, for a normal texture
// (`normalTexture`), its scale into the map's factor (the core normalTexture's rule; another
// textureInfo has no scale, and a stray one must not replace the factor). False when there is none or it is
// unusable, with a note naming the field for what is wrong.
bool readExtensionTexture(const tinygltf::Model& model, const tinygltf::Value& extensionObject,
    const char* extension, const char* field, bool normalTexture, const std::string& assetPath,
    const std::string& where, MaterialMap& map, Notes& notes)
{
    if (!extensionObject.Has(field))
        return false;
    const std::string at = where + " " + extension + "." + field;
    const tinygltf::Value& info = extensionObject.Get(field);
    if (!info.IsObject() || !info.Has("index") || !info.Get("index").IsInt()) {
        notes.add(at + " is not a textureInfo with an integer index: its factor is used alone");
        return false;
    }
    int texCoord = 0;
    if (info.Has("texCoord") && info.Get("texCoord").IsInt())
        texCoord = info.Get("texCoord").GetNumberAsInt();
    if (normalTexture && info.Has("scale")) {
        if (info.Get("scale").IsNumber())
            map.factor = glm::dvec4(clamped(info.Get("scale").GetNumberAsDouble(), 0.0,
                Material::kMaxNormalStrength, at + ".scale", notes));
        else
            notes.add(at + ".scale is not a number: 1 used");
    }
    tinygltf::ExtensionMap extensions;
    if (info.Has("extensions") && info.Get("extensions").IsObject()) {
        const tinygltf::Value& object = info.Get("extensions");
        for (const std::string& key : object.Keys())
            extensions[key] = object.Get(key);
    }
    return readTexture(
        model, info.Get("index").GetNumberAsInt(), texCoord, extensions, assetPath, at, map, notes);
}

} // namespace

Material defaultGltfMaterial()
{
    Material m;
    m.name = "Default";
    m.setBaseColor(glm::dvec3(1.0), 1.0);
    m.setFactor(MapSlot::Metallic, 1.0);
    m.setFactor(MapSlot::Roughness, 1.0);
    m.doubleSided = false;
    return m;
}

Material convertMaterial(const tinygltf::Model& model, int index, const std::string& assetPath, Notes& notes)
{
    const tinygltf::Material& g = model.materials[std::size_t(index)];
    Material m = defaultGltfMaterial();
    m.name = g.name.empty() ? "Material " + std::to_string(index) : g.name;
    const std::string where = "material '" + m.name + "'";
    const tinygltf::PbrMetallicRoughness& pbr = g.pbrMetallicRoughness;

    // Base colour: linear RGBA factor x sRGB texture (glTF 3.9.2).
    glm::dvec4 base(1.0);
    for (std::size_t c = 0; c < 4 && c < pbr.baseColorFactor.size(); ++c)
        base[int(c)] = clamped(pbr.baseColorFactor[c], 0.0, 1.0, where + " baseColorFactor", notes);
    m.map(MapSlot::BaseColor).factor = base;
    readTexture(model, pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
        pbr.baseColorTexture.extensions, assetPath, where + " base colour", m.map(MapSlot::BaseColor), notes);

    // Metallic and roughness: one texture, roughness in G, metallic in B (glTF 3.9.2).
    m.setFactor(MapSlot::Metallic, clamped(pbr.metallicFactor, 0.0, 1.0, where + " metallicFactor", notes));
    m.setFactor(
        MapSlot::Roughness, clamped(pbr.roughnessFactor, 0.0, 1.0, where + " roughnessFactor", notes));
    MaterialMap packed;
    if (readTexture(model, pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
            pbr.metallicRoughnessTexture.extensions, assetPath, where + " metallic-roughness", packed,
            notes)) {
        for (MapSlot slot : {MapSlot::Metallic, MapSlot::Roughness}) {
            MaterialMap& map = m.map(slot);
            map.path = packed.path;
            map.uv = packed.uv;
            map.texCoord = packed.texCoord;
            map.sampler = packed.sampler;
            map.colorSpace = ColorEncoding::Linear;
            map.channel = slot == MapSlot::Metallic ? MapChannel::B : MapChannel::G;
        }
    }

    // Normal: tangent space, OpenGL convention (+Y green), X and Y scaled by `scale` (3.9.3).
    MaterialMap& normal = m.map(MapSlot::Normal);
    normal.factor
        = glm::dvec4(clamped(g.normalTexture.scale, 0.0, 10.0, where + " normalTexture.scale", notes));
    readTexture(model, g.normalTexture.index, g.normalTexture.texCoord, g.normalTexture.extensions, assetPath,
        where + " normal", normal, notes);

    // Occlusion: R channel, mix(1, ao, strength) (3.9.4).
    MaterialMap& occlusion = m.map(MapSlot::Occlusion);
    occlusion.factor
        = glm::dvec4(clamped(g.occlusionTexture.strength, 0.0, 1.0, where + " occlusion strength", notes));
    occlusion.channel = MapChannel::R;
    readTexture(model, g.occlusionTexture.index, g.occlusionTexture.texCoord, g.occlusionTexture.extensions,
        assetPath, where + " occlusion", occlusion, notes);

    // Emissive: linear RGB factor x sRGB texture x KHR_materials_emissive_strength (3.9.5).
    MaterialMap& emissive = m.map(MapSlot::Emissive);
    glm::dvec4 emissiveFactor(0.0, 0.0, 0.0, 1.0);
    for (std::size_t c = 0; c < 3 && c < g.emissiveFactor.size(); ++c)
        emissiveFactor[int(c)] = clamped(g.emissiveFactor[c], 0.0, 1.0, where + " emissiveFactor", notes);
    emissive.factor = emissiveFactor;
    readTexture(model, g.emissiveTexture.index, g.emissiveTexture.texCoord, g.emissiveTexture.extensions,
        assetPath, where + " emissive", emissive, notes);

    // Alpha (3.9.6) and sidedness.
    if (g.alphaMode == "MASK")
        m.alphaMode = AlphaMode::Mask;
    else if (g.alphaMode == "BLEND")
        m.alphaMode = AlphaMode::Blend;
    else if (g.alphaMode != "OPAQUE" && !g.alphaMode.empty())
        notes.add(where + " has an unknown alphaMode \"" + g.alphaMode + "\": opaque used");
    m.alphaCutoff = clamped(g.alphaCutoff, 0.0, 1.0, where + " alphaCutoff", notes);
    m.doubleSided = g.doubleSided;

    // Extensions of the material model.
    // A number of an extension's object: its value clamped to [lo, hi] (a note when it was not
    // there), or `otherwise` with a note naming the field when it is not a number.
    const auto extensionNumber = [&](const tinygltf::Value& object, const char* extension, const char* field,
                                     double lo, double hi, double otherwise) {
        if (!object.Has(field))
            return otherwise;
        const std::string at = where + " " + extension + "." + field;
        if (!object.Get(field).IsNumber()) {
            notes.add(at + " is not a number: " + number(otherwise) + " used");
            return otherwise;
        }
        return clamped(object.Get(field).GetNumberAsDouble(), lo, hi, at, notes);
    };
    // An RGB array of an extension's object, each component clamped to [0, hi]; `otherwise` (the
    // extension's default, black or white) with a note naming the field when it is not three numbers.
    const auto extensionColor = [&](const tinygltf::Value& object, const char* extension, const char* field,
                                    const glm::dvec3& otherwise, double hi) {
        if (!object.Has(field))
            return otherwise;
        const std::string at = where + " " + extension + "." + field;
        const tinygltf::Value& array = object.Get(field);
        const bool numbers = array.IsArray() && array.ArrayLen() == 3 && array.Get(0).IsNumber()
            && array.Get(1).IsNumber() && array.Get(2).IsNumber();
        if (!numbers) {
            notes.add(at + " is not an array of three numbers: "
                + (otherwise == glm::dvec3(0.0) ? "black" : "white") + " used");
            return otherwise;
        }
        glm::dvec3 color;
        for (int c = 0; c < 3; ++c)
            color[c] = clamped(array.Get(c).GetNumberAsDouble(), 0.0, hi, at, notes);
        return color;
    };
    // An extension's numbers and colours, as the material property registry places them
    // (core/material/MaterialProperties.h, GltfField): each clamped to its row's range (an angle
    // wrapped into it), the extension's own value where the field is absent. False: the registry
    // knows no field of `extension`.
    const auto readFields = [&](const std::string& extension, const tinygltf::Value& object) {
        bool known = false;
        for (const MaterialPropertyInfo& info : materialProperties()) {
            const GltfField& gltf = info.gltf;
            if (!gltf.extension || extension != gltf.extension)
                continue;
            known = true;
            if (info.value == PropertyValue::Color) {
                setColor(m, info.property,
                    extensionColor(
                        object, gltf.extension, gltf.field, glm::dvec3(gltf.absent), info.maximum));
                continue;
            }
            // Any angle is an angle (whole turns change nothing); the registry's range is one turn.
            const double lo = gltf.periodic ? -1e6 : info.minimum * gltf.scale;
            const double hi = gltf.periodic ? 1e6 : info.maximum * gltf.scale;
            double value
                = extensionNumber(object, gltf.extension, gltf.field, lo, hi, gltf.absent) / gltf.scale;
            if (gltf.periodic)
                value = std::remainder(value, info.maximum - info.minimum);
            setScalar(m, info.property, value);
        }
        return known;
    };
    // A colour texture (sRGB RGB) and a number in a texture's alpha (linear; often the same file):
    // the packing of KHR_materials_sheen (colour, roughness) and KHR_materials_specular (colour,
    // strength).
    const auto colorAndAlphaTextures = [&](const tinygltf::Value& object, const char* extension,
                                           const char* colorField, MapSlot colorSlot, const char* alphaField,
                                           MapSlot alphaSlot) {
        MaterialMap& color = m.map(colorSlot);
        color.colorSpace = ColorEncoding::SRGB;
        color.channel = MapChannel::Rgb;
        readExtensionTexture(model, object, extension, colorField, false, assetPath, where, color, notes);
        MaterialMap& scalar = m.map(alphaSlot);
        scalar.colorSpace = ColorEncoding::Linear;
        scalar.channel = MapChannel::A;
        readExtensionTexture(model, object, extension, alphaField, false, assetPath, where, scalar, notes);
    };
    for (const auto& [name, value] : g.extensions) {
        if (name == "KHR_materials_unlit") {
            m.unlit = true; // an empty object: its presence is the whole extension
            continue;
        }
        if (!readFields(name, value)) {
            notes.add(
                "the material extension " + name + " is not supported: previewed as metallic-roughness");
            continue;
        }
        // Their textures. The extensions' defaults (the registry's GltfField::absent): clearcoat,
        // sheen, anisotropy and iridescence 0 (none of the lobe), specular 1 and white (the layer
        // of glTF 2.0's core), the film's index 1.3 and thickness 100 to 400 nm (its minimum may
        // exceed its maximum: a texture then runs the other way). The sheen's and the specular
        // colour factors are linear, the specular one may exceed 1 (docs/gltf.md); the anisotropy
        // rotation is radians in the file, degrees wrapped to [-180, 180] here.
        if (name == "KHR_materials_clearcoat") {
            // The strength in R and the roughness in G (so one texture can hold both), the
            // normal as the core normal texture with its scale; all linear.
            const char* const extension = "KHR_materials_clearcoat";
            const auto coatTexture = [&](const char* field, MapSlot slot) {
                MaterialMap& map = m.map(slot);
                map.colorSpace = ColorEncoding::Linear;
                readExtensionTexture(
                    model, value, extension, field, isNormalSlot(slot), assetPath, where, map, notes);
            };
            coatTexture("clearcoatTexture", MapSlot::Clearcoat);
            coatTexture("clearcoatRoughnessTexture", MapSlot::ClearcoatRoughness);
            coatTexture("clearcoatNormalTexture", MapSlot::ClearcoatNormal);
            m.map(MapSlot::Clearcoat).channel = MapChannel::R;
            m.map(MapSlot::ClearcoatRoughness).channel = MapChannel::G;
        } else if (name == "KHR_materials_sheen") {
            // The colour texture is sRGB RGB, the roughness its own texture's alpha (often the
            // same texture's).
            colorAndAlphaTextures(value, "KHR_materials_sheen", "sheenColorTexture", MapSlot::SheenColor,
                "sheenRoughnessTexture", MapSlot::SheenRoughness);
        } else if (name == "KHR_materials_specular") {
            // The strength is its texture's alpha, the colour its own texture's sRGB RGB (often
            // one file).
            colorAndAlphaTextures(value, "KHR_materials_specular", "specularColorTexture",
                MapSlot::SpecularColor, "specularTexture", MapSlot::Specular);
        } else if (name == "KHR_materials_anisotropy") {
            // Linear RGB: the direction in RG, the strength in B.
            MaterialMap& map = m.map(MapSlot::Anisotropy);
            map.colorSpace = ColorEncoding::Linear;
            map.channel = MapChannel::Rgb;
            readExtensionTexture(model, value, "KHR_materials_anisotropy", "anisotropyTexture", false,
                assetPath, where, map, notes);
        } else if (name == "KHR_materials_iridescence") {
            // The strength is its texture's R, the thickness its own texture's G (often one file),
            // both linear.
            const auto filmTexture = [&](const char* field, MapSlot slot, MapChannel channel) {
                MaterialMap& map = m.map(slot);
                map.colorSpace = ColorEncoding::Linear;
                map.channel = channel;
                readExtensionTexture(
                    model, value, "KHR_materials_iridescence", field, false, assetPath, where, map, notes);
            };
            filmTexture("iridescenceTexture", MapSlot::Iridescence, MapChannel::R);
            filmTexture("iridescenceThicknessTexture", MapSlot::IridescenceThickness, MapChannel::G);
        }
    }
    return m;
}

} // namespace facet::gltfsupport

namespace facet {

namespace {
// WebGL's numbers, as glTF 2.0 stores them.
constexpr std::pair<TextureFilter, int> kGltfFilters[]
    = {{TextureFilter::Nearest, 9728}, {TextureFilter::Linear, 9729},
        {TextureFilter::NearestMipmapNearest, 9984}, {TextureFilter::LinearMipmapNearest, 9985},
        {TextureFilter::NearestMipmapLinear, 9986}, {TextureFilter::LinearMipmapLinear, 9987}};
constexpr std::pair<TextureWrap, int> kGltfWraps[]
    = {{TextureWrap::ClampToEdge, 33071}, {TextureWrap::MirroredRepeat, 33648}, {TextureWrap::Repeat, 10497}};

template <typename Enum, std::size_t N>
Enum fromGltfNumber(const std::pair<Enum, int> (&table)[N], int number, Enum otherwise)
{
    for (const auto& [value, gl] : table)
        if (gl == number)
            return value;
    return otherwise;
}
template <typename Enum, std::size_t N> int toGltfNumber(const std::pair<Enum, int> (&table)[N], Enum value)
{
    for (const auto& [v, gl] : table)
        if (v == value)
            return gl;
    return -1;
}
} // namespace

TextureSampler textureSamplerFromGltf(int magFilter, int minFilter, int wrapS, int wrapT)
{
    TextureSampler sampler;
    sampler.magFilter = fromGltfNumber(kGltfFilters, magFilter, TextureFilter::Auto);
    if (sampler.magFilter != TextureFilter::Nearest && sampler.magFilter != TextureFilter::Linear)
        sampler.magFilter = TextureFilter::Auto; // a minification value where magnification belongs
    sampler.minFilter = fromGltfNumber(kGltfFilters, minFilter, TextureFilter::Auto);
    sampler.wrapS = fromGltfNumber(kGltfWraps, wrapS, TextureWrap::Repeat);
    sampler.wrapT = fromGltfNumber(kGltfWraps, wrapT, TextureWrap::Repeat);
    return sampler;
}

std::array<int, 4> gltfSamplerValues(const TextureSampler& sampler)
{
    return {toGltfNumber(kGltfFilters, sampler.magFilter), toGltfNumber(kGltfFilters, sampler.minFilter),
        toGltfNumber(kGltfWraps, sampler.wrapS), toGltfNumber(kGltfWraps, sampler.wrapT)};
}

} // namespace facet
