// The headless OpenGL context (EGL, no display server) and the float framebuffer read-back that
// every GPU-against-CPU test relies on. Runs with DISPLAY unset: nothing here may need X.

#include <epoxy/gl.h> // before any header that could pull in <GL/gl.h>

#include "render/Framebuffer.h"
#include "render/GLDebug.h"
#include "render/GLInfo.h"
#include "render/HeadlessGLContext.h"

#include "TestSupport.h"

#include <QCoreApplication>
#include <QProcess>
#include <QtTest/QTest>

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

using namespace facet;

namespace {

std::string describe(const glm::vec4& value)
{
    char text[128];
    std::snprintf(text, sizeof text, "(%.9g, %.9g, %.9g, %.9g)", double(value.x), double(value.y),
        double(value.z), double(value.w));
    return text;
}

// Every pixel of `image` in rows [firstRow, lastRow) equals `expected` exactly; else a message.
std::string firstMismatch(const Image& image, int firstRow, int lastRow, const glm::vec4& expected)
{
    for (int y = firstRow; y < lastRow; ++y)
        for (int x = 0; x < image.width(); ++x)
            if (image.at(x, y) != expected)
                return "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is "
                    + describe(image.at(x, y)) + ", expected " + describe(expected);
    return {};
}

} // namespace

class HeadlessContextGLTest : public QObject {
    Q_OBJECT
public:
    // Runs before QCoreApplication: the context must come up with no display server at all.
    static void initMain()
    {
        facet::test::forgetDisplayServer();
    }

private Q_SLOTS:
    void createsCoreContextWithoutDisplay();
    void makeCurrentAndDoneCurrent();
    void movedContextKeepsWorking();
    void secondContextSurvivesTheFirst();
    void debugOutputReachesTheLog();
    void rgba16fKeepsUnclampedValues();
    void rgba32fKeepsFullPrecision();
    void readbackIsTopRowFirst();
    void readbackLeavesEarlierErrorsPending();
    void rejectsBadFramebufferSize();
    void refusesOldGLVersion();
};

void HeadlessContextGLTest::createsCoreContextWithoutDisplay()
{
    QVERIFY(qEnvironmentVariableIsEmpty("DISPLAY"));
    std::string error;
    std::optional<HeadlessGLContext> context = HeadlessGLContext::create(&error);
    QVERIFY2(context, error.c_str());
    QVERIFY(context->isCurrent());

    const GLInfo& info = context->info();
    qInfo("%s on %s", info.summary().c_str(), context->displayDescription().c_str());
    QVERIFY2(info.atLeast(4, 1), info.version.c_str());
    QVERIFY2(info.coreProfile, info.version.c_str());
    QVERIFY(!info.renderer.empty());
    QVERIFY(!info.vendor.empty());
    QVERIFY(!info.shadingLanguageVersion.empty());
    QCOMPARE(info.hasCompute, info.atLeast(4, 3) || epoxy_has_gl_extension("GL_ARB_compute_shader"));
    // The version string starts with the numbers GL_MAJOR/MINOR_VERSION report.
    const std::string numbers = std::to_string(info.major) + "." + std::to_string(info.minor);
    QVERIFY2(info.version.rfind(numbers, 0) == 0, (info.version + " vs " + numbers).c_str());
}

void HeadlessContextGLTest::makeCurrentAndDoneCurrent()
{
    std::string error;
    std::optional<HeadlessGLContext> context = HeadlessGLContext::create(&error);
    QVERIFY2(context, error.c_str());

    context->doneCurrent();
    QVERIFY(!context->isCurrent());
    // Without a current context GL must not be called; the query says so instead of crashing.
    QVERIFY(!queryCurrentGLInfo().isValid());

    QVERIFY(context->makeCurrent());
    QVERIFY(context->isCurrent());
    const GLInfo again = queryCurrentGLInfo();
    QCOMPARE(again.version, context->info().version);
    QCOMPARE(again.renderer, context->info().renderer);
}

void HeadlessContextGLTest::movedContextKeepsWorking()
{
    std::string error;
    std::optional<HeadlessGLContext> first = HeadlessGLContext::create(&error);
    QVERIFY2(first, error.c_str());
    HeadlessGLContext moved = std::move(*first);
    QVERIFY(!first->makeCurrent()); // moved-from: owns nothing
    first.reset(); // and destroying it leaves `moved` alone
    QVERIFY(moved.makeCurrent());
    std::optional<Framebuffer> target = Framebuffer::create(4, 4, FramebufferFormat::RGBA16F, &error);
    QVERIFY2(target, error.c_str());
    target->clear(glm::vec4(0.5f));
    QCOMPARE(target->readPixels().at(3, 3), glm::vec4(0.5f));
}

void HeadlessContextGLTest::secondContextSurvivesTheFirst()
{
    // Both contexts live on the same EGLDisplay: destroying one must not terminate it.
    std::string error;
    std::optional<HeadlessGLContext> first = HeadlessGLContext::create(&error);
    QVERIFY2(first, error.c_str());
    std::optional<HeadlessGLContext> second = HeadlessGLContext::create(&error);
    QVERIFY2(second, error.c_str());
    first.reset();
    QVERIFY(second->makeCurrent());
    std::optional<Framebuffer> target = Framebuffer::create(2, 2, FramebufferFormat::RGBA32F, &error);
    QVERIFY2(target, error.c_str());
    target->clear(glm::vec4(0.25f, 0.5f, 0.75f, 1.0f));
    QCOMPARE(target->readPixels().at(1, 1), glm::vec4(0.25f, 0.5f, 0.75f, 1.0f));
}

void HeadlessContextGLTest::debugOutputReachesTheLog()
{
    std::vector<std::string> messages;
    HeadlessGLContextOptions options;
    options.debug = true;
    options.debugLog
        = [&messages](GLDebugSeverity, std::string_view message) { messages.emplace_back(message); };
    std::string error;
    std::optional<HeadlessGLContext> context = HeadlessGLContext::create(options, &error);
    QVERIFY2(context, error.c_str());
    if (!context->info().hasDebugOutput)
        QSKIP("no KHR_debug on this context");

    glEnable(GLenum(0x7fff)); // not a capability: GL_INVALID_ENUM, reported synchronously
    QCOMPARE(glGetError(), GLenum(GL_INVALID_ENUM));
    QVERIFY(!messages.empty());
    QVERIFY2(messages.front().rfind("GL error (high): ", 0) == 0, messages.front().c_str());
}

void HeadlessContextGLTest::rgba16fKeepsUnclampedValues()
{
    std::string error;
    std::optional<HeadlessGLContext> context = HeadlessGLContext::create(&error);
    QVERIFY2(context, error.c_str());
    std::optional<Framebuffer> target = Framebuffer::create(8, 6, FramebufferFormat::RGBA16F, &error);
    QVERIFY2(target, error.c_str());
    QCOMPARE(target->width(), 8);
    QCOMPARE(target->height(), 6);

    // Exactly representable in half: 3.5, -2, 1e4 (= 1250 * 2^3, 11 significant bits) and 0.25.
    // Radiance is unbounded and may be negative mid-pipeline: nothing may clamp it to [0, 1].
    const glm::vec4 value(3.5f, -2.0f, 1.0e4f, 0.25f);
    target->clear(value);
    QCOMPARE(glGetError(), GLenum(GL_NO_ERROR));
    const Image image = target->readPixels();
    QCOMPARE(image.width(), 8);
    QCOMPARE(image.height(), 6);
    const std::string mismatch = firstMismatch(image, 0, image.height(), value);
    QVERIFY2(mismatch.empty(), mismatch.c_str());
}

void HeadlessContextGLTest::rgba32fKeepsFullPrecision()
{
    std::string error;
    std::optional<HeadlessGLContext> context = HeadlessGLContext::create(&error);
    QVERIFY2(context, error.c_str());
    std::optional<Framebuffer> target = Framebuffer::create(5, 3, FramebufferFormat::RGBA32F, &error);
    QVERIFY2(target, error.c_str());
    // Not representable in half (half would give 0, 65504 at most, 0.333252): float must keep them.
    const glm::vec4 value(1.0e-7f, 123456.789f, -0.3333333f, 1.0e6f);
    target->clear(value);
    const Image image = target->readPixels();
    const std::string mismatch = firstMismatch(image, 0, image.height(), value);
    QVERIFY2(mismatch.empty(), mismatch.c_str());
}

// A read of Facet's own target neither hides nor clears an error an earlier call left pending
// (GLDebug and the frame checks still see it); a read of a framebuffer it cannot read says so.
void HeadlessContextGLTest::readbackLeavesEarlierErrorsPending()
{
    std::string error;
    std::optional<HeadlessGLContext> context = HeadlessGLContext::create(&error);
    QVERIFY2(context, error.c_str());
    std::optional<Framebuffer> target = Framebuffer::create(4, 4, FramebufferFormat::RGBA16F, &error);
    QVERIFY2(target, error.c_str());
    target->clear(glm::vec4(0.5f));
    while (glGetError() != GL_NO_ERROR) { }

    glEnable(GLenum(0x7fff)); // not a capability: GL_INVALID_ENUM
    QCOMPARE(target->readPixels().at(1, 1), glm::vec4(0.5f));
    QCOMPARE(glGetError(), GLenum(GL_INVALID_ENUM));

    glEnable(GLenum(0x7fff));
    QCOMPARE(target->readPixel(2, 0), std::optional(glm::vec4(0.5f)));
    QCOMPARE(glGetError(), GLenum(GL_INVALID_ENUM));
    QCOMPARE(target->readPixel(4, 0), std::nullopt);
    QCOMPARE(glGetError(), GLenum(GL_NO_ERROR));
}

void HeadlessContextGLTest::readbackIsTopRowFirst()
{
    std::string error;
    std::optional<HeadlessGLContext> context = HeadlessGLContext::create(&error);
    QVERIFY2(context, error.c_str());
    const int width = 7;
    const int height = 6;
    std::optional<Framebuffer> target
        = Framebuffer::create(width, height, FramebufferFormat::RGBA16F, &error);
    QVERIFY2(target, error.c_str());

    const glm::vec4 bottom(0.0f, 0.0f, 1.0f, 1.0f);
    const glm::vec4 top(1.0f, 0.5f, 0.0f, 1.0f);
    target->clear(bottom);
    // GL's window coordinates start at the bottom: the top half is y in [height/2, height).
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, height / 2, width, height - height / 2);
    glClearColor(top.x, top.y, top.z, top.w);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);

    const Image image = target->readPixels();
    std::string mismatch = firstMismatch(image, 0, height / 2, top);
    QVERIFY2(mismatch.empty(), ("top half: " + mismatch).c_str());
    mismatch = firstMismatch(image, height / 2, height, bottom);
    QVERIFY2(mismatch.empty(), ("bottom half: " + mismatch).c_str());
}

void HeadlessContextGLTest::rejectsBadFramebufferSize()
{
    std::string error;
    std::optional<HeadlessGLContext> context = HeadlessGLContext::create(&error);
    QVERIFY2(context, error.c_str());
    for (const auto& [width, height] : {std::pair {0, 4}, std::pair {4, -1}, std::pair {1 << 20, 1}}) {
        error.clear();
        QVERIFY(!Framebuffer::create(width, height, FramebufferFormat::RGBA16F, &error));
        QVERIFY2(error.rfind("Framebuffer::create: size ", 0) == 0, error.c_str());
    }
}

void HeadlessContextGLTest::refusesOldGLVersion()
{
    // Mesa reads MESA_GL_VERSION_OVERRIDE once per process, so the check runs in a child process
    // of this test, which then takes the first branch.
    if (qEnvironmentVariable("MESA_GL_VERSION_OVERRIDE") == QStringLiteral("3.3")) {
        std::string error;
        std::optional<HeadlessGLContext> context = HeadlessGLContext::create(&error);
        if (context) {
            if (context->info().version.find("Mesa") == std::string::npos)
                QSKIP("not a Mesa driver: MESA_GL_VERSION_OVERRIDE does not apply");
            QFAIL(("a context was made under a 3.3 override: " + context->info().version).c_str());
        }
        qInfo("%s", error.c_str());
        QVERIFY2(error.rfind("HeadlessGLContext::create: OpenGL 4.1 core profile is required; ", 0) == 0,
            error.c_str());
        QVERIFY2(error.find("offers only OpenGL 3.3") != std::string::npos, error.c_str());
        return;
    }

    std::string error;
    {
        std::optional<HeadlessGLContext> context = HeadlessGLContext::create(&error);
        QVERIFY2(context, error.c_str());
        if (context->info().version.find("Mesa") == std::string::npos)
            QSKIP("not a Mesa driver: MESA_GL_VERSION_OVERRIDE does not apply");
    }
    QProcess child;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("MESA_GL_VERSION_OVERRIDE"), QStringLiteral("3.3"));
    child.setProcessEnvironment(environment);
    child.setProcessChannelMode(QProcess::MergedChannels);
    child.start(QCoreApplication::applicationFilePath(), {QStringLiteral("refusesOldGLVersion")});
    QVERIFY2(child.waitForFinished(120000), "the child test did not finish");
    const QByteArray output = child.readAll();
    QVERIFY2(child.exitStatus() == QProcess::NormalExit && child.exitCode() == 0, output.constData());
    qInfo("child: %s", output.constData());
}

QTEST_GUILESS_MAIN(HeadlessContextGLTest)
#include "HeadlessContextGLTest.moc"
