// render/FrameRenderer: the one path from a project to pixels that the viewport, `facet render`,
// `facet bench` and the tests share. Checked here: an environment used by several views (or
// FrameRenderers sharing one precompute) is precomputed once; the IBL memory cache keeps to its
// byte budget, least recently used out; present() writes exactly its rectangle, at full and
// reduced resolution, with the pixels renderImage() reads back; the target pool stays bounded;
// the cells of one frame with different maps never evict each other's textures (eviction is
// finishFrame()'s), and renderers sharing a texture cache (the views of a window) upload a map
// once, a released decoded copy (a stand-in) drawing from the shared texture.

#include <epoxy/gl.h> // before any header that could pull in <GL/gl.h>

#include "core/image/ImageMetrics.h"
#include "core/project/Project.h"
#include "core/project/ProjectAssets.h"
#include "render/FrameRenderer.h"
#include "render/Framebuffer.h"
#include "render/HeadlessGLContext.h"
#include "render/IblSettings.h"
#include "render/Renderer.h"
#include "render/TextureCache.h"

#include "TestSupport.h"

#include <QTemporaryDir>
#include <QtTest/QTest>

#include <cmath>
#include <memory>
#include <optional>
#include <string>

using namespace facet;

namespace {

// A cheap precompute: the draft preset at tiny sizes (the tests count passes, not quality).
IblSettings tinySettings()
{
    IblSettings settings = *IblSettings::preset("draft");
    settings.cubeSize = 32;
    settings.prefilterSize = 16;
    settings.prefilterMipLevels = 3;
    settings.irradianceSize = 8;
    settings.dfgSize = 16;
    settings.dfgSamples = 64;
    return settings;
}

Project sphereIn(const std::string& environment)
{
    Project project = Project::defaultProject();
    project.environment.source = environment;
    project.view.msaaSamples = 1;
    return project;
}

// The largest and the mean difference of any channel between two equally sized images (RGB).
struct Difference {
    float max = 0.0f;
    double mean = 0.0;
};
Difference difference(const Image& a, const Image& b)
{
    Difference d;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            for (int c = 0; c < 3; ++c) {
                const float e = std::abs(a.at(x, y)[c] - b.at(x, y)[c]);
                d.max = std::max(d.max, e);
                d.mean += e;
            }
    d.mean /= 3.0 * a.width() * a.height();
    return d;
}

// The sphere of sphereIn(environment) with a base colour map of one colour, named `path` (the
// texture cache keys by path and timestamp: no file is read).
struct MappedSphere {
    Project project;
    ProjectAssets assets;
};
std::optional<MappedSphere> mappedSphere(const std::string& path, glm::vec3 colour, std::string* error)
{
    MappedSphere sphere;
    sphere.project = sphereIn("uniform:0.5");
    sphere.project.material().map(MapSlot::BaseColor).path = path;
    sphere.project.material().map(MapSlot::BaseColor).factor = glm::dvec4(1.0);
    Project withoutMap = sphere.project;
    withoutMap.material().map(MapSlot::BaseColor).path.clear();
    auto assets = loadProjectAssets(withoutMap, error);
    if (!assets)
        return std::nullopt;
    sphere.assets = std::move(*assets);
    Image pixels(8, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            pixels.at(x, y) = glm::vec4(colour, 1.0f);
    LoadedMapImage& map = sphere.assets.maps.at(0)[std::size_t(MapSlot::BaseColor)];
    map.image
        = std::make_shared<const MapImage>(MapImage::fromImage(pixels, MapLayout::Rgb, MapSampleType::UInt8));
    map.path = path;
    map.timestamp = 1;
    return sphere;
}

} // namespace

class FrameRendererGLTest : public QObject {
    Q_OBJECT
public:
    static void initMain() { facet::test::forgetDisplayServer(); }

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void environmentSharedByViewsIsPrecomputedOnce();
    void memoryCacheKeepsItsBudget_data();
    void memoryCacheKeepsItsBudget();
    void iblBytesOfThePresets_data();
    void iblBytesOfThePresets();
    void presentWritesItsRectangle_data();
    void presentWritesItsRectangle();
    void targetPoolIsBounded();
    void coverageAlphaIsTheObject_data();
    void coverageAlphaIsTheObject();
    void texturesOfEveryCellStayUntilTheFrameEnds();
    void renderersSharingTexturesUploadOnce();
    void seamlessCubeFilteringInTheDrawingContext();

private:
    std::optional<HeadlessGLContext> m_context;
    QTemporaryDir m_cacheDir;
};

void FrameRendererGLTest::initTestCase()
{
    std::string error;
    m_context = HeadlessGLContext::create(&error);
    QVERIFY2(m_context, error.c_str());
    QVERIFY(m_cacheDir.isValid());
}

void FrameRendererGLTest::cleanupTestCase()
{
    m_context.reset();
}

void FrameRendererGLTest::environmentSharedByViewsIsPrecomputedOnce()
{
    // Four views of one environment (one precompute shared by their FrameRenderers, as the
    // cells of a grid share one), then a fifth with another environment.
    auto precompute = std::make_shared<IblPrecompute>(m_cacheDir.path(), /*useDiskCache=*/false);
    const IblSettings settings = tinySettings();
    std::string error;
    const Project project = sphereIn("uniform:0.5");
    const auto assets = loadProjectAssets(project, &error);
    QVERIFY2(assets, error.c_str());
    int passes = 0;
    int memoryHits = 0;
    QVERIFY(!precompute->holds(assets->environment, settings));
    for (int view = 0; view < 4; ++view) {
        FrameRenderer frames(precompute);
        IblStats stats;
        const auto scene
            = frames.prepare(project, *assets, settings, sceneOptionsFor(settings, true), &stats, &error);
        QVERIFY2(scene, error.c_str());
        QVERIFY(scene->environment.prefilteredCubemap != 0);
        QVERIFY(scene->environment.dfgLutFor(project.material().shading.visibility));
        passes += stats.passesRun;
        memoryHits += stats.cacheHitsMemory;
    }
    // equirect->cube, prefilter, irradiance and one DFG table, once; three memory hits.
    QCOMPARE(passes, 4);
    QCOMPARE(memoryHits, 3);
    QVERIFY(precompute->holds(assets->environment, settings)); // a fifth view would draw at once
    QCOMPARE(int(precompute->memoryEntries()), 1);

    const Project other = sphereIn("uniform:0.25");
    const auto otherAssets = loadProjectAssets(other, &error);
    QVERIFY2(otherAssets, error.c_str());
    FrameRenderer frames(precompute);
    IblStats stats;
    QVERIFY2(frames.prepare(other, *otherAssets, settings, sceneOptionsFor(settings, true), &stats, &error),
        error.c_str());
    QCOMPARE(stats.passesRun, 3); // the new environment's three passes; the DFG table is shared
    QCOMPARE(int(precompute->memoryEntries()), 2);
}

void FrameRendererGLTest::memoryCacheKeepsItsBudget_data()
{
    QTest::addColumn<int>("budgetSets"); // the budget in IBL sets of this size
    QTest::addColumn<int>("environments"); // prepared in turn: uniform:0.1, 0.2, ...
    QTest::addColumn<int>("expectedEntries");
    QTest::addColumn<bool>("firstStillCached");
    QTest::newRow("room for all") << 9 << 9 << 9 << true;
    QTest::newRow("room for four of nine") << 4 << 9 << 4 << false;
    QTest::newRow("room for none: the newest stays") << 0 << 3 << 1 << false;
    QTest::newRow("first used again stays") << 3 << 5 << 3 << true;
}

void FrameRendererGLTest::memoryCacheKeepsItsBudget()
{
    QFETCH(int, budgetSets);
    QFETCH(int, environments);
    QFETCH(int, expectedEntries);
    QFETCH(bool, firstStillCached);
    IblPrecompute precompute(m_cacheDir.path(), /*useDiskCache=*/false);
    const IblSettings settings = tinySettings();
    std::string error;
    const auto environmentOf = [](int i) {
        std::string message;
        return *Environment::fromSpec("uniform:" + std::to_string(0.1 * (i + 1)), &message);
    };
    const Environment first = environmentOf(0);
    const auto firstSet = precompute.prepare(first, settings, nullptr, &error);
    QVERIFY2(firstSet, error.c_str());
    const std::size_t setBytes = firstSet->bytes();
    QVERIFY(setBytes > 0);
    precompute.setMemoryBudget(std::size_t(budgetSets) * setBytes);
    const bool touchFirst = QByteArray(QTest::currentDataTag()) == "first used again stays";
    for (int i = 1; i < environments; ++i) {
        QVERIFY2(precompute.prepare(environmentOf(i), settings, nullptr, &error), error.c_str());
        if (touchFirst)
            QVERIFY(precompute.prepare(first, settings, nullptr, &error)); // most recently used again
    }
    QCOMPARE(int(precompute.memoryEntries()), expectedEntries);
    QVERIFY(precompute.memoryBytes() <= std::max<std::size_t>(std::size_t(budgetSets) * setBytes, setBytes));
    IblStats stats;
    QVERIFY2(precompute.prepare(first, settings, &stats, &error), error.c_str());
    QCOMPARE(stats.cacheHitsMemory == 1, firstStillCached);
}

void FrameRendererGLTest::iblBytesOfThePresets_data()
{
    // The figures docs/ibl.md and IblPrecompute::kMemoryBudgetBytes quote, for a 2K equirect.
    QTest::addColumn<QString>("preset");
    QTest::addColumn<double>("megabytes");
    QTest::newRow("draft") << "draft" << 1.33;
    QTest::newRow("default") << "default" << 5.33;
    QTest::newRow("high") << "high" << 21.3;
}

void FrameRendererGLTest::iblBytesOfThePresets()
{
    QFETCH(QString, preset);
    QFETCH(double, megabytes);
    const IblSettings settings = IblSettings::preset(preset.toStdString())->forImage(2048);
    IblTextures textures;
    textures.environmentSize = settings.cubeSize;
    textures.environmentMipLevels = int(std::floor(std::log2(settings.cubeSize))) + 1;
    textures.prefilteredSize = settings.prefilterSize;
    textures.prefilteredMipLevels = settings.prefilterMipLevels;
    textures.irradianceSize = settings.irradianceSize;
    QVERIFY2(std::abs(double(textures.bytes()) / 1e6 - megabytes) < 0.05 * megabytes,
        qPrintable(QString::number(double(textures.bytes()) / 1e6) + QStringLiteral(" MB")));
}

void FrameRendererGLTest::presentWritesItsRectangle_data()
{
    QTest::addColumn<int>("x");
    QTest::addColumn<int>("y");
    QTest::addColumn<int>("width");
    QTest::addColumn<int>("height");
    QTest::addColumn<double>("scale");
    QTest::newRow("whole, full resolution") << 0 << 0 << 96 << 64 << 1.0;
    QTest::newRow("cell, full resolution") << 32 << 16 << 48 << 40 << 1.0;
    QTest::newRow("whole, half resolution") << 0 << 0 << 96 << 64 << 0.5;
    QTest::newRow("cell, half resolution") << 40 << 8 << 48 << 48 << 0.5;
    QTest::newRow("corner cell") << 64 << 32 << 32 << 32 << 1.0;
}

void FrameRendererGLTest::presentWritesItsRectangle()
{
    QFETCH(int, x);
    QFETCH(int, y);
    QFETCH(int, width);
    QFETCH(int, height);
    QFETCH(double, scale);
    constexpr int kWidth = 96;
    constexpr int kHeight = 64;
    FrameRenderer frames(m_cacheDir.path(), /*useDiskCache=*/false);
    const IblSettings settings = tinySettings();
    std::string error;
    const Project project = sphereIn("uniform:0.5");
    const auto assets = loadProjectAssets(project, &error);
    QVERIFY2(assets, error.c_str());
    const auto scene
        = frames.prepare(project, *assets, settings, sceneOptionsFor(settings, false), nullptr, &error);
    QVERIFY2(scene, error.c_str());

    // The caller's framebuffer, filled with a colour no frame has.
    auto target = Framebuffer::create(kWidth, kHeight, FramebufferFormat::RGBA16F, &error);
    QVERIFY2(target, error.c_str());
    const glm::vec4 marker(-1.0f, 2.0f, -3.0f, 1.0f);
    target->clear(marker);
    QVERIFY2(frames.present(*scene, target->framebufferId(), FrameRect {x, y, width, height}, scale, &error),
        error.c_str());
    QCOMPARE(frames.lastRenderWidth(), int(std::lround(width * scale)));
    QCOMPARE(frames.lastRenderHeight(), int(std::lround(height * scale)));
    const Image written = target->readPixels();

    // Outside the rectangle: untouched. Inside: the display image renderImage() gives at the
    // rectangle's size (exactly at full resolution; at half, its bilinear stretch is close).
    const auto expected = frames.renderImage(*scene, width, height, FrameOutput::DisplayReferred, &error);
    QVERIFY2(expected, error.c_str());
    Image cell(width, height);
    for (int row = 0; row < kHeight; ++row)
        for (int column = 0; column < kWidth; ++column) {
            const int glRow = kHeight - 1 - row; // readPixels is top row first
            const bool inside = column >= x && column < x + width && glRow >= y && glRow < y + height;
            if (!inside) {
                if (written.at(column, row) != marker)
                    QFAIL(qPrintable(QStringLiteral("pixel (%1, %2) outside the rectangle was written")
                                         .arg(column)
                                         .arg(row)));
                continue;
            }
            cell.at(column - x, (height - 1) - (glRow - y)) = written.at(column, row);
        }
    const Difference d = difference(cell, *expected);
    if (scale >= 1.0) {
        QCOMPARE(d.max, 0.0f);
    } else {
        // A stretched half-size image: its silhouette is blurred, the rest close.
        QVERIFY2(d.mean < 0.02, qPrintable(QString::number(d.mean)));
        QVERIFY2(d.mean > 0.0, "a reduced frame cannot equal the full one exactly");
    }
}

void FrameRendererGLTest::targetPoolIsBounded()
{
    FrameRenderer frames(m_cacheDir.path(), /*useDiskCache=*/false);
    const IblSettings settings = tinySettings();
    std::string error;
    const Project project = sphereIn("uniform:0.5");
    const auto assets = loadProjectAssets(project, &error);
    QVERIFY2(assets, error.c_str());
    const auto scene
        = frames.prepare(project, *assets, settings, sceneOptionsFor(settings, false), nullptr, &error);
    QVERIFY2(scene, error.c_str());
    // A window resized step by step: every size once.
    for (int size = 8; size < 40; size += 4) {
        QVERIFY2(frames.renderImage(*scene, size, size, FrameOutput::DisplayReferred, &error), error.c_str());
        QVERIFY(frames.pooledTargets() <= FrameRenderer::kPooledTargets);
    }
    QCOMPARE(frames.pooledTargets(), FrameRenderer::kPooledTargets);
}

void FrameRendererGLTest::coverageAlphaIsTheObject_data()
{
    QTest::addColumn<QString>("background");
    QTest::addColumn<int>("msaa");
    QTest::newRow("environment") << QStringLiteral("environment") << 1;
    QTest::newRow("blurred") << QStringLiteral("blurred") << 1;
    QTest::newRow("colour") << QStringLiteral("color") << 1;
    QTest::newRow("environment, 4x MSAA") << QStringLiteral("environment") << 4;
}

// RenderScene::coverageAlpha: the background writes alpha 0 and the sphere 1 (fractions only
// at an MSAA-resolved silhouette); the radiance is the same with and without it. The error view's
// mask (core/image/ImageMetrics objectMask) is made from it.
void FrameRendererGLTest::coverageAlphaIsTheObject()
{
    QFETCH(QString, background);
    QFETCH(int, msaa);
    FrameRenderer frames(m_cacheDir.path(), /*useDiskCache=*/false);
    const IblSettings settings = tinySettings();
    std::string error;
    Project project = sphereIn("uniform:0.5");
    project.view.background = *backgroundModeFromString(background.toStdString());
    project.view.msaaSamples = msaa;
    const auto assets = loadProjectAssets(project, &error);
    QVERIFY2(assets, error.c_str());
    auto scene
        = frames.prepare(project, *assets, settings, sceneOptionsFor(settings, false), nullptr, &error);
    QVERIFY2(scene, error.c_str());
    constexpr int kSize = 48;
    const auto plain = frames.renderImage(
        *scene, kSize, kSize, FrameOutput::LinearRadiance, &error, FramebufferFormat::RGBA32F);
    QVERIFY2(plain, error.c_str());
    scene->coverageAlpha = true;
    const auto covered = frames.renderImage(
        *scene, kSize, kSize, FrameOutput::LinearRadiance, &error, FramebufferFormat::RGBA32F);
    QVERIFY2(covered, error.c_str());
    QCOMPARE(difference(*plain, *covered).max, 0.0f);
    int object = 0;
    int partial = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            QCOMPARE(plain->at(x, y).a, 1.0f);
            const float alpha = covered->at(x, y).a;
            QVERIFY(alpha >= 0.0f && alpha <= 1.0f);
            object += alpha == 1.0f ? 1 : 0;
            partial += alpha > 0.0f && alpha < 1.0f ? 1 : 0;
        }
    QCOMPARE(covered->at(0, 0).a, 0.0f); // the corners are background
    QCOMPARE(covered->at(kSize - 1, kSize - 1).a, 0.0f);
    QCOMPARE(covered->at(kSize / 2, kSize / 2).a, 1.0f); // the centre the sphere
    // The default camera frames the unit sphere: a disc of a good part of the image.
    QVERIFY2(
        object > kSize * kSize / 8 && object < kSize * kSize * 3 / 4, qPrintable(QString::number(object)));
    QCOMPARE(partial > 0, msaa > 1);
    const PixelMask mask = objectMask(*covered);
    const auto marked = std::count(mask.begin(), mask.end(), std::uint8_t(1));
    QVERIFY(marked > 0 && marked < object);
}

void FrameRendererGLTest::texturesOfEveryCellStayUntilTheFrameEnds()
{
    // Two cells of one frame (A/B) showing materials with different maps: drawing B must not
    // evict A's texture, or every frame would upload both again.
    FrameRenderer frames(m_cacheDir.path(), /*useDiskCache=*/false);
    const IblSettings settings = tinySettings();
    std::string error;
    const auto a = mappedSphere("a.png", {0.9f, 0.1f, 0.1f}, &error);
    const auto b = mappedSphere("b.png", {0.1f, 0.1f, 0.9f}, &error);
    QVERIFY2(a && b, error.c_str());
    const auto sceneA
        = frames.prepare(a->project, a->assets, settings, sceneOptionsFor(settings, false), nullptr, &error);
    const auto sceneB
        = frames.prepare(b->project, b->assets, settings, sceneOptionsFor(settings, false), nullptr, &error);
    QVERIFY2(sceneA && sceneB, error.c_str());
    const auto uploadsOf = [&](const RenderScene& scene) {
        std::string problem;
        const bool drawn
            = frames.renderImage(scene, 16, 16, FrameOutput::LinearRadiance, &problem).has_value();
        return drawn ? frames.renderer().lastFrameStats().texturesUploaded : -1;
    };
    // Frame 1 uploads each map once; frame 2 uploads nothing.
    QCOMPARE(uploadsOf(*sceneA), 1);
    QCOMPARE(uploadsOf(*sceneB), 1);
    frames.finishFrame();
    QCOMPARE(uploadsOf(*sceneA), 0);
    QCOMPARE(uploadsOf(*sceneB), 0);
    frames.finishFrame();
    QCOMPARE(int(frames.textureCache().size()), 2);
    // A frame showing A alone: B's texture goes when it ends, not before.
    QCOMPARE(uploadsOf(*sceneA), 0);
    QCOMPARE(int(frames.textureCache().size()), 2);
    frames.finishFrame();
    QCOMPARE(int(frames.textureCache().size()), 1);
    QVERIFY(frames.textureCache().isReady("a.png", 1, ColorEncoding::SRGB));
    QVERIFY(!frames.textureCache().isReady("b.png", 1, ColorEncoding::SRGB));
}

void FrameRendererGLTest::renderersSharingTexturesUploadOnce()
{
    // The single view and the Compare view: two FrameRenderers sharing the IBL precompute and the
    // texture cache (ui/viewport/ViewShareGroup; one context here, a share group in the window).
    auto precompute = std::make_shared<IblPrecompute>(m_cacheDir.path(), /*useDiskCache=*/false);
    auto textures = std::make_shared<TextureCache>();
    FrameRenderer single(precompute, textures);
    FrameRenderer compare(precompute, textures);
    QCOMPARE(compare.sharedTextureCache(), single.sharedTextureCache());
    const IblSettings settings = tinySettings();
    std::string error;
    auto sphere = mappedSphere("red.png", {0.9f, 0.1f, 0.1f}, &error);
    QVERIFY2(sphere, error.c_str());
    const auto scene = single.prepare(
        sphere->project, sphere->assets, settings, sceneOptionsFor(settings, false), nullptr, &error);
    QVERIFY2(scene, error.c_str());
    const auto drawn = single.renderImage(*scene, 32, 32, FrameOutput::LinearRadiance, &error);
    QVERIFY2(drawn, error.c_str());
    QCOMPARE(single.renderer().lastFrameStats().texturesUploaded, 1);

    // The other view draws the same map from the texture the first one uploaded, even from a
    // stand-in without pixels (the window released the decoded copy), with the same pixels.
    LoadedMapImage& map = sphere->assets.maps[0][std::size_t(MapSlot::BaseColor)];
    map.image = std::make_shared<const MapImage>(MapImage::withoutPixels(*map.image));
    IblStats stats;
    const auto standIn = compare.prepare(
        sphere->project, sphere->assets, settings, sceneOptionsFor(settings, false), &stats, &error);
    QVERIFY2(standIn, error.c_str());
    QCOMPARE(stats.passesRun, 0); // the IBL set and the DFG table are the first view's
    const auto again = compare.renderImage(*standIn, 32, 32, FrameOutput::LinearRadiance, &error);
    QVERIFY2(again, error.c_str());
    QCOMPARE(compare.renderer().lastFrameStats().texturesUploaded, 0);
    const Difference d = difference(*drawn, *again);
    QCOMPARE(d.max, 0.0f);
    // And the map is drawn: the centre is red.
    const glm::vec4 centre = again->at(16, 16);
    QVERIFY2(centre.r > 3.0f * centre.g && centre.r > 3.0f * centre.b,
        qPrintable(QStringLiteral("centre (%1, %2, %3)").arg(centre.r).arg(centre.g).arg(centre.b)));
}

void FrameRendererGLTest::seamlessCubeFilteringInTheDrawingContext()
{
    // GL_TEXTURE_CUBE_MAP_SEAMLESS is per context. A view drawing with IBL sets another view's
    // context computed (memory hits: no pass runs here) must still filter across cube faces.
    auto precompute = std::make_shared<IblPrecompute>(m_cacheDir.path(), /*useDiskCache=*/false);
    const IblSettings settings = tinySettings();
    std::string error;
    const Project project = sphereIn("uniform:0.375");
    const auto assets = loadProjectAssets(project, &error);
    QVERIFY2(assets, error.c_str());
    FrameRenderer first(precompute);
    QVERIFY2(first.prepare(project, *assets, settings, sceneOptionsFor(settings, true), nullptr, &error),
        error.c_str());
    glDisable(GL_TEXTURE_CUBE_MAP_SEAMLESS); // as a fresh context of the share group has it
    FrameRenderer second(precompute);
    IblStats stats;
    const auto scene
        = second.prepare(project, *assets, settings, sceneOptionsFor(settings, true), &stats, &error);
    QVERIFY2(scene, error.c_str());
    QCOMPARE(stats.passesRun, 0);
    QVERIFY(!glIsEnabled(GL_TEXTURE_CUBE_MAP_SEAMLESS));
    QVERIFY2(second.renderImage(*scene, 16, 16, FrameOutput::LinearRadiance, &error), error.c_str());
    QVERIFY(glIsEnabled(GL_TEXTURE_CUBE_MAP_SEAMLESS));
}

QTEST_GUILESS_MAIN(FrameRendererGLTest)
#include "FrameRendererGLTest.moc"
