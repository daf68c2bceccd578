// The tone-map pass with an OpenColorIO display/view (render/OcioDisplayTransform, through
// Renderer::toneMap and ToneMapping) against OCIO's CPU processor (core/image/ColorManagement.h) on a
// ramp of HDR values, on a headless context: the built-in config's views, and a config written
// here whose views are a 3D LUT and 1D LUTs (so the texture uploads are exercised: the built-in
// views are all shader code). Also: programs are cached per view, and unknown names fail with a
// message listing what exists.

#include <epoxy/gl.h>

#include "core/image/ColorManagement.h"
#include "render/Framebuffer.h"
#include "render/HeadlessGLContext.h"
#include "render/OcioDisplayTransform.h"
#include "render/Renderer.h"
#include "render/ToneMapping.h"

#include "TestSupport.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

using namespace facet;
using facet::test::writeText;

namespace {

// The HDR ramp: each column one value (0, 1e-4 ... 1000), each row a tint (grey, warm, cool,
// pure green, pure red) to exercise the hue-dependent parts (ACES red modifier, glow).
const float kRamp[]
    = {0.0f, 1e-4f, 1e-3f, 0.01f, 0.05f, 0.18f, 0.5f, 1.0f, 2.0f, 4.0f, 16.0f, 100.0f, 1000.0f};
constexpr int kWidth = int(std::size(kRamp));
const glm::vec3 kTints[]
    = {{1.0f, 1.0f, 1.0f}, {1.0f, 0.5f, 0.25f}, {0.1f, 0.6f, 1.0f}, {0.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}};
constexpr int kHeight = int(std::size(kTints));

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}


// Pixel (x, y) of the ramp, y counted from the top (as Framebuffer::readPixels returns rows).
glm::vec3 rampPixel(int x, int y)
{
    return kTints[y] * kRamp[x];
}

// Uploads the ramp into `hdr` (RGBA32F, kWidth x kHeight). GL rows are bottom-up.
void uploadRamp(const Framebuffer& hdr)
{
    std::vector<glm::vec4> pixels(std::size_t(kWidth * kHeight));
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            pixels[std::size_t((kHeight - 1 - y) * kWidth + x)] = glm::vec4(rampPixel(x, y), 1.0f);
    glBindTexture(GL_TEXTURE_2D, hdr.colorTexture());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kWidth, kHeight, GL_RGBA, GL_FLOAT, pixels.data());
    glBindTexture(GL_TEXTURE_2D, 0);
}

// Largest difference between the GPU's display values and the CPU processor's for the ramp at
// `exposureEV`, relative to max(1, |cpu|) so that Raw's 1000 and ACES's 0.36 weigh alike.
double worstDifference(
    const Image& gpu, const OCIO::ConstCPUProcessorRcPtr& cpu, double exposureEV, std::string* where)
{
    const auto scale = float(std::exp2(exposureEV));
    double worst = 0.0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const glm::vec3 in = rampPixel(x, y) * scale;
            float expected[3] = {in.x, in.y, in.z};
            cpu->applyRGB(expected);
            const glm::vec4 actual = gpu.at(x, y);
            for (int c = 0; c < 3; ++c) {
                const double difference = std::abs(double(actual[c]) - double(expected[c]))
                    / std::max(1.0, std::abs(double(expected[c])));
                if (!(difference <= worst)) { // NaN counts as worst
                    worst = std::isnan(difference) ? 1e30 : difference;
                    char text[160];
                    std::snprintf(text, sizeof text, "input %g (tint row %d, channel %d): GPU %.7g, CPU %.7g",
                        double(in[c]), y, c, double(actual[c]), double(expected[c]));
                    *where = text;
                }
            }
        }
    return worst;
}

// A config with LUT views: "Cube" (a 17^3 .cube, tetrahedral), "Curve" (a 1D .spi1d of 8193
// entries: wider than OCIO's 4096 texture limit, so it arrives as a 2D texture) and "Short curve"
// (a 1D .spi1d of 64 entries: a 1D texture).
const char* const kLutConfig = R"(ocio_profile_version: 2
search_path: "."

roles:
  default: linear
  scene_linear: linear

file_rules:
  - !<Rule> {name: Default, colorspace: default}

displays:
  LUT Monitor:
    - !<View> {name: Cube, colorspace: cube}
    - !<View> {name: Curve, colorspace: curve}
    - !<View> {name: Short curve, colorspace: shortcurve}

active_displays: []
active_views: []

colorspaces:
  - !<ColorSpace>
    name: linear
  - !<ColorSpace>
    name: cube
    from_reference: !<FileTransform> {src: test.cube, interpolation: tetrahedral}
  - !<ColorSpace>
    name: curve
    from_reference: !<FileTransform> {src: long.spi1d, interpolation: linear}
  - !<ColorSpace>
    name: shortcurve
    from_reference: !<FileTransform> {src: short.spi1d, interpolation: linear}
)";

// Smooth, non-separable functions of [0, 1]^3 and [0, 1] for the LUTs.
QByteArray cubeLut(int size)
{
    QByteArray text = "LUT_3D_SIZE " + QByteArray::number(size) + "\n";
    for (int b = 0; b < size; ++b)
        for (int g = 0; g < size; ++g)
            for (int r = 0; r < size; ++r) { // red fastest (.cube order)
                const double R = r / double(size - 1);
                const double G = g / double(size - 1);
                const double B = b / double(size - 1);
                char line[96];
                std::snprintf(line, sizeof line, "%.7f %.7f %.7f\n", std::sqrt(R), G * G,
                    0.5 * (R + B) * (1.0 - 0.3 * G));
                text += line;
            }
    return text;
}

QByteArray spi1d(int length)
{
    QByteArray text = "Version 1\nFrom 0.0 1.0\nLength " + QByteArray::number(length) + "\nComponents 1\n{\n";
    for (int i = 0; i < length; ++i) {
        const double x = i / double(length - 1);
        char line[48];
        std::snprintf(line, sizeof line, "  %.8f\n", std::pow(x, 1.0 / 2.2));
        text += line;
    }
    return text + "}\n";
}

} // namespace

class OcioGLTest : public QObject {
    Q_OBJECT
public:
    static void initMain()
    {
        facet::test::forgetDisplayServer();
        // Renderer::toneMap uses ColorManagement::shared(): $OCIO when set. These tests are about
        // the built-in config (the LUT config is handed to ToneMapping directly).
        qunsetenv("OCIO");
    }

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void builtInViewsMatchCpu_data();
    void builtInViewsMatchCpu();
    void lutViewsMatchCpu_data();
    void lutViewsMatchCpu();
    void programsAreCachedPerView();
    void unknownNamesFail();

private:
    std::optional<HeadlessGLContext> m_context;
    std::unique_ptr<Renderer> m_renderer;
    std::optional<Framebuffer> m_hdr;
    std::optional<Framebuffer> m_display;
};

void OcioGLTest::initTestCase()
{
    std::string error;
    m_context = HeadlessGLContext::create(&error);
    QVERIFY2(m_context, error.c_str());
    qInfo("%s", m_context->info().summary().c_str());
    m_renderer = std::make_unique<Renderer>();
    m_hdr = Framebuffer::create(kWidth, kHeight, FramebufferFormat::RGBA32F, &error);
    QVERIFY2(m_hdr, error.c_str());
    // RGBA32F output: the comparison sees the pass's float result, not a quantised one.
    m_display = Framebuffer::create(kWidth, kHeight, FramebufferFormat::RGBA32F, &error);
    QVERIFY2(m_display, error.c_str());
    uploadRamp(*m_hdr);
}

void OcioGLTest::cleanupTestCase()
{
    m_display.reset();
    m_hdr.reset();
    m_renderer.reset();
    m_context.reset();
}

void OcioGLTest::builtInViewsMatchCpu_data()
{
    QTest::addColumn<QString>("display");
    QTest::addColumn<QString>("view");
    const ColorManagement builtIn = ColorManagement::builtIn();
    for (const std::string& display : builtIn.displays()) {
        std::string error;
        const std::optional<std::vector<std::string>> views = builtIn.views(display, &error);
        QVERIFY2(views, error.c_str());
        for (const std::string& view : *views)
            QTest::newRow((display + " / " + view).c_str())
                << QString::fromStdString(display) << QString::fromStdString(view);
    }
}

void OcioGLTest::builtInViewsMatchCpu()
{
    QFETCH(QString, display);
    QFETCH(QString, view);
    const ColorManagement builtIn = ColorManagement::builtIn();
    std::string error;
    const OCIO::ConstCPUProcessorRcPtr cpu
        = builtIn.cpuProcessor(display.toStdString(), view.toStdString(), &error);
    QVERIFY2(cpu, error.c_str());
    for (double exposureEV : {0.0, 1.5}) {
        ViewSettings settings;
        settings.ocioDisplay = display.toStdString();
        settings.ocioView = view.toStdString();
        settings.exposureEV = exposureEV;
        settings.toneMapper = ToneMapper::Reinhard; // must be ignored: the OCIO view replaces it
        QVERIFY2(m_renderer->toneMap(*m_hdr, *m_display, settings, &error), error.c_str());
        const Image out = m_display->readPixels();
        std::string where;
        const double worst = worstDifference(out, cpu, exposureEV, &where);
        qInfo("%s / %s, EV %+.1f: worst GPU-CPU difference %.3g at %s", qPrintable(display), qPrintable(view),
            exposureEV, worst, where.c_str());
        // The same OCIO ops in float on both sides (the CPU with OCIO's SSE approximations of
        // log2/exp2, the GPU with the driver's). Measured on llvmpipe: at most 2.8e-5, for
        // Rec.1886's x^(1/2.4) of the ~1e-11 that ACES leaves at black, where the curve's slope is
        // huge; elsewhere below 1e-6 (docs/rendering.md). 2e-4 leaves room for other drivers'
        // pow/log2 and is 1/20 of an 8-bit step (3.9e-3).
        QVERIFY2(worst < 2e-4, ("worst difference " + std::to_string(worst) + " at " + where).c_str());
    }
}

void OcioGLTest::lutViewsMatchCpu_data()
{
    QTest::addColumn<QString>("view");
    QTest::newRow("3D LUT (3D texture)") << QStringLiteral("Cube");
    QTest::newRow("1D LUT, 8193 entries (2D texture)") << QStringLiteral("Curve");
    QTest::newRow("1D LUT, 64 entries (1D texture)") << QStringLiteral("Short curve");
}

void OcioGLTest::lutViewsMatchCpu()
{
    QFETCH(QString, view);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QDir folder(dir.path());
    QVERIFY(writeText(folder.filePath(QStringLiteral("lut.ocio")), kLutConfig));
    QVERIFY(writeText(folder.filePath(QStringLiteral("test.cube")), cubeLut(17)));
    QVERIFY(writeText(folder.filePath(QStringLiteral("long.spi1d")), spi1d(8193)));
    QVERIFY(writeText(folder.filePath(QStringLiteral("short.spi1d")), spi1d(64)));
    std::string error;
    std::optional<ColorManagement> config
        = ColorManagement::fromFile(folder.filePath(QStringLiteral("lut.ocio")).toStdString(), &error);
    QVERIFY2(config, error.c_str());
    const OCIO::ConstCPUProcessorRcPtr cpu = config->cpuProcessor("LUT Monitor", view.toStdString(), &error);
    QVERIFY2(cpu, error.c_str());

    // The view really goes through one LUT texture (else this test would not test the uploads).
    {
        std::unique_ptr<OcioDisplayTransform> transform = OcioDisplayTransform::create(
            config->displayProcessor("LUT Monitor", view.toStdString(), &error), view.toStdString(), &error);
        QVERIFY2(transform, error.c_str());
        QCOMPARE(transform->lutTextureCount(), 1);
    }

    ToneMapping toneMapping;
    toneMapping.setColorManagement(std::make_shared<const ColorManagement>(std::move(*config)));
    ViewSettings settings;
    settings.ocioDisplay = "LUT Monitor";
    settings.ocioView = view.toStdString();
    settings.exposureEV = -1.0; // most of the ramp inside the LUTs' [0, 1] domain, the rest clamps
    bool compiled = false;
    QVERIFY2(toneMapping.apply(m_hdr->colorTexture(), m_display->framebufferId(), kWidth, kHeight, settings,
                 &error, &compiled),
        error.c_str());
    QVERIFY(compiled);
    const Image out = m_display->readPixels();
    std::string where;
    const double worst = worstDifference(out, cpu, settings.exposureEV, &where);
    qInfo("LUT view %s: worst GPU-CPU difference %.3g at %s", qPrintable(view), worst, where.c_str());
    // Tetrahedral 3D: exact texel fetches (GL_NEAREST) and float arithmetic on both sides. 1D:
    // GL_LINEAR filtering, exact in float on llvmpipe (measured: at most 6e-8 for all three views)
    // but done with 8 fractional weight bits on many GPUs: 1/512 of the 64-entry LUT's steepest
    // step (0.15 near 0) is 3e-4. 1e-3 bounds that, a quarter of an 8-bit step.
    QVERIFY2(worst < 1e-3, ("worst difference " + std::to_string(worst) + " at " + where).c_str());
}

void OcioGLTest::programsAreCachedPerView()
{
    // A renderer of its own: the one of the other tests has compiled every built-in view already.
    Renderer renderer;
    std::string error;
    ViewSettings settings;
    settings.ocioDisplay = "sRGB - Display";
    settings.ocioView = "ACES 1.0 - SDR Video";
    QVERIFY2(renderer.toneMap(*m_hdr, *m_display, settings, &error), error.c_str());
    const std::size_t before = renderer.totalStats().programsCompiled;
    // Same view, another exposure: nothing compiles.
    settings.exposureEV = 2.0;
    QVERIFY2(renderer.toneMap(*m_hdr, *m_display, settings, &error), error.c_str());
    QCOMPARE(std::size_t(renderer.totalStats().programsCompiled), before);
    // Back to Facet's own tone mapper and to OCIO again: both programs are kept.
    ViewSettings facetView;
    QVERIFY2(renderer.toneMap(*m_hdr, *m_display, facetView, &error), error.c_str());
    const std::size_t withFacet = renderer.totalStats().programsCompiled;
    QVERIFY2(renderer.toneMap(*m_hdr, *m_display, settings, &error), error.c_str());
    QVERIFY2(renderer.toneMap(*m_hdr, *m_display, facetView, &error), error.c_str());
    QCOMPARE(std::size_t(renderer.totalStats().programsCompiled), withFacet);
    // Another view compiles one program.
    settings.ocioView = "Un-tone-mapped";
    QVERIFY2(renderer.toneMap(*m_hdr, *m_display, settings, &error), error.c_str());
    QCOMPARE(std::size_t(renderer.totalStats().programsCompiled), withFacet + 1);
}

void OcioGLTest::unknownNamesFail()
{
    std::string error;
    ViewSettings settings;
    settings.ocioDisplay = "sRGB - Display";
    settings.ocioView = "Filmic";
    QVERIFY(!m_renderer->toneMap(*m_hdr, *m_display, settings, &error));
    QVERIFY2(contains(error, "ToneMapping::apply: "), error.c_str());
    QVERIFY2(contains(error, "no view \"Filmic\""), error.c_str());
    QVERIFY2(contains(error, "\"ACES 1.0 - SDR Video\", \"Un-tone-mapped\", \"Raw\""), error.c_str());
    // Asked again (a viewport redraws): the same message, from the remembered failure.
    std::string again;
    QVERIFY(!m_renderer->toneMap(*m_hdr, *m_display, settings, &again));
    QCOMPARE(again, error);

    settings.ocioDisplay = "P3 Cinema";
    settings.ocioView = "Raw";
    error.clear();
    QVERIFY(!m_renderer->toneMap(*m_hdr, *m_display, settings, &error));
    QVERIFY2(contains(error, "unknown display \"P3 Cinema\"") && contains(error, "\"sRGB - Display\""),
        error.c_str());

    settings.ocioDisplay = "sRGB - Display";
    settings.ocioView.clear();
    error.clear();
    QVERIFY(!m_renderer->toneMap(*m_hdr, *m_display, settings, &error));
    QVERIFY2(contains(error, "ToneMapping::apply: ") && contains(error, "no view"), error.c_str());

    // A failure leaves the renderer usable.
    settings.ocioView = "Raw";
    QVERIFY2(m_renderer->toneMap(*m_hdr, *m_display, settings, &error), error.c_str());
}

QTEST_GUILESS_MAIN(OcioGLTest)
#include "OcioGLTest.moc"
