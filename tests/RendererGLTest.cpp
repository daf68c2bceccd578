// The surface renderer on a headless context (llvmpipe: small images, 48-64 px): the GPU against
// its CPU twins (split sum, tone mapping, punctual lights), the white furnace, stability, the DFG
// table each material's visibility term needs, and the counters that show skipped work. Debug
// views, every feature's variant and the wireframe: RendererDebugViewsGLTest.
//
// The IBL here is built by hand (support/RendererTestScene.h): with a UNIFORM environment of
// radiance L the prefiltered map is L at every level and the irradiance is pi L, exactly, so the
// split sum's inputs carry no error of their own and the comparison isolates the shader.

#include <epoxy/gl.h>

#include "core/image/MapImage.h"
#include "core/image/ToneMap.h"
#include "core/shading/Brdf.h"
#include "core/shading/DfgTable.h"
#include "core/shading/MaterialBrdf.h"
#include "core/shading/Punctual.h"
#include "core/shading/SplitSum.h"
#include "render/DfgLut.h"
#include "render/Framebuffer.h"
#include "render/HeadlessGLContext.h"
#include "render/Renderer.h"
#include "render/ShaderVariant.h"

#include "RendererTestScene.h"
#include "TestSupport.h"

#include <QScopeGuard>
#include <QtTest/QTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

using namespace facet;
using facet::test::dfgTable;
using facet::test::interiorPixels;
using facet::test::kSize;
using facet::test::referenceScene;
using facet::test::SpherePixel;
using facet::test::TinyIbl;

namespace {

MaterialInfo materialInfo(const Material& material)
{
    MaterialInfo info;
    info.baseColor = glm::dvec3(material.baseColorFactor());
    info.metallic = material.metallic();
    info.perceptualRoughness = material.roughness();
    info.ior = material.ior;
    return info;
}

} // namespace

class RendererGLTest : public QObject, public facet::test::RendererGLFixture {
    Q_OBJECT
public:
    static void initMain() { facet::test::forgetDisplayServer(); }

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void toneMappingMatchesCpu();
    void whiteFurnaceMetal();
    void whiteFurnaceDebugView();
    void splitSumMatchesCpu_data();
    void splitSumMatchesCpu();
    void missingDfgTableIsRefused_data();
    void missingDfgTableIsRefused();
    void dfgTableIsFiledUnderItsVisibility();
    void directLightMatchesCpu();
    void extremesStayFinite();
    void skippedWorkIsCounted();
    void mapsBeyondTheTextureUnitsAreLeftOut_data();
    void mapsBeyondTheTextureUnitsAreLeftOut();
};

void RendererGLTest::initTestCase()
{
    initRendererFixture();
}

void RendererGLTest::cleanupTestCase()
{
    cleanupRendererFixture();
}

void RendererGLTest::toneMappingMatchesCpu()
{
    const int width = 64;
    const int height = 4;
    std::string error;
    std::optional<Framebuffer> hdr = Framebuffer::create(width, height, FramebufferFormat::RGBA32F, &error);
    QVERIFY2(hdr, error.c_str());
    std::optional<Framebuffer> display
        = Framebuffer::create(width, height, FramebufferFormat::RGBA32F, &error);
    QVERIFY2(display, error.c_str());
    // A gradient from 1e-4 to 1e4 (log spaced); rows tint it differently to exercise hue handling.
    std::vector<glm::vec4> pixels(std::size_t(width * height));
    const glm::vec3 tints[height]
        = {{1.0f, 1.0f, 1.0f}, {1.0f, 0.5f, 0.25f}, {0.1f, 0.6f, 1.0f}, {0.0f, 1.0f, 0.0f}};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float value = std::pow(10.0f, -4.0f + 8.0f * float(x) / float(width - 1));
            pixels[std::size_t(y * width + x)] = glm::vec4(tints[y] * value, 1.0f);
        }
    glBindTexture(GL_TEXTURE_2D, hdr->colorTexture());
    glTexSubImage2D(
        GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, pixels.data()); // GL rows: bottom-up
    glBindTexture(GL_TEXTURE_2D, 0);

    for (ToneMapper mapper : {ToneMapper::None, ToneMapper::Reinhard, ToneMapper::Exposure, ToneMapper::Aces,
             ToneMapper::KhronosNeutral, ToneMapper::AgX}) {
        for (DisplayEncoding encoding : {DisplayEncoding::SRGB, DisplayEncoding::Gamma}) {
            ViewSettings view;
            view.toneMapper = mapper;
            view.displayEncoding = encoding;
            view.gamma = 2.4;
            view.exposureEV = 0.5;
            QVERIFY2(m_renderer->toneMap(*hdr, *display, view, &error), error.c_str());
            const Image out = display->readPixels();
            double worst = 0.0;
            for (int y = 0; y < height; ++y)
                for (int x = 0; x < width; ++x) {
                    const glm::dvec3 in(glm::vec3(pixels[std::size_t((height - 1 - y) * width + x)]));
                    const glm::dvec3 expected = tonemap::displayTransform(in, view);
                    const glm::dvec3 actual(glm::vec3(out.at(x, y)));
                    worst = std::max(worst, glm::length(actual - expected));
                }
            // Float against double through pow/log2/exp: 1e-3 of the display range, far below one
            // 8-bit step (3.9e-3).
            QVERIFY2(worst < 1e-3,
                (std::string(toString(mapper)) + ": worst difference " + std::to_string(worst)).c_str());
        }
    }
}

void RendererGLTest::whiteFurnaceMetal()
{
    // A white metal with multi-scatter compensation reflects everything: (scale + bias) M(1) = 1.
    TinyIbl ibl {glm::vec3(1.0f)};
    RenderScene scene = referenceScene(ibl);
    scene.materials[0].material.setBaseColor(glm::dvec3(1.0));
    scene.materials[0].material.setFactor(MapSlot::Metallic, 1.0);
    const std::vector<SpherePixel> pixels = interiorPixels(kSize);
    QVERIFY(pixels.size() > 500);
    for (double roughness : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        scene.materials[0].material.setFactor(MapSlot::Roughness, roughness);
        const Image image = renderScene(scene);
        double worst = 0.0;
        for (const SpherePixel& p : pixels)
            worst = std::max(worst, double(glm::length(glm::vec3(image.at(p.x, p.y)) - glm::vec3(1.0f))));
        // 1%: the furnace bound of docs/architecture.md (measured: float rounding only, ~1e-6).
        QVERIFY2(worst < 0.01,
            ("roughness " + std::to_string(roughness) + ": worst " + std::to_string(worst)).c_str());
    }
}

void RendererGLTest::whiteFurnaceDebugView()
{
    // The white-furnace view replaces the environment by radiance 1 and the base colour by white:
    // with the energy-preserving coupling a white dielectric is exactly 1 as well (E_s + 1 - E_s).
    TinyIbl ibl {glm::vec3(0.3f, 2.0f, 7.0f)};
    RenderScene scene = referenceScene(ibl);
    scene.view.debugView = DebugView::WhiteFurnace;
    scene.materials[0].material.setBaseColor(glm::dvec3(0.2, 0.4, 0.1));
    scene.materials[0].material.shading.coupling = DielectricCoupling::EnergyPreserving;
    const std::vector<SpherePixel> pixels = interiorPixels(kSize);
    for (double metallic : {0.0, 1.0})
        for (double roughness : {0.1, 0.6}) {
            scene.materials[0].material.setFactor(MapSlot::Metallic, metallic);
            scene.materials[0].material.setFactor(MapSlot::Roughness, roughness);
            const Image image = renderScene(scene);
            double worst = 0.0;
            for (const SpherePixel& p : pixels)
                worst = std::max(worst, double(glm::length(glm::vec3(image.at(p.x, p.y)) - glm::vec3(1.0f))));
            QVERIFY2(worst < 0.01,
                ("metallic " + std::to_string(metallic) + " roughness " + std::to_string(roughness)
                    + ": worst " + std::to_string(worst))
                    .c_str());
        }
}

void RendererGLTest::splitSumMatchesCpu_data()
{
    QTest::addColumn<int>("model");
    QTest::addColumn<double>("metallic");
    QTest::addColumn<double>("roughness");
    // Models: 0 glTF fresnel_mix, 1 glTF energy-preserving, 2 LearnOpenGL (Schlick-GGX V),
    // 3 glTF with the uncorrelated Smith V. The scene holds every V's table: each model must
    // read its own (another V's is off by more than the bound at grazing n.v).
    for (int model : {0, 1, 2, 3})
        for (double metallic : {0.0, 1.0})
            for (double roughness : {0.05, 0.5, 1.0})
                QTest::addRow("model%d-m%.0f-r%.2f", model, metallic, roughness)
                    << model << metallic << roughness;
}

void RendererGLTest::splitSumMatchesCpu()
{
    QFETCH(int, model);
    QFETCH(double, metallic);
    QFETCH(double, roughness);
    ShadingModel shading; // 0: glTF fresnel_mix
    if (model == 1)
        shading.coupling = DielectricCoupling::EnergyPreserving;
    if (model == 2)
        shading = ShadingModel::learnOpenGL();
    if (model == 3)
        shading.visibility = Visibility::SmithGGXUncorrelated;
    const DfgTable& table = dfgTable(shading.visibility);
    const glm::vec3 L(0.8f, 1.0f, 1.3f);
    TinyIbl ibl {L};
    RenderScene scene = referenceScene(ibl);
    scene.environment.intensity = 1.5;
    scene.materials[0].material.shading = shading;
    scene.materials[0].material.setBaseColor(glm::dvec3(0.9, 0.5, 0.2));
    scene.materials[0].material.setFactor(MapSlot::Metallic, metallic);
    scene.materials[0].material.setFactor(MapSlot::Roughness, roughness);
    const MaterialBrdf brdf(shading, table);
    const MaterialInfo info = materialInfo(scene.materials[0].material);
    scene.materials[0].couplingAlbedos.dielectric = brdf.dielectricSpecularAverageAlbedo(f0FromIor(info.ior), roughness);
    const Image image = renderScene(scene);
    SplitSumLighting lighting;
    lighting.prefilteredRadiance = glm::dvec3(L) * 1.5;
    lighting.irradiance = glm::dvec3(L) * shading::kPi * 1.5;
    double worst = 0.0;
    std::string where;
    for (const SpherePixel& p : interiorPixels(kSize)) {
        const glm::dvec3 expected = splitSumRadiance(brdf, table, info, glm::dot(p.n, p.v), lighting).total();
        const glm::dvec3 actual(glm::vec3(image.at(p.x, p.y)));
        const double error = glm::length(actual - expected) / std::max(glm::length(expected), 1e-3);
        if (error > worst) {
            worst = error;
            where = "pixel " + std::to_string(p.x) + "," + std::to_string(p.y) + ": "
                + facet::test::describe(actual) + " vs " + facet::test::describe(expected);
        }
    }
    // 1%: the tessellated sphere's interpolated normal differs from the analytic one by ~1e-3 rad
    // (128 x 64 segments), which moves n.v, and the table changes fastest at grazing n.v.
    QVERIFY2(worst < 0.01, ("relative error " + std::to_string(worst) + " at " + where).c_str());
}

void RendererGLTest::missingDfgTableIsRefused_data()
{
    QTest::addColumn<int>("visibility");
    for (Visibility visibility : kAllVisibilities)
        QTest::addRow("%s", toString(visibility)) << int(visibility);
}

void RendererGLTest::missingDfgTableIsRefused()
{
    // A material whose visibility term has no table in the scene is refused, even when the
    // other variants' tables are there: no frame is drawn with a stand-in table.
    QFETCH(int, visibility);
    const Visibility own = Visibility(visibility);
    TinyIbl ibl {glm::vec3(1.0f)};
    RenderScene scene = referenceScene(ibl);
    scene.materials[0].material.shading.visibility = own;
    scene.environment.setDfgLut(own, 0, 0);
    std::string error;
    std::optional<Framebuffer> target = Framebuffer::create(16, 16, FramebufferFormat::RGBA32F, &error);
    QVERIFY2(target, error.c_str());
    target->bind();
    glViewport(0, 0, 16, 16);
    glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    QVERIFY(!m_renderer->render(scene, *target, &error));
    QCOMPARE(error,
        std::string("Renderer::render: the scene has no split-sum DFG table for the visibility term '")
            + toString(own) + "' of its material (FrameRenderer::prepare adds them)");
    const Image untouched = target->readPixels();
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            QVERIFY(untouched.at(x, y) == glm::vec4(0.25f, 0.5f, 0.75f, 1.0f)); // nothing drawn

    // Its own table alone is enough.
    EnvironmentLighting only = ibl.lighting();
    for (Visibility other : kAllVisibilities)
        if (other != own)
            only.setDfgLut(other, 0, 0);
    scene.environment = only;
    QVERIFY2(m_renderer->render(scene, *target, &error), error.c_str());
    QVERIFY(target->readPixels().at(8, 8) != glm::vec4(0.25f, 0.5f, 0.75f, 1.0f));

    // Nothing to shade, nothing needed: a background-only frame renders without any table.
    scene.mesh.reset();
    scene.environment.setDfgLut(own, 0, 0);
    QVERIFY(dfgVisibilitiesFor(scene).empty());
    QVERIFY2(m_renderer->render(scene, *target, &error), error.c_str());
}

void RendererGLTest::dfgTableIsFiledUnderItsVisibility()
{
    // A table from IblPrecompute carries its V, and setDfgLut files it there and nowhere else.
    auto table = std::make_shared<DfgLut>();
    table->texture = std::make_shared<GLTexture>(GLTexture::create(GL_TEXTURE_2D));
    table->size = 8;
    table->visibility = Visibility::SchlickGGX;
    EnvironmentLighting lighting;
    lighting.setDfgLut(table);
    for (Visibility visibility : kAllVisibilities) {
        const DfgLutBinding* binding = lighting.dfgLutFor(visibility);
        if (visibility == Visibility::SchlickGGX) {
            QVERIFY(binding);
            QCOMPARE(binding->texture, table->id());
            QCOMPARE(binding->size, 8);
            QCOMPARE(lighting.dfgTables[std::size_t(visibility)].get(), table.get()); // kept alive
        } else {
            QVERIFY2(!binding, toString(visibility));
        }
    }
}

void RendererGLTest::directLightMatchesCpu()
{
    // Black environment, one directional and one point light: the GPU against MaterialBrdf.
    const DfgTable& table = dfgTable(Visibility::SmithGGXCorrelated);
    TinyIbl ibl {glm::vec3(0.0f)};
    RenderScene scene = referenceScene(ibl);
    scene.materials[0].material.setBaseColor(glm::dvec3(0.7, 0.3, 0.2));
    scene.materials[0].material.setFactor(MapSlot::Roughness, 0.4);
    scene.materials[0].material.setFactor(MapSlot::Metallic, 0.3);
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::dvec3(-0.3, -0.5, -1.0);
    sun.intensity = 2.0;
    Light lamp;
    lamp.type = LightType::Point;
    lamp.position = glm::dvec3(1.5, 1.0, 2.0);
    lamp.intensity = 5.0;
    lamp.color = glm::dvec3(1.0, 0.8, 0.6);
    lamp.range = 6.0;
    scene.lights = {sun, lamp};
    const Image image = renderScene(scene);
    const MaterialBrdf brdf(scene.materials[0].material.shading, table);
    const MaterialInfo info = materialInfo(scene.materials[0].material);
    double worst = 0.0;
    std::string where;
    for (const SpherePixel& p : interiorPixels(kSize)) {
        glm::dvec3 expected(0.0);
        for (const Light& light : scene.lights) {
            glm::dvec3 l;
            glm::dvec3 irradiance = light.linearColor() * light.intensity;
            if (light.type == LightType::Directional) {
                l = -glm::normalize(light.direction);
            } else {
                const glm::dvec3 toLight = light.position - p.n;
                l = glm::normalize(toLight);
                irradiance *= shading::getRangeAttenuation(light.range, glm::length(toLight));
            }
            const double NoL = glm::dot(p.n, l);
            if (NoL > 0.0)
                expected
                    += brdf.evaluate(info, p.n, p.v, l, LightingKind::Punctual).total() * irradiance * NoL;
        }
        const glm::dvec3 actual(glm::vec3(image.at(p.x, p.y)));
        const double error = glm::length(actual - expected) / std::max(glm::length(expected), 0.02);
        if (error > worst) {
            worst = error;
            where = "pixel " + std::to_string(p.x) + "," + std::to_string(p.y) + ": "
                + facet::test::describe(actual) + " vs " + facet::test::describe(expected);
        }
    }
    // 3%: highlights are sharp in the normal, and the tessellated normal is off by ~1e-3 rad.
    QVERIFY2(worst < 0.03, ("relative error " + std::to_string(worst) + " at " + where).c_str());
}

void RendererGLTest::extremesStayFinite()
{
    // Roughness 0 and 1, metallic 0 and 1, radiance 1e-6 and 1e6, with a light: every pixel finite
    // and non-negative, in both target formats (RGBA16F saturates at 65504 instead of +Inf).
    for (float radiance : {1e-6f, 1e6f}) {
        TinyIbl ibl {glm::vec3(radiance)};
        RenderScene scene = referenceScene(ibl);
        Light light;
        light.intensity = 1e6;
        scene.lights = {light};
        for (double roughness : {0.0, 1.0})
            for (double metallic : {0.0, 1.0})
                for (FramebufferFormat format : {FramebufferFormat::RGBA16F, FramebufferFormat::RGBA32F}) {
                    scene.materials[0].material.setFactor(MapSlot::Roughness, roughness);
                    scene.materials[0].material.setFactor(MapSlot::Metallic, metallic);
                    // The shader replaces NaN by 0 before writing, so the image alone cannot show
                    // one: the non-finite view marks every pixel whose radiance was NaN, Inf or
                    // negative before that guard.
                    scene.view.debugView = DebugView::NonFinite;
                    scene.view.background = BackgroundMode::Color; // black: only the surface marks
                    scene.view.backgroundColor = glm::dvec3(0.0);
                    const Image marks = renderScene(scene, format, 32);
                    scene.view.background = BackgroundMode::Environment;
                    int marked = 0;
                    for (int y = 0; y < marks.height(); ++y)
                        for (int x = 0; x < marks.width(); ++x)
                            marked += marks.at(x, y).r != 0.0f ? 1 : 0;

                    QVERIFY2(marked == 0, (std::to_string(marked) + " pixels non-finite or negative before the guard, radiance "
                                              + std::to_string(radiance) + " roughness " + std::to_string(roughness)
                                              + " metallic " + std::to_string(metallic))
                                              .c_str());
                    scene.view.debugView = DebugView::None;
                    const Image image = renderScene(scene, format, 32);
                    for (int y = 0; y < image.height(); ++y)
                        for (int x = 0; x < image.width(); ++x) {
                            const glm::vec4 c = image.at(x, y);
                            for (int i = 0; i < 3; ++i)
                                QVERIFY2(std::isfinite(c[i]) && c[i] >= 0.0f,
                                    ("pixel " + std::to_string(x) + "," + std::to_string(y) + " radiance "
                                        + std::to_string(radiance) + " roughness "
                                        + std::to_string(roughness))
                                        .c_str());
                        }
                }
    }
}

void RendererGLTest::skippedWorkIsCounted()
{
    // A fresh renderer so that earlier tests' caches do not hide the first compile.
    Renderer renderer;
    TinyIbl ibl {glm::vec3(1.0f)};
    RenderScene scene = referenceScene(ibl);
    auto image = std::make_shared<const MapImage>(MapImage::fromImage(
        Image(4, 4, glm::vec4(0.5f, 0.5f, 0.5f, 1.0f)), MapLayout::Rgb, MapSampleType::UInt8));
    scene.materials[0].material.map(MapSlot::BaseColor).path = "/textures/base.png";
    scene.materials[0].material.map(MapSlot::BaseColor).colorSpace = ColorEncoding::SRGB;
    scene.materials[0].maps[std::size_t(MapSlot::BaseColor)] = {image, "/textures/base.png", 1};
    std::string error;
    std::optional<Framebuffer> target = Framebuffer::create(32, 32, FramebufferFormat::RGBA16F, &error);
    QVERIFY2(target, error.c_str());

    QVERIFY2(renderer.render(scene, *target, &error), error.c_str());
    QCOMPARE(renderer.lastFrameStats().programsCompiled, 2); // background + surface variant
    QCOMPARE(renderer.lastFrameStats().texturesUploaded, 1);
    QCOMPARE(renderer.lastFrameStats().meshesUploaded, 1);
    QCOMPARE(renderer.lastFrameStats().drawCalls, 2);

    // The same scene again: nothing compiled, nothing uploaded.
    QVERIFY2(renderer.render(scene, *target, &error), error.c_str());
    QCOMPARE(renderer.lastFrameStats().programsCompiled, 0);
    QCOMPARE(renderer.lastFrameStats().texturesUploaded, 0);
    QCOMPARE(renderer.lastFrameStats().meshesUploaded, 0);

    // A roughness change is a uniform: still nothing.
    scene.materials[0].material.setFactor(MapSlot::Roughness, 0.9);
    QVERIFY2(renderer.render(scene, *target, &error), error.c_str());
    QCOMPARE(renderer.lastFrameStats().programsCompiled, 0);
    QCOMPARE(renderer.lastFrameStats().texturesUploaded, 0);

    // A new file timestamp re-uploads that texture only; a new mesh key re-uploads the mesh.
    scene.materials[0].maps[std::size_t(MapSlot::BaseColor)].timestamp = 2;
    scene.meshKey = 2;
    QVERIFY2(renderer.render(scene, *target, &error), error.c_str());
    QCOMPARE(renderer.lastFrameStats().programsCompiled, 0);
    QCOMPARE(renderer.lastFrameStats().texturesUploaded, 1);
    QCOMPARE(renderer.lastFrameStats().meshesUploaded, 1);

    // Adding a light changes the variant: one compile; the tone-map pass compiles once too.
    scene.lights = {Light::defaultDirectional()};
    QVERIFY2(renderer.render(scene, *target, &error), error.c_str());
    QCOMPARE(renderer.lastFrameStats().programsCompiled, 1);
    std::optional<Framebuffer> display = Framebuffer::create(32, 32, FramebufferFormat::RGBA16F, &error);
    QVERIFY2(renderer.toneMap(*target, *display, scene.view, &error), error.c_str());
    QCOMPARE(renderer.lastFrameStats().programsCompiled, 2);
    QVERIFY2(renderer.toneMap(*target, *display, scene.view, &error), error.c_str());
    QCOMPARE(renderer.totalStats().programsCompiled, 2 + 1 + 1);
    QCOMPARE(renderer.totalStats().frameCount, std::uint64_t(5));
}

// A material with every lobe on and a texture in each of its 16 slots (each a grey of its own,
// or one texture for metallic, roughness and occlusion), drawn with the driver's texture units
// and with a 16-unit driver's (GL 4.1's least: 8 for maps after the lighting's). The slots left
// out are listed here, not taken from the renderer; each slot's debug view shows its texture
// when bound and its factor alone when left out, and GL reports no error.
void RendererGLTest::mapsBeyondTheTextureUnitsAreLeftOut_data()
{
    QTest::addColumn<int>("unitLimit"); // 0: the driver's
    QTest::addColumn<bool>("packed"); // metallic, roughness and occlusion from one texture
    QTest::addColumn<QList<int>>("leftOut"); // MapSlot values
    const auto slots = [](std::initializer_list<MapSlot> list) {
        QList<int> out;
        for (const MapSlot slot : list)
            out.push_back(int(slot));
        return out;
    };
    QTest::newRow("the driver's units, every map bound") << 0 << false << QList<int>();
    QTest::newRow("16 units, 16 textures")
        << 16 << false
        << slots({MapSlot::IridescenceThickness, MapSlot::SheenRoughness, MapSlot::ClearcoatNormal,
               MapSlot::Iridescence, MapSlot::Anisotropy, MapSlot::SpecularColor, MapSlot::Specular,
               MapSlot::ClearcoatRoughness, MapSlot::SheenColor});
    // 14 textures: the shared one takes one unit, so two fewer slots go.
    QTest::newRow("16 units, metallic roughness occlusion packed")
        << 16 << true
        << slots({MapSlot::IridescenceThickness, MapSlot::SheenRoughness, MapSlot::ClearcoatNormal,
               MapSlot::Iridescence, MapSlot::Anisotropy, MapSlot::SpecularColor, MapSlot::Specular});
}

void RendererGLTest::mapsBeyondTheTextureUnitsAreLeftOut()
{
    QFETCH(int, unitLimit);
    QFETCH(bool, packed);
    QFETCH(QList<int>, leftOut);
    TinyIbl ibl {glm::vec3(1.0f)};
    RenderScene scene = referenceScene(ibl);
    Material& material = scene.materials[0].material;
    // Every factor 1 (a factor of 0 would make its texture irrelevant, and unbound), the film
    // 100 to 400 nm.
    for (const MapSlot slot : kAllMapSlots)
        material.map(slot).factor = glm::dvec4(1.0);
    material.emissiveStrength = 1.0;
    material.setIridescence(1.0, 1.3, 100.0, 400.0);
    std::array<double, kMapSlotCount> grey {};
    std::shared_ptr<const MapImage> packedImage;
    for (const MapSlot slot : kAllMapSlots) {
        const int i = int(slot);
        grey[std::size_t(i)] = double(60 + 8 * i) / 255.0;
        // Grey in every channel, alpha too: the sheen's roughness and the specular strength read A.
        glm::vec4 texel(float(grey[std::size_t(i)]));
        if (slot == MapSlot::Normal || slot == MapSlot::ClearcoatNormal)
            texel = glm::vec4(128.0f / 255.0f, 128.0f / 255.0f, 1.0f, 1.0f); // flat
        auto image = std::make_shared<const MapImage>(
            MapImage::fromImage(Image(4, 4, texel), MapLayout::Rgba, MapSampleType::UInt8));
        const bool shared = packed
            && (slot == MapSlot::Metallic || slot == MapSlot::Roughness || slot == MapSlot::Occlusion);
        if (shared) {
            if (!packedImage)
                packedImage = image;
            image = packedImage;
            grey[std::size_t(i)] = grey[std::size_t(MapSlot::Metallic)];
        }
        const std::string path
            = shared ? "/textures/orm.png" : "/textures/" + std::string(toString(slot)) + ".png";
        material.map(slot).path = path;
        material.map(slot).colorSpace = ColorEncoding::Linear;
        scene.materials[0].maps[std::size_t(i)] = {image, path, 1};
    }
    m_renderer->setMapUnitLimit(unitLimit);
    const auto restore = qScopeGuard([this] { m_renderer->setMapUnitLimit(0); });
    while (glGetError() != GL_NO_ERROR) { }
    renderScene(scene);
    if (unitLimit == 0 && m_renderer->mapUnits() < Renderer::kAllMapUnits)
        QSKIP("this driver has fewer texture units than the material needs: the 16-unit rows test it");
    QCOMPARE(m_renderer->lastFrameStats().mapsLeftOut, int(leftOut.size()));
    QList<int> reported;
    for (const MapSlot slot : m_renderer->lastFrameMapsLeftOut())
        reported.push_back(int(slot));
    QList<int> expectedSlots = leftOut;
    std::sort(expectedSlots.begin(), expectedSlots.end());
    QCOMPARE(reported, expectedSlots);
    QCOMPARE(int(glGetError()), int(GL_NO_ERROR));

    // A view per slot of one value (the factors are 1; the film's thickness is mix(100, 400, g)
    // nm, shown / 1000, and 400 nm alone).
    struct View {
        const char* name;
        MapSlot slot;
    };
    const View views[] = {{"base-color", MapSlot::BaseColor}, {"metallic", MapSlot::Metallic},
        {"roughness", MapSlot::Roughness}, {"occlusion", MapSlot::Occlusion}, {"emissive", MapSlot::Emissive},
        {"clearcoat", MapSlot::Clearcoat}, {"clearcoat-roughness", MapSlot::ClearcoatRoughness},
        {"sheen-color", MapSlot::SheenColor}, {"sheen-roughness", MapSlot::SheenRoughness},
        {"specular", MapSlot::Specular}, {"specular-color", MapSlot::SpecularColor},
        {"anisotropy", MapSlot::Anisotropy}, {"iridescence", MapSlot::Iridescence},
        {"iridescence-thickness", MapSlot::IridescenceThickness}};
    for (const View& view : views) {
        scene.view.debugView = debugViewFromString(view.name).value();
        const Image image = renderScene(scene);
        const double shown = image.at(kSize / 2, kSize / 2).x;
        const bool out = leftOut.contains(int(view.slot));
        double expected = out ? 1.0 : grey[std::size_t(view.slot)];
        if (view.slot == MapSlot::IridescenceThickness)
            expected = (out ? 400.0 : 100.0 + 300.0 * expected) / 1000.0;
        QVERIFY2(std::abs(shown - expected) < 2e-3,
            qPrintable(QStringLiteral("%1 (%2): shown %3, expected %4")
                           .arg(QLatin1String(view.name), QLatin1String(out ? "left out" : "bound"))
                           .arg(shown)
                           .arg(expected)));
    }
    QCOMPARE(int(glGetError()), int(GL_NO_ERROR));
}

QTEST_GUILESS_MAIN(RendererGLTest)
#include "RendererGLTest.moc"
