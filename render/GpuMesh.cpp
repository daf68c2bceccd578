#include <epoxy/gl.h>

#include "render/GpuMesh.h"

#include <cstddef>
#include <utility>

namespace facet {

static_assert(sizeof(Vertex) == 14 * sizeof(float) + 4 * sizeof(std::uint16_t),
    "GpuMesh assumes core Vertex is 14 packed floats and 4 16-bit colour channels");

GpuMesh::GpuMesh(GpuMesh&& other) noexcept
    : m_vao(std::exchange(other.m_vao, 0u))
    , m_vertexBuffer(std::exchange(other.m_vertexBuffer, 0u))
    , m_indexBuffer(std::exchange(other.m_indexBuffer, 0u))
    , m_indexCount(std::exchange(other.m_indexCount, 0u))
    , m_key(other.m_key)
    , m_hasKey(std::exchange(other.m_hasKey, false))
{
}

GpuMesh& GpuMesh::operator=(GpuMesh&& other) noexcept
{
    if (this != &other) {
        destroy();
        m_vao = std::exchange(other.m_vao, 0u);
        m_vertexBuffer = std::exchange(other.m_vertexBuffer, 0u);
        m_indexBuffer = std::exchange(other.m_indexBuffer, 0u);
        m_indexCount = std::exchange(other.m_indexCount, 0u);
        m_key = other.m_key;
        m_hasKey = std::exchange(other.m_hasKey, false);
    }
    return *this;
}

GpuMesh::~GpuMesh() { destroy(); }

void GpuMesh::destroy()
{
    if (m_vao)
        glDeleteVertexArrays(1, &m_vao);
    if (m_vertexBuffer)
        glDeleteBuffers(1, &m_vertexBuffer);
    if (m_indexBuffer)
        glDeleteBuffers(1, &m_indexBuffer);
    m_vao = m_vertexBuffer = m_indexBuffer = 0;
    m_indexCount = 0;
    m_hasKey = false;
}

bool GpuMesh::update(const Mesh& mesh, std::uint64_t key)
{
    if (m_hasKey && m_key == key)
        return false;
    if (!m_vao) {
        glGenVertexArrays(1, &m_vao);
        glGenBuffers(1, &m_vertexBuffer);
        glGenBuffers(1, &m_indexBuffer);
    }
    glBindVertexArray(m_vao);
    glBindBuffer(GL_ARRAY_BUFFER, m_vertexBuffer);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.vertices.size() * sizeof(Vertex)), mesh.vertices.data(),
                 GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_indexBuffer);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(std::uint32_t)), mesh.indices.data(),
                 GL_STATIC_DRAW);
    const auto stride = GLsizei(sizeof(Vertex));
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(Vertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(Vertex, normal)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(Vertex, tangent)));
    glEnableVertexAttribArray(3);
    glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(Vertex, uv)));
    // TEXCOORD_1 (only variants with HAS_TEXCOORD_1 read it).
    glEnableVertexAttribArray(5);
    glVertexAttribPointer(
        5, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(Vertex, uv1)));
    // COLOR_0 in 16-bit fixed point, read as [0, 1] (only variants with HAS_VERTEX_COLOR use it).
    glEnableVertexAttribArray(4);
    glVertexAttribPointer(
        4, 4, GL_UNSIGNED_SHORT, GL_TRUE, stride, reinterpret_cast<const void*>(offsetof(Vertex, color)));
    glBindVertexArray(0);
    m_indexCount = std::uint32_t(mesh.indices.size());
    m_key = key;
    m_hasKey = true;
    return true;
}

int GpuMesh::draw(const Mesh& mesh) const
{
    if (!m_vao || m_indexCount == 0)
        return 0;
    glBindVertexArray(m_vao);
    int calls = 0;
    if (mesh.subMeshes.empty()) {
        glDrawElements(GL_TRIANGLES, GLsizei(m_indexCount), GL_UNSIGNED_INT, nullptr);
        ++calls;
    } else {
        for (const SubMesh& sub : mesh.subMeshes) {
            if (!sub.visible || sub.indexCount == 0 || sub.firstIndex + sub.indexCount > m_indexCount)
                continue;
            glDrawElements(GL_TRIANGLES, GLsizei(sub.indexCount), GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(std::size_t(sub.firstIndex) * sizeof(std::uint32_t)));
            ++calls;
        }
    }
    glBindVertexArray(0);
    return calls;
}

int GpuMesh::drawRange(std::uint32_t firstIndex, std::uint32_t indexCount) const
{
    if (!m_vao || indexCount == 0 || std::uint64_t(firstIndex) + indexCount > m_indexCount)
        return 0;
    glBindVertexArray(m_vao);
    glDrawElements(GL_TRIANGLES, GLsizei(indexCount), GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(std::size_t(firstIndex) * sizeof(std::uint32_t)));
    glBindVertexArray(0);
    return 1;
}

} // namespace facet
