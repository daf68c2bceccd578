// Materials and maps moved between places in the main window under Xvfb (issue 30, "Materials as
// first-class objects"), driven as an artist does:
// - Edit > Copy / Paste Material (Ctrl+Shift+C / V, ui/document/MaterialTransfer): factors, maps and options
//   onto the current material, its name kept, one undo step; a clipboard without one says so.
// - A material assigned to the selected parts (several rows of the Parts list, or Ctrl+clicks in
//   the viewport) in one undo step, from the Assign to Selected button's menu.
// - One map copied and pasted (a slot's context menu: Copy Map, Paste Map, Paste Value), from one
//   material's slot to another material's slot of the same or another kind, one undo step each.
// - A material or preset dropped on a part in the viewport: a project material assigned, a preset
//   added and assigned, one undo step each; a drop beside the mesh changes nothing.
// - The preset library (the Material dock's Presets): search by name, large swatches in a grid,
//   Save to Library (the current material with its textures, as a package), and files added to a
//   preset folder listed without a restart.
// Needs a display (Xvfb via with-display.sh).

#include "core/material/Material.h"
#include "core/project/Project.h"
#include "ui/MainWindow.h"
#include "ui/docks/MapSlotWidget.h"
#include "ui/docks/MaterialDock.h"
#include "ui/docks/MaterialsDock.h"
#include "ui/docks/TextureMapsDock.h"
#include "ui/document/Document.h"
#include "ui/document/MaterialTransfer.h"
#include "ui/document/ProjectFileController.h"
#include "ui/document/UserPresets.h"
#include "ui/viewport/PartPicker.h"
#include "ui/viewport/SceneController.h"
#include "ui/viewport/SurfaceFormat.h"
#include "ui/viewport/ViewportWidget.h"

#include "TestAssets.h"
#include "TwoMaterialWindow.h"
#include "WindowTestSupport.h"

#include <QApplication>
#include <QClipboard>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QToolButton>
#include <QTreeWidget>
#include <QUndoStack>
#include <QtTest/QTest>

#include <map>
#include <memory>
#include <vector>

using namespace facet;

namespace {

using test::materialNames;
std::vector<std::string> partMaterials(const Project& project)
{
    return test::partMaterialNames(project);
}
using Names = std::vector<std::string>;

} // namespace

class MaterialTransferUiTest : public QObject, public test::TwoMaterialWindowFixture {
    Q_OBJECT
public:
    static void initMain() { test::initWindowTestMain(); }

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void copyAndPasteAMaterial();
    void assignAMaterialToSelectedParts();
    void copyAndPasteAMapOrAValue();
    void dropAMaterialOrAPresetOnAPart();
    void theLibrarySearchesAndShowsLargeSwatches();
    void savedToTheLibraryAndWatchedFolders();

private:
};

void MaterialTransferUiTest::initTestCase()
{
    // The test's own presets folder (test mode), emptied before the window reads it: what a run
    // saved must not meet the next.
    QCoreApplication::setOrganizationName(QStringLiteral("FacetTests"));
    QVERIFY(QDir(UserPresets::directory()).removeRecursively());
    QSettings().remove(QStringLiteral("presets"));
    initWindowFixture();
}

void MaterialTransferUiTest::cleanupTestCase()
{
    cleanupWindowFixture();
}

void MaterialTransferUiTest::copyAndPasteAMaterial()
{
    QVERIFY(openTwoMaterials());
    Material red = m_document->project().materials[0];
    red.setFactor(MapSlot::Roughness, 0.31);
    red.map(MapSlot::Normal).path = m_dir.filePath(QStringLiteral("normal.png")).toStdString();
    red.ior = 1.7;
    m_document->setMaterial(red, QStringLiteral("Set up"));
    m_document->undoStack()->clear();
    QVERIFY(focus(m_window->viewport()));
    QTest::keyClick(m_window->viewport(), Qt::Key_C, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY2(m_window->statusMessage().startsWith(QStringLiteral("Copied “Red”")),
        qPrintable(m_window->statusMessage()));
    m_document->setCurrentMaterial(1);
    const Material blue = m_document->project().material();
    QTest::keyClick(m_window->viewport(), Qt::Key_V, Qt::ControlModifier | Qt::ShiftModifier);
    Material pasted = m_document->project().material();
    QCOMPARE(pasted.name, std::string("Blue"));
    pasted.name = red.name;
    QVERIFY(pasted == red);
    QCOMPARE(m_document->undoStack()->count(), 1);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Paste Material"));
    QVERIFY2(m_window->statusMessage().startsWith(QStringLiteral("Pasted “Red” onto “Blue”")),
        qPrintable(m_window->statusMessage()));
    m_document->undoStack()->undo();
    QVERIFY(m_document->project().material() == blue);

    QGuiApplication::clipboard()->setText(QStringLiteral("not a material"));
    QTest::keyClick(m_window->viewport(), Qt::Key_V, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(m_document->project().material() == blue);
    QCOMPARE(m_window->statusMessage(),
        QStringLiteral("The clipboard holds no material (Edit > Copy Material copies one)"));
    QGuiApplication::clipboard()->setText(QStringLiteral("{\"roughness\": {\"factor\": \"high\"}}"));
    m_window->pasteMaterial();
    QVERIFY(m_document->project().material() == blue);
    QVERIFY2(m_window->statusMessage().startsWith(
                 QStringLiteral("The clipboard's material cannot be used: material.roughness")),
        qPrintable(m_window->statusMessage()));
}

void MaterialTransferUiTest::assignAMaterialToSelectedParts()
{
    QVERIFY(openTwoMaterials());
    MaterialsDock* dock = m_window->materialsDock();
    QCOMPARE(partMaterials(m_document->project()), (Names {"Red", "Blue"}));
    QToolButton* assign = dock->assignToPartsButton();
    dock->partList()->clearSelection();
    QVERIFY(!assign->isEnabled());
    // Both rows selected (as Ctrl-click does), then "Blue" from the button's menu.
    dock->partList()->topLevelItem(0)->setSelected(true);
    dock->partList()->topLevelItem(1)->setSelected(true);
    QVERIFY(assign->isEnabled());
    QCOMPARE(dock->selectedParts(), (std::vector<int> {0, 1}));
    Q_EMIT assign->menu()->aboutToShow();
    QAction* blue = assign->menu()->findChild<QAction*>(QStringLiteral("assignMaterial_1"));
    QVERIFY(blue);
    const int steps = m_document->undoStack()->count();
    blue->trigger();
    QCOMPARE(partMaterials(m_document->project()), (Names {"Blue", "Blue"}));
    QCOMPARE(m_document->undoStack()->count(), steps + 1);
    QCOMPARE(m_window->statusMessage(), QStringLiteral("Assigned Blue to 1 part")); // the other had it
    // Red to both: two parts in one step; Ctrl+Z takes both back.
    dock->assignMaterialToParts(0, dock->selectedParts());
    QCOMPARE(partMaterials(m_document->project()), (Names {"Red", "Red"}));
    QCOMPARE(m_window->statusMessage(), QStringLiteral("Assigned Red to 2 parts"));
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Assign Red to 2 parts"));
    m_document->undoStack()->undo();
    QCOMPARE(partMaterials(m_document->project()), (Names {"Blue", "Blue"}));
    // Ctrl-clicks in the viewport (PartPicker, extend) add a part to the selection or take it out.
    dock->selectPart(0);
    QCOMPARE(dock->selectedParts(), (std::vector<int> {0}));
    dock->selectPart(1, true);
    QCOMPARE(dock->selectedParts(), (std::vector<int> {0, 1}));
    dock->selectPart(0, true);
    QCOMPARE(dock->selectedParts(), (std::vector<int> {1}));
    dock->selectPart(0, true);
    // Nothing to change: no step, and the status bar says so.
    dock->assignMaterialToParts(1, {0, 1});
    QCOMPARE(m_document->undoStack()->index(), steps + 1);
    QVERIFY(m_document->undoStack()->canRedo());
    QCOMPARE(m_window->statusMessage(), QStringLiteral("The selected parts already show Blue"));
}

void MaterialTransferUiTest::copyAndPasteAMapOrAValue()
{
    QVERIFY(openTwoMaterials());
    // Red's roughness reads the green channel of an ORM file, inverted, at 0.4.
    Material red = m_document->project().materials[0];
    const std::string orm = m_dir.filePath(QStringLiteral("orm.png")).toStdString();
    MaterialMap& roughness = red.map(MapSlot::Roughness);
    roughness.path = orm;
    roughness.channel = MapChannel::G;
    roughness.invert = true;
    red.setFactor(MapSlot::Roughness, 0.4);
    m_document->setMaterial(red, QStringLiteral("Set up"));
    m_document->undoStack()->clear();
    QGuiApplication::clipboard()->clear();
    TextureMapsDock* maps = m_window->textureMapsDock();
    // Nothing copied yet: the pastes say so and change nothing.
    QVERIFY(!maps->slotWidget(MapSlot::Metallic)->pasteMap());
    QVERIFY2(m_window->statusMessage().contains(QStringLiteral("the clipboard holds no map")),
        qPrintable(m_window->statusMessage()));
    maps->slotWidget(MapSlot::Roughness)->copyMap();
    QCOMPARE(m_window->statusMessage(), QStringLiteral("Copied the roughness map (orm.png)"));

    // Onto Blue's metallic (one kind: all of it) and its roughness value, each one step.
    m_document->setCurrentMaterial(1);
    const int steps = m_document->undoStack()->index();
    QVERIFY(maps->slotWidget(MapSlot::Metallic)->pasteMap());
    const MaterialMap& metallic = m_document->project().materials[1].map(MapSlot::Metallic);
    QCOMPARE(metallic.path, orm);
    QCOMPARE(metallic.channel, MapChannel::G);
    QVERIFY(metallic.invert);
    QCOMPARE(metallic.factor.x, 0.4);
    QCOMPARE(m_window->statusMessage(), QStringLiteral("Pasted the roughness map onto metallic"));
    QVERIFY(maps->slotWidget(MapSlot::Roughness)->pasteValue());
    QCOMPARE(m_document->project().materials[1].map(MapSlot::Roughness).factor.x, 0.4);
    QVERIFY(!m_document->project().materials[1].map(MapSlot::Roughness).hasTexture()); // the value only
    QCOMPARE(m_document->undoStack()->index(), steps + 2);
    // A scalar value does not fit a colour; the map does, read as a colour map reads.
    QVERIFY(!maps->slotWidget(MapSlot::BaseColor)->pasteValue());
    QCOMPARE(m_window->statusMessage(),
        QStringLiteral("Paste Value: a roughness value does not fit the base colour slot"));
    QVERIFY(maps->slotWidget(MapSlot::Normal)->pasteMap());
    const MaterialMap& normal = m_document->project().materials[1].map(MapSlot::Normal);
    QCOMPARE(normal.path, orm);
    QCOMPARE(normal.channel, MapChannel::Rgb);
    QVERIFY(!normal.invert);
    QCOMPARE(normal.factor.x, 1.0); // its own strength
    // Undo takes the pastes back one at a time; Red is untouched throughout.
    m_document->undoStack()->undo();
    QVERIFY(!m_document->project().materials[1].map(MapSlot::Normal).hasTexture());
    m_document->undoStack()->undo();
    m_document->undoStack()->undo();
    QVERIFY(!m_document->project().materials[1].map(MapSlot::Metallic).hasTexture());
    QCOMPARE(m_document->project().materials[0].map(MapSlot::Roughness), roughness);
}

void MaterialTransferUiTest::dropAMaterialOrAPresetOnAPart()
{
    QVERIFY(openTwoMaterials());
    QCOMPARE(partMaterials(m_document->project()), (Names {"Red", "Blue"}));
    // Where each part is on screen (and a place with none), as a click would find them.
    PartPicker* picker = m_window->partPicker();
    std::map<int, QPointF> at;
    std::optional<QPointF> nowhere;
    const QSize size = m_window->viewport()->size();
    for (int y = 4; y < size.height(); y += 8)
        for (int x = 4; x < size.width(); x += 8) {
            const QPointF position(x + 0.5, y + 0.5);
            if (const std::optional<int> part = picker->partAt(position))
                at.emplace(*part, position);
            else if (!nowhere)
                nowhere = position;
        }
    QVERIFY(at.count(0) && at.count(1) && nowhere);
    MaterialDropHandler* drops = m_window->materialDrops();
    const int steps = m_document->undoStack()->index();

    // Blue, dragged from the Materials list, onto part 0: assigned, no new material.
    std::unique_ptr<QMimeData> blue(materialMimeData(m_document->project().materials[1], 1));
    QVERIFY(drops->dropMaterial(blue.get(), at[0]));
    QCOMPARE(partMaterials(m_document->project()), (Names {"Blue", "Blue"}));
    QCOMPARE(materialNames(m_document->project()), (Names {"Red", "Blue"}));
    QCOMPARE(m_document->undoStack()->index(), steps + 1);
    // The Gold preset onto part 1: a new material "Gold", shown there and made current.
    QListWidget* presets = m_window->findChild<QListWidget*>(QStringLiteral("presetList"));
    QVERIFY(presets);
    QListWidgetItem* gold = presets->findItems(QStringLiteral("Gold"), Qt::MatchStartsWith).value(0);
    QVERIFY(gold);
    std::unique_ptr<QMimeData> preset(m_window->findChild<MaterialDock*>()->presetMimeData(gold));
    QVERIFY(!preset->hasFormat(QLatin1String(kMaterialIndexMime)));
    QVERIFY(drops->dropMaterial(preset.get(), at[1]));
    QCOMPARE(materialNames(m_document->project()), (Names {"Red", "Blue", "Gold"}));
    QCOMPARE(partMaterials(m_document->project()), (Names {"Blue", "Gold"}));
    QCOMPARE(m_document->project().currentMaterial, 2);
    QCOMPARE(m_document->undoStack()->index(), steps + 2);
    QVERIFY2(m_document->undoStack()->undoText().startsWith(QStringLiteral("Drop Gold onto")),
        qPrintable(m_document->undoStack()->undoText()));
    // Beside the mesh, or the same material again: nothing changes, the status bar says why.
    QVERIFY(!drops->dropMaterial(preset.get(), *nowhere));
    QVERIFY2(m_window->statusMessage().startsWith(QStringLiteral("Drop “Gold” on a part of the mesh")),
        qPrintable(m_window->statusMessage()));
    QVERIFY(!drops->dropMaterial(blue.get(), at[0]));
    QCOMPARE(m_document->undoStack()->index(), steps + 2);
    // Undo takes the preset's material away again, then the assignment.
    m_document->undoStack()->undo();
    QCOMPARE(materialNames(m_document->project()), (Names {"Red", "Blue"}));
    m_document->undoStack()->undo();
    QCOMPARE(partMaterials(m_document->project()), (Names {"Red", "Blue"}));
}

void MaterialTransferUiTest::theLibrarySearchesAndShowsLargeSwatches()
{
    MaterialDock* dock = m_window->findChild<MaterialDock*>();
    QListWidget* list = dock->presetList();
    const auto visible = [list] {
        QStringList names;
        for (int row = 0; row < list->count(); ++row)
            if (!list->item(row)->isHidden())
                names.append(list->item(row)->text());
        return names;
    };
    const int all = int(visible().size());
    QVERIFY(all >= 9);
    auto* search = dock->findChild<QLineEdit*>(QStringLiteral("presetSearch"));
    QVERIFY(search);
    QTest::keyClicks(search, QStringLiteral("GOL"));
    QCOMPARE(visible(), QStringList {QStringLiteral("Gold")});
    search->clear();
    QCOMPARE(int(visible().size()), all);
    QTest::keyClicks(search, QStringLiteral("no such preset"));
    QVERIFY(visible().isEmpty());
    search->clear();

    // Large swatches: a grid of 96-pixel swatches, rendered at that size; back to the list.
    auto* large = dock->findChild<QToolButton*>(QStringLiteral("largeSwatchesButton"));
    large->click();
    QVERIFY(dock->largeSwatches());
    QCOMPARE(list->viewMode(), QListView::IconMode);
    QCOMPARE(list->iconSize(), QSize(MaterialDock::kLargeSwatchSize, MaterialDock::kLargeSwatchSize));
    QVERIFY(QTest::qWaitFor([dock] { return dock->pendingSwatches() == 0; }, 30000));
    const QListWidgetItem* gold = list->findItems(QStringLiteral("Gold"), Qt::MatchExactly).value(0);
    QVERIFY(gold);
    QVERIFY(QTest::qWaitFor(
        [gold] {
            const QList<QSize> sizes = gold->icon().availableSizes();
            return !sizes.isEmpty() && sizes.first().width() >= MaterialDock::kLargeSwatchSize;
        },
        30000));
    QCOMPARE(QSettings().value(QStringLiteral("presets/largeSwatches")).toBool(), true);
    large->click();
    QCOMPARE(list->viewMode(), QListView::ListMode);
    QCOMPARE(list->iconSize(), QSize(MaterialDock::kSwatchSize, MaterialDock::kSwatchSize));
}

void MaterialTransferUiTest::savedToTheLibraryAndWatchedFolders()
{
    m_document->newProject();
    MaterialDock* dock = m_window->findChild<MaterialDock*>();
    QListWidget* list = dock->presetList();
    // The current material with a texture, saved to the library: a package in the presets folder,
    // listed and selected at once.
    const QString base = m_dir.filePath(QStringLiteral("library_basecolor.png"));
    QImage texture(8, 8, QImage::Format_RGB888);
    texture.fill(QColor(200, 120, 40));
    QVERIFY(texture.save(base));
    Material material = m_document->project().material();
    material.map(MapSlot::BaseColor).path = base.toStdString();
    m_document->setMaterial(material, QStringLiteral("Texture"));
    QVERIFY(dock->saveCurrentToLibrary(QStringLiteral("Rusty Panel")));
    QVERIFY(list->currentItem());
    QVERIFY2(list->currentItem()->text().startsWith(QStringLiteral("Rusty Panel (user, with textures)")),
        qPrintable(list->currentItem()->text()));
    QVERIFY(QFileInfo(list->currentItem()->toolTip()).isDir()); // the package's folder
    QVERIFY(list->currentItem()->toolTip().startsWith(UserPresets::directory()));
    QVERIFY(dock->watchedFolders().contains(UserPresets::directory()));

    // A preset file copied into the folder by another program appears without a reload call.
    QString error;
    const QString written = UserPresets::save(QStringLiteral("Copied In"), Material(), &error);
    QVERIFY2(!written.isEmpty(), qPrintable(error));
    // (save wrote it into the watched folder: the watcher, not this call, lists it)
    QVERIFY(QTest::qWaitFor(
        [list] { return !list->findItems(QStringLiteral("Copied In"), Qt::MatchStartsWith).isEmpty(); },
        MaterialDock::kWatchDelayMs * 20));
    // And a file removed behind Facet's back goes.
    QVERIFY(QFile::remove(written));
    QVERIFY(QTest::qWaitFor(
        [list] { return list->findItems(QStringLiteral("Copied In"), Qt::MatchStartsWith).isEmpty(); },
        MaterialDock::kWatchDelayMs * 20));
}

QTEST_MAIN(MaterialTransferUiTest)
#include "MaterialTransferUiTest.moc"
