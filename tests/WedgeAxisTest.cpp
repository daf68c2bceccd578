// Wedge axes (core/project/WedgeAxis.h): every parameter parsed from the command line's form and applied
// to a project, every parse error's message, the range table held to Material's and
// ViewSettings's validation, labels, the text round trip, validation and the no-effect notes.

#include <cmath>
#include <limits>

#include <QtTest/QTest>

#include "TestSupport.h"
#include "core/project/Project.h"
#include "core/project/WedgeAxis.h"

using namespace facet;

namespace {
bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

// The value the axis' parameter has in `project`, read back independently of WedgeAxis.
double valueIn(const Project& project, WedgeParameter parameter)
{
    const Material& m = project.material();
    switch (parameter) {
    case WedgeParameter::Metallic:
        return m.map(MapSlot::Metallic).factor.x;
    case WedgeParameter::Roughness:
        return m.map(MapSlot::Roughness).factor.x;
    case WedgeParameter::Occlusion:
        return m.map(MapSlot::Occlusion).factor.x;
    case WedgeParameter::Normal:
        return m.map(MapSlot::Normal).factor.x;
    case WedgeParameter::Ior:
        return m.ior;
    case WedgeParameter::EmissiveStrength:
        return m.emissiveStrength;
    case WedgeParameter::AlphaCutoff:
        return m.alphaCutoff;
    case WedgeParameter::Alpha:
        return m.map(MapSlot::BaseColor).factor.w;
    case WedgeParameter::Clearcoat:
        return m.clearcoat();
    case WedgeParameter::ClearcoatRoughness:
        return m.clearcoatRoughness();
    case WedgeParameter::SheenRoughness:
        return m.sheenRoughness();
    case WedgeParameter::Specular:
        return m.specular();
    case WedgeParameter::Anisotropy:
        return m.anisotropy();
    case WedgeParameter::AnisotropyRotation:
        return m.anisotropyRotationDegrees;
    case WedgeParameter::Iridescence:
        return m.iridescence();
    case WedgeParameter::IridescenceIor:
        return m.iridescenceIor;
    case WedgeParameter::IridescenceThickness:
        return m.iridescenceThicknessMaximum();
    case WedgeParameter::Exposure:
        return project.view.exposureEV;
    case WedgeParameter::Environment:
        break;
    }
    return std::numeric_limits<double>::quiet_NaN();
}

// A project of two materials with the second one current, so that apply() can be seen to touch
// the current material and nothing else.
Project twoMaterials()
{
    Project p = Project::defaultProject();
    Material other = p.material();
    other.name = "Other";
    p.materials.push_back(other);
    p.currentMaterial = 1;
    return p;
}
} // namespace

class WedgeAxisTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void parameterNames()
    {
        QCOMPARE(wedgeParameterNameList(),
            std::string("metallic, roughness, occlusion, normal, ior, emissiveStrength, alphaCutoff, alpha, "
                        "clearcoat, "
                        "clearcoatRoughness, sheenRoughness, specular, anisotropy, anisotropyRotation, "
                        "iridescence, iridescenceIor, iridescenceThickness, env, exposure"));
        for (const WedgeParameterInfo& info : wedgeParameters()) {
            QCOMPARE(wedgeParameterFromString(info.name), std::optional(info.parameter));
            QCOMPARE(toString(info.parameter), info.name);
            QCOMPARE(&infoOf(info.parameter), &info);
        }
        QVERIFY(!wedgeParameterFromString("Roughness"));
        QVERIFY(!wedgeParameterFromString("roughnessFactor"));
    }

    // The range each numeric parameter advertises is exactly what validation accepts: both ends
    // pass, the next double beyond either end is refused, by WedgeAxis::validate and by the
    // project's own validate() after apply().
    void rangesAgreeWithProjectValidation_data()
    {
        QTest::addColumn<int>("parameter");
        QTest::addColumn<double>("minimum");
        QTest::addColumn<double>("maximum");
        QTest::newRow("metallic") << int(WedgeParameter::Metallic) << 0.0 << 1.0;
        QTest::newRow("roughness") << int(WedgeParameter::Roughness) << 0.0 << 1.0;
        QTest::newRow("occlusion") << int(WedgeParameter::Occlusion) << 0.0 << 1.0;
        QTest::newRow("normal") << int(WedgeParameter::Normal) << 0.0 << 10.0;
        QTest::newRow("ior") << int(WedgeParameter::Ior) << 1.0 << 5.0;
        QTest::newRow("emissiveStrength") << int(WedgeParameter::EmissiveStrength) << 0.0 << 10000.0;
        QTest::newRow("alphaCutoff") << int(WedgeParameter::AlphaCutoff) << 0.0 << 1.0;
        QTest::newRow("alpha") << int(WedgeParameter::Alpha) << 0.0 << 1.0;
        QTest::newRow("anisotropy") << int(WedgeParameter::Anisotropy) << 0.0 << 1.0;
        QTest::newRow("anisotropyRotation") << int(WedgeParameter::AnisotropyRotation) << -180.0 << 180.0;
        QTest::newRow("iridescence") << int(WedgeParameter::Iridescence) << 0.0 << 1.0;
        QTest::newRow("iridescenceIor") << int(WedgeParameter::IridescenceIor) << 1.0 << 5.0;
        QTest::newRow("iridescenceThickness") << int(WedgeParameter::IridescenceThickness) << 0.0 << 100000.0;
        QTest::newRow("exposure") << int(WedgeParameter::Exposure) << -20.0 << 20.0;
    }
    void rangesAgreeWithProjectValidation()
    {
        QFETCH(int, parameter);
        QFETCH(double, minimum);
        QFETCH(double, maximum);
        const WedgeParameterInfo& info = infoOf(WedgeParameter(parameter));
        QCOMPARE(info.minimum, minimum);
        QCOMPARE(info.maximum, maximum);
        const double below = std::nextafter(minimum, -1e9);
        const double above = std::nextafter(maximum, 1e9);
        const double nan = std::numeric_limits<double>::quiet_NaN();
        for (const auto& [value, valid] : {std::pair {minimum, true}, std::pair {maximum, true},
                 std::pair {below, false}, std::pair {above, false}, std::pair {nan, false}}) {
            const WedgeAxis axis {WedgeParameter(parameter), {value}, {}};
            std::string problem;
            QVERIFY2(axis.validate(&problem) == valid, problem.c_str());
            Project project = Project::defaultProject();
            axis.apply(0, project);
            QVERIFY2(project.validate(&problem) == valid, problem.c_str());
            if (!valid)
                QVERIFY2(contains(problem, info.field), problem.c_str());
        }
    }

    // Each parameter parsed from the command line's form, each value applied to the current
    // material (or the environment, or the view) and nothing else, and a cell's label.
    void parseAndApply_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<int>("parameter");
        QTest::addColumn<QList<double>>("values");
        QTest::addColumn<QStringList>("environments");
        QTest::addColumn<QString>("secondLabel");
        QTest::addColumn<QString>("canonical");
        using W = WedgeParameter;
        const QStringList none;
        QTest::newRow("metallic") << "metallic=0,1" << int(W::Metallic) << QList<double> {0, 1} << none
                                  << "metallic 1"
                                  << "metallic=0,1";
        QTest::newRow("roughness") << "roughness=0,0.25,0.5,0.75,1" << int(W::Roughness)
                                   << QList<double> {0, 0.25, 0.5, 0.75, 1} << none << "roughness 0.25"
                                   << "roughness=0,0.25,0.5,0.75,1";
        QTest::newRow("occlusion") << "occlusion=0.5,1" << int(W::Occlusion) << QList<double> {0.5, 1} << none
                                   << "occlusion 1"
                                   << "occlusion=0.5,1";
        QTest::newRow("normal") << "normal=0,2.5,10" << int(W::Normal) << QList<double> {0, 2.5, 10} << none
                                << "normal 2.5"
                                << "normal=0,2.5,10";
        QTest::newRow("ior") << "ior=1,1.45,5" << int(W::Ior) << QList<double> {1, 1.45, 5} << none
                             << "ior 1.45"
                             << "ior=1,1.45,5";
        QTest::newRow("emissiveStrength") << "emissiveStrength=0,10,1e4" << int(W::EmissiveStrength)
                                          << QList<double> {0, 10, 10000} << none << "emissiveStrength 10"
                                          << "emissiveStrength=0,10,10000";
        QTest::newRow("alphaCutoff") << "alphaCutoff=0.1,0.9" << int(W::AlphaCutoff)
                                     << QList<double> {0.1, 0.9} << none << "alphaCutoff 0.9"
                                     << "alphaCutoff=0.1,0.9";
        QTest::newRow("alpha") << "alpha=0,0.5" << int(W::Alpha) << QList<double> {0, 0.5} << none
                               << "alpha 0.5"
                               << "alpha=0,0.5";
        QTest::newRow("exposure") << "exposure=-2,+1,0" << int(W::Exposure) << QList<double> {-2, 1, 0}
                                  << none << "exposure +1 EV"
                                  << "exposure=-2,1,0";
        QTest::newRow("env") << "env=studio,uniform:1,0.5,0.25,sky,library:installed/hdri/night.exr"
                             << int(W::Environment) << QList<double> {}
                             << QStringList {QStringLiteral("studio"), QStringLiteral("uniform:1,0.5,0.25"),
                                    QStringLiteral("sky"), QStringLiteral("library:installed/hdri/night.exr")}
                             << "env uniform:1,0.5,0.25"
                             << "env=studio,uniform:1,0.5,0.25,sky,library:installed/hdri/night.exr";
        QTest::newRow("env, a single uniform value before a number-like name")
            << "env=uniform:2,sky" << int(W::Environment) << QList<double> {}
            << QStringList {QStringLiteral("uniform:2"), QStringLiteral("sky")} << "env sky"
            << "env=uniform:2,sky";
        QTest::newRow("spaces around names and values")
            << " roughness = 0 , 1 " << int(W::Roughness) << QList<double> {0, 1} << none << "roughness 1"
            << "roughness=0,1";
        QTest::newRow("one value") << "metallic=0.5" << int(W::Metallic) << QList<double> {0.5} << none
                                   << QString() << "metallic=0.5";
        QTest::newRow("sixteen values, the most")
            << "roughness=0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,1" << int(W::Roughness)
            << QList<double> {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1} << none << "roughness 0"
            << "roughness=0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,1";
    }
    void parseAndApply()
    {
        QFETCH(QString, text);
        QFETCH(int, parameter);
        QFETCH(QList<double>, values);
        QFETCH(QStringList, environments);
        QFETCH(QString, secondLabel);
        QFETCH(QString, canonical);
        std::string error;
        const std::optional<WedgeAxis> axis = WedgeAxis::parse(text.toStdString(), &error);
        QVERIFY2(axis, error.c_str());
        QCOMPARE(int(axis->parameter), parameter);
        QCOMPARE(axis->values, std::vector<double>(values.begin(), values.end()));
        std::vector<std::string> specs;
        for (const QString& spec : environments)
            specs.push_back(spec.toStdString());
        QCOMPARE(axis->environments, specs);
        QCOMPARE(axis->size(), std::size_t(std::max(values.size(), environments.size())));
        QVERIFY2(axis->validate(&error), error.c_str());
        if (axis->size() > 1)
            QCOMPARE(QString::fromStdString(axis->label(1)), secondLabel);

        // toString is parse's inverse.
        QCOMPARE(QString::fromStdString(axis->toString()), canonical);
        QCOMPARE(WedgeAxis::parse(axis->toString(), &error), axis);

        // Each value lands where the axis says and nowhere else: the other material, and every
        // other part of the project, stay as they were.
        const Project original = twoMaterials();
        for (std::size_t i = 0; i < axis->size(); ++i) {
            Project p = original;
            axis->apply(i, p);
            if (axis->isEnvironment())
                QCOMPARE(p.environment.source, specs[i]);
            else
                QCOMPARE(valueIn(p, axis->parameter), values[qsizetype(i)]);
            QVERIFY(p.materials[0] == original.materials[0]);
            Project rest = p;
            rest.material() = original.material();
            rest.environment.source = original.environment.source;
            rest.view.exposureEV = original.view.exposureEV;
            QVERIFY(rest == original);
            std::string problem;
            QVERIFY2(p.validate(&problem), problem.c_str());
        }
    }

    // Every kind of bad text, with the message that names the problem.
    void parseErrors_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("expected");
        QTest::newRow("no =") << "roughness"
                              << "expected PARAMETER=V1,V2,... (e.g. roughness=0,0.5,1)";
        QTest::newRow("unknown parameter")
            << "rough=0,1"
            << "unknown parameter \"rough\" (known: metallic, roughness, occlusion, normal, ior, "
               "emissiveStrength, alphaCutoff, alpha, clearcoat, clearcoatRoughness, sheenRoughness, "
               "specular, anisotropy, anisotropyRotation, iridescence, iridescenceIor, iridescenceThickness, env, "
               "exposure)";
        QTest::newRow("names are case-sensitive") << "Roughness=0,1"
                                                  << "unknown parameter \"Roughness\"";
        QTest::newRow("no name") << "=0,1"
                                 << "unknown parameter \"\"";
        QTest::newRow("no values") << "roughness="
                                   << "roughness: no values (expected roughness=V1,V2,...)";
        QTest::newRow("only spaces") << "metallic=  "
                                     << "metallic: no values";
        QTest::newRow("empty value") << "roughness=0,,1"
                                     << "roughness: value 2 is empty";
        QTest::newRow("trailing comma") << "roughness=0,1,"
                                        << "roughness: value 3 is empty";
        QTest::newRow("not a number") << "roughness=0,abc"
                                      << "roughness: value 2, \"abc\", is not a number";
        QTest::newRow("trailing junk") << "roughness=0.5x"
                                       << "value 1, \"0.5x\", is not a number";
        QTest::newRow("two numbers") << "roughness=0 1"
                                     << "value 1, \"0 1\", is not a number";
        QTest::newRow("hex") << "roughness=0x1"
                             << "value 1, \"0x1\", is not a number";
        QTest::newRow("double sign") << "exposure=+-1"
                                     << "value 1, \"+-1\", is not a number";
        QTest::newRow("metallic below") << "metallic=-0.5"
                                        << "metallic: value 1: metallic.factor: -0.5 is outside [0, 1]";
        QTest::newRow("roughness above") << "roughness=0,1.5"
                                         << "roughness: value 2: roughness.factor: 1.5 is outside [0, 1]";
        QTest::newRow("occlusion above") << "occlusion=1.01"
                                         << "occlusion.factor: 1.01 is outside [0, 1]";
        QTest::newRow("normal above") << "normal=0,11"
                                      << "value 2: normal.factor: 11 is outside [0, 10]";
        QTest::newRow("ior below") << "ior=0.5"
                                   << "ior: value 1: ior: 0.5 is outside [1, 5]";
        QTest::newRow("emissiveStrength above") << "emissiveStrength=20000"
                                                << "emissiveStrength: 20000 is outside [0, 10000]";
        QTest::newRow("alphaCutoff below") << "alphaCutoff=-0.1"
                                           << "alphaCutoff: -0.1 is outside [0, 1]";
        QTest::newRow("alpha above") << "alpha=2"
                                     << "alpha: value 1: baseColor.factor.a: 2 is outside [0, 1]";
        QTest::newRow("exposure above") << "exposure=21"
                                        << "exposure: value 1: exposureEV: 21 is outside [-20, 20]";
        QTest::newRow("not finite") << "roughness=nan"
                                    << "roughness.factor: nan is outside [0, 1]";
        QTest::newRow("infinite") << "exposure=-inf"
                                  << "exposureEV: -inf is outside [-20, 20]";
        QTest::newRow("seventeen values") << "roughness=0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,1"
                                          << "roughness: 17 values, more than the 16 an axis holds";
        QTest::newRow("env: empty value") << "env=studio,,sky"
                                          << "env: value 2 is empty";
        QTest::newRow("env: bad uniform") << "env=studio,uniform:-1"
                                          << "env: value 2: uniform:-1: expected uniform:VALUE or "
                                             "uniform:R,G,B with finite non-negative numbers";
        QTest::newRow("env: uniform with two numbers")
            << "env=uniform:1,2"
            << "env: value 2, \"2\", is a number, not an environment (uniform:R,G,B takes three numbers; a "
               "file of that name is ./2)";
        QTest::newRow("env: seventeen")
            << "env=sky,sky,sky,sky,sky,sky,sky,sky,sky,sky,sky,sky,sky,sky,sky,sky,sky"
            << "env: 17 values, more than the 16";
    }
    void parseErrors()
    {
        QFETCH(QString, text);
        QFETCH(QString, expected);
        std::string error;
        QVERIFY(!WedgeAxis::parse(text.toStdString(), &error));
        QVERIFY2(error.rfind("WedgeAxis::parse: \"" + text.toStdString() + "\": ", 0) == 0, error.c_str());
        QVERIFY2(contains(error, expected.toStdString()), error.c_str());
        QVERIFY(!WedgeAxis::parse(text.toStdString(), nullptr)); // no message wanted: no crash
    }

    // validate() of axes made in code (the window's, a file's), naming the field.
    void validateRefusals_data()
    {
        QTest::addColumn<int>("parameter");
        QTest::addColumn<QList<double>>("values");
        QTest::addColumn<QStringList>("environments");
        QTest::addColumn<QString>("expected");
        using W = WedgeParameter;
        QTest::newRow("no values") << int(W::Roughness) << QList<double> {} << QStringList {}
                                   << "values: needs at least one value";
        QTest::newRow("no environments") << int(W::Environment) << QList<double> {} << QStringList {}
                                         << "values: needs at least one value";
        QList<double> seventeen(17, 0.5);
        QTest::newRow("seventeen") << int(W::Metallic) << seventeen << QStringList {}
                                   << "values: 17 values, more than the 16 an axis holds";
        QTest::newRow("a bad value, by index")
            << int(W::Roughness) << QList<double> {0, 0.5, 1.5} << QStringList {}
            << "values[2]: roughness.factor: 1.5 is outside [0, 1]";
        QTest::newRow("an empty environment")
            << int(W::Environment) << QList<double> {} << QStringList {QStringLiteral("sky"), QString()}
            << "values[1]: empty environment";
        QTest::newRow("numbers on an env axis")
            << int(W::Environment) << QList<double> {1} << QStringList {QStringLiteral("sky")}
            << "values: the env axis holds environment specs, not numbers";
        QTest::newRow("specs on a number axis")
            << int(W::Exposure) << QList<double> {1} << QStringList {QStringLiteral("sky")}
            << "values: the exposure axis holds numbers, not environment specs";
    }
    void validateRefusals()
    {
        QFETCH(int, parameter);
        QFETCH(QList<double>, values);
        QFETCH(QStringList, environments);
        QFETCH(QString, expected);
        WedgeAxis axis {WedgeParameter(parameter), std::vector<double>(values.begin(), values.end()), {}};
        for (const QString& spec : environments)
            axis.environments.push_back(spec.toStdString());
        std::string problem;
        QVERIFY(!axis.validate(&problem));
        QVERIFY2(problem.rfind(expected.toStdString(), 0) == 0, problem.c_str());
    }

    void labels_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QStringList>("expected");
        QTest::newRow("numbers, shortest")
            << "roughness=0,0.1,1e-05,0.333"
            << test::strings({"roughness 0", "roughness 0.1", "roughness 1e-05", "roughness 0.333"});
        QTest::newRow("exposure, signed in EV")
            << "exposure=-2.5,0,1" << test::strings({"exposure -2.5 EV", "exposure 0 EV", "exposure +1 EV"});
        QTest::newRow("env: names as they are, files by base name")
            << "env=studio,uniform:0.5,/data/hdri/night.exr,library:installed/hdri/park.exr,./studio"
            << test::strings({"env studio", "env uniform:0.5", "env night", "env park", "env studio"});
    }
    void labels()
    {
        QFETCH(QString, text);
        QFETCH(QStringList, expected);
        std::string error;
        const std::optional<WedgeAxis> axis = WedgeAxis::parse(text.toStdString(), &error);
        QVERIFY2(axis, error.c_str());
        QCOMPARE(axis->size(), std::size_t(expected.size()));
        for (std::size_t i = 0; i < axis->size(); ++i)
            QCOMPARE(QString::fromStdString(axis->label(i)), expected[qsizetype(i)]);
    }

    void defaults()
    {
        QCOMPARE(WedgeAxis::defaultRows().toString(), std::string("roughness=0,0.25,0.5,0.75,1"));
        QCOMPARE(WedgeAxis::defaultColumns().toString(), std::string("metallic=0,1"));
        std::string problem;
        QVERIFY2(WedgeAxis::defaultRows().validate(&problem), problem.c_str());
        QVERIFY2(WedgeAxis::defaultColumns().validate(&problem), problem.c_str());
    }

    // An axis that changes nothing in the project says why; one that does says nothing.
    void noEffectReason_data()
    {
        QTest::addColumn<QString>("axis");
        QTest::addColumn<QString>("setup");
        QTest::addColumn<QString>("expected");
        QTest::newRow("alphaCutoff, opaque") << "alphaCutoff=0.2,0.8"
                                             << ""
                                             << "alphaMode \"mask\"";
        QTest::newRow("alphaCutoff, mask") << "alphaCutoff=0.2,0.8"
                                           << "mask"
                                           << "";
        QTest::newRow("alpha, opaque") << "alpha=0,1"
                                       << ""
                                       << "alphaMode \"opaque\"";
        QTest::newRow("alpha, blend") << "alpha=0,1"
                                      << "blend"
                                      << "";
        QTest::newRow("emissiveStrength, black") << "emissiveStrength=1,10"
                                                 << ""
                                                 << "black";
        QTest::newRow("emissiveStrength, glowing") << "emissiveStrength=1,10"
                                                   << "emissive"
                                                   << "";
        QTest::newRow("normal, no map") << "normal=0,1"
                                        << ""
                                        << "has none";
        QTest::newRow("normal, a map") << "normal=0,1"
                                       << "maps"
                                       << "";
        QTest::newRow("occlusion, no map") << "occlusion=0,1"
                                           << ""
                                           << "has none";
        QTest::newRow("occlusion, a map") << "occlusion=0,1"
                                          << "maps"
                                          << "";
        QTest::newRow("ior, a metal") << "ior=1.3,1.7"
                                      << "metal"
                                      << "metal";
        QTest::newRow("ior, a dielectric") << "ior=1.3,1.7"
                                           << ""
                                           << "";
        QTest::newRow("roughness") << "roughness=0,1"
                                   << ""
                                   << "";
        QTest::newRow("clearcoat, none") << "clearcoat=0,1"
                                         << ""
                                         << "";
        QTest::newRow("clearcoatRoughness, no coat") << "clearcoatRoughness=0,1"
                                                     << ""
                                                     << "has none (clearcoat 0)";
        QTest::newRow("clearcoatRoughness, coated") << "clearcoatRoughness=0,1"
                                                    << "coat"
                                                    << "";
        QTest::newRow("sheenRoughness, no sheen") << "sheenRoughness=0,1"
                                                  << ""
                                                  << "has none (sheenColor black)";
        QTest::newRow("sheenRoughness, a sheen") << "sheenRoughness=0,1"
                                                 << "sheen"
                                                 << "";
        QTest::newRow("specular, a metal") << "specular=0,1"
                                           << "metal"
                                           << "and the material is a metal (metallic 1)";
        QTest::newRow("specular, a dielectric") << "specular=0,1"
                                                << ""
                                                << "";
        QTest::newRow("anisotropy, isotropic") << "anisotropy=0,1"
                                               << ""
                                               << "";
        QTest::newRow("anisotropyRotation, isotropic") << "anisotropyRotation=0,90"
                                                       << ""
                                                       << "has none (anisotropy 0)";
        QTest::newRow("anisotropyRotation, brushed") << "anisotropyRotation=0,90"
                                                     << "brushed"
                                                     << "";
        QTest::newRow("iridescenceThickness, no film") << "iridescenceThickness=100,400"
                                                       << ""
                                                       << "has none (iridescence 0)";
        QTest::newRow("iridescenceIor, no film") << "iridescenceIor=1.3,2"
                                                 << ""
                                                 << "has none (iridescence 0)";
        QTest::newRow("iridescenceThickness, a film") << "iridescenceThickness=100,400"
                                                      << "film"
                                                      << "";
        QTest::newRow("env") << "env=studio,sky"
                             << ""
                             << "";
        QTest::newRow("exposure") << "exposure=0,1"
                                  << ""
                                  << "";
    }
    void noEffectReason()
    {
        QFETCH(QString, axis);
        QFETCH(QString, setup);
        QFETCH(QString, expected);
        Project p = twoMaterials();
        Material& m = p.material();
        if (setup == QLatin1String("mask"))
            m.alphaMode = AlphaMode::Mask;
        if (setup == QLatin1String("blend"))
            m.alphaMode = AlphaMode::Blend;
        if (setup == QLatin1String("emissive"))
            m.map(MapSlot::Emissive).factor = {0.0, 0.5, 0.0, 1.0};
        if (setup == QLatin1String("maps")) {
            m.map(MapSlot::Normal).path = "/textures/normal.png";
            m.map(MapSlot::Occlusion).path = "/textures/orm.png";
        }
        if (setup == QLatin1String("metal"))
            m.setFactor(MapSlot::Metallic, 1.0);
        if (setup == QLatin1String("coat"))
            m.setFactor(MapSlot::Clearcoat, 1.0);
        if (setup == QLatin1String("sheen"))
            m.setSheen(glm::dvec3(0.5), 0.0);
        if (setup == QLatin1String("brushed"))
            m.setAnisotropy(0.8, 0.0);
        if (setup == QLatin1String("film"))
            m.setFactor(MapSlot::Iridescence, 1.0);
        std::string error;
        const std::optional<WedgeAxis> parsed = WedgeAxis::parse(axis.toStdString(), &error);
        QVERIFY2(parsed, error.c_str());
        const std::string reason = parsed->noEffectReason(p);
        if (expected.isEmpty())
            QVERIFY2(reason.empty(), reason.c_str());
        else
            QVERIFY2(contains(reason, expected.toStdString()), reason.c_str());
    }
};

QTEST_GUILESS_MAIN(WedgeAxisTest)
#include "WedgeAxisTest.moc"
