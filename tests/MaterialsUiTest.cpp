// glTF assets and several materials in the main window under Xvfb, driven as a user does, with
// small assets written by the test (support/TestAssets.h: two quads side by side, "Left" in the
// material "Red" and "Right" in "Blue"; the window: support/TwoMaterialWindow.h):
// - File > Open of a .glb: an untitled project named after the asset, its materials and parts
//   listed, Save offering a project file next to the asset; the import's notes in the window's
//   wording in the status bar.
// - The emissive strength's logarithmic slider, and the Base Colour slot naming its image
//   (embedded, external, missing).
// - Choosing the second material in the Materials dock: the Texture Maps and Material docks show
//   it, and a roughness edit changes only it, in one undo step.
// - File > Import Asset and a drop on the viewport: the mesh, materials and parts replaced in one
//   undo step, the environment and camera kept.
// Needs a display (Xvfb via with-display.sh). Picking, parts and edits seen in the rendered frame:
// MaterialsFrameUiTest.

#include "ui/MainWindow.h"
#include "ui/docks/MapSlotWidget.h"
#include "ui/docks/MaterialDock.h"
#include "ui/docks/MaterialsDock.h"
#include "ui/docks/TextureMapsDock.h"
#include "ui/document/Document.h"
#include "ui/document/ProjectFileController.h"
#include "ui/viewport/CameraController.h"
#include "ui/viewport/SceneController.h"
#include "ui/viewport/SurfaceFormat.h"
#include "ui/viewport/ViewportDropHandler.h"
#include "ui/viewport/ViewportWidget.h"
#include "ui/widgets/ColorButton.h"
#include "ui/widgets/ValueSlider.h"

#include "GltfWriter.h"
#include "TestSupport.h"
#include "TwoMaterialWindow.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMimeData>
#include <QSignalSpy>
#include <QSlider>
#include <QStandardPaths>
#include <QTimer>
#include <QTreeWidget>
#include <QUndoStack>
#include <QUrl>
#include <QtTest/QTest>

#include <cmath>
#include <memory>

using namespace facet;
using facet::test::waitFor;

namespace {

// Drags `urls` onto `target` and drops them there, as the desktop would. False when the target
// refused the drag.
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

} // namespace

class MaterialsUiTest : public QObject, public facet::test::TwoMaterialWindowFixture {
    Q_OBJECT
public:
    static void initMain()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setAttribute(Qt::AA_DontUseNativeDialogs);
        installViewportSurfaceFormat();
    }

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void openingAnAssetListsItsMaterialsAndParts();
    void importNotesReachTheStatusBar();
    void logarithmicSliderSpansTheDecades_data();
    void logarithmicSliderSpansTheDecades();
    void mapSlotNamesTheImage_data();
    void mapSlotNamesTheImage();
    void choosingAMaterialEditsOnlyIt();
    void importIsOneUndoStep();
    void dropOnTheViewport_data();
    void dropOnTheViewport();
};

void MaterialsUiTest::initTestCase()
{
    initWindowFixture();
}

void MaterialsUiTest::cleanupTestCase()
{
    cleanupWindowFixture();
}

void MaterialsUiTest::openingAnAssetListsItsMaterialsAndParts()
{
    // Not open(): the status bar is read before the mesh arrives (and the lighting says it is ready).
    QVERIFY(m_window->projectFiles()->openFile(m_twoMaterials));
    QVERIFY(m_document->filePath().isEmpty()); // untitled: Save asks where
    QCOMPARE(m_document->sourceAssetPath(), m_twoMaterials);
    QVERIFY(!m_document->isModified());
    QVERIFY2(m_window->windowTitle().startsWith(QStringLiteral("Untitled (two.glb)")),
        qPrintable(m_window->windowTitle()));
    QVERIFY2(m_window->statusMessage().startsWith(QStringLiteral("Opened two.glb (2 materials, 2 parts)")),
        qPrintable(m_window->statusMessage()));
    QCOMPARE(m_window->projectFiles()->recentFiles().value(0), m_twoMaterials);

    MaterialsDock* dock = m_window->materialsDock();
    QListWidget* materials = dock->materialList();
    QCOMPARE(materials->count(), 2);
    QCOMPARE(materials->item(0)->text(), QStringLiteral("Red"));
    QCOMPARE(materials->item(1)->text(), QStringLiteral("Blue"));
    QCOMPARE(materials->currentRow(), 0);
    QTreeWidget* parts = dock->partList();
    // The mesh loads off the GUI thread; its parts are listed when it arrives.
    QTRY_COMPARE_WITH_TIMEOUT(parts->topLevelItemCount(), 2, 30000);
    QCOMPARE(parts->topLevelItem(0)->text(0), QStringLiteral("Left"));
    QCOMPARE(parts->topLevelItem(1)->text(0), QStringLiteral("Right"));
    for (int part = 0; part < 2; ++part) {
        QCOMPARE(parts->topLevelItem(part)->checkState(0), Qt::Checked);
        QComboBox* combo = dock->partMaterialCombo(part);
        QVERIFY(combo);
        QCOMPARE(combo->count(), 2);
        QCOMPARE(combo->currentIndex(), part);
    }

    // Save asks where, offering a project next to the asset named after it; cancelled here.
    QString offered;
    QTimer poll;
    poll.setInterval(50);
    connect(&poll, &QTimer::timeout, this, [&] {
        auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
        if (!dialog)
            return;
        poll.stop();
        offered = dialog->selectedFiles().value(0);
        dialog->reject();
    });
    poll.start();
    auto* save = m_window->findChild<QAction*>(QStringLiteral("saveAction"));
    QVERIFY(save);
    save->trigger();
    poll.stop();
    QCOMPARE(offered, m_dir.filePath(QStringLiteral("two.json")));
    QVERIFY(m_document->filePath().isEmpty());

    // Saved, it is a project of its own: the title names the project file.
    QVERIFY(m_window->projectFiles()->saveToFile(m_dir.filePath(QStringLiteral("two.json"))));
    QCOMPARE(m_window->windowTitle(), QStringLiteral("two.json[*] — Facet"));
    QVERIFY(m_document->sourceAssetPath().isEmpty());
}

void MaterialsUiTest::importNotesReachTheStatusBar()
{
    // An asset naming an external image that is not there: it opens, says so in the window's
    // words and offers the relink.
    test::GltfWriter w;
    QJsonObject pbr;
    QJsonObject info;
    info[QLatin1String("index")] = w.addTexture(w.addImageUri(QStringLiteral("lost_basecolor.png")));
    pbr[QLatin1String("baseColorTexture")] = info;
    QJsonObject material;
    material[QLatin1String("pbrMetallicRoughness")] = pbr;
    w.addNode(w.addQuad(w.addMaterial(material)));
    const QString path = m_dir.filePath(QStringLiteral("lost.glb"));
    QString error;
    QVERIFY2(w.write(path, test::GltfWriter::BufferStorage::Glb, &error), qPrintable(error));

    QVERIFY(m_window->projectFiles()->openFile(path)); // the status bar as the open leaves it
    const QString status = m_window->statusMessage();
    QVERIFY2(status.contains(QStringLiteral("lost.glb uses the image lost_basecolor.png, which is missing")),
        qPrintable(status));
    QVERIFY2(
        !status.contains(QStringLiteral("importGltf")) && !status.contains(m_dir.path()), qPrintable(status));
    QCOMPARE(m_document->missingFiles().size(), 1);
}

void MaterialsUiTest::logarithmicSliderSpansTheDecades_data()
{
    // The emissive strength's slider: 0 at position 0, then 0.01 to 10000 geometrically over
    // positions 1 to 1000 (six decades in 999 steps: 333 steps a decade).
    QTest::addColumn<double>("value");
    QTest::addColumn<int>("position");
    QTest::newRow("0") << 0.0 << 0;
    QTest::newRow("0.01, the first step") << 0.01 << 1;
    QTest::newRow("1") << 1.0 << 334;
    QTest::newRow("100") << 100.0 << 667;
    QTest::newRow("10000, the last") << 10000.0 << 1000;
}

void MaterialsUiTest::logarithmicSliderSpansTheDecades()
{
    QFETCH(double, value);
    QFETCH(int, position);
    ValueSlider slider(0.0, Material::kMaxEmissiveStrength, 3);
    slider.setLogarithmic(0.01);
    slider.setValue(value);
    QCOMPARE(slider.slider()->value(), position);
    QCOMPARE(slider.spinBox()->value(), value);
    // Moving the slider to the position gives the value back (to the spin box's 3 decimals).
    slider.setValue(123.0);
    QSignalSpy edited(&slider, &ValueSlider::valueEdited);
    slider.slider()->setValue(position);
    QCOMPARE(edited.count(), 1);
    QVERIFY2(std::abs(edited.at(0).at(0).toDouble() - value) <= 5e-4 * std::max(1.0, value),
        qPrintable(QString::number(edited.at(0).at(0).toDouble())));
}

void MaterialsUiTest::mapSlotNamesTheImage_data()
{
    QTest::addColumn<QString>("image"); // "embedded", or an external file name
    QTest::addColumn<bool>("writeImage");
    QTest::addColumn<QString>("label"); // how the Base Colour slot's label starts
    QTest::addColumn<bool>("missing");
    QTest::newRow("embedded in the .glb")
        << QStringLiteral("embedded") << true << QStringLiteral("slot-embedded.glb, image 0\n4×4") << false;
    QTest::newRow("external, present")
        << QStringLiteral("here_basecolor.png") << true << QStringLiteral("here_basecolor.png\n4×4") << false;
    QTest::newRow("external, missing")
        << QStringLiteral("gone_basecolor.png") << false << QStringLiteral("gone_basecolor.png") << true;
}

void MaterialsUiTest::mapSlotNamesTheImage()
{
    QFETCH(QString, image);
    QFETCH(bool, writeImage);
    QFETCH(QString, label);
    QFETCH(bool, missing);
    const QByteArray png
        = test::encodePng(4, 4, 4, std::vector<glm::vec4>(16, glm::vec4(0.2f, 0.6f, 0.3f, 1.0f)));
    test::GltfWriter w;
    const bool embedded = image == QLatin1String("embedded");
    const int source = embedded ? w.addImageEmbedded(png, QStringLiteral("image/png")) : w.addImageUri(image);
    if (!embedded && writeImage) {
        QFile file(m_dir.filePath(image));
        QVERIFY(file.open(QIODevice::WriteOnly) && file.write(png) == png.size());
    }
    QJsonObject info;
    info[QLatin1String("index")] = w.addTexture(source);
    QJsonObject pbr;
    pbr[QLatin1String("baseColorTexture")] = info;
    QJsonObject material;
    material[QLatin1String("pbrMetallicRoughness")] = pbr;
    w.addNode(w.addQuad(w.addMaterial(material)));
    const QString path
        = m_dir.filePath(QStringLiteral("slot-%1.glb").arg(embedded ? QStringLiteral("embedded") : image));
    QString error;
    QVERIFY2(w.write(path, test::GltfWriter::BufferStorage::Glb, &error), qPrintable(error));

    QVERIFY(open(path));
    MapSlotWidget* slot = m_window->textureMapsDock()->slotWidget(MapSlot::BaseColor);
    // The thumbnail (and with it the resolution) comes from a worker thread.
    if (writeImage)
        QVERIFY(waitFor([&] { return slot->fileLabel()->text().contains(QStringLiteral("×")); }, 10000));
    const QString text = slot->fileLabel()->text();
    QVERIFY2(text.startsWith(label), qPrintable(text));
    QCOMPARE(text.contains(QStringLiteral("(missing)")), missing);
}

void MaterialsUiTest::choosingAMaterialEditsOnlyIt()
{
    QVERIFY(open(m_twoMaterials));
    QListWidget* list = m_window->materialsDock()->materialList();
    QSignalSpy sceneChanged(m_window->sceneController(), &SceneController::sceneChanged);
    QTest::mouseClick(
        list->viewport(), Qt::LeftButton, Qt::NoModifier, list->visualItemRect(list->item(1)).center());
    QCOMPARE(m_document->project().currentMaterial, 1);
    QCOMPARE(m_document->undoStack()->count(), 0); // a selection, not an edit
    QVERIFY(!m_document->isModified());
    QCOMPARE(sceneChanged.count(), 0); // nothing drawn changed: no frame

    // Both docks show the blue material.
    TextureMapsDock* maps = m_window->textureMapsDock();
    const glm::dvec3 shown = maps->slotWidget(MapSlot::BaseColor)->colorButton()->linearColor();
    QVERIFY2(
        std::abs(shown.b - 0.8) < 1e-6 && std::abs(shown.r - 0.05) < 1e-6, test::describe(shown).c_str());
    QVERIFY2(maps->materialLabel()->text().contains(QStringLiteral("Blue")),
        qPrintable(maps->materialLabel()->text()));
    QCOMPARE(m_window->materialDock()->findChild<QLineEdit*>(QStringLiteral("materialName"))->text(),
        QStringLiteral("Blue"));

    // A roughness edit changes the blue material only, in one undo step.
    ValueSlider* roughness = maps->slotWidget(MapSlot::Roughness)->factorSlider();
    QCOMPARE(roughness->value(), 0.5);
    roughness->spinBox()->setValue(0.9);
    QCOMPARE(m_document->project().materials[1].roughness(), 0.9);
    QCOMPARE(m_document->project().materials[0].roughness(), 0.5);
    QCOMPARE(m_document->undoStack()->count(), 1);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Roughness"));

    // Back to the red one: its own roughness shows; undo restores the blue one's.
    list->setCurrentRow(0);
    QCOMPARE(roughness->value(), 0.5);
    m_document->undoStack()->undo();
    QCOMPARE(m_document->project().materials[1].roughness(), 0.5);
    QCOMPARE(m_document->project().materials[0].roughness(), 0.5);

    // Renaming in the list is an undo step of its own.
    list->item(1)->setText(QStringLiteral("Deep Blue"));
    QCOMPARE(m_document->project().materials[1].name, std::string("Deep Blue"));
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Rename Material"));
    QCOMPARE(m_window->materialsDock()->partMaterialCombo(1)->itemText(1), QStringLiteral("Deep Blue"));
    m_document->undoStack()->undo();
    QCOMPARE(list->item(1)->text(), QStringLiteral("Blue"));
}

void MaterialsUiTest::importIsOneUndoStep()
{
    QVERIFY(m_window->projectFiles()->newProject());
    const Project before = m_document->project();
    EnvironmentSettings environment = before.environment;
    environment.rotationDegrees = 45.0;
    m_document->setEnvironment(environment, QStringLiteral("Rotation"));
    m_window->cameraController()->orbit(30.0, 10.0);
    const Camera camera = m_document->project().camera;
    const int steps = m_document->undoStack()->count();

    QVERIFY(m_window->projectFiles()->importAssetFile(m_twoMaterials));
    const Project& imported = m_document->project();
    QCOMPARE(m_document->undoStack()->count(), steps + 1);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Import two.glb"));
    QCOMPARE(imported.materials.size(), std::size_t(2));
    QCOMPARE(imported.parts.size(), std::size_t(2));
    QCOMPARE(imported.view.mesh, m_twoMaterials.toStdString());
    QCOMPARE(imported.environment.rotationDegrees, 45.0); // kept
    QCOMPARE(imported.camera, camera); // kept
    QCOMPARE(imported.lights, before.lights);
    QVERIFY(m_document->filePath().isEmpty()
        && m_document->sourceAssetPath().isEmpty()); // still the same project
    QVERIFY2(m_window->statusMessage().startsWith(QStringLiteral("Imported two.glb (2 materials, 2 parts)")),
        qPrintable(m_window->statusMessage()));
    QCOMPARE(m_window->materialsDock()->materialList()->count(), 2);
    QVERIFY(waitFor([this] { return m_window->materialsDock()->partList()->topLevelItemCount() == 2; }));

    m_document->undoStack()->undo();
    QCOMPARE(m_document->project().materials, before.materials);
    QCOMPARE(m_document->project().view.mesh, before.view.mesh);
    QVERIFY(m_document->project().parts.empty());
    QCOMPARE(m_document->project().environment.rotationDegrees, 45.0);
    QCOMPARE(m_window->materialsDock()->materialList()->count(), 1);
    QVERIFY(waitFor([this] { return m_window->materialsDock()->partList()->topLevelItemCount() == 1; }));
    m_document->undoStack()->redo();
    QCOMPARE(m_document->project().materials.size(), std::size_t(2));
}

void MaterialsUiTest::dropOnTheViewport_data()
{
    QTest::addColumn<QString>("file"); // in the test's folder
    QTest::addColumn<bool>("accepted");
    QTest::newRow("a glTF asset is imported") << QStringLiteral("two.glb") << true;
    QTest::newRow("an image is refused") << QStringLiteral("wood_basecolor.png") << false;
}

void MaterialsUiTest::dropOnTheViewport()
{
    QFETCH(QString, file);
    QFETCH(bool, accepted);
    QVERIFY(m_window->projectFiles()->newProject());
    const QString path = m_dir.filePath(file);
    if (!QFileInfo::exists(path)) {
        QImage image(8, 8, QImage::Format_RGB32);
        image.fill(Qt::darkYellow);
        QVERIFY(image.save(path));
    }
    QCOMPARE(dropUrls(m_viewport, {QUrl::fromLocalFile(path)}), accepted);
    if (!accepted) {
        QTest::qWait(100);
        QCOMPARE(m_document->undoStack()->count(), 0);
        QCOMPARE(m_document->project().materials.size(), std::size_t(1));
        return;
    }
    // The import runs once the drop has returned (ViewportDropHandler).
    QVERIFY(waitFor([this] { return m_document->project().materials.size() == 2; }, 5000));
    QCOMPARE(m_document->undoStack()->count(), 1);
    QCOMPARE(m_document->project().view.mesh, path.toStdString());
    QVERIFY(m_document->filePath().isEmpty());
}

QTEST_MAIN(MaterialsUiTest)
#include "MaterialsUiTest.moc"
