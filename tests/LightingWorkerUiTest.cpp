// ui/viewport/LightingWorker: the window's IBL precompute on a thread of its own, in a context sharing
// with the views'. What it delivers is what a precompute on the GUI thread makes, texel for texel,
// readable from the view's context; a request for another set cancels the one running (nothing
// of it is cached); the same request is not run twice; progress rises to the end; a failure is
// named; destroying the worker mid-precompute returns promptly.

#include <epoxy/gl.h> // before Qt's GL headers

#include "core/ibl/Environment.h"
#include "core/ibl/IblDiskCache.h"
#include "render/IblPrecompute.h"
#include "render/IblSettings.h"
#include "render/IblTextures.h"
#include "ui/viewport/LightingWorker.h"
#include "ui/viewport/SurfaceFormat.h"

#include <QDir>
#include <QElapsedTimer>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <cmath>
#include <memory>
#include <vector>

using namespace facet;

namespace {

// Every level of every face of `texture` (a cubemap of `levels` levels, `size` wide), as RGBA floats.
std::vector<float> readCube(const GLTexture& texture, int size, int levels)
{
    std::vector<float> texels;
    glBindTexture(GL_TEXTURE_CUBE_MAP, texture.id());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    for (int level = 0; level < levels; ++level) {
        const int s = std::max(size >> level, 1);
        for (int face = 0; face < 6; ++face) {
            std::vector<float> part(std::size_t(s) * std::size_t(s) * 4);
            glGetTexImage(
                GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), level, GL_RGBA, GL_FLOAT, part.data());
            texels.insert(texels.end(), part.begin(), part.end());
        }
    }
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    return texels;
}

// A set that takes long enough on llvmpipe to be cancelled while it runs (seconds).
IblSettings slowSettings()
{
    IblSettings settings = *IblSettings::preset("high");
    settings.prefilterSamples = 4096;
    return settings;
}

// A 1024x512 environment of its own (another content hash than the built-in studio's).
Environment gradientEnvironment(float scale)
{
    Image image(1024, 512);
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            image.at(x, y) = glm::vec4(scale * (0.2f + float(x) / 1024.0f),
                scale * (0.1f + float(y) / 512.0f), scale * (((x / 64 + y / 64) % 2) ? 4.0f : 0.05f), 1.0f);
    return Environment(std::move(image), "gradient");
}

} // namespace

class LightingWorkerUiTest : public QObject {
    Q_OBJECT
public:
    static void initMain() { installViewportSurfaceFormat(); }

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void deliversWhatTheGuiThreadMakes_data();
    void deliversWhatTheGuiThreadMakes();
    void anotherRequestCancelsTheRunningOne();
    void theSameRequestRunsOnce();
    void queuedSetsRunInOrderAndCancelNothing();
    void aRequestEmptiesTheQueue();
    void failureIsNamed();
    void destroyedWhileRunningReturnsPromptly();

private:
    QOffscreenSurface m_surface;
    std::unique_ptr<QOpenGLContext> m_view; // stands for a view's context
};

void LightingWorkerUiTest::initTestCase()
{
    m_surface.setFormat(QSurfaceFormat::defaultFormat());
    m_surface.create();
    m_view = std::make_unique<QOpenGLContext>();
    m_view->setFormat(QSurfaceFormat::defaultFormat());
    QVERIFY(m_view->create());
    QVERIFY(m_view->makeCurrent(&m_surface));
    QVERIFY2(
        QOpenGLContext::supportsThreadedOpenGL(), "the test's platform should run GL on a second thread");
}

void LightingWorkerUiTest::cleanupTestCase()
{
    m_view->makeCurrent(&m_surface);
    m_view->doneCurrent();
}

void LightingWorkerUiTest::deliversWhatTheGuiThreadMakes_data()
{
    QTest::addColumn<QString>("preset");
    QTest::addColumn<bool>("diskCacheWarm"); // the worker reads the set from disk
    QTest::newRow("draft, computed") << QStringLiteral("draft") << false;
    QTest::newRow("default, computed") << QStringLiteral("default") << false;
    QTest::newRow("default, from the disk cache") << QStringLiteral("default") << true;
}

void LightingWorkerUiTest::deliversWhatTheGuiThreadMakes()
{
    QFETCH(QString, preset);
    QFETCH(bool, diskCacheWarm);
    QTemporaryDir cache;
    QVERIFY(m_view->makeCurrent(&m_surface));
    const Environment environment = Environment::builtin(Environment::Builtin::Studio);
    const IblSettings settings = *IblSettings::preset(preset.toStdString());

    IblPrecompute gui(cache.path(), /*useDiskCache=*/diskCacheWarm);
    std::string error;
    const auto expected = gui.prepare(environment, settings, nullptr, &error);
    QVERIFY2(expected, error.c_str());

    LightingWorker worker(cache.path(), /*useDiskCache=*/diskCacheWarm);
    QVERIFY2(worker.isValid(), qPrintable(worker.problem()));
    QSignalSpy finished(&worker, &LightingWorker::finished);
    QSignalSpy progress(&worker, &LightingWorker::progress);
    const std::uint64_t key = worker.request(environment, settings);
    QCOMPARE(key, IblPrecompute::cacheKey(environment, settings));
    QVERIFY(finished.wait(60000));
    QCOMPARE(finished.first().first().toULongLong(), quint64(key));
    std::optional<LightingWorker::Result> result = worker.take(key);
    QVERIFY(result);
    QVERIFY2(result->textures, result->error.c_str());
    QVERIFY(!worker.take(key)); // once
    QCOMPARE(result->stats.cacheHitsDisk, diskCacheWarm ? 1 : 0);
    QCOMPARE(result->stats.passesRun, diskCacheWarm ? 0 : 3);
    QCOMPARE(result->environmentName, QStringLiteral("studio"));
    // Progress rises (only computed sets report it, at most every kProgressIntervalMs).
    double last = 0.0;
    for (const QList<QVariant>& report : progress) {
        QCOMPARE(report.at(0).toULongLong(), quint64(key));
        const double fraction = report.at(1).toDouble();
        QVERIFY(fraction >= last && fraction <= 1.0);
        last = fraction;
    }

    // Read from this (the view's) context: the worker's textures, complete and equal.
    QVERIFY(m_view->makeCurrent(&m_surface));
    const IblTextures& made = *result->textures;
    QCOMPARE(readCube(*made.prefiltered, made.prefilteredSize, made.prefilteredMipLevels),
        readCube(*expected->prefiltered, expected->prefilteredSize, expected->prefilteredMipLevels));
    QCOMPARE(readCube(*made.irradiance, made.irradianceSize, 1),
        readCube(*expected->irradiance, expected->irradianceSize, 1));
    QCOMPARE(readCube(*made.environment, made.environmentSize, made.environmentMipLevels),
        readCube(*expected->environment, expected->environmentSize, expected->environmentMipLevels));
    for (std::size_t i = 0; i < 9; ++i)
        QCOMPARE(made.irradianceSH[i], expected->irradianceSH[i]);

    // Adopted into the views' precompute, it is a memory hit there.
    IblPrecompute views({}, false);
    QVERIFY(!views.holds(environment, settings));
    views.adopt(key, result->textures);
    QVERIFY(views.holds(environment, settings));
    IblStats stats;
    QCOMPARE(views.prepare(environment, settings, &stats, &error), result->textures);
    QCOMPARE(stats.cacheHitsMemory, 1);
    QCOMPARE(stats.passesRun, 0);
}

void LightingWorkerUiTest::anotherRequestCancelsTheRunningOne()
{
    QTemporaryDir cache;
    QVERIFY(m_view->makeCurrent(&m_surface));
    const Environment slow = gradientEnvironment(1.0f);
    const Environment next = Environment::builtin(Environment::Builtin::Studio);
    const IblSettings nextSettings = *IblSettings::preset("draft");
    LightingWorker worker(cache.path(), /*useDiskCache=*/true);
    QVERIFY2(worker.isValid(), qPrintable(worker.problem()));
    QSignalSpy finished(&worker, &LightingWorker::finished);
    QSignalSpy progress(&worker, &LightingWorker::progress);
    const std::uint64_t slowKey = worker.request(slow, slowSettings());
    QVERIFY(progress.wait(60000)); // it runs
    QCOMPARE(worker.busyWith(), std::optional<std::uint64_t>(slowKey));
    const std::uint64_t nextKey = worker.request(next, nextSettings);
    QVERIFY(nextKey != slowKey);
    QCOMPARE(worker.busyWith(), std::optional<std::uint64_t>(nextKey));
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 60000);
    QCOMPARE(finished.at(0).first().toULongLong(), quint64(slowKey));
    QCOMPARE(finished.at(1).first().toULongLong(), quint64(nextKey));
    const auto cancelled = worker.take(slowKey);
    QVERIFY(cancelled);
    QVERIFY(cancelled->stats.cancelled);
    QVERIFY(!cancelled->textures);
    QCOMPARE(cancelled->error, std::string("IblPrecompute::prepare: cancelled"));
    const auto done = worker.take(nextKey);
    QVERIFY(done && done->textures && !done->stats.cancelled);
    QVERIFY(!worker.busyWith());
    // Nothing of the cancelled set was cached; the finished one was.
    QVERIFY(!IblDiskCache(cache.path()).load(slowKey, nullptr));
    QVERIFY(IblDiskCache(cache.path()).load(nextKey, nullptr));
}

void LightingWorkerUiTest::theSameRequestRunsOnce()
{
    QVERIFY(m_view->makeCurrent(&m_surface));
    const Environment environment = gradientEnvironment(2.0f);
    const IblSettings settings = *IblSettings::preset("draft");
    LightingWorker worker({}, /*useDiskCache=*/false);
    QVERIFY2(worker.isValid(), qPrintable(worker.problem()));
    QSignalSpy finished(&worker, &LightingWorker::finished);
    const std::uint64_t key = worker.request(environment, settings);
    QCOMPARE(worker.request(environment, settings), key); // queued or running: not again
    QCOMPARE(worker.request(environment, settings), key);
    QVERIFY(finished.wait(60000));
    QTest::qWait(200);
    QCOMPARE(finished.count(), 1);
    const auto result = worker.take(key);
    QVERIFY(result && result->textures);
    QCOMPARE(result->stats.passesRun, 3);
}

void LightingWorkerUiTest::queuedSetsRunInOrderAndCancelNothing()
{
    // The Compare view's way: every set of a grid is wanted. Queued while the first runs, they
    // run after it in order, none is cancelled, and one asked for again is not repeated.
    QVERIFY(m_view->makeCurrent(&m_surface));
    const IblSettings settings = *IblSettings::preset("draft");
    const std::vector<Environment> environments
        = {gradientEnvironment(5.0f), gradientEnvironment(6.0f), gradientEnvironment(7.0f)};
    LightingWorker worker({}, /*useDiskCache=*/false);
    QVERIFY2(worker.isValid(), qPrintable(worker.problem()));
    QSignalSpy finished(&worker, &LightingWorker::finished);
    std::vector<std::uint64_t> keys;
    for (const Environment& environment : environments)
        keys.push_back(worker.enqueue(environment, settings));
    QCOMPARE(worker.enqueue(environments[1], settings), keys[1]); // queued: not again
    QCOMPARE(worker.enqueue(environments[0], settings), keys[0]); // running or queued: not again
    QCOMPARE(worker.busyWith(), std::optional<std::uint64_t>(keys[2])); // the last queued
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 3, 60000);
    QTest::qWait(200);
    QCOMPARE(finished.count(), 3);
    for (std::size_t i = 0; i < keys.size(); ++i) {
        QCOMPARE(finished.at(int(i)).first().toULongLong(), quint64(keys[i]));
        const auto result = worker.take(keys[i]);
        QVERIFY(result && result->textures);
        QVERIFY(!result->stats.cancelled);
        QCOMPARE(result->stats.passesRun, 3);
    }
    QVERIFY(!worker.busyWith());
}

void LightingWorkerUiTest::aRequestEmptiesTheQueue()
{
    // The single view's way after a grid's: newest wins, the sets queued before are dropped and
    // the one running is cancelled.
    QVERIFY(m_view->makeCurrent(&m_surface));
    LightingWorker worker({}, /*useDiskCache=*/false);
    QVERIFY2(worker.isValid(), qPrintable(worker.problem()));
    QSignalSpy finished(&worker, &LightingWorker::finished);
    QSignalSpy progress(&worker, &LightingWorker::progress);
    const IblSettings draft = *IblSettings::preset("draft");
    const std::uint64_t slowKey = worker.enqueue(gradientEnvironment(8.0f), slowSettings());
    const std::uint64_t queuedKey = worker.enqueue(gradientEnvironment(9.0f), draft);
    QVERIFY(progress.wait(60000)); // the first runs
    const std::uint64_t wantedKey = worker.request(gradientEnvironment(10.0f), draft);
    QCOMPARE(worker.busyWith(), std::optional<std::uint64_t>(wantedKey));
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 2, 60000);
    QTest::qWait(200);
    QCOMPARE(finished.count(), 2);
    QCOMPARE(finished.at(0).first().toULongLong(), quint64(slowKey));
    QCOMPARE(finished.at(1).first().toULongLong(), quint64(wantedKey));
    const auto cancelled = worker.take(slowKey);
    QVERIFY(cancelled && cancelled->stats.cancelled && !cancelled->textures);
    QVERIFY(!worker.take(queuedKey)); // never ran
    const auto done = worker.take(wantedKey);
    QVERIFY(done && done->textures);
}

void LightingWorkerUiTest::failureIsNamed()
{
    QVERIFY(m_view->makeCurrent(&m_surface));
    LightingWorker worker({}, /*useDiskCache=*/false);
    QVERIFY2(worker.isValid(), qPrintable(worker.problem()));
    QSignalSpy finished(&worker, &LightingWorker::finished);
    const std::uint64_t key = worker.request(Environment(), IblSettings {});
    QVERIFY(finished.wait(60000));
    const auto result = worker.take(key);
    QVERIFY(result);
    QVERIFY(!result->textures);
    QVERIFY(!result->stats.cancelled);
    QCOMPARE(result->error, std::string("IblPrecompute::prepare: the environment has no image"));
}

void LightingWorkerUiTest::destroyedWhileRunningReturnsPromptly()
{
    QVERIFY(m_view->makeCurrent(&m_surface));
    auto worker = std::make_unique<LightingWorker>(QString(), /*useDiskCache=*/false);
    QVERIFY2(worker->isValid(), qPrintable(worker->problem()));
    QSignalSpy progress(worker.get(), &LightingWorker::progress);
    worker->request(gradientEnvironment(3.0f), slowSettings());
    QVERIFY(progress.wait(60000));
    QElapsedTimer clock;
    clock.start();
    worker.reset(); // cancels after the face running, frees its objects in its own context
    const qint64 ms = clock.elapsed();
    qInfo("destroyed %lld ms after a progress report of a set of several seconds", ms);
    QVERIFY2(ms < 1000, qPrintable(QStringLiteral("%1 ms").arg(ms)));
    // The view's context is still good.
    QVERIFY(m_view->makeCurrent(&m_surface));
    QCOMPARE(glGetError(), GLenum(GL_NO_ERROR));
}

QTEST_MAIN(LightingWorkerUiTest)
#include "LightingWorkerUiTest.moc"
