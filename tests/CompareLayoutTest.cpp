// The compare layout of project format version 3 (core/project/CompareLayout.h): every mode's JSON round
// trip (a table of layouts), every refusal with its JSON path, unknown keys warned about, missing
// keys defaulted, the defaults themselves, and the operations the window and `facet sheet` use:
// per-cell environment, camera and exposure, linking and unlinking cameras, promoting a cell,
// wedge cells, swapping A and B, and keeping B's material index right when materials are removed.

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonParseError>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include "TestSupport.h"
#include "core/gltf/GltfImport.h"
#include "core/material/MaterialPresets.h"
#include "core/project/AssetProject.h"
#include "core/project/CompareLayout.h"
#include "core/project/Project.h"

using namespace facet;

namespace {
bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

// A project of three materials ("A", "B", "C"; A current) in the sky environment.
Project threeMaterials()
{
    Project p = Project::defaultProject();
    p.environment.source = "sky";
    p.environment.rotationDegrees = 30.0;
    p.view.exposureEV = 1.0;
    p.material().name = "A";
    for (const char* name : {"B", "C"}) {
        Material m = p.material();
        m.name = name;
        p.materials.push_back(m);
    }
    p.materials[1].setFactor(MapSlot::Roughness, 0.8);
    p.materials[2].setFactor(MapSlot::Metallic, 1.0);
    p.compare = CompareLayout::defaultFor(p);
    return p;
}

// The JSON object of a version 3 project with `compare` (a JSON object's text) as its compare
// layout and three materials.
QJsonObject projectWithCompare(const QByteArray& compare)
{
    const QByteArray text = R"({"format": "facet-project", "version": 3,
        "materials": [{"name": "A"}, {"name": "B"}, {"name": "C"}], "compare": )"
        + compare + "}";
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(text, &error);
    if (error.error != QJsonParseError::NoError)
        qWarning("bad test JSON: %s in %s", qPrintable(error.errorString()), text.constData());
    return document.object();
}

Camera orbitedCamera(double x)
{
    Camera camera;
    camera.position = {x, 1.0, 2.0};
    camera.verticalFovDegrees = 30.0;
    return camera;
}
} // namespace

Q_DECLARE_METATYPE(facet::CompareLayout)

class CompareLayoutTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void names()
    {
        for (const char* name : {"single", "environments", "ab", "wedge"})
            QCOMPARE(toString(*compareModeFromString(name)), name);
        for (const char* name : {"material", "snapshot", "preset"})
            QCOMPARE(toString(*bSourceFromString(name)), name);
        for (const char* name : {"split", "side-by-side"})
            QCOMPARE(toString(*abLayoutFromString(name)), name);
        QVERIFY(
            !compareModeFromString("grid") && !bSourceFromString("file") && !abLayoutFromString("stacked"));
    }

    // The grid starts with the project's environment, then the built-in ones that are not it.
    void defaultCells_data()
    {
        QTest::addColumn<QString>("current");
        QTest::addColumn<QStringList>("expected");
        QTest::newRow("studio") << "studio" << test::strings({"studio", "sky", "uniform:1"});
        QTest::newRow("sky") << "sky" << test::strings({"sky", "studio", "uniform:1"});
        QTest::newRow("uniform:1") << "uniform:1" << test::strings({"uniform:1", "studio", "sky"});
        QTest::newRow("a file") << "/data/hdri/night.exr"
                                << test::strings({"/data/hdri/night.exr", "studio", "sky", "uniform:1"});
        QTest::newRow("another uniform")
            << "uniform:0.5" << test::strings({"uniform:0.5", "studio", "sky", "uniform:1"});
    }
    void defaultCells()
    {
        QFETCH(QString, current);
        QFETCH(QStringList, expected);
        const std::vector<EnvironmentCell> cells = EnvironmentGrid::defaultCells(current.toStdString());
        QCOMPARE(cells.size(), std::size_t(expected.size()));
        for (std::size_t i = 0; i < cells.size(); ++i) {
            QCOMPARE(QString::fromStdString(cells[i].source), expected[qsizetype(i)]);
            // The rest of each cell is EnvironmentCell's default: following all, linked.
            EnvironmentCell plain;
            plain.source = cells[i].source;
            QVERIFY(cells[i] == plain);
        }
    }

    void defaults()
    {
        const CompareLayout layout;
        QCOMPARE(layout.mode, CompareMode::Single);
        QCOMPARE(layout.environments.cells.size(), std::size_t(3));
        QVERIFY(layout.environments.linkedCameras);
        QCOMPARE(layout.ab.source, BSource::Snapshot);
        QCOMPARE(layout.ab.split, 0.5);
        QCOMPARE(layout.ab.layout, ABLayout::Split);
        QCOMPARE(layout.wedge.rows.toString(), std::string("roughness=0,0.25,0.5,0.75,1"));
        QVERIFY(layout.wedge.columns);
        QCOMPARE(layout.wedge.columns->toString(), std::string("metallic=0,1"));
        QCOMPARE(layout.wedge.rowCount() * layout.wedge.columnCount(), std::size_t(10));
        std::string problem;
        QVERIFY2(layout.validate(1, &problem), problem.c_str());

        // A default project's layout is the default for it; Project {}'s is CompareLayout {}.
        QVERIFY(CompareLayout::defaultFor(Project {}) == CompareLayout {});
        const Project fresh = Project::defaultProject();
        QVERIFY(fresh.compare == CompareLayout::defaultFor(fresh));
        QVERIFY(fresh.compare.ab.snapshot == fresh.material());
        // defaultFor must not trust currentMaterial: it runs on a file before validation.
        Project broken;
        broken.currentMaterial = 7;
        QVERIFY(CompareLayout::defaultFor(broken).ab.snapshot == Material {});
    }

    // Version 3 round-trips exactly, through JSON with and without a project folder and through a
    // file, for a table of layouts: each mode, each feature alone, and all together.
    void roundTrip_data()
    {
        QTest::addColumn<CompareLayout>("layout");
        const Project base = threeMaterials();
        const CompareLayout plain = base.compare;
        QTest::newRow("default") << plain;
        for (CompareMode mode :
            {CompareMode::Environments, CompareMode::AB, CompareMode::Wedge, CompareMode::Error}) {
            CompareLayout l = plain;
            l.mode = mode;
            QTest::newRow((std::string("mode ") + toString(mode)).c_str()) << l;
        }
        CompareLayout l = plain;
        l.environments.cells.resize(2);
        QTest::newRow("two cells, the fewest") << l;
        l = plain;
        l.environments.cells.resize(9);
        for (std::size_t i = 0; i < 9; ++i)
            l.environments.cells[i].source = i % 2 ? "uniform:" + std::to_string(i) : "sky";
        QTest::newRow("nine cells, the most") << l;
        l = plain;
        l.environments.cells[1].rotationFollowsAll = false;
        l.environments.cells[1].rotationDegrees = -135.25;
        QTest::newRow("a cell's own rotation") << l;
        l = plain;
        l.environments.cells[2].exposureFollowsAll = false;
        l.environments.cells[2].exposureOffsetEV = 20.0;
        QTest::newRow("a cell's own exposure") << l;
        l = plain;
        l.environments.cells[0].rotationDegrees = 12.0; // kept while following all
        l.environments.cells[0].exposureOffsetEV = -3.0;
        QTest::newRow("own values kept while following all") << l;
        l = plain;
        l.environments.unlinkCamera(1, orbitedCamera(2.0));
        QTest::newRow("an unlinked camera") << l;
        l = plain;
        l.environments.setLinkedCameras(false, orbitedCamera(-1.0));
        QTest::newRow("the grid's cameras unlinked") << l;
        l = plain;
        l.environments.cells.emplace_back().source = "library:somewhere-else/loft.exr";
        QTest::newRow("a library this computer lacks") << l;
        l = plain;
        l.ab.source = BSource::Material;
        l.ab.material = 2;
        QTest::newRow("B another material") << l;
        l = plain;
        l.ab.snapshot = base.materials[1];
        l.ab.snapshot.name = "Before the edit";
        l.ab.snapshot.map(MapSlot::BaseColor).path = "/textures/albedo.png";
        l.ab.snapshot.map(MapSlot::Roughness).path = "/textures/orm.png";
        QTest::newRow("B a snapshot with textures") << l;
        l = plain;
        l.ab.source = BSource::Preset;
        l.ab.preset = "copper";
        QTest::newRow("B a preset") << l;
        l = plain;
        l.ab.split = 0.0;
        l.ab.layout = ABLayout::SideBySide;
        QTest::newRow("split 0, side by side") << l;
        l = plain;
        l.ab.split = 1.0;
        QTest::newRow("split 1") << l;
        l = plain;
        l.wedge.columns.reset();
        QTest::newRow("a wedge of one axis") << l;
        l = plain;
        l.wedge.rows = *WedgeAxis::parse("env=studio,uniform:1,0.5,0.25,/data/hdri/night.exr", nullptr);
        l.wedge.columns = *WedgeAxis::parse("exposure=-1,0,+1.5", nullptr);
        QTest::newRow("env x exposure") << l;
        l = plain;
        l.wedge.rows
            = *WedgeAxis::parse("ior=1,1.1,1.2,1.3,1.4,1.5,1.6,1.7,1.8,1.9,2,2.1,2.2,2.3,2.4,5", nullptr);
        l.wedge.columns
            = *WedgeAxis::parse("normal=0,0.1,0.2,0.3,0.4,0.5,0.6,0.7,0.8,0.9,1,2,3,4,5,10", nullptr);
        QTest::newRow("16 x 16, the most") << l;
        l = plain;
        l.wedge.rows = *WedgeAxis::parse("alpha=0.1", nullptr);
        l.wedge.columns = *WedgeAxis::parse("emissiveStrength=0.1,1e-05", nullptr);
        QTest::newRow("numbers that need all their digits") << l;
        l.mode = CompareMode::AB;
        l.environments.cells[1].rotationFollowsAll = false;
        l.environments.cells[1].rotationDegrees = 90.0;
        l.environments.unlinkCamera(2, orbitedCamera(3.0));
        l.ab.source = BSource::Material;
        l.ab.material = 1;
        l.ab.preset = "gold";
        l.ab.snapshot.name = "Kept";
        l.ab.split = 0.3;
        QTest::newRow("everything at once") << l;
        l = plain;
        l.mode = CompareMode::Error;
        l.error.samples = 1;
        l.error.scale = ErrorCompare::kMinScale;
        l.error.showNoise = true;
        QTest::newRow("error view: the fewest samples, the smallest scale, noise") << l;
        l.error.samples = kMaxIblSamples;
        l.error.scale = ErrorCompare::kMaxScale;
        l.error.showNoise = false;
        QTest::newRow("error view: the most samples, the largest scale") << l;
        l.error.scale = 0.123456789;
        QTest::newRow("error view: a scale that needs all its digits") << l;
    }
    void roundTrip()
    {
        QFETCH(CompareLayout, layout);
        Project project = threeMaterials();
        project.compare = layout;
        std::string error;
        QVERIFY2(project.validate(&error), error.c_str());

        std::string warning;
        const std::optional<Project> inMemory = Project::fromJson(project.toJson(), {}, &error, &warning);
        QVERIFY2(inMemory, error.c_str());
        QVERIFY2(warning.empty(), warning.c_str());
        QVERIFY(inMemory->compare == layout);
        QVERIFY(*inMemory == project);

        // With a project folder (paths stored relative to it) and through a file.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string path = dir.filePath(QStringLiteral("compare.json")).toStdString();
        QVERIFY2(project.save(path, &error), error.c_str());
        const std::optional<Project> loaded = Project::load(path, &error, &warning);
        QVERIFY2(loaded, error.c_str());
        QVERIFY2(warning.empty(), warning.c_str());
        QVERIFY(loaded->compare == layout);

        // The layout on its own.
        const std::optional<CompareLayout> alone = CompareLayout::fromJson(
            layout.toJson(dir.path().toStdString()), dir.path().toStdString(), 3, &error);
        QVERIFY2(alone, error.c_str());
        QVERIFY(*alone == layout);
    }

    // Every way a compare section is refused, with the JSON path of the problem.
    void refusals_data()
    {
        QTest::addColumn<QByteArray>("compare");
        QTest::addColumn<QString>("expected");
        QTest::newRow("not an object") << QByteArray(R"([])") << "compare: expected an object, got an array";
        QTest::newRow("mode unknown")
            << QByteArray(R"({"mode": "grid"})")
            << R"(compare.mode: unknown name "grid" (expected one of "single", "environments", "ab", "wedge", "error"))";
        QTest::newRow("mode not a string")
            << QByteArray(R"({"mode": 1})") << "compare.mode: expected a string, got a number";
        QTest::newRow("environments not an object") << QByteArray(
            R"({"environments": []})") << "compare.environments: expected an object, got an array";
        QTest::newRow("linkedCameras not a boolean")
            << QByteArray(R"({"environments": {"linkedCameras": 1}})")
            << "compare.environments.linkedCameras: expected true or false, got a number";
        QTest::newRow("cells not an array") << QByteArray(R"({"environments": {"cells": {}}})")
                                            << "compare.environments.cells: expected an array, got an object";
        QTest::newRow("one cell") << QByteArray(R"({"environments": {"cells": [{}]}})")
                                  << "compare.environments.cells: 1 cell; a grid shows 2 to 9";
        QTest::newRow("ten cells") << QByteArray(
            R"({"environments": {"cells": [{}, {}, {}, {}, {}, {}, {}, {}, {}, {}]}})")
                                   << "compare.environments.cells: 10 cells; a grid shows 2 to 9";
        QTest::newRow("a cell not an object")
            << QByteArray(R"({"environments": {"cells": [{}, "sky"]}})")
            << "compare.environments.cells[1]: expected an object, got a string";
        QTest::newRow("a cell's source empty")
            << QByteArray(R"({"environments": {"cells": [{}, {"source": ""}]}})")
            << "compare.environments.cells[1].source: empty environment";
        QTest::newRow("a cell's source not a string")
            << QByteArray(R"({"environments": {"cells": [{"source": 3}, {}]}})")
            << "compare.environments.cells[0].source: expected a string, got a number";
        QTest::newRow("a cell's bad uniform")
            << QByteArray(R"({"environments": {"cells": [{"source": "uniform:x"}, {}]}})")
            << "compare.environments.cells[0].source: uniform:x: expected uniform:VALUE or uniform:R,G,B";
        QTest::newRow("a cell's exposure offset out of range")
            << QByteArray(R"({"environments": {"cells": [{}, {"exposureOffsetEV": 30}]}})")
            << "compare.environments.cells[1].exposureOffsetEV: 30 is outside [-20, 20]";
        QTest::newRow("a cell's flag not a boolean")
            << QByteArray(R"({"environments": {"cells": [{}, {"rotationFollowsAll": "no"}]}})")
            << "compare.environments.cells[1].rotationFollowsAll: expected true or false, got a string";
        QTest::newRow("a cell's camera")
            << QByteArray(R"({"environments": {"cells": [{}, {"camera": {"nearPlane": 0}}]}})")
            << "compare.environments.cells[1].camera.nearPlane: must be > 0";
        QTest::newRow("a cell's camera, wrong length")
            << QByteArray(R"({"environments": {"cells": [{}, {"camera": {"position": [1, 2]}}]}})")
            << "compare.environments.cells[1].camera.position: expected an array of 3 numbers, got 2";
        QTest::newRow("ab not an object")
            << QByteArray(R"({"ab": 1})") << "compare.ab: expected an object, got a number";
        QTest::newRow("B's source unknown")
            << QByteArray(R"({"ab": {"source": "file"}})")
            << R"(compare.ab.source: unknown name "file" (expected one of "material", "snapshot", "preset"))";
        QTest::newRow("B's material past the end")
            << QByteArray(R"({"ab": {"source": "material", "material": 3}})")
            << "compare.ab.material: 3 is not a material (there are 3)";
        QTest::newRow("B's material negative, whatever the source") << QByteArray(
            R"({"ab": {"material": -1}})") << "compare.ab.material: -1 is not a material (there are 3)";
        QTest::newRow("B's material a fraction") << QByteArray(R"({"ab": {"material": 1.5}})")
                                                 << "compare.ab.material: expected an integer, got 1.5";
        QTest::newRow("snapshot not an object") << QByteArray(R"({"ab": {"snapshot": []}})")
                                                << "compare.ab.snapshot: expected an object, got an array";
        QTest::newRow("snapshot out of range")
            << QByteArray(R"({"ab": {"snapshot": {"roughness": {"factor": 2}}}})")
            << "compare.ab.snapshot.roughness.factor: 2 is outside [0, 1]";
        QTest::newRow("snapshot with a bad name")
            << QByteArray(R"({"ab": {"snapshot": {"shading": {"fresnel": "exact"}}}})")
            << R"(compare.ab.snapshot.shading.fresnel: unknown name "exact")";
        QTest::newRow("unknown preset")
            << QByteArray(R"({"ab": {"preset": "unobtainium"}})")
            << R"(compare.ab.preset: unknown preset "unobtainium" (the built-in presets: water, plastic-low,)";
        QTest::newRow("source preset without one")
            << QByteArray(R"({"ab": {"source": "preset"}})")
            << R"(compare.ab.preset: must name a built-in preset when the source is "preset" (one of: water,)";
        QTest::newRow("split above 1")
            << QByteArray(R"({"ab": {"split": 1.5}})") << "compare.ab.split: 1.5 is outside [0, 1]";
        QTest::newRow("split below 0")
            << QByteArray(R"({"ab": {"split": -0.25}})") << "compare.ab.split: -0.25 is outside [0, 1]";
        QTest::newRow("layout unknown")
            << QByteArray(R"({"ab": {"layout": "stacked"}})")
            << R"(compare.ab.layout: unknown name "stacked" (expected one of "split", "side-by-side"))";
        QTest::newRow("wedge not an object")
            << QByteArray(R"({"wedge": "roughness"})") << "compare.wedge: expected an object, got a string";
        QTest::newRow("rows null") << QByteArray(R"({"wedge": {"rows": null}})")
                                   << "compare.wedge.rows: expected an object, got null";
        QTest::newRow("columns a number")
            << QByteArray(R"({"wedge": {"columns": 2}})")
            << "compare.wedge.columns: expected an object or null, got a number";
        QTest::newRow("axis without parameter")
            << QByteArray(R"({"wedge": {"rows": {"values": [0, 1]}}})")
            << R"(compare.wedge.rows.parameter: missing (an axis needs "parameter" and "values"))";
        QTest::newRow("axis without values")
            << QByteArray(R"({"wedge": {"columns": {"parameter": "metallic"}}})")
            << R"(compare.wedge.columns.values: missing (an axis needs "parameter" and "values"))";
        QTest::newRow("axis parameter unknown")
            << QByteArray(R"({"wedge": {"rows": {"parameter": "shininess", "values": [1]}}})")
            << R"(compare.wedge.rows.parameter: unknown name "shininess" (expected one of "metallic", "roughness",)";
        QTest::newRow("axis values not an array")
            << QByteArray(R"({"wedge": {"rows": {"parameter": "roughness", "values": 0.5}}})")
            << "compare.wedge.rows.values: expected an array, got a number";
        QTest::newRow("a number axis with a string")
            << QByteArray(R"({"wedge": {"rows": {"parameter": "roughness", "values": [0, "0.5"]}}})")
            << "compare.wedge.rows.values[1]: expected a number, got a string";
        QTest::newRow("an env axis with a number")
            << QByteArray(R"({"wedge": {"columns": {"parameter": "env", "values": [1]}}})")
            << "compare.wedge.columns.values[0]: expected a string, got a number";
        QTest::newRow("axis value out of range")
            << QByteArray(R"({"wedge": {"rows": {"parameter": "roughness", "values": [0, 0.5, 1.5]}}})")
            << "compare.wedge.rows.values[2]: roughness.factor: 1.5 is outside [0, 1]";
        QTest::newRow("exposure axis out of range")
            << QByteArray(R"({"wedge": {"columns": {"parameter": "exposure", "values": [-21]}}})")
            << "compare.wedge.columns.values[0]: exposureEV: -21 is outside [-20, 20]";
        QTest::newRow("env axis, an empty spec")
            << QByteArray(R"({"wedge": {"columns": {"parameter": "env", "values": ["sky", ""]}}})")
            << "compare.wedge.columns.values[1]: empty environment";
        QTest::newRow("axis without values")
            << QByteArray(R"({"wedge": {"rows": {"parameter": "roughness", "values": []}}})")
            << "compare.wedge.rows.values: needs at least one value";
        QTest::newRow("error not an object")
            << QByteArray(R"({"error": 1024})") << "compare.error: expected an object, got a number";
        QTest::newRow("error samples 0")
            << QByteArray(R"({"error": {"samples": 0}})") << "compare.error.samples: 0 is outside [1, 65536]";
        QTest::newRow("error samples too many") << QByteArray(R"({"error": {"samples": 65537}})")
                                                << "compare.error.samples: 65537 is outside [1, 65536]";
        QTest::newRow("error samples a fraction")
            << QByteArray(R"({"error": {"samples": 2.5}})") << "compare.error.samples: expected an integer";
        QTest::newRow("error scale 0")
            << QByteArray(R"({"error": {"scale": 0}})") << "compare.error.scale: 0 is outside [0.001, 10]";
        QTest::newRow("error scale above 10")
            << QByteArray(R"({"error": {"scale": 11}})") << "compare.error.scale: 11 is outside [0.001, 10]";
        QTest::newRow("error showNoise not a boolean") << QByteArray(R"({"error": {"showNoise": "yes"}})")
                                                       << "compare.error.showNoise: expected true or false";
        QTest::newRow("axis of 17 values") << QByteArray(
            R"({"wedge": {"columns": {"parameter": "metallic", "values": [0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,1]}}})")
                                           << "compare.wedge.columns.values: 17 values, more than the 16 an "
                                              "axis holds";
    }
    void refusals()
    {
        QFETCH(QByteArray, compare);
        QFETCH(QString, expected);
        const QJsonObject object = projectWithCompare(compare);
        QVERIFY(!object.isEmpty());
        std::string error;
        QVERIFY(!Project::fromJson(object, {}, &error));
        QVERIFY2(error.rfind("Project::fromJson: " + expected.toStdString(), 0) == 0, error.c_str());

        // CompareLayout::fromJson gives the same message, with its own name.
        const QJsonValue value = object.value(QLatin1String("compare"));
        if (value.isObject()) {
            QVERIFY(!CompareLayout::fromJson(value.toObject(), {}, 3, &error));
            QVERIFY2(
                error.rfind("CompareLayout::fromJson: " + expected.toStdString(), 0) == 0, error.c_str());
        }
    }

    // A layout made in code is held to the same rules: validate() names the field, and a project
    // holding it is not saved.
    void validateInCode()
    {
        Project p = threeMaterials();
        std::string problem;
        p.compare.ab.material = 3;
        QVERIFY(!p.validate(&problem));
        QCOMPARE(problem, std::string("compare.ab.material: 3 is not a material (there are 3)"));
        QTemporaryDir dir;
        const std::string path = dir.filePath(QStringLiteral("p.json")).toStdString();
        QVERIFY(!p.save(path, &problem));
        QVERIFY2(
            contains(problem, "not saved, the project is invalid: compare.ab.material"), problem.c_str());
        p = threeMaterials();
        p.compare.environments.cells[2].rotationDegrees = std::numeric_limits<double>::infinity();
        QVERIFY(!p.validate(&problem));
        QCOMPARE(problem, std::string("compare.environments.cells[2].rotationDegrees: must be finite"));
        p = threeMaterials();
        p.compare.wedge.columns->environments = {"sky"};
        QVERIFY(!p.validate(&problem));
        QCOMPARE(problem,
            std::string(
                "compare.wedge.columns.values: the metallic axis holds numbers, not environment specs"));
    }

    void unknownKeysAreWarnedAbout()
    {
        const QJsonObject object = projectWithCompare(R"({"zoom": 2,
            "environments": {"rows": 2, "cells": [{"label": "x"}, {"camera": {"fov": 1}}]},
            "ab": {"swap": true, "snapshot": {"rougness": {}}},
            "wedge": {"cellSize": 3, "rows": {"parameter": "roughness", "values": [0, 1], "unit": "x"}}})");
        std::string error;
        std::string warning;
        const std::optional<Project> p = Project::fromJson(object, {}, &error, &warning);
        QVERIFY2(p, error.c_str());
        for (const char* key :
            {"compare.zoom", "compare.environments.rows", "compare.environments.cells[0].label",
                "compare.environments.cells[1].camera.fov", "compare.ab.swap", "compare.ab.snapshot.rougness",
                "compare.wedge.cellSize", "compare.wedge.rows.unit"})
            QVERIFY2(contains(warning, std::string("Project::fromJson: ") + key + ": unknown key, ignored"),
                (key + std::string(" in: ") + warning).c_str());
        // What was known was read.
        QCOMPARE(p->compare.wedge.rows.values, std::vector<double>({0.0, 1.0}));
    }

    // Keys a compare section lacks take the default for the project: an empty section is
    // defaultFor(project); "columns": null is a one-axis wedge.
    void missingKeysTakeDefaults()
    {
        std::string error;
        QJsonObject object = projectWithCompare("{}");
        object[QLatin1String("environment")] = QJsonObject {{QLatin1String("source"), QLatin1String("sky")}};
        object[QLatin1String("currentMaterial")] = 2;
        std::optional<Project> p = Project::fromJson(object, {}, &error);
        QVERIFY2(p, error.c_str());
        QVERIFY(p->compare == CompareLayout::defaultFor(*p));
        QCOMPARE(p->compare.environments.cells[0].source, std::string("sky"));
        QCOMPARE(p->compare.ab.snapshot.name, std::string("C"));

        object[QLatin1String("compare")]
            = QJsonDocument::fromJson(R"({"mode": "wedge", "environments": {"linkedCameras": false},
                "ab": {"split": 0.75}, "wedge": {"columns": null}})")
                  .object();
        p = Project::fromJson(object, {}, &error);
        QVERIFY2(p, error.c_str());
        CompareLayout expected = CompareLayout::defaultFor(*p);
        expected.mode = CompareMode::Wedge;
        expected.environments.linkedCameras = false;
        expected.ab.split = 0.75;
        expected.wedge.columns.reset();
        QVERIFY(p->compare == expected);
        QCOMPARE(p->compare.wedge.columnCount(), std::size_t(1));
        // Written back, "columns" is null, and it reads back the same.
        const QJsonObject written = p->toJson().value(QLatin1String("compare")).toObject();
        QVERIFY(written.value(QLatin1String("wedge")).toObject().value(QLatin1String("columns")).isNull());
        QVERIFY(Project::fromJson(p->toJson(), {}, &error) == p);
    }

    // What each cell shows: the project's environment with the cell's source, rotation and
    // exposure following all or its own; the shared camera or its own.
    void cellViews_data()
    {
        QTest::addColumn<bool>("rotationFollowsAll");
        QTest::addColumn<bool>("exposureFollowsAll");
        QTest::addColumn<bool>("cameraLinked");
        QTest::addColumn<bool>("gridLinked");
        QTest::addColumn<double>("rotation");
        QTest::addColumn<double>("exposure");
        QTest::addColumn<bool>("sharedCamera");
        QTest::newRow("all followed") << true << true << true << true << 30.0 << 1.0 << true;
        QTest::newRow("own rotation") << false << true << true << true << -90.0 << 1.0 << true;
        QTest::newRow("own exposure") << true << false << true << true << 30.0 << -1.5 << true;
        QTest::newRow("own camera") << true << true << false << true << 30.0 << 1.0 << false;
        QTest::newRow("grid unlinked") << true << true << true << false << 30.0 << 1.0 << false;
        QTest::newRow("all its own") << false << false << false << false << -90.0 << -1.5 << false;
    }
    void cellViews()
    {
        QFETCH(bool, rotationFollowsAll);
        QFETCH(bool, exposureFollowsAll);
        QFETCH(bool, cameraLinked);
        QFETCH(bool, gridLinked);
        QFETCH(double, rotation);
        QFETCH(double, exposure);
        QFETCH(bool, sharedCamera);
        Project p = threeMaterials(); // sky, rotated 30 degrees, exposure +1
        p.environment.intensity = 0.5;
        p.environment.quality = IblQuality::High;
        EnvironmentGrid& grid = p.compare.environments;
        EnvironmentCell& cell = grid.cells[1];
        cell.rotationFollowsAll = rotationFollowsAll;
        cell.rotationDegrees = -90.0;
        cell.exposureFollowsAll = exposureFollowsAll;
        cell.exposureOffsetEV = -2.5;
        cell.cameraLinked = cameraLinked;
        cell.camera = orbitedCamera(5.0);
        grid.linkedCameras = gridLinked;

        const EnvironmentSettings environment = grid.environmentOf(1, p);
        QCOMPARE(environment.source, std::string("studio"));
        QCOMPARE(environment.rotationDegrees, rotation);
        QCOMPARE(environment.intensity, 0.5);
        QCOMPARE(environment.quality, IblQuality::High);
        QCOMPARE(grid.exposureEVOf(1, p), exposure);
        QCOMPARE(grid.isLinked(1), sharedCamera);
        QVERIFY(grid.cameraOf(1, p) == (sharedCamera ? p.camera : orbitedCamera(5.0)));
        // Cell 0 follows everything: the project's own view.
        QCOMPARE(grid.environmentOf(0, p).source, std::string("sky"));
        QCOMPARE(grid.environmentOf(0, p).rotationDegrees, 30.0);
        QCOMPARE(grid.exposureEVOf(0, p), 1.0);
    }

    void linkingCameras()
    {
        Project p = threeMaterials();
        EnvironmentGrid& grid = p.compare.environments;
        const Camera shared = orbitedCamera(1.0);
        // Unlinking a cell starts its camera where the shared one is.
        grid.unlinkCamera(1, shared);
        QVERIFY(!grid.isLinked(1) && grid.cells[1].camera == shared);
        // Orbiting it alone leaves the others; unlinking again keeps its own camera.
        grid.cells[1].camera = orbitedCamera(2.0);
        grid.unlinkCamera(1, shared);
        QVERIFY(grid.cells[1].camera == orbitedCamera(2.0));
        // Unlinking the grid starts every linked cell from the shared camera, not the unlinked one.
        grid.setLinkedCameras(false, orbitedCamera(3.0));
        QVERIFY(!grid.linkedCameras);
        QVERIFY(grid.cells[0].camera == orbitedCamera(3.0) && grid.cells[2].camera == orbitedCamera(3.0));
        QVERIFY(grid.cells[1].camera == orbitedCamera(2.0));
        QVERIFY(grid.cells[0].cameraLinked); // kept for linking the grid again
        grid.setLinkedCameras(true, orbitedCamera(4.0));
        QVERIFY(grid.isLinked(0) && !grid.isLinked(1) && grid.isLinked(2));
        QVERIFY(grid.cameraOf(0, p) == p.camera);
    }

    void promotingACell()
    {
        Project p = threeMaterials();
        p.compare.mode = CompareMode::Environments;
        EnvironmentCell& cell = p.compare.environments.cells[1]; // studio
        cell.rotationFollowsAll = false;
        cell.rotationDegrees = 75.0;
        cell.exposureFollowsAll = false;
        cell.exposureOffsetEV = -0.5;
        p.compare.environments.unlinkCamera(1, orbitedCamera(2.0));
        const Project before = p;
        promoteCell(p, 1);
        QCOMPARE(p.compare.mode, CompareMode::Single);
        QCOMPARE(p.environment.source, std::string("studio"));
        QCOMPARE(p.environment.rotationDegrees, 75.0);
        QCOMPARE(p.environment.intensity, before.environment.intensity);
        QCOMPARE(p.view.exposureEV, 0.5);
        QVERIFY(p.camera == orbitedCamera(2.0));
        QVERIFY(p.materials == before.materials);
        std::string problem;
        QVERIFY2(p.validate(&problem), problem.c_str());

        // A sum beyond the view's range is clamped to it, so the project stays valid.
        p = before;
        p.view.exposureEV = 15.0;
        p.compare.environments.cells[1].exposureOffsetEV = 10.0;
        promoteCell(p, 1);
        QCOMPARE(p.view.exposureEV, 20.0);
        QVERIFY2(p.validate(&problem), problem.c_str());
    }

    void wedgeCells()
    {
        const Project p = threeMaterials();
        const WedgeLayout& wedge = p.compare.wedge; // roughness 0..1 x metallic 0, 1
        QCOMPARE(wedge.rowCount(), std::size_t(5));
        QCOMPARE(wedge.columnCount(), std::size_t(2));
        for (std::size_t row = 0; row < 5; ++row)
            for (std::size_t column = 0; column < 2; ++column) {
                const Project cell = wedge.cellProject(p, row, column);
                QCOMPARE(cell.material().roughness(), 0.25 * double(row));
                QCOMPARE(cell.material().metallic(), double(column));
                QVERIFY(cell.materials[1] == p.materials[1] && cell.materials[2] == p.materials[2]);
            }
        WedgeLayout one;
        one.columns.reset();
        one.rows = *WedgeAxis::parse("env=studio,sky", nullptr);
        QCOMPARE(one.columnCount(), std::size_t(1));
        QCOMPARE(one.cellProject(p, 1, 0).environment.source, std::string("sky"));
        QVERIFY(one.cellProject(p, 1, 0).material() == p.material());
    }

    // Swap A and B for each source of B; swapping twice gives back the project.
    void swapping_data()
    {
        QTest::addColumn<int>("source");
        QTest::newRow("material") << int(BSource::Material);
        QTest::newRow("snapshot") << int(BSource::Snapshot);
        QTest::newRow("preset") << int(BSource::Preset);
    }
    void swapping()
    {
        QFETCH(int, source);
        Project p = threeMaterials();
        ABCompare& ab = p.compare.ab;
        ab.source = BSource(source);
        ab.material = 2;
        ab.snapshot = p.materials[1];
        ab.snapshot.name = "Snapshot";
        ab.preset = "gold";
        const Project before = p;
        const Material a = before.material();
        const Material b = ab.materialB(before);
        QCOMPARE(b.name,
            std::string(source == int(BSource::Material) ? "C"
                    : source == int(BSource::Snapshot)   ? "Snapshot"
                                                         : "Gold"));
        swapAB(p);
        QVERIFY(p.material() == b);
        QVERIFY(p.compare.ab.materialB(p) == a);
        std::string problem;
        QVERIFY2(p.validate(&problem), problem.c_str());
        if (source == int(BSource::Material)) {
            QCOMPARE(p.currentMaterial, 2);
            QCOMPARE(p.compare.ab.material, 0);
            QVERIFY(p.materials == before.materials); // only the indices moved
        }
        if (source == int(BSource::Preset)) // B is now what A was, kept as a snapshot
            QCOMPARE(p.compare.ab.source, BSource::Snapshot);
        swapAB(p);
        QVERIFY(p.material() == a);
        if (source != int(BSource::Preset))
            QVERIFY(p == before);
    }

    // Removing a material keeps B on the material it showed; B showing the removed one becomes
    // a snapshot of it. Inserting one (undoing a removal) moves the index back.
    void removingMaterials_data()
    {
        QTest::addColumn<int>("source");
        QTest::addColumn<int>("b");
        QTest::addColumn<int>("removed");
        QTest::addColumn<int>("expectedSource");
        QTest::addColumn<int>("expectedB");
        const int m = int(BSource::Material);
        const int s = int(BSource::Snapshot);
        const int p = int(BSource::Preset);
        QTest::newRow("B after the removed one moves down") << m << 2 << 0 << m << 1;
        QTest::newRow("B before the removed one stays") << m << 0 << 1 << m << 0;
        QTest::newRow("B's own material removed: a snapshot of it") << m << 1 << 1 << s << 0;
        QTest::newRow("B's last material removed") << m << 2 << 2 << s << 0;
        QTest::newRow("a snapshot B: only the kept index moves") << s << 2 << 1 << s << 1;
        QTest::newRow("a snapshot B whose index is removed stays a snapshot") << s << 1 << 1 << s << 0;
        QTest::newRow("a preset B whose index is removed stays a preset") << p << 1 << 1 << p << 0;
    }
    void removingMaterials()
    {
        QFETCH(int, source);
        QFETCH(int, b);
        QFETCH(int, removed);
        QFETCH(int, expectedSource);
        QFETCH(int, expectedB);
        Project p = threeMaterials();
        p.compare.ab.source = BSource(source);
        p.compare.ab.material = b;
        p.compare.ab.preset = "silver";
        p.compare.ab.snapshot.name = "Old snapshot";
        const Project before = p;
        const Material shown = p.compare.ab.materialB(p);

        const Material gone = p.materials[std::size_t(removed)];
        p.materials.erase(p.materials.begin() + removed);
        p.currentMaterial = 0;
        p.compare.removeMaterial(removed, gone);
        QCOMPARE(int(p.compare.ab.source), expectedSource);
        QCOMPARE(p.compare.ab.material, expectedB);
        std::string problem;
        QVERIFY2(p.validate(&problem), problem.c_str());
        // B shows what it showed (the same material, wherever it now is).
        QVERIFY(p.compare.ab.materialB(p) == shown);

        // Putting the material back moves the kept index back (a snapshot made of B stays one:
        // the undo command restores the layout it saved).
        p.materials.insert(p.materials.begin() + removed, gone);
        p.compare.insertMaterial(removed);
        if (expectedSource == source)
            QCOMPARE(p.compare.ab.material, b == removed ? (removed == 0 ? 1 : 0) : b);
        QVERIFY2(p.validate(&problem), problem.c_str());
        QVERIFY(p.compare.ab.materialB(p) == shown);
    }

    // An asset's materials replacing the project's (File > Import, withAsset): B that showed one
    // of them keeps showing it, as a snapshot, and the project stays valid.
    void assetsReplacingTheMaterials_data()
    {
        QTest::addColumn<int>("source");
        QTest::addColumn<int>("b");
        QTest::addColumn<int>("expectedSource");
        QTest::newRow("B a material") << int(BSource::Material) << 2 << int(BSource::Snapshot);
        QTest::newRow("B a snapshot") << int(BSource::Snapshot) << 2 << int(BSource::Snapshot);
        QTest::newRow("B a preset") << int(BSource::Preset) << 1 << int(BSource::Preset);
    }
    void assetsReplacingTheMaterials()
    {
        QFETCH(int, source);
        QFETCH(int, b);
        QFETCH(int, expectedSource);
        Project p = threeMaterials();
        p.compare.ab.source = BSource(source);
        p.compare.ab.material = b;
        p.compare.ab.preset = "iron";
        const Material shown = p.compare.ab.materialB(p);
        GltfAsset asset;
        asset.materials.emplace_back().name = "Asset's only material";
        const Project imported = withAsset(p, asset, "/assets/thing.glb");
        std::string problem;
        QVERIFY2(imported.validate(&problem), problem.c_str());
        QCOMPARE(int(imported.compare.ab.source), expectedSource);
        QCOMPARE(imported.compare.ab.material, 0);
        QVERIFY(imported.compare.ab.materialB(imported) == shown);
        // The rest of the layout stays.
        QVERIFY(imported.compare.environments == p.compare.environments
            && imported.compare.wedge == p.compare.wedge);
    }
};

QTEST_GUILESS_MAIN(CompareLayoutTest)
#include "CompareLayoutTest.moc"
