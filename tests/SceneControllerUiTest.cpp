// SceneController (ui/viewport/SceneController.h) redoes only what a change names
// (ui/document/DocumentChanges.h): a new file in one slot of one material decodes that file and nothing else,
// even when the other materials' files changed on disk unnoticed (they are not even looked at); a change that
// names no slot (files changed on disk) looks at every file; and a frame is asked for only when the frame
// shows what changed (not a name, not a material no visible part shows, not a light that stays
// off, not which material the docks edit). Decodes are counted by core/image/MapImageCache. Environment
// and mesh files load off the GUI thread (ui/document/DocumentAssets): the previous ones stay drawn until
// they arrive, and one frame follows the arrival.
// No window: a Document and a SceneController. It links facet_ui, hence "Ui" (runs under
// with-display.sh but opens nothing).

#include "TestSupport.h"
#include "core/image/MapImageCache.h"
#include "core/project/Project.h"
#include "ui/document/Document.h"
#include "ui/document/DocumentAssets.h"
#include "ui/viewport/SceneController.h"

#include <QDateTime>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <OpenImageIO/imageio.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

using namespace facet;

Q_DECLARE_METATYPE(std::function<void(facet::Document&)>)

namespace {

// A small 8-bit RGB PNG of one colour.
bool writeFlatPng(const std::string& path, int r, int g, int b)
{
    constexpr int kSize = 8;
    std::vector<unsigned char> pixels(std::size_t(kSize * kSize * 3));
    for (std::size_t i = 0; i < pixels.size(); i += 3) {
        pixels[i] = static_cast<unsigned char>(r);
        pixels[i + 1] = static_cast<unsigned char>(g);
        pixels[i + 2] = static_cast<unsigned char>(b);
    }
    auto output = OIIO::ImageOutput::create(path);
    OIIO::ImageSpec spec(kSize, kSize, 3, OIIO::TypeDesc::UINT8);
    return output && output->open(path, spec) && output->write_image(OIIO::TypeDesc::UINT8, pixels.data())
        && output->close();
}

// Gives the file a later modification time, as an image editor saving it would.
bool touch(const std::string& path, int seconds)
{
    QFile file(QString::fromStdString(path));
    return file.open(QIODevice::ReadWrite)
        && file.setFileTime(QDateTime::currentDateTime().addSecs(seconds), QFileDevice::FileModificationTime);
}

} // namespace

class SceneControllerUiTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void oneMapChangeDecodesThatFileOnly_data();
    void oneMapChangeDecodesThatFileOnly();
    void frameOnlyForWhatIsDrawn_data();
    void frameOnlyForWhatIsDrawn();
    void environmentAndMeshFilesLoadOffTheGuiThread_data();
    void environmentAndMeshFilesLoadOffTheGuiThread();
    void changedFileChosenAgainShowsItsNewVersion();
    void viewsShareOneMapLoader();
    void releasedPixelsLeaveTheSharedCacheToo();
    void aMissingMapIsSaidOnceUntilChosenAgain();

private:
    // Two materials, each with a file in base colour, normal and roughness (six files).
    Project texturedProject() const;
    std::string file(const std::string& name) const
    {
        return m_dir.filePath(QString::fromStdString(name)).toStdString();
    }

    QTemporaryDir m_dir;
};

void SceneControllerUiTest::initTestCase()
{
    QVERIFY(m_dir.isValid());
    for (const char* name : {"m0_base.png", "m0_normal.png", "m0_rough.png", "m1_base.png", "m1_normal.png",
             "m1_rough.png", "new_normal.png", "new_base.png"})
        QVERIFY(writeFlatPng(file(name), 100, 150, 200));
}

Project SceneControllerUiTest::texturedProject() const
{
    Project project = Project::defaultProject();
    Material second = project.materials[0];
    second.name = "Second";
    project.materials.push_back(second);
    for (std::size_t m = 0; m < 2; ++m) {
        const std::string prefix = "m" + std::to_string(m) + "_";
        project.materials[m].map(MapSlot::BaseColor).path = file(prefix + "base.png");
        project.materials[m].map(MapSlot::Normal).path = file(prefix + "normal.png");
        project.materials[m].map(MapSlot::Roughness).path = file(prefix + "rough.png");
    }
    return project;
}

void SceneControllerUiTest::oneMapChangeDecodesThatFileOnly_data()
{
    // An edit (or a notification), and the files it must decode. Before it, every file of
    // material 0 is rewritten on disk without anyone being told.
    QTest::addColumn<std::function<void(Document&)>>("edit");
    QTest::addColumn<QStringList>("decoded");

    const auto setMap = [](std::size_t m, MapSlot slot, std::function<void(MaterialMap&)> change) {
        return std::function<void(Document&)>([m, slot, change](Document& document) {
            Project project = document.project();
            change(project.materials[m].map(slot));
            document.setProject(project, QStringLiteral("Edit"));
        });
    };
    const std::string newNormal = file("new_normal.png");
    const std::string newBase = file("new_base.png");
    QTest::newRow("material 1 normal map")
        << setMap(1, MapSlot::Normal, [newNormal](MaterialMap& map) { map.path = newNormal; })
        << QStringList {QStringLiteral("new_normal.png")};
    QTest::newRow("material 0 base colour map")
        << setMap(0, MapSlot::BaseColor, [newBase](MaterialMap& map) { map.path = newBase; })
        << QStringList {QStringLiteral("new_base.png")};
    QTest::newRow("material 1 roughness colour space")
        << setMap(1, MapSlot::Roughness, [](MaterialMap& map) { map.colorSpace = ColorEncoding::SRGB; })
        << QStringList {};
    QTest::newRow("material 1 roughness factor")
        << setMap(1, MapSlot::Roughness, [](MaterialMap& map) { map.factor = glm::dvec4(0.25); })
        << QStringList {};
    // Kinds alone name no slot: every file is looked at, the rewritten ones are decoded again.
    QTest::newRow("files changed on disk")
        << std::function<void(Document&)>(
               [](Document& document) { document.notifyFilesChangedOnDisk(DocumentChange::MaterialMaps); })
        << QStringList {QStringLiteral("m0_base.png"), QStringLiteral("m0_normal.png"),
               QStringLiteral("m0_rough.png")};
}

void SceneControllerUiTest::oneMapChangeDecodesThatFileOnly()
{
    QFETCH(std::function<void(Document&)>, edit);
    QFETCH(QStringList, decoded);

    Document document;
    document.setProject(texturedProject(), QStringLiteral("Maps"));
    SceneController scene(&document);
    QTRY_COMPARE_WITH_TIMEOUT(scene.pendingMapLoads(), 0, 30000);
    const char* names[] = {"m0_base.png", "m0_normal.png", "m0_rough.png", "m1_base.png", "m1_normal.png",
        "m1_rough.png", "new_normal.png", "new_base.png"};
    // Every file shown is in memory (decoded once, held by the controller).
    for (const char* name : names)
        if (QByteArray(name).startsWith("m"))
            QVERIFY2(MapImageCache::shared().isHeld(file(name)), name);

    static int later = 10; // a later time for every row: the cache must see a new file each time
    later += 10;
    for (const char* name : {"m0_base.png", "m0_normal.png", "m0_rough.png"})
        QVERIFY(touch(file(name), later));
    std::map<std::string, std::uint64_t> before;
    for (const char* name : names)
        before[name] = MapImageCache::shared().decodeCount(file(name));
    const int loadsBefore = scene.loadCounts().maps;

    edit(document);
    QTRY_COMPARE_WITH_TIMEOUT(scene.pendingMapLoads(), 0, 30000);

    for (const char* name : names) {
        const std::uint64_t expected = before[name] + (decoded.contains(QLatin1String(name)) ? 1 : 0);
        QVERIFY2(MapImageCache::shared().decodeCount(file(name)) == expected,
            qPrintable(QStringLiteral("%1 decoded %2 times, expected %3")
                           .arg(QLatin1String(name))
                           .arg(MapImageCache::shared().decodeCount(file(name)) - before[name])
                           .arg(expected - before[name])));
    }
    QCOMPARE(scene.loadCounts().maps - loadsBefore, int(decoded.size()));
}

void SceneControllerUiTest::frameOnlyForWhatIsDrawn_data()
{
    QTest::addColumn<std::function<void(Document&)>>("edit");
    QTest::addColumn<bool>("frame");

    const auto project = [](std::function<void(Project&)> change) {
        return std::function<void(Document&)>([change](Document& document) {
            Project after = document.project();
            change(after);
            document.setProject(after, QStringLiteral("Edit"));
        });
    };
    // The sphere is one part, and it shows material 0; material 1 is shown by nothing.
    QTest::newRow("material 0 roughness")
        << project([](Project& p) { p.materials[0].setFactor(MapSlot::Roughness, 0.9); }) << true;
    QTest::newRow("material 0 name") << project([](Project& p) { p.materials[0].name = "Renamed"; }) << false;
    QTest::newRow("material 1 roughness (not shown)")
        << project([](Project& p) { p.materials[1].setFactor(MapSlot::Roughness, 0.9); }) << false;
    QTest::newRow("material 1 shading (not shown)")
        << project([](Project& p) { p.materials[1].shading.multiScatter = false; }) << false;
    QTest::newRow("the part shows material 1") << project([](Project& p) {
        p.parts = {{"sphere", 1, true}};
    }) << true;
    QTest::newRow("material 1 roughness, shown") << project([](Project& p) {
        p.parts = {{"sphere", 1, true}};
        p.materials[1].setFactor(MapSlot::Roughness, 0.9);
    }) << true;
    QTest::newRow("material appended")
        << project([](Project& p) { p.materials.push_back(Material {}); }) << true;
    QTest::newRow("light 0 name") << project([](Project& p) { p.lights[0].name = "Renamed"; }) << false;
    QTest::newRow("light 0 intensity") << project([](Project& p) { p.lights[0].intensity = 7.0; }) << true;
    QTest::newRow("light 1 (off) intensity")
        << project([](Project& p) { p.lights[1].intensity = 7.0; }) << false;
    QTest::newRow("light 1 switched on") << project([](Project& p) { p.lights[1].enabled = true; }) << true;
    QTest::newRow("light removed") << project([](Project& p) { p.lights.pop_back(); }) << true;
    QTest::newRow("exposure") << project([](Project& p) { p.view.exposureEV = 1.0; }) << true;
    QTest::newRow("environment rotation")
        << project([](Project& p) { p.environment.rotationDegrees = 30; }) << true;
    QTest::newRow("current material")
        << std::function<void(Document&)>([](Document& document) { document.setCurrentMaterial(1); })
        << false;
    // The compare layout is the Compare view's to draw, not the single view's.
    QTest::newRow("compare layout") << project([](Project& p) { p.compare.ab.split = 0.25; }) << false;
    QTest::newRow("camera") << std::function<void(Document&)>([](Document& document) {
        Camera camera = document.project().camera;
        camera.position.x += 1.0;
        document.setCamera(camera);
    }) << true;
}

void SceneControllerUiTest::frameOnlyForWhatIsDrawn()
{
    QFETCH(std::function<void(Document&)>, edit);
    QFETCH(bool, frame);

    Document document;
    Project start = Project::defaultProject();
    Material second = start.materials[0];
    second.name = "Second";
    start.materials.push_back(second);
    Light on = Light::defaultDirectional();
    Light off = on;
    off.enabled = false;
    start.lights = {on, off};
    document.setProject(start, QStringLiteral("Start"));
    SceneController scene(&document);
    QSignalSpy sceneChanged(&scene, &SceneController::sceneChanged);

    edit(document);
    QCOMPARE(sceneChanged.count(), frame ? 1 : 0);
}

void SceneControllerUiTest::environmentAndMeshFilesLoadOffTheGuiThread_data()
{
    QTest::addColumn<bool>("environment"); // else the mesh
    QTest::addColumn<QString>("file");
    QTest::addColumn<bool>("readable");
    QTest::newRow("environment EXR") << true << "sky.exr" << true;
    QTest::newRow("environment missing") << true << "gone.exr" << false;
    QTest::newRow("mesh OBJ") << false << "tri.obj" << true;
    QTest::newRow("mesh missing") << false << "gone.obj" << false;
}

void SceneControllerUiTest::environmentAndMeshFilesLoadOffTheGuiThread()
{
    QFETCH(bool, environment);
    QFETCH(QString, file);
    QFETCH(bool, readable);
    const std::string path = this->file(file.toStdString());
    if (readable && environment)
        QVERIFY(test::writeConstantExr(QString::fromStdString(path), 0.5f));
    if (readable && !environment) {
        QFile obj(QString::fromStdString(path));
        QVERIFY(obj.open(QIODevice::WriteOnly));
        obj.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    }
    Document document;
    SceneController scene(&document);
    QVERIFY(scene.hasScene()); // the default project: built-in studio and sphere, made at once
    const std::uint64_t iblKey = scene.iblKey();
    const std::uint64_t meshKey = scene.assets().meshKey;
    QSignalSpy sceneChanged(&scene, &SceneController::sceneChanged);
    QSignalSpy messages(&scene, &SceneController::message);

    Project project = document.project();
    (environment ? project.environment.source : project.view.mesh) = path;
    document.setProject(project, QStringLiteral("Change"));
    // The edit returned before the file was read: the previous one is drawn meanwhile, and the
    // status bar says what is loading.
    QCOMPARE(scene.pendingAssetLoads(), 1);
    QVERIFY(scene.hasScene());
    QCOMPARE(scene.iblKey(), iblKey);
    QCOMPARE(scene.assets().meshKey, meshKey);
    QVERIFY(!messages.isEmpty());
    QVERIFY2(
        messages.last().first().toString().contains(file), qPrintable(messages.last().first().toString()));
    const int framesBefore = sceneChanged.count();

    scene.documentAssets()->waitForLoads();
    QCOMPARE(scene.pendingAssetLoads(), 0);
    if (readable) {
        QCOMPARE(sceneChanged.count(), framesBefore + 1); // the frame that shows it
        if (environment)
            QVERIFY(scene.iblKey() != iblKey && scene.environmentName() == file);
        else
            QVERIFY(scene.assets().meshKey != meshKey);
        QVERIFY(scene.environmentProblem().isEmpty());
    } else {
        QCOMPARE(sceneChanged.count(), framesBefore + 1); // the settled frame: the previous one stays
        QCOMPARE(scene.iblKey(), iblKey);
        QCOMPARE(scene.assets().meshKey, meshKey);
        QVERIFY2(messages.last().first().toString().contains(file),
            qPrintable(messages.last().first().toString()));
        if (environment)
            QVERIFY(scene.environmentProblem().contains(file));
    }
    QCOMPARE(scene.loadCounts().environments, environment ? 2 : 1);
    QCOMPARE(scene.loadCounts().meshes, environment ? 1 : 2);
}

void SceneControllerUiTest::changedFileChosenAgainShowsItsNewVersion()
{
    // Another view (a grid cell) keeps X in the document's cache. X changes on disk; the single
    // view chooses another environment and then X again: the previous version of X shows at once
    // and the new one replaces it when it arrives.
    const QString x = QString::fromStdString(file("changing.exr"));
    QVERIFY(test::writeConstantExr(x, 0.25f));
    Document document;
    SceneController scene(&document);
    const int cell = 0;
    scene.documentAssets()->setInUse(&cell, DocumentAssets::Kind::Environment, {x.toStdString()});
    const auto choose = [&document](const std::string& source) {
        Project project = document.project();
        project.environment.source = source;
        document.setProject(project, QStringLiteral("Choose"));
    };
    choose(x.toStdString());
    scene.documentAssets()->waitForLoads();
    QCOMPARE(scene.assets().environment.image().at(0, 0).r, 0.25f);
    choose("uniform:0.5");
    QVERIFY(test::writeConstantExr(x, 0.75f));
    {
        QFile changed(x);
        QVERIFY(changed.open(QIODevice::ReadWrite));
        QVERIFY(changed.setFileTime(changed.fileTime(QFileDevice::FileModificationTime).addSecs(5),
            QFileDevice::FileModificationTime));
    }
    choose(x.toStdString());
    QCOMPARE(scene.assets().environment.image().at(0, 0).r, 0.25f); // the previous version, at once
    QCOMPARE(scene.pendingAssetLoads(), 1);
    const std::uint64_t staleKey = scene.iblKey();
    QSignalSpy sceneChanged(&scene, &SceneController::sceneChanged);
    scene.documentAssets()->waitForLoads();
    QCOMPARE(scene.pendingAssetLoads(), 0);
    QCOMPARE(scene.assets().environment.image().at(0, 0).r, 0.75f);
    QVERIFY(scene.iblKey() != staleKey);
    QCOMPARE(sceneChanged.count(), 1);
}

QTEST_GUILESS_MAIN(SceneControllerUiTest)
#include "SceneControllerUiTest.moc"

void SceneControllerUiTest::viewsShareOneMapLoader()
{
    // Two views of one document (the single view and the Compare view's controller) over the
    // window's asset cache: the maps load once, through the cache, and the second view takes
    // the first's images at once (the window had two map loaders before: this read 0 loads).
    Document document;
    document.setProject(texturedProject(), QStringLiteral("Maps"));
    DocumentAssets assets;
    SceneController first(&document, &assets);
    QCOMPARE(first.pendingMapLoads(), 6);
    QTRY_COMPARE_WITH_TIMEOUT(first.pendingMapLoads(), 0, 30000);
    QCOMPARE(assets.loads(DocumentAssets::Kind::Map), 6);
    QCOMPARE(first.loadCounts().maps, 6);

    QSignalSpy arrived(&first, &SceneController::mapsArrived);
    SceneController second(&document, &assets);
    QCOMPARE(second.pendingMapLoads(), 0); // there at once, from the cache
    QCOMPARE(second.loadCounts().maps, 0);
    QCOMPARE(assets.loads(DocumentAssets::Kind::Map), 6);
    for (std::size_t m = 0; m < 2; ++m)
        for (MapSlot slot : {MapSlot::BaseColor, MapSlot::Normal, MapSlot::Roughness}) {
            const LoadedMapImage& a = first.assets().maps[m][std::size_t(slot)];
            const LoadedMapImage& b = second.assets().maps[m][std::size_t(slot)];
            QVERIFY(a.image && a.image == b.image); // one decoded copy
            QCOMPARE(a.timestamp, b.timestamp); // one texture key
            QVERIFY(a.timestamp != 0);
        }

    // A new file for one slot: one load, and the other view takes it on arrival, not again.
    Project project = document.project();
    project.materials[1].map(MapSlot::Normal).path = file("new_normal.png");
    document.setProject(project, QStringLiteral("New normal"));
    QTRY_COMPARE_WITH_TIMEOUT(first.pendingMapLoads() + second.pendingMapLoads(), 0, 30000);
    QCOMPARE(assets.loads(DocumentAssets::Kind::Map), 7);
    QCOMPARE(first.assets().maps[1][std::size_t(MapSlot::Normal)].image,
        second.assets().maps[1][std::size_t(MapSlot::Normal)].image);
    QVERIFY(first.assets().maps[1][std::size_t(MapSlot::Normal)].image);
    QVERIFY(arrived.count() > 0);
}

void SceneControllerUiTest::releasedPixelsLeaveTheSharedCacheToo()
{
    // After upload the view keeps a stand-in without pixels, and so does the asset cache: the
    // decoded copy is freed (MapImageCache holds it weakly). A view without the texture asks for
    // it again (reloadMaps): one decode, and it arrives.
    Document document;
    Project project = Project::defaultProject();
    project.material().map(MapSlot::BaseColor).path = file("m0_base.png");
    project.material().map(MapSlot::Roughness).path = file("m0_rough.png");
    document.setProject(project, QStringLiteral("Maps"));
    DocumentAssets assets;
    SceneController scene(&document, &assets);
    QTRY_COMPARE_WITH_TIMEOUT(scene.pendingMapLoads(), 0, 30000);
    QVERIFY(MapImageCache::shared().isHeld(file("m0_base.png")));

    // On the GPU in every colour space: both released.
    QCOMPARE(scene.releaseMapPixels([](const std::string&, std::int64_t, ColorEncoding) { return true; }), 2);
    QCOMPARE(scene.releaseMapPixels([](const std::string&, std::int64_t, ColorEncoding) { return true; }), 0);
    for (const char* name : {"m0_base.png", "m0_rough.png"}) {
        QVERIFY2(!MapImageCache::shared().isHeld(file(name)), name);
        const std::shared_ptr<const MapImage> cached = assets.map(file(name));
        QVERIFY(cached && !cached->hasPixels());
        QCOMPARE(cached->width(), 8); // the stand-in keeps the size and format
    }
    QVERIFY(scene.assets().maps[0][std::size_t(MapSlot::BaseColor)].image
        == assets.map(file("m0_base.png"))); // one stand-in for the view and the cache

    // A new GL context: decoded again, once, then shown with its pixels.
    const std::uint64_t decodes = MapImageCache::shared().decodeCount(file("m0_base.png"));
    scene.reloadMaps({file("m0_base.png")});
    QCOMPARE(scene.pendingMapLoads(), 1);
    QTRY_COMPARE_WITH_TIMEOUT(scene.pendingMapLoads(), 0, 30000);
    QCOMPARE(MapImageCache::shared().decodeCount(file("m0_base.png")), decodes + 1);
    QVERIFY(scene.assets().maps[0][std::size_t(MapSlot::BaseColor)].image->hasPixels());
    QVERIFY(!scene.assets().maps[0][std::size_t(MapSlot::Roughness)].image->hasPixels());
}

void SceneControllerUiTest::aMissingMapIsSaidOnceUntilChosenAgain()
{
    // A slot whose file is missing is named once (status bar and problem bar); files changing on
    // disk elsewhere look at it again without saying it again; choosing it again says it again.
    Document document;
    Project project = Project::defaultProject();
    project.material().map(MapSlot::BaseColor).path = file("m0_base.png");
    project.material().map(MapSlot::Normal).path = file("missing_normal.png");
    document.setProject(project, QStringLiteral("Maps"));
    SceneController scene(&document);
    QSignalSpy messages(&scene, &SceneController::message);
    QSignalSpy problems(&scene, &SceneController::problemChanged);
    QTRY_COMPARE_WITH_TIMEOUT(scene.pendingMapLoads(), 0, 30000);
    const auto saidMissing = [&] {
        int count = 0;
        for (const QList<QVariant>& arguments : messages)
            if (arguments.at(0).toString().contains(QStringLiteral("missing_normal.png")))
                ++count;
        return count;
    };
    QCOMPARE(saidMissing(), 1);
    QVERIFY(!scene.mapProblem(0, MapSlot::Normal).empty());
    const int problemsBefore = problems.count();

    for (int round = 0; round < 2; ++round) {
        document.notifyFilesChangedOnDisk(DocumentChange::MaterialMaps);
        QTRY_COMPARE_WITH_TIMEOUT(scene.pendingMapLoads(), 0, 30000);
        QCoreApplication::processEvents();
    }
    QCOMPARE(saidMissing(), 1);
    QCOMPARE(problems.count(), problemsBefore);
    QVERIFY(!scene.mapProblem(0, MapSlot::Normal).empty());

    // A material added in front moves the textured one to index 1 (reported as changed in full):
    // its maps are not chosen again, so nothing is said again.
    Project moved = document.project();
    Material added = moved.materials[0];
    added.name = "Added";
    added.map(MapSlot::BaseColor).path.clear();
    added.map(MapSlot::Normal).path.clear();
    moved.materials.insert(moved.materials.begin(), added);
    document.setProject(moved, QStringLiteral("Add a material in front"));
    QTRY_COMPARE_WITH_TIMEOUT(scene.pendingMapLoads(), 0, 30000);
    QCoreApplication::processEvents();
    QCOMPARE(saidMissing(), 1);
    QVERIFY(!scene.mapProblem(1, MapSlot::Normal).empty());
    moved.materials.erase(moved.materials.begin());
    document.setProject(moved, QStringLiteral("Remove it"));
    QTRY_COMPARE_WITH_TIMEOUT(scene.pendingMapLoads(), 0, 30000);

    // Chosen again (the same file): tried and said again.
    Project again = document.project();
    again.material().map(MapSlot::Normal).path.clear();
    document.setProject(again, QStringLiteral("Clear"));
    again.material().map(MapSlot::Normal).path = file("missing_normal.png");
    document.setProject(again, QStringLiteral("Choose again"));
    QTRY_COMPARE_WITH_TIMEOUT(scene.pendingMapLoads(), 0, 30000);
    QTRY_COMPARE_WITH_TIMEOUT(saidMissing(), 2, 10000);
}
