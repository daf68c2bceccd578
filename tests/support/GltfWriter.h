#pragma once
// Small glTF 2.0 files written by the tests themselves (tests/GltfImportTest.cpp, the glTF GL and
// UI tests): quads and spheres with known factors, packed textures with distinct channel values,
// emissive maps, texture transforms, several materials, and deliberately broken variants. The JSON
// is built with QJsonObject so a test can break any field; the binary data is one buffer, written
// as an external .bin, a data URI or the BIN chunk of a .glb.

#include <QByteArray>
#include <QJsonArray>
#include <QJsonObject>
#include <QString>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

namespace facet::test {

class GltfWriter {
public:
    enum class BufferStorage { ExternalFile, DataUri, Glb };

    // Appends raw bytes to the buffer (4-byte aligned), returns the buffer view's index.
    int addBufferView(const QByteArray& bytes, int target = 0);
    // An accessor over a new buffer view of floats (VEC2/VEC3/VEC4/SCALAR by `components`).
    int addFloatAccessor(const std::vector<float>& values, int components, bool withMinMax = false);
    int addIndexAccessor(const std::vector<std::uint32_t>& indices);
    // A primitive of positions/normals/uvs (glTF's UV convention: v = 0 is the image's TOP row)
    // and indices; material -1 leaves "material" out. Returns the mesh index.
    int addMesh(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                const std::vector<glm::vec2>& uvs, const std::vector<std::uint32_t>& indices, int material,
                const QString& name = {});
    // A unit quad in the XY plane facing +Z, UVs (0,0) top-left to (1,1) bottom-right.
    int addQuad(int material, float z = 0.0f, const QString& name = {});
    // A UV sphere of radius 1 (glTF UVs).
    int addSphere(int material, int segments = 48, int rings = 24);
    // Sets `key` of the first primitive of `mesh` to `value` ("attributes", "targets", ...), or,
    // with `attribute`, one entry of its "attributes" ("COLOR_0" -> an accessor index).
    void setPrimitive(int mesh, const QString& key, const QJsonValue& value);
    void setAttribute(int mesh, const QString& attribute, int accessor);
    // A node showing `mesh` (with an optional JSON transform), added to the scene's roots.
    int addNode(int mesh, const QJsonObject& transform = {});
    // An image: an external file name (relative to the asset), or bytes embedded in the buffer.
    int addImageUri(const QString& uri);
    int addImageEmbedded(const QByteArray& encoded, const QString& mimeType);
    int addTexture(int image, int sampler = -1);
    int addMaterial(const QJsonObject& material);

    QJsonObject& json() { return m_json; }
    QByteArray& buffer() { return m_buffer; }

    // Writes the asset. ExternalFile writes `<path without extension>.bin` next to it; Glb needs
    // a .glb path. False with a message on an I/O error.
    bool write(const QString& path, BufferStorage storage, QString* error = nullptr) const;

private:
    QJsonArray array(const char* key) const;
    void setArray(const char* key, const QJsonArray& value);
    int append(const char* key, const QJsonObject& value);

    QJsonObject m_json;
    QByteArray m_buffer;
};

// [v0, v1, ...] for a glTF JSON field.
QJsonArray jsonNumbers(std::initializer_list<double> values);
// A textureInfo object {"index": texture} with optional "extensions".
QJsonObject textureInfo(int texture, const QJsonObject& extensions = {});

// PNG bytes of a width x height image of 8-bit channels (1 to 4), each texel from `texel`.
QByteArray encodePng(int width, int height, int channels, const std::vector<glm::vec4>& texels);

} // namespace facet::test
