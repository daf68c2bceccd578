#include "core/gltf/GltfImport.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <map>
#include <numbers>
#include <set>
#include <utility>

#include <QFile>
#include <QFileInfo>
#include <QUrl>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "core/gltf/GltfModel.h"
#include "core/gltf/GltfSupport.h"
#include "core/gltf/TinyGltf.h"
#include "core/support/Finite.h"

#include "core/gltf/GltfPrimitive.h"
#include "core/mesh/MeshFinish.h"

#include <nlohmann/json.hpp>

namespace facet {

namespace {

using gltfmodel::AccessorView;
using gltfmodel::accessorView;
using gltfmodel::attributeTypeProblem;
using gltfmodel::component;
using gltfmodel::indexAt;
using gltfmodel::loadModel;
using gltfmodel::MorphDisplacement;
using gltfmodel::morphDisplacement;
using gltfprimitive::Attribute;
using gltfprimitive::decodeDraco;
using gltfprimitive::PrimitiveData;
using gltfsupport::Notes;

// ---- Nodes --------------------------------------------------------------------------------

glm::mat4 localTransform(const tinygltf::Node& node)
{
    if (node.matrix.size() == 16) {
        glm::mat4 m;
        for (int column = 0; column < 4; ++column)
            for (int row = 0; row < 4; ++row)
                m[column][row] = float(node.matrix[std::size_t(column * 4 + row)]); // column-major, as glm
        return m;
    }
    glm::mat4 t(1.0f);
    if (node.translation.size() == 3)
        t[3] = glm::vec4(
            float(node.translation[0]), float(node.translation[1]), float(node.translation[2]), 1.0f);
    glm::mat4 r(1.0f);
    if (node.rotation.size() == 4) {
        // glTF stores (x, y, z, w); glm::quat's constructor takes (w, x, y, z).
        const glm::quat q(float(node.rotation[3]), float(node.rotation[0]), float(node.rotation[1]),
            float(node.rotation[2]));
        r = glm::mat4_cast(glm::length(q) > 0.0f ? glm::normalize(q) : glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
    }
    glm::mat4 s(1.0f);
    if (node.scale.size() == 3) {
        s[0][0] = float(node.scale[0]);
        s[1][1] = float(node.scale[1]);
        s[2][2] = float(node.scale[2]);
    }
    return t * r * s;
}

struct MeshInstance {
    int mesh = -1;
    int node = -1;
    glm::mat4 transform {1.0f};
};

// The mesh instances of the scene to show, depth first with an explicit stack. A node reached a
// second time means a cycle or a node with two parents, both invalid glTF (section 3.5.1).
std::optional<std::vector<MeshInstance>> meshInstances(
    const tinygltf::Model& model, const GltfImportOptions& options, std::string* problem)
{
    std::vector<int> roots;
    const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : (model.scenes.empty() ? -1 : 0);
    if (sceneIndex >= 0) {
        if (std::size_t(sceneIndex) >= model.scenes.size()) {
            gltfsupport::fail("the default scene " + std::to_string(sceneIndex) + " does not exist", problem);
            return std::nullopt;
        }
        roots = model.scenes[std::size_t(sceneIndex)].nodes;
    } else {
        // No scene: every node that is nobody's child is a root.
        std::vector<bool> isChild(model.nodes.size(), false);
        for (const tinygltf::Node& node : model.nodes)
            for (int child : node.children)
                if (child >= 0 && std::size_t(child) < model.nodes.size())
                    isChild[std::size_t(child)] = true;
        for (std::size_t i = 0; i < model.nodes.size(); ++i)
            if (!isChild[i])
                roots.push_back(int(i));
    }
    std::vector<MeshInstance> instances;
    std::vector<bool> visited(model.nodes.size(), false);
    std::vector<std::pair<int, glm::mat4>> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it)
        stack.emplace_back(*it, glm::mat4(1.0f));
    std::size_t visits = 0;
    while (!stack.empty()) {
        const auto [index, parent] = stack.back();
        stack.pop_back();
        if (index < 0 || std::size_t(index) >= model.nodes.size()) {
            gltfsupport::fail("node " + std::to_string(index) + " does not exist (the file has "
                    + std::to_string(model.nodes.size()) + " nodes)",
                problem);
            return std::nullopt;
        }
        if (visited[std::size_t(index)]) {
            gltfsupport::fail("node " + std::to_string(index)
                    + " is reached twice: the node graph has a cycle or a node with two parents",
                problem);
            return std::nullopt;
        }
        visited[std::size_t(index)] = true;
        if (++visits > options.maxNodes) {
            gltfsupport::fail("more than " + std::to_string(options.maxNodes) + " nodes", problem);
            return std::nullopt;
        }
        const tinygltf::Node& node = model.nodes[std::size_t(index)];
        const glm::mat4 global = parent * localTransform(node);
        if (node.mesh >= 0) {
            if (std::size_t(node.mesh) >= model.meshes.size()) {
                gltfsupport::fail("node " + std::to_string(index) + " names mesh " + std::to_string(node.mesh)
                        + ", which does not exist",
                    problem);
                return std::nullopt;
            }
            instances.push_back({node.mesh, index, global});
        }
        for (auto it = node.children.rbegin(); it != node.children.rend(); ++it)
            stack.emplace_back(*it, global);
    }
    return instances;
}

// ---- Primitives ---------------------------------------------------------------------------

struct PartFacts {
    bool hasUvs = false;
    bool hasTangents = false;
    bool flatNormals = false;
};

// Reads the accessors a primitive names, each checked (accessorView) and consistent in count.
std::optional<PrimitiveData> readAccessors(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
    const std::string& where, const GltfImportOptions& options, std::string* problem)
{
    PrimitiveData data;
    const auto attribute = [&](const char* name) {
        const auto it = primitive.attributes.find(name);
        return it == primitive.attributes.end() ? -1 : it->second;
    };
    const int positionIndex = attribute("POSITION");
    if (positionIndex < 0) {
        gltfsupport::fail(where + ": no POSITION attribute", problem);
        return std::nullopt;
    }
    data.position.view = accessorView(model, positionIndex, 3, where + " POSITION", problem);
    if (!data.position.view)
        return std::nullopt;
    const bool quantized
        = std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), "KHR_mesh_quantization")
        != model.extensionsUsed.end();
    if (std::string typeProblem = attributeTypeProblem("POSITION", *data.position.view, quantized, where);
        !typeProblem.empty()) {
        gltfsupport::fail(typeProblem, problem);
        return std::nullopt;
    }
    data.position.components = 3;
    data.vertexCount = data.position.view->count;
    if (data.vertexCount > options.mesh.maxVertices) {
        gltfsupport::fail(where + ": " + std::to_string(data.vertexCount) + " vertices are over the "
                + std::to_string(options.mesh.maxVertices) + " Facet previews (docs/meshes.md, limits)",
            problem);
        return std::nullopt;
    }
    const auto optional = [&](const char* name, int components, Attribute& out) {
        const int index = attribute(name);
        if (index < 0)
            return true;
        out.view = accessorView(model, index, components, where + " " + name, problem);
        if (!out.view)
            return false;
        if (std::string typeProblem = attributeTypeProblem(name, *out.view, quantized, where);
            !typeProblem.empty())
            return gltfsupport::fail(typeProblem, problem);
        out.components = components;
        if (out.view->count != data.vertexCount)
            return gltfsupport::fail(where + " " + name + ": " + std::to_string(out.view->count)
                    + " elements, but POSITION has " + std::to_string(data.vertexCount),
                problem);
        return true;
    };
    // COLOR_0 is RGB or RGBA (glTF 2.0 section 3.7.2.1); its accessor says which.
    const int colorIndex = attribute("COLOR_0");
    const int colorComponents = colorIndex >= 0 && std::size_t(colorIndex) < model.accessors.size()
            && model.accessors[std::size_t(colorIndex)].type == TINYGLTF_TYPE_VEC4
        ? 4
        : 3;
    if (!optional("NORMAL", 3, data.normal) || !optional("TANGENT", 4, data.tangent)
        || !optional("TEXCOORD_0", 2, data.uv) || !optional("TEXCOORD_1", 2, data.uv1)
        || !optional("COLOR_0", colorComponents, data.color))
        return std::nullopt;
    if (primitive.indices >= 0) {
        const auto indices = accessorView(model, primitive.indices, 1, where + " indices", problem);
        if (!indices)
            return std::nullopt;
        if (indices->componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE
            && indices->componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT
            && indices->componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
            gltfsupport::fail(where + " indices: must be unsigned integers", problem);
            return std::nullopt;
        }
        if (indices->count > 3 * options.mesh.maxTriangles) {
            gltfsupport::fail(
                where + ": " + std::to_string(indices->count) + " indices, over the limit", problem);
            return std::nullopt;
        }
        data.indices.resize(indices->count);
        for (std::size_t i = 0; i < indices->count; ++i)
            data.indices[i] = indexAt(*indices, i);
    } else {
        data.indices.resize(data.vertexCount);
        for (std::size_t i = 0; i < data.vertexCount; ++i)
            data.indices[i] = std::uint32_t(i);
    }
    return data;
}

// A primitive instance's sub-mesh name: its mesh's name (else its node's), "#i" when the mesh
// has several primitives.
std::string partName(const tinygltf::Model& model, const MeshInstance& instance, std::size_t primitiveIndex)
{
    const tinygltf::Mesh& gltfMesh = model.meshes[std::size_t(instance.mesh)];
    std::string name = !gltfMesh.name.empty() ? gltfMesh.name : model.nodes[std::size_t(instance.node)].name;
    if (name.empty())
        name = "mesh " + std::to_string(instance.mesh);
    if (gltfMesh.primitives.size() > 1)
        name += " #" + std::to_string(primitiveIndex);
    return name;
}

// Whether a primitive has at least one triangle, from its accessors' declared counts (what
// appendPrimitive would append a sub-mesh for), without reading any vertex data.
bool declaresTriangles(const tinygltf::Model& model, const tinygltf::Primitive& primitive)
{
    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    const auto count = [&model](int accessor) -> std::size_t {
        return accessor >= 0 && std::size_t(accessor) < model.accessors.size()
            ? model.accessors[std::size_t(accessor)].count
            : 0;
    };
    const auto position = primitive.attributes.find("POSITION");
    const std::size_t corners = primitive.indices >= 0 ? count(primitive.indices)
        : position != primitive.attributes.end()       ? count(position->second)
                                                       : 0;
    // A Draco primitive's indices are in its bitstream (loadModel strips "indices"): its
    // POSITION accessor still declares the vertex count.
    if (mode == TINYGLTF_MODE_TRIANGLES)
        return corners >= 3 || primitive.extensions.count("KHR_draco_mesh_compression");
    return corners >= 3;
}

// Appends one primitive instance as a sub-mesh. nullopt with *problem on broken data; a
// PartFacts without a new sub-mesh for points, lines or no triangles.
std::optional<PartFacts> appendPrimitive(const tinygltf::Model& model, const MeshInstance& instance,
    std::size_t primitiveIndex, int materialIndex, const GltfImportOptions& options, Mesh& out,
    std::string* problem)
{
    const tinygltf::Mesh& gltfMesh = model.meshes[std::size_t(instance.mesh)];
    const tinygltf::Primitive& primitive = gltfMesh.primitives[primitiveIndex];
    const std::string where
        = "mesh " + std::to_string(instance.mesh) + " primitive " + std::to_string(primitiveIndex);
    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP
        && mode != TINYGLTF_MODE_TRIANGLE_FAN)
        return PartFacts {}; // points and lines: the caller counts and drops them

    const auto draco = primitive.extensions.find("KHR_draco_mesh_compression");
    const std::optional<PrimitiveData> data = draco != primitive.extensions.end()
        ? decodeDraco(model, primitive, draco->second, where, options, problem)
        : readAccessors(model, primitive, where, options, problem);
    if (!data)
        return std::nullopt;
    const std::size_t vertexCount = data->vertexCount;
    // The node's weights, else the mesh's (glTF 2.0 section 3.7.2.2).
    const tinygltf::Node& node = model.nodes[std::size_t(instance.node)];
    const std::optional<MorphDisplacement> morph = morphDisplacement(model,
        !node.weights.empty() ? node.weights : model.meshes[std::size_t(instance.mesh)].weights, primitive,
        vertexCount, where, problem);
    if (!morph)
        return std::nullopt;

    // Triangle corners as vertex indices of this primitive.
    const std::vector<std::uint32_t>& list = data->indices;
    std::vector<std::uint32_t> corners;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        corners.assign(list.begin(), list.begin() + std::ptrdiff_t(list.size() / 3 * 3));
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        // Every other triangle flips its winding back (glTF 2.0 section 3.7.2.1).
        for (std::size_t i = 0; i + 2 < list.size(); ++i)
            if (i % 2 == 0)
                corners.insert(corners.end(), {list[i], list[i + 1], list[i + 2]});
            else
                corners.insert(corners.end(), {list[i + 1], list[i], list[i + 2]});
    } else {
        for (std::size_t i = 1; i + 1 < list.size(); ++i)
            corners.insert(corners.end(), {list[0], list[i], list[i + 1]});
    }
    for (std::uint32_t c : corners)
        if (c >= vertexCount) {
            gltfsupport::fail(where + ": index " + std::to_string(c) + " is out of range ("
                    + std::to_string(vertexCount) + " vertices)",
                problem);
            return std::nullopt;
        }
    if (corners.empty())
        return PartFacts {};

    const glm::mat3 linear(instance.transform);
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(linear));
    const bool mirrored = glm::determinant(linear) < 0.0f;
    PartFacts facts;
    facts.hasUvs = data->uv.present();
    facts.hasTangents = data->tangent.present() && data->normal.present();
    facts.flatNormals = !data->normal.present();

    if (data->color.present())
        out.hasVertexColors = true;
    if (data->uv1.present())
        out.hasTexCoord1 = true;
    SubMesh sub;
    sub.name = partName(model, instance, primitiveIndex);
    sub.materialIndex = materialIndex;
    sub.firstIndex = std::uint32_t(out.indices.size());

    const auto vertexAt = [&](std::uint32_t i) {
        Vertex v;
        glm::vec3 p(data->position.at(i, 0), data->position.at(i, 1), data->position.at(i, 2));
        if (!morph->position.empty())
            p += morph->position[i];
        v.position = glm::vec3(instance.transform * glm::vec4(p, 1.0f));
        if (data->normal.present()) {
            glm::vec3 n(data->normal.at(i, 0), data->normal.at(i, 1), data->normal.at(i, 2));
            if (!morph->normal.empty())
                n += morph->normal[i];
            v.normal = normalizedOrZero(normalMatrix * n);
        }
        if (data->tangent.present()) {
            glm::vec3 t(data->tangent.at(i, 0), data->tangent.at(i, 1), data->tangent.at(i, 2));
            if (!morph->tangent.empty())
                t += morph->tangent[i];
            const float w = data->tangent.at(i, 3) < 0.0f ? -1.0f : 1.0f;
            // A mirroring transform flips cross(n, t) against the transformed bitangent.
            v.tangent = glm::vec4(linear * t, mirrored ? -w : w);
        }
        if (data->uv.present())
            v.uv = glm::vec2(data->uv.at(i, 0), 1.0f - data->uv.at(i, 1)); // top-left -> bottom-left
        v.uv1 = data->uv1.present() ? glm::vec2(data->uv1.at(i, 0), 1.0f - data->uv1.at(i, 1)) : v.uv;
        if (data->color.present())
            v.color = packVertexColor(glm::vec4(data->color.at(i, 0), data->color.at(i, 1),
                data->color.at(i, 2), data->color.components == 4 ? data->color.at(i, 3) : 1.0f));
        return v;
    };

    const auto base = std::uint32_t(out.vertices.size());
    if (facts.flatNormals) {
        // glTF 2.0 section 3.7.2.1: without normals a client MUST compute flat normals, so each
        // triangle gets vertices of its own with the face normal.
        for (std::size_t t = 0; t + 2 < corners.size(); t += 3) {
            Vertex a = vertexAt(corners[t]), b = vertexAt(corners[t + 1]), c = vertexAt(corners[t + 2]);
            if (mirrored)
                std::swap(b, c);
            const glm::vec3 n
                = normalizedOrZero(glm::cross(b.position - a.position, c.position - a.position));
            a.normal = b.normal = c.normal = n;
            const auto first = std::uint32_t(out.vertices.size());
            out.vertices.insert(out.vertices.end(), {a, b, c});
            out.indices.insert(out.indices.end(), {first, first + 1, first + 2});
        }
    } else {
        for (std::uint32_t i = 0; i < vertexCount; ++i)
            out.vertices.push_back(vertexAt(i));
        for (std::size_t t = 0; t + 2 < corners.size(); t += 3) {
            std::uint32_t a = base + corners[t], b = base + corners[t + 1], c = base + corners[t + 2];
            if (mirrored)
                std::swap(b, c);
            out.indices.insert(out.indices.end(), {a, b, c});
        }
    }
    sub.indexCount = std::uint32_t(out.indices.size()) - sub.firstIndex;
    out.subMeshes.push_back(std::move(sub));
    return facts;
}

bool isPointOrLineMode(int mode)
{
    return mode == TINYGLTF_MODE_POINTS || mode == TINYGLTF_MODE_LINE || mode == TINYGLTF_MODE_LINE_LOOP
        || mode == TINYGLTF_MODE_LINE_STRIP;
}

// Extensions a file may require that Facet reads (everything else it requires is refused).
const std::set<std::string>& supportedRequiredExtensions()
{
    static const std::set<std::string> kSupported = {"KHR_texture_transform",
        "KHR_materials_emissive_strength", "KHR_materials_ior", "KHR_materials_clearcoat",
        "KHR_mesh_quantization", "EXT_texture_webp", "KHR_draco_mesh_compression"};
    return kSupported;
}

std::optional<GltfAsset> importChecked(
    const std::string& path, const GltfImportOptions& options, std::string* problem, Notes& notes)
{
    tinygltf::Model model;
    std::string readerWarning;
    if (!loadModel(path, options.maxFileBytes, model, problem, &readerWarning))
        return std::nullopt;
    if (!readerWarning.empty())
        notes.add(readerWarning);
    for (const std::string& extension : model.extensionsRequired)
        if (!supportedRequiredExtensions().count(extension)) {
            gltfsupport::fail("requires the extension " + extension + ", which Facet does not read", problem);
            return std::nullopt;
        }
    if (model.materials.size() > options.maxMaterials) {
        gltfsupport::fail(std::to_string(model.materials.size()) + " materials, over the limit of "
                + std::to_string(options.maxMaterials),
            problem);
        return std::nullopt;
    }

    const auto instances = meshInstances(model, options, problem);
    if (!instances)
        return std::nullopt;

    GltfAsset asset;
    Notes unreported;
    Notes& materialNotes = options.materialNotes ? notes : unreported;
    for (std::size_t i = 0; i < model.materials.size(); ++i)
        asset.materials.push_back(gltfsupport::convertMaterial(model, int(i), path, materialNotes));
    int defaultMaterial = -1;
    const auto materialFor = [&](int index) -> std::optional<int> {
        if (index >= 0 && std::size_t(index) < model.materials.size())
            return index;
        if (index >= 0)
            return std::nullopt;
        if (defaultMaterial < 0) {
            defaultMaterial = int(asset.materials.size());
            asset.materials.push_back(gltfsupport::defaultGltfMaterial());
        }
        return defaultMaterial;
    };

    Mesh& mesh = asset.mesh;
    mesh.name = QFileInfo(QString::fromStdString(path)).completeBaseName().toStdString();
    ImportedParts parts;
    parts.allHaveTangents = true;
    std::size_t pointsAndLines = 0;
    std::size_t flat = 0;
    for (const MeshInstance& instance : *instances) {
        if (!isFinite(instance.transform) || glm::determinant(glm::mat3(instance.transform)) == 0.0f) {
            notes.add(
                "node " + std::to_string(instance.node) + " has a singular or non-finite transform: skipped");
            continue;
        }
        const tinygltf::Mesh& gltfMesh = model.meshes[std::size_t(instance.mesh)];
        for (std::size_t p = 0; p < gltfMesh.primitives.size(); ++p) {
            const tinygltf::Primitive& primitive = gltfMesh.primitives[p];
            if (isPointOrLineMode(primitive.mode)) {
                ++pointsAndLines;
                continue;
            }
            const std::optional<int> material = materialFor(primitive.material);
            if (!material) {
                gltfsupport::fail("mesh " + std::to_string(instance.mesh) + " primitive " + std::to_string(p)
                        + " names material " + std::to_string(primitive.material) + ", which does not exist",
                    problem);
                return std::nullopt;
            }
            if (mesh.subMeshes.size() >= options.maxParts) {
                gltfsupport::fail("more than " + std::to_string(options.maxParts) + " mesh parts", problem);
                return std::nullopt;
            }
            if (options.materialsOnly) {
                // The parts as the full import makes them, without reading a vertex.
                if (declaresTriangles(model, primitive)) {
                    SubMesh sub;
                    sub.name = partName(model, instance, p);
                    sub.materialIndex = *material;
                    mesh.subMeshes.push_back(std::move(sub));
                    asset.partSources.push_back({instance.node, instance.mesh, int(p)});
                }
                continue;
            }
            const std::size_t before = mesh.subMeshes.size();
            const auto facts = appendPrimitive(model, instance, p, *material, options, mesh, problem);
            if (!facts)
                return std::nullopt;
            if (mesh.subMeshes.size() == before)
                continue; // no triangles
            asset.partSources.push_back({instance.node, instance.mesh, int(p)});
            if (!facts->hasUvs)
                parts.withoutUvs.push_back(before);
            parts.allHaveTangents = parts.allHaveTangents && facts->hasTangents;
            flat += facts->flatNormals ? 1 : 0;
            if (mesh.vertices.size() > options.mesh.maxVertices
                || mesh.triangleCount() > options.mesh.maxTriangles) {
                gltfsupport::fail(std::to_string(mesh.vertices.size()) + " vertices and "
                        + std::to_string(mesh.triangleCount()) + " triangles are over the "
                        + std::to_string(options.mesh.maxVertices) + " / "
                        + std::to_string(options.mesh.maxTriangles)
                        + " Facet previews (docs/meshes.md, limits)",
                    problem);
                return std::nullopt;
            }
        }
    }
    if (pointsAndLines > 0)
        notes.add(std::to_string(pointsAndLines) + " primitive(s) made of points or lines dropped");
    if (flat > 0)
        notes.add("no normals in " + std::to_string(flat)
            + " primitive(s): flat normals generated (glTF 2.0 3.7.2.1)");
    if (mesh.subMeshes.empty()) {
        gltfsupport::fail("contains no triangles", problem);
        return std::nullopt;
    }
    if (options.materialsOnly)
        return asset;
    std::vector<std::string> repairs;
    if (!finishImportedMesh(mesh, parts, options.mesh.uvFallback, repairs, problem))
        return std::nullopt;
    for (const std::string& repair : repairs)
        notes.add(repair);
    // A map on the second set of a mesh without one reads the first (the shader's HAS_TEXCOORD_1
    // is off): say so, as the glTF validator would.
    if (!mesh.hasTexCoord1)
        for (const Material& material : asset.materials)
            for (const MapSlot slot : kAllMapSlots)
                if (material.map(slot).hasTexture() && material.map(slot).texCoord == 1)
                    notes.add("material '" + material.name + "' " + toString(slot)
                        + " reads TEXCOORD_1, which no primitive has: set 0 is read");
    return asset;
}

} // namespace

bool isGltfFileName(const std::string& path)
{
    const QString suffix = QFileInfo(QString::fromStdString(path)).suffix().toLower();
    return suffix == QLatin1String("gltf") || suffix == QLatin1String("glb");
}

std::optional<GltfAsset> importGltf(
    const std::string& path, std::string* error, std::string* warning, const GltfImportOptions& options)
{
    if (warning)
        warning->clear();
    Notes notes;
    std::string problem;
    std::optional<GltfAsset> asset;
    try {
        asset = importChecked(path, options, &problem, notes);
    } catch (const std::bad_alloc&) {
        problem = "out of memory";
    } catch (const std::exception& e) {
        problem = std::string("the glTF reader failed: ") + e.what();
    }
    if (!asset) {
        if (error)
            *error = "importGltf: " + path + ": " + problem;
        return std::nullopt;
    }
    if (warning && !notes.empty())
        *warning = "importGltf: " + path + ": " + notes.joined();
    return asset;
}

std::string gltfImageReference(const std::string& assetPath, int imageIndex)
{
    return assetPath + "#images/" + std::to_string(imageIndex);
}

std::optional<GltfImageReference> parseGltfImageReference(const std::string& path)
{
    const std::string marker = "#images/";
    const std::size_t at = path.rfind(marker);
    if (at == std::string::npos)
        return std::nullopt;
    const std::string asset = path.substr(0, at);
    const std::string digits = path.substr(at + marker.size());
    if (!isGltfFileName(asset) || digits.empty() || digits.size() > 9
        || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return std::nullopt;
    return GltfImageReference {asset, std::stoi(digits)};
}

std::string fileOfImagePath(const std::string& path)
{
    if (QFileInfo::exists(QString::fromStdString(path)))
        return path;
    if (const auto reference = parseGltfImageReference(path))
        return reference->assetPath;
    return path;
}

std::optional<std::vector<unsigned char>> readGltfImage(
    const GltfImageReference& reference, std::string* mimeType, std::string* error)
{
    const auto failed = [&](const std::string& problem) -> std::optional<std::vector<unsigned char>> {
        if (error)
            *error = "readGltfImage: " + gltfImageReference(reference.assetPath, reference.imageIndex) + ": "
                + problem;
        return std::nullopt;
    };
    tinygltf::Model model;
    std::string problem;
    if (!loadModel(reference.assetPath, GltfImportOptions {}.maxFileBytes, model, &problem, nullptr))
        return failed(problem);
    if (reference.imageIndex < 0 || std::size_t(reference.imageIndex) >= model.images.size())
        return failed("the asset has " + std::to_string(model.images.size()) + " images");
    const tinygltf::Image& image = model.images[std::size_t(reference.imageIndex)];
    if (mimeType)
        *mimeType = image.mimeType;
    if (image.bufferView >= 0) {
        if (std::size_t(image.bufferView) >= model.bufferViews.size())
            return failed("its buffer view " + std::to_string(image.bufferView) + " does not exist");
        const tinygltf::BufferView& view = model.bufferViews[std::size_t(image.bufferView)];
        if (view.buffer < 0 || std::size_t(view.buffer) >= model.buffers.size())
            return failed("its buffer view names no buffer");
        const std::vector<unsigned char>& data = model.buffers[std::size_t(view.buffer)].data;
        if (std::uint64_t(view.byteOffset) + std::uint64_t(view.byteLength) > data.size()
            || view.byteLength == 0)
            return failed("its bytes reach past the end of the buffer (the file may be cut short)");
        return std::vector<unsigned char>(data.begin() + std::ptrdiff_t(view.byteOffset),
            data.begin() + std::ptrdiff_t(view.byteOffset + view.byteLength));
    }
    if (image.as_is && !image.image.empty())
        return image.image; // a data URI, kept encoded by keepEncodedImage()
    return failed(
        image.uri.empty() ? "no image data" : "it is the external file '" + image.uri + "', not embedded");
}

UvTransform gltfTextureTransform(const glm::dvec2& offset, double rotationRadians, const glm::dvec2& scale)
{
    // The matrix the sample renderers use (the Khronos glTF Sample Viewer's material.js and
    // three.js's setUvTransform): M = T(o) R(-theta) S(s) with R(a) the counter-clockwise rotation
    // [[cos a, -sin a], [sin a, cos a]]. The GLSL printed in the extension's README builds R(theta)
    // instead (its mat3 takes columns); the TextureTransformTest asset's arrows, and every
    // renderer of the glTF render-fidelity comparison, follow the renderers (issue 29: Facet's
    // arrows pointed at the "opposite direction" marker). docs/gltf.md, "Texture transforms".
    //
    // Facet's UVs start at the bottom-left: F M F with F(u, v) = (u, 1 - v). For D = diag(1, -1),
    // D R(-theta) D = R(theta) and D S D = S, so the linear part is R(theta) S; the translation is
    // D R(-theta) S (0, 1) + D o + (0, 1) = (o.x + s.y sin(theta), 1 - o.y - s.y cos(theta)).
    UvTransform uv;
    uv.scale = scale;
    uv.rotationDegrees = rotationRadians * 180.0 / std::numbers::pi;
    uv.offset = {
        offset.x + scale.y * std::sin(rotationRadians), 1.0 - offset.y - scale.y * std::cos(rotationRadians)};
    return uv;
}

} // namespace facet
