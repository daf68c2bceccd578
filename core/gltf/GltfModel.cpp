// Reading a glTF asset into a tinygltf::Model with Facet's own file callbacks, and its accessors,
// checked (core/gltf/GltfModel.h).

#include "core/gltf/GltfModel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <exception>
#include <utility>

#include <QFile>
#include <QFileInfo>
#include <QUrl>

#include <nlohmann/json.hpp>

#include "core/json/JsonStructure.h"
#include "core/support/Failure.h"

namespace facet::gltfmodel {

namespace {

// ---- Reading the file ---------------------------------------------------------------------

// tinygltf's file callbacks, replaced so that a buffer or image URI can never make Facet read a
// device, a FIFO or an enormous file (issue 12: /dev/zero and FIFOs given as inputs hang), and
// so that `~` or `$VAR` in a URI is not expanded.
struct FileAccess {
    std::size_t maxBytes = 0;
};

// Any existing entry "exists", so that readWholeFile() can say what is wrong with it.
bool fileExists(const std::string& path, void*)
{
    return QFileInfo::exists(QString::fromStdString(path));
}

std::string expandFilePath(const std::string& path, void*)
{
    return path;
}

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* userData)
{
    const auto* access = static_cast<const FileAccess*>(userData);
    const QFileInfo info(QString::fromStdString(path));
    if (!info.exists()) {
        *err = "no such file";
        return false;
    }
    if (!info.isFile()) {
        *err = "not a regular file";
        return false;
    }
    if (std::size_t(info.size()) > access->maxBytes) {
        *err = "larger than " + std::to_string(access->maxBytes >> 20) + " MiB";
        return false;
    }
    QFile file(info.filePath());
    if (!file.open(QIODevice::ReadOnly)) {
        *err = file.errorString().toStdString();
        return false;
    }
    // Exactly the size the file has (a regular file's size is known): QIODevice::read(n) reserves
    // n bytes up front, so asking for the limit would allocate it for every small file.
    const qint64 size = file.size();
    out->resize(std::size_t(size));
    const qint64 got = size > 0 ? file.read(reinterpret_cast<char*>(out->data()), size) : 0;
    if (got != size || file.error() != QFileDevice::NoError) {
        *err = file.error() != QFileDevice::NoError ? file.errorString().toStdString()
                                                    : "the file changed while reading";
        return false;
    }
    return true;
}

bool writeWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&, void*)
{
    *err = "Facet does not write through the glTF reader";
    return false;
}

// Keeps the encoded bytes of data-URI images (tinygltf keeps no URI for them) and decodes
// nothing: embedded images are read on demand by readGltfImage().
bool keepEncodedImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
    const unsigned char* bytes, int size, void*)
{
    if (image->uri.empty() && image->bufferView < 0 && bytes && size > 0) {
        image->image.assign(bytes, bytes + size);
        image->as_is = true;
    }
    return true;
}

// tinygltf's messages are several lines; Facet's are one.
std::string oneLine(std::string text)
{
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
        text.pop_back();
    std::string result;
    for (char c : text)
        result += c == '\n' ? std::string("; ") : std::string(1, c);
    return result;
}

// tinygltf refuses a primitive whose "indices" accessor has no buffer view, which is how
// KHR_draco_mesh_compression stores them (the CC0 sample meshes do), and its own Draco support
// indexes buffer views without bounds checks. So Draco primitives lose their "indices" before
// tinygltf sees the JSON, and decodeDraco() reads the indices from the bitstream, checked.
// Returns the JSON unchanged when there is nothing to strip or it does not parse (tinygltf then
// reports the syntax error).
//
// The same pass checks what tinygltf reads without a word: a negative "byteOffset" (or length,
// stride, count) became 0 (issue 29), so the accessor read other bytes than the file says; *problem
// names the field ("accessors[2].byteOffset: -12 is negative").
std::string prepareJson(const std::string& text, std::string* problem)
{
    nlohmann::json json = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (json.is_discarded() || !json.is_object())
        return text;
    static const std::pair<const char*, std::array<const char*, 4>> kSizes[] = {
        {"accessors", {"byteOffset", "count", nullptr, nullptr}},
        {"bufferViews", {"byteOffset", "byteLength", "byteStride", nullptr}},
        {"buffers", {"byteLength", nullptr, nullptr, nullptr}},
    };
    for (const auto& [array, keys] : kSizes) {
        if (!json.contains(array) || !json[array].is_array())
            continue;
        for (std::size_t i = 0; i < json[array].size(); ++i) {
            const nlohmann::json& item = json[array][i];
            if (!item.is_object())
                continue;
            for (const char* key : keys)
                if (key && item.contains(key) && item[key].is_number() && item[key].get<double>() < 0) {
                    fail(std::string(array) + "[" + std::to_string(i) + "]." + key + ": " + item[key].dump()
                            + " is negative",
                        problem);
                    return text;
                }
        }
    }
    if (!json.contains("meshes") || !json["meshes"].is_array())
        return text;
    bool changed = false;
    for (auto& mesh : json["meshes"]) {
        if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array())
            continue;
        for (auto& primitive : mesh["primitives"]) {
            if (primitive.is_object() && primitive.contains("extensions")
                && primitive["extensions"].is_object()
                && primitive["extensions"].contains("KHR_draco_mesh_compression")
                && primitive.contains("indices")) {
                primitive.erase("indices");
                changed = true;
            }
        }
    }
    return changed ? json.dump() : text;
}

// Nesting is bounded before nlohmann-json or tinygltf see the text (both recurse: 20 000 levels
// overflowed the stack); duplicate keys are left to JSON's "SHOULD" (core/json/JsonStructure.h).
constexpr JsonStructureRules kGltfJsonRules {kMaxJsonDepth, /*refuseDuplicateKeys=*/false};

std::uint32_t readUint32(const std::vector<unsigned char>& bytes, std::size_t at)
{
    std::uint32_t value = 0;
    std::memcpy(&value, bytes.data() + at, 4);
    return value; // glTF binary is little-endian, as every machine Facet builds for
}

} // namespace

bool loadModel(const std::string& path, std::size_t maxBytes, tinygltf::Model& model, std::string* problem,
    std::string* warning, std::string* sourceJson)
{
    const QFileInfo info(QString::fromStdString(path));
    if (path.empty())
        return fail("no file name given", problem);
    if (!info.exists())
        return fail("file does not exist", problem);
    if (info.isDir())
        return fail("is a directory, not a glTF file", problem);
    if (!info.isFile())
        return fail("is not a regular file", problem);
    if (info.size() == 0)
        return fail("file is empty", problem);
    FileAccess access {maxBytes};
    std::vector<unsigned char> bytes;
    std::string readError;
    if (!readWholeFile(&bytes, &readError, path, &access))
        return fail("cannot read it: " + readError, problem);

    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({&fileExists, &expandFilePath, &readWholeFile, &writeWholeFile, &access});
    loader.SetImageLoader(&keepEncodedImage, nullptr);
    const std::string baseDir = info.absolutePath().toStdString();
    std::string err;
    std::string warn;
    bool ok = false;
    try {
        const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
        if (binary) {
            if (bytes.size() < 12)
                return fail(
                    "cut short: a .glb header is 12 bytes, the file has " + std::to_string(bytes.size()),
                    problem);
            if (readUint32(bytes, 8) > bytes.size())
                return fail("cut short: its header says " + std::to_string(readUint32(bytes, 8))
                        + " bytes, the file has " + std::to_string(bytes.size()),
                    problem);
            // Header (magic, version, length) and the JSON chunk's header: rewrite the JSON
            // chunk when Draco primitives need it, keep everything after it as it is.
            if (bytes.size() >= 20 && readUint32(bytes, 16) == 0x4E4F534A /* "JSON" */) {
                const std::size_t jsonLength = readUint32(bytes, 12);
                if (20 + std::uint64_t(jsonLength) <= bytes.size()) {
                    const std::string json(
                        bytes.begin() + 20, bytes.begin() + std::ptrdiff_t(20 + jsonLength));
                    if (const std::optional<std::string> shape = jsonStructureProblem(json, kGltfJsonRules))
                        return fail("its JSON chunk, " + *shape, problem);
                    if (sourceJson)
                        *sourceJson = json;
                    std::string field;
                    std::string rewritten = prepareJson(json, &field);
                    if (!field.empty())
                        return fail(field, problem);
                    if (rewritten != json) {
                        while (rewritten.size() % 4 != 0)
                            rewritten += ' ';
                        std::vector<unsigned char> glb(bytes.begin(), bytes.begin() + 12);
                        const auto appendUint32 = [&glb](std::uint32_t v) {
                            const auto* p = reinterpret_cast<const unsigned char*>(&v);
                            glb.insert(glb.end(), p, p + 4);
                        };
                        appendUint32(std::uint32_t(rewritten.size()));
                        appendUint32(0x4E4F534A);
                        glb.insert(glb.end(), rewritten.begin(), rewritten.end());
                        glb.insert(glb.end(), bytes.begin() + std::ptrdiff_t(20 + jsonLength), bytes.end());
                        const std::uint32_t total = std::uint32_t(glb.size());
                        std::memcpy(glb.data() + 8, &total, 4);
                        bytes = std::move(glb);
                    }
                }
            }
            ok = loader.LoadBinaryFromMemory(
                &model, &err, &warn, bytes.data(), unsigned(bytes.size()), baseDir);
        } else {
            const std::string_view json(reinterpret_cast<const char*>(bytes.data()), bytes.size());
            if (const std::optional<std::string> shape = jsonStructureProblem(json, kGltfJsonRules))
                return fail(*shape, problem);
            if (sourceJson)
                sourceJson->assign(json);
            std::string field;
            const std::string text = prepareJson(std::string(bytes.begin(), bytes.end()), &field);
            if (!field.empty())
                return fail(field, problem);
            ok = loader.LoadASCIIFromString(&model, &err, &warn, text.data(), unsigned(text.size()), baseDir);
        }
    } catch (const std::exception& e) {
        return fail(std::string("the glTF reader failed: ") + e.what(), problem);
    } catch (...) {
        return fail("the glTF reader failed with an unknown exception", problem);
    }
    if (!ok)
        return fail("not a readable glTF file: " + oneLine(err.empty() ? std::string("unknown error") : err),
            problem);
    if (warning)
        *warning = oneLine(warn);
    return true;
}

// ---- Accessors ----------------------------------------------------------------------------

namespace {

int componentSize(int componentType)
{
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return 4;
    default:
        return 0;
    }
}

const char* componentTypeName(int componentType)
{
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
        return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT:
        return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return "FLOAT";
    default:
        return "an unknown type";
    }
}

int componentCount(int type)
{
    switch (type) {
    case TINYGLTF_TYPE_SCALAR:
        return 1;
    case TINYGLTF_TYPE_VEC2:
        return 2;
    case TINYGLTF_TYPE_VEC3:
        return 3;
    case TINYGLTF_TYPE_VEC4:
        return 4;
    default:
        return 0;
    }
}

} // namespace

std::optional<AccessorView> accessorView(const tinygltf::Model& model, int index, int expectedComponents,
    const std::string& what, std::string* problem)
{
    const auto failed = [&](const std::string& text) -> std::optional<AccessorView> {
        fail(what + " (accessor " + std::to_string(index) + "): " + text, problem);
        return std::nullopt;
    };
    if (index < 0 || std::size_t(index) >= model.accessors.size())
        return failed("no such accessor (the file has " + std::to_string(model.accessors.size()) + ")");
    const tinygltf::Accessor& accessor = model.accessors[std::size_t(index)];
    const int size = componentSize(accessor.componentType);
    const int components = componentCount(accessor.type);
    if (size == 0)
        return failed("unknown component type " + std::to_string(accessor.componentType));
    if (components != expectedComponents)
        return failed("expected " + std::to_string(expectedComponents) + " components per element, got "
            + std::to_string(components));
    if (accessor.sparse.isSparse)
        return failed("sparse accessors are not supported");
    if (accessor.count == 0)
        return failed("it has no elements");
    if (accessor.bufferView < 0 || std::size_t(accessor.bufferView) >= model.bufferViews.size())
        return failed("no buffer view (data compressed by an extension, or a broken reference)");
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(accessor.bufferView)];
    if (view.buffer < 0 || std::size_t(view.buffer) >= model.buffers.size())
        return failed("buffer view " + std::to_string(accessor.bufferView) + " names no buffer");
    const tinygltf::Buffer& buffer = model.buffers[std::size_t(view.buffer)];
    const std::uint64_t elementSize = std::uint64_t(size) * std::uint64_t(components);
    const std::uint64_t stride = view.byteStride == 0 ? elementSize : std::uint64_t(view.byteStride);
    if (stride < elementSize || stride % std::uint64_t(size) != 0)
        return failed("byte stride " + std::to_string(view.byteStride) + " does not fit its elements");
    const std::uint64_t viewEnd = std::uint64_t(view.byteOffset) + std::uint64_t(view.byteLength);
    if (viewEnd > buffer.data.size())
        return failed("buffer view " + std::to_string(accessor.bufferView)
            + " reaches past the end of its buffer (" + std::to_string(viewEnd) + " > "
            + std::to_string(buffer.data.size()) + " bytes)");
    if (accessor.count > (std::uint64_t(1) << 32))
        return failed(std::to_string(accessor.count) + " elements is more than a mesh can hold");
    const std::uint64_t last
        = std::uint64_t(accessor.byteOffset) + stride * (std::uint64_t(accessor.count) - 1) + elementSize;
    if (last > std::uint64_t(view.byteLength))
        return failed(std::to_string(accessor.count) + " elements reach past the end of buffer view "
            + std::to_string(accessor.bufferView) + " (" + std::to_string(last) + " > "
            + std::to_string(view.byteLength) + " bytes)");
    if ((std::uint64_t(view.byteOffset) + std::uint64_t(accessor.byteOffset)) % std::uint64_t(size) != 0)
        return failed("its data is not aligned to its component size");
    AccessorView result;
    result.data = buffer.data.data() + view.byteOffset + accessor.byteOffset;
    result.count = accessor.count;
    result.stride = std::size_t(stride);
    result.componentType = accessor.componentType;
    result.components = components;
    result.normalized = accessor.normalized;
    return result;
}

float component(const AccessorView& view, std::size_t i, int c)
{
    const unsigned char* p
        = view.data + i * view.stride + std::size_t(c) * std::size_t(componentSize(view.componentType));
    switch (view.componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float value;
        std::memcpy(&value, p, 4);
        return value;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return view.normalized ? float(*p) / 255.0f : float(*p);
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const auto value = static_cast<std::int8_t>(*p);
        return view.normalized ? std::max(float(value) / 127.0f, -1.0f) : float(value);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t value;
        std::memcpy(&value, p, 2);
        return view.normalized ? float(value) / 65535.0f : float(value);
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t value;
        std::memcpy(&value, p, 2);
        return view.normalized ? std::max(float(value) / 32767.0f, -1.0f) : float(value);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        std::uint32_t value;
        std::memcpy(&value, p, 4);
        return float(value);
    }
    default:
        return 0.0f;
    }
}

std::uint32_t indexAt(const AccessorView& view, std::size_t i)
{
    const unsigned char* p = view.data + i * view.stride;
    switch (view.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return *p;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t value;
        std::memcpy(&value, p, 2);
        return value;
    }
    default: {
        std::uint32_t value;
        std::memcpy(&value, p, 4);
        return value;
    }
    }
}

std::string attributeTypeProblem(
    const std::string& name, const AccessorView& view, bool quantized, const std::string& where)
{
    const int type = view.componentType;
    const bool isFloat = type == TINYGLTF_COMPONENT_TYPE_FLOAT;
    const bool small = type == TINYGLTF_COMPONENT_TYPE_BYTE || type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE
        || type == TINYGLTF_COMPONENT_TYPE_SHORT || type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    const bool unsignedNormalized = view.normalized
        && (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    const bool signedNormalized
        = view.normalized && (type == TINYGLTF_COMPONENT_TYPE_BYTE || type == TINYGLTF_COMPONENT_TYPE_SHORT);
    bool core = isFloat;
    bool withQuantization = isFloat;
    if (name == "POSITION") {
        withQuantization = isFloat || small;
    } else if (name == "NORMAL" || name == "TANGENT") {
        withQuantization = isFloat || signedNormalized;
    } else { // TEXCOORD_n, COLOR_n
        core = isFloat || unsignedNormalized;
        withQuantization = isFloat || small;
        if (name.starts_with("COLOR_"))
            withQuantization = core;
    }
    if (core || (quantized && withQuantization))
        return {};
    const std::string given = std::string(view.normalized ? "normalized " : "") + componentTypeName(type);
    const bool geometry = name == "POSITION" || name == "NORMAL" || name == "TANGENT";
    if (!quantized && withQuantization)
        return where + " " + name + ": " + given
            + " components need the KHR_mesh_quantization extension, which the asset does not use (glTF 2.0 "
              "alone allows "
            + (geometry ? "FLOAT" : "FLOAT or normalized UNSIGNED_BYTE or UNSIGNED_SHORT") + " here)";
    return where + " " + name + ": " + given + " components are not allowed for this attribute";
}

std::optional<MorphDisplacement> morphDisplacement(const tinygltf::Model& model,
    const std::vector<double>& weights, const tinygltf::Primitive& primitive, std::size_t vertexCount,
    const std::string& where, std::string* problem)
{
    MorphDisplacement out;
    const std::size_t targets = std::min(weights.size(), primitive.targets.size());
    for (std::size_t k = 0; k < targets; ++k) {
        const auto w = float(weights[k]);
        if (w == 0.0f || !std::isfinite(w))
            continue;
        for (const auto& [name, accessor] : primitive.targets[k]) {
            std::vector<glm::vec3>* sum = name == "POSITION" ? &out.position
                : name == "NORMAL"                           ? &out.normal
                : name == "TANGENT"                          ? &out.tangent
                                                             : nullptr;
            if (!sum)
                continue; // TEXCOORD_n, COLOR_n displacements: not read (docs/gltf.md)
            const std::string what = where + " morph target " + std::to_string(k) + " " + name;
            const std::optional<AccessorView> view = accessorView(model, accessor, 3, what, problem);
            if (!view)
                return std::nullopt;
            if (view->count != vertexCount) {
                fail(what + ": " + std::to_string(view->count) + " elements, but POSITION has "
                        + std::to_string(vertexCount),
                    problem);
                return std::nullopt;
            }
            if (sum->empty())
                sum->assign(vertexCount, glm::vec3(0.0f));
            for (std::size_t i = 0; i < vertexCount; ++i)
                (*sum)[i]
                    += w * glm::vec3(component(*view, i, 0), component(*view, i, 1), component(*view, i, 2));
        }
    }
    return out;
}

} // namespace facet::gltfmodel
