// Inspection in the main window under Xvfb (issue 30, "Inspection"), driven as an artist does:
// - View > Value Picker (I) and the Values dock (ui/viewport/ValuePicker, ui/docks/ValuesDock): the radiance
// read
//   is the one the view's frame holds (the same as a linear still of the view at that pixel), the
//   screen value is the displayed pixel, the surface is the material of the part under the cursor
//   with every map's texel (maps the window released decoded again, then read) and the inputs
//   they make; hovering follows, a click pins, Esc follows again, an edit re-reads the pin, the
//   background reads no surface, turning it off stops reading.
// - Inspect Map… on a packed ORM file: each channel's thumbnail, what it feeds, its histogram and
//   numbers (ui/dialogs/MapInspectorDialog).
// - View > Wireframe (Shift+W) draws the mesh's edges over the view and takes them away again.
// Needs a display (Xvfb via with-display.sh).

#include "core/image/Image.h"
#include "core/image/MapImageCache.h"
#include "ui/MainWindow.h"
#include "ui/dialogs/MapInspectorDialog.h"
#include "ui/docks/MapSlotWidget.h"
#include "ui/docks/TextureMapsDock.h"
#include "ui/docks/ValuesDock.h"
#include "ui/document/Document.h"
#include "ui/viewport/SceneController.h"
#include "ui/viewport/SurfaceFormat.h"
#include "ui/viewport/ValuePicker.h"
#include "ui/viewport/ViewportWidget.h"

#include "TestAssets.h"
#include "WindowTestSupport.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QImage>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QtTest/QTest>

#include <array>
#include <cmath>
#include <memory>

using namespace facet;

class InspectionUiTest : public QObject {
    Q_OBJECT
public:
    static void initMain() { test::initWindowTestMain(); }

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void valuePickerReadsWhatTheViewShows();
    void valuePickerFollowsPinsAndStops();
    void inspectAPackedMap();
    void wireframeFromTheViewMenu();

private:
    // Waits for a full frame of the scene as it is: maps up, no preview.
    bool settledFrame();
    template <typename T> T* child(const char* name) const
    {
        return m_window->findChild<T*>(QLatin1String(name));
    }

    QTemporaryDir m_dir;
    QTemporaryDir m_recovery;
    QString m_walls;
    std::unique_ptr<MainWindow> m_window;
    Document* m_document = nullptr;
};

void InspectionUiTest::initTestCase()
{
    QCoreApplication::setOrganizationName(QStringLiteral("FacetTests"));
    m_walls = test::writeTexturedProject(m_dir.path());
    QVERIFY(!m_walls.isEmpty());
    m_window = test::showTestWindow(m_recovery.path());
    QVERIFY(m_window);
    m_document = m_window->document();
}

void InspectionUiTest::cleanupTestCase()
{
    m_document->newProject();
    m_window.reset();
}

bool InspectionUiTest::settledFrame()
{
    ViewportWidget* viewport = m_window->viewport();
    QSignalSpy rendered(viewport, &ViewportWidget::frameRendered);
    viewport->update();
    if (!rendered.wait(30000))
        return false;
    return QTest::qWaitFor(
        [viewport] {
            const ViewportFrameStats& stats = viewport->lastFrameStats();
            return !viewport->isPreviewing() && !stats.loadingMaps && stats.mapsHeldBack == 0
                && !stats.reduced && viewport->frameCount() > 0;
        },
        30000);
}

void InspectionUiTest::valuePickerReadsWhatTheViewShows()
{
    QVERIFY(test::openAndSettle(*m_window, m_walls));
    QVERIFY(settledFrame());
    ViewportWidget* viewport = m_window->viewport();
    ValuePicker* picker = m_window->valuePicker();
    ValuesDock* dock = m_window->valuesDock();
    QAction* action = child<QAction>("valuePickerAction");
    QVERIFY(action && action->isCheckable());
    QCOMPARE(action->shortcut(), QKeySequence(Qt::Key_I));
    QVERIFY(!picker->isActive());
    action->trigger();
    QVERIFY(picker->isActive());
    QVERIFY(dock->isVisible());

    // Up and left of the sphere's centre (far from its mirror images, so a flipped row or column
    // reads another value): Brick Wall (base colour, normal and one ORM file read three ways).
    const QPointF point(viewport->width() / 2 - viewport->height() / 8 + 0.5,
        viewport->height() / 2 - viewport->height() / 6 + 0.5);
    PickedValue value = picker->readAt(point);
    QVERIFY(value.surface);
    QCOMPARE(value.surface->materialName, QStringLiteral("Brick Wall"));
    // The window let the decoded maps go after upload: they are read again off the GUI thread.
    QVERIFY(QTest::qWaitFor([picker] { return picker->pendingMapLoads() == 0; }, 20000));
    value = *picker->current();
    QVERIFY(value.surface && value.surface->mapsLoading.empty() && value.surface->mapProblems.empty());
    const SurfaceProbe& probe = value.surface->probe;
    QCOMPARE(int(probe.maps.size()), 5);
    const auto readOf = [&](MapSlot slot) -> const MapProbe& {
        for (const MapProbe& read : probe.maps)
            if (read.slot == slot)
                return read;
        return probe.maps.front();
    };
    // Uniform files (tests/support/TestAssets writeTexturedProject): their 8-bit values.
    QVERIFY(std::abs(readOf(MapSlot::BaseColor).stored.r - 0.6) <= 0.5 / 255.0 + 1e-6);
    QCOMPARE(readOf(MapSlot::BaseColor).size, glm::ivec2(32, 16));
    QVERIFY(std::abs(probe.inputs.perceptualRoughness - 0.6) <= 0.5 / 255.0 + 1e-6); // ORM green
    QVERIFY(std::abs(probe.inputs.occlusion - 0.9) <= 0.5 / 255.0 + 1e-6); // ORM red
    QVERIFY(std::abs(probe.inputs.metallic) <= 1e-6); // ORM blue
    // Facing the camera, turned up and left as the point is.
    QVERIFY(probe.geometricNormal.z > 0.5 && probe.geometricNormal.x < -0.1 && probe.geometricNormal.y > 0.1);

    // The radiance is the frame's: a linear still of the view holds the same value at that pixel.
    QVERIFY(value.radiance);
    QVERIFY(value.display);
    const QImage shown = viewport->grabFramebuffer();
    const QRgb screen = shown.pixel(value.pixel);
    QVERIFY2(std::abs(qRed(screen) - value.display->r) <= 1
            && std::abs(qGreen(screen) - value.display->g) <= 1
            && std::abs(qBlue(screen) - value.display->b) <= 1,
        qPrintable(QStringLiteral("screen %1 %2 %3, picked %4 %5 %6")
                       .arg(qRed(screen))
                       .arg(qGreen(screen))
                       .arg(qBlue(screen))
                       .arg(value.display->r)
                       .arg(value.display->g)
                       .arg(value.display->b)));
    std::string error;
    const std::optional<Image> still = viewport->renderStill(FrameOutput::LinearRadiance, &error);
    QVERIFY2(still, error.c_str());
    const glm::vec4 expected = still->at(value.pixel.x(), value.pixel.y());
    for (int c = 0; c < 3; ++c)
        QVERIFY2(std::abs((*value.radiance)[c] - expected[c]) <= 1e-3f * std::max(expected[c], 1e-3f),
            qPrintable(QStringLiteral("channel %1: picked %2, still %3")
                           .arg(c)
                           .arg((*value.radiance)[c])
                           .arg(expected[c])));
    QVERIFY(expected.r > 0.0f);

    // The dock's rows say the same.
    QCOMPARE(dock->valueOf(QStringLiteral("Surface/Material")), QStringLiteral("Brick Wall"));
    QVERIFY2(dock->valueOf(QStringLiteral("Maps/Roughness")).startsWith(QStringLiteral("texel ")),
        qPrintable(dock->text()));
    QCOMPARE(dock->valueOf(QStringLiteral("Material inputs/Roughness")),
        QString::number(probe.inputs.perceptualRoughness, 'g', 4));
    QVERIFY(!dock->valueOf(QStringLiteral("Shaded radiance")).isEmpty());
    QVERIFY(dock->valueOf(QStringLiteral("On screen (sRGB)")).contains(QLatin1Char('#')));

    // Beside the sphere: the background's radiance, no surface (read from the frame the view drew
    // again after the still).
    QVERIFY(settledFrame());
    value = picker->readAt(QPointF(2.5, 2.5));
    QVERIFY(!value.surface);
    QVERIFY(value.radiance);
    QCOMPARE(dock->valueOf(QStringLiteral("Surface")), QStringLiteral("background"));
    action->trigger();
    QVERIFY(!picker->isActive());
}

void InspectionUiTest::valuePickerFollowsPinsAndStops()
{
    QVERIFY(test::openAndSettle(*m_window, m_walls));
    QVERIFY(settledFrame());
    ViewportWidget* viewport = m_window->viewport();
    ValuePicker* picker = m_window->valuePicker();
    picker->setActive(true);
    QVERIFY(viewport->hasMouseTracking());
    const QPoint centre(viewport->width() / 2, viewport->height() / 2);
    const QPoint aside = centre + QPoint(viewport->height() / 10, 0);
    // Hovering follows the cursor.
    QTest::mouseMove(viewport, centre);
    QVERIFY(QTest::qWaitFor(
        [&] {
            return picker->current() && picker->current()->position == QPointF(centre) + QPointF(0.5, 0.5);
        },
        5000));
    QTest::mouseMove(viewport, aside);
    QVERIFY(QTest::qWaitFor(
        [&] { return picker->current()->position == QPointF(aside) + QPointF(0.5, 0.5); }, 5000));
    // A click pins: moving on reads nothing new.
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, centre);
    QVERIFY(picker->isPinned());
    QCOMPARE(picker->current()->position, QPointF(centre) + QPointF(0.5, 0.5));
    QVERIFY(m_window->valuesDock()->findChild<QCheckBox*>(QStringLiteral("valuesPinned"))->isChecked());
    // A cross marks the pinned point.
    QWidget* pin = viewport->findChild<QWidget*>(QStringLiteral("valuePickerPin"));
    QVERIFY(pin && pin->isVisible());
    QVERIFY(pin->geometry().contains(centre));
    QTest::mouseMove(viewport, aside);
    QTest::qWait(50);
    QCOMPARE(picker->current()->position, QPointF(centre) + QPointF(0.5, 0.5));
    QVERIFY(QTest::qWaitFor([picker] { return picker->pendingMapLoads() == 0; }, 20000));
    // An edit: the pinned point is read again with the next frame (roughness factor 0.5 x G 0.6).
    const double before = picker->current()->surface->probe.inputs.perceptualRoughness;
    Material material = m_document->project().material();
    material.setFactor(MapSlot::Roughness, 0.5);
    m_document->setMaterial(material, QStringLiteral("Rougher"));
    QVERIFY(settledFrame());
    QVERIFY(QTest::qWaitFor(
        [&] {
            return std::abs(picker->current()->surface->probe.inputs.perceptualRoughness - 0.5 * before)
                < 1e-6;
        },
        10000));
    // A clear coat: its rows join the material's inputs (none without one).
    ValuesDock* values = m_window->valuesDock();
    QVERIFY2(
        values->valueOf(QStringLiteral("Material inputs/Clearcoat")).isEmpty(), qPrintable(values->text()));
    material.setClearcoat(0.75, 0.25);
    m_document->setMaterial(material, QStringLiteral("Coated"));
    QVERIFY(settledFrame());
    QVERIFY(QTest::qWaitFor(
        [&] {
            return values->valueOf(QStringLiteral("Material inputs/Clearcoat")) == QStringLiteral("0.75");
        },
        10000));
    QCOMPARE(values->valueOf(QStringLiteral("Material inputs/Clearcoat roughness")), QStringLiteral("0.25"));
    QCOMPARE(picker->current()->surface->probe.inputs.clearcoat, 0.75);
    // Esc follows the cursor again.
    QTest::keyClick(viewport, Qt::Key_Escape);
    QVERIFY(!picker->isPinned());
    QVERIFY(!pin->isVisible());
    QTest::mouseMove(viewport, aside + QPoint(1, 0));
    QVERIFY(QTest::qWaitFor(
        [&] { return picker->current()->position == QPointF(aside + QPoint(1, 0)) + QPointF(0.5, 0.5); },
        5000));
    // Off: no reading, no tracking.
    picker->setActive(false);
    QVERIFY(!picker->current());
    QVERIFY(!viewport->hasMouseTracking());
}

void InspectionUiTest::inspectAPackedMap()
{
    m_document->newProject();
    // An ORM file: R a left-to-right gradient (occlusion), G 128 (roughness), B 255 (metallic).
    const QString orm = m_dir.filePath(QStringLiteral("inspect_orm.png"));
    QImage image(32, 16, QImage::Format_RGB888);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 32; ++x)
            image.setPixelColor(x, y, QColor(x * 8, 128, 255));
    QVERIFY(image.save(orm));
    Material material = m_document->project().material();
    const std::pair<MapSlot, MapChannel> reads[] = {{MapSlot::Occlusion, MapChannel::R},
        {MapSlot::Roughness, MapChannel::G}, {MapSlot::Metallic, MapChannel::B}};
    for (const auto& [slot, channel] : reads) {
        material.map(slot).path = orm.toStdString();
        material.map(slot).channel = channel;
    }
    m_document->setMaterial(material, QStringLiteral("ORM"));
    TextureMapsDock* maps = m_window->textureMapsDock();
    QVERIFY(!maps->slotWidget(MapSlot::Normal)->inspectMap()); // no file
    QCOMPARE(m_window->statusMessage(), QStringLiteral("Inspect Map: the normal slot has no file"));
    MapInspectorDialog* dialog = maps->slotWidget(MapSlot::Roughness)->inspectMap();
    QVERIFY(dialog);
    QCOMPARE(dialog->channelCaptions(),
        (QStringList {QStringLiteral("R: ambient occlusion"), QStringLiteral("G: roughness (this slot)"),
            QStringLiteral("B: metallic")}));
    const QStringList summaries = dialog->channelSummaries();
    QCOMPARE(summaries.value(0), QStringLiteral("min 0.000 · max 0.973 · mean 0.486")); // 0..248 / 255
    QCOMPARE(summaries.value(1), QStringLiteral("min 0.502 · max 0.502 · mean 0.502"));
    QCOMPARE(summaries.value(2), QStringLiteral("min 1.000 · max 1.000 · mean 1.000"));
    dialog->close();
    // The histogram as drawn: one full-height bar for a constant, none where no value falls.
    std::array<std::uint64_t, 256> histogram {};
    histogram[128] = 512;
    const QImage bars = MapInspectorDialog::histogramImage(histogram, QSize(256, 64));
    QVERIFY(bars.pixelColor(128, 0).lightness() > 200 && bars.pixelColor(128, 63).lightness() > 200);
    QVERIFY(bars.pixelColor(10, 63).lightness() < 60);
    // The channel thumbnail keeps the file's top row at the top: the gradient runs left to right.
    std::string error;
    const auto decoded = MapImageCache::shared().load(orm.toStdString(), &error);
    QVERIFY2(decoded, error.c_str());
    const QImage red = MapInspectorDialog::channelThumbnail(*decoded, 0, 128);
    QCOMPARE(red.size(), QSize(32, 16));
    QCOMPARE(qGray(red.pixel(31, 0)), 248);
    QCOMPARE(qGray(red.pixel(0, 15)), 0);
}

void InspectionUiTest::wireframeFromTheViewMenu()
{
    m_document->newProject();
    ViewportWidget* viewport = m_window->viewport();
    const auto frame = [&] {
        QSignalSpy rendered(viewport, &ViewportWidget::frameRendered);
        viewport->update();
        rendered.wait(30000);
        (void)QTest::qWaitFor([viewport] { return !viewport->isPreviewing(); }, 10000);
        return viewport->grabFramebuffer();
    };
    const QImage plain = frame();
    QAction* wireframe = child<QAction>("wireframeAction");
    QVERIFY(wireframe && wireframe->isCheckable());
    QCOMPARE(wireframe->shortcut(), QKeySequence(Qt::SHIFT | Qt::Key_W));
    wireframe->trigger();
    QVERIFY(m_window->viewport()->viewState().wireframe);
    const QImage wired = frame();
    int changed = 0;
    for (int y = 0; y < plain.height(); y += 2)
        for (int x = 0; x < plain.width(); x += 2)
            changed += plain.pixel(x, y) != wired.pixel(x, y) ? 1 : 0;
    QVERIFY2(changed > 100, qPrintable(QString::number(changed)));
    wireframe->trigger();
    QVERIFY(!m_window->viewport()->viewState().wireframe);
    const QImage again = frame();
    int left = 0;
    for (int y = 0; y < plain.height(); y += 2)
        for (int x = 0; x < plain.width(); x += 2)
            left += qAbs(qGreen(plain.pixel(x, y)) - qGreen(again.pixel(x, y))) > 8 ? 1 : 0;
    QVERIFY2(left < 20, qPrintable(QString::number(left)));
}

QTEST_MAIN(InspectionUiTest)
#include "InspectionUiTest.moc"
