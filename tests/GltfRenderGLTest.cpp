// glTF assets as they render: small files this test writes (support/GltfWriter), opened the way
// `facet render ASSET.glb --reference-view` opens them (core/project/AssetProject projectFromAsset, then
// the command's own render path, support/ReferenceViewRenderer::renderAsCommand), and checked in
// the rendered image, not only in the loaded data: factors, the packed metallic-roughness texture,
// occlusion strength, emissive with its strength, KHR_texture_transform, a map on TEXCOORD_1, two
// materials side by side, alpha MASK and BLEND, a hidden part, single-sided culling.
//
// The meshes are quads in the XY plane facing +Z; the view normalises them to the unit sphere, so
// a quad spanning [-1, 1]^2 covers the middle 36 x 36 pixels of the 64 x 64 reference view.

#include "core/image/Image.h"
#include "core/image/ToneMap.h"
#include "core/project/AssetProject.h"
#include "core/project/Project.h"

#include "GltfWriter.h"
#include "ReferenceViewRenderer.h"
#include "TestSupport.h"

#include <QTemporaryDir>
#include <QtTest/QTest>

#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <string>

using namespace facet;
using facet::test::GltfWriter;
using facet::test::jsonNumbers;
using facet::test::textureInfo;

namespace {

constexpr int kSize = 64;
constexpr double kBackground = 0.5; // the uniform environment's radiance



QJsonObject pbr(const QJsonObject& values)
{
    QJsonObject material;
    material[QLatin1String("pbrMetallicRoughness")] = values;
    return material;
}

// A PNG of `size` x `size` texels of one RGBA value (8-bit: the values land on k / 255).
QByteArray constantPng(glm::vec4 value, int size = 4)
{
    return facet::test::encodePng(size, size, 4, std::vector<glm::vec4>(std::size_t(size * size), value));
}

// 8 x 8 texels in four quadrants (rows top first): red top-left, green top-right, blue
// bottom-left, white bottom-right.
QByteArray quadrantsPng()
{
    std::vector<glm::vec4> texels;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const bool right = x >= 4;
            const bool bottom = y >= 4;
            texels.push_back(!bottom ? (right ? glm::vec4(0, 1, 0, 1) : glm::vec4(1, 0, 0, 1))
                                     : (right ? glm::vec4(1, 1, 1, 1) : glm::vec4(0, 0, 1, 1)));
        }
    return facet::test::encodePng(8, 8, 4, texels);
}

// A quad covering x in [x0, x1], y in [-1, 1], facing +Z (or -Z when `away`), glTF UVs.
int addQuadAt(GltfWriter& w, float x0, float x1, int material, bool away = false)
{
    std::vector<std::uint32_t> indices = away ? std::vector<std::uint32_t> {0, 2, 1, 0, 3, 2}
                                              : std::vector<std::uint32_t> {0, 1, 2, 0, 2, 3};
    const glm::vec3 n(0, 0, away ? -1 : 1);
    return w.addMesh({{x0, -1, 0}, {x1, -1, 0}, {x1, 1, 0}, {x0, 1, 0}}, {n, n, n, n},
                     {{0, 1}, {1, 1}, {1, 0}, {0, 0}}, indices, material);
}

glm::dvec3 pixel(const Image& image, int x, int y)
{
    return glm::dvec3(glm::vec3(image.at(x, y)));
}

QString text(const glm::dvec3& v)
{
    return QStringLiteral("(%1, %2, %3)").arg(v.x).arg(v.y).arg(v.z);
}

} // namespace

class GltfRenderGLTest : public QObject {
    Q_OBJECT
public:
    static void initMain() { facet::test::forgetDisplayServer(); }

private Q_SLOTS:
    void initTestCase();
    void factorsOnAQuad();
    void packedTextureOcclusionAndEmissive();
    void textureTransformPicksTheQuadrant_data();
    void textureTransformPicksTheQuadrant();
    void secondUvSetFeedsItsMap();
    void twoMaterialsSideBySide();
    void vertexColorsMultiplyTheBaseColour();
    void unlitShowsTheBaseColour();
    void hiddenPartIsNotDrawn();
    void alphaMaskCutsOut();
    void alphaBlendComposites();
    void singleSidedFacesAreCulled();

private:
    // Writes `w` as a .glb, opens it as `facet render` does and renders `view` (linear radiance).
    std::optional<Image> render(const GltfWriter& w, const QString& name, const std::string& view,
                                Project* opened = nullptr, const std::function<void(Project&)>& edit = {});
    void expectPixel(const Image& image, int x, int y, const glm::dvec3& expected, double tolerance);

    QTemporaryDir m_dir;
    facet::test::ReferenceViewRenderer m_gpu;
};

void GltfRenderGLTest::initTestCase()
{
    QVERIFY(m_dir.isValid());
    std::string error;
    QVERIFY2(m_gpu.initialize(&error), error.c_str());
}

std::optional<Image> GltfRenderGLTest::render(const GltfWriter& w, const QString& name, const std::string& view,
                                              Project* opened, const std::function<void(Project&)>& edit)
{
    const QString file = m_dir.filePath(name + QStringLiteral(".glb"));
    QString writeError;
    if (!w.write(file, GltfWriter::BufferStorage::Glb, &writeError)) {
        qWarning("%s", qPrintable(writeError));
        return std::nullopt;
    }
    std::string error;
    std::optional<Project> project = projectFromAsset(file.toStdString(), &error);
    if (!project) {
        qWarning("%s", error.c_str());
        return std::nullopt;
    }
    project->environment.source = "uniform:" + std::to_string(kBackground);
    project->view.debugView = debugViewFromString(view).value();
    if (edit)
        edit(*project);
    if (opened)
        *opened = *project;
    auto image = m_gpu.renderAsCommand(*project, "draft", kSize, &error);
    if (!image)
        qWarning("%s", error.c_str());
    return image;
}

void GltfRenderGLTest::expectPixel(const Image& image, int x, int y, const glm::dvec3& expected, double tolerance)
{
    const glm::dvec3 actual = pixel(image, x, y);
    const glm::dvec3 d = glm::abs(actual - expected);
    QVERIFY2(std::max({d.x, d.y, d.z}) <= tolerance,
             qPrintable(QStringLiteral("pixel (%1, %2): %3, expected %4 (tolerance %5)")
                            .arg(x)
                            .arg(y)
                            .arg(text(actual), text(expected))
                            .arg(tolerance)));
}

// Constant factors reach the material inputs (half-float output: 1e-3).
void GltfRenderGLTest::factorsOnAQuad()
{
    GltfWriter w;
    QJsonObject values;
    values[QLatin1String("baseColorFactor")] = jsonNumbers({0.2, 0.4, 0.6, 1.0});
    values[QLatin1String("metallicFactor")] = 0.3;
    values[QLatin1String("roughnessFactor")] = 0.7;
    w.addNode(w.addQuad(w.addMaterial(pbr(values))));
    const auto base = render(w, QStringLiteral("factors"), "base-color");
    QVERIFY(base);
    expectPixel(*base, 32, 32, {0.2, 0.4, 0.6}, 1e-3);
    expectPixel(*base, 2, 2, glm::dvec3(kBackground), 1e-3); // outside the quad: the environment
    const auto metallic = render(w, QStringLiteral("factors"), "metallic");
    QVERIFY(metallic);
    expectPixel(*metallic, 32, 32, glm::dvec3(0.3), 1e-3);
    const auto roughness = render(w, QStringLiteral("factors"), "roughness");
    QVERIFY(roughness);
    expectPixel(*roughness, 32, 32, glm::dvec3(0.7), 1e-3);
}

// glTF's packed texture: roughness from G, metallic from B; occlusion from R with its strength;
// emissive factor x sRGB texture x KHR_materials_emissive_strength.
void GltfRenderGLTest::packedTextureOcclusionAndEmissive()
{
    GltfWriter w;
    const int packed = w.addTexture(w.addImageEmbedded(constantPng({0.2f, 0.4f, 0.6f, 1.0f}), QStringLiteral("image/png")));
    const int glow = w.addTexture(w.addImageEmbedded(constantPng({0.5f, 0.5f, 0.5f, 1.0f}), QStringLiteral("image/png")));
    QJsonObject values;
    values[QLatin1String("metallicRoughnessTexture")] = textureInfo(packed);
    QJsonObject material = pbr(values);
    QJsonObject occlusion = textureInfo(packed);
    occlusion[QLatin1String("strength")] = 0.5;
    material[QLatin1String("occlusionTexture")] = occlusion;
    material[QLatin1String("emissiveTexture")] = textureInfo(glow);
    material[QLatin1String("emissiveFactor")] = jsonNumbers({1.0, 0.5, 0.25});
    QJsonObject strength;
    strength[QLatin1String("emissiveStrength")] = 4.0;
    QJsonObject extensions;
    extensions[QLatin1String("KHR_materials_emissive_strength")] = strength;
    material[QLatin1String("extensions")] = extensions;
    w.addNode(w.addQuad(w.addMaterial(material)));

    const double r = 51.0 / 255.0, g = 102.0 / 255.0, b = 153.0 / 255.0;
    const auto roughness = render(w, QStringLiteral("packed"), "roughness");
    QVERIFY(roughness);
    expectPixel(*roughness, 32, 32, glm::dvec3(g), 2e-3);
    const auto metallic = render(w, QStringLiteral("packed"), "metallic");
    QVERIFY(metallic);
    expectPixel(*metallic, 32, 32, glm::dvec3(b), 2e-3);
    const auto ao = render(w, QStringLiteral("packed"), "occlusion");
    QVERIFY(ao);
    expectPixel(*ao, 32, 32, glm::dvec3(1.0 + 0.5 * (r - 1.0)), 2e-3);
    const auto emissive = render(w, QStringLiteral("packed"), "emissive");
    QVERIFY(emissive);
    const double texel = tonemap::srgbToLinear(128.0 / 255.0);
    expectPixel(*emissive, 32, 32, glm::dvec3(1.0, 0.5, 0.25) * texel * 4.0, 5e-3);
    // In the shaded image the emission adds to the lit surface.
    const auto shaded = render(w, QStringLiteral("packed"), "none");
    QVERIFY(shaded);
    QVERIFY2(pixel(*shaded, 32, 32).r > 4.0 * texel * 0.99, qPrintable(text(pixel(*shaded, 32, 32))));
}

void GltfRenderGLTest::textureTransformPicksTheQuadrant_data()
{
    QTest::addColumn<QVector<double>>("offset");
    QTest::addColumn<QVector<double>>("scale");
    QTest::addColumn<double>("rotation"); // radians
    QTest::addColumn<QVector<double>>("expected"); // the colour at the quad's centre
    // The quad's UVs span the image; scale 0.5 and an offset pick one quadrant (glTF's UV origin
    // is the image's top-left: offset (0.5, 0) is the top-right quadrant).
    QTest::newRow("top-left") << QVector<double> {0.0, 0.0} << QVector<double> {0.5, 0.5} << 0.0
                              << QVector<double> {1, 0, 0};
    QTest::newRow("top-right") << QVector<double> {0.5, 0.0} << QVector<double> {0.5, 0.5} << 0.0
                               << QVector<double> {0, 1, 0};
    QTest::newRow("bottom-left") << QVector<double> {0.0, 0.5} << QVector<double> {0.5, 0.5} << 0.0
                                 << QVector<double> {0, 0, 1};
    QTest::newRow("bottom-right") << QVector<double> {0.5, 0.5} << QVector<double> {0.5, 0.5} << 0.0
                                  << QVector<double> {1, 1, 1};
    // Rotation as the sample renderers apply it (T R(-rotation) S): the centre (0.25, 0.25) after
    // scaling turns to (0.25, -0.25) for +90 degrees, and the offset brings it into a quadrant.
    // The README's GLSL (the other direction, issue 29) lands in the opposite quadrant.
    QTest::newRow("rotation +90 degrees: top-right, not bottom-left") << QVector<double> {0.5,
        0.5} << QVector<double> {0.5, 0.5} << std::numbers::pi / 2 << QVector<double> {0, 1, 0};
    QTest::newRow("rotation -90 degrees: bottom-left, not top-right") << QVector<double> {0.5,
        0.5} << QVector<double> {0.5, 0.5} << -std::numbers::pi / 2 << QVector<double> {0, 0, 1};
}

void GltfRenderGLTest::textureTransformPicksTheQuadrant()
{
    QFETCH(QVector<double>, offset);
    QFETCH(QVector<double>, scale);
    QFETCH(double, rotation);
    QFETCH(QVector<double>, expected);
    GltfWriter w;
    const int quadrants = w.addTexture(w.addImageEmbedded(quadrantsPng(), QStringLiteral("image/png")));
    QJsonObject transform;
    transform[QLatin1String("offset")] = jsonNumbers({offset[0], offset[1]});
    transform[QLatin1String("scale")] = jsonNumbers({scale[0], scale[1]});
    if (rotation != 0.0)
        transform[QLatin1String("rotation")] = rotation;
    QJsonObject extension;
    extension[QLatin1String("KHR_texture_transform")] = transform;
    QJsonObject values;
    values[QLatin1String("baseColorTexture")] = textureInfo(quadrants, extension);
    w.addNode(w.addQuad(w.addMaterial(pbr(values))));
    const auto image = render(w, QStringLiteral("transform"), "base-color");
    QVERIFY(image);
    // Pixels near the centre read the middle of one quadrant (uv' = offset + 0.25 +- a little).
    for (const auto& [x, y] : {std::pair {32, 32}, std::pair {28, 28}, std::pair {36, 36}})
        expectPixel(*image, x, y, {expected[0], expected[1], expected[2]}, 2e-3);
}

// Issue 29: a textureInfo with texCoord 1 read UV 0. The quad's TEXCOORD_1 is (0.25, 0.25) at every
// corner, the red quadrant's middle; its TEXCOORD_0 spans the texture. On set 1 the whole quad is
// red; on set 0 each pixel shows its own quadrant (blue lower left, green upper right).
void GltfRenderGLTest::secondUvSetFeedsItsMap()
{
    for (const int set : {1, 0}) {
        GltfWriter w;
        const int quadrants = w.addTexture(w.addImageEmbedded(quadrantsPng(), QStringLiteral("image/png")));
        QJsonObject info = textureInfo(quadrants);
        info[QLatin1String("texCoord")] = set;
        QJsonObject values;
        values[QLatin1String("baseColorTexture")] = info;
        const int mesh = w.addQuad(w.addMaterial(pbr(values)));
        w.setAttribute(
            mesh, QStringLiteral("TEXCOORD_1"), w.addFloatAccessor(std::vector<float>(8, 0.25f), 2));
        w.addNode(mesh);
        const auto image = render(w, QStringLiteral("uv-set-%1").arg(set), "base-color");
        QVERIFY(image);
        expectPixel(*image, 20, 40, set == 1 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1), 2e-3);
        expectPixel(*image, 44, 24, set == 1 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0), 2e-3);
    }
}

// Issue 29: COLOR_0 multiplies the base colour (glTF 2.0 section 3.9.2), here a uniform colour
// on every vertex of a quad whose material says 0.8 grey: the base-color view reads their product,
// and the asset without COLOR_0 reads the factor alone (the same program would show white there).
void GltfRenderGLTest::vertexColorsMultiplyTheBaseColour()
{
    for (const bool withColours : {true, false}) {
        GltfWriter w;
        QJsonObject values;
        values[QLatin1String("baseColorFactor")] = jsonNumbers({0.8, 0.8, 0.8, 1});
        const int mesh = w.addQuad(w.addMaterial(pbr(values)));
        if (withColours) {
            std::vector<float> colours(16);
            for (std::size_t i = 0; i < colours.size(); ++i)
                colours[i] = std::array<float, 4> {0.5f, 0.25f, 1.0f, 1.0f}[i % 4];
            const int accessor = w.addFloatAccessor(colours, 4);
            w.setAttribute(mesh, QStringLiteral("COLOR_0"), accessor);
        }
        w.addNode(mesh);
        const auto image
            = render(w, withColours ? QStringLiteral("colours") : QStringLiteral("no-colours"), "base-color");
        QVERIFY(image);
        const glm::dvec3 expected = withColours ? glm::dvec3(0.4, 0.2, 0.8) : glm::dvec3(0.8);
        for (const auto& [x, y] : {std::pair {32, 32}, std::pair {20, 40}, std::pair {44, 24}})
            expectPixel(*image, x, y, expected, 2e-3);
    }
}

// Issue 29: KHR_materials_unlit was dropped (the sample renderer, Filament, three.js and Babylon
// read it). An unlit material shows its base colour x vertex colour as radiance whatever the
// environment, the lights and the emission; the same material lit does not. Its glTF round trip
// keeps the extension; the CPU ground truth gives the same radiance.
void GltfRenderGLTest::unlitShowsTheBaseColour()
{
    for (const bool unlit : {true, false}) {
        GltfWriter w;
        QJsonObject values;
        values[QLatin1String("baseColorFactor")] = jsonNumbers({0.6, 0.3, 0.1, 1});
        QJsonObject material = pbr(values);
        material[QLatin1String("emissiveFactor")] = jsonNumbers({0.5, 0.5, 0.5});
        if (unlit) {
            material[QLatin1String("extensions")]
                = QJsonObject {{QStringLiteral("KHR_materials_unlit"), QJsonObject {}}};
            w.json()[QLatin1String("extensionsUsed")] = QJsonArray {QStringLiteral("KHR_materials_unlit")};
        }
        w.addNode(w.addQuad(w.addMaterial(material)));
        Project opened;
        const auto image
            = render(w, unlit ? QStringLiteral("unlit") : QStringLiteral("lit"), "none", &opened);
        QVERIFY(image);
        QCOMPARE(opened.materials.front().unlit, unlit);
        const glm::dvec3 shown = pixel(*image, 32, 32);
        if (unlit) {
            expectPixel(*image, 32, 32, {0.6, 0.3, 0.1}, 2e-3);
            expectPixel(*image, 20, 44, {0.6, 0.3, 0.1}, 2e-3);
        } else {
            QVERIFY2(glm::length(shown - glm::dvec3(0.6, 0.3, 0.1)) > 0.1, qPrintable(text(shown)));
        }
    }
}

// Two primitives with two materials: each half shows its own, as the part assignment says.
void GltfRenderGLTest::twoMaterialsSideBySide()
{
    GltfWriter w;
    QJsonObject red, blue;
    red[QLatin1String("baseColorFactor")] = jsonNumbers({1, 0, 0, 1});
    blue[QLatin1String("baseColorFactor")] = jsonNumbers({0, 0, 1, 1});
    const int redMaterial = w.addMaterial(pbr(red));
    const int blueMaterial = w.addMaterial(pbr(blue));
    w.addNode(addQuadAt(w, -1.0f, -0.05f, redMaterial));
    w.addNode(addQuadAt(w, 0.05f, 1.0f, blueMaterial));
    Project opened;
    const auto image = render(w, QStringLiteral("two"), "base-color", &opened);
    QVERIFY(image);
    QCOMPARE(opened.materials.size(), std::size_t(2));
    QCOMPARE(opened.parts.size(), std::size_t(2));
    expectPixel(*image, 22, 32, {1, 0, 0}, 1e-3);
    expectPixel(*image, 42, 32, {0, 0, 1}, 1e-3);
    // Assigning the red material to the right part in the project: both halves red.
    const auto reassigned = render(w, QStringLiteral("two"), "base-color", nullptr,
                                   [](Project& p) { p.parts[1].material = 0; });
    QVERIFY(reassigned);
    expectPixel(*reassigned, 42, 32, {1, 0, 0}, 1e-3);
}

void GltfRenderGLTest::hiddenPartIsNotDrawn()
{
    GltfWriter w;
    QJsonObject red;
    red[QLatin1String("baseColorFactor")] = jsonNumbers({1, 0, 0, 1});
    const int material = w.addMaterial(pbr(red));
    w.addNode(addQuadAt(w, -1.0f, -0.05f, material));
    w.addNode(addQuadAt(w, 0.05f, 1.0f, material));
    const auto image = render(w, QStringLiteral("hidden"), "base-color", nullptr,
                              [](Project& p) { p.parts[1].visible = false; });
    QVERIFY(image);
    expectPixel(*image, 22, 32, {1, 0, 0}, 1e-3);
    expectPixel(*image, 42, 32, glm::dvec3(kBackground), 1e-3);
}

// MASK: texels with alpha below the cutoff are not drawn (the environment shows), the rest opaque.
void GltfRenderGLTest::alphaMaskCutsOut()
{
    std::vector<glm::vec4> texels;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            texels.emplace_back(1.0f, 1.0f, 1.0f, x < 4 ? 0.0f : 1.0f);
    GltfWriter w;
    const int cutout = w.addTexture(w.addImageEmbedded(facet::test::encodePng(8, 8, 4, texels), QStringLiteral("image/png")));
    QJsonObject values;
    values[QLatin1String("baseColorTexture")] = textureInfo(cutout);
    values[QLatin1String("baseColorFactor")] = jsonNumbers({1, 0, 0, 1});
    QJsonObject material = pbr(values);
    material[QLatin1String("alphaMode")] = QLatin1String("MASK");
    material[QLatin1String("alphaCutoff")] = 0.5;
    w.addNode(w.addQuad(w.addMaterial(material)));
    const auto image = render(w, QStringLiteral("mask"), "base-color");
    QVERIFY(image);
    expectPixel(*image, 22, 32, glm::dvec3(kBackground), 1e-3); // alpha 0: cut out
    expectPixel(*image, 42, 32, {1, 0, 0}, 1e-3);               // alpha 1: drawn
}

// BLEND: the shaded surface composited "over" the environment behind it: alpha S + (1 - alpha) B.
void GltfRenderGLTest::alphaBlendComposites()
{
    const auto writer = [](const char* mode) {
        GltfWriter w;
        QJsonObject values;
        values[QLatin1String("baseColorFactor")] = jsonNumbers({0.9, 0.2, 0.1, 0.25});
        values[QLatin1String("metallicFactor")] = 0.0;
        QJsonObject material = pbr(values);
        material[QLatin1String("alphaMode")] = QLatin1String(mode);
        w.addNode(w.addQuad(w.addMaterial(material)));
        return w;
    };
    const auto opaque = render(writer("OPAQUE"), QStringLiteral("opaque"), "none");
    const auto blended = render(writer("BLEND"), QStringLiteral("blend"), "none");
    QVERIFY(opaque && blended);
    for (const auto& [x, y] : {std::pair {32, 32}, std::pair {24, 40}}) {
        const glm::dvec3 expected = 0.25 * pixel(*opaque, x, y) + 0.75 * glm::dvec3(kBackground);
        expectPixel(*blended, x, y, expected, 2e-3);
    }
    expectPixel(*blended, 2, 2, glm::dvec3(kBackground), 1e-3);
}

// A single-sided material's faces seen from behind are culled; double-sided ones are drawn.
void GltfRenderGLTest::singleSidedFacesAreCulled()
{
    for (const bool doubleSided : {false, true}) {
        GltfWriter w;
        QJsonObject values;
        values[QLatin1String("baseColorFactor")] = jsonNumbers({0, 1, 0, 1});
        QJsonObject material = pbr(values);
        material[QLatin1String("doubleSided")] = doubleSided;
        w.addNode(addQuadAt(w, -1.0f, 1.0f, w.addMaterial(material), /*away=*/true));
        const auto image = render(w, QStringLiteral("sided"), "base-color");
        QVERIFY(image);
        expectPixel(*image, 32, 32, doubleSided ? glm::dvec3(0, 1, 0) : glm::dvec3(kBackground), 1e-3);
    }
}

QTEST_GUILESS_MAIN(GltfRenderGLTest)
#include "GltfRenderGLTest.moc"
