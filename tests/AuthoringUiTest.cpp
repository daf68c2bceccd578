// Issue 30's authoring defects in the main window under Xvfb, driven as an artist does:
// - Materials as objects (ui/docks/MaterialsDock, core/material/MaterialList): New, Duplicate and Delete by
// the
//   buttons and by the list's keys, each one undo step that Ctrl+Z takes back, the parts showing
//   what they showed, the status bar saying what happened; the last material cannot go.
// - Undo from every kind of editor (ui/document/UndoShortcutRouter): an edit committed in a spin box,
//   slider, colour button, combo box, line edit or check box, the focus left in it, then Ctrl+Z
//   undoes the document and Ctrl+Shift+Z redoes it; a field with an uncommitted edit keeps Ctrl+Z
//   for its text.
// - Presets take Ctrl+1..9: the number key alone changes nothing; with Ctrl the look changes and the
//   name and maps stay, and the status bar says what changed.
// (Moving materials and maps between places: tests/MaterialTransferUiTest.cpp; inspection, the
// value picker, Inspect Map and the wireframe: tests/InspectionUiTest.cpp.)
// - The cache budget (ui/widgets/CacheBudget, Edit > Preferences): where the number comes from (setting,
//   FACET_CACHE_BUDGET_MB, default, each out of range), and the window's IBL cache keeping to it
//   while environments change, a new budget applying at the next frame; freed memory handed back
//   (ui/widgets/FreedMemoryTimer).
// Needs a display (Xvfb via with-display.sh).

#include "core/image/Image.h"
#include "core/support/FreedMemory.h"
#include "ui/MainWindow.h"
#include "ui/dialogs/ExportDialog.h"
#include "ui/dialogs/PreferencesDialog.h"
#include "ui/docks/MapSlotWidget.h"
#include "ui/docks/MaterialDock.h"
#include "ui/docks/MaterialsDock.h"
#include "ui/docks/TextureMapsDock.h"
#include "ui/document/Document.h"
#include "ui/document/MaterialTransfer.h"
#include "ui/document/ProjectFileController.h"
#include "ui/viewport/PartPicker.h"
#include "ui/viewport/SceneController.h"
#include "ui/viewport/SurfaceFormat.h"
#include "ui/viewport/ViewportWidget.h"
#include "ui/widgets/CacheBudget.h"
#include "ui/widgets/ColorButton.h"
#include "ui/widgets/FreedMemoryTimer.h"
#include "ui/widgets/ValueSlider.h"

#include "TestAssets.h"
#include "TwoMaterialWindow.h"
#include "WindowTestSupport.h"

#include <QAbstractItemView>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QClipboard>
#include <QColorDialog>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabBar>
#include <QTemporaryDir>
#include <QTimer>
#include <QToolButton>
#include <QTreeWidget>
#include <QUndoStack>
#include <QtTest/QTest>

#include <map>
#include <memory>
#include <thread>
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

class AuthoringUiTest : public QObject, public test::TwoMaterialWindowFixture {
    Q_OBJECT
public:
    static void initMain() { test::initWindowTestMain(); }

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void materialsAreObjects();
    void theLastMaterialStays();
    void undoReachesTheDocumentFromEveryEditor_data();
    void undoReachesTheDocumentFromEveryEditor();
    void anUncommittedFieldKeepsItsOwnUndo();
    void presetsNeedCtrlAndKeepNameAndMaps();
    void exportNamesAndFolderFollowTheProject();
    void normalStrengthAndUvScaleAsTheFormatHasThem();
    void messagesStayWhileTrueAndGoWhenNot();
    void docksShowEnoughAtASmallSize();
    void cacheBudgetComesFromSettingOrEnvironment_data();
    void cacheBudgetComesFromSettingOrEnvironment();
    void theLightingCacheKeepsToTheBudget();
    void freedMemoryGoesBackToTheSystem();

private:
    void keyOnFocus(Qt::Key key, Qt::KeyboardModifiers modifiers = Qt::NoModifier)
    {
        QWidget* target = QApplication::focusWidget() ? QApplication::focusWidget() : m_window.get();
        QTest::keyClick(target, key, modifiers);
    }
    template <typename T> T* child(const char* name) const
    {
        return m_window->findChild<T*>(QLatin1String(name));
    }
};

void AuthoringUiTest::initTestCase()
{
    initWindowFixture();
}

void AuthoringUiTest::cleanupTestCase()
{
    cleanupWindowFixture();
}

void AuthoringUiTest::materialsAreObjects()
{
    QVERIFY(openTwoMaterials());
    QCOMPARE(materialNames(m_document->project()), (Names {"Red", "Blue"}));
    QCOMPARE(partMaterials(m_document->project()), (Names {"Red", "Blue"}));
    QListWidget* list = child<QListWidget>("materialList");
    QVERIFY(list);
    QUndoStack* undo = m_document->undoStack();

    // The buttons.
    QTest::mouseClick(child<QToolButton>("newMaterialButton"), Qt::LeftButton);
    QCOMPARE(materialNames(m_document->project()), (Names {"Red", "Material", "Blue"}));
    QCOMPARE(m_document->project().currentMaterial, 1);
    QCOMPARE(list->currentRow(), 1);
    QCOMPARE(m_window->statusMessage(), QStringLiteral("New material “Material”"));
    QTest::mouseClick(child<QToolButton>("duplicateMaterialButton"), Qt::LeftButton);
    QCOMPARE(materialNames(m_document->project()), (Names {"Red", "Material", "Material copy", "Blue"}));
    QCOMPARE(m_document->project().currentMaterial, 2);
    QCOMPARE(partMaterials(m_document->project()), (Names {"Red", "Blue"})); // the parts kept theirs

    // The list's keys, with the list focused: Delete on Red (its part shows the new first).
    QVERIFY(focus(list));
    list->setCurrentRow(0);
    QTest::keyClick(list, Qt::Key_Delete);
    QCOMPARE(materialNames(m_document->project()), (Names {"Material", "Material copy", "Blue"}));
    QCOMPARE(partMaterials(m_document->project()), (Names {"Material", "Blue"}));
    QCOMPARE(m_window->statusMessage(),
        QStringLiteral("Deleted “Red”: its part shows “Material” (Ctrl+Z brings it back)"));
    QTest::keyClick(list, Qt::Key_D, Qt::ControlModifier);
    QCOMPARE(materialNames(m_document->project()),
        (Names {"Material", "Material copy 2", "Material copy", "Blue"}));
    QTest::keyClick(list, Qt::Key_N, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(m_document->project().materials.size(), std::size_t(5));
    QCOMPARE(m_document->project().material().name, std::string("Material 2"));
    QCOMPARE(undo->count(), 5);

    // Ctrl+Z five times, from the list: back where it was, parts and all.
    for (int i = 0; i < 5; ++i)
        QTest::keyClick(list, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(materialNames(m_document->project()), (Names {"Red", "Blue"}));
    QCOMPARE(partMaterials(m_document->project()), (Names {"Red", "Blue"}));
    QCOMPARE(list->count(), 2);
}

void AuthoringUiTest::theLastMaterialStays()
{
    m_document->newProject();
    QCOMPARE(m_document->project().materials.size(), std::size_t(1));
    QToolButton* remove = child<QToolButton>("deleteMaterialButton");
    QVERIFY(!remove->isEnabled());
    auto* dock = m_window->findChild<MaterialsDock*>();
    dock->deleteMaterial(0);
    QCOMPARE(m_document->project().materials.size(), std::size_t(1));
    QVERIFY2(m_window->statusMessage().contains(QStringLiteral("at least one material")),
        qPrintable(m_window->statusMessage()));
    QCOMPARE(m_document->undoStack()->count(), 0);
    QTest::mouseClick(child<QToolButton>("newMaterialButton"), Qt::LeftButton);
    QVERIFY(remove->isEnabled());
    m_document->undoStack()->undo();
    QVERIFY(!remove->isEnabled());
}

void AuthoringUiTest::undoReachesTheDocumentFromEveryEditor_data()
{
    QTest::addColumn<QString>("editor");
    for (const char* editor : {"spin box", "slider", "colour", "combo box", "line edit", "check box"})
        QTest::newRow(editor) << QString::fromLatin1(editor);
}

// Each editor's edit is committed as an artist commits it, with the focus left in the editor;
// then Ctrl+Z and Ctrl+Shift+Z on the focused widget.
void AuthoringUiTest::undoReachesTheDocumentFromEveryEditor()
{
    QFETCH(QString, editor);
    m_document->newProject();
    const Project before = m_document->project();
    if (editor == QLatin1String("spin box")) {
        // View > Exposure: type 2, Enter (the case).
        QDoubleSpinBox* spin = child<ValueSlider>("exposureSlider")->spinBox();
        QVERIFY(focus(spin));
        spin->selectAll();
        QTest::keyClicks(spin, QStringLiteral("2"));
        QTest::keyClick(spin, Qt::Key_Return);
        QCOMPARE(m_document->project().view.exposureEV, 2.0);
    } else if (editor == QLatin1String("slider")) {
        QSlider* slider = child<ValueSlider>("uvRotationSlider")->slider();
        QVERIFY(focus(slider));
        QTest::keyClick(slider, Qt::Key_PageUp);
    } else if (editor == QLatin1String("colour")) {
        auto* button = child<ColorButton>("baseColorButton");
        QVERIFY(focus(button));
        bool answered = false;
        QTimer poll;
        poll.setInterval(50);
        connect(&poll, &QTimer::timeout, this, [&] {
            if (auto* dialog = qobject_cast<QColorDialog*>(QApplication::activeModalWidget())) {
                poll.stop();
                dialog->setCurrentColor(QColor(20, 200, 40));
                answered = true;
                dialog->accept();
            }
        });
        poll.start();
        QTest::keyClick(button, Qt::Key_Space);
        QVERIFY(answered);
        QVERIFY(focus(button));
    } else if (editor == QLatin1String("combo box")) {
        QComboBox* combo = child<QComboBox>("toneMapperCombo");
        QVERIFY(focus(combo));
        QTest::keyClick(combo, Qt::Key_Down);
    } else if (editor == QLatin1String("line edit")) {
        auto* name = child<QLineEdit>("materialName");
        QVERIFY(focus(name));
        name->selectAll();
        QTest::keyClicks(name, QStringLiteral("Lacquer"));
        QTest::keyClick(name, Qt::Key_Return);
        QCOMPARE(m_document->project().material().name, std::string("Lacquer"));
    } else {
        auto* check = child<QCheckBox>("doubleSidedCheck");
        QVERIFY(focus(check));
        QTest::keyClick(check, Qt::Key_Space);
    }
    const Project after = m_document->project();
    QVERIFY2(!(after == before), "the edit did not reach the document");
    QVERIFY(QApplication::focusWidget());
    const QString focused = QString::fromLatin1(QApplication::focusWidget()->metaObject()->className());
    keyOnFocus(Qt::Key_Z, Qt::ControlModifier);
    QVERIFY2(m_document->project() == before,
        qPrintable(QStringLiteral("Ctrl+Z in a %1 did not undo").arg(focused)));
    keyOnFocus(Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY2(m_document->project() == after,
        qPrintable(QStringLiteral("Ctrl+Shift+Z in a %1 did not redo").arg(focused)));
}

// Typing without Enter: Ctrl+Z takes the typing back in the field, not the document's last edit.
void AuthoringUiTest::anUncommittedFieldKeepsItsOwnUndo()
{
    m_document->newProject();
    ViewSettings view = m_document->project().view;
    view.exposureEV = 1.0;
    m_document->setView(view, QStringLiteral("Exposure"));
    auto* name = child<QLineEdit>("materialName");
    QVERIFY(focus(name));
    const QString original = name->text();
    QTest::keyClicks(name, QStringLiteral("xyz"));
    QCOMPARE(name->text(), original + QStringLiteral("xyz"));
    QTest::keyClick(name, Qt::Key_Z, Qt::ControlModifier);
    QVERIFY2(name->text() != original + QStringLiteral("xyz"), qPrintable(name->text()));
    QCOMPARE(m_document->project().view.exposureEV, 1.0); // the document's edit stays
    QCOMPARE(m_document->undoStack()->count(), 1);
}

void AuthoringUiTest::presetsNeedCtrlAndKeepNameAndMaps()
{
    QVERIFY(openTwoMaterials());
    Material red = m_document->project().material();
    QCOMPARE(red.name, std::string("Red"));
    red.map(MapSlot::Normal).path = m_dir.filePath(QStringLiteral("normal.png")).toStdString();
    m_document->setMaterial(red, QStringLiteral("Normal Map"));
    const Project before = m_document->project();
    QVERIFY(focus(m_window->viewport()));
    QTest::keyClick(m_window->viewport(), Qt::Key_1);
    QVERIFY2(m_document->project() == before, "the key 1 alone changed the material");
    QTest::keyClick(m_window->viewport(), Qt::Key_1, Qt::ControlModifier);
    const Material& applied = m_document->project().material();
    QCOMPARE(applied.name, std::string("Red"));
    QCOMPARE(applied.map(MapSlot::Normal).path, red.map(MapSlot::Normal).path);
    QVERIFY(!(applied == red));
    QVERIFY2(m_window->statusMessage().startsWith(QStringLiteral("Applied "))
            && m_window->statusMessage().contains(QStringLiteral("to “Red”"))
            && m_window->statusMessage().endsWith(QStringLiteral("its maps kept")),
        qPrintable(m_window->statusMessage()));
}

// Exports are named after the project without its extension and start in its folder (issue 30:
// barrel.json exported "barrel.json.gltf" into the home folder).
void AuthoringUiTest::exportNamesAndFolderFollowTheProject()
{
    m_document->newProject();
    QCOMPARE(m_document->exportBaseName(), QStringLiteral("material"));
    QCOMPARE(m_document->exportFolder(), QString());
    QString error;
    for (const auto& [file, stem] :
        {std::pair {"barrel.json", "barrel"}, std::pair {"crate.facet.json", "crate"}}) {
        const QString path = m_dir.filePath(QLatin1String(file));
        QVERIFY2(m_document->saveAs(path, &error), qPrintable(error));
        QCOMPARE(m_document->exportBaseName(), QLatin1String(stem));
        QCOMPARE(m_document->exportFolder(), QFileInfo(path).absolutePath());
    }
    QVERIFY(openTwoMaterials()); // untitled, from two.glb
    QCOMPARE(m_document->exportBaseName(), QStringLiteral("two"));
    QCOMPARE(m_document->exportFolder(), QFileInfo(m_twoMaterials).absolutePath());

    QTemporaryDir elsewhere;
    QSettings().setValue(QStringLiteral("export/folder"), elsewhere.path());
    {
        ExportDialog dialog(
            m_document->project(), m_document->exportBaseName(), nullptr, m_document->exportFolder());
        QCOMPARE(
            dialog.findChild<QLineEdit*>(QStringLiteral("exportFolder"))->text(), m_document->exportFolder());
    }
    {
        ExportDialog dialog(m_document->project(), QStringLiteral("material"));
        QCOMPARE(dialog.findChild<QLineEdit*>(QStringLiteral("exportFolder"))->text(), elsewhere.path());
    }
}

// The window reaches what the format holds (issue 30): a normal strength up to 10 (the slider spans
// 0-2, the field takes more) and UV scales apart in U and V.
void AuthoringUiTest::normalStrengthAndUvScaleAsTheFormatHasThem()
{
    m_document->newProject();
    QDoubleSpinBox* strength = child<ValueSlider>("factorSlider_normal")->spinBox();
    QVERIFY(focus(strength));
    strength->selectAll();
    QTest::keyClicks(strength, QStringLiteral("5"));
    QTest::keyClick(strength, Qt::Key_Return);
    QCOMPARE(m_document->project().material().normalStrength(), 5.0);

    auto* linked = child<QCheckBox>("uvScaleLinkedCheck");
    QVERIFY(linked->isChecked());
    const auto typeInto = [this](const char* slider, const QString& text) {
        QDoubleSpinBox* spin = child<ValueSlider>(slider)->spinBox();
        QVERIFY(focus(spin));
        spin->selectAll();
        QTest::keyClicks(spin, text);
        QTest::keyClick(spin, Qt::Key_Return);
    };
    typeInto("uvScaleSlider", QStringLiteral("2"));
    for (const MaterialMap& map : m_document->project().material().maps)
        QCOMPARE(map.uv.scale, glm::dvec2(2.0, 2.0));
    QVERIFY(focus(linked));
    QTest::keyClick(linked, Qt::Key_Space);
    QVERIFY(!linked->isChecked());
    typeInto("uvScaleVSlider", QStringLiteral("3"));
    for (const MaterialMap& map : m_document->project().material().maps)
        QCOMPARE(map.uv.scale, glm::dvec2(2.0, 3.0));
    QCOMPARE(child<ValueSlider>("uvScaleSlider")->spinBox()->value(), 2.0);
    // Shown as they are after an undo and a redo: unlinked, as the scales differ.
    m_document->undoStack()->undo();
    linked->setChecked(true);
    m_document->undoStack()->redo();
    QVERIFY(!linked->isChecked());
    QCOMPARE(child<ValueSlider>("uvScaleVSlider")->spinBox()->value(), 3.0);
}

// Issue 30's messages: an action's message is not overwritten at once by lighting news; a step's
// note in the Texture Maps dock goes when the step is undone, and the bar says what was undone.
void AuthoringUiTest::messagesStayWhileTrueAndGoWhenNot()
{
    // Opening an asset: its summary stays while its lighting is prepared (in a second, here).
    QVERIFY(openTwoMaterials());
    const QString opened = m_window->statusMessage();
    QVERIFY2(opened.startsWith(QStringLiteral("Opened two.glb")), qPrintable(opened));
    EnvironmentSettings environment = m_document->project().environment;
    environment.source = "uniform:0.3";
    m_document->setEnvironment(environment, QStringLiteral("Environment"));
    QTest::qWait(1500);
    QCOMPARE(m_window->statusMessage(), opened);

    // A texture set assigned, then undone: the dock's note goes, the bar says what was undone.
    QTemporaryDir folder;
    const QString project = test::writeTexturedProject(folder.path());
    QVERIFY(!project.isEmpty());
    QStringList maps;
    for (const QFileInfo& file : QDir(folder.path()).entryInfoList({QStringLiteral("*.png")}, QDir::Files))
        maps << file.absoluteFilePath();
    QVERIFY(maps.size() >= 2);
    auto* dock = m_window->findChild<TextureMapsDock*>();
    const QString note = dock->assignFiles(maps);
    QVERIFY2(note.startsWith(QStringLiteral("Assigned ")), qPrintable(note));
    auto* label = dock->findChild<QLabel*>(QStringLiteral("textureMapsMessage"));
    QVERIFY(label && label->isVisibleTo(dock) && label->text() == note);
    QVERIFY(focus(m_window->viewport()));
    QTest::keyClick(m_window->viewport(), Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(!label->isVisibleTo(dock));
    QVERIFY2(m_window->statusMessage().startsWith(QStringLiteral("Undone: ")),
        qPrintable(m_window->statusMessage()));

    // A long message ends in "…" before the frame statistics, whole in the tooltip.
    const QString longMessage = QStringLiteral("engine.glb has no texture coordinates; ").repeated(8);
    m_window->showStatusMessage(longMessage);
    QCOMPARE(m_window->statusMessage(), longMessage);
    const QString shown = m_window->statusBar()->currentMessage();
    QVERIFY2(shown.endsWith(QChar(0x2026)) && shown.size() < longMessage.size(), qPrintable(shown));
    QCOMPARE(m_window->statusBar()->toolTip(), longMessage);
    QVERIFY(m_window->statusBar()->fontMetrics().horizontalAdvance(shown) < m_window->statusBar()->width()
            - m_window->findChild<QLabel*>(QStringLiteral("frameStatsLabel"))->width());
}

// Issue 30's cramped docks at 1280 x 720: the lists show several rows, and the tab names stay whole
// (a tab bar too short for them scrolls).
void AuthoringUiTest::docksShowEnoughAtASmallSize()
{
    m_window->resize(1200, 650);
    QTest::qWait(100);
    auto* presets = child<QListWidget>("presetList");
    QVERIFY(presets->minimumHeight() >= 5 * 40);
    QVERIFY(child<QListWidget>("environmentLibrary")->minimumHeight() >= 2 * 56);
    QVERIFY(child<QListWidget>("materialList")->minimumHeight()
        >= 5 * child<QListWidget>("materialList")->fontMetrics().height());
    QStringList names;
    for (QTabBar* bar : m_window->findChildren<QTabBar*>(Qt::FindDirectChildrenOnly)) {
        if (bar->count() == 0)
            continue;
        QCOMPARE(bar->elideMode(), Qt::ElideNone);
        QVERIFY(bar->usesScrollButtons());
        for (int tab = 0; tab < bar->count(); ++tab)
            names << bar->tabText(tab);
    }
    QVERIFY2(names.contains(QStringLiteral("Texture Maps"))
            && names.contains(QStringLiteral("Environment Library")),
        qPrintable(names.join(QStringLiteral(", "))));
    m_window->resize(1200, 800);
}

// Edit > Copy Material and Paste Material (Ctrl+Shift+C / V): Red's factors and maps onto Blue,
// whose name stays, in one undo step; a clipboard without a material changes nothing and says so.
void AuthoringUiTest::cacheBudgetComesFromSettingOrEnvironment_data()
{
    QTest::addColumn<QVariant>("setting"); // invalid: none stored
    QTest::addColumn<QByteArray>("environment"); // empty: unset
    QTest::addColumn<int>("expected");
    QTest::addColumn<bool>("fromEnvironment");
    const int standard = CacheBudget::kDefaultMegabytes;
    QTest::newRow("nothing set: the default") << QVariant() << QByteArray() << standard << false;
    QTest::newRow("the setting") << QVariant(1024) << QByteArray() << 1024 << false;
    QTest::newRow("a setting below the range") << QVariant(10) << QByteArray() << standard << false;
    QTest::newRow("a setting that is no number")
        << QVariant(QStringLiteral("lots")) << QByteArray() << standard << false;
    QTest::newRow("the environment wins") << QVariant(1024) << QByteArray("128") << 128 << true;
    QTest::newRow("the environment, no setting") << QVariant() << QByteArray("2048") << 2048 << true;
    QTest::newRow("an environment below the range") << QVariant(1024) << QByteArray("32") << 1024 << false;
    QTest::newRow("an environment with a unit") << QVariant(1024) << QByteArray("512MB") << 1024 << false;
    QTest::newRow("an environment above the range")
        << QVariant() << QByteArray("9999999") << standard << false;
}

void AuthoringUiTest::cacheBudgetComesFromSettingOrEnvironment()
{
    QFETCH(QVariant, setting);
    QFETCH(QByteArray, environment);
    QFETCH(int, expected);
    QFETCH(bool, fromEnvironment);
    const auto restore = qScopeGuard([] {
        QSettings().remove(QStringLiteral("cache/budgetMB"));
        qunsetenv("FACET_CACHE_BUDGET_MB");
        CacheBudget::reload();
    });
    if (setting.isValid())
        QSettings().setValue(QStringLiteral("cache/budgetMB"), setting);
    else
        QSettings().remove(QStringLiteral("cache/budgetMB"));
    if (environment.isEmpty())
        qunsetenv("FACET_CACHE_BUDGET_MB");
    else
        qputenv("FACET_CACHE_BUDGET_MB", environment);
    CacheBudget::reload();
    QCOMPARE(CacheBudget::megabytes(), expected);
    QCOMPARE(CacheBudget::bytes(), std::size_t(expected) << 20);
    QCOMPARE(CacheBudget::fromEnvironment(), fromEnvironment);

    // The preference shows it, disabled when the environment sets it; OK stores what it shows.
    PreferencesDialog dialog(0, 0, m_window.get());
    QCOMPARE(dialog.cacheBudgetSpin()->value(), expected);
    QCOMPARE(dialog.cacheBudgetSpin()->isEnabled(), !fromEnvironment);
    QCOMPARE(
        dialog.findChild<QLabel*>(QStringLiteral("cacheBudgetEnvironmentNote")) != nullptr, fromEnvironment);
    if (!fromEnvironment) {
        QSignalSpy changed(CacheBudget::instance(), &CacheBudget::changed);
        dialog.cacheBudgetSpin()->setValue(768);
        dialog.accept();
        QCOMPARE(CacheBudget::megabytes(), 768);
        QCOMPARE(QSettings().value(QStringLiteral("cache/budgetMB")).toInt(), 768);
        QCOMPARE(changed.count(), 1);
        // setMegabytes clamps to the range.
        CacheBudget::setMegabytes(1);
        QCOMPARE(CacheBudget::megabytes(), CacheBudget::kMinMegabytes);
    }
}

void AuthoringUiTest::theLightingCacheKeepsToTheBudget()
{
    // Environments 1024 pixels wide at the high preset: an IBL set and its source take ~20 MiB,
    // so the smallest budget (64 MiB) holds three at most.
    const auto restore = qScopeGuard([] {
        QSettings().remove(QStringLiteral("cache/budgetMB"));
        CacheBudget::reload();
    });
    CacheBudget::setMegabytes(CacheBudget::kMinMegabytes);
    m_document->newProject();
    EnvironmentSettings environment = m_document->project().environment;
    environment.quality = IblQuality::High;
    ViewportWidget* viewport = m_window->viewport();
    const auto show = [&](int index) {
        Image image(1024, 512, glm::vec4(0.2f + 0.1f * float(index), 0.5f, 0.7f, 1.0f));
        image.at(100 * index, 100) = glm::vec4(1000.0f); // each its own content
        const QString path = m_dir.filePath(QStringLiteral("budget%1.exr").arg(index));
        std::string error;
        if (!image.save(path.toStdString(), &error))
            return false;
        environment.source = path.toStdString();
        const std::uint64_t framesBefore = viewport->frameCount();
        m_document->setEnvironment(environment, QStringLiteral("Environment"));
        return QTest::qWaitFor(
            [&] {
                const ViewportFrameStats& stats = viewport->lastFrameStats();
                return !stats.lightingPending && m_window->sceneController()->pendingAssetLoads() == 0
                    && m_window->sceneController()->environmentName() == QFileInfo(path).fileName()
                    && stats.iblCacheEntries > 0 && viewport->frameCount() > framesBefore;
            },
            60000);
    };
    QVERIFY(show(0));
    const std::size_t oneSet = viewport->lastFrameStats().iblCacheBytes;
    QVERIFY2(oneSet > std::size_t(12) << 20, qPrintable(QStringLiteral("one set: %1 bytes").arg(oneSet)));
    const std::size_t budget = CacheBudget::bytes();
    for (int index = 1; index < 6; ++index) {
        QVERIFY(show(index));
        const ViewportFrameStats& stats = viewport->lastFrameStats();
        QVERIFY2(stats.iblCacheBytes <= budget,
            qPrintable(QStringLiteral("environment %1: %2 bytes held, budget %3")
                           .arg(index)
                           .arg(stats.iblCacheBytes)
                           .arg(budget)));
    }
    const int heldUnderTheSmallBudget = viewport->lastFrameStats().iblCacheEntries;
    QVERIFY(heldUnderTheSmallBudget < 6);
    // A larger budget applies at the next frame: two more environments join what is held, which
    // now takes more than the small budget allowed.
    CacheBudget::setMegabytes(1024);
    QVERIFY(show(6));
    QVERIFY(show(7));
    QVERIFY2(viewport->lastFrameStats().iblCacheEntries > heldUnderTheSmallBudget
            && viewport->lastFrameStats().iblCacheBytes > budget,
        qPrintable(QStringLiteral("%1 entries (%2 under the small budget), %3 bytes")
                       .arg(viewport->lastFrameStats().iblCacheEntries)
                       .arg(heldUnderTheSmallBudget)
                       .arg(viewport->lastFrameStats().iblCacheBytes)));
    // Edit > Preferences says what is held.
    PreferencesDialog dialog(
        viewport->lastFrameStats().iblCacheBytes, viewport->lastFrameStats().iblCacheEntries, m_window.get());
    QVERIFY(dialog.findChild<QLabel*>(QStringLiteral("cacheHeldLabel"))
                ->text()
                .contains(QStringLiteral("(%1 entries)").arg(viewport->lastFrameStats().iblCacheEntries)));
}

void AuthoringUiTest::freedMemoryGoesBackToTheSystem()
{
#if defined(__SANITIZE_ADDRESS__)
    QSKIP("AddressSanitizer's allocator replaces glibc's: malloc_trim has nothing of it to hand back");
#endif
    FreedMemoryTimer timer;
    timer.setEnabled(false);
    // Blocks freed by another thread stay in its arena (as a decode worker's do): 96 MiB freed of
    // 64 KiB blocks (below the allocator's mmap threshold), every other one kept so that the freed
    // ones cannot merge into the arena's top.
    std::vector<std::unique_ptr<char[]>> kept;
    std::thread worker([&] {
        std::vector<std::unique_ptr<char[]>> blocks;
        constexpr std::size_t kBlock = std::size_t(64) << 10;
        for (int i = 0; i < 3072; ++i) {
            blocks.emplace_back(new char[kBlock]);
            std::fill_n(blocks.back().get(), kBlock, char(i)); // resident
        }
        for (std::size_t i = 0; i < blocks.size(); i += 2)
            kept.push_back(std::move(blocks[i]));
    });
    worker.join();
    QVERIFY2(freedMemoryHeld() > FreedMemoryTimer::kThresholdBytes,
        qPrintable(QStringLiteral("%1 bytes free").arg(freedMemoryHeld())));
    const std::size_t before = residentBytes();
    QVERIFY(timer.check());
    QCOMPARE(timer.returns(), 1);
    const std::size_t after = residentBytes();
    QVERIFY2(after + (std::size_t(32) << 20) < before,
        qPrintable(QStringLiteral("resident %1 -> %2 MiB").arg(before >> 20).arg(after >> 20)));
}

QTEST_MAIN(AuthoringUiTest)
#include "AuthoringUiTest.moc"
