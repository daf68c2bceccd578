#include "core/gltf/GltfExport.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <numbers>
#include <optional>
#include <set>

#include <QByteArray>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include "core/export/ExportTemplate.h"
#include "core/gltf/GltfAssetCopy.h"
#include "core/gltf/GltfImport.h"
#include "core/image/ImageWriter.h"
#include "core/material/MaterialProperties.h"
#include "core/support/AtomicFile.h"
#include "core/support/FileSet.h"

namespace facet {

namespace {

// The fields of `extension` for `material`, as the material property registry places them
// (core/material/MaterialProperties.h, GltfField), each in the file's units and left out where it
// equals what the extension means without it. `baked`: the value a field takes instead because a
// baked texture holds factor x texture (1, or the specular colour's scale).
QJsonObject extensionFields(
    const char* extension, const Material& material, const std::map<MaterialProperty, glm::dvec3>& baked = {})
{
    QJsonObject object;
    for (const MaterialPropertyInfo& info : materialProperties()) {
        const GltfField& gltf = info.gltf;
        if (!gltf.extension || std::strcmp(gltf.extension, extension) != 0)
            continue;
        const auto bakedValue = baked.find(info.property);
        const QString field = QString::fromLatin1(gltf.field);
        if (info.value == PropertyValue::Color) {
            const glm::dvec3 rgb
                = bakedValue != baked.end() ? bakedValue->second : colorOf(material, info.property);
            if (rgb != glm::dvec3(gltf.absent))
                object.insert(field, QJsonArray {rgb.r, rgb.g, rgb.b});
            continue;
        }
        const double value
            = (bakedValue != baked.end() ? bakedValue->second.x : scalarOf(material, info.property))
            * gltf.scale;
        if (value != gltf.absent)
            object.insert(field, value);
    }
    return object;
}

constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr int kFloat = 5126;
constexpr int kUnsignedInt = 5125;

// The gltf-textures template's outputs, by the slots they serve.
enum class Texture {
    BaseColor,
    Normal,
    Orm,
    Emissive,
    Clearcoat,
    ClearcoatNormal,
    Sheen,
    Specular,
    Anisotropy,
    Iridescence
};
const char* mapName(Texture texture)
{
    switch (texture) {
    case Texture::BaseColor:
        return "baseColor";
    case Texture::Normal:
        return "normal";
    case Texture::Orm:
        return "occlusionRoughnessMetallic";
    case Texture::Clearcoat:
        return "clearcoat";
    case Texture::ClearcoatNormal:
        return "clearcoatNormal";
    case Texture::Sheen:
        return "sheen";
    case Texture::Specular:
        return "specular";
    case Texture::Anisotropy:
        return "anisotropy";
    case Texture::Iridescence:
        return "iridescence";
    case Texture::Emissive:
        break;
    }
    return "emissive";
}

// The material slots a texture is made from.
std::vector<MapSlot> slotsOf(const std::string& outputMap)
{
    if (outputMap == mapName(Texture::Orm))
        return {MapSlot::Occlusion, MapSlot::Roughness, MapSlot::Metallic};
    if (outputMap == mapName(Texture::Normal))
        return {MapSlot::Normal};
    if (outputMap == mapName(Texture::Emissive))
        return {MapSlot::Emissive};
    if (outputMap == mapName(Texture::Clearcoat))
        return {MapSlot::Clearcoat, MapSlot::ClearcoatRoughness};
    if (outputMap == mapName(Texture::ClearcoatNormal))
        return {MapSlot::ClearcoatNormal};
    if (outputMap == mapName(Texture::Sheen))
        return {MapSlot::SheenColor, MapSlot::SheenRoughness};
    if (outputMap == mapName(Texture::Specular))
        return {MapSlot::SpecularColor, MapSlot::Specular};
    if (outputMap == mapName(Texture::Anisotropy))
        return {MapSlot::Anisotropy};
    if (outputMap == mapName(Texture::Iridescence))
        return {MapSlot::Iridescence, MapSlot::IridescenceThickness};
    return {MapSlot::BaseColor};
}

// The sampler a texture keeps: its textured slots' one sampler, or the default where they
// differ (the bake read each map with its own).
TextureSampler samplerOf(const Material& material, const std::string& outputMap)
{
    std::optional<TextureSampler> common;
    for (const MapSlot slot : slotsOf(outputMap)) {
        const MaterialMap& map = material.map(slot);
        if (!map.hasTexture())
            continue;
        if (common && !(*common == map.sampler))
            return TextureSampler {};
        common = map.sampler;
    }
    return common.value_or(TextureSampler {});
}

// What one material becomes: which textures, the transform they share, the job that bakes them.
struct MaterialPlan {
    bool base = false, normal = false, orm = false, emissive = false;
    // KHR_materials_clearcoat: one texture for the strength (R) and roughness (G), and the coat's
    // normal map; only for a lit material with a coat.
    bool coat = false, coatNormal = false;
    // KHR_materials_sheen: one sRGB texture, the colour in RGB and the roughness in A (linear, as
    // an sRGB texture's alpha is); only for a lit material with a sheen.
    bool sheen = false;
    // KHR_materials_specular: one sRGB texture, the colour in RGB and the strength in A; the colour
    // divided by `specularColorScale` (its factor's largest component when above 1, which the
    // written factor carries) so that a tint above 1 fits the file.
    bool specular = false;
    double specularColorScale = 1.0;
    // KHR_materials_anisotropy: the texture as the extension packs it (direction RG, strength B),
    // baked without the strength factor and the rotation, which stay parameters.
    bool anisotropy = false;
    // KHR_materials_iridescence: one linear texture, the strength in R (baked without the factor,
    // which stays a parameter) and the thickness in G (between the minimum and maximum, which stay
    // parameters); each textureInfo written only for a slot with a texture.
    bool iridescence = false;
    std::optional<UvTransform> shared; // written as KHR_texture_transform
    int texCoord = 0; // the UV set every textured slot reads (textureInfo.texCoord)
    std::optional<TextureSetExport> job;
    std::map<std::string, std::string> fileOf; // {map} -> file name
};

std::string stemOf(const std::string& path)
{
    return std::filesystem::path(path).stem().string();
}

// `secondSet`: the mesh has TEXCOORD_1; without it every map reads set 0, whatever it names.
std::optional<std::vector<MaterialPlan>> planMaterials(const std::string& path,
    const std::vector<Material>& materials, const GltfExportOptions& options, bool secondSet,
    std::string* error)
{
    std::optional<ExportTemplate> gltf = ExportTemplate::builtin("gltf-textures");
    if (!gltf) {
        *error = "the gltf-textures template is missing from this build";
        return std::nullopt;
    }
    if (options.textures.bitDepth != 0 && options.textures.bitDepth != 8 && options.textures.bitDepth != 16) {
        *error = "glTF textures are PNG: 8 or 16 bits, not " + std::to_string(options.textures.bitDepth);
        return std::nullopt;
    }
    std::vector<MaterialPlan> plans;
    std::set<std::string> usedNames;
    for (std::size_t i = 0; i < materials.size(); ++i) {
        const Material& material = materials[i];
        MaterialPlan plan;
        plan.base = material.map(MapSlot::BaseColor).hasTexture();
        plan.normal = material.map(MapSlot::Normal).hasTexture();
        plan.orm = material.map(MapSlot::Occlusion).hasTexture()
            || material.map(MapSlot::Roughness).hasTexture() || material.map(MapSlot::Metallic).hasTexture();
        plan.emissive = material.map(MapSlot::Emissive).hasTexture();
        const bool coated = material.hasClearcoat() && !material.unlit;
        plan.coat = coated
            && (material.map(MapSlot::Clearcoat).hasTexture()
                || material.map(MapSlot::ClearcoatRoughness).hasTexture());
        plan.coatNormal = coated && material.map(MapSlot::ClearcoatNormal).hasTexture();
        plan.sheen = material.hasSheen() && !material.unlit
            && (material.map(MapSlot::SheenColor).hasTexture()
                || material.map(MapSlot::SheenRoughness).hasTexture());
        plan.specular = material.hasSpecular() && !material.unlit
            && (material.map(MapSlot::Specular).hasTexture()
                || material.map(MapSlot::SpecularColor).hasTexture());
        if (plan.specular) {
            const glm::dvec3 tint = material.specularColor();
            plan.specularColorScale = std::max({1.0, tint.r, tint.g, tint.b});
        }
        plan.anisotropy
            = material.hasAnisotropy() && !material.unlit && material.map(MapSlot::Anisotropy).hasTexture();
        plan.iridescence = material.hasIridescence() && !material.unlit
            && (material.map(MapSlot::Iridescence).hasTexture()
                || material.map(MapSlot::IridescenceThickness).hasTexture());

        // One transform on every textured slot: kept as KHR_texture_transform; else baked. The
        // bake writes every map into one texture set, in one UV set: maps on different sets
        // cannot share it.
        Material baked = material;
        std::optional<UvTransform> common;
        std::optional<int> set;
        bool same = true;
        for (const MapSlot slot : kAllMapSlots) {
            const MaterialMap& map = material.map(slot);
            if (!map.hasTexture() || !material.usesSlot(slot)
                || (material.unlit && lobeOf(slot) != MaterialLobe::Core))
                continue;
            const int texCoord = secondSet ? map.texCoord : 0;
            if (set && *set != texCoord) {
                *error = "material '" + material.name + "': its maps read different texture-coordinate sets ("
                    + toString(slot) + " reads TEXCOORD_" + std::to_string(texCoord)
                    + "), which one baked texture set cannot hold: give them one set (docs/export.md)";
                return std::nullopt;
            }
            set = texCoord;
            if (!common)
                common = map.uv;
            else if (!(*common == map.uv))
                same = false;
        }
        plan.texCoord = set.value_or(0);
        if (same && common && !common->isIdentity()) {
            plan.shared = common;
            for (const MapSlot slot : kAllMapSlots)
                baked.map(slot).uv = UvTransform {};
        }
        // glTF has the normal map's strength (normalTexture.scale) and the occlusion strength
        // (occlusionTexture.strength) as parameters: kept as such, not baked (a baked strength
        // changes what filtering between texels gives: the normal is renormalised per texel).
        baked.setFactor(MapSlot::Normal, 1.0);
        baked.setFactor(MapSlot::ClearcoatNormal, 1.0);
        baked.setFactor(MapSlot::Occlusion, 1.0);
        baked.map(MapSlot::SpecularColor).factor /= plan.specularColorScale;
        // The anisotropy's strength and rotation are the extension's parameters too: the texture
        // holds the file's own direction and strength multiplier.
        if (plan.anisotropy)
            baked.setAnisotropy(1.0, 0.0);
        if (plan.iridescence && material.map(MapSlot::Iridescence).hasTexture())
            baked.setFactor(MapSlot::Iridescence, 1.0);
        // File names: "<asset>_<material>_<map>.png", a material name used twice numbered.
        std::string name = fileNameSafe(material.name);
        for (int n = 2; !usedNames.insert(name).second; ++n)
            name = fileNameSafe(material.name) + "_" + std::to_string(n);
        baked.name = name;

        ExportTemplate subset = *gltf;
        subset.id = stemOf(path);
        subset.fileName = "{template}_{material}_{map}";
        subset.outputs.clear();
        for (const ExportOutput& output : gltf->outputs) {
            const bool wanted = (output.map == mapName(Texture::BaseColor) && plan.base)
                || (output.map == mapName(Texture::Normal) && plan.normal)
                || (output.map == mapName(Texture::Orm) && plan.orm)
                || (output.map == mapName(Texture::Emissive) && plan.emissive)
                || (output.map == mapName(Texture::Clearcoat) && plan.coat)
                || (output.map == mapName(Texture::ClearcoatNormal) && plan.coatNormal)
                || (output.map == mapName(Texture::Sheen) && plan.sheen)
                || (output.map == mapName(Texture::Specular) && plan.specular)
                || (output.map == mapName(Texture::Anisotropy) && plan.anisotropy)
                || (output.map == mapName(Texture::Iridescence) && plan.iridescence);
            if (wanted) {
                ExportOutput kept = output;
                kept.optional = false;
                subset.outputs.push_back(kept);
            }
        }
        std::string problem;
        plan.job = TextureSetExport::prepare(subset, {baked}, options.textures, &problem);
        if (!plan.job) {
            *error = problem;
            return std::nullopt;
        }
        for (const PlannedTexture& texture : plan.job->plans().front().files)
            plan.fileOf[texture.output.map] = texture.fileName;
        plans.push_back(std::move(plan));
    }
    return plans;
}

// The binary buffer, 4-byte aligned views.
class Buffer {
public:
    int addView(const void* data, std::size_t bytes, int target, QJsonArray& views)
    {
        while (m_bytes.size() % 4 != 0)
            m_bytes.append('\0');
        QJsonObject view {{QStringLiteral("buffer"), 0},
            {QStringLiteral("byteOffset"), qint64(m_bytes.size())},
            {QStringLiteral("byteLength"), qint64(bytes)}};
        if (target != 0)
            view.insert(QStringLiteral("target"), target);
        m_bytes.append(static_cast<const char*>(data), qsizetype(bytes));
        views.append(view);
        return int(views.size() - 1);
    }
    QByteArray& bytes() { return m_bytes; }

private:
    QByteArray m_bytes;
};

QJsonArray array(std::initializer_list<double> values)
{
    QJsonArray result;
    for (const double v : values)
        result.append(v);
    return result;
}

// `secondSet`: the mesh has TEXCOORD_1. Without it a map on set 1 reads set 0 (as Facet draws it),
// and the file says so rather than naming an attribute it lacks.
QJsonObject textureInfo(int index, const MaterialPlan& plan, bool secondSet, QJsonObject extra = {})
{
    const std::optional<UvTransform>& shared = plan.shared;
    extra.insert(QStringLiteral("index"), index);
    if (plan.texCoord != 0 && secondSet)
        extra.insert(QStringLiteral("texCoord"), plan.texCoord);
    if (shared) {
        const GltfTextureTransform t = toGltfTextureTransform(*shared);
        extra.insert(QStringLiteral("extensions"),
            QJsonObject {{QStringLiteral("KHR_texture_transform"),
                QJsonObject {{QStringLiteral("offset"), array({t.offset.x, t.offset.y})},
                    {QStringLiteral("rotation"), t.rotation},
                    {QStringLiteral("scale"), array({t.scale.x, t.scale.y})}}}});
    }
    return extra;
}

// The mesh as Facet holds it: one view per attribute, the indices in one view, a primitive per
// sub-mesh, one node. The asset's JSON without materials, buffers and buffer views.
QJsonObject meshAsset(const Mesh& mesh, const std::vector<int>& partMaterials, int materialCount,
    Buffer& buffer, QJsonArray& bufferViews)
{
    QJsonArray accessors;
    std::vector<float> positions, normals, uvs, uvs1, tangents, colors;
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const Vertex& v : mesh.vertices) {
        positions.insert(positions.end(), {v.position.x, v.position.y, v.position.z});
        lo = glm::min(lo, v.position);
        hi = glm::max(hi, v.position);
        const glm::vec3 n
            = glm::length(v.normal) > 0.0f ? v.normal / glm::length(v.normal) : glm::vec3(0, 1, 0);
        normals.insert(normals.end(), {n.x, n.y, n.z});
        uvs.insert(uvs.end(), {v.uv.x, 1.0f - v.uv.y}); // glTF: v = 0 is the image's top
        if (mesh.hasTexCoord1)
            uvs1.insert(uvs1.end(), {v.uv1.x, 1.0f - v.uv1.y});
        if (mesh.hasTangents)
            tangents.insert(
                tangents.end(), {v.tangent.x, v.tangent.y, v.tangent.z, v.tangent.w < 0.0f ? -1.0f : 1.0f});
        if (mesh.hasVertexColors) {
            const glm::vec4 c = vertexColor(v);
            colors.insert(colors.end(), {c.r, c.g, c.b, c.a});
        }
    }
    const qint64 count = qint64(mesh.vertices.size());
    const auto attribute = [&](const std::vector<float>& values, const char* type, bool withBounds) {
        const int view
            = buffer.addView(values.data(), values.size() * sizeof(float), kArrayBuffer, bufferViews);
        QJsonObject accessor {{QStringLiteral("bufferView"), view}, {QStringLiteral("componentType"), kFloat},
            {QStringLiteral("count"), count}, {QStringLiteral("type"), QLatin1String(type)}};
        if (withBounds) {
            accessor.insert(QStringLiteral("min"), array({lo.x, lo.y, lo.z}));
            accessor.insert(QStringLiteral("max"), array({hi.x, hi.y, hi.z}));
        }
        accessors.append(accessor);
        return int(accessors.size() - 1);
    };
    QJsonObject attributes {{QStringLiteral("POSITION"), attribute(positions, "VEC3", true)},
        {QStringLiteral("NORMAL"), attribute(normals, "VEC3", false)}};
    if (mesh.hasUvs)
        attributes.insert(QStringLiteral("TEXCOORD_0"), attribute(uvs, "VEC2", false));
    if (mesh.hasTexCoord1)
        attributes.insert(QStringLiteral("TEXCOORD_1"), attribute(uvs1, "VEC2", false));
    if (mesh.hasTangents)
        attributes.insert(QStringLiteral("TANGENT"), attribute(tangents, "VEC4", false));
    if (mesh.hasVertexColors) // glTF COLOR_0, as read (core/mesh/Mesh.h Vertex::color)
        attributes.insert(QStringLiteral("COLOR_0"), attribute(colors, "VEC4", false));
    const int indexView = buffer.addView(
        mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t), kElementArrayBuffer, bufferViews);
    std::vector<SubMesh> parts = mesh.subMeshes;
    if (parts.empty())
        parts.push_back(SubMesh {mesh.name, 0, std::uint32_t(mesh.indices.size()), 0, true});
    QJsonArray primitives;
    for (std::size_t p = 0; p < parts.size(); ++p) {
        const SubMesh& part = parts[p];
        if (part.indexCount == 0)
            continue;
        accessors.append(QJsonObject {{QStringLiteral("bufferView"), indexView},
            {QStringLiteral("byteOffset"), qint64(part.firstIndex) * 4},
            {QStringLiteral("componentType"), kUnsignedInt},
            {QStringLiteral("count"), qint64(part.indexCount)},
            {QStringLiteral("type"), QStringLiteral("SCALAR")}});
        const int material
            = p < partMaterials.size() ? std::clamp(partMaterials[p], 0, materialCount - 1) : 0;
        primitives.append(QJsonObject {{QStringLiteral("attributes"), attributes},
            {QStringLiteral("indices"), int(accessors.size() - 1)}, {QStringLiteral("material"), material}});
    }

    return QJsonObject {
        {QStringLiteral("scene"), 0},
        {QStringLiteral("scenes"), QJsonArray {QJsonObject {{QStringLiteral("nodes"), QJsonArray {0}}}}},
        {QStringLiteral("nodes"),
            QJsonArray {QJsonObject {
                {QStringLiteral("mesh"), 0}, {QStringLiteral("name"), QString::fromStdString(mesh.name)}}}},
        {QStringLiteral("meshes"),
            QJsonArray {QJsonObject {{QStringLiteral("name"), QString::fromStdString(mesh.name)},
                {QStringLiteral("primitives"), primitives}}}},
        {QStringLiteral("accessors"), accessors},
    };
}

} // namespace

GltfTextureTransform toGltfTextureTransform(const UvTransform& uv)
{
    // The inverse of gltfTextureTransform (core/gltf/GltfImport.cpp): the same rotation, and
    // o = (o'.x - s.y sin(theta), 1 - o'.y - s.y cos(theta)).
    GltfTextureTransform t;
    t.scale = uv.scale;
    t.rotation = uv.rotationDegrees * std::numbers::pi / 180.0;
    t.offset = {uv.offset.x - uv.scale.y * std::sin(t.rotation),
        1.0 - uv.offset.y - uv.scale.y * std::cos(t.rotation)};
    return t;
}

std::vector<std::string> gltfAssetFiles(const std::string& path, const std::vector<Material>& materials,
    const GltfExportOptions& options, std::string* error, bool meshHasTexCoord1)
{
    std::vector<std::string> files;
    const std::optional<std::vector<MaterialPlan>> plans
        = planMaterials(path, materials, options, meshHasTexCoord1, error);
    if (!plans)
        return files;
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    if (!options.binary) {
        for (const MaterialPlan& plan : *plans)
            for (const std::string& name : plan.job->fileNames())
                files.push_back((folder / name).string());
        files.push_back((folder / (stemOf(path) + ".bin")).string());
    }
    files.push_back(path);
    return files;
}

bool writeGltfAsset(const std::string& path, const Mesh& mesh, const std::vector<int>& partMaterials,
    const std::vector<Material>& materials, const GltfExportOptions& options, bool replace,
    std::vector<std::string>* written, std::string* error)
{
    const auto fail = [error](const std::string& problem) {
        if (error)
            *error = problem;
        return false;
    };
    if (materials.empty())
        return fail("no material to export");
    if (mesh.vertices.empty() || mesh.indices.empty())
        return fail("the mesh '" + mesh.name + "' has no triangles");
    std::string problem;
    const std::optional<std::vector<MaterialPlan>> plans
        = planMaterials(path, materials, options, mesh.hasTexCoord1, &problem);
    if (!plans)
        return fail(problem);
    // The source asset's nodes, meshes, skins and animations, its materials taken out.
    std::optional<GltfAssetCopy> source;
    if (!options.source.empty()) {
        source = copyGltfAsset(options.source, partMaterials, int(materials.size()), &problem);
        if (!source)
            return fail(problem);
    }

    std::filesystem::path folderPath = std::filesystem::path(path).parent_path();
    if (folderPath.empty())
        folderPath = ".";
    std::error_code code;
    std::filesystem::create_directories(folderPath, code);
    if (!std::filesystem::is_directory(folderPath, code))
        return fail(folderPath.string() + ": cannot make the folder");
    FileSet files(folderPath.string());
    const std::string assetName = std::filesystem::path(path).filename().string();
    const std::string binName = stemOf(path) + ".bin";
    std::vector<std::string> names;
    if (!options.binary) {
        for (const MaterialPlan& plan : *plans)
            for (const std::string& name : plan.job->fileNames())
                names.push_back(name);
        names.push_back(binName);
    }
    names.push_back(assetName);
    if (!replace)
        if (const std::vector<std::string> existing = files.existing(names); !existing.empty())
            return fail(existing.front() + ": exists");
    // All or nothing (core/support/FileSet.h): an asset replaced with --force keeps its old textures and
    // buffer until the new ones are all written.
    if (!files.begin(&problem))
        return fail(folderPath.string() + ": " + problem);

    QJsonArray bufferViews, images, textures, jsonMaterials;
    Buffer buffer;
    std::set<QString> extensionsUsed;
    if (source) {
        buffer.bytes() = source->bytes;
        bufferViews = source->bufferViews;
        for (const QJsonValue& name : source->extensionsUsed)
            extensionsUsed.insert(name.toString());
    }

    // Textures: rendered and encoded; beside the asset or in its buffer.
    std::vector<std::map<std::string, int>> textureIndex(plans->size());
    // {magFilter, minFilter, wrapS, wrapT} (gltfSamplerValues), one per distinct sampler.
    std::vector<std::array<int, 4>> samplers;
    for (std::size_t m = 0; m < plans->size(); ++m) {
        const MaterialPlan& plan = (*plans)[m];
        const TextureSetPlan& set = plan.job->plans().front();
        for (std::size_t f = 0; f < set.files.size(); ++f) {
            const PlannedTexture& texture = set.files[f];
            const std::vector<float> values = plan.job->fileValues(0, f, &problem);
            if (values.empty())
                return fail(problem);
            std::vector<unsigned char> encoded;
            const std::string filePath = files.path(texture.fileName);
            if (!encodeImageFile(
                    filePath, textureFileSpec(texture), values.data(), "export", &encoded, &problem))
                return fail(problem.starts_with("export: ") ? problem.substr(8) : problem);
            QJsonObject image;
            if (options.binary) {
                image.insert(QStringLiteral("bufferView"),
                    buffer.addView(encoded.data(), encoded.size(), 0, bufferViews));
                image.insert(QStringLiteral("mimeType"), QStringLiteral("image/png"));
            } else {
                if (!writeFileAtomically(files.stagedPath(texture.fileName),
                        std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size()),
                        &problem))
                    return fail(filePath + ": cannot write: " + problem);
                files.written(texture.fileName);
                image.insert(QStringLiteral("uri"), QString::fromStdString(texture.fileName));
            }
            image.insert(QStringLiteral("name"), QString::fromStdString(texture.fileName));
            images.append(image);
            const std::array<int, 4> sampler = gltfSamplerValues(samplerOf(materials[m], texture.output.map));
            auto known = std::find(samplers.begin(), samplers.end(), sampler);
            if (known == samplers.end())
                known = samplers.insert(samplers.end(), sampler);
            textures.append(QJsonObject {{QStringLiteral("sampler"), int(known - samplers.begin())},
                {QStringLiteral("source"), int(images.size() - 1)}});
            textureIndex[m][texture.output.map] = int(textures.size() - 1);
        }
    }

    // Materials.
    for (std::size_t m = 0; m < materials.size(); ++m) {
        const Material& material = materials[m];
        const MaterialPlan& plan = (*plans)[m];
        const auto index = [&](Texture texture) { return textureIndex[m].at(mapName(texture)); };
        // One baked texture that two textureInfos of an extension name (the coat's strength and
        // roughness, the sheen's colour and roughness, the specular colour and strength).
        const auto packedTexture
            = [&](QJsonObject& extension, Texture texture, const char* first, const char* second) {
                  const QJsonObject info = textureInfo(index(texture), plan, mesh.hasTexCoord1);
                  extension.insert(QLatin1String(first), info);
                  extension.insert(QLatin1String(second), info);
              };
        if (plan.shared)
            extensionsUsed.insert(QStringLiteral("KHR_texture_transform"));
        QJsonObject pbr;
        const glm::dvec4 base = plan.base ? glm::dvec4(1.0) : material.baseColorFactor();
        pbr.insert(QStringLiteral("baseColorFactor"), array({base.r, base.g, base.b, base.a}));
        if (plan.base)
            pbr.insert(QStringLiteral("baseColorTexture"),
                textureInfo(index(Texture::BaseColor), plan, mesh.hasTexCoord1));
        const bool mrTexture = plan.orm
            && (material.map(MapSlot::Roughness).hasTexture()
                || material.map(MapSlot::Metallic).hasTexture());
        pbr.insert(QStringLiteral("metallicFactor"), mrTexture ? 1.0 : material.metallic());
        pbr.insert(QStringLiteral("roughnessFactor"), mrTexture ? 1.0 : material.roughness());
        if (mrTexture)
            pbr.insert(QStringLiteral("metallicRoughnessTexture"),
                textureInfo(index(Texture::Orm), plan, mesh.hasTexCoord1));
        QJsonObject json {{QStringLiteral("name"), QString::fromStdString(material.name)},
            {QStringLiteral("pbrMetallicRoughness"), pbr}};
        if (plan.normal)
            json.insert(QStringLiteral("normalTexture"),
                textureInfo(index(Texture::Normal), plan, mesh.hasTexCoord1,
                    QJsonObject {{QStringLiteral("scale"), material.normalStrength()}}));
        if (material.map(MapSlot::Occlusion).hasTexture())
            json.insert(QStringLiteral("occlusionTexture"),
                textureInfo(index(Texture::Orm), plan, mesh.hasTexCoord1,
                    QJsonObject {{QStringLiteral("strength"), material.occlusionStrength()}}));
        const glm::dvec3 emissive
            = plan.emissive ? glm::dvec3(1.0) : glm::dvec3(material.map(MapSlot::Emissive).factor);
        const bool emits = plan.emissive || emissive != glm::dvec3(0.0);
        if (emits)
            json.insert(QStringLiteral("emissiveFactor"), array({emissive.r, emissive.g, emissive.b}));
        if (plan.emissive)
            json.insert(QStringLiteral("emissiveTexture"),
                textureInfo(index(Texture::Emissive), plan, mesh.hasTexCoord1));
        if (material.alphaMode != AlphaMode::Opaque) {
            json.insert(QStringLiteral("alphaMode"),
                material.alphaMode == AlphaMode::Mask ? QStringLiteral("MASK") : QStringLiteral("BLEND"));
            if (material.alphaMode == AlphaMode::Mask)
                json.insert(QStringLiteral("alphaCutoff"), material.alphaCutoff);
        }
        if (material.doubleSided)
            json.insert(QStringLiteral("doubleSided"), true);
        QJsonObject extensions;
        // An unlit material carries no extension of the lit model beside KHR_materials_unlit (the
        // validator warns of MULTIPLE_EXTENSIONS): its IOR and emission strength mean nothing.
        // The numbers and colours from the registry (extensionFields); here what decides that an
        // extension is written, and its textures.
        const auto add = [&](const char* extension, const QJsonObject& object) {
            extensions.insert(QLatin1String(extension), object);
            extensionsUsed.insert(QLatin1String(extension));
        };
        if (!material.unlit && std::abs(material.ior - Material::kDefaultIor) > 1e-9)
            add("KHR_materials_ior", extensionFields("KHR_materials_ior", material));
        if (!material.unlit && emits && material.emissiveStrength != 1.0)
            add("KHR_materials_emissive_strength",
                extensionFields("KHR_materials_emissive_strength", material));
        using P = MaterialProperty;
        if (!material.unlit && material.hasClearcoat()) {
            // A baked coat texture holds factor x texture: its factors are 1.
            QJsonObject clearcoat = extensionFields("KHR_materials_clearcoat", material,
                plan.coat ? std::map<P, glm::dvec3> {{P::Clearcoat, glm::dvec3(1.0)},
                    {P::ClearcoatRoughness, glm::dvec3(1.0)}}
                          : std::map<P, glm::dvec3> {});
            if (plan.coat)
                packedTexture(clearcoat, Texture::Clearcoat, "clearcoatTexture", "clearcoatRoughnessTexture");
            if (plan.coatNormal)
                clearcoat.insert(QStringLiteral("clearcoatNormalTexture"),
                    textureInfo(index(Texture::ClearcoatNormal), plan, mesh.hasTexCoord1,
                        QJsonObject {
                            {QStringLiteral("scale"), material.map(MapSlot::ClearcoatNormal).factor.x}}));
            add("KHR_materials_clearcoat", clearcoat);
        }
        if (!material.unlit && material.hasSheen()) {
            // A baked sheen texture holds factor x texture: its factors are 1.
            QJsonObject sheen = extensionFields("KHR_materials_sheen", material,
                plan.sheen ? std::map<P, glm::dvec3> {{P::SheenColor, glm::dvec3(1.0)},
                    {P::SheenRoughness, glm::dvec3(1.0)}}
                           : std::map<P, glm::dvec3> {});
            if (plan.sheen)
                packedTexture(sheen, Texture::Sheen, "sheenColorTexture", "sheenRoughnessTexture");
            add("KHR_materials_sheen", sheen);
        }
        if (!material.unlit && material.hasSpecular()) {
            // A baked texture holds factor x texture (the colour over specularColorScale): the
            // strength's factor is 1, the colour's the scale.
            QJsonObject specular = extensionFields("KHR_materials_specular", material,
                plan.specular ? std::map<P, glm::dvec3> {{P::Specular, glm::dvec3(1.0)},
                    {P::SpecularColor, glm::dvec3(plan.specularColorScale)}}
                              : std::map<P, glm::dvec3> {});
            if (plan.specular)
                packedTexture(specular, Texture::Specular, "specularColorTexture", "specularTexture");
            add("KHR_materials_specular", specular);
        }
        if (!material.unlit && material.hasAnisotropy()) {
            // Strength and rotation as they are: the texture is baked without them.
            QJsonObject anisotropy = extensionFields("KHR_materials_anisotropy", material);
            if (plan.anisotropy)
                anisotropy.insert(QStringLiteral("anisotropyTexture"),
                    textureInfo(index(Texture::Anisotropy), plan, mesh.hasTexCoord1));
            add("KHR_materials_anisotropy", anisotropy);
        }
        if (!material.unlit && material.hasIridescence()) {
            // The factor, the film's index and thickness range as they are: the texture is baked
            // without them.
            QJsonObject iridescence = extensionFields("KHR_materials_iridescence", material);
            const QJsonObject info = plan.iridescence
                ? textureInfo(index(Texture::Iridescence), plan, mesh.hasTexCoord1)
                : QJsonObject {};
            if (plan.iridescence && material.map(MapSlot::Iridescence).hasTexture())
                iridescence.insert(QStringLiteral("iridescenceTexture"), info);
            if (plan.iridescence && material.map(MapSlot::IridescenceThickness).hasTexture())
                iridescence.insert(QStringLiteral("iridescenceThicknessTexture"), info);
            add("KHR_materials_iridescence", iridescence);
        }
        if (material.unlit) {
            extensions.insert(QStringLiteral("KHR_materials_unlit"), QJsonObject {});
            extensionsUsed.insert(QStringLiteral("KHR_materials_unlit"));
        }
        if (!extensions.isEmpty())
            json.insert(QStringLiteral("extensions"), extensions);
        jsonMaterials.append(json);
    }

    QJsonObject asset
        = source ? source->root : meshAsset(mesh, partMaterials, int(materials.size()), buffer, bufferViews);
    QJsonObject assetInfo = asset.value(QStringLiteral("asset")).toObject();
    assetInfo.insert(QStringLiteral("version"), QStringLiteral("2.0"));
    assetInfo.insert(QStringLiteral("generator"), QString::fromStdString(options.generator));
    assetInfo.remove(QStringLiteral("minVersion"));
    asset.insert(QStringLiteral("asset"), assetInfo);
    QJsonObject bufferJson {{QStringLiteral("byteLength"), qint64(buffer.bytes().size())}};
    if (!options.binary)
        bufferJson.insert(QStringLiteral("uri"), QString::fromStdString(binName));
    asset.insert(QStringLiteral("materials"), jsonMaterials);
    asset.insert(QStringLiteral("bufferViews"), bufferViews);
    asset.insert(QStringLiteral("buffers"), QJsonArray {bufferJson});
    if (source && !source->extensionsRequired.isEmpty())
        asset.insert(QStringLiteral("extensionsRequired"), source->extensionsRequired);
    if (!textures.isEmpty()) {
        asset.insert(QStringLiteral("textures"), textures);
        asset.insert(QStringLiteral("images"), images);
        // Each texture's maps' wraps and filters; an Auto filter is left out (the reader's choice).
        QJsonArray jsonSamplers;
        for (const std::array<int, 4>& sampler : samplers) {
            QJsonObject json {{QStringLiteral("wrapS"), sampler[2]}, {QStringLiteral("wrapT"), sampler[3]}};
            if (sampler[0] >= 0)
                json.insert(QStringLiteral("magFilter"), sampler[0]);
            if (sampler[1] >= 0)
                json.insert(QStringLiteral("minFilter"), sampler[1]);
            jsonSamplers.append(json);
        }
        asset.insert(QStringLiteral("samplers"), jsonSamplers);
    }
    if (!extensionsUsed.empty()) {
        QJsonArray used;
        for (const QString& name : extensionsUsed)
            used.append(name);
        asset.insert(QStringLiteral("extensionsUsed"), used);
    }
    QByteArray json
        = QJsonDocument(asset).toJson(options.binary ? QJsonDocument::Compact : QJsonDocument::Indented);

    std::string bytes;
    if (options.binary) {
        // GLB: header, JSON chunk (padded with spaces), BIN chunk (padded with zeros).
        while (json.size() % 4 != 0)
            json.append(' ');
        QByteArray& bin = buffer.bytes();
        while (bin.size() % 4 != 0)
            bin.append('\0');
        const auto u32 = [&bytes](std::uint32_t v) { bytes.append(reinterpret_cast<const char*>(&v), 4); };
        u32(0x46546C67); // "glTF"
        u32(2);
        u32(std::uint32_t(12 + 8 + json.size() + 8 + bin.size()));
        u32(std::uint32_t(json.size()));
        u32(0x4E4F534A); // "JSON"
        bytes.append(json.constData(), std::size_t(json.size()));
        u32(std::uint32_t(bin.size()));
        u32(0x004E4942); // "BIN\0"
        bytes.append(bin.constData(), std::size_t(bin.size()));
    } else {
        if (!writeFileAtomically(files.stagedPath(binName),
                std::string_view(buffer.bytes().constData(), std::size_t(buffer.bytes().size())), &problem))
            return fail(files.path(binName) + ": cannot write: " + problem);
        files.written(binName);
        bytes.assign(json.constData(), std::size_t(json.size()));
    }
    if (!writeFileAtomically(files.stagedPath(assetName), bytes, &problem))
        return fail(files.path(assetName) + ": cannot write: " + problem);
    files.written(assetName);
    if (!files.commit(&problem))
        return fail(problem);
    if (written)
        *written = files.writtenPaths();
    return true;
}

} // namespace facet
