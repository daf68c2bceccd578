// The surface renderer's debug views and overlays on a headless context (llvmpipe: small images,
// 48-96 px): the base colour view (a constant and an sRGB texture), every feature and debug view
// compiling to finite values (and SH irradiance through the irradiance view), the texel-density
// and UV-checker views against their CPU formulas, and the wireframe overlay. The GPU against its
// CPU twins, the furnace and the counters: RendererGLTest. The uniform IBL here is built by hand
// (support/RendererTestScene.h).

#include <epoxy/gl.h> // before any header that could pull in <GL/gl.h>

#include "core/image/ToneMap.h"
#include "core/mesh/MeshPrimitives.h"
#include "core/shading/Brdf.h"
#include "render/Framebuffer.h"
#include "render/HeadlessGLContext.h"
#include "render/Renderer.h"

#include "RendererTestScene.h"
#include "TestSupport.h"

#include <QtTest/QTest>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

using namespace facet;
using facet::test::interiorPixels;
using facet::test::kSize;
using facet::test::referenceScene;
using facet::test::SpherePixel;
using facet::test::TinyIbl;

class RendererDebugViewsGLTest : public QObject, public facet::test::RendererGLFixture {
    Q_OBJECT
public:
    static void initMain() { facet::test::forgetDisplayServer(); }

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void baseColorDebugView();
    void everyFeatureAndDebugViewCompiles();
    void texelDensityView_data();
    void texelDensityView();
    void uvCheckerView();
    void wireframeOverlay();
};

void RendererDebugViewsGLTest::initTestCase()
{
    initRendererFixture();
}

void RendererDebugViewsGLTest::cleanupTestCase()
{
    cleanupRendererFixture();
}

void RendererDebugViewsGLTest::baseColorDebugView()
{
    TinyIbl ibl {glm::vec3(1.0f)};
    RenderScene scene = referenceScene(ibl);
    scene.view.debugView = DebugView::BaseColor;
    const glm::dvec3 base(0.2, 0.5, 0.8);
    scene.materials[0].material.setBaseColor(base);
    Image image = renderScene(scene);
    const std::vector<SpherePixel> pixels = interiorPixels(kSize);
    for (const SpherePixel& p : pixels)
        QVERIFY(glm::length(glm::dvec3(glm::vec3(image.at(p.x, p.y))) - base) < 1e-6);

    // An sRGB-encoded texture (encoded 128/255 everywhere) is decoded to linear and multiplied by
    // the factor; a constant texture makes filtering irrelevant.
    auto texture = std::make_shared<const MapImage>(
        MapImage::fromImage(Image(8, 8, glm::vec4(128.0f / 255.0f, 128.0f / 255.0f, 128.0f / 255.0f, 1.0f)),
            MapLayout::Rgb, MapSampleType::UInt8));
    scene.materials[0].material.map(MapSlot::BaseColor).path = "/t/base.png";
    scene.materials[0].material.map(MapSlot::BaseColor).colorSpace = ColorEncoding::SRGB;
    scene.materials[0].maps[std::size_t(MapSlot::BaseColor)] = {texture, "/t/base.png", 7};
    image = renderScene(scene);
    const glm::dvec3 expected = base * tonemap::srgbToLinear(128.0 / 255.0);
    for (const SpherePixel& p : pixels) {
        const glm::dvec3 actual(glm::vec3(image.at(p.x, p.y)));
        // 8-bit sRGB decode in the sampler: within 1e-3 of the exact curve (llvmpipe's table).
        QVERIFY2(glm::length(actual - expected) < 2e-3,
            (facet::test::describe(actual) + " vs " + facet::test::describe(expected)).c_str());
    }
}

void RendererDebugViewsGLTest::everyFeatureAndDebugViewCompiles()
{
    // Every map with a texture (normal map: tangent frame), a spot and a point light, SH
    // irradiance, each model switch, and each debug view: compiles, renders finite values.
    TinyIbl ibl {glm::vec3(1.0f)};
    RenderScene scene = referenceScene(ibl);
    auto texture = std::make_shared<const MapImage>(MapImage::fromImage(
        Image(4, 4, glm::vec4(0.5f, 0.5f, 1.0f, 1.0f)), MapLayout::Rgba, MapSampleType::UInt8));
    for (MapSlot slot : kAllMapSlots) {
        scene.materials[0].material.map(slot).path = std::string("/t/") + toString(slot) + ".png";
        scene.materials[0].material.map(slot).channel = isScalarSlot(slot) ? MapChannel::G : MapChannel::Rgb;
        scene.materials[0].maps[std::size_t(slot)] = {texture, scene.materials[0].material.map(slot).path, 1};
    }
    scene.materials[0].material.map(MapSlot::Normal).flipGreen = true;
    scene.materials[0].material.map(MapSlot::BaseColor).uv.rotationDegrees = 30.0;
    Light spot;
    spot.type = LightType::Spot;
    spot.position = glm::dvec3(0.0, 0.0, 3.0);
    spot.innerConeAngle = 0.1;
    spot.outerConeAngle = 0.4;
    Light point;
    point.type = LightType::Point;
    point.position = glm::dvec3(2.0, 2.0, 2.0);
    scene.lights = {spot, point};
    scene.environment.useSH = true;
    scene.environment.irradianceSH[0] = glm::vec3(float(shading::kPi / 0.282094791773878)); // E = pi
    std::vector<ShadingModel> models(5);
    models[1] = ShadingModel::learnOpenGL();
    models[2].distribution = Distribution::Beckmann;
    models[2].visibility = Visibility::SmithGGXUncorrelated;
    models[3].fresnel = Fresnel::Dielectric;
    models[3].coupling = DielectricCoupling::EnergyPreserving;
    models[4].multiScatter = false;
    for (const ShadingModel& model : models)
        for (int view = 0; view < kDebugViewCount; ++view) {
            if (model != models[0] && view != 0)
                continue; // debug views once, with the default model
            scene.materials[0].material.shading = model;
            scene.view.debugView = DebugView(view);
            std::string error;
            std::optional<Framebuffer> target
                = Framebuffer::create(16, 16, FramebufferFormat::RGBA16F, &error);
            QVERIFY2(target, error.c_str());
            QVERIFY2(m_renderer->render(scene, *target, &error), error.c_str());
            const Image image = target->readPixels();
            for (int y = 0; y < 16; ++y)
                for (int x = 0; x < 16; ++x)
                    for (int i = 0; i < 3; ++i)
                        QVERIFY2(std::isfinite(image.at(x, y)[i]) && image.at(x, y)[i] >= 0.0f,
                            toString(DebugView(view)));
        }
    // SH irradiance of a constant E = pi gives the furnace's irradiance view: E / pi = 1.
    scene.materials[0].material.shading = models[0];
    scene.view.debugView = DebugView::Irradiance;
    const Image image = renderScene(scene);
    for (const SpherePixel& p : interiorPixels(kSize))
        QVERIFY(std::abs(image.at(p.x, p.y).x - 1.0f) < 1e-4f);
}

void RendererDebugViewsGLTest::texelDensityView_data()
{
    // A 256 x 128 base colour map on the unit sphere: at the equator, facing the camera, u runs
    // 256 texels around 2 pi units and v 128 texels over pi units: 256 / (2 pi) = 40.74 texels
    // per unit both ways. The colour at the centre is texelDensityColor of it against the target
    // (t = log2(density / target) / 2, clamped to [-1, 1]), shaded by n.v = 1.
    QTest::addColumn<double>("targetOverDensity");
    QTest::addColumn<float>("scaleFromSource");
    QTest::addColumn<QVector<double>>("expected");
    QTest::newRow("on target: green") << 1.0 << 1.0f << QVector<double> {0.1, 0.8, 0.1};
    QTest::newRow("a quarter of the target: blue") << 4.0 << 1.0f << QVector<double> {0.1, 0.2, 0.9};
    QTest::newRow("half the target: halfway to blue") << 2.0 << 1.0f << QVector<double> {0.1, 0.5, 0.5};
    QTest::newRow("four times the target: red") << 0.25 << 1.0f << QVector<double> {0.9, 0.1, 0.1};
    QTest::newRow("sixteen times: still red") << 1.0 / 16.0 << 1.0f << QVector<double> {0.9, 0.1, 0.1};
    // The mesh was twice this size in its file (world = 0.5 x source): half the texels a source
    // unit, so a target of half the density is on target.
    QTest::newRow("a mesh scaled from its source") << 0.5 << 0.5f << QVector<double> {0.1, 0.8, 0.1};
}

void RendererDebugViewsGLTest::texelDensityView()
{
    QFETCH(double, targetOverDensity);
    QFETCH(float, scaleFromSource);
    QFETCH(QVector<double>, expected);
    TinyIbl ibl {glm::vec3(1.0f)};
    RenderScene scene = referenceScene(ibl);
    Mesh sphere = makeSphere(128, 64);
    sphere.scaleFromSource = scaleFromSource;
    scene.mesh = std::make_shared<const Mesh>(std::move(sphere));
    scene.meshKey = 100 + int(scaleFromSource * 10.0f);
    auto texture = std::make_shared<const MapImage>(
        MapImage::fromImage(Image(256, 128, glm::vec4(0.5f)), MapLayout::Rgb, MapSampleType::UInt8));
    scene.materials[0].material.map(MapSlot::BaseColor).path = "/t/density.png";
    scene.materials[0].maps[std::size_t(MapSlot::BaseColor)] = {texture, "/t/density.png", 7};
    scene.view.debugView = DebugView::TexelDensity;
    const double density = 256.0 / (2.0 * std::numbers::pi);
    scene.view.texelDensityTarget = density * targetOverDensity;
    const Image image = renderScene(scene);
    const glm::dvec3 centre(glm::vec3(image.at(kSize / 2, kSize / 2)));
    const glm::dvec3 wanted(expected[0], expected[1], expected[2]);
    // The sphere's facets and the centre pixel's offset from the exact equator: within 0.04.
    QVERIFY2(glm::length(centre - wanted) < 0.04,
        (facet::test::describe(centre) + " vs " + facet::test::describe(wanted)).c_str());
}

void RendererDebugViewsGLTest::uvCheckerView()
{
    // Each pixel shows the checker of its own texture coordinate (read from the "uv" view),
    // shaded by n.v: 8 x 8 squares per unit, light 0.85 and dark 0.25, tinted by the place in
    // the unit (the CPU formula below is the shader's).
    TinyIbl ibl {glm::vec3(1.0f)};
    RenderScene scene = referenceScene(ibl);
    scene.view.debugView = DebugView::Uv;
    const Image uvs = renderScene(scene);
    scene.view.debugView = DebugView::UvChecker;
    const Image checker = renderScene(scene);
    int light = 0;
    int dark = 0;
    for (const SpherePixel& p : interiorPixels(kSize)) {
        const glm::dvec2 uv(uvs.at(p.x, p.y).r, uvs.at(p.x, p.y).g);
        const glm::dvec2 cell = glm::floor(uv * 8.0);
        const glm::dvec2 inCell = glm::fract(uv * 8.0);
        // Pixels near a square's edge may fall either way (the UV interpolated per fragment).
        if (glm::min(glm::min(inCell.x, inCell.y), glm::min(1.0 - inCell.x, 1.0 - inCell.y)) < 0.05)
            continue;
        const bool isLight = std::fmod(cell.x + cell.y, 2.0) < 0.5;
        (isLight ? light : dark) += 1;
        const glm::dvec2 inUnit = glm::fract(uv);
        const glm::dvec3 expected = (isLight ? 0.85 : 0.25)
            * glm::dvec3(0.55 + 0.45 * inUnit.x, 0.55 + 0.45 * inUnit.y, 0.55)
            * (0.35 + 0.65 * std::max(glm::dot(p.n, p.v), 0.0));
        const glm::dvec3 actual(glm::vec3(checker.at(p.x, p.y)));
        QVERIFY2(glm::length(actual - expected) < 0.02,
            (QStringLiteral("pixel %1, %2: ").arg(p.x).arg(p.y).toStdString() + facet::test::describe(actual)
                + " vs " + facet::test::describe(expected))
                .c_str());
    }
    QVERIFY2(
        light > 50 && dark > 50, qPrintable(QStringLiteral("%1 light, %2 dark pixels").arg(light).arg(dark)));
}

void RendererDebugViewsGLTest::wireframeOverlay()
{
    // View > Wireframe: the sphere's edges drawn over it in kWireframeColor / 2^exposure; the
    // background and the faces between the edges as before; hidden (back) edges stay hidden.
    TinyIbl ibl {glm::vec3(0.2f)};
    RenderScene scene = referenceScene(ibl);
    scene.mesh = std::make_shared<const Mesh>(makeSphere(16, 8)); // facets several pixels wide
    scene.meshKey = 300;
    scene.materials[0].material.setBaseColor(glm::dvec3(0.2));
    const Image plain = renderScene(scene, FramebufferFormat::RGBA32F, 96);
    scene.wireframe = true;
    scene.view.exposureEV = 1.0;
    const Image wired = renderScene(scene, FramebufferFormat::RGBA32F, 96);
    const glm::vec3 line = kWireframeColor * 0.5f;
    int onLines = 0;
    int changedElsewhere = 0;
    int interior = 0;
    for (int y = 0; y < 96; ++y)
        for (int x = 0; x < 96; ++x) {
            const glm::vec3 before(plain.at(x, y));
            const glm::vec3 after(wired.at(x, y));
            if (glm::length(after - before) < 1e-6f)
                continue;
            if (glm::length(after - line) < 1e-4f)
                ++onLines;
            else
                ++changedElsewhere;
        }
    for (const SpherePixel& p : interiorPixels(96))
        interior += p.x >= 0 ? 1 : 0; // every interior pixel
    // The 16 x 8 sphere's edges cover a share of its pixels at this size, far from all of them.
    QVERIFY2(onLines > interior / 20 && onLines < interior / 2,
        qPrintable(QStringLiteral("%1 line pixels of %2").arg(onLines).arg(interior)));
    QCOMPARE(changedElsewhere, 0);
    // The corners are background: untouched.
    QVERIFY(glm::length(glm::vec3(wired.at(0, 0)) - glm::vec3(plain.at(0, 0))) < 1e-6f);
}

QTEST_GUILESS_MAIN(RendererDebugViewsGLTest)
#include "RendererDebugViewsGLTest.moc"
