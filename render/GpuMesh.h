#pragma once
// A core Mesh in GL buffers: one VAO, an interleaved vertex buffer in core/mesh/Mesh.h's Vertex layout
// (location 0 position, 1 normal, 2 tangent, 3 uv) and a 32-bit index buffer. Move-only; destroy
// with the context current.

#include <cstdint>

#include "core/mesh/Mesh.h"

namespace facet {

class GpuMesh {
public:
    GpuMesh() = default;
    GpuMesh(GpuMesh&& other) noexcept;
    GpuMesh& operator=(GpuMesh&& other) noexcept;
    GpuMesh(const GpuMesh&) = delete;
    GpuMesh& operator=(const GpuMesh&) = delete;
    ~GpuMesh();

    // Uploads `mesh` unless `key` is the one already uploaded. True when it uploaded.
    bool update(const Mesh& mesh, std::uint64_t key);
    bool isEmpty() const { return m_indexCount == 0; }
    std::uint64_t key() const { return m_key; }
    // Draws every visible sub-mesh (or all indices when there are none); returns draw calls made.
    int draw(const Mesh& mesh) const;
    // Draws `indexCount` indices from `firstIndex` (a sub-mesh's range); 0 when the range is not
    // inside the uploaded index buffer, else 1 (draw calls made).
    int drawRange(std::uint32_t firstIndex, std::uint32_t indexCount) const;

private:
    void destroy();
    unsigned m_vao = 0;
    unsigned m_vertexBuffer = 0;
    unsigned m_indexBuffer = 0;
    std::uint32_t m_indexCount = 0;
    std::uint64_t m_key = 0;
    bool m_hasKey = false;
};

} // namespace facet
