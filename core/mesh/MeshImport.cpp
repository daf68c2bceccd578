#include "core/mesh/MeshImport.h"

#include "core/gltf/GltfImport.h"
#include "core/mesh/MeshFinish.h"
#include "core/support/FileCheck.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>
#include <utility>
#include <vector>

#include <QFile>
#include <QFileInfo>

#include <assimp/DefaultIOSystem.h>
#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace facet {

namespace {

// Post-processing after the raw read (Assimp runs the steps in its own fixed order, not this
// one). GenSmoothNormals only fills in meshes without normals. CalcTangentSpace is left out on
// purpose: tangents the file lacks come from generateTangents(), so an imported mesh, a
// primitive and a mesh with generated UVs all get the same MikkTSpace-like frame (glTF 2.0 asks
// for MikkTSpace; Assimp's step is a different algorithm: unweighted per-face tangents smoothed
// between vertices at one position within 45 degrees). docs/meshes.md, section 5.
constexpr unsigned kPostProcess = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices
    | aiProcess_GenSmoothNormals | aiProcess_SortByPType | aiProcess_FindInvalidData
    | aiProcess_FindDegenerates | aiProcess_GenUVCoords;

glm::mat4 toGlm(const aiMatrix4x4& m)
{
    // aiMatrix4x4 is row-major (a1..a4 is the first row), glm is column-major.
    return glm::mat4(
        m.a1, m.b1, m.c1, m.d1, m.a2, m.b2, m.c2, m.d2, m.a3, m.b3, m.c3, m.d3, m.a4, m.b4, m.c4, m.d4);
}

glm::vec3 toGlm(const aiVector3D& v)
{
    return {v.x, v.y, v.z};
}

struct Instance {
    const aiMesh* mesh;
    const aiNode* node;
    glm::mat4 transform;
};

// Every mesh instance in the node tree with its node's global transform. Depth-first with an
// explicit stack: a deep hierarchy in a hostile file cannot overflow the call stack.
std::vector<Instance> flatten(const aiScene& scene)
{
    std::vector<Instance> instances;
    std::vector<std::pair<const aiNode*, glm::mat4>> stack;
    if (scene.mRootNode)
        stack.emplace_back(scene.mRootNode, glm::mat4(1.0f));
    while (!stack.empty()) {
        const auto [node, parent] = stack.back();
        stack.pop_back();
        const glm::mat4 global = parent * toGlm(node->mTransformation);
        for (unsigned i = 0; i < node->mNumMeshes; ++i)
            if (node->mMeshes[i] < scene.mNumMeshes)
                instances.push_back({scene.mMeshes[node->mMeshes[i]], node, global});
        // Children pushed in reverse so they come off the stack in file order.
        for (unsigned c = node->mNumChildren; c-- > 0;)
            if (node->mChildren[c])
                stack.emplace_back(node->mChildren[c], global);
    }
    return instances;
}

bool isTriangleMesh(const aiMesh& mesh)
{
    return (mesh.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) != 0 && mesh.mNumFaces > 0
        && mesh.mNumVertices > 0;
}

std::string subMeshName(const Instance& instance, std::size_t index)
{
    if (instance.mesh->mName.length > 0)
        return instance.mesh->mName.C_Str();
    if (instance.node->mName.length > 0)
        return instance.node->mName.C_Str();
    return "mesh " + std::to_string(index);
}

// Per-part facts the flattening collects for the steps after it.
struct PartInfo {
    bool hasUvs = false;
    bool hasTangents = false;
};

// Appends one instance: positions by its transform, normals by the inverse transpose, tangents
// and bitangents by the transform, winding reversed when the transform mirrors.
PartInfo appendInstance(Mesh& out, const Instance& instance, std::size_t index)
{
    const aiMesh& in = *instance.mesh;
    const glm::mat3 linear(instance.transform);
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(linear));
    const bool mirrored = glm::determinant(linear) < 0.0f;
    const bool hasUvs = in.mTextureCoords[0] != nullptr;
    const bool hasUv1 = hasUvs && in.mTextureCoords[1] != nullptr;
    if (hasUv1)
        out.hasTexCoord1 = true;
    const bool hasTangents = in.mTangents != nullptr && in.mBitangents != nullptr && in.mNormals != nullptr;

    SubMesh sub;
    sub.name = subMeshName(instance, index);
    sub.firstIndex = uint32_t(out.indices.size());
    sub.materialIndex = int(in.mMaterialIndex);
    const auto base = uint32_t(out.vertices.size());
    for (unsigned i = 0; i < in.mNumVertices; ++i) {
        Vertex v;
        v.position = glm::vec3(instance.transform * glm::vec4(toGlm(in.mVertices[i]), 1.0f));
        // Zero where the file had none or a broken one: repaired from the faces afterwards.
        v.normal = in.mNormals ? normalizedOrZero(normalMatrix * toGlm(in.mNormals[i])) : glm::vec3(0.0f);
        if (hasUvs)
            v.uv = {in.mTextureCoords[0][i].x, in.mTextureCoords[0][i].y};
        v.uv1 = hasUv1 ? glm::vec2(in.mTextureCoords[1][i].x, in.mTextureCoords[1][i].y) : v.uv;
        if (hasTangents) {
            const glm::vec3 t = linear * toGlm(in.mTangents[i]);
            const glm::vec3 b = linear * toGlm(in.mBitangents[i]);
            v.tangent = glm::vec4(t, glm::dot(glm::cross(v.normal, t), b) < 0.0f ? -1.0f : 1.0f);
        }
        out.vertices.push_back(v);
    }
    for (unsigned f = 0; f < in.mNumFaces; ++f) {
        const aiFace& face = in.mFaces[f];
        if (face.mNumIndices != 3)
            continue; // SortByPType put points and lines in meshes of their own; belt and braces
        const uint32_t a = base + face.mIndices[0];
        uint32_t b = base + face.mIndices[1], c = base + face.mIndices[2];
        if (mirrored)
            std::swap(b, c);
        out.indices.insert(out.indices.end(), {a, b, c});
    }
    sub.indexCount = uint32_t(out.indices.size()) - sub.firstIndex;
    out.subMeshes.push_back(std::move(sub));
    return {hasUvs, hasTangents};
}

// A PLY header as the checks below read it: the format and each element with its count and
// properties. Parsed once from the lines before "end_header".
struct PlyHeader {
    struct Property {
        bool list = false; // "property list ..."
        QByteArray type; // a scalar's type, or a whole list line's count type
        QByteArray itemType; // a list's item type
    };
    struct Element {
        QByteArray name;
        double count = 0; // a double: counts up to 2^32 times properties overflow nothing
        QByteArray countText; // as written
        std::vector<Property> properties;
    };
    bool ascii = false;
    bool bigEndian = false; // binary_big_endian
    std::vector<Element> elements;
};

// A PLY scalar type's size in bytes; 0 for a name that is none.
int plyScalarBytes(const QByteArray& type)
{
    static const std::pair<const char*, int> kSizes[] = {{"char", 1}, {"uchar", 1}, {"int8", 1}, {"uint8", 1},
        {"short", 2}, {"ushort", 2}, {"int16", 2}, {"uint16", 2}, {"int", 4}, {"uint", 4}, {"int32", 4},
        {"uint32", 4}, {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
    for (const auto& [name, bytes] : kSizes)
        if (type == name)
            return bytes;
    return 0;
}

// nullopt with *problem for an element count that is not a number (or negative).
std::optional<PlyHeader> parsePlyHeader(const QList<QByteArray>& lines, std::string* problem)
{
    PlyHeader header;
    for (const QByteArray& rawLine : lines) {
        const QList<QByteArray> words = rawLine.simplified().split(' ');
        if (words.size() >= 2 && words[0] == "format") {
            header.ascii = words[1] == "ascii";
            header.bigEndian = words[1] == "binary_big_endian";
        } else if (words.size() >= 3 && words[0] == "element") {
            bool ok = false;
            const double count = words[2].toDouble(&ok);
            if (!ok || count < 0) {
                *problem = "broken PLY header: element \"" + words[1].toStdString() + "\" has the count \""
                    + words[2].toStdString() + "\"";
                return std::nullopt;
            }
            header.elements.push_back({words[1], count, words[2], {}});
        } else if (words.size() >= 3 && words[0] == "property" && !header.elements.empty()) {
            const bool list = words[1] == "list";
            header.elements.back().properties.push_back(
                {list, list && words.size() >= 5 ? words[2] : words[1],
                    list && words.size() >= 5 ? words[3] : QByteArray()});
        }
    }
    return header;
}

// The fewest bytes the elements a PLY header declares can take: in ASCII each value is at least
// one digit and one separator, in binary each scalar its size and each list its count. A header
// claiming more than the file holds (210 bytes declaring 10 million vertices) is refused here,
// before Assimp reserves memory for it and reads on for minutes.
std::string plyBodyProblem(const PlyHeader& header, qint64 bodyBytes)
{
    const auto scalarBytes
        = [](const QByteArray& type) -> double { return std::max(plyScalarBytes(type), 1); };
    double needed = 0; // bytes
    std::string claimed;
    for (const PlyHeader::Element& element : header.elements) {
        double elementBytes = 0;
        for (const PlyHeader::Property& property : element.properties)
            elementBytes += header.ascii ? 2.0 : scalarBytes(property.type);
        // An element without (known) properties still costs its reader a loop per instance:
        // count it as a byte each (a line in ASCII), so 1e11 of them in a 246-byte file are
        // refused too.
        needed += element.count * std::max(elementBytes, 1.0);
        claimed += (claimed.empty() ? "" : ", ") + element.countText.toStdString() + " "
            + element.name.toStdString();
    }
    if (header.ascii && needed > 0)
        needed -= 1; // the last value needs no separator
    if (needed > double(bodyBytes))
        return "broken PLY file: its header declares " + claimed + " elements, at least "
            + std::to_string(static_cast<long long>(std::min(needed, 9e18))) + " bytes of data, but "
            + std::to_string(std::max<qint64>(bodyBytes, 0)) + " bytes follow the header";
    return {};
}

// An ASCII PLY list's count is read from the data (a face's "3 0 1 2"): Assimp reads as many
// values as it says, past the end of the file, so a count of 99999999999 in a 258-byte file ran
// for minutes. Elements are taken a line each (as writers write them); a list count larger than
// every value left in the file is refused.
std::string plyAsciiListProblem(const PlyHeader& header, const QByteArray& body)
{
    const auto hasList = [](const PlyHeader::Element& e) {
        return std::any_of(e.properties.begin(), e.properties.end(), [](const auto& p) { return p.list; });
    };
    if (std::none_of(header.elements.begin(), header.elements.end(), hasList))
        return {};
    // Each line's values, split once.
    std::vector<QList<QByteArray>> lines;
    double remaining = 0; // values left in the file from the current line on
    for (const QByteArray& rawLine : body.split('\n')) {
        const QByteArray simple = rawLine.simplified();
        if (simple.isEmpty())
            continue;
        lines.push_back(simple.split(' '));
        remaining += double(lines.back().size());
    }
    const std::vector<PlyHeader::Element>& elements = header.elements;
    std::size_t element = 0;
    double instance = 0;
    for (const QList<QByteArray>& values : lines) {
        while (element < elements.size() && instance >= elements[element].count) {
            ++element;
            instance = 0;
        }
        if (element >= elements.size())
            break;
        qsizetype at = 0;
        for (std::size_t p = 0; p < elements[element].properties.size() && at < values.size(); ++p) {
            if (!elements[element].properties[p].list) {
                ++at;
                continue;
            }
            const double count = values[at].toDouble();
            if (!(count <= remaining - double(at) - 1.0))
                return "broken PLY file: " + elements[element].name.toStdString() + " "
                    + std::to_string(static_cast<long long>(instance)) + " has a list of "
                    + values[at].left(24).toStdString() + " values, more than the file holds";
            at += 1 + qsizetype(count);
        }
        remaining -= double(values.size());
        instance += 1;
    }
    return {};
}

// The same for a binary PLY: a face's list count is a number in the data, and Assimp reserves
// what it says before reading (a count of 300 million took 2.4 GB and 14 s before Assimp refused
// the file, issue 29). The body is walked element by element (elements without lists in one
// step) and a list whose count times its item size is more than the bytes left is refused.
std::string plyBinaryListProblem(const PlyHeader& header, QFile& file, qint64 bodyStart)
{
    const auto hasList = [](const PlyHeader::Element& e) {
        return std::any_of(e.properties.begin(), e.properties.end(), [](const auto& p) { return p.list; });
    };
    if (std::none_of(header.elements.begin(), header.elements.end(), hasList))
        return {};
    if (!file.seek(bodyStart))
        return {};
    const QByteArray body = file.readAll(); // the whole body: plyBodyProblem bounded what it may claim
    const qint64 size = body.size();
    const auto readCount = [&](qint64 at, int bytes, const QByteArray& type) -> double {
        std::uint64_t raw = 0;
        for (int i = 0; i < bytes; ++i) {
            const auto byte = std::uint64_t(static_cast<unsigned char>(body[at + i]));
            raw |= header.bigEndian ? byte << (8 * (bytes - 1 - i)) : byte << (8 * i);
        }
        const bool isSigned = type == "char" || type == "int8" || type == "short" || type == "int16"
            || type == "int" || type == "int32";
        if (isSigned && bytes < 8 && (raw >> (8 * bytes - 1)) != 0)
            return -1.0; // negative
        if (type == "float" || type == "float32" || type == "double" || type == "float64")
            return -2.0; // a float count: Assimp's reader takes it as garbage too
        return double(raw);
    };
    qint64 at = 0;
    for (const PlyHeader::Element& element : header.elements) {
        if (!hasList(element)) {
            double bytes = 0;
            for (const PlyHeader::Property& property : element.properties)
                bytes += std::max(plyScalarBytes(property.type), 1);
            at += qint64(std::min(element.count * bytes, 9e18));
            if (at > size)
                return {}; // plyBodyProblem reported this already
            continue;
        }
        for (double instance = 0; instance < element.count; instance += 1) {
            for (const PlyHeader::Property& property : element.properties) {
                const int countBytes = std::max(plyScalarBytes(property.type), 1);
                if (!property.list) {
                    at += countBytes;
                    continue;
                }
                if (at + countBytes > size)
                    return "broken PLY file: " + element.name.toStdString() + " "
                        + std::to_string(static_cast<long long>(instance)) + " is cut short";
                const double count = readCount(at, countBytes, property.type);
                at += countBytes;
                const double itemBytes = std::max(plyScalarBytes(property.itemType), 1);
                if (count < 0 || count * itemBytes > double(size - at))
                    return "broken PLY file: " + element.name.toStdString() + " "
                        + std::to_string(static_cast<long long>(instance)) + " has a list of "
                        + (count < 0 ? std::string("a negative or non-integer number of")
                                     : std::to_string(static_cast<long long>(count)))
                        + " values, more than the " + std::to_string(size - at)
                        + " bytes left in the file hold";
                at += qint64(count * itemBytes);
            }
        }
    }
    return {};
}

// Assimp 5.2's PLY reader can loop forever on a header without a complete "end_header" line (a
// file cut short, or a damaged keyword; found by fuzzing with mutated files, docs/meshes.md). A PLY
// file (by extension or by its "ply" magic, which Assimp also goes by) must show that line
// within its first MiB before Assimp sees it; its body must hold what the header declares
// (plyBodyProblem) and, in ASCII, what its lists count (plyAsciiListProblem). Empty when the file
// is fine or not a PLY.
std::string plyHeaderProblem(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    const QByteArray head = file.read(1 << 20);
    const bool plyMagic = head.startsWith("ply\n") || head.startsWith("ply\r");
    if (!plyMagic && !path.endsWith(QLatin1String(".ply"), Qt::CaseInsensitive))
        return {};
    if (!plyMagic)
        return "not a PLY file: it does not start with the line \"ply\"";
    // Only whole lines count: a file cut right after "end_header", before its newline, hangs too.
    const QList<QByteArray> lines = head.split('\n');
    qsizetype headerBytes = 0;
    for (qsizetype i = 0; i + 1 < lines.size(); ++i) {
        headerBytes += lines[i].size() + 1;
        if (lines[i].trimmed() != "end_header")
            continue;
        std::string problem;
        const std::optional<PlyHeader> header = parsePlyHeader(lines.mid(0, i), &problem);
        if (!header)
            return problem;
        if (problem = plyBodyProblem(*header, file.size() - headerBytes); !problem.empty())
            return problem;
        if (!header->ascii)
            return plyBinaryListProblem(*header, file, headerBytes);
        file.seek(headerBytes);
        return plyAsciiListProblem(*header, file.readAll());
    }
    return "broken PLY header: no \"end_header\" line in the first MiB (the file may be cut short)";
}

// Assimp opens the files a model names (an OBJ's mtllib, ...) with fopen: a FIFO there blocks
// the import for ever, a device reads without end. Only regular files are opened; the format's
// reader then treats the file as missing (an OBJ's material library: a warning).
class RegularFilesOnly : public Assimp::DefaultIOSystem {
public:
    bool Exists(const char* file) const override { return file && checkRegularFile(file).ok(); }
    Assimp::IOStream* Open(const char* file, const char* mode) override
    {
        if (!file || !checkRegularFile(file).ok())
            return nullptr;
        return DefaultIOSystem::Open(file, mode);
    }
};

std::string joined(const std::vector<std::string>& parts)
{
    std::string text;
    for (const std::string& part : parts)
        text += (text.empty() ? "" : "; ") + part;
    return text;
}

std::optional<Mesh> importChecked(const std::string& path, const MeshImportOptions& options,
    std::string* error, std::vector<std::string>& warnings)
{
    const auto failed = [&](const std::string& problem) -> std::optional<Mesh> {
        if (error)
            *error = "importMesh: " + path + ": " + problem;
        return std::nullopt;
    };

    Assimp::Importer importer;
    importer.SetIOHandler(new RegularFilesOnly); // the importer owns it
    importer.SetPropertyFloat(AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, options.smoothingAngleDegrees);
    // Remove degenerate triangles outright (instead of turning them into lines), and only those
    // with coincident corners: the area test's fixed 1e-6 threshold would delete every triangle
    // of a model made in metres with millimetre detail.
    importer.SetPropertyBool(AI_CONFIG_PP_FD_REMOVE, true);
    importer.SetPropertyBool(AI_CONFIG_PP_FD_CHECKAREA, false);

    // Read raw and validated first, to see what the file itself holds before post-processing
    // fills it in; ValidateDataStructure catches out-of-range indices and the like.
    const aiScene* scene = importer.ReadFile(path, aiProcess_ValidateDataStructure);
    if (!scene) {
        const std::string reason = importer.GetErrorString();
        if (reason.find("mNumMeshes is 0") != std::string::npos)
            return failed("contains no meshes (Assimp: " + reason + ")");
        return failed("Assimp cannot read it: " + reason);
    }
    if (scene->mNumMeshes == 0 || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
        return failed("contains no meshes");

    std::size_t rawVertices = 0;
    bool normalsMissing = false;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh& raw = *scene->mMeshes[m];
        // Assimp 5.2's validation lets a face with no indices through (a PLY face list cut
        // short), and Debian builds Assimp with its asserts on, so Triangulate would abort the
        // process on it (found by fuzzing, docs/meshes.md). Refuse it here.
        for (unsigned f = 0; f < raw.mNumFaces; ++f)
            if (raw.mFaces[f].mNumIndices == 0 || !raw.mFaces[f].mIndices)
                return failed(
                    "face " + std::to_string(f) + " of mesh " + std::to_string(m) + " has no vertices");
        rawVertices += raw.mNumVertices;
        normalsMissing = normalsMissing || (isTriangleMesh(raw) && !raw.mNormals);
    }
    // Formats without shared vertices (STL, some OBJ) hold up to a triangle's worth of copies of
    // each vertex until JoinIdenticalVertices: refuse only what cannot shrink under the limit.
    if (rawVertices / 8 > options.maxVertices)
        return failed(std::to_string(rawVertices) + " vertices, far over the "
            + std::to_string(options.maxVertices) + " Facet previews (docs/meshes.md, limits)");

    scene = importer.ApplyPostProcessing(kPostProcess);
    if (!scene)
        return failed("Assimp cannot process it: " + std::string(importer.GetErrorString()));

    std::size_t droppedMeshes = 0;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m)
        droppedMeshes += isTriangleMesh(*scene->mMeshes[m]) ? 0 : 1;
    if (droppedMeshes > 0)
        warnings.push_back(std::to_string(droppedMeshes) + " part(s) made of points or lines dropped");

    std::vector<Instance> instances;
    std::size_t vertexCount = 0, triangleCount = 0, singular = 0;
    for (const Instance& instance : flatten(*scene)) {
        if (!isTriangleMesh(*instance.mesh))
            continue;
        // A transform that flattens the mesh to a plane or a point leaves no usable normals.
        const glm::mat3 linear(instance.transform);
        const float det = glm::determinant(linear);
        const float scale
            = std::max({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])});
        if (!std::isfinite(det) || !(std::abs(det) > 1e-12f * scale * scale * scale)) {
            ++singular;
            continue;
        }
        instances.push_back(instance);
        vertexCount += instance.mesh->mNumVertices;
        triangleCount += instance.mesh->mNumFaces;
    }
    if (singular > 0)
        warnings.push_back(
            std::to_string(singular) + " instance(s) with a singular or non-finite transform skipped");
    if (instances.empty())
        return failed("contains no triangles");
    if (vertexCount > options.maxVertices)
        return failed(std::to_string(vertexCount) + " vertices (all instances) are over the "
            + std::to_string(options.maxVertices) + " Facet previews: at 56 bytes each that is more memory"
            + " than a preview should take (docs/meshes.md, limits)");
    if (triangleCount > options.maxTriangles)
        return failed(std::to_string(triangleCount) + " triangles (all instances) are over the "
            + std::to_string(options.maxTriangles) + " Facet previews (docs/meshes.md, limits)");

    Mesh mesh;
    mesh.name = QFileInfo(QString::fromStdString(path)).completeBaseName().toStdString();
    mesh.vertices.reserve(vertexCount);
    mesh.indices.reserve(3 * triangleCount);
    std::vector<std::size_t> partsWithoutUvs;
    bool allTangents = true;
    for (std::size_t i = 0; i < instances.size(); ++i) {
        const PartInfo info = appendInstance(mesh, instances[i], i);
        if (!info.hasUvs)
            partsWithoutUvs.push_back(i);
        allTangents = allTangents && info.hasTangents;
    }

    if (normalsMissing)
        warnings.push_back("no normals in the file: smooth normals generated (hard edges over "
            + std::to_string(int(options.smoothingAngleDegrees)) + " degrees)");
    ImportedParts parts;
    parts.withoutUvs = std::move(partsWithoutUvs);
    parts.allHaveTangents = allTangents;
    std::string problem;
    if (!finishImportedMesh(mesh, parts, options.uvFallback, warnings, &problem))
        return failed(problem);
    return mesh;
}

} // namespace

std::optional<Mesh> importMesh(
    const std::string& path, std::string* error, std::string* warning, const MeshImportOptions& options)
{
    if (warning)
        warning->clear();
    const auto failed = [&](const std::string& problem) -> std::optional<Mesh> {
        if (error)
            *error = "importMesh: " + path + ": " + problem;
        return std::nullopt;
    };
    switch (const FileCheck check = checkRegularFile(path); check.kind) {
    case FileKind::Regular:
        break;
    case FileKind::Missing:
        return failed("file does not exist");
    case FileKind::Folder:
        return failed("is a directory, not a mesh file");
    default:
        return failed(check.problem);
    }
    const QFileInfo info(QString::fromStdString(path));
    if (!info.isReadable())
        return failed("cannot be read (permission denied)");
    if (info.size() == 0)
        return failed("file is empty");

    if (const std::string problem = plyHeaderProblem(info.filePath()); !problem.empty())
        return failed(problem);

    // glTF goes through Facet's own reader (core/gltf/GltfImport.h): materials, checked accessors, and
    // no recursion that a crafted node graph could overflow.
    if (isGltfFileName(path)) {
        GltfImportOptions gltfOptions;
        gltfOptions.mesh = options;
        gltfOptions.materialNotes = false; // the materials' import reports them (GltfImportOptions)
        std::string gltfError;
        auto asset = importGltf(path, &gltfError, warning, gltfOptions);
        // The messages keep importMesh's own prefix, the contract of this function.
        const auto renamed = [](std::string text) {
            const std::string from = "importGltf: ";
            return text.rfind(from, 0) == 0 ? "importMesh: " + text.substr(from.size()) : text;
        };
        if (warning && !warning->empty())
            *warning = renamed(*warning);
        if (!asset) {
            if (error)
                *error = renamed(gltfError);
            return std::nullopt;
        }
        return std::move(asset->mesh);
    }

    std::vector<std::string> warnings;
    std::optional<Mesh> mesh;
    // Assimp reports failures by a null scene, but a bad_alloc on a hostile size field or an
    // exception from a reader outside its guard must not cross the API either (docs/architecture.md, "Bad
    // input").
    try {
        mesh = importChecked(path, options, error, warnings);
    } catch (const std::exception& e) {
        return failed(std::string("Assimp failed: ") + e.what());
    } catch (...) {
        return failed("Assimp failed with an unknown exception");
    }
    if (mesh && warning && !warnings.empty())
        *warning = "importMesh: " + path + ": " + joined(warnings);
    return mesh;
}

std::string importableMeshPatterns()
{
    std::string patterns;
    Assimp::Importer().GetExtensionList(patterns);
    return patterns;
}

} // namespace facet
