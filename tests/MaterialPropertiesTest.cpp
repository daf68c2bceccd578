// The material property registry (core/material/MaterialProperties.h), a row per property: its
// field is the project file's (a value set through the row is found at that path of the
// material's JSON), its range is the one Material::validate enforces (each end accepted, the next
// number beyond refused naming the field), its setter and getter agree, its name reads back, and
// the wedge axes of material properties take their name, field and range from it.

#include <QtTest/QTest>

#include <QJsonArray>
#include <QJsonObject>

#include <cmath>
#include <set>
#include <string>

#include "core/material/MaterialProperties.h"
#include "core/project/Project.h"
#include "core/project/WedgeAxis.h"

using namespace facet;

Q_DECLARE_METATYPE(facet::MaterialProperty)

namespace {

// The JSON value at a dotted field ("roughness.factor", "baseColor.factor.a"; a, r, g, b index a
// factor array).
QJsonValue valueAt(const QJsonObject& material, const std::string& field)
{
    QJsonValue node = material;
    std::size_t start = 0;
    while (start <= field.size()) {
        const std::size_t dot = field.find('.', start);
        const std::string token
            = field.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
        if (node.isArray()) {
            const int index = token == "r" ? 0 : token == "g" ? 1 : token == "b" ? 2 : token == "a" ? 3 : -1;
            node = node.toArray().at(index);
        } else {
            node = node.toObject().value(QString::fromStdString(token));
        }
        if (dot == std::string::npos)
            break;
        start = dot + 1;
    }
    return node;
}

} // namespace

class MaterialPropertiesTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void everyProperty_data()
    {
        QTest::addColumn<MaterialProperty>("property");
        QTest::addColumn<double>("inside"); // a value inside the range other than the default
        for (const MaterialPropertyInfo& info : materialProperties())
            QTest::newRow(info.name) << info.property << 0.5 * (info.minimum + info.maximum) * 0.77;
    }

    void everyProperty()
    {
        QFETCH(MaterialProperty, property);
        QFETCH(double, inside);
        const MaterialPropertyInfo& info = infoOf(property);
        QCOMPARE(int(info.property), int(property));
        QCOMPARE(materialPropertyFromString(info.name), std::optional(property));
        QVERIFY(info.minimum < info.maximum);
        QVERIFY(std::string(info.label).size() > 2);
        const bool color = info.value == PropertyValue::Color;
        QVERIFY(!color || info.slot);

        // The default material's value lies in the range.
        const Material defaults;
        std::string problem;
        QVERIFY2(checkProperty(defaults, property, &problem), problem.c_str());

        // Set through the row, found at the row's field of the file, and read back the same.
        Material material;
        const glm::dvec3 rgb(inside, 0.5 * inside, 0.25 * inside);
        if (color)
            setColor(material, property, rgb);
        else
            setScalar(material, property, inside);
        const QJsonObject json = materialToJson(material, {});
        if (color) {
            QCOMPARE(colorOf(material, property), rgb);
            const std::string field = info.field;
            QCOMPARE(valueAt(json, field + ".r").toDouble(), rgb.r);
            QCOMPARE(valueAt(json, field + ".g").toDouble(), rgb.g);
            QCOMPARE(valueAt(json, field + ".b").toDouble(), rgb.b);
            // A colour keeps the factor's fourth component (the base colour's alpha).
            QCOMPARE(material.map(*info.slot).factor.w, defaults.map(*info.slot).factor.w);
        } else {
            QCOMPARE(scalarOf(material, property), inside);
            QCOMPARE(valueAt(json, info.field).toDouble(), inside);
            if (info.slot && isScalarSlot(*info.slot))
                QCOMPARE(material.map(*info.slot).factor, glm::dvec4(inside)); // equal components
        }
        QVERIFY2(material.validate(&problem), problem.c_str());

        // validate() takes each end and refuses the next number beyond, naming the field.
        const std::string named = std::string(info.field) + (color ? ".g" : "");
        for (const double end : {info.minimum, info.maximum}) {
            Material probe;
            color ? setColor(probe, property, glm::dvec3(end)) : setScalar(probe, property, end);
            QVERIFY2(probe.validate(&problem), problem.c_str());
            const double beyond = std::nextafter(end, end == info.minimum ? -INFINITY : INFINITY);
            color ? setColor(probe, property, glm::dvec3(end, beyond, end))
                  : setScalar(probe, property, beyond);
            QVERIFY(!probe.validate(&problem));
            QVERIFY2(problem.rfind(named + ": ", 0) == 0, problem.c_str());
            QVERIFY2(problem.find("is outside") != std::string::npos, problem.c_str());
        }
    }

    // The rows as the project format, glTF's ranges and the command line documents them
    // (docs/project-format.md): an edit of the table shows here.
    void goldenRows_data()
    {
        QTest::addColumn<MaterialProperty>("property");
        QTest::addColumn<QString>("field");
        QTest::addColumn<double>("minimum");
        QTest::addColumn<double>("maximum");
        QTest::addColumn<QString>("flag");
        using P = MaterialProperty;
        QTest::newRow("base colour") << P::BaseColor << "baseColor.factor" << 0.0 << 1.0 << "base-color";
        QTest::newRow("alpha") << P::Alpha << "baseColor.factor.a" << 0.0 << 1.0 << "";
        QTest::newRow("metallic") << P::Metallic << "metallic.factor" << 0.0 << 1.0 << "metallic";
        QTest::newRow("roughness") << P::Roughness << "roughness.factor" << 0.0 << 1.0 << "roughness";
        QTest::newRow("occlusion") << P::Occlusion << "occlusion.factor" << 0.0 << 1.0 << "";
        QTest::newRow("normal") << P::Normal << "normal.factor" << 0.0 << 10.0 << "";
        QTest::newRow("emissive") << P::Emissive << "emissive.factor" << 0.0 << 1.0 << "";
        QTest::newRow("emissive strength")
            << P::EmissiveStrength << "emissiveStrength" << 0.0 << 10000.0 << "";
        QTest::newRow("ior") << P::Ior << "ior" << 1.0 << 5.0 << "";
        QTest::newRow("alpha cutoff") << P::AlphaCutoff << "alphaCutoff" << 0.0 << 1.0 << "";
        QTest::newRow("clearcoat") << P::Clearcoat << "clearcoat.factor" << 0.0 << 1.0 << "clearcoat";
        QTest::newRow("clearcoat roughness")
            << P::ClearcoatRoughness << "clearcoatRoughness.factor" << 0.0 << 1.0 << "clearcoat-roughness";
        QTest::newRow("clearcoat normal")
            << P::ClearcoatNormal << "clearcoatNormal.factor" << 0.0 << 10.0 << "";
        QTest::newRow("sheen colour") << P::SheenColor << "sheenColor.factor" << 0.0 << 1.0 << "sheen-color";
        QTest::newRow("sheen roughness")
            << P::SheenRoughness << "sheenRoughness.factor" << 0.0 << 1.0 << "sheen-roughness";
        QTest::newRow("specular") << P::Specular << "specular.factor" << 0.0 << 1.0 << "specular";
        QTest::newRow("specular colour")
            << P::SpecularColor << "specularColor.factor" << 0.0 << 100.0 << "specular-color";
        QTest::newRow("anisotropy") << P::Anisotropy << "anisotropy.factor" << 0.0 << 1.0 << "anisotropy";
        QTest::newRow("anisotropy rotation") << P::AnisotropyRotation << "anisotropyRotationDegrees" << -180.0
                                             << 180.0 << "anisotropy-rotation";
        QTest::newRow("iridescence") << P::Iridescence << "iridescence.factor" << 0.0 << 1.0 << "iridescence";
        QTest::newRow("iridescence ior") << P::IridescenceIor << "iridescenceIor" << 1.0 << 5.0 << "iridescence-ior";
        QTest::newRow("iridescence thickness") << P::IridescenceThickness << "iridescenceThickness.factor" << 0.0
                                               << 100000.0 << "iridescence-thickness";
        QTest::newRow("iridescence thickness minimum") << P::IridescenceThicknessMinimum
                                                       << "iridescenceThicknessMinimum" << 0.0 << 100000.0
                                                       << "iridescence-thickness-minimum";
        QCOMPARE(kMaterialPropertyCount, 23); // a new property adds its golden row here
    }

    void goldenRows()
    {
        QFETCH(MaterialProperty, property);
        QFETCH(QString, field);
        QFETCH(double, minimum);
        QFETCH(double, maximum);
        QFETCH(QString, flag);
        const MaterialPropertyInfo& info = infoOf(property);
        QCOMPARE(QString::fromLatin1(info.field), field);
        QCOMPARE(info.minimum, minimum);
        QCOMPARE(info.maximum, maximum);
        QCOMPARE(QString::fromLatin1(info.flag ? info.flag : ""), flag);
    }

    void namesAndFlagsAreUnique()
    {
        std::set<std::string> names;
        std::set<std::string> fields;
        std::set<std::string> flags;
        for (const MaterialPropertyInfo& info : materialProperties()) {
            QVERIFY2(names.insert(info.name).second, info.name);
            QVERIFY2(fields.insert(info.field).second, info.field);
            if (info.flag)
                QVERIFY2(flags.insert(info.flag).second, info.flag);
        }
        QCOMPARE(int(names.size()), kMaterialPropertyCount);
        QVERIFY(!materialPropertyFromString("shininess"));
    }

    // A wedge axis of a material property is the registry's row: same name, field, range and
    // setter (applying a value through the axis equals setting it through the row).
    void wedgeAxesReadTheRegistry()
    {
        int materialAxes = 0;
        for (const WedgeParameterInfo& axis : wedgeParameters()) {
            if (!axis.property)
                continue;
            ++materialAxes;
            const MaterialPropertyInfo& info = infoOf(*axis.property);
            QCOMPARE(std::string(axis.name), std::string(info.name));
            QCOMPARE(std::string(axis.field), std::string(info.field));
            QCOMPARE(axis.minimum, info.minimum);
            QCOMPARE(axis.maximum, info.maximum);
            const double value = info.minimum + 0.3 * (info.maximum - info.minimum);
            WedgeAxis wedge;
            wedge.parameter = axis.parameter;
            wedge.values = {value};
            Project project = Project::defaultProject();
            wedge.apply(0, project);
            Material expected = Project::defaultProject().material();
            setScalar(expected, *axis.property, value);
            QCOMPARE(scalarOf(project.material(), *axis.property), value);
            QVERIFY(project.material() == expected);
        }
        QCOMPARE(materialAxes, 17);
    }

    // Every map slot's factor has its row (the Texture Maps dock's sliders are made from it,
    // ValueSlider::forProperty): a colour row for a colour map, a scalar one otherwise, naming the
    // slot; a row per slot, one slot per row.
    void everySlotHasItsFactorRow_data()
    {
        QTest::addColumn<int>("slot");
        for (MapSlot slot : kAllMapSlots)
            QTest::newRow(toString(slot)) << int(slot);
    }
    void everySlotHasItsFactorRow()
    {
        QFETCH(int, slot);
        const std::optional<MaterialProperty> property = factorPropertyOf(MapSlot(slot));
        QVERIFY(property);
        const MaterialPropertyInfo& info = infoOf(*property);
        QVERIFY(info.slot == MapSlot(slot));
        QCOMPARE(info.value == PropertyValue::Color, isColorSlot(MapSlot(slot)));
        const double sliderEnd = info.sliderMaximum > 0.0 ? info.sliderMaximum : info.maximum;
        QVERIFY(sliderEnd > info.minimum && sliderEnd <= info.maximum);
        // A normal map's slider spans the usual 0-2 of the format's 0-10 (issue 30).
        if (isNormalSlot(MapSlot(slot)))
            QCOMPARE(sliderEnd, 2.0);
    }
};

QTEST_GUILESS_MAIN(MaterialPropertiesTest)
#include "MaterialPropertiesTest.moc"
