// Projects through the main window: the dirty marker in the title, save and reopen give the same
// project, a broken file is reported with its name (the window's wording) and changes nothing, an
// unknown debug view is refused, a missing texture opens anyway with a relink message and dialog,
// an installed or user-library environment chosen in the library survives moving the project
// folder, a missing library file opens with the relink dialog saying how to get it, the
// unsaved-changes question, recent files, autosave to a recovery file and the recovery offer,
// Reset Layout. Needs a display (Xvfb).

#include "ui/MainWindow.h"
#include "ui/docks/EnvironmentDock.h"
#include "ui/document/AutosaveController.h"
#include "ui/document/Document.h"
#include "ui/document/MissingFilesDialog.h"
#include "ui/document/ProjectFileController.h"
#include "ui/viewport/CameraController.h"
#include "ui/viewport/SceneController.h"
#include "ui/viewport/SurfaceFormat.h"
#include "ui/viewport/ViewportWidget.h"
#include "ui/widgets/ProblemBar.h"

#include "TestSupport.h"

#include <QAbstractButton>
#include <QApplication>
#include <QDateTime>
#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QListWidget>
#include <QMessageBox>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>
#include <QUndoStack>
#include <QtTest/QTest>

#include <memory>

using namespace facet;

namespace {

Material withRoughness(const Document& document, double roughness)
{
    Material material = document.project().material();
    material.setFactor(MapSlot::Roughness, roughness);
    return material;
}

} // namespace

class ProjectFileUiTest : public QObject {
    Q_OBJECT
public:
    static void initMain()
    {
        QStandardPaths::setTestModeEnabled(true);
        installViewportSurfaceFormat();
    }

private Q_SLOTS:
    void initTestCase();
    void init();
    void cleanup();
    void titleShowsDirtyMarker();
    void saveAndReopenGiveSameProject();
    void brokenFileIsReportedAndChangesNothing();
    void unknownDebugViewIsRefused();
    void missingTextureOpensWithRelinkMessage();
    void libraryEnvironmentSurvivesAMove_data();
    void libraryEnvironmentSurvivesAMove();
    void missingLibraryFileOpensWithRelinkDialog_data();
    void missingLibraryFileOpensWithRelinkDialog();
    void unsavedChangesQuestion();
    void projectChangedOnDiskIsNotOverwrittenSilently_data();
    void projectChangedOnDiskIsNotOverwrittenSilently();
    void failedSaveProblemClearsOnSuccess();
    void autosaveWritesRecoveryFile();
    void recoveryOfferRestoresWork();
    void resetLayoutRedocksPanels();

private:
    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
    QString recoveryDir() const { return m_dir.filePath(QStringLiteral("recovery")); }
    // This test's installed samples ($FACET_ASSETS_DIR) and a user library folder.
    QString installedDir() const { return m_dir.filePath(QStringLiteral("assets")); }
    QString userLibraryDir() const { return m_dir.filePath(QStringLiteral("My HDRIs")); }
};

void ProjectFileUiTest::initTestCase()
{
    QCoreApplication::setOrganizationName(QStringLiteral("FacetTests"));
    QVERIFY(m_dir.isValid());
    // Environments of this test's own, so the library holds exactly what the test expects; every
    // window made in init() lists them.
    qputenv("FACET_ASSETS_DIR", installedDir().toLocal8Bit());
    QSettings().remove(QStringLiteral("assetLibraries"));
    QVERIFY(test::writeConstantExr(installedDir() + QStringLiteral("/hdri/night.exr"), 0.05f));
    QVERIFY(test::writeConstantExr(installedDir() + QStringLiteral("/hdri/studio.exr"), 0.8f));
    QVERIFY(test::writeConstantExr(userLibraryDir() + QStringLiteral("/loft.exr"), 0.4f));
}

void ProjectFileUiTest::init()
{
    m_window = std::make_unique<MainWindow>(nullptr, recoveryDir());
    m_window->projectFiles()->setUnsavedChangesAnswer(QMessageBox::Discard);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
}

void ProjectFileUiTest::cleanup()
{
    m_window.reset();
}

void ProjectFileUiTest::titleShowsDirtyMarker()
{
    QCOMPARE(m_window->windowTitle(), QStringLiteral("Untitled[*] — Facet"));
    QVERIFY(!m_window->isWindowModified());
    Document* document = m_window->document();
    document->setMaterial(withRoughness(*document, 0.9), QStringLiteral("Roughness"));
    QVERIFY(m_window->isWindowModified());
    document->undoStack()->undo();
    QVERIFY(!m_window->isWindowModified());
    document->undoStack()->redo();
    const QString path = m_dir.filePath(QStringLiteral("titled.json"));
    QVERIFY(m_window->projectFiles()->saveToFile(path));
    QVERIFY(!m_window->isWindowModified());
    QCOMPARE(m_window->windowTitle(), QStringLiteral("titled.json[*] — Facet"));
    QVERIFY2(m_window->statusMessage().contains(QStringLiteral("titled.json")),
        qPrintable(m_window->statusMessage()));
}

void ProjectFileUiTest::saveAndReopenGiveSameProject()
{
    Document* document = m_window->document();
    Material material = withRoughness(*document, 0.2);
    material.setFactor(MapSlot::Metallic, 1.0);
    document->setMaterial(material, QStringLiteral("Metal"));
    document->setLights({Light::defaultDirectional()}, QStringLiteral("Add Light"));
    EnvironmentSettings environment = document->project().environment;
    environment.source = "sky";
    environment.rotationDegrees = 120.0;
    document->setEnvironment(environment, QStringLiteral("Environment"));
    const Project saved = document->project();
    const QString path = m_dir.filePath(QStringLiteral("roundtrip.json"));
    QVERIFY(m_window->projectFiles()->saveToFile(path));
    QCOMPARE(m_window->projectFiles()->recentFiles().value(0), path);

    QVERIFY(m_window->projectFiles()->newProject());
    // The default project, its camera framed for the viewport's shape (CameraController).
    Project fresh = Project::defaultProject();
    fresh.camera = CameraController::defaultView(
        double(m_window->viewport()->width()) / m_window->viewport()->height());
    QCOMPARE(document->project(), fresh);
    QVERIFY(m_window->projectFiles()->openFile(path));
    QCOMPARE(document->project(), saved);
    QCOMPARE(document->filePath(), path);
    QVERIFY(!m_window->isWindowModified());
    QVERIFY(m_window->projectFiles()->missingFilesMessage().isEmpty());
}

void ProjectFileUiTest::brokenFileIsReportedAndChangesNothing()
{
    const QString path = m_dir.filePath(QStringLiteral("broken.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{\"format\": \"facet-project\", \"version\": 1, \"material\": 3}");
    file.close();
    const Project before = m_window->document()->project();
    QVERIFY(!m_window->projectFiles()->openFile(path));
    // The precise message (stderr, logs) names the function and the whole path; the window says
    // the same about the file in its own words.
    const QString error = m_window->projectFiles()->lastError();
    QVERIFY2(error.contains(path) && error.contains(QStringLiteral("Project::load"))
            && error.contains(QStringLiteral("material")),
        qPrintable(error));
    const QString shown = m_window->statusMessage();
    QCOMPARE(shown, QStringLiteral("Could not open the project: broken.json: material: expected an object, got a number"));
    QCOMPARE(m_window->document()->project(), before);
    // Shown in a non-modal message box: nothing waits for a click.
    auto* box = m_window->findChild<QMessageBox*>(QStringLiteral("errorMessageBox"));
    QVERIFY(box);
    QVERIFY(box->isVisible());
    QCOMPARE(box->text(), shown);
    box->close();
}

void ProjectFileUiTest::unknownDebugViewIsRefused()
{
    // Core does not know the renderer's names; the window refuses the file like any bad name,
    // instead of silently showing the shaded image.
    const QString path = m_dir.filePath(QStringLiteral("bad-view.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("{\"format\": \"facet-project\", \"version\": 1, \"view\": {\"debugView\": \"bogus\"}}");
    file.close();
    const Project before = m_window->document()->project();
    QVERIFY(!m_window->projectFiles()->openFile(path));
    const QString error = m_window->projectFiles()->lastError();
    QVERIFY2(error.contains(QStringLiteral("view.debugView: unknown debug view \"bogus\" (expected one of: none, "))
            && error.contains(QStringLiteral("distribution (or d)")) && error.contains(path),
        qPrintable(error));
    QVERIFY2(m_window->statusMessage().startsWith(
                 QStringLiteral("Could not open the project: bad-view.json: view.debugView: unknown debug view")),
        qPrintable(m_window->statusMessage()));
    QCOMPARE(m_window->document()->project(), before);
    if (auto* box = m_window->findChild<QMessageBox*>(QStringLiteral("errorMessageBox")))
        box->close();
}

void ProjectFileUiTest::missingTextureOpensWithRelinkMessage()
{
    // A project whose base colour map is gone; a file of that name sits in another folder.
    const QString gone = m_dir.filePath(QStringLiteral("old-textures/brick_albedo.png"));
    const QString folder = m_dir.filePath(QStringLiteral("new-textures"));
    QVERIFY(QDir().mkpath(folder));
    QImage image(4, 4, QImage::Format_RGB32);
    image.fill(QColor(200, 100, 50));
    QVERIFY(image.save(QDir(folder).filePath(QStringLiteral("brick_albedo.png"))));
    Project project = Project::defaultProject();
    project.material().map(MapSlot::BaseColor).path = gone.toStdString();
    const QString path = m_dir.filePath(QStringLiteral("missing.json"));
    std::string error;
    QVERIFY2(project.save(path.toStdString(), &error), error.c_str());

    QVERIFY(m_window->projectFiles()->openFile(path)); // the project still opens
    QCOMPARE(m_window->document()->missingFiles(), QStringList {gone});
    const QString message = m_window->projectFiles()->missingFilesMessage();
    QVERIFY2(
        message.contains(QStringLiteral("brick_albedo.png")) && message.contains(QStringLiteral("Relink")),
        qPrintable(message));
    QCOMPARE(m_window->statusMessage(), message);
    MissingFilesDialog* dialog = m_window->projectFiles()->missingFilesDialog();
    QVERIFY(dialog);
    QVERIFY(dialog->isVisible());
    QVERIFY2(dialog->message().contains(QStringLiteral("missing.json")), qPrintable(dialog->message()));

    QCOMPARE(dialog->relinkFromFolder(folder), 1);
    QVERIFY(m_window->document()->missingFiles().isEmpty());
    QVERIFY(!dialog->isVisible()); // nothing left to relink
    QCOMPARE(QString::fromStdString(m_window->document()->project().material().map(MapSlot::BaseColor).path),
        QDir(folder).filePath(QStringLiteral("brick_albedo.png")));
    QVERIFY(m_window->isWindowModified()); // relinking is an edit: save to keep it
}

void ProjectFileUiTest::libraryEnvironmentSurvivesAMove_data()
{
    QTest::addColumn<QString>("file"); // under the library's folder
    QTest::addColumn<bool>("userLibrary");
    QTest::addColumn<QString>("stored");
    QTest::addColumn<QString>("label");
    QTest::newRow("installed sample") << "hdri/night.exr" << false << "library:installed/hdri/night.exr"
                                      << "Night (CC0 sample)";
    QTest::newRow("installed studio.exr, not the built-in")
        << "hdri/studio.exr" << false << "library:installed/hdri/studio.exr" << "Studio (CC0 sample)";
    QTest::newRow("user library") << "loft.exr" << true << "library:my-hdris/loft.exr" << "Loft (my-hdris)";
}

// As an artist does it: pick an environment from the library, save the project, move the project
// folder one level deeper, open it again: the same environment, selected in the library, nothing
// missing.
void ProjectFileUiTest::libraryEnvironmentSurvivesAMove()
{
    QFETCH(QString, file);
    QFETCH(bool, userLibrary);
    QFETCH(QString, stored);
    QFETCH(QString, label);
    EnvironmentDock* dock = m_window->environmentDock();
    if (userLibrary)
        QVERIFY(dock->addFolder(userLibraryDir()));
    const QString source = (userLibrary ? userLibraryDir() : installedDir()) + QLatin1Char('/') + file;
    QListWidget* library = dock->library();
    QListWidgetItem* item = nullptr;
    for (int row = 0; row < library->count(); ++row)
        if (library->item(row)->data(Qt::UserRole).toString() == source)
            item = library->item(row);
    QVERIFY2(item, qPrintable(source));
    QCOMPARE(item->text().section(QLatin1Char('\n'), 0, 0), label); // the resolution follows
    dock->raise();
    library->scrollToItem(item);
    QTest::mouseClick(library->viewport(), Qt::LeftButton, Qt::NoModifier, library->visualItemRect(item).center());
    QCOMPARE(QString::fromStdString(m_window->document()->project().environment.source), source);

    const QString folder = m_dir.filePath(QStringLiteral("artist/scene"));
    QDir(m_dir.filePath(QStringLiteral("artist"))).removeRecursively();
    QVERIFY(QDir().mkpath(folder));
    QVERIFY(m_window->projectFiles()->saveToFile(folder + QStringLiteral("/scene.json")));
    QFile saved(folder + QStringLiteral("/scene.json"));
    QVERIFY(saved.open(QIODevice::ReadOnly));
    QVERIFY2(saved.readAll().contains(QStringLiteral("\"source\": \"%1\"").arg(stored).toUtf8()), qPrintable(stored));
    saved.close();
    QVERIFY(m_window->projectFiles()->newProject());

    const QString moved = m_dir.filePath(QStringLiteral("artist/deeper/scene"));
    QVERIFY(QDir().mkpath(QFileInfo(moved).absolutePath()));
    QVERIFY(QDir().rename(folder, moved));
    QVERIFY(m_window->projectFiles()->openFile(moved + QStringLiteral("/scene.json")));
    QCOMPARE(QString::fromStdString(m_window->document()->project().environment.source), source);
    QVERIFY2(m_window->document()->missingFiles().isEmpty(),
        qPrintable(m_window->document()->missingFiles().join(QLatin1Char(' '))));
    QVERIFY(library->currentItem());
    QCOMPARE(library->currentItem()->data(Qt::UserRole).toString(), source);
    QCOMPARE(library->currentItem()->text().section(QLatin1Char('\n'), 0, 0), label);
    // The environment file loads off the GUI thread (ui/document/DocumentAssets).
    QTRY_COMPARE_WITH_TIMEOUT(m_window->sceneController()->pendingAssetLoads(), 0, 30000);
    QCOMPARE(m_window->sceneController()->environmentName(), QFileInfo(source).fileName());
    QVERIFY(m_window->sceneController()->environmentProblem().isEmpty());
}

void ProjectFileUiTest::missingLibraryFileOpensWithRelinkDialog_data()
{
    QTest::addColumn<QString>("stored");
    QTest::addColumn<QString>("missing"); // as Document::missingFiles lists it
    QTest::addColumn<QString>("advice"); // in the dialog's entry
    QTest::newRow("installed sample not installed")
        << "library:installed/hdri/gone.exr" << installedDir() + QStringLiteral("/hdri/gone.exr")
        << "run packaging/fetch-assets.sh";
    QTest::newRow("library this computer lacks") << "library:nobody/gone.exr" << "library:nobody/gone.exr"
                                                 << "Add Folder… in the Environment dock";
}

// A project naming a library file this computer does not have opens anyway, with the relink dialog
// saying where the file comes from; relinking from a folder fixes it.
void ProjectFileUiTest::missingLibraryFileOpensWithRelinkDialog()
{
    QFETCH(QString, stored);
    QFETCH(QString, missing);
    QFETCH(QString, advice);
    const QString path = m_dir.filePath(QStringLiteral("uses-library.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(QStringLiteral("{\"format\": \"facet-project\", \"version\": 1, \"environment\": {\"source\": \"%1\"}}")
                   .arg(stored)
                   .toUtf8());
    file.close();

    QVERIFY(m_window->projectFiles()->openFile(path)); // opens, does not fail
    QCOMPARE(m_window->document()->missingFiles(), QStringList {missing});
    MissingFilesDialog* dialog = m_window->projectFiles()->missingFilesDialog();
    QVERIFY(dialog);
    QVERIFY(dialog->isVisible());
    QCOMPARE(dialog->entries().size(), 1);
    QVERIFY2(dialog->entries()[0].contains(QStringLiteral("gone.exr")) && dialog->entries()[0].contains(advice),
        qPrintable(dialog->entries()[0]));
    // The window never claims the missing environment is lit.
    QTRY_COMPARE_WITH_TIMEOUT(m_window->sceneController()->pendingAssetLoads(), 0, 30000);
    QVERIFY2(m_window->sceneController()->environmentProblem().contains(QStringLiteral("gone.exr")),
        qPrintable(m_window->sceneController()->environmentProblem()));

    const QString folder = m_dir.filePath(QStringLiteral("found"));
    QVERIFY(test::writeConstantExr(folder + QStringLiteral("/gone.exr"), 0.3f));
    QCOMPARE(dialog->relinkFromFolder(folder), 1);
    QVERIFY(m_window->document()->missingFiles().isEmpty());
    QCOMPARE(QString::fromStdString(m_window->document()->project().environment.source),
        folder + QStringLiteral("/gone.exr"));
    QVERIFY(m_window->sceneController()->environmentProblem().isEmpty());
    QVERIFY(QDir(folder).removeRecursively());
}

void ProjectFileUiTest::unsavedChangesQuestion()
{
    Document* document = m_window->document();
    document->setMaterial(withRoughness(*document, 0.9), QStringLiteral("Roughness"));
    ProjectFileController* files = m_window->projectFiles();
    files->setUnsavedChangesAnswer(QMessageBox::Cancel);
    QVERIFY(!files->newProject());
    QVERIFY(document->isModified());
    QCOMPARE(document->project().material().roughness(), 0.9);
    // Closing the window is refused the same way.
    QVERIFY(!m_window->close());
    QVERIFY(m_window->isVisible());
    files->setUnsavedChangesAnswer(QMessageBox::Discard);
    QVERIFY(files->newProject());
    QVERIFY(!document->isModified());
}

void ProjectFileUiTest::projectChangedOnDiskIsNotOverwrittenSilently_data()
{
    QTest::addColumn<QString>("otherWriter"); // what changes the file after this window opened it
    QTest::addColumn<int>("answer"); // to "changed on disk": Save = overwrite, Discard = reload
    QTest::addColumn<double>("roughnessOnDisk"); // afterwards
    QTest::addColumn<double>("roughnessHere");
    QTest::addColumn<bool>("modifiedHere");
    // This window's edit is roughness 0.9; the other writer's 0.4; the file was written with 0.2.
    QTest::newRow("nobody: saved without a question")
        << QString() << int(QMessageBox::Cancel) << 0.9 << 0.9 << false;
    QTest::newRow("another window, cancel")
        << QStringLiteral("window") << int(QMessageBox::Cancel) << 0.4 << 0.9 << true;
    QTest::newRow("another window, overwrite")
        << QStringLiteral("window") << int(QMessageBox::Save) << 0.9 << 0.9 << false;
    QTest::newRow("another window, reload")
        << QStringLiteral("window") << int(QMessageBox::Discard) << 0.4 << 0.4 << false;
    // A copy over the file keeping the old modification time (cp -p): the inode tells.
    QTest::newRow("cp -p over it, cancel")
        << QStringLiteral("copy") << int(QMessageBox::Cancel) << 0.4 << 0.9 << true;
    // Removed meanwhile: saving loses nothing, so no question.
    QTest::newRow("removed: saved without a question")
        << QStringLiteral("remove") << int(QMessageBox::Cancel) << 0.9 << 0.9 << false;
}

// Issue 29, "Data lost, silently": two windows with the same project open, each saving: the
// second save overwrote the first with no warning. A save over the document's own file that
// another writer changed since it was opened or saved asks first (ProjectFileController), and the
// answer is carried out; after an overwrite or a reload, the next save asks nothing.
void ProjectFileUiTest::projectChangedOnDiskIsNotOverwrittenSilently()
{
    QFETCH(QString, otherWriter);
    QFETCH(int, answer);
    QFETCH(double, roughnessOnDisk);
    QFETCH(double, roughnessHere);
    QFETCH(bool, modifiedHere);
    const QString path = m_dir.filePath(
        QStringLiteral("shared-%1.json").arg(QLatin1String(QTest::currentDataTag())).replace(u' ', u'-'));
    {
        Document writer;
        writer.setMaterial(withRoughness(writer, 0.2), QStringLiteral("Roughness"));
        QString error;
        QVERIFY2(writer.saveAs(path, &error), qPrintable(error));
    }
    ProjectFileController* files = m_window->projectFiles();
    files->setErrorDialogsEnabled(false);
    QVERIFY(files->openFile(path));
    Document* document = m_window->document();
    QVERIFY(!document->changedOnDisk());

    // The second window: opens the same file, edits, saves.
    if (otherWriter == QLatin1String("window") || otherWriter == QLatin1String("copy")) {
        Document other;
        ProjectFileController otherFiles(&other, nullptr);
        otherFiles.setErrorDialogsEnabled(false);
        QVERIFY(otherFiles.openFile(path));
        other.setMaterial(withRoughness(other, 0.4), QStringLiteral("Roughness"));
        const QString target = otherWriter == QLatin1String("copy") ? path + QStringLiteral(".copy") : path;
        QVERIFY(otherFiles.saveToFile(target));
        if (otherWriter == QLatin1String("copy")) {
            const QDateTime time = QFileInfo(path).lastModified();
            QFile::remove(path);
            QVERIFY(QFile::copy(target, path));
            QFile copied(path);
            QVERIFY(copied.open(QIODevice::ReadWrite));
            QVERIFY(copied.setFileTime(time, QFileDevice::FileModificationTime));
        }
        QVERIFY(document->changedOnDisk());
    } else if (otherWriter == QLatin1String("remove")) {
        QVERIFY(QFile::remove(path));
        QVERIFY(!document->changedOnDisk());
    }

    document->setMaterial(withRoughness(*document, 0.9), QStringLiteral("Roughness"));
    files->setChangedOnDiskAnswer(QMessageBox::StandardButton(answer));
    const int questionsBefore = files->changedOnDiskQuestions();
    const bool saved = files->saveToFile(path);
    QCOMPARE(files->changedOnDiskQuestions() - questionsBefore,
        otherWriter == QLatin1String("window") || otherWriter == QLatin1String("copy") ? 1 : 0);
    QCOMPARE(saved, roughnessOnDisk == 0.9);

    std::string error;
    const std::optional<Project> onDisk = Project::load(path.toStdString(), &error);
    QVERIFY2(onDisk, error.c_str());
    QCOMPARE(onDisk->material().roughness(), roughnessOnDisk);
    QCOMPARE(document->project().material().roughness(), roughnessHere);
    QCOMPARE(document->isModified(), modifiedHere);
    QVERIFY2(!m_window->statusMessage().isEmpty(), "the window says what happened");

    // Overwritten or reloaded: the document and the file agree again, the next save asks nothing.
    if (!modifiedHere) {
        document->setMaterial(withRoughness(*document, 0.7), QStringLiteral("Roughness"));
        QVERIFY(files->saveToFile(path));
        QCOMPARE(files->changedOnDiskQuestions() - questionsBefore,
            otherWriter == QLatin1String("window") ? 1 : 0);
    }
    files->setChangedOnDiskAnswer(std::nullopt);
}

// Issue 29: the problem bar kept "Could not save" after the next save succeeded.
void ProjectFileUiTest::failedSaveProblemClearsOnSuccess()
{
    ProjectFileController* files = m_window->projectFiles();
    files->setErrorDialogsEnabled(false);
    const QString bad = m_dir.filePath(QStringLiteral("no-such-folder/p.json"));
    QVERIFY(!files->saveToFile(bad));
    QCOMPARE(m_window->problemBar()->problems().size(), qsizetype(1));
    QVERIFY2(m_window->problemBar()->problems().front().contains(QStringLiteral("Could not save")),
        qPrintable(m_window->problemBar()->problems().join(u'|')));
    QVERIFY(files->saveToFile(m_dir.filePath(QStringLiteral("saved-after-failure.json"))));
    QVERIFY2(
        !m_window->problemBar()->hasProblems(), qPrintable(m_window->problemBar()->problems().join(u'|')));
}

void ProjectFileUiTest::autosaveWritesRecoveryFile()
{
    AutosaveController* autosave = m_window->autosave();
    autosave->setIntervalMs(50);
    QSignalSpy autosaved(autosave, &AutosaveController::autosaved);
    Document* document = m_window->document();
    const QString path = m_dir.filePath(QStringLiteral("autosaved.json"));
    QVERIFY(m_window->projectFiles()->saveToFile(path));
    document->setMaterial(withRoughness(*document, 0.77), QStringLiteral("Roughness"));
    QVERIFY(autosaved.wait(5000));
    const QString recovery = autosave->recoveryFilePath();
    QVERIFY(QFileInfo::exists(recovery));
    QVERIFY(recovery.startsWith(recoveryDir()));
    QCOMPARE(Document::recoveryOriginalPath(recovery), path);
    QVERIFY(document->isModified()); // an autosave is not a save
    // This session is alive: its file is not offered as a crash leftover.
    QVERIFY(autosave->orphanedRecoveryFiles().isEmpty());
    // Saving removes it.
    QVERIFY(m_window->projectFiles()->saveToFile(path));
    QVERIFY(!QFileInfo::exists(recovery));
}

void ProjectFileUiTest::recoveryOfferRestoresWork()
{
    // A recovery file left by a session that crashed (no lock held for it).
    const QString orphan
        = QDir(recoveryDir()).filePath(QStringLiteral("session-999999-1.facet-recovery.json"));
    {
        Document crashed;
        crashed.setMaterial(withRoughness(crashed, 0.66), QStringLiteral("Roughness"));
        QString error;
        QVERIFY2(crashed.writeRecoveryFile(orphan, &error), qPrintable(error));
    }
    QCOMPARE(m_window->autosave()->orphanedRecoveryFiles(), QStringList {orphan});
    // Answer the question box as a user would.
    bool answered = false;
    QTimer::singleShot(200, this, [&answered] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (box) {
            box->button(QMessageBox::Yes)->click();
            answered = true;
        }
    });
    m_window->offerRecovery();
    QVERIFY(answered);
    QCOMPARE(m_window->document()->project().material().roughness(), 0.66);
    QVERIFY(m_window->isWindowModified());
    QVERIFY(!QFileInfo::exists(orphan));
    QVERIFY2(m_window->statusMessage().contains(QStringLiteral("Recovered")),
        qPrintable(m_window->statusMessage()));
}

void ProjectFileUiTest::resetLayoutRedocksPanels()
{
    // A plain dock stands in for the real panels (they are added the same way).
    MainWindow window(nullptr, recoveryDir());
    auto* dock = new QDockWidget(QStringLiteral("Probe"));
    dock->setObjectName(QStringLiteral("probeDock"));
    window.addDock(dock, Qt::LeftDockWidgetArea);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QVERIFY(dock->features().testFlag(QDockWidget::DockWidgetFloatable));
    QVERIFY(dock->features().testFlag(QDockWidget::DockWidgetClosable));
    dock->setFloating(true);
    dock->close();
    window.resetLayout();
    QVERIFY(!dock->isFloating());
    QVERIFY(dock->isVisible());
    QCOMPARE(window.dockWidgetArea(dock), Qt::LeftDockWidgetArea);
    window.projectFiles()->setUnsavedChangesAnswer(QMessageBox::Discard);
}

QTEST_MAIN(ProjectFileUiTest)
#include "ProjectFileUiTest.moc"
