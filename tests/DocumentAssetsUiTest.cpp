// ui/document/DocumentAssets, the window's asset cache: what needs no file (a built-in environment,
// uniform:V, a primitive mesh) is made at once; files load on a worker and arrive through
// assetArrived, once however many ask; a failure is named and not tried again until retry() or
// the file changes; a file changed on disk loads again, the previous version standing in
// meanwhile; entries no user names are dropped; an environment file read before (the environment
// index) arrives before its pixels are decoded, and environmentDecoded follows. Needs no display, but links
// ui/ (a UiTest).

#include "ui/document/DocumentAssets.h"

#include "TestSupport.h"
#include "core/image/MapImageCache.h"

#include <QDateTime>
#include <QFile>
#include <QFileInfo>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <limits>
#include <memory>
#include <string>

using namespace facet;
using Kind = DocumentAssets::Kind;

namespace {

bool writeTriangleObj(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return false;
    file.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\nf 1/1/1 2/2/1 3/3/1\n");
    return true;
}

// Moves the file's modification time by `seconds` (a changed file without waiting a second).
bool touch(const QString& path, int seconds)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadWrite))
        return false;
    const QDateTime modified = file.fileTime(QFileDevice::FileModificationTime).addSecs(seconds);
    return file.setFileTime(modified, QFileDevice::FileModificationTime);
}

} // namespace

class DocumentAssetsUiTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        // The environment index and the IBL cache in the test's folder, not the user's.
        qputenv("FACET_CACHE_DIR", m_dir.filePath(QStringLiteral("cache")).toUtf8());
    }
    void madeAtOnceWithoutAFile_data();
    void madeAtOnceWithoutAFile();
    void filesLoadOnAWorkerOnce_data();
    void filesLoadOnAWorkerOnce();
    void failureIsNamedAndNotRetriedUntilAsked();
    void retryTriesAnUnchangedFileAgain();
    void changedFileLoadsAgainPreviousStandsIn();
    void entriesNoUserNamesAreDropped();
    void indexedEnvironmentArrivesBeforeItsPixels();
    void mapPixelsReleasedThenReloaded();
    void mapWarningNamesSanitisedSamples();

private:
    QString path(const QString& name) const { return m_dir.filePath(name); }
    QTemporaryDir m_dir;
};

void DocumentAssetsUiTest::madeAtOnceWithoutAFile_data()
{
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("name");
    QTest::newRow("built-in studio") << int(Kind::Environment) << "studio";
    QTest::newRow("built-in sky") << int(Kind::Environment) << "sky";
    QTest::newRow("uniform") << int(Kind::Environment) << "uniform:0.5";
    QTest::newRow("sphere") << int(Kind::Mesh) << "sphere";
    QTest::newRow("shaderball") << int(Kind::Mesh) << "shaderball";
}

void DocumentAssetsUiTest::madeAtOnceWithoutAFile()
{
    QFETCH(int, kind);
    QFETCH(QString, name);
    DocumentAssets assets;
    QSignalSpy arrived(&assets, &DocumentAssets::assetArrived);
    const std::string n = name.toStdString();
    const bool made
        = Kind(kind) == Kind::Environment ? assets.environment(n) != nullptr : assets.mesh(n) != nullptr;
    QVERIFY(made);
    QVERIFY(!assets.isLoading(Kind(kind), n));
    QCOMPARE(assets.pendingLoads(), 0);
    QCOMPARE(arrived.count(), 0); // nothing to wait for, nothing announced
    // Asked again: the same entry, not made again.
    if (Kind(kind) == Kind::Environment)
        QVERIFY(assets.environment(n));
    else
        QVERIFY(assets.mesh(n));
    QCOMPARE(assets.loads(Kind(kind)), 1);
}

void DocumentAssetsUiTest::filesLoadOnAWorkerOnce_data()
{
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("file");
    QTest::newRow("environment EXR") << int(Kind::Environment) << "grey.exr";
    QTest::newRow("mesh OBJ") << int(Kind::Mesh) << "triangle.obj";
    QTest::newRow("map EXR") << int(Kind::Map) << "grey.exr";
}

void DocumentAssetsUiTest::filesLoadOnAWorkerOnce()
{
    QFETCH(int, kind);
    QFETCH(QString, file);
    QVERIFY(test::writeConstantExr(path(QStringLiteral("grey.exr")), 0.25f));
    QVERIFY(writeTriangleObj(path(QStringLiteral("triangle.obj"))));
    const std::string name = path(file).toStdString();
    DocumentAssets assets;
    QSignalSpy arrived(&assets, &DocumentAssets::assetArrived);
    const auto request = [&] {
        switch (Kind(kind)) {
        case Kind::Environment:
            return assets.environment(name) != nullptr;
        case Kind::Mesh:
            return assets.mesh(name) != nullptr;
        case Kind::Map:
            return assets.map(name) != nullptr;
        }
        return false;
    };
    // Three views ask before it arrives: one load.
    for (int view = 0; view < 3; ++view)
        QVERIFY(!request());
    QVERIFY(assets.isLoading(Kind(kind), name));
    QCOMPARE(assets.pendingLoads(), 1);
    assets.waitForLoads();
    QCOMPARE(arrived.count(), 1);
    QVERIFY(!assets.isLoading(Kind(kind), name));
    QVERIFY2(request(), assets.problem(Kind(kind), name).c_str());
    QVERIFY(assets.problem(Kind(kind), name).empty());
    QCOMPARE(assets.loads(Kind(kind)), 1);
    if (Kind(kind) == Kind::Environment)
        QCOMPARE(assets.environment(name)->image().at(3, 3).g, 0.25f);
    if (Kind(kind) == Kind::Mesh)
        QVERIFY(assets.mesh(name)->key != 0 && !assets.mesh(name)->mesh->vertices.empty());
}

void DocumentAssetsUiTest::failureIsNamedAndNotRetriedUntilAsked()
{
    const std::string missing = path(QStringLiteral("night.exr")).toStdString();
    DocumentAssets assets;
    QVERIFY(!assets.environment(missing));
    assets.waitForLoads();
    QVERIFY(!assets.environment(missing));
    QVERIFY(!assets.isLoading(Kind::Environment, missing));
    const std::string problem = assets.problem(Kind::Environment, missing);
    QVERIFY2(problem.find("night.exr") != std::string::npos, problem.c_str());
    QCOMPARE(assets.loads(Kind::Environment), 1); // asked again: not tried again
}

void DocumentAssetsUiTest::retryTriesAnUnchangedFileAgain()
{
    // A file that fails to read, then is mended without its modification time changing (a
    // restored backup, a slow network share): only retry() (choosing it again) reads it again.
    const QString file = path(QStringLiteral("mended.exr"));
    {
        QFile broken(file);
        QVERIFY(broken.open(QIODevice::WriteOnly));
        broken.write("not an EXR");
    }
    const QDateTime modified = QFileInfo(file).lastModified();
    const std::string name = file.toStdString();
    DocumentAssets assets;
    assets.environment(name);
    assets.waitForLoads();
    QVERIFY(!assets.environment(name));
    QVERIFY(!assets.problem(Kind::Environment, name).empty());
    QVERIFY(test::writeConstantExr(file, 0.5f));
    {
        QFile mended(file);
        QVERIFY(mended.open(QIODevice::ReadWrite));
        QVERIFY(mended.setFileTime(modified, QFileDevice::FileModificationTime));
    }
    QVERIFY(!assets.environment(name)); // same modification time: still the failure
    QCOMPARE(assets.loads(Kind::Environment), 1);
    assets.retry(Kind::Environment, name);
    QVERIFY(!assets.environment(name));
    assets.waitForLoads();
    QVERIFY(assets.environment(name));
    QCOMPARE(assets.loads(Kind::Environment), 2);
    QVERIFY(assets.problem(Kind::Environment, name).empty());
}

void DocumentAssetsUiTest::changedFileLoadsAgainPreviousStandsIn()
{
    const QString file = path(QStringLiteral("changing.exr"));
    QVERIFY(test::writeConstantExr(file, 0.25f));
    const std::string name = file.toStdString();
    DocumentAssets assets;
    assets.environment(name);
    assets.waitForLoads();
    QCOMPARE(assets.environment(name)->image().at(0, 0).r, 0.25f);
    QVERIFY(test::writeConstantExr(file, 0.75f));
    QVERIFY(touch(file, 5));
    // The previous version while the new one loads, then the new one.
    const auto standIn = assets.environment(name);
    QVERIFY(standIn);
    QCOMPARE(standIn->image().at(0, 0).r, 0.25f);
    QVERIFY(assets.isLoading(Kind::Environment, name));
    assets.waitForLoads();
    QCOMPARE(assets.environment(name)->image().at(0, 0).r, 0.75f);
    QCOMPARE(assets.loads(Kind::Environment), 2);
}

void DocumentAssetsUiTest::entriesNoUserNamesAreDropped()
{
    DocumentAssets assets;
    const int single = 0;
    const int compare = 0;
    for (const char* spec : {"uniform:0.1", "uniform:0.2", "uniform:0.3"})
        QVERIFY(assets.environment(spec));
    assets.setInUse(&compare, Kind::Environment, {"uniform:0.1", "uniform:0.2"}); // drops 0.3
    assets.setInUse(&single, Kind::Environment, {"uniform:0.1"});
    QCOMPARE(assets.loads(Kind::Environment), 3);
    // Named by a user: kept (no new load); named by none: made again.
    QVERIFY(assets.environment("uniform:0.1"));
    QVERIFY(assets.environment("uniform:0.2"));
    QCOMPARE(assets.loads(Kind::Environment), 3);
    QVERIFY(assets.environment("uniform:0.3"));
    QCOMPARE(assets.loads(Kind::Environment), 4);
    // The Compare view goes: what only it named goes with it.
    assets.setInUse(&single, Kind::Environment, {"uniform:0.1"});
    assets.forgetUser(&compare);
    QVERIFY(assets.environment("uniform:0.1"));
    QCOMPARE(assets.loads(Kind::Environment), 4);
    QVERIFY(assets.environment("uniform:0.2"));
    QCOMPARE(assets.loads(Kind::Environment), 5);
}

void DocumentAssetsUiTest::indexedEnvironmentArrivesBeforeItsPixels()
{
    const QString file = path(QStringLiteral("indexed.exr"));
    QVERIFY(test::writeConstantExr(file, 0.5f));
    QVERIFY(touch(file, -10)); // older than the index's 2 s "racy" window
    const std::string name = file.toStdString();
    {
        // The first load decodes it (and remembers its hash and size by the file's identity).
        DocumentAssets first;
        QSignalSpy decoded(&first, &DocumentAssets::environmentDecoded);
        QVERIFY(!first.environment(name));
        first.waitForLoads();
        QVERIFY(first.environment(name));
        QVERIFY(first.environment(name)->decoded());
        QCOMPARE(decoded.count(), 0); // arrived decoded: nothing follows
    }
    // A second document: the entry arrives with its hash and size, undecoded; the decode follows
    // on the pool and says so.
    DocumentAssets second;
    QSignalSpy arrived(&second, &DocumentAssets::assetArrived);
    QSignalSpy decoded(&second, &DocumentAssets::environmentDecoded);
    QVERIFY(!second.environment(name));
    QVERIFY(arrived.wait(20000));
    const std::shared_ptr<const Environment> environment = second.environment(name);
    QVERIFY(environment);
    QCOMPARE(environment->width(), 16);
    QVERIFY(decoded.count() == 1 || decoded.wait(20000));
    QCOMPARE(decoded.first().first().toULongLong(), quint64(environment->contentHash()));
    QVERIFY(environment->decoded());
    QCOMPARE(environment->image().at(3, 3).g, 0.5f);
}

QTEST_GUILESS_MAIN(DocumentAssetsUiTest)
#include "DocumentAssetsUiTest.moc"

void DocumentAssetsUiTest::mapPixelsReleasedThenReloaded()
{
    const QString file = path(QStringLiteral("released.exr"));
    QVERIFY(test::writeConstantExr(file, 0.5f));
    const std::string name = file.toStdString();
    DocumentAssets assets;
    assets.map(name);
    assets.waitForLoads();
    std::shared_ptr<const MapImage> image = assets.map(name);
    QVERIFY(image && image->hasPixels());
    QCOMPARE(assets.mapTimestamp(name), QFileInfo(file).lastModified().toMSecsSinceEpoch());

    // Only the current entry is released; a copy the cache no longer holds is left alone.
    const MapImage other = *image;
    QVERIFY(!assets.releaseMapPixels(name, &other));
    const std::shared_ptr<const MapImage> standIn = assets.releaseMapPixels(name, image.get());
    QVERIFY(standIn && !standIn->hasPixels());
    QCOMPARE(standIn->width(), image->width());
    QCOMPARE(assets.map(name), standIn);
    QVERIFY(!assets.releaseMapPixels(name, standIn.get())); // nothing left to release
    image.reset();
    QVERIFY(!MapImageCache::shared().isHeld(name)); // the pixels are gone

    // Asked for again: the stand-in meanwhile, then a new decode with pixels.
    assets.reload(Kind::Map, name);
    QCOMPARE(assets.map(name), standIn);
    QVERIFY(assets.isLoading(Kind::Map, name));
    assets.waitForLoads();
    QVERIFY(assets.map(name)->hasPixels());
    QCOMPARE(assets.loads(Kind::Map), 2);
    QCOMPARE(assets.map(name)->width(), standIn->width());
    QCOMPARE(assets.loads(Kind::Map), 2); // once reloaded, current again
}

void DocumentAssetsUiTest::mapWarningNamesSanitisedSamples()
{
    const QString clean = path(QStringLiteral("clean.exr"));
    const QString dirty = path(QStringLiteral("nan.exr"));
    QVERIFY(test::writeConstantExr(clean, 0.5f));
    QVERIFY(test::writeConstantExr(dirty, std::numeric_limits<float>::quiet_NaN()));
    DocumentAssets assets;
    assets.map(clean.toStdString());
    assets.map(dirty.toStdString());
    assets.waitForLoads();
    QVERIFY(assets.map(dirty.toStdString()));
    QCOMPARE(assets.warning(Kind::Map, clean.toStdString()), std::string());
    const std::string warning = assets.warning(Kind::Map, dirty.toStdString());
    QVERIFY2(warning.find("nan.exr: replaced") != std::string::npos, warning.c_str());
}
