#pragma once
// Private to core/gltf/GltfImport*.cpp: what the geometry reader and the material conversion share.

#include <string>
#include <vector>

#include "core/gltf/TinyGltf.h"
#include "core/material/Material.h"
#include "core/support/Failure.h"

namespace facet::gltfsupport {

using facet::fail;

// What was repaired or ignored, for the import's one warning line. A note repeated for many
// materials or textures is kept once with a count.
class Notes {
public:
    void add(const std::string& note);
    bool empty() const { return m_notes.empty(); }
    std::string joined() const; // "a; b (3 times); c"

private:
    std::vector<std::pair<std::string, int>> m_notes;
};

// Material `index` of the model as a Facet material: glTF's metallic-roughness model maps onto
// Facet's one to one (core/material/Material.h); out-of-range factors are clamped with a note, textures
// become map paths (an external file resolved against the asset's folder, or an embedded-image
// reference, core/gltf/GltfImport.h), each with its KHR_texture_transform in Facet's UV space.
Material convertMaterial(const tinygltf::Model& model, int index, const std::string& assetPath, Notes& notes);

// glTF 2.0's default material (section 3.9.6 "Default Material"): base colour 1, metallic 1,
// roughness 1, single-sided, named "Default".
Material defaultGltfMaterial();

} // namespace facet::gltfsupport
