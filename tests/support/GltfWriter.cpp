#include "GltfWriter.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QTemporaryDir>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

namespace facet::test {

namespace {

QByteArray bytesOf(const void* data, std::size_t size)
{
    return QByteArray(static_cast<const char*>(data), qsizetype(size));
}

void appendUint32(QByteArray& out, std::uint32_t value)
{
    out.append(bytesOf(&value, 4)); // little-endian on every machine Facet builds for
}

} // namespace

QJsonArray GltfWriter::array(const char* key) const
{
    return m_json.value(QLatin1String(key)).toArray();
}

void GltfWriter::setArray(const char* key, const QJsonArray& value)
{
    m_json[QLatin1String(key)] = value;
}

int GltfWriter::append(const char* key, const QJsonObject& value)
{
    QJsonArray a = array(key);
    a.append(value);
    setArray(key, a);
    return int(a.size()) - 1;
}

int GltfWriter::addBufferView(const QByteArray& bytes, int target)
{
    while (m_buffer.size() % 4 != 0)
        m_buffer.append('\0');
    QJsonObject view;
    view[QLatin1String("buffer")] = 0;
    view[QLatin1String("byteOffset")] = int(m_buffer.size());
    view[QLatin1String("byteLength")] = int(bytes.size());
    if (target != 0)
        view[QLatin1String("target")] = target;
    m_buffer.append(bytes);
    return append("bufferViews", view);
}

int GltfWriter::addFloatAccessor(const std::vector<float>& values, int components, bool withMinMax)
{
    const int view = addBufferView(bytesOf(values.data(), values.size() * sizeof(float)), 34962);
    QJsonObject accessor;
    accessor[QLatin1String("bufferView")] = view;
    accessor[QLatin1String("componentType")] = 5126;
    accessor[QLatin1String("count")] = int(values.size()) / components;
    static const char* const kTypes[] = {"", "SCALAR", "VEC2", "VEC3", "VEC4"};
    accessor[QLatin1String("type")] = QLatin1String(kTypes[components]);
    if (withMinMax) {
        QJsonArray lo, hi;
        for (int c = 0; c < components; ++c) {
            float mn = INFINITY, mx = -INFINITY;
            for (std::size_t i = std::size_t(c); i < values.size(); i += std::size_t(components)) {
                mn = std::min(mn, values[i]);
                mx = std::max(mx, values[i]);
            }
            lo.append(mn);
            hi.append(mx);
        }
        accessor[QLatin1String("min")] = lo;
        accessor[QLatin1String("max")] = hi;
    }
    return append("accessors", accessor);
}

int GltfWriter::addIndexAccessor(const std::vector<std::uint32_t>& indices)
{
    const int view = addBufferView(bytesOf(indices.data(), indices.size() * 4), 34963);
    QJsonObject accessor;
    accessor[QLatin1String("bufferView")] = view;
    accessor[QLatin1String("componentType")] = 5125;
    accessor[QLatin1String("count")] = int(indices.size());
    accessor[QLatin1String("type")] = QLatin1String("SCALAR");
    return append("accessors", accessor);
}

int GltfWriter::addMesh(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                        const std::vector<glm::vec2>& uvs, const std::vector<std::uint32_t>& indices, int material,
                        const QString& name)
{
    const auto flat = [](const auto& vectors, int n) {
        std::vector<float> out;
        for (const auto& v : vectors)
            for (int c = 0; c < n; ++c)
                out.push_back(v[c]);
        return out;
    };
    QJsonObject attributes;
    attributes[QLatin1String("POSITION")] = addFloatAccessor(flat(positions, 3), 3, true);
    if (!normals.empty())
        attributes[QLatin1String("NORMAL")] = addFloatAccessor(flat(normals, 3), 3);
    if (!uvs.empty())
        attributes[QLatin1String("TEXCOORD_0")] = addFloatAccessor(flat(uvs, 2), 2);
    QJsonObject primitive;
    primitive[QLatin1String("attributes")] = attributes;
    primitive[QLatin1String("indices")] = addIndexAccessor(indices);
    if (material >= 0)
        primitive[QLatin1String("material")] = material;
    QJsonObject mesh;
    mesh[QLatin1String("primitives")] = QJsonArray {primitive};
    if (!name.isEmpty())
        mesh[QLatin1String("name")] = name;
    return append("meshes", mesh);
}

int GltfWriter::addQuad(int material, float z, const QString& name)
{
    return addMesh({{-1, -1, z}, {1, -1, z}, {1, 1, z}, {-1, 1, z}}, {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}},
                   {{0, 1}, {1, 1}, {1, 0}, {0, 0}}, {0, 1, 2, 0, 2, 3}, material, name);
}

int GltfWriter::addSphere(int material, int segments, int rings)
{
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> indices;
    for (int r = 0; r <= rings; ++r) {
        const double theta = std::numbers::pi * double(r) / rings; // from +Y down
        for (int s = 0; s <= segments; ++s) {
            const double phi = 2.0 * std::numbers::pi * double(s) / segments;
            const glm::vec3 p(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                              float(-std::sin(theta) * std::sin(phi)));
            positions.push_back(p);
            normals.push_back(p);
            uvs.emplace_back(float(s) / segments, float(r) / rings); // v = 0 at the top (glTF)
        }
    }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const auto a = std::uint32_t(r * (segments + 1) + s);
            const auto b = a + std::uint32_t(segments + 1);
            indices.insert(indices.end(), {a, b, a + 1, a + 1, b, b + 1});
        }
    return addMesh(positions, normals, uvs, indices, material, QStringLiteral("sphere"));
}

void GltfWriter::setPrimitive(int mesh, const QString& key, const QJsonValue& value)
{
    QJsonArray meshes = m_json[QLatin1String("meshes")].toArray();
    QJsonObject m = meshes[mesh].toObject();
    QJsonArray primitives = m[QLatin1String("primitives")].toArray();
    QJsonObject p = primitives[0].toObject();
    p[key] = value;
    primitives[0] = p;
    m[QLatin1String("primitives")] = primitives;
    meshes[mesh] = m;
    m_json[QLatin1String("meshes")] = meshes;
}

void GltfWriter::setAttribute(int mesh, const QString& attribute, int accessor)
{
    QJsonObject attributes = m_json[QLatin1String("meshes")]
                                 .toArray()[mesh]
                                 .toObject()[QLatin1String("primitives")]
                                 .toArray()[0]
                                 .toObject()[QLatin1String("attributes")]
                                 .toObject();
    attributes[attribute] = accessor;
    setPrimitive(mesh, QStringLiteral("attributes"), attributes);
}

int GltfWriter::addNode(int mesh, const QJsonObject& transform)
{
    QJsonObject node = transform;
    if (mesh >= 0)
        node[QLatin1String("mesh")] = mesh;
    const int index = append("nodes", node);
    QJsonArray scenes = array("scenes");
    QJsonObject scene = scenes.isEmpty() ? QJsonObject() : scenes[0].toObject();
    QJsonArray roots = scene.value(QLatin1String("nodes")).toArray();
    roots.append(index);
    scene[QLatin1String("nodes")] = roots;
    if (scenes.isEmpty())
        scenes.append(scene);
    else
        scenes[0] = scene;
    setArray("scenes", scenes);
    m_json[QLatin1String("scene")] = 0;
    return index;
}

int GltfWriter::addImageUri(const QString& uri)
{
    QJsonObject image;
    image[QLatin1String("uri")] = uri;
    return append("images", image);
}

int GltfWriter::addImageEmbedded(const QByteArray& encoded, const QString& mimeType)
{
    QJsonObject image;
    image[QLatin1String("bufferView")] = addBufferView(encoded);
    image[QLatin1String("mimeType")] = mimeType;
    return append("images", image);
}

int GltfWriter::addTexture(int image, int sampler)
{
    QJsonObject texture;
    texture[QLatin1String("source")] = image;
    if (sampler >= 0)
        texture[QLatin1String("sampler")] = sampler;
    return append("textures", texture);
}

int GltfWriter::addMaterial(const QJsonObject& material)
{
    return append("materials", material);
}

bool GltfWriter::write(const QString& path, BufferStorage storage, QString* error) const
{
    const auto fail = [error](const QString& text) {
        if (error)
            *error = text;
        return false;
    };
    QJsonObject json = m_json;
    QJsonObject asset;
    asset[QLatin1String("version")] = QLatin1String("2.0");
    asset[QLatin1String("generator")] = QLatin1String("Facet tests");
    json[QLatin1String("asset")] = asset;
    QByteArray padded = m_buffer;
    while (padded.size() % 4 != 0)
        padded.append('\0');
    QJsonObject buffer;
    buffer[QLatin1String("byteLength")] = int(m_buffer.size());
    if (storage == BufferStorage::ExternalFile) {
        const QFileInfo info(path);
        const QString binName = info.completeBaseName() + QStringLiteral(".bin");
        QFile bin(info.dir().filePath(binName));
        if (!bin.open(QIODevice::WriteOnly) || bin.write(m_buffer) != m_buffer.size())
            return fail(QStringLiteral("cannot write ") + bin.fileName());
        buffer[QLatin1String("uri")] = binName;
    } else if (storage == BufferStorage::DataUri) {
        buffer[QLatin1String("uri")]
            = QStringLiteral("data:application/octet-stream;base64,") + QString::fromLatin1(m_buffer.toBase64());
    }
    if (!m_buffer.isEmpty())
        json[QLatin1String("buffers")] = QJsonArray {buffer};

    QByteArray text = QJsonDocument(json).toJson(QJsonDocument::Compact);
    QByteArray out;
    if (storage == BufferStorage::Glb) {
        while (text.size() % 4 != 0)
            text.append(' ');
        const std::uint32_t length = std::uint32_t(12 + 8 + text.size() + (padded.isEmpty() ? 0 : 8 + padded.size()));
        out.append("glTF", 4);
        appendUint32(out, 2);
        appendUint32(out, length);
        appendUint32(out, std::uint32_t(text.size()));
        out.append("JSON", 4);
        out.append(text);
        if (!padded.isEmpty()) {
            appendUint32(out, std::uint32_t(padded.size()));
            out.append("BIN\0", 4);
            out.append(padded);
        }
    } else {
        out = text;
    }
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(out) != out.size())
        return fail(QStringLiteral("cannot write ") + path);
    return true;
}

QJsonArray jsonNumbers(std::initializer_list<double> values)
{
    QJsonArray a;
    for (double v : values)
        a.append(v);
    return a;
}

QJsonObject textureInfo(int texture, const QJsonObject& extensions)
{
    QJsonObject info;
    info[QLatin1String("index")] = texture;
    if (!extensions.isEmpty())
        info[QLatin1String("extensions")] = extensions;
    return info;
}

QByteArray encodePng(int width, int height, int channels, const std::vector<glm::vec4>& texels)
{
    QTemporaryDir dir;
    const std::string file = dir.filePath(QStringLiteral("image.png")).toStdString();
    std::vector<unsigned char> pixels(std::size_t(width) * std::size_t(height) * std::size_t(channels));
    for (std::size_t i = 0; i < std::size_t(width) * std::size_t(height); ++i)
        for (int c = 0; c < channels; ++c)
            pixels[i * std::size_t(channels) + std::size_t(c)]
                = static_cast<unsigned char>(std::lround(std::clamp(texels[i][c], 0.0f, 1.0f) * 255.0f));
    auto output = OIIO::ImageOutput::create(file);
    OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (!output || !output->open(file, spec) || !output->write_image(OIIO::TypeDesc::UINT8, pixels.data())
        || !output->close())
        return {};
    QFile f(QString::fromStdString(file));
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace facet::test
