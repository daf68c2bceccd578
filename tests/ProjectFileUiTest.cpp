// Projects through the main window: the dirty marker in the title, save and reopen give the same
// project, a broken file is reported with its name and changes nothing, a missing texture opens
// anyway with a relink message and dialog, the unsaved-changes question, recent files, autosave
// to a recovery file and the recovery offer, Reset Layout. Needs a display (Xvfb).

#include "ui/AutosaveController.h"
#include "ui/CameraController.h"
#include "ui/Document.h"
#include "ui/MainWindow.h"
#include "ui/MissingFilesDialog.h"
#include "ui/ProjectFileController.h"
#include "ui/SurfaceFormat.h"
#include "ui/ViewportWidget.h"

#include "TestSupport.h"

#include <QAbstractButton>
#include <QApplication>
#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QMessageBox>
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
    Material material = document.project().material;
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
    void missingTextureOpensWithRelinkMessage();
    void unsavedChangesQuestion();
    void autosaveWritesRecoveryFile();
    void recoveryOfferRestoresWork();
    void resetLayoutRedocksPanels();

private:
    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
    QString recoveryDir() const { return m_dir.filePath(QStringLiteral("recovery")); }
};

void ProjectFileUiTest::initTestCase()
{
    QCoreApplication::setOrganizationName(QStringLiteral("FacetTests"));
    QVERIFY(m_dir.isValid());
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
    const QString error = m_window->projectFiles()->lastError();
    QVERIFY2(error.contains(path) && error.contains(QStringLiteral("material")), qPrintable(error));
    QCOMPARE(m_window->statusMessage(), error);
    QCOMPARE(m_window->document()->project(), before);
    // Shown in a non-modal message box: nothing waits for a click.
    auto* box = m_window->findChild<QMessageBox*>(QStringLiteral("errorMessageBox"));
    QVERIFY(box);
    QVERIFY(box->isVisible());
    QVERIFY(box->text().contains(path));
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
    project.material.map(MapSlot::BaseColor).path = gone.toStdString();
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
    QCOMPARE(QString::fromStdString(m_window->document()->project().material.map(MapSlot::BaseColor).path),
        QDir(folder).filePath(QStringLiteral("brick_albedo.png")));
    QVERIFY(m_window->isWindowModified()); // relinking is an edit: save to keep it
}

void ProjectFileUiTest::unsavedChangesQuestion()
{
    Document* document = m_window->document();
    document->setMaterial(withRoughness(*document, 0.9), QStringLiteral("Roughness"));
    ProjectFileController* files = m_window->projectFiles();
    files->setUnsavedChangesAnswer(QMessageBox::Cancel);
    QVERIFY(!files->newProject());
    QVERIFY(document->isModified());
    QCOMPARE(document->project().material.roughness(), 0.9);
    // Closing the window is refused the same way.
    QVERIFY(!m_window->close());
    QVERIFY(m_window->isVisible());
    files->setUnsavedChangesAnswer(QMessageBox::Discard);
    QVERIFY(files->newProject());
    QVERIFY(!document->isModified());
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
    QCOMPARE(m_window->document()->project().material.roughness(), 0.66);
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
