// Several materials in the main window under Xvfb, checked in the rendered frame, driven as a user
// does, with small assets written by the test (support/TestAssets.h: two quads side by side, "Left"
// in the material "Red" and "Right" in "Blue"; the window: support/TwoMaterialWindow.h):
// - Clicking a part in the viewport makes its material current (the parts list follows); a drag
//   does not pick; a turned object is picked where it is drawn; a hidden part is not picked.
// - A part's visibility check box (the rendered pixel becomes the background; undo restores it)
//   and its material combo (the pixel takes the other material's colour), one undo step each.
// - The emissive colour and strength (Texture Maps dock) and the alpha mode, cutoff and
//   double-sidedness (Material dock), each edit checked in the rendered frame and undone.
// Needs a display (Xvfb via with-display.sh). Opening and importing assets, choosing and
// renaming materials: MaterialsUiTest.

#include "core/mesh/MeshPicking.h"
#include "ui/MainWindow.h"
#include "ui/docks/MapSlotWidget.h"
#include "ui/docks/MaterialDock.h"
#include "ui/docks/MaterialsDock.h"
#include "ui/docks/TextureMapsDock.h"
#include "ui/document/Document.h"
#include "ui/viewport/CameraController.h"
#include "ui/viewport/PartPicker.h"
#include "ui/viewport/SceneController.h"
#include "ui/viewport/SurfaceFormat.h"
#include "ui/viewport/ViewportWidget.h"
#include "ui/widgets/ColorButton.h"
#include "ui/widgets/ValueSlider.h"

#include "TestSupport.h"
#include "TwoMaterialWindow.h"
#include "WindowTestSupport.h"

#include <QAbstractItemView>
#include <QApplication>
#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDockWidget>
#include <QImage>
#include <QListWidget>
#include <QSignalSpy>
#include <QSlider>
#include <QStandardPaths>
#include <QStyleOptionButton>
#include <QTimer>
#include <QTreeWidget>
#include <QUndoStack>
#include <QtTest/QTest>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <memory>

using namespace facet;
using facet::test::chooseInCombo;
using facet::test::waitFor;

namespace {

// Clicks `button` (which opens a QColorDialog) and answers the dialog with `color`.
bool clickAndChooseColour(QAbstractButton* button, const QColor& color)
{
    bool answered = false;
    QTimer poll;
    poll.setInterval(50);
    QObject::connect(&poll, &QTimer::timeout, [&] {
        auto* dialog = qobject_cast<QColorDialog*>(QApplication::activeModalWidget());
        if (!dialog)
            return;
        poll.stop();
        dialog->setCurrentColor(color);
        answered = true;
        dialog->accept();
    });
    poll.start(); // for as long as the click lasts: a loaded machine may take seconds to show it
    QTest::mouseClick(button, Qt::LeftButton);
    return answered;
}

QString describe(const QColor& c)
{
    return QStringLiteral("(%1, %2, %3)").arg(c.red()).arg(c.green()).arg(c.blue());
}

bool isBlue(const QColor& c)
{
    return c.blue() > c.red() + 40 && c.blue() > c.green() + 30;
}

bool isRed(const QColor& c)
{
    return c.red() > c.blue() + 40 && c.red() > c.green() + 40;
}

// Within `tolerance` code values in each channel (8-bit output after the display transform).
bool near(const QColor& a, const QColor& b, int tolerance = 3)
{
    return std::abs(a.red() - b.red()) <= tolerance && std::abs(a.green() - b.green()) <= tolerance
        && std::abs(a.blue() - b.blue()) <= tolerance;
}

} // namespace

class MaterialsFrameUiTest : public QObject, public facet::test::TwoMaterialWindowFixture {
    Q_OBJECT
public:
    static void initMain()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setAttribute(Qt::AA_DontUseNativeDialogs);
        installViewportSurfaceFormat();
    }

    enum class Edit {
        EmissiveColour,
        EmissiveStrength,
        AlphaMask,
        AlphaCutoff,
        AlphaBlend,
        DoubleSided,
        Unlit
    };
    Q_ENUM(Edit)

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void clickPicksThePart_data();
    void clickPicksThePart();
    void hidingAPartShowsTheBackground();
    void assigningAnotherMaterialToAPart();
    void emissiveAndAlphaEditsReachTheFrame_data();
    void emissiveAndAlphaEditsReachTheFrame();

private:
    // Opens `asset` (File > Open's path) and sets the scene up for pixel checks: a uniform grey
    // environment behind, the base colour debug view (unless `debugView` says otherwise), the
    // turntable stopped at 0, the default view; the history is cleared. False when it did not open.
    bool openForPixels(const QString& asset, const std::string& debugView = "base-color");
    // Where `part`'s centre (the mean of its vertices, in the loaded, normalised mesh) is drawn,
    // in viewport widget coordinates.
    QPoint pixelOfPart(int part) const;
    // Where the point `objectPoint` of the loaded mesh is drawn (with the model matrix when
    // `turned`, else as if the turntable were at 0).
    QPoint pixelOf(const glm::dvec3& objectPoint, bool turned = true) const;
    // The colour of the finished (full-resolution) frame at `point` (widget coordinates).
    QColor framePixel(const QPoint& point);
    QColor backgroundPixel() { return framePixel(QPoint(6, 6)); }
};

void MaterialsFrameUiTest::initTestCase()
{
    initWindowFixture();
}

void MaterialsFrameUiTest::cleanupTestCase()
{
    cleanupWindowFixture();
}

bool MaterialsFrameUiTest::openForPixels(const QString& asset, const std::string& debugView)
{
    if (!open(asset) || m_document->project().parts.size() != 2)
        return false;
    m_window->viewport()->setTurntableAngles(0.0, 0.0);
    m_window->cameraController()->resetView();
    EnvironmentSettings environment = m_document->project().environment;
    environment.source = "uniform:0.5";
    m_document->setEnvironment(environment, QStringLiteral("test setup"));
    ViewSettings view = m_document->project().view;
    view.debugView = debugViewFromString(debugView).value();
    m_document->setView(view, QStringLiteral("test setup"));
    m_document->undoStack()->clear();
    return true;
}

QPoint MaterialsFrameUiTest::pixelOfPart(int part) const
{
    const Mesh& mesh = *m_window->sceneController()->assets().mesh;
    const SubMesh& sub = mesh.subMeshes.at(std::size_t(part));
    glm::dvec3 sum(0.0);
    for (uint32_t i = sub.firstIndex; i < sub.firstIndex + sub.indexCount; ++i)
        sum += glm::dvec3(mesh.vertices[mesh.indices[i]].position);
    return pixelOf(sum / double(sub.indexCount));
}

QPoint MaterialsFrameUiTest::pixelOf(const glm::dvec3& objectPoint, bool turned) const
{
    const Camera& camera = m_document->project().camera;
    const double width = m_viewport->width();
    const double height = m_viewport->height();
    const glm::dvec4 clip = camera.projectionMatrix(width / height) * camera.viewMatrix()
        * (turned ? m_window->viewport()->modelMatrix() : glm::dmat4(1.0)) * glm::dvec4(objectPoint, 1.0);
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    return QPoint(
        int(std::floor((ndc.x + 1.0) * 0.5 * width)), int(std::floor((1.0 - ndc.y) * 0.5 * height)));
}

QColor MaterialsFrameUiTest::framePixel(const QPoint& point)
{
    // Let the change reach the renderer and the refined frame follow any preview, drawn with its
    // environment's lighting (prepared on the lighting worker, the old one or grey shown meanwhile).
    QTest::qWait(50);
    waitFor([this] { return !m_viewport->isPreviewing() && !m_viewport->lastFrameStats().lightingPending; });
    const QImage frame = m_viewport->grabFramebuffer();
    const qreal ratio = frame.devicePixelRatio();
    return frame.pixelColor(QPoint(int(point.x() * ratio), int(point.y() * ratio)));
}

void MaterialsFrameUiTest::clickPicksThePart_data()
{
    QTest::addColumn<int>("part"); // where to click (its centre as drawn); -1: the background
    // Instead, where the right part's outer half was before the object turned: (0.6, 0, 0) of the
    // normalised mesh, which spans x in [0.035, 0.707] there.
    QTest::addColumn<bool>("whereItWas");
    QTest::addColumn<bool>("drag"); // press there, move 40 pixels, release
    QTest::addColumn<double>("turntableDegrees");
    QTest::addColumn<int>("startMaterial");
    QTest::addColumn<int>("expectedMaterial");
    QTest::newRow("left part") << 0 << false << false << 0.0 << 1 << 0;
    QTest::newRow("right part") << 1 << false << false << 0.0 << 0 << 1;
    QTest::newRow("background: nothing") << -1 << false << false << 0.0 << 1 << 1;
    QTest::newRow("drag over the right part: an orbit") << 1 << false << true << 0.0 << 0 << 0;
    QTest::newRow("turned 35 degrees: where it is drawn") << 1 << false << false << 35.0 << 0 << 1;
    // Turned 60 degrees the right part spans only x < 0.36 in front of the camera: nothing there.
    QTest::newRow("turned 60 degrees: not where it was") << 1 << true << false << 60.0 << 0 << 0;
}

void MaterialsFrameUiTest::clickPicksThePart()
{
    QFETCH(int, part);
    QFETCH(bool, whereItWas);
    QFETCH(bool, drag);
    QFETCH(double, turntableDegrees);
    QFETCH(int, startMaterial);
    QFETCH(int, expectedMaterial);
    QVERIFY(openForPixels(m_twoMaterials));
    m_window->viewport()->setTurntableAngles(turntableDegrees, 0.0);
    m_document->setCurrentMaterial(startMaterial);
    const Camera cameraBefore = m_document->project().camera;

    const QPoint at = whereItWas ? pixelOf({0.6, 0.0, 0.0}, false)
        : part >= 0              ? pixelOfPart(part)
                                 : QPoint(6, 6);
    QVERIFY2(m_viewport->rect().contains(at), qPrintable(QStringLiteral("%1, %2").arg(at.x()).arg(at.y())));
    QSignalSpy picked(m_window->partPicker(), &PartPicker::partPicked);
    if (drag) {
        QTest::mousePress(m_viewport, Qt::LeftButton, Qt::NoModifier, at);
        for (int i = 1; i <= 4; ++i)
            QTest::mouseMove(m_viewport, at + QPoint(10 * i, 0), 10);
        QTest::mouseRelease(m_viewport, Qt::LeftButton, Qt::NoModifier, at + QPoint(40, 0), 10);
        QVERIFY(m_document->project().camera != cameraBefore); // the drag orbited
    } else {
        QTest::mouseClick(m_viewport, Qt::LeftButton, Qt::NoModifier, at);
        QCOMPARE(m_document->project().camera, cameraBefore); // a click does not move the camera
    }
    QCOMPARE(m_document->project().currentMaterial, expectedMaterial);
    const bool picks = part >= 0 && !drag && !whereItWas;
    QCOMPARE(picked.count(), picks ? 1 : 0);
    QCOMPARE(m_document->undoStack()->count(), 0); // picking is not an edit
    if (picks) {
        QCOMPARE(m_window->materialsDock()->partList()->currentItem(),
            m_window->materialsDock()->partList()->topLevelItem(part));
        QCOMPARE(m_window->materialsDock()->materialList()->currentRow(), expectedMaterial);
    }
    m_window->viewport()->setTurntableAngles(0.0, 0.0);
}

void MaterialsFrameUiTest::hidingAPartShowsTheBackground()
{
    QVERIFY(openForPixels(m_twoMaterials));
    const QPoint right = pixelOfPart(1);
    const QColor background = backgroundPixel();
    const QColor shown = framePixel(right);
    QVERIFY2(isBlue(shown), qPrintable(describe(shown)));

    QTreeWidgetItem* row = m_window->materialsDock()->partList()->topLevelItem(1);
    row->setCheckState(0, Qt::Unchecked); // what a click on the check box does
    QCOMPARE(m_document->project().parts.at(1).visible, false);
    QCOMPARE(m_document->project().parts.at(0).visible, true);
    QCOMPARE(m_document->undoStack()->count(), 1);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Hide Right"));
    const QColor hidden = framePixel(right);
    QVERIFY2(near(hidden, background),
        qPrintable(describe(hidden) + QStringLiteral(" vs ") + describe(background)));
    // A hidden part cannot be clicked.
    m_document->setCurrentMaterial(0);
    QVERIFY(!m_window->partPicker()->pickAt(QPointF(right) + QPointF(0.5, 0.5)));
    QCOMPARE(m_document->project().currentMaterial, 0);

    m_document->undoStack()->undo();
    QCOMPARE(row->checkState(0), Qt::Checked);
    const QColor restored = framePixel(right);
    QVERIFY2(isBlue(restored), qPrintable(describe(restored)));
}

void MaterialsFrameUiTest::assigningAnotherMaterialToAPart()
{
    QVERIFY(openForPixels(m_twoMaterials));
    const QPoint right = pixelOfPart(1);
    QComboBox* combo = m_window->materialsDock()->partMaterialCombo(1);
    QVERIFY(combo);
    QVERIFY(chooseInCombo(combo, QStringLiteral("Red"), test::ComboInput::Keyboard));
    QCOMPARE(m_document->project().parts.at(1).material, 0);
    QCOMPARE(m_document->undoStack()->count(), 1);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Assign Red to Right"));
    const QColor red = framePixel(right);
    QVERIFY2(isRed(red), qPrintable(describe(red)));
    // Both parts now show the red material: a click on the right one makes it current.
    m_document->setCurrentMaterial(1);
    QCOMPARE(m_window->partPicker()->pickAt(QPointF(right) + QPointF(0.5, 0.5)).value_or(-1), 1);
    QCOMPARE(m_document->project().currentMaterial, 0);

    m_document->undoStack()->undo();
    QCOMPARE(combo->currentIndex(), 1);
    const QColor blue = framePixel(right);
    QVERIFY2(isBlue(blue), qPrintable(describe(blue)));
}

void MaterialsFrameUiTest::emissiveAndAlphaEditsReachTheFrame_data()
{
    QTest::addColumn<Edit>("edit");
    QTest::addColumn<QString>("undoText");
    QTest::newRow("emissive colour") << Edit::EmissiveColour << QStringLiteral("Emissive Colour");
    QTest::newRow("emissive strength (a slider drag)")
        << Edit::EmissiveStrength << QStringLiteral("Emissive Strength");
    QTest::newRow("alpha mode mask") << Edit::AlphaMask << QStringLiteral("Alpha Mode");
    QTest::newRow("alpha cutoff (a slider drag)") << Edit::AlphaCutoff << QStringLiteral("Alpha cutoff");
    QTest::newRow("alpha mode blend") << Edit::AlphaBlend << QStringLiteral("Alpha Mode");
    QTest::newRow("double-sided") << Edit::DoubleSided << QStringLiteral("Double-sided");
    QTest::newRow("unlit") << Edit::Unlit << QStringLiteral("Unlit");
}

void MaterialsFrameUiTest::emissiveAndAlphaEditsReachTheFrame()
{
    QFETCH(Edit, edit);
    QFETCH(QString, undoText);
    const bool emissive = edit == Edit::EmissiveColour || edit == Edit::EmissiveStrength;
    // The right part's alpha is 0.3 (drawn opaque until the alpha mode says otherwise). Blending
    // shows in the shaded image (the debug views write the value itself).
    QVERIFY(openForPixels(m_translucent,
        emissive                                              ? "emissive"
            : edit == Edit::AlphaBlend || edit == Edit::Unlit ? "none"
                                                              : "base-color"));
    m_window->materialsDock()->materialList()->setCurrentRow(1); // the blue material
    QCOMPARE(m_document->project().currentMaterial, 1);
    TextureMapsDock* maps = m_window->textureMapsDock();
    MaterialDock* material = m_window->materialDock();
    (emissive ? static_cast<QDockWidget*>(maps) : material)->raise(); // the tab the user works in
    MapSlotWidget* emissiveSlot = maps->slotWidget(MapSlot::Emissive);
    QVERIFY(emissiveSlot->colorButton() && emissiveSlot->strengthSlider());
    QVERIFY(!emissiveSlot->factorSlider()); // no generic value slider for a colour
    QVERIFY(!emissiveSlot->findChild<QComboBox*>(QStringLiteral("mapChannel_emissive"))); // and no channel

    // The state before the edit (set up through the document, then forgotten by the history).
    Material setup = m_document->project().material();
    if (edit == Edit::EmissiveStrength)
        setup.map(MapSlot::Emissive).factor = glm::dvec4(0.05, 0.05, 0.05, 1.0);
    if (edit == Edit::AlphaCutoff)
        setup.alphaMode = AlphaMode::Mask;
    if (edit == Edit::DoubleSided)
        QCOMPARE(setup.doubleSided, false); // glTF's default: single-sided
    m_document->setMaterial(setup, QStringLiteral("test setup"));
    m_document->undoStack()->clear();
    if (edit == Edit::DoubleSided) // seen from behind: culled while single-sided
        m_window->viewport()->setTurntableAngles(180.0, 0.0);
    const QPoint right = pixelOfPart(1);
    QVERIFY(m_viewport->rect().contains(right));
    const QColor background = backgroundPixel();
    const QColor before = framePixel(right);
    const Material otherBefore = m_document->project().materials[0];

    switch (edit) {
    case Edit::EmissiveColour:
        QVERIFY(clickAndChooseColour(emissiveSlot->colorButton(), QColor(255, 0, 0)));
        QCOMPARE(
            glm::dvec3(m_document->project().material().map(MapSlot::Emissive).factor), glm::dvec3(1, 0, 0));
        break;
    case Edit::EmissiveStrength: {
        QCOMPARE(emissiveSlot->strengthSlider()->value(), 1.0);
        test::dragSlider(
            emissiveSlot->strengthSlider()->slider(), emissiveSlot->strengthSlider()->slider()->width() / 6);
        QVERIFY2(m_document->project().material().emissiveStrength > 4.0,
            qPrintable(QString::number(m_document->project().material().emissiveStrength)));
        QVERIFY(m_document->project().material().emissiveStrength <= Material::kMaxEmissiveStrength);
        break;
    }
    case Edit::AlphaMask:
        QVERIFY(chooseInCombo(
            material->alphaModeCombo(), QStringLiteral("Mask (cut-out)"), test::ComboInput::Keyboard));
        QVERIFY(material->alphaCutoffSlider()->isEnabled());
        break;
    case Edit::AlphaCutoff:
        QVERIFY(material->alphaCutoffSlider()->isEnabled());
        test::dragSlider(
            material->alphaCutoffSlider()->slider(), -material->alphaCutoffSlider()->slider()->width() / 2);
        QVERIFY2(m_document->project().material().alphaCutoff < 0.3,
            qPrintable(QString::number(m_document->project().material().alphaCutoff)));
        break;
    case Edit::AlphaBlend:
        QVERIFY(chooseInCombo(
            material->alphaModeCombo(), QStringLiteral("Blend (transparent)"), test::ComboInput::Keyboard));
        QVERIFY(!material->alphaCutoffSlider()->isEnabled());
        break;
    case Edit::Unlit:
    case Edit::DoubleSided: {
        // On the box itself, where a user clicks.
        QCheckBox* check = edit == Edit::Unlit ? material->unlitCheck() : material->doubleSidedCheck();
        QStyleOptionButton option;
        option.initFrom(check);
        const QRect box = check->style()->subElementRect(QStyle::SE_CheckBoxIndicator, &option, check);
        QTest::mouseClick(check, Qt::LeftButton, Qt::NoModifier, box.center());
        QVERIFY(edit == Edit::Unlit ? m_document->project().material().unlit
                                    : m_document->project().material().doubleSided);
        break;
    }
    }
    QCOMPARE(m_document->undoStack()->count(), 1); // a slider drag too: one step
    QCOMPARE(m_document->undoStack()->undoText(), undoText);
    QVERIFY(m_document->project().materials[0] == otherBefore); // the red material is untouched
    const QColor after = framePixel(right);
    const QString report = QStringLiteral("before %1, after %2, background %3")
                               .arg(describe(before), describe(after), describe(background));
    switch (edit) {
    case Edit::EmissiveColour: // black (no emission) -> red
        // (The display transform desaturates bright colours a little: green and blue are not 0.)
        QVERIFY2(before.red() < 10 && after.red() > 150 && after.red() > after.green() + 150
                && after.red() > after.blue() + 150,
            qPrintable(report));
        break;
    case Edit::EmissiveStrength: // a dim grey glow -> a bright one
        QVERIFY2(after.green() > before.green() + 40, qPrintable(report));
        break;
    case Edit::AlphaMask: // alpha 0.3 under the 0.5 cutoff: cut out
        QVERIFY2(isBlue(before) && near(after, background), qPrintable(report));
        break;
    case Edit::AlphaCutoff: // the cutoff below 0.3: drawn again
        QVERIFY2(near(before, background) && isBlue(after), qPrintable(report));
        break;
    case Edit::AlphaBlend: { // 30% blue over the grey: between the two, in every channel
        const auto between = [](int value, int a, int b) {
            return value >= std::min(a, b) - 3 && value <= std::max(a, b) + 3;
        };
        QVERIFY2(isBlue(before) && between(after.red(), before.red(), background.red())
                && between(after.green(), before.green(), background.green())
                && between(after.blue(), before.blue(), background.blue()) && !near(after, background, 10)
                && !near(after, before, 10),
            qPrintable(report));
        break;
    }
    case Edit::DoubleSided: // the back face drawn
        QVERIFY2(near(before, background) && isBlue(after), qPrintable(report));
        break;
    case Edit::Unlit: // the lit blue becomes its flat base colour
        QVERIFY2(isBlue(before) && isBlue(after) && !near(after, before, 10), qPrintable(report));
        break;
    }

    m_document->undoStack()->undo();
    const QColor undone = framePixel(right);
    QVERIFY2(near(undone, before), qPrintable(report + QStringLiteral(", undone %1").arg(describe(undone))));
    m_window->viewport()->setTurntableAngles(0.0, 0.0);
}

QTEST_MAIN(MaterialsFrameUiTest)
#include "MaterialsFrameUiTest.moc"
