// What the window says when the disk is full (issue 12, "A saved project can be lost"): Ctrl+S on
// a full disk reports the failure naming the file, never "Saved", and the document stays
// modified; the autosave and a user preset on a full disk report it too. In every row the old
// file is byte-identical afterwards and no temporary is left; with room again the same action
// succeeds. Needs a display (Xvfb) and a small full tmpfs (tests/support/FullVolume.h; without
// one the tests skip locally and fail under CI=true).

#include "ui/MainWindow.h"
#include "ui/docks/MaterialDock.h"
#include "ui/document/AutosaveController.h"
#include "ui/document/Document.h"
#include "ui/document/ProjectFileController.h"
#include "ui/document/UserPresets.h"
#include "ui/viewport/SurfaceFormat.h"

#include "FullVolume.h"
#include "TestSupport.h"

#include <QAction>
#include <QMessageBox>
#include <QFileInfo>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <memory>

using namespace facet;
using facet::test::fileBytes;
using facet::test::FullVolume;

namespace {

const QString kNoSpace = QStringLiteral("No space left on device");

Material withRoughness(const Document& document, double roughness)
{
    Material material = document.project().material();
    material.setFactor(MapSlot::Roughness, roughness);
    return material;
}

} // namespace

class SafeWriteUiTest : public QObject {
    Q_OBJECT
public:
    static void initMain()
    {
        FullVolume::isolateMounts(); // before any thread exists
        QStandardPaths::setTestModeEnabled(true);
        installViewportSurfaceFormat();
    }

private Q_SLOTS:
    void initTestCase();
    void cleanup();
    void saveOnFullDiskIsReportedAndStaysModified_data();
    void saveOnFullDiskIsReportedAndStaysModified();
    void autosaveOnFullDiskIsReported();
    void presetOnFullDiskIsReported();

private:
    void openWindow(const QString& recoveryDir);

    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
};

void SafeWriteUiTest::initTestCase()
{
    QCoreApplication::setOrganizationName(QStringLiteral("FacetTests"));
    QVERIFY(m_dir.isValid());
}

void SafeWriteUiTest::cleanup()
{
    m_window.reset(); // before the volumes of the test go
}

void SafeWriteUiTest::openWindow(const QString& recoveryDir)
{
    m_window = std::make_unique<MainWindow>(nullptr, recoveryDir);
    m_window->projectFiles()->setUnsavedChangesAnswer(QMessageBox::Discard);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
}

void SafeWriteUiTest::saveOnFullDiskIsReportedAndStaysModified_data()
{
    // The project file is under or over QFileDevice's 16 KiB write buffer: under it QSaveFile
    // left a 0-byte file and the window said "Saved".
    QTest::addColumn<int>("extraLights");
    QTest::newRow("project < 16 KiB") << 0;
    QTest::newRow("project > 16 KiB") << 80;
}

void SafeWriteUiTest::saveOnFullDiskIsReportedAndStaysModified()
{
    QFETCH(int, extraLights);
    FullVolume volume;
    FACET_REQUIRE_FULL_VOLUME(volume);
    openWindow(m_dir.filePath(QStringLiteral("recovery")));
    Document* document = m_window->document();
    ProjectFileController* files = m_window->projectFiles();
    files->setErrorDialogsEnabled(false);
    const QString path = volume.filePath(QStringLiteral("project.json"));
    QVERIFY2(files->saveToFile(path), qPrintable(files->lastError()));
    const QByteArray old = fileBytes(path);
    QVERIFY(!old.isEmpty());

    document->setMaterial(withRoughness(*document, 0.9), QStringLiteral("Roughness"));
    if (extraLights > 0) {
        // Disabled, so that the viewport does not light 80 lights on a software rasteriser.
        std::vector<Light> lights(std::size_t(extraLights), Light::defaultDirectional());
        for (Light& light : lights)
            light.enabled = false;
        document->setLights(lights, QStringLiteral("Lights"));
    }
    QVERIFY(document->isModified());
    QVERIFY2(volume.fill(), qPrintable(volume.problem()));

    // Ctrl+S, as the user presses it.
    auto* saveAction = m_window->findChild<QAction*>(QStringLiteral("saveAction"));
    QVERIFY(saveAction);
    QSignalSpy errors(files, &ProjectFileController::errorReported);
    saveAction->trigger();
    QCOMPARE(errors.count(), 1);
    const QString message = m_window->statusMessage();
    QVERIFY2(!message.startsWith(QStringLiteral("Saved")), qPrintable(message));
    // The window names the file by its name (ui/widgets/WindowMessages); the precise message keeps the path.
    QVERIFY2(message.contains(QFileInfo(path).fileName()) && message.contains(kNoSpace), qPrintable(message));
    QVERIFY2(files->lastError().contains(path), qPrintable(files->lastError()));
    QVERIFY(files->lastError() != message); // the precise message (function, full path) is kept apart
    QVERIFY(document->isModified());
    QVERIFY(m_window->isWindowModified());
    QCOMPARE(fileBytes(path), old);
    QCOMPARE(volume.entries(), QStringList {QStringLiteral("project.json")});

    // With room again the same Ctrl+S saves.
    QVERIFY(volume.drain());
    saveAction->trigger();
    QVERIFY2(
        m_window->statusMessage().startsWith(QStringLiteral("Saved")), qPrintable(m_window->statusMessage()));
    QVERIFY(!document->isModified());
    QVERIFY(fileBytes(path) != old);
    QCOMPARE(volume.entries(), QStringList {QStringLiteral("project.json")});
}

void SafeWriteUiTest::autosaveOnFullDiskIsReported()
{
    FullVolume volume;
    FACET_REQUIRE_FULL_VOLUME(volume);
    openWindow(volume.path()); // the recovery folder is the full volume
    Document* document = m_window->document();
    AutosaveController* autosave = m_window->autosave();
    document->setMaterial(withRoughness(*document, 0.4), QStringLiteral("Roughness"));
    QVERIFY(autosave->autosaveNow());
    const QString recovery = autosave->recoveryFilePath();
    QVERIFY(recovery.startsWith(volume.path()));
    const QByteArray old = fileBytes(recovery);
    QVERIFY(!old.isEmpty());
    const QStringList before = volume.entries(); // the recovery file and the session's lock file

    document->setMaterial(withRoughness(*document, 0.8), QStringLiteral("Roughness"));
    QVERIFY2(volume.fill(), qPrintable(volume.problem()));
    QSignalSpy failed(autosave, &AutosaveController::failed);
    QVERIFY(!autosave->autosaveNow());
    QCOMPARE(failed.count(), 1);
    const QString message = failed.at(0).at(0).toString();
    QVERIFY2(message.startsWith(QStringLiteral("Autosave failed")) && message.contains(QFileInfo(recovery).fileName())
            && message.contains(kNoSpace),
        qPrintable(message));
    QCOMPARE(m_window->statusMessage(), message);
    QCOMPARE(fileBytes(recovery), old); // the last good copy is still there to recover
    QCOMPARE(volume.entries(), before);

    QVERIFY(volume.drain());
    QVERIFY(autosave->autosaveNow());
    QVERIFY(fileBytes(recovery) != old);
    QCOMPARE(volume.entries(), before);
}

void SafeWriteUiTest::presetOnFullDiskIsReported()
{
    // The user's preset folder itself is the full volume (only inside this process's mounts).
    FullVolume volume(UserPresets::directory());
    FACET_REQUIRE_FULL_VOLUME(volume);
    openWindow(m_dir.filePath(QStringLiteral("recovery")));
    MaterialDock* dock = m_window->materialDock();
    QVERIFY(dock->saveCurrentAsPreset(QStringLiteral("Old look")));
    const QString oldPath = volume.filePath(QStringLiteral("old-look.json"));
    const QByteArray old = fileBytes(oldPath);
    QVERIFY(!old.isEmpty());
    QVERIFY2(volume.fill(), qPrintable(volume.problem()));

    QVERIFY(!dock->saveCurrentAsPreset(QStringLiteral("New look")));
    const QString message = m_window->statusMessage();
    QVERIFY2(message.startsWith(QStringLiteral("Could not save the preset"))
            && message.contains(volume.filePath(QStringLiteral("new-look.json")))
            && message.contains(kNoSpace),
        qPrintable(message));
    QCOMPARE(fileBytes(oldPath), old);
    QCOMPARE(volume.entries(), QStringList {QStringLiteral("old-look.json")});

    QVERIFY(volume.drain());
    QVERIFY(dock->saveCurrentAsPreset(QStringLiteral("New look")));
    QCOMPARE(
        volume.entries(), (QStringList {QStringLiteral("new-look.json"), QStringLiteral("old-look.json")}));
}

QTEST_MAIN(SafeWriteUiTest)
#include "SafeWriteUiTest.moc"
