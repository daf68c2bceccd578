#include "TestAssets.h"

#include "GltfWriter.h"

#include "core/project/Project.h"

#include <OpenImageIO/imageio.h>

#include <QJsonArray>
#include <QJsonObject>

#include <cmath>
#include <cstdint>
#include <vector>

namespace facet::test {

std::vector<std::string> materialNames(const Project& project)
{
    std::vector<std::string> names;
    for (const Material& material : project.materials)
        names.push_back(material.name);
    return names;
}

std::vector<std::string> partMaterialNames(const Project& project, std::size_t parts)
{
    std::vector<std::string> names;
    for (std::size_t part = 0; part < parts; ++part)
        names.push_back(project.materials[std::size_t(project.materialOfPart(part))].name);
    return names;
}

namespace {

// A width x height 8-bit RGB PNG of one colour, written with OpenImageIO directly.
bool writeUniformMap(const QString& path, int width, int height, const float rgb[3])
{
    std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path.toStdString());
    if (!output
        || !output->open(path.toStdString(), OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8)))
        return false;
    std::vector<float> pixels;
    for (int i = 0; i < width * height; ++i)
        pixels.insert(pixels.end(), rgb, rgb + 3);
    return output->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) && output->close();
}

QJsonObject material(
    const QString& name, std::initializer_list<double> baseColor, double metallic, double roughness)
{
    QJsonObject pbr;
    pbr[QLatin1String("baseColorFactor")] = jsonNumbers(baseColor);
    pbr[QLatin1String("metallicFactor")] = metallic;
    pbr[QLatin1String("roughnessFactor")] = roughness;
    QJsonObject m;
    m[QLatin1String("name")] = name;
    m[QLatin1String("pbrMetallicRoughness")] = pbr;
    return m;
}

// A quad spanning [x0, x1] x [-1, 1] at z = 0 facing +Z, glTF UVs.
int addQuadAt(GltfWriter& w, float x0, float x1, int material, const QString& name)
{
    const glm::vec3 n(0, 0, 1);
    return w.addMesh({{x0, -1, 0}, {x1, -1, 0}, {x1, 1, 0}, {x0, 1, 0}}, {n, n, n, n},
        {{0, 1}, {1, 1}, {1, 0}, {0, 0}}, {0, 1, 2, 0, 2, 3}, material, name);
}

// An axis-aligned box [-1, 1]^3 without its top face, wound counter-clockwise from outside.
int addOpenBox(GltfWriter& w, int material, const QString& name)
{
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> indices;
    const glm::vec3 axes[5][3] = {
        // normal, u direction, v direction (u x v = normal)
        {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}},
        {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},
        {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
    };
    for (const auto& face : axes) {
        const std::uint32_t base = std::uint32_t(positions.size());
        for (const glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
            positions.push_back(face[0] + c.x * face[1] + c.y * face[2]);
            normals.push_back(face[0]);
            uvs.emplace_back((c.x + 1) / 2, 1 - (c.y + 1) / 2);
        }
        indices.insert(indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    return w.addMesh(positions, normals, uvs, indices, material, name);
}

QJsonObject placed(std::initializer_list<double> translation, std::initializer_list<double> scale)
{
    QJsonObject transform;
    transform[QLatin1String("translation")] = jsonNumbers(translation);
    transform[QLatin1String("scale")] = jsonNumbers(scale);
    return transform;
}

} // namespace

bool writeTwoMaterialAsset(const QString& path, QString* error, double rightAlpha)
{
    GltfWriter w;
    const int red = w.addMaterial(material(QStringLiteral("Red"), {0.8, 0.05, 0.05, 1.0}, 0.0, 0.5));
    const int blue = w.addMaterial(material(QStringLiteral("Blue"), {0.05, 0.1, 0.8, rightAlpha}, 0.0, 0.5));
    w.addNode(
        addQuadAt(w, TwoMaterialAsset::kLeftX0, TwoMaterialAsset::kLeftX1, red, QStringLiteral("Left")));
    w.addNode(
        addQuadAt(w, TwoMaterialAsset::kRightX0, TwoMaterialAsset::kRightX1, blue, QStringLiteral("Right")));
    return w.write(path, GltfWriter::BufferStorage::Glb, error);
}

bool writeShowcaseAsset(const QString& path, QString* error)
{
    GltfWriter w;
    // Textures: a two-tone checker (base colour) and a speckle (concrete), 64 x 64 8-bit.
    std::vector<glm::vec4> checker, speckle;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const bool odd = ((x / 8) + (y / 8)) % 2 == 1;
            checker.push_back(
                odd ? glm::vec4(0.92f, 0.78f, 0.35f, 1.0f) : glm::vec4(0.12f, 0.28f, 0.55f, 1.0f));
            // A speckle from an integer hash of the texel (no visible pattern).
            std::uint32_t h = std::uint32_t(x) * 73856093u ^ std::uint32_t(y) * 19349663u;
            h = (h ^ (h >> 13)) * 1274126177u;
            const float noise = 0.55f + 0.25f * float(h >> 24) / 255.0f;
            speckle.push_back(glm::vec4(noise, noise * 0.97f, noise * 0.92f, 1.0f));
        }
    const int checkerTexture
        = w.addTexture(w.addImageEmbedded(encodePng(64, 64, 4, checker), QStringLiteral("image/png")));
    const int speckleTexture
        = w.addTexture(w.addImageEmbedded(encodePng(64, 64, 4, speckle), QStringLiteral("image/png")));

    QJsonObject concrete = material(QStringLiteral("Concrete"), {1, 1, 1, 1}, 0.0, 0.9);
    QJsonObject pbr = concrete[QLatin1String("pbrMetallicRoughness")].toObject();
    pbr[QLatin1String("baseColorTexture")] = textureInfo(speckleTexture);
    concrete[QLatin1String("pbrMetallicRoughness")] = pbr;
    QJsonObject painted = material(QStringLiteral("Painted Checker"), {1, 1, 1, 1}, 0.0, 0.35);
    pbr = painted[QLatin1String("pbrMetallicRoughness")].toObject();
    pbr[QLatin1String("baseColorTexture")] = textureInfo(checkerTexture);
    painted[QLatin1String("pbrMetallicRoughness")] = pbr;
    QJsonObject glass = material(QStringLiteral("Tinted Glass"), {0.6, 0.9, 0.8, 0.35}, 0.0, 0.05);
    glass[QLatin1String("alphaMode")] = QLatin1String("BLEND");
    glass[QLatin1String("doubleSided")] = true;
    QJsonObject lamp = material(QStringLiteral("Lamp"), {0.1, 0.1, 0.1, 1}, 0.0, 0.6);
    lamp[QLatin1String("emissiveFactor")] = jsonNumbers({1.0, 0.55, 0.2});
    QJsonObject strength;
    strength[QLatin1String("emissiveStrength")] = 8.0;
    QJsonObject extensions;
    extensions[QLatin1String("KHR_materials_emissive_strength")] = strength;
    lamp[QLatin1String("extensions")] = extensions;
    QJsonArray used {QLatin1String("KHR_materials_emissive_strength")};
    w.json()[QLatin1String("extensionsUsed")] = used;
    const QJsonObject rubber = material(QStringLiteral("Rubber"), {0.05, 0.05, 0.05, 1}, 0.0, 0.7);

    const int concreteMaterial = w.addMaterial(concrete);
    const int paintedMaterial = w.addMaterial(painted);
    const int glassMaterial = w.addMaterial(glass);
    const int lampMaterial = w.addMaterial(lamp);
    const int rubberMaterial = w.addMaterial(rubber);

    w.addNode(addOpenBox(w, concreteMaterial, QStringLiteral("Base")), placed({0, -1.0, 0}, {1.6, 0.2, 1.2}));
    w.addNode(w.addQuad(rubberMaterial, 0.0f, QStringLiteral("Base Top")), [] {
        // The quad faces +Z: turned -90 degrees about X it faces +Y, on top of the slab.
        QJsonObject t = placed({0, -0.8, 0}, {1.6, 1.2, 1});
        const double s = std::sqrt(0.5);
        t[QLatin1String("rotation")] = jsonNumbers({-s, 0, 0, s});
        return t;
    }());
    const auto sphere = [&](int materialIndex, const QString& name) {
        const int mesh = w.addSphere(materialIndex, 48, 24);
        // addSphere names its mesh "sphere": name the part.
        QJsonArray meshes = w.json()[QLatin1String("meshes")].toArray();
        QJsonObject object = meshes[mesh].toObject();
        object[QLatin1String("name")] = name;
        meshes[mesh] = object;
        w.json()[QLatin1String("meshes")] = meshes;
        return mesh;
    };
    w.addNode(sphere(paintedMaterial, QStringLiteral("Body")), placed({-0.55, -0.1, 0}, {0.7, 0.7, 0.7}));
    w.addNode(sphere(glassMaterial, QStringLiteral("Glass")), placed({0.7, -0.3, 0.35}, {0.5, 0.5, 0.5}));
    w.addNode(sphere(lampMaterial, QStringLiteral("Lamp")), placed({0.45, 0.55, -0.35}, {0.25, 0.25, 0.25}));
    return w.write(path, GltfWriter::BufferStorage::Glb, error);
}

// The project: "Brick Wall" (base colour 32x16, normal, ORM, sharing one packed file), "Steel"
// (base colour and roughness), "Gold" (constants).
QString writeTexturedProject(const QString& folder)
{
    const float base[3] = {0.6f, 0.3f, 0.2f};
    const float normal[3] = {0.5f, 0.5f, 1.0f};
    const float orm[3] = {0.9f, 0.6f, 0.0f};
    const float grey[3] = {0.4f, 0.4f, 0.4f};
    if (!writeUniformMap(folder + QStringLiteral("/brick_base.png"), 32, 16, base)
        || !writeUniformMap(folder + QStringLiteral("/brick_normal.png"), 16, 16, normal)
        || !writeUniformMap(folder + QStringLiteral("/brick_orm.png"), 16, 16, orm)
        || !writeUniformMap(folder + QStringLiteral("/steel_base.png"), 8, 8, grey)
        || !writeUniformMap(folder + QStringLiteral("/steel_rough.png"), 8, 8, grey))
        return {};
    facet::Project project;
    facet::Material brick;
    brick.name = "Brick Wall";
    brick.map(facet::MapSlot::BaseColor).path = (folder + QStringLiteral("/brick_base.png")).toStdString();
    brick.map(facet::MapSlot::Normal).path = (folder + QStringLiteral("/brick_normal.png")).toStdString();
    for (const auto& [slot, channel] : {std::pair {facet::MapSlot::Occlusion, facet::MapChannel::R},
             {facet::MapSlot::Roughness, facet::MapChannel::G},
             {facet::MapSlot::Metallic, facet::MapChannel::B}}) {
        brick.map(slot).path = (folder + QStringLiteral("/brick_orm.png")).toStdString();
        brick.map(slot).channel = channel;
        brick.setFactor(slot, 1.0);
    }
    facet::Material steel;
    steel.name = "Steel";
    steel.map(facet::MapSlot::BaseColor).path = (folder + QStringLiteral("/steel_base.png")).toStdString();
    steel.map(facet::MapSlot::Roughness).path = (folder + QStringLiteral("/steel_rough.png")).toStdString();
    steel.setFactor(facet::MapSlot::Metallic, 1.0);
    facet::Material gold;
    gold.name = "Gold";
    gold.setBaseColor(glm::dvec3(1.0, 0.766, 0.336));
    gold.setFactor(facet::MapSlot::Metallic, 1.0);
    project.materials = {brick, steel, gold};
    const QString path = folder + QStringLiteral("/walls.json");
    std::string error;
    return project.save(path.toStdString(), &error) ? path : QString();
}

facet::Image variedImage(int seed, int channels)
{
    facet::Image image(16, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x)
            for (int c = 0; c < 4; ++c)
                image.at(x, y)[c] = c < channels
                    ? float(((x * 13 + y * 29 + c * 71 + seed * 37) % 200) + 30) / 255.0f
                    : 1.0f;
    image.setEncoding(facet::ColorEncoding::Linear);
    return image;
}

QByteArray exportTemplateJson(const QByteArray& outputs, const QByteArray& fileName)
{
    return "{\"format\": \"facet-export-template\", \"version\": 1, \"name\": \"T\", \"fileName\": \""
        + fileName + "\", \"outputs\": [" + outputs + "]}";
}

} // namespace facet::test
