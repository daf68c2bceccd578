// The five dock panels driven through their widgets, in the main window under Xvfb: a roughness
// slider drag is one undo step that re-renders and undoes back into the control; an image dropped
// on a map slot becomes its texture (and a non-image is refused with a message); a folder of maps
// is assigned by name in one step with a message saying what went where (the naming table is
// MapNamingTest's, packed channels and whole-set replacement TextureSetUiTest's); the environment
// library switches the environment and relights, and tells the built-in studio/sky from the
// installed samples of those names; lights are added, edited and removed through the Lights dock;
// the View dock changes exposure and the debug view, which have descriptive names; a mesh warning
// reaches the status bar in the window's wording (ui/widgets/WindowMessages.h); presets are saved,
// applied, deleted.

#include "core/material/MaterialPresets.h"
#include "core/material/PresetPackage.h"
#include "render/ShaderVariant.h"
#include "ui/MainWindow.h"
#include "ui/docks/EnvironmentDock.h"
#include "ui/docks/LightsDock.h"
#include "ui/docks/MapSlotWidget.h"
#include "ui/docks/MaterialDock.h"
#include "ui/docks/TextureMapsDock.h"
#include "ui/docks/ViewDock.h"
#include "ui/document/Document.h"
#include "ui/document/ProjectFileController.h"
#include "ui/document/UserPresets.h"
#include "ui/viewport/SceneController.h"
#include "ui/viewport/SurfaceFormat.h"
#include "ui/viewport/ViewportWidget.h"
#include "ui/widgets/ValueSlider.h"

#include "TestAssets.h"
#include "TestSupport.h"
#include "WindowTestSupport.h"

#include <QAbstractItemView>
#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QListWidget>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QRegularExpression>
#include <QSet>
#include <QSignalSpy>
#include <QSlider>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QUrl>
#include <QtTest/QTest>

#include <memory>

using namespace facet;

namespace {

using test::chooseInCombo;
using test::waitFor;

// Drags `urls` onto `target` and drops them there, as the desktop would.
bool dropUrls(QWidget* target, const QList<QUrl>& urls)
{
    QMimeData mime;
    mime.setUrls(urls);
    const QPoint pos = target->rect().center();
    QDragEnterEvent enter(pos, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(target, &enter);
    if (!enter.isAccepted())
        return false;
    QDropEvent drop(QPointF(pos), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(target, &drop);
    return drop.isAccepted();
}

bool writePng(const QString& path, QColor color, QSize size = QSize(8, 8))
{
    QImage image(size, QImage::Format_RGB32);
    image.fill(color);
    return image.save(path);
}

} // namespace

class DocksUiTest : public QObject {
    Q_OBJECT
public:
    static void initMain()
    {
        QStandardPaths::setTestModeEnabled(true);
        installViewportSurfaceFormat();
    }

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void roughnessDragIsOneUndoStep();
    void dropImageOnSlot();
    void dropNonImageIsRefused();
    void dropFolderAssignsByName();
    void environmentLibrarySwitches();
    void environmentLibraryTellsStudiosApart_data();
    void environmentLibraryTellsStudiosApart();
    void lightsAddEditRemove();
    void lightingMethodRefinesTheView();
    void viewDockExposureAndDebugView();
    void debugViewsHaveDescriptiveNames_data();
    void debugViewsHaveDescriptiveNames();
    void meshWarningInWindowWording();
    void presetsSaveApplyDelete();
    void presetPackages();
    void presetFolders();
    void presetSwatches();

private:
    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
    Document* m_document = nullptr;
    ViewportWidget* m_viewport = nullptr;
};

void DocksUiTest::initTestCase()
{
    QCoreApplication::setOrganizationName(QStringLiteral("FacetTests"));
    QVERIFY(m_dir.isValid());
    // The library lists the installed samples where the tests find them too.
    qputenv("FACET_ASSETS_DIR", test::assetsDir().toLocal8Bit());
    m_window = std::make_unique<MainWindow>(nullptr, m_dir.filePath(QStringLiteral("recovery")));
    m_document = m_window->document();
    m_viewport = m_window->viewport();
    QSignalSpy rendered(m_viewport, &ViewportWidget::frameRendered);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    m_window->resetLayout(); // another test's saved layout must not hide a dock
    QVERIFY(rendered.count() > 0 || rendered.wait(60000));
    m_window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    for (QDockWidget* dock : m_window->findChildren<QDockWidget*>())
        QVERIFY2(!dock->objectName().isEmpty(), qPrintable(dock->windowTitle()));
}

void DocksUiTest::cleanupTestCase()
{
    m_document->newProject(); // nothing to ask about on close
    m_window.reset();
}

void DocksUiTest::roughnessDragIsOneUndoStep()
{
    m_window->textureMapsDock()->raise();
    auto* control = m_window->findChild<ValueSlider*>(QStringLiteral("factorSlider_roughness"));
    QVERIFY(control);
    QSlider* slider = control->slider();
    const double before = m_document->project().material().roughness();
    QCOMPARE(control->value(), before);
    const int stepsBefore = m_document->undoStack()->index();
    const SceneController::LoadCounts loadsBefore = m_window->sceneController()->loadCounts();
    QSignalSpy rendered(m_viewport, &ViewportWidget::frameRendered);

    test::dragSlider(slider, slider->width() / 4);

    const double after = m_document->project().material().roughness();
    QVERIFY2(after > before + 0.05, qPrintable(QStringLiteral("roughness %1 -> %2").arg(before).arg(after)));
    QCOMPARE(control->value(), after);
    QCOMPARE(control->spinBox()->value(), after);
    QVERIFY(!m_document->interactiveEditOpen());
    QCOMPARE(m_document->undoStack()->index(), stepsBefore + 1); // the whole drag: one step
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Roughness"));
    QVERIFY(rendered.count() > 0 || rendered.wait(30000));
    // A factor change reloads nothing.
    QCOMPARE(m_window->sceneController()->loadCounts().maps, loadsBefore.maps);
    QCOMPARE(m_window->sceneController()->loadCounts().environments, loadsBefore.environments);

    // Undo through the Edit menu's action: the old value, in the document and in the control.
    auto* undo = m_window->findChild<QAction*>(QStringLiteral("undoAction"));
    QVERIFY(undo);
    QCOMPARE(undo->text(), QStringLiteral("&Undo Roughness"));
    rendered.clear();
    undo->trigger();
    QCOMPARE(m_document->project().material().roughness(), before);
    QCOMPARE(control->value(), before);
    QCOMPARE(control->spinBox()->value(), before);
    QCOMPARE(slider->value(), int(std::lround(before * ValueSlider::kSteps)));
    QVERIFY(rendered.count() > 0 || rendered.wait(30000));
}

void DocksUiTest::dropImageOnSlot()
{
    const QString file = m_dir.filePath(QStringLiteral("red.png"));
    QVERIFY(writePng(file, QColor(200, 30, 30), QSize(16, 8)));
    MapSlotWidget* slot = m_window->textureMapsDock()->slotWidget(MapSlot::BaseColor);
    const int stepsBefore = m_document->undoStack()->index();
    const int mapLoadsBefore = m_window->sceneController()->loadCounts().maps;
    QSignalSpy rendered(m_viewport, &ViewportWidget::frameRendered);

    QVERIFY(dropUrls(slot, {QUrl::fromLocalFile(file)}));

    const MaterialMap& map = m_document->project().material().map(MapSlot::BaseColor);
    QCOMPARE(QString::fromStdString(map.path), file);
    QCOMPARE(map.colorSpace, ColorEncoding::SRGB);
    QCOMPARE(m_document->undoStack()->index(), stepsBefore + 1);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Set Base Colour Map"));
    QCOMPARE(m_window->sceneController()->loadCounts().maps, mapLoadsBefore + 1); // that map only
    QVERIFY(rendered.count() > 0 || rendered.wait(30000));
    // The slot shows the file, its resolution and a thumbnail (made off the GUI thread).
    QVERIFY(waitFor([&] { return m_window->textureMapsDock()->pendingThumbnails() == 0; }));
    QVERIFY2(
        slot->fileLabel()->text().contains(QStringLiteral("red.png")), qPrintable(slot->fileLabel()->text()));
    QVERIFY2(
        slot->fileLabel()->text().contains(QStringLiteral("16×8")), qPrintable(slot->fileLabel()->text()));

    // The file changes on disk: the watcher reloads that map (and nothing else).
    const int loadsBeforeReload = m_window->sceneController()->loadCounts().maps;
    QTest::qWait(1100); // file times have a resolution of a second on some file systems
    QVERIFY(writePng(file, QColor(30, 200, 30), QSize(32, 8)));
    QVERIFY(
        waitFor([&] { return m_window->sceneController()->loadCounts().maps > loadsBeforeReload; }, 10000));
    QVERIFY2(m_window->statusMessage().contains(QStringLiteral("Reloaded red.png")),
        qPrintable(m_window->statusMessage()));
    QVERIFY(waitFor([&] { return slot->fileLabel()->text().contains(QStringLiteral("32×8")); }, 10000));
    QCOMPARE(m_document->undoStack()->index(), stepsBefore + 1); // a reload is not an edit

    // Deleted, then made again (an exporter that clears the old set first): the file's watch
    // ended with the delete, and the folder's watch brings it back (issue 29: it never reloaded).
    QVERIFY(QFile::remove(file));
    QTest::qWait(300);
    const int loadsBeforeRecreate = m_window->sceneController()->loadCounts().maps;
    QVERIFY(writePng(file, QColor(30, 30, 200), QSize(48, 8)));
    QVERIFY(
        waitFor([&] { return m_window->sceneController()->loadCounts().maps > loadsBeforeRecreate; }, 10000));
    QVERIFY(waitFor([&] { return slot->fileLabel()->text().contains(QStringLiteral("48×8")); }, 10000));
    QCOMPARE(m_document->undoStack()->index(), stepsBefore + 1);

    m_document->undoStack()->undo();
    QVERIFY(!m_document->project().material().map(MapSlot::BaseColor).hasTexture());
}

void DocksUiTest::dropNonImageIsRefused()
{
    const QString file = m_dir.filePath(QStringLiteral("notes.txt"));
    QFile text(file);
    QVERIFY(text.open(QIODevice::WriteOnly));
    text.write("not an image\n");
    text.close();
    const Project before = m_document->project();
    const int stepsBefore = m_document->undoStack()->index();
    QVERIFY(dropUrls(m_window->textureMapsDock()->slotWidget(MapSlot::Normal), {QUrl::fromLocalFile(file)}));
    QCOMPARE(m_document->project(), before);
    QCOMPARE(m_document->undoStack()->index(), stepsBefore);
    const QString message = m_window->statusMessage();
    QVERIFY2(
        message.contains(QStringLiteral("notes.txt")) && message.contains(QStringLiteral("not an image")),
        qPrintable(message));
}

void DocksUiTest::dropFolderAssignsByName()
{
    const QString folder = m_dir.filePath(QStringLiteral("wood"));
    QVERIFY(QDir().mkpath(folder));
    const QStringList names = {QStringLiteral("wood_basecolor.png"), QStringLiteral("wood_normal.png"),
        QStringLiteral("wood_roughness.png"), QStringLiteral("wood_ao.png"),
        QStringLiteral("wood_metallic.png")};
    for (const QString& name : names)
        QVERIFY(writePng(QDir(folder).filePath(name), QColor(128, 128, 255)));
    QFile readme(QDir(folder).filePath(QStringLiteral("readme.txt")));
    QVERIFY(readme.open(QIODevice::WriteOnly));
    readme.close();
    const Material before = m_document->project().material();
    const int stepsBefore = m_document->undoStack()->index();
    QSignalSpy rendered(m_viewport, &ViewportWidget::frameRendered);

    QVERIFY(dropUrls(m_window->textureMapsDock(), {QUrl::fromLocalFile(folder)}));

    const Material& material = m_document->project().material();
    const auto pathOf = [&](MapSlot slot) { return QString::fromStdString(material.map(slot).path); };
    QCOMPARE(pathOf(MapSlot::BaseColor), QDir(folder).filePath(QStringLiteral("wood_basecolor.png")));
    QCOMPARE(pathOf(MapSlot::Normal), QDir(folder).filePath(QStringLiteral("wood_normal.png")));
    QCOMPARE(pathOf(MapSlot::Roughness), QDir(folder).filePath(QStringLiteral("wood_roughness.png")));
    QCOMPARE(pathOf(MapSlot::Occlusion), QDir(folder).filePath(QStringLiteral("wood_ao.png")));
    QCOMPARE(pathOf(MapSlot::Metallic), QDir(folder).filePath(QStringLiteral("wood_metallic.png")));
    QCOMPARE(material.map(MapSlot::Roughness).channel, MapChannel::R);
    QCOMPARE(m_document->undoStack()->index(), stepsBefore + 1);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Assign Maps"));
    const QString message = m_window->statusMessage();
    QVERIFY2(message.startsWith(QStringLiteral("Assigned 5 maps")), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("Normal ← wood_normal.png")), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral("readme.txt")), qPrintable(message));
    QCOMPARE(m_window->textureMapsDock()->lastMessage(), message);
    QVERIFY(rendered.count() > 0 || rendered.wait(30000));

    m_document->undoStack()->undo(); // one step takes all five back
    QCOMPARE(m_document->project().material(), before);
}

void DocksUiTest::environmentLibrarySwitches()
{
    EnvironmentDock* dock = m_window->environmentDock();
    dock->raise();
    QListWidget* library = dock->library();
    QVERIFY(waitFor([&] { return dock->pendingThumbnails() == 0; }, 120000));
    qInfo("environment library: %d entries, thumbnails %.0f ms in all (one worker thread)", library->count(),
        dock->thumbnailMilliseconds());
    QListWidgetItem* sky = nullptr;
    for (int row = 0; row < library->count(); ++row)
        if (library->item(row)->data(Qt::UserRole).toString() == QStringLiteral("sky"))
            sky = library->item(row);
    QVERIFY(sky);
    QVERIFY(!sky->icon().isNull());
    QCOMPARE(m_document->project().environment.source, std::string("studio"));
    const int environmentLoads = m_window->sceneController()->loadCounts().environments;
    QSignalSpy rendered(m_viewport, &ViewportWidget::frameRendered);

    library->scrollToItem(sky);
    QTest::mouseClick(
        library->viewport(), Qt::LeftButton, Qt::NoModifier, library->visualItemRect(sky).center());

    QCOMPARE(m_document->project().environment.source, std::string("sky"));
    QCOMPARE(m_window->sceneController()->loadCounts().environments, environmentLoads + 1);
    QVERIFY(rendered.count() > 0 || rendered.wait(60000));
    QVERIFY(waitFor([&] { return !m_viewport->lastFrameStats().reduced; }));

    // Intensity in EV, stored linear.
    auto* intensity = m_window->findChild<ValueSlider*>(QStringLiteral("environmentIntensitySlider"));
    QVERIFY(intensity);
    intensity->spinBox()->setValue(1.0); // what typing "1" + Enter does (keyboard tracking is off)
    QCOMPARE(m_document->project().environment.intensity, 2.0);

    m_document->undoStack()->undo();
    m_document->undoStack()->undo();
    QCOMPARE(m_document->project().environment.source, std::string("studio"));
    QCOMPARE(library->currentItem()->data(Qt::UserRole).toString(), QStringLiteral("studio"));
}

void DocksUiTest::environmentLibraryTellsStudiosApart_data()
{
    QTest::addColumn<QString>("source"); // {installed}: the installed samples' hdri folder
    QTest::addColumn<QString>("label");
    QTest::addColumn<QString>("toolTip");
    QTest::newRow("built-in studio") << "studio"
                                     << "Studio (built-in)"
                                     << "built into Facet";
    QTest::newRow("installed studio") << "{installed}/studio.exr"
                                      << "Studio (CC0 sample)"
                                      << "library:installed/hdri/studio.exr";
    QTest::newRow("built-in sky") << "sky"
                                  << "Sky (built-in)"
                                  << "built into Facet";
    QTest::newRow("installed sky") << "{installed}/sky.exr"
                                   << "Sky (CC0 sample)"
                                   << "library:installed/hdri/sky.exr";
}

// The built-in procedural "studio"/"sky" and the installed CC0 HDRIs of the same names are
// different environments: each has its own label and tooltip, choosing it selects exactly it, and
// a saved project reopens with it selected.
void DocksUiTest::environmentLibraryTellsStudiosApart()
{
    QFETCH(QString, source);
    QFETCH(QString, label);
    QFETCH(QString, toolTip);
    FACET_REQUIRE_ASSET(test::hdriPath(QStringLiteral("studio")), "hdri/studio.exr");
    FACET_REQUIRE_ASSET(test::hdriPath(QStringLiteral("sky")), "hdri/sky.exr");
    source.replace(QLatin1String("{installed}"), EnvironmentDock::installedHdriFolder());
    EnvironmentDock* dock = m_window->environmentDock();
    dock->raise();
    QListWidget* library = dock->library();
    QStringList labels;
    QListWidgetItem* item = nullptr;
    for (int row = 0; row < library->count(); ++row) {
        labels.append(library->item(row)->text());
        if (library->item(row)->data(Qt::UserRole).toString() == source)
            item = library->item(row);
    }
    QVERIFY2(item, qPrintable(source));
    // The label, and once the thumbnail is made the image's resolution on a line of its own.
    QVERIFY(waitFor([&] { return item->text().contains(QLatin1Char('\n')); }, 30000));
    QCOMPARE(item->text().section(QLatin1Char('\n'), 0, 0), label);
    const QString resolution = item->text().section(QLatin1Char('\n'), 1);
    QVERIFY2(QRegularExpression(QStringLiteral("^[1-9][0-9]*×[1-9][0-9]*$")).match(resolution).hasMatch(),
        qPrintable(resolution));
    QVERIFY2(item->toolTip().contains(toolTip), qPrintable(item->toolTip()));
    QVERIFY2(item->toolTip().contains(QString(resolution).replace(QStringLiteral("×"), QStringLiteral(" × "))
                 + QStringLiteral(" pixels")),
        qPrintable(item->toolTip()));
    for (QString& text : labels)
        text = text.section(QLatin1Char('\n'), 0, 0);
    QCOMPARE(labels.count(label), 1); // no other entry reads the same
    QCOMPARE(labels.size(), QSet<QString>(labels.begin(), labels.end()).size());

    library->scrollToItem(item);
    QTest::mouseClick(
        library->viewport(), Qt::LeftButton, Qt::NoModifier, library->visualItemRect(item).center());
    QCOMPARE(QString::fromStdString(m_document->project().environment.source), source);
    QCOMPARE(library->currentItem(), item);

    // Saved, something else chosen, reopened: the same entry is selected again.
    ProjectFileController* files = m_window->projectFiles();
    files->setErrorDialogsEnabled(false);
    files->setUnsavedChangesAnswer(QMessageBox::Discard);
    const QString path = m_dir.filePath(QStringLiteral("library-choice.json"));
    QVERIFY(files->saveToFile(path));
    EnvironmentSettings other = m_document->project().environment;
    other.source = source.contains(QLatin1String("studio")) ? "sky" : "studio";
    m_document->setEnvironment(other, QStringLiteral("Other"));
    QVERIFY(library->currentItem() != item);
    QVERIFY(files->openFile(path));
    QCOMPARE(QString::fromStdString(m_document->project().environment.source), source);
    QVERIFY(library->currentItem());
    QCOMPARE(library->currentItem()->data(Qt::UserRole).toString(), source);
    QCOMPARE(library->currentItem()->text().section(QLatin1Char('\n'), 0, 0), label);
    m_document->newProject();
}

void DocksUiTest::lightsAddEditRemove()
{
    LightsDock* dock = m_window->lightsDock();
    dock->raise();
    QVERIFY(m_document->project().lights.empty());
    QSignalSpy rendered(m_viewport, &ViewportWidget::frameRendered);

    dock->addLightAction(LightType::Spot)->trigger();
    QCOMPARE(m_document->project().lights.size(), std::size_t(1));
    QCOMPARE(m_document->project().lights[0].type, LightType::Spot);
    QCOMPARE(dock->list()->count(), 1);
    QCOMPARE(dock->currentLight(), 0);
    QVERIFY(rendered.count() > 0 || rendered.wait(30000));

    // Intensity: type 40 and Enter in the spin box (candela for a spot).
    QDoubleSpinBox* spin = dock->intensitySlider()->spinBox();
    QVERIFY2(spin->suffix().contains(QStringLiteral("cd")), qPrintable(spin->suffix()));
    spin->selectAll();
    QTest::keyClicks(spin, QStringLiteral("40"));
    QTest::keyClick(spin, Qt::Key_Return);
    QCOMPARE(m_document->project().lights[0].intensity, 40.0);
    // The outer cone by dragging its slider: one step.
    const int steps = m_document->undoStack()->index();
    const double outerBefore = m_document->project().lights[0].outerConeAngle;
    auto* outer = m_window->findChild<ValueSlider*>(QStringLiteral("lightOuterConeSlider"));
    QVERIFY(outer);
    test::dragSlider(outer->slider(), -outer->slider()->width() / 5);
    const Light& edited = m_document->project().lights[0];
    QVERIFY(edited.outerConeAngle < outerBefore);
    QVERIFY(edited.innerConeAngle < edited.outerConeAngle);
    QCOMPARE(m_document->undoStack()->index(), steps + 1);
    // Disable through the list's check box.
    dock->list()->item(0)->setCheckState(Qt::Unchecked);
    QVERIFY(!m_document->project().lights[0].enabled);

    // Duplicate, then remove the copy and the original.
    QTest::mouseClick(
        m_window->findChild<QPushButton*>(QStringLiteral("duplicateLightButton")), Qt::LeftButton);
    QCOMPARE(m_document->project().lights.size(), std::size_t(2));
    QTest::mouseClick(dock->removeButton(), Qt::LeftButton);
    QTest::mouseClick(dock->removeButton(), Qt::LeftButton);
    QVERIFY(m_document->project().lights.empty());
    QCOMPARE(dock->list()->count(), 0);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Remove Light"));
    m_document->undoStack()->undo();
    QCOMPARE(m_document->project().lights.size(), std::size_t(1));
    QCOMPARE(m_document->project().lights[0].intensity, 40.0);
    QCOMPARE(dock->list()->count(), 1);
    QCOMPARE(dock->intensitySlider()->value(), 40.0);
}

void DocksUiTest::lightingMethodRefinesTheView()
{
    // The Environment dock's Lighting: one undo step, the project's method (with its default
    // samples), and the still view refines by it; undo brings back the split sum.
    EnvironmentDock* dock = m_window->environmentDock();
    dock->raise();
    QVERIFY(waitFor([&] { return !m_viewport->isPreviewing(); }));
    auto* combo = dock->findChild<QComboBox*>(QStringLiteral("iblMethodCombo"));
    QVERIFY(combo);
    QCOMPARE(combo->currentText(), QStringLiteral("Split sum (real time)"));
    const int steps = m_document->undoStack()->index();
    QVERIFY(chooseInCombo(combo, QStringLiteral("Reference (converging)")));
    QCOMPARE(m_document->project().environment.method, IblMethod::Reference);
    QCOMPARE(m_document->project().environment.samples, 0);
    QCOMPARE(m_document->undoStack()->index(), steps + 1);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Lighting Method"));
    QVERIFY(waitFor([&] {
        const ViewportFrameStats& stats = m_viewport->lastFrameStats();
        return stats.refineMethod == IblMethod::Reference && stats.refinement.samples > 0;
    }));
    QCOMPARE(m_viewport->lastFrameStats().refinement.target, defaultIblSamples(IblMethod::Reference));
    QVERIFY2(m_viewport->lastError().isEmpty(), qPrintable(m_viewport->lastError()));
    m_document->undoStack()->undo();
    QCOMPARE(m_document->project().environment.method, IblMethod::SplitSum);
    QCOMPARE(combo->currentText(), QStringLiteral("Split sum (real time)"));
    QVERIFY(waitFor([&] { return m_viewport->lastFrameStats().refineMethod == IblMethod::SplitSum; }));
}

void DocksUiTest::viewDockExposureAndDebugView()
{
    ViewDock* dock = m_window->viewDock();
    dock->raise();
    QVERIFY(waitFor([&] { return !m_viewport->isPreviewing(); }));
    QSignalSpy rendered(m_viewport, &ViewportWidget::frameRendered);
    ValueSlider* exposure = dock->exposureSlider();
    const double before = m_document->project().view.exposureEV;
    const int steps = m_document->undoStack()->index();
    test::dragSlider(exposure->slider(), exposure->slider()->width() / 6);
    QVERIFY(m_document->project().view.exposureEV > before);
    QCOMPARE(m_document->undoStack()->index(), steps + 1);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Exposure"));
    QVERIFY(rendered.count() > 0 || rendered.wait(30000));

    QVERIFY(chooseInCombo(dock->debugViewCombo(), QStringLiteral("Roughness")));
    QCOMPARE(m_document->project().view.debugView, DebugView::Roughness);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Debug View"));
    rendered.clear();
    QVERIFY(rendered.wait(30000));
    QVERIFY2(m_viewport->lastError().isEmpty(), qPrintable(m_viewport->lastError()));
    // Every renderer debug view is offered.
    QCOMPARE(dock->debugViewCombo()->count(), kDebugViewCount);

    // The statistics show the GL renderer and a frame time.
    auto* glLabel = dock->findChild<QLabel*>(QStringLiteral("viewGlLabel"));
    auto* frameLabel = dock->findChild<QLabel*>(QStringLiteral("viewFrameLabel"));
    QVERIFY(glLabel->text().contains(QStringLiteral("OpenGL")));
    QVERIFY2(frameLabel->text().contains(QStringLiteral("ms")), qPrintable(frameLabel->text()));

    m_document->undoStack()->undo();
    m_document->undoStack()->undo();
    QCOMPARE(m_document->project().view.debugView, DebugView::None);
    QCOMPARE(dock->debugViewCombo()->currentText(), QStringLiteral("Off (shaded image)"));
    QCOMPARE(exposure->value(), before);
}

void DocksUiTest::debugViewsHaveDescriptiveNames_data()
{
    QTest::addColumn<QString>("label"); // what the View dock shows
    QTest::addColumn<QString>("name"); // what the project stores
    QTest::addColumn<QString>("alias"); // an older name that selects it too ("" for none)
    QTest::newRow("distribution") << "Distribution D"
                                  << "distribution"
                                  << "d";
    QTest::newRow("visibility") << "Visibility V"
                                << "visibility"
                                << "v";
    QTest::newRow("fresnel") << "Fresnel F"
                             << "fresnel"
                             << "f";
    QTest::newRow("none") << "Off (shaded image)"
                          << "none"
                          << "";
    QTest::newRow("base colour") << "Base colour"
                                 << "base-color"
                                 << "";
    QTest::newRow("occlusion") << "Ambient occlusion"
                               << "occlusion"
                               << "";
    QTest::newRow("brdf table") << "BRDF lookup table (DFG)"
                                << "brdf-lut"
                                << "";
}

void DocksUiTest::debugViewsHaveDescriptiveNames()
{
    QFETCH(QString, label);
    QFETCH(QString, name);
    QFETCH(QString, alias);
    ViewDock* dock = m_window->viewDock();
    dock->raise();
    QComboBox* combo = dock->debugViewCombo();
    // Every entry reads as words (no one-letter names), each differently.
    QStringList texts;
    for (int i = 0; i < combo->count(); ++i) {
        QVERIFY2(combo->itemText(i).size() > 3, qPrintable(combo->itemText(i)));
        texts.append(combo->itemText(i));
    }
    QCOMPARE(QSet<QString>(texts.begin(), texts.end()).size(), int(texts.size()));

    QVERIFY(chooseInCombo(combo, label));
    QCOMPARE(QString::fromLatin1(toString(m_document->project().view.debugView)), name);
    // A project of an older Facet stores the one-letter name: it reads as the same view
    // (ProjectTest::limitsAreInclusive loads one).
    if (!alias.isEmpty())
        QCOMPARE(
            debugViewFromString(alias.toStdString()), std::optional(m_document->project().view.debugView));
    m_document->newProject();
    QCOMPARE(combo->currentText(), QStringLiteral("Off (shaded image)"));
}

// A mesh without UVs, imported through the View dock: the status bar says so in the window's
// words, naming the file, without core's function name or folders.
void DocksUiTest::meshWarningInWindowWording()
{
    const QString path = m_dir.filePath(QStringLiteral("meshes/triangle.obj"));
    QVERIFY(QDir().mkpath(QFileInfo(path).absolutePath()));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n");
    file.close();
    QVERIFY(m_window->viewDock()->importMesh(path));
    // The mesh loads off the GUI thread (ui/document/DocumentAssets); its notes come when it arrives.
    QTRY_COMPARE_WITH_TIMEOUT(m_window->sceneController()->pendingAssetLoads(), 0, 30000);
    const QString message = m_window->statusMessage();
    QVERIFY2(message.startsWith(QStringLiteral(
                 "triangle.obj has no texture coordinates; Facet generated them by box projection")),
        qPrintable(message));
    QVERIFY2(!message.contains(QStringLiteral("importMesh")) && !message.contains(m_dir.path()),
        qPrintable(message));
    m_document->newProject();
}

void DocksUiTest::presetsSaveApplyDelete()
{
    MaterialDock* dock = m_window->materialDock();
    dock->raise();
    QListWidget* list = dock->presetList();
    QCOMPARE(list->count(), int(builtinPresets().size()) + int(UserPresets::load(nullptr).size()));
    QVERIFY(dock->saveCurrentAsPreset(QStringLiteral("My Plastic")));
    const QString path = QDir(UserPresets::directory()).filePath(QStringLiteral("my-plastic.json"));
    QVERIFY2(QFile::exists(path), qPrintable(path));
    QVERIFY(list->currentItem() && list->currentItem()->text() == QStringLiteral("My Plastic (user)"));

    const auto gold = list->findItems(QStringLiteral("Gold"), Qt::MatchExactly);
    QCOMPARE(gold.size(), 1);
    list->setCurrentItem(gold.first());
    const std::string name = m_document->project().material().name;
    QTest::mouseClick(dock->findChild<QPushButton*>(QStringLiteral("applyPresetButton")), Qt::LeftButton);
    QCOMPARE(m_document->project().material().name, name); // a preset keeps the material's name (issue 30)
    QCOMPARE(m_document->project().material().metallic(), 1.0);
    QVERIFY(!dock->findChild<QPushButton*>(QStringLiteral("deletePresetButton"))->isEnabled()); // built-in

    list->setCurrentItem(list->findItems(QStringLiteral("My Plastic (user)"), Qt::MatchExactly).first());
    QVERIFY(dock->applySelectedPreset());
    QCOMPARE(m_document->project().material().name, name);
    QVERIFY(dock->deleteSelectedPreset());
    QVERIFY(!QFile::exists(path));
    QVERIFY(list->findItems(QStringLiteral("My Plastic (user)"), Qt::MatchExactly).isEmpty());
    m_document->undoStack()->undo();
    m_document->undoStack()->undo();
}

// Export Package… and Import Package…: a textured material leaves as a package and comes back as
// a user preset "with textures"; applying it to a plain material brings the texture set (each
// map's file inside the installed package, its channel and options); deleting it removes the
// package's folder.
void DocksUiTest::presetPackages()
{
    QTemporaryDir sources;
    const QString projectPath = test::writeTexturedProject(sources.path());
    QVERIFY(!projectPath.isEmpty());
    std::string error;
    const std::optional<Project> textured = Project::load(projectPath.toStdString(), &error);
    QVERIFY2(textured, error.c_str());
    m_document->setProject(*textured, QStringLiteral("Open"));
    MaterialDock* dock = m_window->materialDock();
    QTemporaryDir outbox;
    const QString package = dock->exportCurrentAsPackage(QStringLiteral("Brick Pack"), outbox.path());
    QVERIFY2(!package.isEmpty(), qPrintable(m_window->statusMessage()));
    QCOMPARE(package, outbox.filePath(QStringLiteral("brick-pack.facetpreset")));

    QVERIFY(dock->importPackage(package));
    QListWidget* list = dock->presetList();
    QVERIFY(list->currentItem()
        && list->currentItem()->text() == QStringLiteral("Brick Pack (user, with textures)"));
    const QString installed
        = QDir(UserPresets::directory()).filePath(QStringLiteral("brick-pack.facetpreset"));
    QVERIFY(QFileInfo(installed).isDir());

    m_document->newProject(); // the default material: no textures
    QVERIFY(!m_document->project().material().map(MapSlot::BaseColor).hasTexture());
    const std::string name = m_document->project().material().name;
    QVERIFY(dock->applySelectedPreset());
    const Material& applied = m_document->project().material();
    QCOMPARE(applied.name, name); // the material keeps its name; the package brings its maps
    for (const MapSlot slot :
        {MapSlot::BaseColor, MapSlot::Normal, MapSlot::Occlusion, MapSlot::Roughness, MapSlot::Metallic}) {
        QVERIFY2(QString::fromStdString(applied.map(slot).path).startsWith(installed), toString(slot));
        QVERIFY(QFileInfo::exists(QString::fromStdString(applied.map(slot).path)));
    }
    QCOMPARE(applied.map(MapSlot::Roughness).channel, MapChannel::G);
    QVERIFY(!applied.map(MapSlot::Emissive).hasTexture());

    QVERIFY(dock->deleteSelectedPreset());
    QVERIFY(!QFileInfo::exists(installed));
    m_document->newProject();
}

// Add Folder…: a shared folder's presets and packages are listed with the user's, named after the
// folder; applying a package from there brings its textures; they cannot be deleted from Facet;
// a folder without presets is refused and names why.
void DocksUiTest::presetFolders()
{
    QTemporaryDir shared;
    QVERIFY(QDir().mkpath(shared.filePath(QStringLiteral("sources"))));
    const QString projectPath = test::writeTexturedProject(shared.filePath(QStringLiteral("sources")));
    QVERIFY(!projectPath.isEmpty());
    std::string error;
    const std::optional<Project> textured = Project::load(projectPath.toStdString(), &error);
    QVERIFY2(textured, error.c_str());
    const QString library = shared.filePath(QStringLiteral("team-presets"));
    QVERIFY(QDir().mkpath(library));
    MaterialPreset look;
    look.id = "team-red";
    look.displayName = "Team Red";
    look.material.setBaseColor(glm::dvec3(0.8, 0.05, 0.05));
    QVERIFY(savePreset(look, (library + QStringLiteral("/team-red.json")).toStdString(), &error));
    MaterialPreset brick {"team-brick", "Team Brick", textured->materials[0]};
    QVERIFY2(exportPresetPackage(brick, library.toStdString(), false, &error), error.c_str());

    MaterialDock* dock = m_window->materialDock();
    QVERIFY(!dock->addPresetFolder(shared.filePath(QStringLiteral("sources"))));
    QVERIFY2(m_window->statusMessage().contains(QStringLiteral("holds no preset")),
        qPrintable(m_window->statusMessage()));
    QVERIFY(dock->addPresetFolder(library));
    QListWidget* list = dock->presetList();
    QCOMPARE(list->findItems(QStringLiteral("Team Red (team-presets)"), Qt::MatchExactly).size(), 1);
    const auto packaged
        = list->findItems(QStringLiteral("Team Brick (team-presets, with textures)"), Qt::MatchExactly);
    QCOMPARE(packaged.size(), 1);
    list->setCurrentItem(packaged.first());
    QVERIFY(!dock->findChild<QPushButton*>(QStringLiteral("deletePresetButton"))->isEnabled());
    QVERIFY(!dock->deleteSelectedPreset());
    QVERIFY(QFileInfo::exists(library + QStringLiteral("/team-brick.facetpreset/preset.json")));
    QVERIFY(dock->applySelectedPreset());
    QVERIFY(QString::fromStdString(m_document->project().material().map(MapSlot::Normal).path)
                .startsWith(library + QStringLiteral("/team-brick.facetpreset/")));
    QVERIFY(UserPresets::folders().contains(QFileInfo(library).absoluteFilePath()));
    UserPresets::removeFolder(library);
    dock->reloadPresets();
    QVERIFY(list->findItems(QStringLiteral("Team Red (team-presets)"), Qt::MatchExactly).isEmpty());
    m_document->newProject();
}

// The preset list shows a rendered swatch per preset (ui/viewport/ThumbnailLoader requestSwatch on its
// worker, core/material/MaterialSwatch): every item gets its icon, and the icons show the materials
// (gold's redder than silver's).
void DocksUiTest::presetSwatches()
{
    MaterialDock* dock = m_window->materialDock();
    dock->reloadPresets();
    QTRY_COMPARE_WITH_TIMEOUT(dock->pendingSwatches(), 0, 60000);
    QListWidget* list = dock->presetList();
    QCOMPARE(list->iconSize(), QSize(MaterialDock::kSwatchSize, MaterialDock::kSwatchSize));
    for (int row = 0; row < list->count(); ++row)
        QVERIFY2(!list->item(row)->icon().isNull(), qPrintable(list->item(row)->text()));
    const auto centre = [list](const QString& name) {
        const QImage image = list->findItems(name, Qt::MatchExactly)
                                 .first()
                                 ->icon()
                                 .pixmap(MaterialDock::kSwatchSize)
                                 .toImage();
        return image.pixelColor(image.width() / 2, image.height() * 2 / 3);
    };
    const QColor gold = centre(QStringLiteral("Gold"));
    const QColor silver = centre(QStringLiteral("Silver"));
    QVERIFY2(gold.redF() - gold.blueF() > silver.redF() - silver.blueF() + 0.1,
        qPrintable(QStringLiteral("gold %1 silver %2").arg(gold.name(), silver.name())));
    // For a person to look at: the list as the dock shows it.
    list->scrollToTop();
    dock->raise();
    const QSize shown = dock->size();
    dock->resize(shown.width(), 900); // the whole dock, its list taller than in the default layout
    QCoreApplication::processEvents();
    dock->grab().save(test::outputDir() + QStringLiteral("/preset-swatches.png"));
    dock->resize(shown);
}

QTEST_MAIN(DocksUiTest)
#include "DocksUiTest.moc"
