// `facet render --scenario JSON` (app/RenderScenario.h, issue 29): the one argument the glTF
// render-fidelity harness gives its offline renderers. The camera each orbit gives (read back
// from --save-project), the harness's defaults, the tone mapping and the transparent background,
// a real sample asset rendered (the Khronos TextureTransformTest: its arrows point at the green
// checks), and every bad field refused with exit 2, a message naming it and no file written.

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <glm/geometric.hpp>

#include <cmath>

#include "TestSupport.h"
#include "core/image/Image.h"
#include "core/project/Project.h"

using namespace facet;

namespace {

facet::test::ProcessResult runFacet(const QStringList& arguments)
{
    return facet::test::runWithoutDisplay(QStringLiteral(FACET_EXECUTABLE), arguments);
}

QString dataPath(const QString& relative)
{
    return QDir(facet::test::sourceDir()).filePath(QStringLiteral("tests/data/") + relative);
}

// The harness's argument for `scenario` (its fields as given) writing `output`.
QString argument(const QJsonObject& scenario, const QString& output)
{
    return QString::fromUtf8(QJsonDocument(
        QJsonObject {{QStringLiteral("scenario"), scenario}, {QStringLiteral("outputFile"), output}})
                                 .toJson(QJsonDocument::Compact));
}

QJsonObject textureTransformScenario()
{
    return QJsonObject {{QStringLiteral("name"), QStringLiteral("khronos-TextureTransformTest")},
        {QStringLiteral("model"),
            dataPath(QStringLiteral("gltf/TextureTransformTest/TextureTransformTest.gltf"))},
        {QStringLiteral("lighting"), dataPath(QStringLiteral("hdri/studio.exr"))},
        {QStringLiteral("dimensions"),
            QJsonObject {{QStringLiteral("width"), 96}, {QStringLiteral("height"), 96}}},
        {QStringLiteral("orbit"),
            QJsonObject {
                {QStringLiteral("theta"), 0}, {QStringLiteral("phi"), 90}, {QStringLiteral("radius"), 4}}}};
}

glm::dvec3 vec3Of(const QJsonValue& value)
{
    const QJsonArray a = value.toArray();
    return {a.at(0).toDouble(), a.at(1).toDouble(), a.at(2).toDouble()};
}

} // namespace

class RenderScenarioTest : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

private Q_SLOTS:
    // model-viewer's orbit: target + radius (sin phi sin theta, cos phi, sin phi cos theta), in
    // degrees, looking at the target; radius 0 looks from the target along -that direction.
    void orbitPlacesTheCamera_data()
    {
        QTest::addColumn<QJsonObject>("orbit");
        QTest::addColumn<QJsonObject>("target");
        QTest::addColumn<QVector<double>>("position");
        QTest::addColumn<QVector<double>>("lookAt");
        const auto orbit = [](double theta, double phi, double radius) {
            return QJsonObject {{QStringLiteral("theta"), theta}, {QStringLiteral("phi"), phi},
                {QStringLiteral("radius"), radius}};
        };
        const QJsonObject origin;
        QTest::newRow("defaults (0, 90, 1)")
            << QJsonObject {} << origin << QVector<double> {0, 0, 1} << QVector<double> {0, 0, 0};
        QTest::newRow("front, radius 4")
            << orbit(0, 90, 4) << origin << QVector<double> {0, 0, 4} << QVector<double> {0, 0, 0};
        QTest::newRow("theta 90 swings to +X")
            << orbit(90, 90, 2) << origin << QVector<double> {2, 0, 0} << QVector<double> {0, 0, 0};
        QTest::newRow("phi 0 is above")
            << orbit(0, 0, 3) << origin << QVector<double> {0, 3, 0} << QVector<double> {0, 0, 0};
        QTest::newRow("(30, 60, 4.75) about a target")
            << orbit(30, 60, 4.75) << QJsonObject {{QStringLiteral("y"), 0.86}}
            << QVector<double> {4.75 * std::sin(M_PI / 3) * 0.5, 0.86 + 4.75 * 0.5,
                   4.75 * std::sin(M_PI / 3) * std::cos(M_PI / 6)}
            << QVector<double> {0, 0.86, 0};
        QTest::newRow("radius 0 looks out from the target")
            << orbit(0, 90, 0) << QJsonObject {{QStringLiteral("x"), 1}} << QVector<double> {1, 0, 0}
            << QVector<double> {1, 0, -1};
    }
    void orbitPlacesTheCamera()
    {
        QFETCH(QJsonObject, orbit);
        QFETCH(QJsonObject, target);
        QFETCH(QVector<double>, position);
        QFETCH(QVector<double>, lookAt);
        QJsonObject scenario = textureTransformScenario();
        scenario.remove(QStringLiteral("orbit"));
        if (!orbit.isEmpty())
            scenario[QStringLiteral("orbit")] = orbit;
        if (!target.isEmpty())
            scenario[QStringLiteral("target")] = target;
        scenario[QStringLiteral("dimensions")]
            = QJsonObject {{QStringLiteral("width"), 8}, {QStringLiteral("height"), 4}};
        const QString out = m_dir.filePath(QStringLiteral("orbit.png"));
        const QString saved = m_dir.filePath(QStringLiteral("orbit.json"));
        const facet::test::ProcessResult r = runFacet({QStringLiteral("render"), QStringLiteral("--scenario"),
            argument(scenario, out), QStringLiteral("--save-project"), saved, QStringLiteral("--quality"),
            QStringLiteral("draft")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QFile file(saved);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QJsonObject project = QJsonDocument::fromJson(file.readAll()).object();
        const QJsonObject camera = project.value(QStringLiteral("camera")).toObject();
        const glm::dvec3 p = vec3Of(camera.value(QStringLiteral("position")));
        const glm::dvec3 t = vec3Of(camera.value(QStringLiteral("target")));
        QVERIFY2(glm::length(p - glm::dvec3(position[0], position[1], position[2])) < 1e-9,
            qPrintable(QStringLiteral("position (%1, %2, %3)").arg(p.x).arg(p.y).arg(p.z)));
        QVERIFY2(glm::length(t - glm::dvec3(lookAt[0], lookAt[1], lookAt[2])) < 1e-9,
            qPrintable(QStringLiteral("target (%1, %2, %3)").arg(t.x).arg(t.y).arg(t.z)));
        // The harness's conventions: 45 degrees unless told, the model in its own units, ACES
        // (Hill) at 1 / 0.6, sRGB, transparent unless renderSkybox.
        QCOMPARE(camera.value(QStringLiteral("verticalFovDegrees")).toDouble(), 45.0);
        const QJsonObject view = project.value(QStringLiteral("view")).toObject();
        QCOMPARE(view.value(QStringLiteral("keepUnits")).toBool(), true);
        QCOMPARE(view.value(QStringLiteral("toneMapper")).toString(), QStringLiteral("aces"));
        QVERIFY(std::abs(view.value(QStringLiteral("exposureEV")).toDouble() - std::log2(1.0 / 0.6)) < 1e-12);
        QCOMPARE(view.value(QStringLiteral("background")).toString(), QStringLiteral("transparent"));
        // Twice the dimensions: the harness compares at a device pixel ratio of 2.
        std::string error;
        const std::optional<Image> image = Image::load(out.toStdString(), &error);
        QVERIFY2(image, error.c_str());
        QCOMPARE(image->width(), 16);
        QCOMPARE(image->height(), 8);
    }

    // The Khronos TextureTransformTest (CC0, tests/data/gltf): each transformed quad's arrow points
    // at a green check in every renderer of the comparison; the wrong rotation turns it to the red
    // "applied in the opposite direction" marker instead. In a 192 x 192 image at the harness's
    // scenario (0, 90, 4) the checks are green and each arrow's head sits just above its check
    // (with the rotation negated, those places are the quads' light grey); around them the
    // background is transparent.
    void textureTransformTestPointsAtTheChecks()
    {
        const QString out = m_dir.filePath(QStringLiteral("texture-transform.png"));
        const facet::test::ProcessResult r = runFacet({QStringLiteral("render"), QStringLiteral("--scenario"),
            argument(textureTransformScenario(), out)});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        std::string error;
        const std::optional<Image> image = Image::load(out.toStdString(), &error);
        QVERIFY2(image, error.c_str());
        QCOMPARE(image->width(), 192);
        QCOMPARE(image->sourceChannels(), 4);
        image->save(QDir(facet::test::outputDir())
                        .filePath(QStringLiteral("texture-transform-test.png"))
                        .toStdString(),
            &error);
        const auto green = [&](int x, int y) {
            const glm::vec4 p = image->at(x, y);
            return p.a > 0.99f && p.g > p.r + 0.15f && p.g > p.b + 0.15f;
        };
        // Dark: some pixel within 2 of (x, y) is the arrow's black.
        const auto dark = [&](int x, int y) {
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx) {
                    const glm::vec4 p = image->at(x + dx, y + dy);
                    if (p.a > 0.99f && std::max({p.r, p.g, p.b}) < 0.15f)
                        return true;
                }
            return false;
        };
        for (const auto& [x, y] : {std::pair {21, 142}, std::pair {90, 120}, std::pair {151, 134}})
            QVERIFY2(dark(x, y), qPrintable(QStringLiteral("no arrow head near (%1, %2)").arg(x).arg(y)));
        for (const auto& [x, y] : {std::pair {28, 158}, std::pair {97, 129}, std::pair {156, 143}})
            QVERIFY2(green(x, y),
                qPrintable(QStringLiteral("(%1, %2) is (%3, %4, %5, %6), not the green check")
                               .arg(x)
                               .arg(y)
                               .arg(image->at(x, y).r)
                               .arg(image->at(x, y).g)
                               .arg(image->at(x, y).b)
                               .arg(image->at(x, y).a)));
        QCOMPARE(image->at(2, 2).a, 0.0f); // a corner: the transparent background
    }

    void badScenariosAreRefused_data()
    {
        QTest::addColumn<QString>("json"); // %1: the model, %2: the lighting, %3: the output
        QTest::addColumn<QString>("message");
        const auto row = [](const char* name, const char* json, const char* message) {
            QTest::newRow(name) << QString::fromUtf8(json) << QString::fromUtf8(message);
        };
        row("not JSON", R"({"scenario": )", "--scenario: not JSON");
        row("no scenario", R"({"outputFile": "%3"})", "scenario: missing");
        row("no model", R"({"scenario": {"lighting": "%2"}, "outputFile": "%3"})", "scenario.model: missing");
        row("missing model",
            R"({"scenario": {"model": "/nowhere/Duck.gltf", "lighting": "%2"}, "outputFile": "%3"})",
            "scenario.model: /nowhere/Duck.gltf: no such file");
        row("missing lighting",
            R"({"scenario": {"model": "%1", "lighting": "/nowhere/sky.hdr"}, "outputFile": "%3"})",
            "scenario.lighting: /nowhere/sky.hdr: no such file");
        row("no output", R"({"scenario": {"model": "%1", "lighting": "%2"}})", "outputFile: missing");
        row("output type", R"({"scenario": {"model": "%1", "lighting": "%2"}, "outputFile": "/tmp/x.jpg"})",
            "outputFile: '/tmp/x.jpg' is not a .png");
        row("phi a string",
            R"({"scenario": {"model": "%1", "lighting": "%2", "orbit": {"phi": "up"}}, "outputFile": "%3"})",
            "scenario.orbit.phi: expected a number, got a string");
        row("negative radius",
            R"({"scenario": {"model": "%1", "lighting": "%2", "orbit": {"radius": -1}}, "outputFile": "%3"})",
            "scenario.orbit.radius: -1 is negative");
        row("width 0",
            R"({"scenario": {"model": "%1", "lighting": "%2", "dimensions": {"width": 0}}, "outputFile": "%3"})",
            "scenario.dimensions.width: 0 is not a whole number from 1 to 8192");
        row("height 2.5",
            R"({"scenario": {"model": "%1", "lighting": "%2", "dimensions": {"height": 2.5}}, "outputFile": "%3"})",
            "scenario.dimensions.height: 2.5 is not a whole number");
        row("fov 180",
            R"({"scenario": {"model": "%1", "lighting": "%2", "verticalFoV": 180}, "outputFile": "%3"})",
            "scenario.verticalFoV: 180 is outside (0, 180)");
        row("skybox a number",
            R"({"scenario": {"model": "%1", "lighting": "%2", "renderSkybox": 1}, "outputFile": "%3"})",
            "scenario.renderSkybox: expected true or false, got a number");
        row("target an array",
            R"({"scenario": {"model": "%1", "lighting": "%2", "target": [0, 0, 0]}, "outputFile": "%3"})",
            "scenario.target: expected an object, got an array");
        row("deep nesting",
            R"({"scenario": {"model": "%1", "lighting": "%2", "name": [[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[]]}, "outputFile": "%3"})",
            "--scenario: line 1, column");
        row("a model that is not one",
            R"({"scenario": {"model": "%2", "lighting": "%2"}, "outputFile": "%3"})", "scenario.model: ");
    }
    void badScenariosAreRefused()
    {
        QFETCH(QString, json);
        QFETCH(QString, message);
        const QString out = m_dir.filePath(QStringLiteral("never.png"));
        const QString model = dataPath(QStringLiteral("gltf/AnimatedMorphCube/AnimatedMorphCube.gltf"));
        const QString lighting = dataPath(QStringLiteral("hdri/studio.exr"));
        const QString text = QString(json)
                                 .replace(QStringLiteral("%1"), model)
                                 .replace(QStringLiteral("%2"), lighting)
                                 .replace(QStringLiteral("%3"), out);
        const facet::test::ProcessResult r
            = runFacet({QStringLiteral("render"), QStringLiteral("--scenario"), text});
        QVERIFY2(r.exitCode == 2, qPrintable(QStringLiteral("exit %1: %2").arg(r.exitCode).arg(r.err)));
        QVERIFY2(
            r.err.startsWith(QStringLiteral("facet render: ")) && r.err.contains(message), qPrintable(r.err));
        QVERIFY(!QFile::exists(out));
    }

    // The scenario says what these flags would: one source for each.
    void conflictingFlagsAreRefused_data()
    {
        QTest::addColumn<QStringList>("flags");
        QTest::addColumn<QString>("message");
        QTest::newRow("-o") << QStringList {QStringLiteral("-o"), QStringLiteral("x.png")}
                            << QStringLiteral("leave out --output");
        QTest::newRow("--size") << QStringList {QStringLiteral("--size"), QStringLiteral("8x8")}
                                << QStringLiteral("leave out --size");
        QTest::newRow("--fov") << QStringList {QStringLiteral("--fov"), QStringLiteral("30")}
                               << QStringLiteral("leave out --fov");
        QTest::newRow("an input") << QStringList {QStringLiteral("project.json")}
                                  << QStringLiteral("leave out 'project.json'");
    }
    void conflictingFlagsAreRefused()
    {
        QFETCH(QStringList, flags);
        QFETCH(QString, message);
        const QString out = m_dir.filePath(QStringLiteral("never.png"));
        QStringList arguments {QStringLiteral("render"), QStringLiteral("--scenario"),
            argument(textureTransformScenario(), out)};
        arguments << flags;
        const facet::test::ProcessResult r = runFacet(arguments);
        QVERIFY2(r.exitCode == 2, qPrintable(QStringLiteral("exit %1: %2").arg(r.exitCode).arg(r.err)));
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY(!QFile::exists(out));
    }
};

QTEST_GUILESS_MAIN(RenderScenarioTest)
#include "RenderScenarioTest.moc"
