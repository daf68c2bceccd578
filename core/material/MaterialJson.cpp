#include "core/material/MaterialJson.h"

#include "core/json/JsonSupport.h"
#include "core/material/MaterialProperties.h"
#include "core/project/Project.h"
#include "core/support/EnumNames.h"

#include <QJsonArray>

#include <array>
#include <utility>

// A material's JSON, the "materials" entries of a project file (docs/project-format.md), the
// preset files and the clipboard's material: written and read here, for core/project/Project.cpp and the
// callers of materialToJson / materialFromJson (core/project/Project.h).

namespace facet {

namespace {

using namespace jsonsupport;

constexpr std::pair<MapChannel, const char*> kChannelNames[] = {{MapChannel::Rgb, "rgb"},
    {MapChannel::R, "r"}, {MapChannel::G, "g"}, {MapChannel::B, "b"}, {MapChannel::A, "a"}};
constexpr std::pair<ColorEncoding, const char*> kEncodingNames[]
    = {{ColorEncoding::SRGB, "srgb"}, {ColorEncoding::Linear, "linear"}};
// The ShadingModel names come from ShadingModel.cpp (toString); the tables here are built from
// them so the two cannot disagree.
template <typename Enum, std::size_t N>
std::array<std::pair<Enum, const char*>, N> namesOf(const Enum (&values)[N])
{
    std::array<std::pair<Enum, const char*>, N> table;
    for (std::size_t i = 0; i < N; ++i)
        table[i] = {values[i], toString(values[i])};
    return table;
}

template <typename Enum, std::size_t N>
void readEnum(ObjectReader& reader, const char* key, Enum& out, const Enum (&values)[N])
{
    reader.enumeration(key, out, namesOf(values));
}

constexpr BrdfComposition kAllCompositions[] = {BrdfComposition::Gltf, BrdfComposition::LearnOpenGL};
constexpr Distribution kAllDistributions[] = {Distribution::GGX, Distribution::Beckmann};
constexpr Visibility kAllVisibilities[]
    = {Visibility::SmithGGXCorrelated, Visibility::SmithGGXUncorrelated, Visibility::SchlickGGX};
constexpr Fresnel kAllFresnels[] = {Fresnel::Schlick, Fresnel::Dielectric};
constexpr AlphaMode kAllAlphaModes[] = {AlphaMode::Opaque, AlphaMode::Mask, AlphaMode::Blend};
constexpr TextureWrap kAllWraps[]
    = {TextureWrap::Repeat, TextureWrap::ClampToEdge, TextureWrap::MirroredRepeat};
constexpr TextureFilter kAllFilters[] = {TextureFilter::Auto, TextureFilter::Nearest, TextureFilter::Linear,
    TextureFilter::NearestMipmapNearest, TextureFilter::LinearMipmapNearest,
    TextureFilter::NearestMipmapLinear, TextureFilter::LinearMipmapLinear};
constexpr DielectricCoupling kAllCouplings[]
    = {DielectricCoupling::FresnelMix, DielectricCoupling::EnergyPreserving};

QJsonObject shadingToJson(const ShadingModel& model)
{
    QJsonObject o;
    o[QLatin1String("composition")] = QLatin1String(toString(model.composition));
    o[QLatin1String("distribution")] = QLatin1String(toString(model.distribution));
    o[QLatin1String("visibility")] = QLatin1String(toString(model.visibility));
    o[QLatin1String("fresnel")] = QLatin1String(toString(model.fresnel));
    o[QLatin1String("coupling")] = QLatin1String(toString(model.coupling));
    o[QLatin1String("multiScatter")] = model.multiScatter;
    return o;
}

void readShading(Messages& messages, const QJsonObject& object, const std::string& path, ShadingModel& model)
{
    ObjectReader r(messages, object, path);
    readEnum(r, "composition", model.composition, kAllCompositions);
    readEnum(r, "distribution", model.distribution, kAllDistributions);
    readEnum(r, "visibility", model.visibility, kAllVisibilities);
    readEnum(r, "fresnel", model.fresnel, kAllFresnels);
    readEnum(r, "coupling", model.coupling, kAllCouplings);
    r.boolean("multiScatter", model.multiScatter);
    r.warnAboutUnknownKeys();
}

QJsonObject uvToJson(const UvTransform& uv)
{
    QJsonObject o;
    o[QLatin1String("scale")] = toArray(uv.scale);
    o[QLatin1String("offset")] = toArray(uv.offset);
    o[QLatin1String("rotationDegrees")] = uv.rotationDegrees;
    return o;
}

QJsonObject mapToJson(
    MapSlot slot, const MaterialMap& map, const std::string& baseDir, bool includeTexturePaths)
{
    QJsonObject o;
    if (includeTexturePaths && !map.path.empty())
        o[QLatin1String("texture")] = qs(json::storedPath(map.path, baseDir));
    if (slot == MapSlot::BaseColor)
        o[QLatin1String("factor")] = toArray(map.factor);
    else if (isColorSlot(slot)) // emissive, the sheen's colour: RGB
        o[QLatin1String("factor")] = toArray(glm::dvec3(map.factor));
    else
        o[QLatin1String("factor")] = map.factor.x;
    o[QLatin1String("channel")] = QLatin1String(toString(map.channel));
    o[QLatin1String("colorSpace")] = QLatin1String(toString(map.colorSpace));
    if (isScalarSlot(slot))
        o[QLatin1String("invert")] = map.invert;
    if (isNormalSlot(slot))
        o[QLatin1String("flipGreen")] = map.flipGreen;
    o[QLatin1String("uv")] = uvToJson(map.uv);
    // Written only where they say something: most maps read set 0 with the default sampler.
    if (map.texCoord != 0)
        o[QLatin1String("texCoord")] = map.texCoord;
    if (!map.sampler.isDefault())
        o[QLatin1String("sampler")] = QJsonObject {
            {QLatin1String("wrapS"), QLatin1String(toString(map.sampler.wrapS))},
            {QLatin1String("wrapT"), QLatin1String(toString(map.sampler.wrapT))},
            {QLatin1String("magFilter"), QLatin1String(toString(map.sampler.magFilter))},
            {QLatin1String("minFilter"), QLatin1String(toString(map.sampler.minFilter))},
        };
    return o;
}

void readMap(Messages& messages, MapSlot slot, const QJsonObject& object, const std::string& path,
    const std::string& baseDir, MaterialMap& map)
{
    ObjectReader r(messages, object, path);
    std::string texture;
    r.string("texture", texture);
    // Facet writes no "texture" key for a slot without one; an empty name is most likely a
    // path that a script or an editor lost.
    if (r.value("texture").isString() && texture.empty())
        messages.warnings.push_back(
            r.pathOf("texture") + ": empty, so the slot has no texture (leave the key out for none)");
    map.path = json::resolvedPath(texture, baseDir);
    if (isColorSlot(slot)) {
        // [r, g, b] or (base colour) [r, g, b, a]; alpha defaults to 1.
        double factor[4] = {map.factor.x, map.factor.y, map.factor.z, 1.0};
        if (r.numbers("factor", factor, 3, slot == MapSlot::BaseColor ? 4 : 3) > 0)
            map.factor = glm::dvec4(factor[0], factor[1], factor[2], factor[3]);
    } else {
        double factor = map.factor.x;
        r.number("factor", factor);
        map.factor = glm::dvec4(factor);
    }
    r.enumeration("channel", map.channel, kChannelNames);
    r.enumeration("colorSpace", map.colorSpace, kEncodingNames);
    if (isScalarSlot(slot))
        r.boolean("invert", map.invert);
    if (isNormalSlot(slot))
        r.boolean("flipGreen", map.flipGreen);
    if (const std::optional<QJsonObject> uv = r.object("uv")) {
        ObjectReader u(messages, *uv, r.pathOf("uv"));
        u.vec2("scale", map.uv.scale);
        u.vec2("offset", map.uv.offset);
        u.number("rotationDegrees", map.uv.rotationDegrees);
        u.warnAboutUnknownKeys();
    }
    r.integer("texCoord", map.texCoord);
    if (const std::optional<QJsonObject> sampler = r.object("sampler")) {
        ObjectReader s(messages, *sampler, r.pathOf("sampler"));
        readEnum(s, "wrapS", map.sampler.wrapS, kAllWraps);
        readEnum(s, "wrapT", map.sampler.wrapT, kAllWraps);
        readEnum(s, "magFilter", map.sampler.magFilter, kAllFilters);
        readEnum(s, "minFilter", map.sampler.minFilter, kAllFilters);
        s.warnAboutUnknownKeys();
    }
    r.warnAboutUnknownKeys();
}

} // namespace

void readMaterial(Messages& messages, const QJsonObject& object, const std::string& path,
    const std::string& baseDir, Material& material)
{
    ObjectReader r(messages, object, path);
    r.string("name", material.name);
    readEnum(r, "alphaMode", material.alphaMode, kAllAlphaModes);
    r.boolean("doubleSided", material.doubleSided);
    r.boolean("unlit", material.unlit);
    // The numbers of no map (the IOR, the emission strength, the alpha cutoff, the anisotropy's
    // rotation, the film's index and minimum thickness): a key each, the registry row's field
    // (core/material/MaterialProperties.h). A map's factor is its map object's "factor".
    for (const MaterialPropertyInfo& info : materialProperties())
        if (!info.slot) {
            double value = scalarOf(material, info.property);
            r.number(info.field, value);
            setScalar(material, info.property, value);
        }
    if (const std::optional<QJsonObject> shading = r.object("shading"))
        readShading(messages, *shading, r.pathOf("shading"), material.shading);
    for (MapSlot slot : kAllMapSlots) {
        const std::optional<QJsonObject> map = r.object(toString(slot));
        if (!map)
            continue;
        if (slot == MapSlot::Clearcoat && map->contains(QLatin1String("roughness"))) {
            // Project format 4 kept the coat's two factors together, {"factor", "roughness"};
            // from version 5 each is its map's factor (docs/project-format.md).
            ObjectReader c(messages, *map, r.pathOf(toString(slot)));
            double factor = material.clearcoat();
            double roughness = material.clearcoatRoughness();
            c.number("factor", factor);
            c.number("roughness", roughness);
            c.warnAboutUnknownKeys();
            material.setFactor(MapSlot::Clearcoat, factor);
            material.setFactor(MapSlot::ClearcoatRoughness, roughness);
            continue;
        }
        readMap(messages, slot, *map, r.pathOf(toString(slot)), baseDir, material.map(slot));
    }
    r.warnAboutUnknownKeys();
}

// ---- Material JSON ----------------------------------------------------------------------

QJsonObject materialToJson(const Material& material, const std::string& baseDir, bool includeTexturePaths)
{
    QJsonObject o;
    o[QLatin1String("name")] = qs(material.name);
    o[QLatin1String("alphaMode")] = QLatin1String(toString(material.alphaMode));
    o[QLatin1String("doubleSided")] = material.doubleSided;
    o[QLatin1String("unlit")] = material.unlit;
    for (const MaterialPropertyInfo& info : materialProperties())
        if (!info.slot)
            o[QLatin1String(info.field)] = scalarOf(material, info.property);
    o[QLatin1String("shading")] = shadingToJson(material.shading);
    for (MapSlot slot : kAllMapSlots)
        o[QLatin1String(toString(slot))] = mapToJson(slot, material.map(slot), baseDir, includeTexturePaths);
    return o;
}

std::optional<Material> materialFromJson(const QJsonObject& object, const std::string& baseDir,
    const std::string& jsonPath, std::string* error, std::string* warning)
{
    Messages messages;
    Material material;
    readMaterial(messages, object, jsonPath, baseDir, material);
    if (messages.failed())
        return failed(messages.error, error);
    std::string invalid;
    if (!material.validate(&invalid))
        return failed((jsonPath.empty() ? "" : jsonPath + ".") + invalid, error);
    appendWarnings(warning, messages.warnings, {});
    return material;
}

} // namespace facet
