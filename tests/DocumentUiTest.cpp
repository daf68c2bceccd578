// The Document (ui/document/Document.h): every edit is one undo step with the right change description
// (what changesBetween works out is checked row by row in DocumentChangesTest), a slider
// drag merges into one step, a drag back to the start leaves no step, camera moves stay off the
// stack, the modified state follows the undo stack, and save/reopen gives the same project.
// Needs no display (QUndoStack is QtGui but opens no window); it links facet_ui, hence "Ui".

#include "ui/document/Document.h"
#include "ui/document/DocumentCommands.h"

#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest/QTest>

#include <functional>

using namespace facet;

Q_DECLARE_METATYPE(facet::DocumentChanges)
Q_DECLARE_METATYPE(std::function<void(facet::Project&)>)

namespace facet {
// QCOMPARE prints the descriptions of both sides when they differ.
char* toString(const DocumentChanges& changes)
{
    return QTest::toString(describe(changes).c_str());
}
} // namespace facet

namespace {

DocumentChanges lastChanges(const QSignalSpy& spy)
{
    return spy.isEmpty() ? DocumentChanges() : spy.last().at(0).value<DocumentChanges>();
}

Material withRoughness(const Document& document, double roughness)
{
    Material material = document.project().material();
    material.setFactor(MapSlot::Roughness, roughness);
    return material;
}

} // namespace

class DocumentUiTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void startsOnDefaultProjectUnmodified();
    void editUndoRedo();
    void unchangedValuePushesNothing();
    void changeFlagsOfHelpers();
    void dragMergesIntoOneStep();
    void separateDragsAreSeparateSteps();
    void dragBackToStartLeavesNoStep();
    void noMergeOutsideInteraction();
    void cameraIsNotUndoable();
    void invalidEditIsRejected();
    void presetKeepsTextures();
    void modifiedFollowsUndoStack();
    void saveAndReopenGiveSameProject();
    void openFailureChangesNothing();
    void missingFilesAndRelink();
    void missingFilesRecheckedByEditsThatNameFiles_data();
    void missingFilesRecheckedByEditsThatNameFiles();
    void recoveryFileRoundTrip();
    void newProjectResets();
};

void DocumentUiTest::startsOnDefaultProjectUnmodified()
{
    Document document;
    QCOMPARE(document.project(), Project::defaultProject());
    QVERIFY(!document.isModified());
    QVERIFY(document.filePath().isEmpty());
    QCOMPARE(document.displayName(), QStringLiteral("Untitled"));
    QCOMPARE(document.undoStack()->count(), 0);
    QVERIFY(document.missingFiles().isEmpty());
}

void DocumentUiTest::editUndoRedo()
{
    Document document;
    const double before = document.project().material().roughness();
    QSignalSpy changed(&document, &Document::changed);
    document.setMaterial(withRoughness(document, 0.8), QStringLiteral("Roughness"), MergeId::Roughness);
    QCOMPARE(document.project().material().roughness(), 0.8);
    QCOMPARE(changed.count(), 1);
    QCOMPARE(document.undoStack()->count(), 1);
    QCOMPARE(document.undoStack()->undoText(), QStringLiteral("Roughness"));

    document.undoStack()->undo();
    QCOMPARE(document.project().material().roughness(), before);
    QCOMPARE(changed.count(), 2);
    // Undo names what it changed back: material 0's roughness factor.
    QCOMPARE(lastChanges(changed),
        DocumentChanges::ofMaterial(0, MaterialChange::ofMap(MapSlot::Roughness, MapProperty::Factor)));
    document.undoStack()->redo();
    QCOMPARE(document.project().material().roughness(), 0.8);
    QCOMPARE(changed.count(), 3);
}

void DocumentUiTest::unchangedValuePushesNothing()
{
    Document document;
    QSignalSpy changed(&document, &Document::changed);
    document.setMaterial(document.project().material(), QStringLiteral("Nothing"));
    document.setLights(document.project().lights, QStringLiteral("Nothing"));
    QCOMPARE(changed.count(), 0);
    QCOMPARE(document.undoStack()->count(), 0);
    QVERIFY(!document.isModified());
}

void DocumentUiTest::changeFlagsOfHelpers()
{
    Document document;
    QSignalSpy changed(&document, &Document::changed);
    EnvironmentSettings environment = document.project().environment;
    environment.rotationDegrees = 45.0;
    document.setEnvironment(environment, QStringLiteral("Rotate Environment"));
    QCOMPARE(lastChanges(changed), DocumentChanges(DocumentChange::EnvironmentRotation));

    document.setLights({Light::defaultDirectional()}, QStringLiteral("Add Light"));
    QCOMPARE(lastChanges(changed), DocumentChanges::ofLightList(ListChange {{0}, {}, false}));

    ViewSettings view = document.project().view;
    view.exposureEV = 0.5;
    document.setView(view, QStringLiteral("Exposure"));
    QCOMPARE(lastChanges(changed), DocumentChanges::ofView(ViewProperty::Exposure));

    QCOMPARE(document.undoStack()->count(), 3);
    document.undoStack()->setIndex(0);
    QCOMPARE(document.project(), Project::defaultProject());
}

void DocumentUiTest::dragMergesIntoOneStep()
{
    Document document;
    const double start = document.project().material().roughness();
    QSignalSpy changed(&document, &Document::changed);
    document.beginInteractiveEdit();
    for (int step = 1; step <= 20; ++step)
        document.setMaterial(
            withRoughness(document, step / 20.0), QStringLiteral("Roughness"), MergeId::Roughness);
    document.endInteractiveEdit();
    QCOMPARE(changed.count(), 20); // the viewport sees every step of the drag
    QCOMPARE(document.undoStack()->count(), 1); // but it is one undo step
    QCOMPARE(document.project().material().roughness(), 1.0);
    document.undoStack()->undo();
    QCOMPARE(document.project().material().roughness(), start);
    document.undoStack()->redo();
    QCOMPARE(document.project().material().roughness(), 1.0);
}

void DocumentUiTest::separateDragsAreSeparateSteps()
{
    Document document;
    for (const double target : {0.7, 0.9}) {
        document.beginInteractiveEdit();
        document.setMaterial(
            withRoughness(document, target - 0.1), QStringLiteral("Roughness"), MergeId::Roughness);
        document.setMaterial(
            withRoughness(document, target), QStringLiteral("Roughness"), MergeId::Roughness);
        document.endInteractiveEdit();
    }
    QCOMPARE(document.undoStack()->count(), 2);
    document.undoStack()->undo();
    QCOMPARE(document.project().material().roughness(), 0.7);

    // Another merge id in the same interaction is its own step.
    Document other;
    other.beginInteractiveEdit();
    other.setMaterial(withRoughness(other, 0.6), QStringLiteral("Roughness"), MergeId::Roughness);
    Material metal = other.project().material();
    metal.setFactor(MapSlot::Metallic, 1.0);
    other.setMaterial(metal, QStringLiteral("Metallic"), MergeId::Metallic);
    other.endInteractiveEdit();
    QCOMPARE(other.undoStack()->count(), 2);
}

void DocumentUiTest::dragBackToStartLeavesNoStep()
{
    Document document;
    const double start = document.project().material().roughness();
    document.beginInteractiveEdit();
    document.setMaterial(withRoughness(document, 0.9), QStringLiteral("Roughness"), MergeId::Roughness);
    document.setMaterial(withRoughness(document, start), QStringLiteral("Roughness"), MergeId::Roughness);
    document.endInteractiveEdit();
    QCOMPARE(document.undoStack()->count(), 0);
    QVERIFY(!document.isModified());
}

void DocumentUiTest::noMergeOutsideInteraction()
{
    Document document;
    document.setMaterial(withRoughness(document, 0.6), QStringLiteral("Roughness"), MergeId::Roughness);
    document.setMaterial(withRoughness(document, 0.7), QStringLiteral("Roughness"), MergeId::Roughness);
    QCOMPARE(document.undoStack()->count(), 2);
}

void DocumentUiTest::cameraIsNotUndoable()
{
    Document document;
    QSignalSpy changed(&document, &Document::changed);
    Camera camera = document.project().camera;
    camera.position = {1.0, 2.0, 3.0};
    document.setCamera(camera);
    QCOMPARE(lastChanges(changed), DocumentChanges(DocumentChange::Camera));
    QCOMPARE(document.undoStack()->count(), 0);
    QVERIFY(!document.isModified());

    // Undoing a material edit leaves the camera where it is now.
    document.setMaterial(withRoughness(document, 0.9), QStringLiteral("Roughness"));
    camera.position = {0.0, 0.0, 5.0};
    document.setCamera(camera);
    document.undoStack()->undo();
    QCOMPARE(document.project().camera, camera);
    QCOMPARE(lastChanges(changed),
        DocumentChanges::ofMaterial(0, MaterialChange::ofMap(MapSlot::Roughness, MapProperty::Factor)));
}

void DocumentUiTest::invalidEditIsRejected()
{
    Document document;
    QSignalSpy rejected(&document, &Document::editRejected);
    document.setMaterial(withRoughness(document, 1.5), QStringLiteral("Roughness"));
    QCOMPARE(rejected.count(), 1);
    QVERIFY2(rejected.first().at(0).toString().contains(QStringLiteral("roughness")),
        qPrintable(rejected.first().at(0).toString()));
    QCOMPARE(document.undoStack()->count(), 0);
    QCOMPARE(document.project(), Project::defaultProject());
}

void DocumentUiTest::presetKeepsTextures()
{
    Document document;
    Material material = document.project().material();
    material.map(MapSlot::Normal).path = "/textures/normal.png";
    document.setMaterial(material, QStringLiteral("Normal Map"));
    const MaterialPreset* gold = findPreset("gold");
    QVERIFY(gold);
    document.applyPreset(*gold);
    const Material& applied = document.project().material();
    QCOMPARE(applied.map(MapSlot::Normal).path, std::string("/textures/normal.png"));
    QCOMPARE(applied.metallic(), gold->material.metallic());
    QCOMPARE(applied.baseColorFactor(), gold->material.baseColorFactor());
    QVERIFY(document.undoStack()->undoText().contains(QString::fromStdString(gold->displayName)));
}

void DocumentUiTest::modifiedFollowsUndoStack()
{
    QTemporaryDir dir;
    Document document;
    QSignalSpy modified(&document, &Document::modifiedChanged);
    document.setMaterial(withRoughness(document, 0.9), QStringLiteral("Roughness"));
    QVERIFY(document.isModified());
    QCOMPARE(modified.count(), 1);
    document.undoStack()->undo();
    QVERIFY(!document.isModified());
    QCOMPARE(modified.count(), 2);
    document.undoStack()->redo();
    QString error;
    QVERIFY2(document.saveAs(dir.filePath(QStringLiteral("p.facet.json")), &error), qPrintable(error));
    QVERIFY(!document.isModified());
    // Undoing past the save point is a modification again.
    document.undoStack()->undo();
    QVERIFY(document.isModified());
}

void DocumentUiTest::saveAndReopenGiveSameProject()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("scene.json"));
    Document document;
    QSignalSpy pathChanged(&document, &Document::filePathChanged);
    Material material = document.project().material();
    material.setFactor(MapSlot::Metallic, 1.0);
    material.setBaseColor({0.9, 0.7, 0.3});
    document.setMaterial(material, QStringLiteral("Metal"));
    document.setLights({Light::defaultDirectional()}, QStringLiteral("Add Light"));
    EnvironmentSettings environment = document.project().environment;
    environment.source = "sky";
    environment.intensity = 2.0;
    document.setEnvironment(environment, QStringLiteral("Environment"));
    Camera camera = document.project().camera;
    camera.position = {2.0, 1.0, 2.0};
    document.setCamera(camera);
    QString error;
    QVERIFY2(document.saveAs(path, &error), qPrintable(error));
    QCOMPARE(document.filePath(), path);
    QCOMPARE(document.displayName(), QStringLiteral("scene.json"));
    QCOMPARE(pathChanged.count(), 1);

    Document reopened;
    QSignalSpy changed(&reopened, &Document::changed);
    QVERIFY2(reopened.open(path, &error), qPrintable(error));
    QCOMPARE(reopened.project(), document.project());
    QCOMPARE(reopened.project().camera, camera); // the camera is saved
    QCOMPARE(lastChanges(changed), DocumentChanges(DocumentChange::WholeProject));
    QVERIFY(!reopened.isModified());
    QCOMPARE(reopened.undoStack()->count(), 0);
}

void DocumentUiTest::openFailureChangesNothing()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("broken.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{ \"format\": \"facet-project\", ");
    file.close();
    Document document;
    document.setMaterial(withRoughness(document, 0.9), QStringLiteral("Roughness"));
    const Project before = document.project();
    QString error;
    QVERIFY(!document.open(path, &error));
    QVERIFY2(error.contains(path), qPrintable(error));
    QCOMPARE(document.project(), before);
    QVERIFY(document.isModified());
    QCOMPARE(document.undoStack()->count(), 1);
    QVERIFY(!document.open(dir.filePath(QStringLiteral("absent.json")), &error));
    QVERIFY2(error.contains(QStringLiteral("absent.json")), qPrintable(error));
}

void DocumentUiTest::missingFilesAndRelink()
{
    QTemporaryDir dir;
    const QString missing = dir.filePath(QStringLiteral("gone/albedo.png"));
    const QString present = dir.filePath(QStringLiteral("albedo.png"));
    QFile file(present);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("not read by the document");
    file.close();

    Document document;
    QSignalSpy missingChanged(&document, &Document::missingFilesChanged);
    Material material = document.project().material();
    material.map(MapSlot::BaseColor).path = missing.toStdString();
    document.setMaterial(material, QStringLiteral("Base Color Map"));
    QCOMPARE(document.missingFiles(), QStringList {missing});
    QCOMPARE(missingChanged.count(), 1);

    // Saved and reopened: the project opens and names the missing file.
    const QString path = dir.filePath(QStringLiteral("p.json"));
    QString error;
    QVERIFY2(document.saveAs(path, &error), qPrintable(error));
    Document reopened;
    QVERIFY2(reopened.open(path, &error), qPrintable(error));
    QCOMPARE(reopened.missingFiles(), QStringList {missing});

    QVERIFY(reopened.relinkFile(missing, present));
    QVERIFY(reopened.missingFiles().isEmpty());
    QCOMPARE(reopened.project().material().map(MapSlot::BaseColor).path, present.toStdString());
    QVERIFY(reopened.undoStack()->undoText().startsWith(QStringLiteral("Relink")));
    reopened.undoStack()->undo();
    QCOMPARE(reopened.missingFiles(), QStringList {missing});
    QVERIFY(!reopened.relinkFile(dir.filePath(QStringLiteral("never-used.png")), present));
}

void DocumentUiTest::missingFilesRecheckedByEditsThatNameFiles_data()
{
    // An edit, and whether it looks at the files on disk again (a slider drag must not stat
    // every map file at each step).
    QTest::addColumn<std::function<void(Project&)>>("edit");
    QTest::addColumn<bool>("rechecked");
    QTest::newRow("roughness factor")
        << std::function<void(Project&)>([](Project& p) { p.material().setFactor(MapSlot::Roughness, 0.9); })
        << false;
    QTest::newRow("material name") << std::function<void(Project&)>([](Project& p) {
        p.material().name += " (renamed)";
    }) << false;
    QTest::newRow("light added") << std::function<void(Project&)>([](Project& p) {
        p.lights.push_back(Light::defaultDirectional());
    }) << false;
    QTest::newRow("exposure") << std::function<void(Project&)>([](Project& p) { p.view.exposureEV = 1.0; })
                              << false;
    QTest::newRow("environment rotation")
        << std::function<void(Project&)>([](Project& p) { p.environment.rotationDegrees = 20.0; }) << false;
    QTest::newRow("base colour colour space") << std::function<void(Project&)>([](Project& p) {
        p.material().map(MapSlot::BaseColor).colorSpace = ColorEncoding::Linear;
    }) << true;
    QTest::newRow("normal map path") << std::function<void(Project&)>([](Project& p) {
        p.material().map(MapSlot::Normal).path = p.material().map(MapSlot::BaseColor).path + ".normal";
    }) << true;
    QTest::newRow("environment source")
        << std::function<void(Project&)>([](Project& p) { p.environment.source = "sky"; }) << true;
    QTest::newRow("mesh") << std::function<void(Project&)>([](Project& p) { p.view.mesh = "cube"; }) << true;
    QTest::newRow("material added") << std::function<void(Project&)>([](Project& p) {
        p.materials.push_back(Material {});
    }) << true;
}

void DocumentUiTest::missingFilesRecheckedByEditsThatNameFiles()
{
    QFETCH(std::function<void(Project&)>, edit);
    QFETCH(bool, rechecked);
    QTemporaryDir dir;
    const QString albedo = dir.filePath(QStringLiteral("albedo.png"));
    QFile file(albedo);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("not read by the document");
    file.close();
    Document document;
    Material material = document.project().material();
    material.map(MapSlot::BaseColor).path = albedo.toStdString();
    document.setMaterial(material, QStringLiteral("Base Color Map"));
    QVERIFY(document.missingFiles().isEmpty());

    QVERIFY(QFile::remove(albedo)); // deleted behind the document's back
    Project after = document.project();
    edit(after);
    document.setProject(after, QStringLiteral("Edit"));
    QCOMPARE(document.undoStack()->count(), 2);
    QCOMPARE(document.missingFiles().contains(albedo), rechecked);
    // Undo is an edit too: it names the same kinds of change.
    document.undoStack()->undo();
    QCOMPARE(document.missingFiles().contains(albedo), rechecked);
}

void DocumentUiTest::recoveryFileRoundTrip()
{
    QTemporaryDir dir;
    const QString projectPath = dir.filePath(QStringLiteral("work.json"));
    const QString recoveryPath = dir.filePath(QStringLiteral("recovery/autosave.json"));
    QVERIFY(QDir().mkpath(dir.filePath(QStringLiteral("recovery"))));
    Document document;
    QString error;
    QVERIFY2(document.saveAs(projectPath, &error), qPrintable(error));
    document.setMaterial(withRoughness(document, 0.95), QStringLiteral("Roughness"));
    QVERIFY2(document.writeRecoveryFile(recoveryPath, &error), qPrintable(error));
    QVERIFY(document.isModified()); // writing a recovery copy is not saving
    QCOMPARE(Document::recoveryOriginalPath(recoveryPath), projectPath);

    Document recovered;
    QVERIFY2(recovered.recover(recoveryPath, &error), qPrintable(error));
    QCOMPARE(recovered.project(), document.project());
    QCOMPARE(recovered.filePath(), projectPath);
    QVERIFY(recovered.isModified());
    QVERIFY(recovered.warnings().isEmpty());
    QVERIFY2(recovered.save(&error), qPrintable(error));
    QVERIFY(!recovered.isModified());
}

void DocumentUiTest::newProjectResets()
{
    Document document;
    document.setMaterial(withRoughness(document, 0.9), QStringLiteral("Roughness"));
    QSignalSpy changed(&document, &Document::changed);
    document.newProject();
    QCOMPARE(document.project(), Project::defaultProject());
    QCOMPARE(document.undoStack()->count(), 0);
    QVERIFY(!document.isModified());
    QCOMPARE(lastChanges(changed), DocumentChanges(DocumentChange::WholeProject));
}

QTEST_GUILESS_MAIN(DocumentUiTest)
#include "DocumentUiTest.moc"
