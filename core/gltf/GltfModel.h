#pragma once
// Reading a glTF asset safely, the step core/gltf/GltfImport's mesh import and readGltfImage share:
// the file into a tinygltf::Model with Facet's file callbacks (no device, FIFO or file over the
// size limit is ever read through a buffer or image URI; `~` and `$VAR` in URIs are not
// expanded; Draco primitives' "indices" are left to the Draco decoder), then its accessors as
// views whose every byte is checked to lie inside its buffer, their component types checked
// against what glTF allows per attribute, and morph targets blended at given weights. Internal
// to core/.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/gltf/TinyGltf.h"

namespace facet::gltfmodel {

// Parses the asset at `path` (a .gltf or .glb of at most maxBytes, its buffers and images each
// as large at most). False with *problem (no prefix); *warning: tinygltf's warnings on one line;
// *json (optional): the file's JSON as written (a .glb's JSON chunk), checked for depth.
bool loadModel(const std::string& path, std::size_t maxBytes, tinygltf::Model& model, std::string* problem,
    std::string* warning, std::string* json = nullptr);

// A checked view of an accessor's elements: every byte it addresses lies inside its buffer.
struct AccessorView {
    const unsigned char* data = nullptr;
    std::size_t count = 0;
    std::size_t stride = 0;
    int componentType = 0;
    int components = 0;
    bool normalized = false;
};

// The checked view of accessor `index`, whose elements must have `expectedComponents`
// components; nullopt with *problem ("<what> (accessor N): why") when the accessor is missing,
// of another shape or addresses bytes outside its buffer.
std::optional<AccessorView> accessorView(const tinygltf::Model& model, int index, int expectedComponents,
    const std::string& what, std::string* problem);

// Component `c` of element `i` as a float (glTF 2.0 section 3.11: normalised integers map to
// [0, 1] or [-1, 1]).
float component(const AccessorView& view, std::size_t i, int c);

// Element `i` of an index accessor (unsigned byte, short or int).
std::uint32_t indexAt(const AccessorView& view, std::size_t i);

// The component types glTF 2.0 allows for a vertex attribute (section 3.7.2.1), and those
// KHR_mesh_quantization adds when the asset uses it. Anything else was read as numbers of another
// meaning: POSITION as UNSIGNED_BYTE without the extension drew garbage (issue 29); the sample
// renderer refuses such a primitive too. "" when allowed.
std::string attributeTypeProblem(
    const std::string& name, const AccessorView& view, bool quantized, const std::string& where);

// A primitive's morph targets blended at the weights the asset gives when nothing animates them
// (glTF 2.0 section 3.7.2.2; the caller passes the node's "weights", else the mesh's): the sum over targets
// of weight x displacement, per vertex, for POSITION, NORMAL and TANGENT (xyz). Empty vectors where no target
// with a non-zero weight displaces that attribute. Issue 29: the weights were not applied, so a mesh whose
// rest shape is a blend (AnimatedMorphCube) showed its base shape.
struct MorphDisplacement {
    std::vector<glm::vec3> position, normal, tangent;
};

std::optional<MorphDisplacement> morphDisplacement(const tinygltf::Model& model,
    const std::vector<double>& weights, const tinygltf::Primitive& primitive, std::size_t vertexCount,
    const std::string& where, std::string* problem);

} // namespace facet::gltfmodel
