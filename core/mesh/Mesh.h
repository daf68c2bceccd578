#pragma once
// A triangle mesh as plain values: what the viewer draws and the importer and the primitive
// builders produce. No GL here (docs/architecture.md): render/ uploads a Mesh, it never reads files.
//
// Conventions (docs/meshes.md):
// - World space as in docs/architecture.md: right-handed, +Y up. Triangles wind counter-clockwise seen from
//   outside (the OpenGL default front face), so a closed mesh has a positive signed volume.
// - UVs follow OpenGL: (0, 0) is the bottom-left of the image, v grows upward. (Assimp's glTF
//   importer already flips glTF's top-left origin; the OBJ format is bottom-left.)
// - Tangents follow glTF 2.0 (section 3.7.2.1, "Meshes"): tangent.xyz points along dP/du, and the
//   bitangent, which points along dP/dv, is cross(normal, tangent.xyz) * tangent.w with w = +-1.
//   Normal maps are OpenGL style (+Y green along the bitangent), as docs/architecture.md says.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/ext/vector_uint4_sized.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace facet {

struct Vertex {
    glm::vec3 position {0.0f};
    glm::vec3 normal {0.0f, 1.0f, 0.0f}; // unit length
    // xyz: unit, perpendicular to the normal, along dP/du; w = +1 or -1, the handedness
    // (glTF convention: bitangent = cross(normal, tangent.xyz) * w).
    glm::vec4 tangent {1.0f, 0.0f, 0.0f, 1.0f};
    glm::vec2 uv {0.0f};
    // The second texture-coordinate set (glTF TEXCOORD_1, a mesh's lightmap or occlusion UVs),
    // read by maps whose texCoord is 1; meaningful where Mesh::hasTexCoord1, else a copy of uv.
    glm::vec2 uv1 {0.0f};
    // Linear RGBA that multiplies the base colour and its alpha (glTF COLOR_0), in 16-bit fixed
    // point (value / 65535): white where the file has none. Eight bytes, not sixteen: at 50 M
    // vertices a float vec4 would cost another 400 MB for a rarely used attribute.
    glm::u16vec4 color {65535, 65535, 65535, 65535};

    bool operator==(const Vertex&) const = default;
};

// A Vertex::color as the linear RGBA it stands for, and back (clamped to [0, 1], rounded).
glm::vec4 vertexColor(const Vertex& vertex);
glm::u16vec4 packVertexColor(const glm::vec4& rgba);

// A range of the index buffer drawn with one material: one per aiMesh instance on import.
struct SubMesh {
    std::string name;
    uint32_t firstIndex = 0; // into Mesh::indices; a multiple of 3
    uint32_t indexCount = 0; // a multiple of 3
    int materialIndex = -1; // the file's material index; -1: none
    bool visible = true;

    bool operator==(const SubMesh&) const = default;
};

// Axis-aligned bounding box. Empty (min > max) until something is added.
struct Bounds {
    glm::vec3 min {1.0f};
    glm::vec3 max {-1.0f};

    bool isEmpty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    glm::vec3 center() const { return isEmpty() ? glm::vec3(0.0f) : 0.5f * (min + max); }
    glm::vec3 size() const { return isEmpty() ? glm::vec3(0.0f) : max - min; }
    void add(const glm::vec3& p);

    bool operator==(const Bounds&) const = default;
};

class Mesh {
public:
    std::string name;
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices; // triangles: 3 indices each, counter-clockwise from outside
    std::vector<SubMesh> subMeshes;
    Bounds bounds; // of every vertex; updateBounds() after editing positions

    bool hasUvs = false; // the UVs mean something (from the file, a primitive, or generated)
    bool uvsGenerated = false; // they were made by generateUvs() because the file had none
    bool hasTangents = false; // tangents are valid (from the file or generated from the UVs)
    bool hasTexCoord1 = false; // some vertex's uv1 is the file's (glTF TEXCOORD_1)
    bool hasVertexColors = false; // some vertex's color is the file's (glTF COLOR_0): the shader reads them
    // World units per unit of the source file (normalizeToUnitSphere's scale; 1 for a mesh in
    // its own units): what turns a length on screen back into the asset's metres (texel density).
    float scaleFromSource = 1.0f;

    std::size_t triangleCount() const { return indices.size() / 3; }

    // Recomputes `bounds` from every vertex position.
    void updateBounds();

    // The bounding sphere the viewer frames (docs/meshes.md): centred on the bounding box's
    // centre, with the radius of the farthest vertex from it. Not the minimal enclosing sphere
    // (Welzl), which can sit off the box centre and move as a mesh is edited; the box centre is
    // where an artist expects the pivot. Radius 0 for an empty mesh.
    glm::vec3 boundingSphereCenter() const { return bounds.center(); }
    float boundingSphereRadius() const;

    // Moves the bounding sphere's centre to the origin and scales uniformly so its radius is 1.
    // Returns the applied transform (world' = transform * world); identity for an empty mesh, a
    // translation only when every vertex sits at one point. Normals and tangents are unchanged
    // (uniform scale). Updates `bounds`.
    glm::mat4 normalizeToUnitSphere();

    // Applies an affine transform: positions by `matrix`, normals by its inverse transpose,
    // tangents by its upper 3x3 with the handedness recomputed, and the winding reversed when
    // the transform mirrors (negative determinant) so faces stay outward. Updates `bounds`.
    // False, mesh unchanged, when the matrix is singular or not finite.
    bool transform(const glm::mat4& matrix, std::string* problem = nullptr);

    // Checks the invariants render/ and the tests rely on: a whole number of triangles, every
    // index in range, finite positions and UVs, unit normals, unit tangents perpendicular to the
    // normals with w = +-1 (when hasTangents), sub-meshes inside the index buffer, bounds that
    // hold every vertex. On failure returns false and sets *problem to
    // "Mesh::validate: '<name>': <problem>".
    bool validate(std::string* problem = nullptr) const;

    bool operator==(const Mesh&) const = default;
};

} // namespace facet
