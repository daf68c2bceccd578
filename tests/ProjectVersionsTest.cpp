// Project files as older Facets wrote them still open, and mean what they meant
// (docs/project-format.md, "Versioning"): tests/data/projects' version 1 and 2 files field for
// field, and version 4's clear coat, whose two factors became two maps' factors in version 5.

#include <optional>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest/QTest>

#include "TestSupport.h"
#include "core/project/Project.h"

using namespace facet;

namespace {
QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}

QByteArray readAll(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// A project file of `version` holding the one `material`.
QJsonObject fileOf(int version, const QJsonObject& material)
{
    return QJsonObject {{QLatin1String("format"), QLatin1String("facet-project")},
        {QLatin1String("version"), version}, {QLatin1String("materials"), QJsonArray {material}},
        {QLatin1String("currentMaterial"), 0}};
}
// The project of a `version` file holding `material`: where `problem` is given, the file is
// refused with a message containing it (and *project stays empty); else it loads without a warning.
void loadOneMaterial(
    int version, const QJsonObject& material, const QString& problem, std::optional<Project>* project)
{
    std::string error, warning;
    *project = Project::fromJson(fileOf(version, material), {}, &error, &warning);
    if (!problem.isEmpty()) {
        QVERIFY(!*project);
        QVERIFY2(QString::fromStdString(error).contains(problem), error.c_str());
        return;
    }
    QVERIFY2(*project, error.c_str());
    QVERIFY2(warning.empty(), warning.c_str());
}
} // namespace

class ProjectVersionsTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    // Files as older Facets wrote them (tests/data/projects: every field, keys in Qt's order)
    // still open: version 1 with one "material", version 2 with "materials" and "parts". Neither
    // has "compare": they open with the default layout for what they hold (the grid starts with
    // the file's environment, B is a snapshot of the current material), and save as the current
    // version, their materials without a coat.
    void olderVersionsOpen_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("materialCount");
        QTest::addColumn<int>("current");
        QTest::addColumn<QString>("currentName");
        QTest::addColumn<double>("currentRoughness");
        QTest::addColumn<int>("partCount");
        QTest::newRow("version 1") << "version1.json" << 1 << 0 << "Old" << 0.25 << 0;
        QTest::newRow("version 2") << "version2.json" << 2 << 1 << "Visor" << 0.75 << 2;
    }
    void olderVersionsOpen()
    {
        QFETCH(QString, file);
        QFETCH(int, materialCount);
        QFETCH(int, current);
        QFETCH(QString, currentName);
        QFETCH(double, currentRoughness);
        QFETCH(int, partCount);
        const QString path = test::sourceDir() + QStringLiteral("/tests/data/projects/") + file;
        std::string error;
        std::string warning;
        const auto project = Project::load(path.toStdString(), &error, &warning);
        QVERIFY2(project, error.c_str());
        QVERIFY2(warning.empty(), warning.c_str());
        QCOMPARE(int(project->materials.size()), materialCount);
        QCOMPARE(project->currentMaterial, current);
        QCOMPARE(qs(project->material().name), currentName);
        QCOMPARE(project->material().roughness(), currentRoughness);
        QCOMPARE(int(project->parts.size()), partCount);
        QCOMPARE(project->environment.source, std::string("sky"));
        QCOMPARE(project->environment.rotationDegrees, 30.0);
        QCOMPARE(project->view.exposureEV, 0.5);
        QCOMPARE(project->lights.size(), std::size_t(1));

        // The default layout for what the file holds.
        QVERIFY(project->compare == CompareLayout::defaultFor(*project));
        QCOMPARE(project->compare.mode, CompareMode::Single);
        QCOMPARE(project->compare.environments.cells.size(), std::size_t(3));
        QCOMPARE(project->compare.environments.cells[0].source, std::string("sky"));
        QCOMPARE(project->compare.environments.cells[1].source, std::string("studio"));
        QCOMPARE(project->compare.environments.cells[2].source, std::string("uniform:1"));
        QVERIFY(project->compare.ab.snapshot == project->material());

        QVERIFY(!project->material().hasClearcoat());
        QVERIFY(!project->material().hasSheen());
        // Saved again, it is a current-version file that reads back the same.
        const QJsonObject saved = project->toJson();
        QCOMPARE(saved.value(QLatin1String("version")).toInt(), Project::kFormatVersion);
        QVERIFY(saved.contains(QLatin1String("compare")) && !saved.contains(QLatin1String("material")));
        const auto again = Project::fromJson(saved, {}, &error);
        QVERIFY2(again, error.c_str());
        QVERIFY(*again == *project);

        // The version 2 file is what a version 2 Facet wrote: the version 3 writer's object
        // without "compare", field for field (so no field of it was left to a default).
        if (file == QLatin1String("version2.json")) {
            QJsonObject v2 = saved;
            v2.remove(QLatin1String("compare"));
            v2[QLatin1String("version")] = 2;
            // Optional fields added since, without a version (docs/project-format.md): "unlit",
            // the view's "keepUnits" and "texelDensityTarget"; the coat's maps (versions 4, 5) and
            // the sheen's (version 6), the specular layer's (version 7), the anisotropy's (version 8)
            // and the film's (version 9).
            QJsonObject view = v2[QLatin1String("view")].toObject();
            view.remove(QLatin1String("keepUnits"));
            view.remove(QLatin1String("texelDensityTarget"));
            v2[QLatin1String("view")] = view;
            QJsonArray materials = v2[QLatin1String("materials")].toArray();
            for (QJsonValueRef each : materials) {
                QJsonObject m = each.toObject();
                m.remove(QLatin1String("unlit"));
                for (const char* key : {"clearcoat", "clearcoatRoughness", "clearcoatNormal", "sheenColor",
                         "sheenRoughness", "specular", "specularColor", "anisotropy", "anisotropyRotationDegrees",
                         "iridescence", "iridescenceThickness", "iridescenceIor", "iridescenceThicknessMinimum"})
                    m.remove(QLatin1String(key));
                each = m;
            }
            v2[QLatin1String("materials")] = materials;
            QJsonObject onDisk = QJsonDocument::fromJson(readAll(path)).object();
            onDisk.remove(QLatin1String("generator"));
            v2.remove(QLatin1String("generator"));
            QCOMPARE(v2, onDisk);
        }
    }

    // Version 4 kept the coat's factors together, {"factor", "roughness"}; version 5 made them the
    // factors of the coat's maps. A version 4 file reads them without a warning and saves as
    // version 5's maps; a version 5 file with the old object is read the same way (a hand edit).
    void version4ClearcoatReads_data()
    {
        QTest::addColumn<int>("version");
        QTest::addColumn<QByteArray>("clearcoat"); // the material's "clearcoat" value
        QTest::addColumn<double>("strength");
        QTest::addColumn<double>("roughness");
        QTest::addColumn<QString>("problem"); // part of the refusal, or empty
        QTest::newRow("version 4 coat")
            << 4 << QByteArray(R"({"factor": 0.75, "roughness": 0.125})") << 0.75 << 0.125 << QString();
        QTest::newRow("version 4 coat, factor alone")
            << 4 << QByteArray(R"({"factor": 0.5})") << 0.5 << 0.0 << QString();
        QTest::newRow("version 5 coat map")
            << 5 << QByteArray(R"({"factor": 0.25, "channel": "g"})") << 0.25 << 0.0 << QString();
        QTest::newRow("version 4 coat out of range")
            << 4 << QByteArray(R"({"factor": 1.5, "roughness": 0.1})") << 0.0 << 0.0
            << QStringLiteral("materials[0].clearcoat.factor: 1.5 is outside [0, 1]");
        QTest::newRow("version 4 coat roughness a string")
            << 4 << QByteArray(R"({"factor": 1, "roughness": "soft"})") << 0.0 << 0.0
            << QStringLiteral("materials[0].clearcoat.roughness");
    }
    void version4ClearcoatReads()
    {
        QFETCH(int, version);
        QFETCH(QByteArray, clearcoat);
        QFETCH(double, strength);
        QFETCH(double, roughness);
        QFETCH(QString, problem);
        const QJsonObject material {{QLatin1String("name"), QLatin1String("Lacquer")},
            {QLatin1String("clearcoat"), QJsonDocument::fromJson(clearcoat).object()}};
        std::string error, warning;
        const auto project = Project::fromJson(fileOf(version, material), {}, &error, &warning);
        if (!problem.isEmpty()) {
            QVERIFY(!project);
            QVERIFY2(qs(error).contains(problem), error.c_str());
            return;
        }
        QVERIFY2(project, error.c_str());
        QVERIFY2(warning.empty(), warning.c_str());
        QCOMPARE(project->material().clearcoat(), strength);
        QCOMPARE(project->material().clearcoatRoughness(), roughness);
        // Saved, the factors are the maps' (the old object is gone), and read back the same.
        const QJsonObject saved = project->toJson();
        const QJsonObject m = saved[QLatin1String("materials")].toArray().at(0).toObject();
        QCOMPARE(m[QLatin1String("clearcoat")].toObject()[QLatin1String("factor")].toDouble(), strength);
        QVERIFY(!m[QLatin1String("clearcoat")].toObject().contains(QLatin1String("roughness")));
        QCOMPARE(
            m[QLatin1String("clearcoatRoughness")].toObject()[QLatin1String("factor")].toDouble(), roughness);
        const auto again = Project::fromJson(saved, {}, &error);
        QVERIFY2(again, error.c_str());
        QVERIFY(*again == *project);
    }

    // Version 6: the sheen's two maps; version 7: the specular layer's two. They read and save
    // back; a file of the version before has neither (its material reads the default: no sheen,
    // the core's specular layer); values out of range, of the wrong type or channel are refused
    // naming the field. `fields` holds the material's keys for the lobe's maps.
    void lobeMaps_data()
    {
        QTest::addColumn<int>("version");
        QTest::addColumn<QString>("lobe"); // "sheen" or "specular"
        QTest::addColumn<QByteArray>("fields");
        QTest::addColumn<QString>("problem"); // part of the refusal, or empty
        const auto row
            = [](const char* name, int version, const char* lobe, const char* fields, const char* problem) {
                  QTest::newRow(name) << version << QString::fromLatin1(lobe) << QByteArray(fields)
                                      << QString::fromLatin1(problem);
              };
        row("version 6 sheen", 6, "sheen",
            R"({"sheenColor": {"factor": [0.8, 0.2, 0.4]}, "sheenRoughness": {"factor": 0.5}})", "");
        row("version 6 sheen maps", 6, "sheen",
            R"({"sheenColor": {"factor": [1, 1, 1], "texture": "/t/velvet.png"},
                "sheenRoughness": {"factor": 1, "texture": "/t/velvet.png", "channel": "a"}})",
            "");
        row("version 5, no sheen", 5, "sheen", "{}", "");
        row("sheen colour above 1", 6, "sheen", R"({"sheenColor": {"factor": [1.5, 0, 0]}})",
            "materials[0].sheenColor.factor.r: 1.5 is outside [0, 1]");
        row("sheen roughness negative", 6, "sheen", R"({"sheenRoughness": {"factor": -0.5}})",
            "materials[0].sheenRoughness.factor: -0.5 is outside [0, 1]");
        row("sheen colour a string", 6, "sheen", R"({"sheenColor": {"factor": "white"}})",
            "materials[0].sheenColor.factor");
        row("sheen colour reads one channel", 6, "sheen",
            R"({"sheenColor": {"factor": [1, 1, 1], "channel": "r"}})",
            "sheenColor.channel: the sheenColor map reads \"rgb\"");
        row("sheen roughness reads rgb", 6, "sheen", R"({"sheenRoughness": {"factor": 1, "channel": "rgb"}})",
            "sheenRoughness.channel");
        row("version 7 specular", 7, "specular",
            R"({"specular": {"factor": 0.5}, "specularColor": {"factor": [2.5, 1, 0.25]}})", "");
        row("version 7 specular maps", 7, "specular",
            R"({"specular": {"factor": 1, "texture": "/t/tint.png", "channel": "a"},
                "specularColor": {"factor": [1, 1, 1], "texture": "/t/tint.png"}})",
            "");
        row("version 6, the default specular layer", 6, "specular", "{}", "");
        row("specular above 1", 7, "specular", R"({"specular": {"factor": 1.5}})",
            "materials[0].specular.factor: 1.5 is outside [0, 1]");
        row("specular colour above 100", 7, "specular", R"({"specularColor": {"factor": [1, 101, 1]}})",
            "materials[0].specularColor.factor.g: 101 is outside [0, 100]");
        row("specular colour reads one channel", 7, "specular",
            R"({"specularColor": {"factor": [1, 1, 1], "channel": "g"}})",
            "specularColor.channel: the specularColor map reads \"rgb\"");
        row("specular a string", 7, "specular", R"({"specular": {"factor": "shiny"}})",
            "materials[0].specular.factor");
    }
    void lobeMaps()
    {
        QFETCH(int, version);
        QFETCH(QString, lobe);
        QFETCH(QByteArray, fields);
        QFETCH(QString, problem);
        QJsonObject material = QJsonDocument::fromJson(fields).object();
        material[QLatin1String("name")] = QLatin1String("Layered");
        std::optional<Project> project;
        loadOneMaterial(version, material, problem, &project);
        if (QTest::currentTestFailed() || !project)
            return;
        const Material& m = project->material();
        const bool written = material.size() > 1;
        const QString colorKey = lobe + QLatin1String("Color");
        QCOMPARE(lobe == QLatin1String("sheen") ? m.hasSheen() : m.hasSpecular(), written);
        if (written) {
            const QJsonArray factor = material[colorKey].toObject()[QLatin1String("factor")].toArray();
            const glm::dvec3 color = lobe == QLatin1String("sheen") ? m.sheenColor() : m.specularColor();
            for (int c = 0; c < 3; ++c)
                QCOMPARE(color[c], factor.at(c).toDouble());
        }
        std::string error;
        const auto again = Project::fromJson(project->toJson(), {}, &error);
        QVERIFY2(again, error.c_str());
        QVERIFY(*again == *project);
    }

    // Version 8: the anisotropy's map and the material's rotation in degrees. They read and save
    // back; a version 7 file has neither (isotropic); values out of range, of the wrong type or
    // channel are refused naming the field.
    void anisotropy_data()
    {
        QTest::addColumn<int>("version");
        QTest::addColumn<QByteArray>("fields");
        QTest::addColumn<double>("strength");
        QTest::addColumn<double>("degrees");
        QTest::addColumn<QString>("problem"); // part of the refusal, or empty
        const auto row = [](const char* name, int version, const char* fields, double strength, double degrees,
                             const char* problem) {
            QTest::newRow(name) << version << QByteArray(fields) << strength << degrees << QString::fromLatin1(problem);
        };
        row("version 8 anisotropy", 8, R"({"anisotropy": {"factor": 0.6}, "anisotropyRotationDegrees": 30})", 0.6,
            30.0, "");
        row("version 8 anisotropy map", 8, R"({"anisotropy": {"factor": 1, "texture": "/t/brushed.png"}})", 1.0,
            0.0, "");
        row("version 7, isotropic", 7, "{}", 0.0, 0.0, "");
        row("strength above 1", 8, R"({"anisotropy": {"factor": 1.5}})", 0.0, 0.0,
            "materials[0].anisotropy.factor: 1.5 is outside [0, 1]");
        row("rotation beyond half a turn", 8, R"({"anisotropyRotationDegrees": 200})", 0.0, 0.0,
            "materials[0].anisotropyRotationDegrees: 200 is outside [-180, 180]");
        row("rotation a string", 8, R"({"anisotropyRotationDegrees": "left"})", 0.0, 0.0,
            "materials[0].anisotropyRotationDegrees");
        row("the map reads one channel", 8, R"({"anisotropy": {"factor": 1, "channel": "b"}})", 0.0, 0.0,
            "anisotropy.channel: the anisotropy map reads \"rgb\"");
    }
    void anisotropy()
    {
        QFETCH(int, version);
        QFETCH(QByteArray, fields);
        QFETCH(double, strength);
        QFETCH(double, degrees);
        QFETCH(QString, problem);
        QJsonObject material = QJsonDocument::fromJson(fields).object();
        material[QLatin1String("name")] = QLatin1String("Brushed");
        std::optional<Project> project;
        loadOneMaterial(version, material, problem, &project);
        if (QTest::currentTestFailed() || !project)
            return;
        const Material& m = project->material();
        QCOMPARE(m.anisotropy(), strength);
        QCOMPARE(m.anisotropyRotationDegrees, degrees);
        QCOMPARE(m.hasAnisotropy(), strength > 0.0);
        std::string error;
        const auto again = Project::fromJson(project->toJson(), {}, &error);
        QVERIFY2(again, error.c_str());
        QVERIFY(*again == *project);
    }

    // Version 9: the film's maps and the material's index and minimum thickness. They read and
    // save back; a version 8 file has none (no film); values out of range, of the wrong type or
    // channel are refused naming the field.
    void iridescence_data()
    {
        QTest::addColumn<int>("version");
        QTest::addColumn<QByteArray>("fields");
        QTest::addColumn<double>("strength");
        QTest::addColumn<double>("ior");
        QTest::addColumn<double>("minimum");
        QTest::addColumn<double>("maximum");
        QTest::addColumn<QString>("problem"); // part of the refusal, or empty
        const auto row = [](const char* name, int version, const char* fields, double strength, double ior,
                             double minimum, double maximum, const char* problem) {
            QTest::newRow(name) << version << QByteArray(fields) << strength << ior << minimum << maximum
                                << QString::fromLatin1(problem);
        };
        row("version 9 film", 9, R"({"iridescence": {"factor": 0.8}, "iridescenceIor": 1.8,
            "iridescenceThicknessMinimum": 250, "iridescenceThickness": {"factor": 650}})",
            0.8, 1.8, 250.0, 650.0, "");
        row("version 9 film maps", 9, R"({"iridescence": {"factor": 1, "texture": "/t/film.png"},
            "iridescenceThickness": {"factor": 500, "texture": "/t/film.png"}})",
            1.0, 1.3, 100.0, 500.0, "");
        row("version 8, no film", 8, "{}", 0.0, 1.3, 100.0, 400.0, "");
        row("strength above 1", 9, R"({"iridescence": {"factor": 1.5}})", 0.0, 0.0, 0.0, 0.0,
            "materials[0].iridescence.factor: 1.5 is outside [0, 1]");
        row("index below 1", 9, R"({"iridescenceIor": 0.5})", 0.0, 0.0, 0.0, 0.0,
            "materials[0].iridescenceIor: 0.5 is outside [1, 5]");
        row("negative minimum", 9, R"({"iridescenceThicknessMinimum": -1})", 0.0, 0.0, 0.0, 0.0,
            "materials[0].iridescenceThicknessMinimum: -1 is outside [0, 100000]");
        row("thickness a string", 9, R"({"iridescenceThickness": {"factor": "thin"}})", 0.0, 0.0, 0.0, 0.0,
            "materials[0].iridescenceThickness.factor");
        row("the thickness map reads one channel", 9, R"({"iridescenceThickness": {"factor": 400, "channel": "rgb"}})",
            0.0, 0.0, 0.0, 0.0, "iridescenceThickness.channel: a iridescenceThickness map reads one channel");
    }
    void iridescence()
    {
        QFETCH(int, version);
        QFETCH(QByteArray, fields);
        QFETCH(double, strength);
        QFETCH(double, ior);
        QFETCH(double, minimum);
        QFETCH(double, maximum);
        QFETCH(QString, problem);
        QJsonObject material = QJsonDocument::fromJson(fields).object();
        material[QLatin1String("name")] = QLatin1String("Film");
        std::optional<Project> project;
        loadOneMaterial(version, material, problem, &project);
        if (QTest::currentTestFailed() || !project)
            return;
        const Material& m = project->material();
        QCOMPARE(m.iridescence(), strength);
        QCOMPARE(m.iridescenceIor, ior);
        QCOMPARE(m.iridescenceThicknessMinimum, minimum);
        QCOMPARE(m.iridescenceThicknessMaximum(), maximum);
        QCOMPARE(m.hasIridescence(), strength > 0.0);
        std::string error;
        const auto again = Project::fromJson(project->toJson(), {}, &error);
        QVERIFY2(again, error.c_str());
        QVERIFY(*again == *project);
    }
};

QTEST_GUILESS_MAIN(ProjectVersionsTest)
#include "ProjectVersionsTest.moc"
