// Loading project files that are not a clean round trip: the limits' good side, every kind of
// broken file giving a message that names the file and the field, what is not a regular file
// refused before it is opened, warnings for an empty texture and unknown keys, missing fields
// taking their defaults, and truncated or corrupted files never crashing the loader. The round
// trip itself: ProjectTest.

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonParseError>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include "ProjectTestSupport.h"
#include "TestSupport.h"
#include "core/project/Project.h"

#include <optional>
#include <string>

#include <sys/stat.h>

using namespace facet;
using facet::test::everythingChanged;
using facet::test::readAll;

namespace {
bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

bool writeAll(const QString& path, const QByteArray& data)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(data) == data.size();
}

// The valid minimal file the error cases start from, with `body` spliced in.
QByteArray minimalWith(const char* body)
{
    QByteArray text = R"({"format": "facet-project", "version": 1)";
    if (body[0] != '\0')
        text += ", " + QByteArray(body);
    return text + "}";
}
} // namespace

class ProjectLoadingTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    // The limits' good side: eight lights, a debug view by its older alias.
    void limitsAreInclusive()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("limits.json"));
        QVERIFY(writeAll(
            path, minimalWith(R"("lights": [{}, {}, {}, {}, {}, {}, {}, {}], "view": {"debugView": "d"})")));
        std::string error;
        const auto loaded = Project::load(path.toStdString(), &error);
        QVERIFY2(loaded, error.c_str());
        QCOMPARE(loaded->lights.size(), std::size_t(kMaxLights));
        QCOMPARE(loaded->view.debugView, DebugView::Distribution);
    }

    void brokenFilesGiveClearErrors_data()
    {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("expected");
        QTest::newRow("no materials")
            << QByteArray(R"({"format": "facet-project", "version": 2, "materials": []})")
            << QStringLiteral("materials: needs at least one material");
        QTest::newRow("current material out of range")
            << QByteArray(
                   R"({"format": "facet-project", "version": 2, "materials": [{}], "currentMaterial": 3})")
            << QStringLiteral("currentMaterial: 3 is not a material (there are 1)");
        QTest::newRow("part's material out of range") << QByteArray(
            R"({"format": "facet-project", "version": 2, "materials": [{}], "parts": [{"material": 1}]})")
                                                      << QStringLiteral("parts[0].material: 1 is not a "
                                                                        "material (there are 1)");
        QTest::newRow("second material invalid")
            << QByteArray(R"({"format": "facet-project", "version": 2, "materials": [{}, {"ior": 0.5}]})")
            << QStringLiteral("materials[1].ior: 0.5 is outside [1, 5]");
        QTest::newRow("part not an object")
            << QByteArray(R"({"format": "facet-project", "version": 2, "parts": [3]})")
            << QStringLiteral("parts[0]: expected an object, got a number");
        // Issue 29 named "a cell's camera reported as camera.farPlane": a compare cell's own camera
        // is named by its path, never as the project's camera.
        QTest::newRow("cell camera") << QByteArray(
            R"({"format": "facet-project", "version": 3, "materials": [{}], "compare": {"environments": {"cells": [{"source": "studio"}, {"source": "sky", "cameraLinked": false, "camera": {"farPlane": 0.01, "nearPlane": 0.05}}]}}})")
                                     << QStringLiteral("compare.environments.cells[1].camera.farPlane: must "
                                                       "be greater than nearPlane");
        QTest::newRow("unknown wrap") << QByteArray(
            R"({"format": "facet-project", "version": 3, "materials": [{"normal": {"sampler": {"wrapT": "clamp"}}}]})")
                                      << QStringLiteral(
                                             "materials[0].normal.sampler.wrapT: unknown name \"clamp\"");
        QTest::newRow("minification filter magnifying") << QByteArray(
            R"({"format": "facet-project", "version": 3, "materials": [{"baseColor": {"sampler": {"magFilter": "linearMipmapLinear"}}}]})")
                                                        << QStringLiteral("materials[0].baseColor.sampler."
                                                                          "magFilter: \"linearMipmapLinear\" "
                                                                          "is a minification filter");
        QTest::newRow("third UV set") << QByteArray(
            R"({"format": "facet-project", "version": 3, "materials": [{"occlusion": {"texCoord": 2}}]})")
                                      << QStringLiteral("materials[0].occlusion.texCoord: 2 is not a "
                                                        "texture-coordinate set (0 or 1)");
        QTest::newRow("UV set not an integer") << QByteArray(
            R"({"format": "facet-project", "version": 3, "materials": [{"occlusion": {"texCoord": 0.5}}]})")
                                               << QStringLiteral(
                                                      "materials[0].occlusion.texCoord: expected an integer");
        QTest::newRow("empty") << QByteArray() << QStringLiteral("the file is empty");
        QTest::newRow("whitespace") << QByteArray(" \n\t\n") << QStringLiteral("the file is empty");
        QTest::newRow("broken JSON") << QByteArray(
            "{\n  \"format\": \"facet-project\",\n  \"version\": 1,\n  oops\n}")
                                     << QStringLiteral("line 4, column"); // Qt points at or just after "oops"
        QTest::newRow("unterminated")
            << QByteArray("{\"format\": \"facet-pro") << QStringLiteral("line 1, column");
        QTest::newRow("binary") << QByteArray("\x89PNG\r\n\x1a\n\0\0\0", 11)
                                << QStringLiteral("not valid JSON");
        QTest::newRow("top-level array")
            << QByteArray("[1, 2]") << QStringLiteral("expected a JSON object at the top level");
        QTest::newRow("no format") << QByteArray(R"({"version": 1})")
                                   << QStringLiteral("\"format\" is missing");
        QTest::newRow("wrong format")
            << QByteArray(R"({"format": "facet-material-preset", "version": 1})")
            << QStringLiteral("format: \"facet-material-preset\" is not \"facet-project\"");
        QTest::newRow("format not a string") << QByteArray(R"({"format": 7, "version": 1})")
                                             << QStringLiteral("format: expected a string, got a number");
        QTest::newRow("no version") << QByteArray(R"({"format": "facet-project"})")
                                    << QStringLiteral("\"version\" is missing");
        QTest::newRow("newer version")
            << QByteArray(
                   R"({"format": "facet-project", "version": 10, "material": {"roughness": "new syntax"}})")
            << QStringLiteral("written by a newer Facet (version 10); this Facet reads up to version 9");
        // Version 3's compare layout (every refusal: tests/CompareLayoutTest.cpp); the path names it.
        QTest::newRow("compare: B names a material the project lacks")
            << QByteArray(R"({"format": "facet-project", "version": 3, "materials": [{}, {}],
                            "compare": {"ab": {"source": "material", "material": 2}}})")
            << QStringLiteral("compare.ab.material: 2 is not a material (there are 2)");
        QTest::newRow("compare: a cell's bad camera")
            << QByteArray(R"({"format": "facet-project", "version": 3, "compare": {"environments": {"cells":
                            [{}, {"camera": {"nearPlane": -1}}]}}})")
            << QStringLiteral("compare.environments.cells[1].camera.nearPlane");
        // Issue 29: reported as compare.environments.cells[0].source (the cell made from it).
        QTest::newRow("bad environment source")
            << minimalWith(R"("environment": {"source": "uniform:-2"})")
            << QStringLiteral("environment.source: uniform:-2: expected uniform:VALUE");
        QTest::newRow("compare: snapshot out of range")
            << QByteArray(R"({"format": "facet-project", "version": 3,
                            "compare": {"ab": {"snapshot": {"roughness": {"factor": 2}}}}})")
            << QStringLiteral("compare.ab.snapshot.roughness.factor: 2 is outside [0, 1]");
        QTest::newRow("compare not an object")
            << QByteArray(R"({"format": "facet-project", "version": 3, "compare": "ab"})")
            << QStringLiteral("compare: expected an object, got a string");
        QTest::newRow("version zero") << QByteArray(R"({"format": "facet-project", "version": 0})")
                                      << QStringLiteral("version: 0 is not a valid version");
        QTest::newRow("version string") << QByteArray(R"({"format": "facet-project", "version": "1"})")
                                        << QStringLiteral("version: expected an integer, got a string");
        QTest::newRow("version fraction") << QByteArray(R"({"format": "facet-project", "version": 1.5})")
                                          << QStringLiteral("version: expected an integer, got 1.5");
        QTest::newRow("intensity string")
            << minimalWith(R"("lights": [{"type": "point"}, {"intensity": "bright"}])")
            << QStringLiteral("lights[1].intensity: expected a number, got a string");
        QTest::newRow("roughness string")
            << minimalWith(R"("material": {"roughness": {"factor": "0.5"}})")
            << QStringLiteral("material.roughness.factor: expected a number, got a string");
        QTest::newRow("roughness out of range")
            << minimalWith(R"("material": {"roughness": {"factor": 1.5}})")
            << QStringLiteral("material.roughness.factor: 1.5 is outside [0, 1]");
        QTest::newRow("negative intensity")
            << minimalWith(R"("lights": [{"intensity": -2}])") << QStringLiteral("lights[0].intensity: -2");
        QTest::newRow("cone angles") << minimalWith(
            R"("lights": [{"type": "spot", "innerConeAngle": 0.8, "outerConeAngle": 0.5}])")
                                     << QStringLiteral("lights[0].innerConeAngle");
        QTest::newRow("unknown tone mapper") << minimalWith(R"("view": {"toneMapper": "filmic"})")
                                             << QStringLiteral("view.toneMapper: unknown name \"filmic\"");
        QTest::newRow("unknown debug view")
            << minimalWith(R"("view": {"debugView": "normals"})")
            << QStringLiteral("view.debugView: unknown debug view \"normals\" "
                              "(expected one of: none, base-color, shading-normal");
        QTest::newRow("nine lights") << minimalWith(R"("lights": [{}, {}, {}, {}, {}, {}, {}, {}, {}])")
                                     << QStringLiteral("lights: 9 lights; Facet draws at most 8");
        QTest::newRow("unknown light type") << minimalWith(R"("lights": [{"type": "area"}])")
                                            << QStringLiteral("lights[0].type: unknown name \"area\"");
        QTest::newRow("unknown visibility")
            << minimalWith(R"("material": {"shading": {"visibility": "smith"}})")
            << QStringLiteral("material.shading.visibility: unknown name \"smith\"");
        QTest::newRow("unknown channel") << minimalWith(R"("material": {"metallic": {"channel": "x"}})")
                                         << QStringLiteral("material.metallic.channel: unknown name \"x\"");
        QTest::newRow("short colour")
            << minimalWith(R"("lights": [{"color": [1, 1]}])")
            << QStringLiteral("lights[0].color: expected an array of 3 numbers, got 2");
        QTest::newRow("colour element")
            << minimalWith(R"("lights": [{"color": [1, "red", 1]}])")
            << QStringLiteral("lights[0].color[1]: expected a number, got a string");
        QTest::newRow("lights not an array") << minimalWith(R"("lights": {"type": "point"})")
                                             << QStringLiteral("lights: expected an array, got an object");
        QTest::newRow("light not an object") << minimalWith(R"("lights": [{}, 5])")
                                             << QStringLiteral("lights[1]: expected an object, got a number");
        QTest::newRow("material not an object") << minimalWith(
            R"("material": [])") << QStringLiteral("material: expected an object, got an array");
        QTest::newRow("base colour size")
            << minimalWith(R"("material": {"baseColor": {"factor": [1, 1]}})")
            << QStringLiteral("material.baseColor.factor: expected an array of 3 to 4 numbers");
        QTest::newRow("uv scale type")
            << minimalWith(R"("material": {"normal": {"uv": {"scale": 2}}})")
            << QStringLiteral("material.normal.uv.scale: expected an array of 2 numbers, got a number");
        QTest::newRow("texture not a string")
            << minimalWith(R"("material": {"normal": {"texture": null}})")
            << QStringLiteral("material.normal.texture: expected a string, got null");
        QTest::newRow("bool as string")
            << minimalWith(R"("material": {"normal": {"flipGreen": "yes"}})")
            << QStringLiteral("material.normal.flipGreen: expected true or false, got a string");
        QTest::newRow("camera fov") << minimalWith(R"("camera": {"verticalFovDegrees": 0})")
                                    << QStringLiteral("camera.verticalFovDegrees");
        QTest::newRow("camera looks at itself") << minimalWith(R"("camera": {"position": [0, 0, 0]})")
                                                << QStringLiteral("camera.target: must differ from position");
        QTest::newRow("msaa not a power of two")
            << minimalWith(R"("view": {"msaaSamples": 3})") << QStringLiteral("view.msaaSamples: 3");
        QTest::newRow("texel density zero")
            << minimalWith(R"("view": {"texelDensityTarget": 0})")
            << QStringLiteral("view.texelDensityTarget: 0 is outside (0, 1000000]");
        QTest::newRow("texel density huge") << minimalWith(R"("view": {"texelDensityTarget": 2e6})")
                                            << QStringLiteral("view.texelDensityTarget: 2000000 is outside");
        QTest::newRow("msaa fraction") << minimalWith(R"("view": {"msaaSamples": 2.5})")
                                       << QStringLiteral("view.msaaSamples: expected an integer, got 2.5");
        QTest::newRow("ocio view without display")
            << minimalWith(R"("view": {"ocioView": "Raw"})")
            << QStringLiteral("view.ocioDisplay: must be set when ocioView is (\"Raw\")");
        QTest::newRow("ocio display without view")
            << minimalWith(R"("view": {"ocioDisplay": "sRGB - Display"})")
            << QStringLiteral("view.ocioView: must be set when ocioDisplay is (\"sRGB - Display\")");
        QTest::newRow("negative environment")
            << minimalWith(R"("environment": {"intensity": -1})") << QStringLiteral("environment.intensity");
        QTest::newRow("unknown quality") << minimalWith(R"("environment": {"quality": "ultra"})")
                                         << QStringLiteral("environment.quality: unknown name \"ultra\"");
        QTest::newRow("unknown method")
            << minimalWith(R"("environment": {"method": "path-tracing"})")
            << QStringLiteral("environment.method: unknown name \"path-tracing\"");
        QTest::newRow("negative samples")
            << minimalWith(R"("environment": {"method": "reference", "samples": -4})")
            << QStringLiteral("environment.samples: -4 must be 0");
        QTest::newRow("too many samples")
            << minimalWith(R"("environment": {"method": "reference", "samples": 65537})")
            << QStringLiteral("environment.samples: 65537 must be 0 (the method's default) to 65536");
        QTest::newRow("samples with the split sum")
            << minimalWith(R"("environment": {"samples": 64})")
            << QStringLiteral("environment.samples: 64 given with the split-sum method");
        // Finite doubles that a 32-bit float cannot hold became infinity on the GPU (a black or
        // white image, exit 0): refused, naming the field, in objects and in arrays.
        QTest::newRow("light intensity 1e308")
            << minimalWith(R"("lights": [{"type": "point", "intensity": 1e308}])")
            << QStringLiteral("lights[0].intensity: 1e+308 is beyond the range of the 32-bit floats");
        QTest::newRow("rotation 1e308") << minimalWith(R"("environment": {"rotationDegrees": 1e308})")
                                        << QStringLiteral("environment.rotationDegrees: 1e+308 is beyond");
        QTest::newRow("far plane 1e308") << minimalWith(R"("camera": {"farPlane": 1e308})")
                                         << QStringLiteral("camera.farPlane: 1e+308 is beyond");
        QTest::newRow("camera position element -1e39")
            << minimalWith(R"("camera": {"position": [0, 0, -1e39]})")
            << QStringLiteral("camera.position[2]: -1e+39 is beyond");
        QTest::newRow("a NUL in a texture path")
            << minimalWith(R"("material": {"baseColor": {"texture": "wood.png\u0000.exr"}})")
            << QStringLiteral("material.baseColor.texture: holds a NUL character");
        // Counted before a light is read: three million of them no longer take a second and a GiB.
        QTest::newRow("a million lights")
            << minimalWith(("\"lights\": [" + QByteArray("{},").repeated(1000000) + "{}]").constData())
            << QStringLiteral("lights: 1000001 lights; Facet draws at most 8");
        // Qt's parser refuses numbers beyond double range, so no infinity reaches the model.
        QTest::newRow("huge number") << minimalWith(R"("environment": {"rotationDegrees": 1e999})")
                                     << QStringLiteral("line 1, column 83: illegal number");
    }
    void brokenFilesGiveClearErrors()
    {
        QFETCH(QByteArray, content);
        QFETCH(QString, expected);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = QDir(dir.path()).filePath(QStringLiteral("broken-project.json"));
        QVERIFY(writeAll(path, content));
        std::string error;
        const std::optional<Project> loaded = Project::load(path.toStdString(), &error);
        QVERIFY2(!loaded, "a broken file loaded");
        QVERIFY2(contains(error, "Project::load: " + path.toStdString() + ": "), error.c_str());
        QVERIFY2(contains(error, expected.toStdString()), error.c_str());
    }

    // What is not a regular file is refused before it is opened: a FIFO blocked the open, a
    // device was read up to the size limit, a link loop said "no such file".
    void notAFileIsRefused_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<QString>("reason");
        QTest::newRow("a FIFO") << QStringLiteral("fifo") << QStringLiteral("is not a regular file");
        QTest::newRow("/dev/zero") << QStringLiteral("zero") << QStringLiteral("is not a regular file");
        QTest::newRow("/dev/urandom") << QStringLiteral("urandom") << QStringLiteral("is not a regular file");
        QTest::newRow("a link loop") << QStringLiteral("loop")
                                     << QStringLiteral("is a loop of symbolic links");
        QTest::newRow("a dangling link") << QStringLiteral(
            "dangling") << QStringLiteral("is a symbolic link to a file that does not exist");
        QTest::newRow("a folder") << QStringLiteral("folder") << QStringLiteral("is a folder, not a file");
        QTest::newRow("nothing") << QStringLiteral("missing") << QStringLiteral("no such file");
    }
    void notAFileIsRefused()
    {
        QFETCH(QString, kind);
        QFETCH(QString, reason);
        QTemporaryDir dir;
        QString path = dir.filePath(QStringLiteral("project.json"));
        if (kind == QLatin1String("fifo"))
            QCOMPARE(::mkfifo(QFile::encodeName(path).constData(), 0600), 0);
        else if (kind == QLatin1String("zero") || kind == QLatin1String("urandom"))
            path = QStringLiteral("/dev/") + kind;
        else if (kind == QLatin1String("loop"))
            QVERIFY(QFile::link(path, path));
        else if (kind == QLatin1String("dangling"))
            QVERIFY(QFile::link(dir.filePath(QStringLiteral("gone.json")), path));
        else if (kind == QLatin1String("folder"))
            QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("project.json")));
        std::string error;
        QVERIFY(!Project::load(path.toStdString(), &error));
        QVERIFY2(contains(error, "Project::load: " + path.toStdString() + ": " + reason.toStdString()),
            error.c_str());
    }

    void emptyTextureIsWarnedAbout()
    {
        std::string error, warning;
        const std::optional<Project> p = Project::fromJson(
            QJsonDocument::fromJson(minimalWith(R"("material": {"normal": {"texture": ""}})")).object(), {},
            &error, &warning);
        QVERIFY2(p, error.c_str());
        QVERIFY(p->material().map(MapSlot::Normal).path.empty());
        QVERIFY2(
            contains(warning, "material.normal.texture: empty, so the slot has no texture"), warning.c_str());
    }

    void missingFieldsTakeDefaults()
    {
        std::string error;
        std::optional<Project> p
            = Project::fromJson(QJsonDocument::fromJson(minimalWith("")).object(), "/x", &error);
        QVERIFY2(p, error.c_str());
        QVERIFY(*p == Project {});

        p = Project::fromJson(
            QJsonDocument::fromJson(
                minimalWith(R"("material": {"roughness": {"factor": 0.2}}, "lights": [{"type": "spot"}])"))
                .object(),
            "/x", &error);
        QVERIFY2(p, error.c_str());
        Material expected;
        expected.setFactor(MapSlot::Roughness, 0.2);
        QVERIFY(p->material() == expected);
        QCOMPARE(p->lights.size(), std::size_t(1));
        Light spot;
        spot.type = LightType::Spot;
        QVERIFY(p->lights[0] == spot);

        // A base colour without alpha gets alpha 1.
        p = Project::fromJson(
            QJsonDocument::fromJson(minimalWith(R"("material": {"baseColor": {"factor": [0.1, 0.2, 0.3]}})"))
                .object(),
            {}, &error);
        QVERIFY2(p, error.c_str());
        QCOMPARE(p->material().baseColorFactor(), glm::dvec4(0.1, 0.2, 0.3, 1.0));
    }

    void unknownKeysAreWarnedAboutNotFatal()
    {
        std::string error;
        std::string warning;
        const std::optional<Project> p = Project::fromJson(
            QJsonDocument::fromJson(
                minimalWith(R"("futureThing": 1, "material": {"rougness": {"factor": 0.1}})"))
                .object(),
            {}, &error, &warning);
        QVERIFY2(p, error.c_str());
        QVERIFY2(contains(warning, "futureThing: unknown key"), warning.c_str());
        QVERIFY2(contains(warning, "material.rougness: unknown key"), warning.c_str());
        QVERIFY(*p == Project {});

        // fromJson names itself in its errors.
        QVERIFY(!Project::fromJson(QJsonObject(), {}, &error));
        QVERIFY2(error.rfind("Project::fromJson: ", 0) == 0, error.c_str());
    }

    void truncatedFilesNeverCrash()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString root = dir.path();
        const Project full = everythingChanged(root);
        const QString path = QDir(root).filePath(QStringLiteral("p.json"));
        std::string error;
        QVERIFY2(full.save(path.toStdString(), &error), error.c_str());
        const QByteArray text = readAll(path);
        QVERIFY(text.size() > 1000);

        // Every prefix goes through the parser and the model in memory; every 13th (and the last
        // few) also through a file, for the file reader's own checks and its line/column report.
        // (Not all through files: rewriting a file thousands of times is slow on some disks.)
        const QString cut = QDir(root).filePath(QStringLiteral("cut.json"));
        int failures = 0;
        for (qsizetype length = 0; length < text.size(); ++length) {
            const QByteArray prefix = text.left(length);
            error.clear();
            std::optional<Project> loaded;
            if (length % 13 == 0 || length + 3 >= text.size()) {
                QVERIFY(writeAll(cut, prefix));
                loaded = Project::load(cut.toStdString(), &error);
                if (!loaded)
                    QVERIFY2(contains(error, "Project::load: " + cut.toStdString() + ": "), error.c_str());
            } else {
                QJsonParseError parseError;
                const QJsonDocument document = QJsonDocument::fromJson(prefix, &parseError);
                if (parseError.error == QJsonParseError::NoError && document.isObject())
                    loaded = Project::fromJson(document.object(), root.toStdString(), &error);
                else
                    error = "not JSON";
            }
            if (loaded) {
                // Only the whole object (perhaps without trailing white space) may load.
                QCOMPARE(prefix.trimmed(), text.trimmed());
                QVERIFY(*loaded == full);
            } else {
                QVERIFY(!error.empty());
                ++failures;
            }
        }
        QVERIFY(failures >= text.size() - 2);

        // Corrupted bytes: whatever loads is valid, whatever fails says why.
        QRandomGenerator random(20240611u);
        for (int round = 0; round < 1500; ++round) {
            QByteArray mutated = text;
            const int edits = 1 + int(random.bounded(4));
            for (int e = 0; e < edits; ++e) {
                const qsizetype at = qsizetype(random.bounded(quint32(mutated.size())));
                switch (random.bounded(3)) {
                case 0:
                    mutated[at] = char(random.bounded(256));
                    break;
                case 1:
                    mutated.remove(at, 1 + qsizetype(random.bounded(8)));
                    break;
                default:
                    mutated.insert(at, "[{\"-1e308,"[random.bounded(10)]);
                    break;
                }
            }
            const std::optional<QJsonObject> object = QJsonDocument::fromJson(mutated).isObject()
                ? std::optional(QJsonDocument::fromJson(mutated).object())
                : std::nullopt;
            if (!object)
                continue;
            error.clear();
            const std::optional<Project> loaded = Project::fromJson(*object, root.toStdString(), &error);
            if (loaded) {
                std::string problem;
                QVERIFY2(loaded->validate(&problem), problem.c_str());
            } else {
                QVERIFY(!error.empty());
            }
        }
    }
};

QTEST_GUILESS_MAIN(ProjectLoadingTest)
#include "ProjectLoadingTest.moc"
