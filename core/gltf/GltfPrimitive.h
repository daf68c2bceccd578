#pragma once
// Private to core/gltf: a primitive's vertex data as the glTF reader gathers it, read in place from
// checked accessors (core/gltf/GltfImport.cpp) or decoded from a Draco bitstream
// (core/gltf/GltfDraco.cpp).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/gltf/GltfImport.h"
#include "core/gltf/GltfModel.h"
#include "core/gltf/TinyGltf.h"

namespace facet::gltfprimitive {

// One vertex attribute of a primitive: read in place from a checked accessor, or decoded (Draco).
struct Attribute {
    std::optional<gltfmodel::AccessorView> view;
    std::vector<float> decoded; // count x components
    int components = 0;
    bool present() const { return view.has_value() || !decoded.empty(); }
    float at(std::size_t i, int c) const
    {
        return view ? gltfmodel::component(*view, i, c)
                    : decoded[i * std::size_t(components) + std::size_t(c)];
    }
};

// A primitive's vertex attributes and its index list (0, 1, 2, ... when it has no indices).
struct PrimitiveData {
    std::size_t vertexCount = 0;
    Attribute position, normal, tangent, uv, uv1, color; // uv1: TEXCOORD_1; color: COLOR_0, VEC3 or VEC4
    std::vector<std::uint32_t> indices;
};

// KHR_draco_mesh_compression: the primitive's geometry is one Draco bitstream in a buffer view,
// decoded with Debian's libdraco. Every reference the extension makes (buffer view, attribute ids,
// component counts) is checked before use; nullopt with *problem naming `where` otherwise.
std::optional<PrimitiveData> decodeDraco(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
    const tinygltf::Value& extension, const std::string& where, const GltfImportOptions& options,
    std::string* problem);

} // namespace facet::gltfprimitive
