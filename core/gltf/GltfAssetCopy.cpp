// The source asset an export keeps (core/gltf/GltfAssetCopy.h).

#include "core/gltf/GltfAssetCopy.h"

#include <map>

#include <QJsonDocument>
#include <QJsonValue>

#include "core/gltf/GltfImport.h"
#include "core/gltf/GltfModel.h"

namespace facet {

namespace {

// Calls edit(element) for each object of parent[key], writing the edits back.
template <class Edit> void editEach(QJsonObject& parent, const QString& key, Edit edit)
{
    if (!parent.contains(key))
        return;
    QJsonArray array = parent.value(key).toArray();
    for (qsizetype i = 0; i < array.size(); ++i) {
        QJsonObject element = array.at(i).toObject();
        edit(element);
        array.replace(i, element);
    }
    parent.insert(key, array);
}

// Calls edit(object) on parent[key] when it is an object, writing the edit back.
template <class Edit> void editObject(QJsonObject& parent, const QString& key, Edit edit)
{
    if (!parent.value(key).isObject())
        return;
    QJsonObject object = parent.value(key).toObject();
    edit(object);
    parent.insert(key, object);
}

// The extensions about materials and textures: Facet writes its own materials and textures, so the
// source's are dropped with them (EXT_meshopt_compression too: it names the source's buffers,
// which become one; its fallback views are kept).
bool isDroppedExtension(const QString& name)
{
    return name.startsWith(QLatin1String("KHR_materials_")) || name == QLatin1String("KHR_texture_transform")
        || name == QLatin1String("KHR_texture_basisu") || name.startsWith(QLatin1String("EXT_texture_"))
        || name == QLatin1String("MSFT_texture_dds") || name == QLatin1String("EXT_meshopt_compression");
}

void dropExtensions(QJsonObject& object)
{
    if (!object.value(QStringLiteral("extensions")).isObject())
        return;
    QJsonObject extensions = object.value(QStringLiteral("extensions")).toObject();
    for (const QString& name : extensions.keys())
        if (isDroppedExtension(name))
            extensions.remove(name);
    if (extensions.isEmpty())
        object.remove(QStringLiteral("extensions"));
    else
        object.insert(QStringLiteral("extensions"), extensions);
}

QJsonArray keptExtensionNames(const QJsonValue& names)
{
    QJsonArray kept;
    for (const QJsonValue& name : names.toArray())
        if (!isDroppedExtension(name.toString()))
            kept.append(name);
    return kept;
}

// The buffer-view references of the geometry: accessors (and their sparse parts) and Draco
// primitives. `visit(object, key)` may read or rewrite object[key].
template <class Visit> void forEachViewReference(QJsonObject& root, Visit visit)
{
    const QString view = QStringLiteral("bufferView");
    editEach(root, QStringLiteral("accessors"), [&](QJsonObject& accessor) {
        visit(accessor, view);
        editObject(accessor, QStringLiteral("sparse"), [&](QJsonObject& sparse) {
            editObject(sparse, QStringLiteral("indices"), [&](QJsonObject& part) { visit(part, view); });
            editObject(sparse, QStringLiteral("values"), [&](QJsonObject& part) { visit(part, view); });
        });
    });
    editEach(root, QStringLiteral("meshes"), [&](QJsonObject& mesh) {
        editEach(mesh, QStringLiteral("primitives"), [&](QJsonObject& primitive) {
            editObject(primitive, QStringLiteral("extensions"), [&](QJsonObject& extensions) {
                editObject(extensions, QStringLiteral("KHR_draco_mesh_compression"),
                    [&](QJsonObject& draco) { visit(draco, view); });
            });
        });
    });
}

} // namespace

std::optional<GltfAssetCopy> copyGltfAsset(const std::string& sourcePath,
    const std::vector<int>& partMaterials, int materialCount, std::string* error)
{
    const auto fail = [&](const std::string& problem) -> std::optional<GltfAssetCopy> {
        if (error)
            *error = sourcePath + ": " + problem;
        return std::nullopt;
    };
    // The parts as the view draws them, and where each comes from.
    GltfImportOptions importOptions;
    importOptions.materialsOnly = true;
    std::string problem;
    const std::optional<GltfAsset> asset = importGltf(sourcePath, &problem, nullptr, importOptions);
    if (!asset) {
        if (error)
            *error = problem.starts_with("importGltf: ") ? problem.substr(12) : problem;
        return std::nullopt;
    }
    const std::vector<GltfAsset::PartSource>& sources = asset->partSources;
    if (!partMaterials.empty() && partMaterials.size() != sources.size())
        return fail("the asset has " + std::to_string(sources.size()) + " drawn parts, the project "
            + std::to_string(partMaterials.size()) + ": it changed since the project was made");

    tinygltf::Model model;
    std::string json;
    if (!gltfmodel::loadModel(sourcePath, importOptions.maxFileBytes, model, &problem, nullptr, &json))
        return fail(problem);
    QJsonParseError parseError {};
    const QJsonDocument document = QJsonDocument::fromJson(QByteArray::fromStdString(json), &parseError);
    if (!document.isObject())
        return fail("its JSON cannot be read again: " + parseError.errorString().toStdString());
    GltfAssetCopy copy;
    QJsonObject root = document.object();

    // Buffer views: those the geometry uses (and any the images do not), copied into one buffer.
    const QJsonArray views = root.value(QStringLiteral("bufferViews")).toArray();
    std::vector<bool> geometryView(std::size_t(views.size()), false);
    std::vector<bool> imageView(std::size_t(views.size()), false);
    const auto inRange = [&](const QJsonValue& value) {
        return value.isDouble() && value.toInt(-1) >= 0 && value.toInt(-1) < views.size();
    };
    forEachViewReference(root, [&](QJsonObject& object, const QString& key) {
        if (inRange(object.value(key)))
            geometryView[std::size_t(object.value(key).toInt())] = true;
    });
    for (const QJsonValue& image : root.value(QStringLiteral("images")).toArray())
        if (inRange(image.toObject().value(QStringLiteral("bufferView"))))
            imageView[std::size_t(image.toObject().value(QStringLiteral("bufferView")).toInt())] = true;
    std::vector<int> renumbered(std::size_t(views.size()), -1);
    for (qsizetype v = 0; v < views.size(); ++v) {
        if (imageView[std::size_t(v)] && !geometryView[std::size_t(v)])
            continue;
        QJsonObject view = views.at(v).toObject();
        const int buffer = view.value(QStringLiteral("buffer")).toInt(-1);
        const qint64 offset = view.value(QStringLiteral("byteOffset")).toInteger(0);
        const qint64 length = view.value(QStringLiteral("byteLength")).toInteger(-1);
        if (buffer < 0 || std::size_t(buffer) >= model.buffers.size() || offset < 0 || length < 0
            || std::uint64_t(offset) + std::uint64_t(length) > model.buffers[std::size_t(buffer)].data.size())
            return fail("buffer view " + std::to_string(v) + " lies outside its buffer");
        while (copy.bytes.size() % 4 != 0) // every component type's alignment
            copy.bytes.append('\0');
        view.insert(QStringLiteral("buffer"), 0);
        view.insert(QStringLiteral("byteOffset"), qint64(copy.bytes.size()));
        copy.bytes.append(
            reinterpret_cast<const char*>(model.buffers[std::size_t(buffer)].data.data()) + offset,
            qsizetype(length));
        dropExtensions(view);
        renumbered[std::size_t(v)] = int(copy.bufferViews.size());
        copy.bufferViews.append(view);
    }
    forEachViewReference(root, [&](QJsonObject& object, const QString& key) {
        if (inRange(object.value(key)))
            object.insert(key, renumbered[std::size_t(object.value(key).toInt())]);
    });

    // Materials: each drawn primitive gets its part's; the rest keep an index that still exists.
    const auto materialOf = [&](std::size_t part) { return partMaterials.empty() ? 0 : partMaterials[part]; };
    std::map<std::pair<int, int>, int> partOf; // (node, primitive) -> part
    std::vector<int> nodesInOrder;
    for (std::size_t part = 0; part < sources.size(); ++part) {
        if (partOf.empty() || nodesInOrder.back() != sources[part].node)
            nodesInOrder.push_back(sources[part].node);
        partOf[{sources[part].node, sources[part].primitive}] = int(part);
    }
    QJsonArray meshes = root.value(QStringLiteral("meshes")).toArray();
    const auto sourceMaterial = [&](const QJsonObject& primitive) {
        const int index = primitive.value(QStringLiteral("material")).toInt(-1);
        return index < materialCount ? index : -1;
    };
    const auto withMaterials = [](QJsonObject mesh, const std::vector<int>& materials) {
        QJsonArray primitives = mesh.value(QStringLiteral("primitives")).toArray();
        for (qsizetype p = 0; p < primitives.size(); ++p) {
            QJsonObject primitive = primitives.at(p).toObject();
            if (materials[std::size_t(p)] >= 0)
                primitive.insert(QStringLiteral("material"), materials[std::size_t(p)]);
            else
                primitive.remove(QStringLiteral("material"));
            dropExtensions(primitive); // KHR_materials_variants names the source's materials
            primitives.replace(p, primitive);
        }
        mesh.insert(QStringLiteral("primitives"), primitives);
        return mesh;
    };
    for (qsizetype m = 0; m < meshes.size(); ++m) {
        const QJsonArray primitives = meshes.at(m).toObject().value(QStringLiteral("primitives")).toArray();
        std::vector<int> materials;
        for (const QJsonValue& primitive : primitives)
            materials.push_back(sourceMaterial(primitive.toObject()));
        meshes.replace(m, withMaterials(meshes.at(m).toObject(), materials));
    }
    QJsonArray nodes = root.value(QStringLiteral("nodes")).toArray();
    std::map<int, std::vector<std::pair<std::vector<int>, int>>> variants; // mesh -> (materials, mesh index)
    for (const int node : nodesInOrder) {
        QJsonObject nodeJson = nodes.at(node).toObject();
        const int mesh = nodeJson.value(QStringLiteral("mesh")).toInt(-1);
        const QJsonObject meshJson = meshes.at(mesh).toObject();
        const QJsonArray primitives = meshJson.value(QStringLiteral("primitives")).toArray();
        std::vector<int> materials;
        for (qsizetype p = 0; p < primitives.size(); ++p) {
            const auto part = partOf.find({node, int(p)});
            materials.push_back(part != partOf.end() ? materialOf(std::size_t(part->second))
                                                     : sourceMaterial(primitives.at(p).toObject()));
        }
        auto& known = variants[mesh];
        const auto same
            = std::find_if(known.begin(), known.end(), [&](const auto& v) { return v.first == materials; });
        int index = mesh;
        if (same != known.end()) {
            index = same->second;
        } else if (known.empty()) {
            meshes.replace(mesh, withMaterials(meshJson, materials));
        } else {
            index = int(meshes.size());
            meshes.append(withMaterials(meshJson, materials));
        }
        if (same == known.end())
            known.emplace_back(materials, index);
        nodeJson.insert(QStringLiteral("mesh"), index);
        nodes.replace(node, nodeJson);
    }
    if (root.contains(QStringLiteral("meshes")))
        root.insert(QStringLiteral("meshes"), meshes);
    if (root.contains(QStringLiteral("nodes")))
        root.insert(QStringLiteral("nodes"), nodes);

    copy.extensionsUsed = keptExtensionNames(root.value(QStringLiteral("extensionsUsed")));
    copy.extensionsRequired = keptExtensionNames(root.value(QStringLiteral("extensionsRequired")));
    dropExtensions(root);
    for (const char* key : {"materials", "textures", "images", "samplers", "buffers", "bufferViews",
             "extensionsUsed", "extensionsRequired"})
        root.remove(QLatin1String(key));
    copy.root = root;
    return copy;
}

} // namespace facet
