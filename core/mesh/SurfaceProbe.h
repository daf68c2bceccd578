#pragma once
// What the surface holds at a point the picker hit (ui/viewport/ValuePicker, the window's value picker):
// the interpolated vertex attributes, and for each map the material reads there, the texel the
// point falls in, its stored and decoded values and the filtered read the shader makes, and the
// material's inputs that follow (core/shading/MaterialInputs, the CPU twin of the shader's reads).
//
// Inputs: a hit of core/mesh/MeshPicking (its triangle and barycentric coordinates) on the mesh, the
// material of the hit part and that material's map images (with their pixels: a caller whose
// images were released after upload decodes them again, core/image/MapImageCache). Mipmapping is not
// modelled (as in MaterialInputs): the values are level 0's, what a close-up shows.

#include "core/shading/MaterialInputs.h"

#include <cstddef>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace facet {

class Mesh;
struct MeshHit;

// One map's reading at the point.
struct MapProbe {
    MapSlot slot = MapSlot::BaseColor;
    glm::dvec2 uv {0.0}; // the map's own coordinates: its set (texCoord), its UV transform applied
    // The texel the point falls in, wrapped as the map's sampler wraps: x from the left, y from
    // the TOP row (as an image editor counts; core/image/MapImage stores rows bottom up).
    glm::ivec2 texel {0};
    glm::ivec2 size {0}; // the map's width and height
    MapSampleType sampleType = MapSampleType::UInt8; // how the file stores a sample
    glm::dvec4 stored {0.0}; // that texel as the file stores it, normalised to [0, 1] (MapImage::texel)
    glm::dvec4 linear {0.0}; // that texel as the texture holds it (sRGB decoded for a colour map)
    glm::dvec4 filtered {0.0}; // the read the shader makes (sampleMap: bilinear, decoded)
};

struct SurfaceProbe {
    std::size_t subMesh = 0;
    std::size_t triangle = 0;
    glm::dvec3 position {0.0}; // world space
    glm::dvec3 geometricNormal {0.0, 1.0, 0.0}; // interpolated vertex normal, world space, unit
    glm::dvec3 shadingNormal {0.0, 1.0, 0.0}; // with the normal map applied, world space, unit
    TexCoords uvs {}; // TEXCOORD_0 and _1 before any map's transform
    glm::dvec4 vertexColor {1.0};
    std::vector<MapProbe> maps; // the slots with a texture and an image with pixels, in MapSlot order
    MaterialInfo inputs; // materialInputs() at the point
};

// The probe of `hit` on `mesh` drawn with `model` (as pickMesh was given), read with `material`
// and its `images` (null or pixel-less entries: the slot's factor alone, as the renderer draws a
// map it has no texture for). `hit` must come from pickMesh on the same mesh.
SurfaceProbe probeSurface(const Mesh& mesh, const glm::dmat4& model, const MeshHit& hit,
    const Material& material, const MaterialMapImages& images);

} // namespace facet
