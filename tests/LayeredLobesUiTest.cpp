// The layered lobes in the window (Material dock, a section per lobe), under Xvfb: turning a lobe
// on through its section's check is one undo step that re-renders, shows the lobe's sliders and
// its maps in the Texture Maps dock and undoes back (sliders and maps hidden, frame as before); a drag of any
// slider made from the property registry is one undo step named by the row's label; an undo of the document
// moves the sliders. A row per lobe and edit.

#include "core/material/MaterialProperties.h"
#include "ui/docks/MaterialDock.h"
#include "ui/docks/TextureMapsDock.h"
#include "ui/widgets/ValueSlider.h"

#include "TestSupport.h"
#include "WindowTestSupport.h"

#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QSlider>
#include <QStyle>
#include <QStyleOptionGroupBox>
#include <QTemporaryDir>

using namespace facet;

namespace {

// Clicks a checkable group box's check, where a user clicks it.
void clickGroupCheck(QGroupBox* group)
{
    QStyleOptionGroupBox option;
    option.initFrom(group);
    option.subControls = QStyle::SC_GroupBoxCheckBox;
    option.text = group->title();
    option.features = QStyleOptionFrame::None;
    const QRect box
        = group->style()->subControlRect(QStyle::CC_GroupBox, &option, QStyle::SC_GroupBoxCheckBox, group);
    QTest::mouseClick(group, Qt::LeftButton, Qt::NoModifier, box.center());
}

} // namespace

class LayeredLobesUiTest : public QObject {
    Q_OBJECT
public:
    static void initMain() { test::initWindowTestMain(); }

private Q_SLOTS:
    void initTestCase()
    {
        QCoreApplication::setOrganizationName(QStringLiteral("FacetTests"));
        m_window = test::showTestWindow(m_recovery.path());
        QVERIFY(m_window);
        m_document = m_window->document();
    }
    void cleanupTestCase() { m_window.reset(); }
    void init()
    {
        // The default material, lobes off, history empty; the Material dock in front.
        Material material = m_document->project().material();
        material.setClearcoat(0.0, 0.0);
        material.setSheen(glm::dvec3(0.0), 0.0);
        material.setFactor(MapSlot::Anisotropy, 0.0);
        material.setFactor(MapSlot::Iridescence, 0.0);
        material.setSpecular(1.0, glm::dvec3(1.0));
        material.setBaseColor(glm::dvec3(0.6, 0.05, 0.02));
        material.setFactor(MapSlot::Roughness, 0.7);
        m_document->setMaterial(material, QStringLiteral("test setup"));
        m_document->undoStack()->clear();
        QVERIFY(test::focusWidget(m_window->materialDock()->clearcoatGroup()));
    }

    void turningALobeOnIsOneStep_data()
    {
        QTest::addColumn<int>("lobe");
        QTest::addColumn<int>("control"); // a registry slider of the section, shown while the lobe is on
        QTest::addColumn<double>("onValue"); // that slider's value once the section turns the lobe on
        QTest::addColumn<QString>("undoText");
        QTest::addColumn<double>("change"); // the least mean difference the lobe makes to the frame
        QTest::newRow("clearcoat") << int(MaterialLobe::Clearcoat) << int(MaterialProperty::Clearcoat) << 1.0
                                   << QStringLiteral("Clearcoat On") << 2.0;
        // The sheen turns on white, at roughness 0.5 (0 would be a hairline at the silhouette).
        QTest::newRow("sheen") << int(MaterialLobe::Sheen) << int(MaterialProperty::SheenRoughness) << 0.5
                               << QStringLiteral("Sheen On") << 2.0;
        // Anisotropy turns on at strength 0.5: the default glossy plastic's highlights stretch, a
        // dielectric's few percent of the light (measured 0.88 of 255 on average).
        QTest::newRow("anisotropy") << int(MaterialLobe::Anisotropy) << int(MaterialProperty::Anisotropy) << 0.5
                                    << QStringLiteral("Anisotropy On") << 0.5;
        // Iridescence turns a full film on (1.3, 400 nm): the plastic's reflection takes the film's
        // colours.
        QTest::newRow("iridescence") << int(MaterialLobe::Iridescence) << int(MaterialProperty::Iridescence) << 1.0
                                     << QStringLiteral("Iridescence On") << 0.5;
    }
    void turningALobeOnIsOneStep()
    {
        QFETCH(int, lobe);
        QFETCH(int, control);
        QFETCH(double, onValue);
        QFETCH(QString, undoText);
        QFETCH(double, change);
        MaterialDock* dock = m_window->materialDock();
        QGroupBox* group = MaterialLobe(lobe) == MaterialLobe::Clearcoat ? dock->clearcoatGroup()
            : MaterialLobe(lobe) == MaterialLobe::Sheen                  ? dock->sheenGroup()
            : MaterialLobe(lobe) == MaterialLobe::Iridescence            ? dock->iridescenceGroup()
                                                                         : dock->anisotropyGroup();
        ValueSlider* slider = dock->propertySlider(MaterialProperty(control));
        QVERIFY(group && slider);
        QVERIFY(test::focusWidget(group));
        QVERIFY(!group->isChecked() && !slider->isVisible()); // off: the section shows its title only
        // The lobe's maps in the Texture Maps dock come and go with it.
        TextureMapsDock* maps = m_window->textureMapsDock();
        QWidget* lobeMaps = maps->lobeSlots(MaterialLobe(lobe));
        QVERIFY(lobeMaps && !lobeMaps->isVisibleTo(maps));
        const QImage before = frame();
        clickGroupCheck(group);
        const Material& on = m_document->project().material();
        QVERIFY(on.hasLobe(MaterialLobe(lobe)));
        QVERIFY(lobeMaps->isVisibleTo(maps));
        QCOMPARE(scalarOf(on, MaterialProperty(control)), onValue);
        if (MaterialLobe(lobe) == MaterialLobe::Sheen)
            QCOMPARE(on.sheenColor(), glm::dvec3(1.0));
        QCOMPARE(m_document->undoStack()->count(), 1);
        QCOMPARE(m_document->undoStack()->undoText(), undoText);
        QVERIFY(group->isChecked() && slider->isVisible());
        QCOMPARE(slider->value(), onValue);
        const QImage lit = frame();
        QVERIFY2(difference(before, lit) > change, qPrintable(QString::number(difference(before, lit))));
        m_document->undoStack()->undo();
        QVERIFY(!m_document->project().material().hasLobe(MaterialLobe(lobe)));
        QVERIFY(!group->isChecked() && !slider->isVisible());
        QVERIFY(!lobeMaps->isVisibleTo(maps));
        QVERIFY2(difference(before, frame()) < 0.5, qPrintable(QString::number(difference(before, frame()))));
    }

    // Every slider the Material dock makes from a registry row (the lobes' and the IOR and alpha
    // cutoff): a drag is one undo step named by the row's label, within the row's range; an undo
    // moves the slider back.
    void aRegistrySliderDragIsOneStep_data()
    {
        QTest::addColumn<int>("property");
        QTest::addColumn<double>("start");
        QTest::newRow("clearcoat strength") << int(MaterialProperty::Clearcoat) << 0.5;
        QTest::newRow("clearcoat roughness") << int(MaterialProperty::ClearcoatRoughness) << 0.5;
        QTest::newRow("sheen roughness") << int(MaterialProperty::SheenRoughness) << 0.5;
        QTest::newRow("specular strength") << int(MaterialProperty::Specular) << 0.5;
        QTest::newRow("anisotropy strength") << int(MaterialProperty::Anisotropy) << 0.5;
        QTest::newRow("anisotropy rotation (degrees)") << int(MaterialProperty::AnisotropyRotation) << 0.0;
        QTest::newRow("iridescence strength") << int(MaterialProperty::Iridescence) << 0.5;
        QTest::newRow("iridescence film ior") << int(MaterialProperty::IridescenceIor) << 1.3;
        QTest::newRow("iridescence thickness (nm; the slider ends at 1200)")
            << int(MaterialProperty::IridescenceThickness) << 400.0;
        QTest::newRow("iridescence thickness minimum (nm)") << int(MaterialProperty::IridescenceThicknessMinimum)
                                                            << 100.0;
        QTest::newRow("ior (the slider ends at 3, the spin box at 5)") << int(MaterialProperty::Ior) << 2.0;
        QTest::newRow("alpha cutoff (mask)") << int(MaterialProperty::AlphaCutoff) << 0.5;
    }
    void aRegistrySliderDragIsOneStep()
    {
        QFETCH(int, property);
        QFETCH(double, start);
        const MaterialPropertyInfo& info = infoOf(MaterialProperty(property));
        Material material = m_document->project().material();
        material.setClearcoat(0.5, 0.5);
        material.setSheen(glm::dvec3(0.5), 0.5);
        material.setAnisotropy(0.5, 0.0);
        material.setIridescence(0.5, 1.3, 100.0, 400.0);
        material.alphaMode = AlphaMode::Mask;
        setScalar(material, MaterialProperty(property), start);
        m_document->setMaterial(material, QStringLiteral("test setup"));
        m_document->undoStack()->clear();
        ValueSlider* slider = m_window->materialDock()->propertySlider(MaterialProperty(property));
        QVERIFY(slider && slider->isVisible() && slider->isEnabled());
        QCOMPARE(slider->value(), start);
        QCOMPARE(slider->spinBox()->maximum(), info.maximum); // typing reaches the whole range
        test::dragSlider(slider->slider(), slider->slider()->width() / 4);
        const double value = scalarOf(m_document->project().material(), MaterialProperty(property));
        QVERIFY2(value > start + 0.05 && value <= info.maximum, qPrintable(QString::number(value)));
        QCOMPARE(slider->value(), value);
        QCOMPARE(m_document->undoStack()->count(), 1); // a drag: one step
        QCOMPARE(m_document->undoStack()->undoText(), QString::fromUtf8(info.label));
        m_document->undoStack()->undo();
        QCOMPARE(slider->value(), start); // the document moved the slider back
    }

    // KHR_materials_specular's section is the dielectric's own reflectance, always shown (as its
    // Texture Maps box): its strength and colour change the frame, each as one undo step; a metal
    // does not change at all.
    void specularLayerChangesTheDielectric_data()
    {
        QTest::addColumn<double>("strength");
        QTest::addColumn<glm::dvec3>("color");
        QTest::addColumn<double>("metallic");
        QTest::addColumn<bool>("changes");
        QTest::newRow("strength 0: no reflection") << 0.0 << glm::dvec3(1.0) << 0.0 << true;
        QTest::newRow("colour 25: F0 1, a mirror") << 1.0 << glm::dvec3(25.0) << 0.0 << true;
        QTest::newRow("a metal ignores it") << 0.0 << glm::dvec3(25.0) << 1.0 << false;
    }
    void specularLayerChangesTheDielectric()
    {
        QFETCH(double, strength);
        QFETCH(glm::dvec3, color);
        QFETCH(double, metallic);
        QFETCH(bool, changes);
        MaterialDock* dock = m_window->materialDock();
        QWidget* section = dock->findChild<QWidget*>(QStringLiteral("specularGroup"));
        ValueSlider* strengthSlider = dock->propertySlider(MaterialProperty::Specular);
        QVERIFY(section && strengthSlider && test::focusWidget(strengthSlider->slider()));
        QVERIFY(section->isVisible() && strengthSlider->isVisible());
        TextureMapsDock* maps = m_window->textureMapsDock();
        QVERIFY(maps->lobeSlots(MaterialLobe::Specular)->isVisibleTo(maps)); // shown at the defaults too
        Material material = m_document->project().material();
        material.setFactor(MapSlot::Metallic, metallic);
        m_document->setMaterial(material, QStringLiteral("test setup"));
        const QImage before = frame();
        material.setSpecular(strength, color);
        m_document->setMaterial(material, QStringLiteral("Specular"));
        QCOMPARE(dock->propertySlider(MaterialProperty::Specular)->value(), strength);
        const double changed = difference(before, frame());
        QVERIFY2(changes ? changed > 2.0 : changed < 0.5, qPrintable(QString::number(changed)));
        m_document->undoStack()->undo();
        QCOMPARE(dock->propertySlider(MaterialProperty::Specular)->value(), 1.0);
    }

private:
    // The finished frame (the refinement done, the lighting ready).
    QImage frame()
    {
        ViewportWidget* viewport = m_window->viewport();
        QTest::qWait(50);
        const bool settled = QTest::qWaitFor(
            [viewport] { return !viewport->isPreviewing() && !viewport->lastFrameStats().lightingPending; },
            30000);
        return settled ? viewport->grabFramebuffer() : QImage(); // a null image differs from every frame
    }
    // Mean absolute difference of two frames, in 8-bit levels per channel.
    static double difference(const QImage& a, const QImage& b)
    {
        if (a.size() != b.size())
            return 255.0;
        double sum = 0.0;
        for (int y = 0; y < a.height(); ++y)
            for (int x = 0; x < a.width(); ++x) {
                const QColor p = a.pixelColor(x, y);
                const QColor q = b.pixelColor(x, y);
                sum += std::abs(p.red() - q.red()) + std::abs(p.green() - q.green())
                    + std::abs(p.blue() - q.blue());
            }
        return sum / (3.0 * a.width() * a.height());
    }

    QTemporaryDir m_recovery;
    std::unique_ptr<MainWindow> m_window;
    Document* m_document = nullptr;
};

QTEST_MAIN(LayeredLobesUiTest)
#include "LayeredLobesUiTest.moc"
