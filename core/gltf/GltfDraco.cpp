#include "core/gltf/GltfPrimitive.h"

#include <cstdint>
#include <memory>

#include <draco/compression/decode.h>

#include "core/gltf/GltfSupport.h"

namespace facet::gltfprimitive {

std::optional<PrimitiveData> decodeDraco(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
    const tinygltf::Value& extension, const std::string& where, const GltfImportOptions& options,
    std::string* problem)
{
    const auto failed = [&](const std::string& text) -> std::optional<PrimitiveData> {
        gltfsupport::fail(where + " (KHR_draco_mesh_compression): " + text, problem);
        return std::nullopt;
    };
    if (!extension.Has("bufferView") || !extension.Get("bufferView").IsInt() || !extension.Has("attributes")
        || !extension.Get("attributes").IsObject())
        return failed("needs a bufferView and an attributes object");
    const int viewIndex = extension.Get("bufferView").GetNumberAsInt();
    if (viewIndex < 0 || std::size_t(viewIndex) >= model.bufferViews.size())
        return failed("buffer view " + std::to_string(viewIndex) + " does not exist");
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(viewIndex)];
    if (view.buffer < 0 || std::size_t(view.buffer) >= model.buffers.size()
        || std::uint64_t(view.byteOffset) + std::uint64_t(view.byteLength)
            > model.buffers[std::size_t(view.buffer)].data.size())
        return failed("buffer view " + std::to_string(viewIndex) + " reaches past the end of its buffer");
    const unsigned char* bytes = model.buffers[std::size_t(view.buffer)].data.data() + view.byteOffset;

    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(bytes), view.byteLength);
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok())
        return failed("Draco cannot decode it: " + decoded.status().error_msg_string());
    const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
    if (!mesh)
        return failed("Draco decoded no mesh");
    PrimitiveData data;
    data.vertexCount = mesh->num_points();
    if (data.vertexCount == 0 || mesh->num_faces() == 0)
        return failed("the bitstream holds no triangles");
    if (data.vertexCount > options.mesh.maxVertices
        || std::size_t(mesh->num_faces()) > options.mesh.maxTriangles)
        return failed(std::to_string(data.vertexCount) + " vertices and " + std::to_string(mesh->num_faces())
            + " triangles are over the " + std::to_string(options.mesh.maxVertices) + " / "
            + std::to_string(options.mesh.maxTriangles) + " Facet previews (docs/meshes.md, limits)");

    const tinygltf::Value& ids = extension.Get("attributes");
    const auto read = [&](const char* name, int components, Attribute& out, bool required) {
        if (!ids.Has(name)) {
            if (required)
                return gltfsupport::fail(
                    where + " (KHR_draco_mesh_compression): no " + std::string(name), problem);
            return true;
        }
        if (!ids.Get(name).IsInt())
            return gltfsupport::fail(where + " (KHR_draco_mesh_compression): attribute id of "
                    + std::string(name) + " is not an integer",
                problem);
        const draco::PointAttribute* attribute
            = mesh->GetAttributeByUniqueId(std::uint32_t(ids.Get(name).GetNumberAsInt()));
        if (!attribute || attribute->num_components() != components)
            return gltfsupport::fail(where + " (KHR_draco_mesh_compression): " + std::string(name)
                    + " is missing from the bitstream or has the wrong number of components",
                problem);
        // The glTF accessor says whether integer data means [0, 1] (normalized).
        const auto it = primitive.attributes.find(name);
        const bool normalized = it != primitive.attributes.end() && it->second >= 0
            && std::size_t(it->second) < model.accessors.size()
            && model.accessors[std::size_t(it->second)].normalized;
        float scale = 1.0f;
        if (normalized && !attribute->normalized()) {
            switch (attribute->data_type()) {
            case draco::DT_UINT8:
                scale = 1.0f / 255.0f;
                break;
            case draco::DT_UINT16:
                scale = 1.0f / 65535.0f;
                break;
            case draco::DT_INT8:
                scale = 1.0f / 127.0f;
                break;
            case draco::DT_INT16:
                scale = 1.0f / 32767.0f;
                break;
            default:
                break;
            }
        }
        out.components = components;
        out.decoded.resize(data.vertexCount * std::size_t(components));
        float values[4] = {0, 0, 0, 0};
        for (draco::PointIndex i(0); i < mesh->num_points(); ++i) {
            if (!attribute->ConvertValue<float>(attribute->mapped_index(i), std::int8_t(components), values))
                return gltfsupport::fail(where + " (KHR_draco_mesh_compression): " + std::string(name)
                        + " cannot be read as numbers",
                    problem);
            for (int c = 0; c < components; ++c)
                out.decoded[std::size_t(i.value()) * std::size_t(components) + std::size_t(c)]
                    = values[c] * scale;
        }
        return true;
    };
    if (!read("POSITION", 3, data.position, true) || !read("NORMAL", 3, data.normal, false)
        || !read("TANGENT", 4, data.tangent, false) || !read("TEXCOORD_0", 2, data.uv, false)
        || !read("TEXCOORD_1", 2, data.uv1, false))
        return std::nullopt;
    data.indices.reserve(std::size_t(mesh->num_faces()) * 3);
    for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f)
        for (int k = 0; k < 3; ++k)
            data.indices.push_back(mesh->face(f)[k].value());
    return data;
}

} // namespace facet::gltfprimitive
