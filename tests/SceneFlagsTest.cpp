// The scene flags of `facet render` and `facet sheet` (app/SceneFlags.h, issue 29): each flag
// sets its project field (read back from --save-project's file), --set reaches any field through
// a JSON pointer and is checked by the rules of a project file, and every bad value is refused
// with exit 2 and a message naming the flag or the path, writing nothing. A transparent background
// writes the object's coverage as alpha (PNG straight, EXR premultiplied) by every method.

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include "TestSupport.h"
#include "core/image/Image.h"
#include "core/project/Project.h"
#include "core/shading/ReferenceView.h"

using namespace facet;

namespace {

facet::test::ProcessResult runFacet(const QStringList& arguments)
{
    return facet::test::runWithoutDisplay(QStringLiteral(FACET_EXECUTABLE), arguments);
}

// The value at a JSON pointer of `root` ("/view/exposureEV").
QJsonValue at(const QJsonObject& root, const QString& pointer)
{
    QJsonValue node(root);
    for (const QString& token : pointer.mid(1).split(u'/')) {
        if (node.isObject())
            node = node.toObject().value(token);
        else if (node.isArray())
            node = node.toArray().at(token.toInt());
        else
            return QJsonValue(QJsonValue::Undefined);
    }
    return node;
}

} // namespace

class SceneFlagsTest : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

private Q_SLOTS:
    void flagsSetTheirFields_data()
    {
        QTest::addColumn<QString>("command"); // render or sheet
        QTest::addColumn<QStringList>("flags");
        QTest::addColumn<QString>("pointer"); // into the saved project
        QTest::addColumn<QString>("expected"); // its value, as compact JSON
        const auto row = [](const char* name, const QString& command, const QStringList& flags,
                             const char* pointer, const char* expected) {
            QTest::newRow(name) << command << flags << QString::fromLatin1(pointer)
                                << QString::fromLatin1(expected);
        };
        const QString render = QStringLiteral("render");
        row("--camera-position", render, {QStringLiteral("--camera-position"), QStringLiteral("0,1.5,4")},
            "/camera/position", "[0,1.5,4]");
        row("--camera-target", render, {QStringLiteral("--camera-target"), QStringLiteral("0.5,0,-1")},
            "/camera/target", "[0.5,0,-1]");
        row("--fov", render, {QStringLiteral("--fov"), QStringLiteral("30")}, "/camera/verticalFovDegrees",
            "30");
        row("--exposure", render, {QStringLiteral("--exposure"), QStringLiteral("-1.5")}, "/view/exposureEV",
            "-1.5");
        row("--tone-mapper", render, {QStringLiteral("--tone-mapper"), QStringLiteral("aces")},
            "/view/toneMapper", "\"aces\"");
        row("--env-rotation", render, {QStringLiteral("--env-rotation"), QStringLiteral("90")},
            "/environment/rotationDegrees", "90");
        row("--env-intensity (EV)", render, {QStringLiteral("--env-intensity"), QStringLiteral("2")},
            "/environment/intensity", "4");
        row("--background env", render, {QStringLiteral("--background"), QStringLiteral("env")},
            "/view/background", "\"environment\"");
        row("--background blurred", render, {QStringLiteral("--background"), QStringLiteral("blurred")},
            "/view/background", "\"blurred\"");
        row("--background transparent", render,
            {QStringLiteral("--background"), QStringLiteral("transparent")}, "/view/background",
            "\"transparent\"");
        row("--background color:", render,
            {QStringLiteral("--background"), QStringLiteral("color:0.1,0.2,0.3")}, "/view/backgroundColor",
            "[0.1,0.2,0.3]");
        row("--set a number", render,
            {QStringLiteral("--set"), QStringLiteral("/materials/0/roughness/factor=0.25")},
            "/materials/0/roughness/factor", "0.25");
        row("--set a bare word", render, {QStringLiteral("--set"), QStringLiteral("/view/toneMapper=agx")},
            "/view/toneMapper", "\"agx\"");
        row("--set a quoted string", render,
            {QStringLiteral("--set"), QStringLiteral("/view/toneMapper=\"reinhard\"")}, "/view/toneMapper",
            "\"reinhard\"");
        row("--set an array", render, {QStringLiteral("--set"), QStringLiteral("/camera/position=[1,2,3]")},
            "/camera/position", "[1,2,3]");
        row("--set a boolean", render,
            {QStringLiteral("--set"), QStringLiteral("/materials/0/doubleSided=true")},
            "/materials/0/doubleSided", "true");
        row("--set an array element", render,
            {QStringLiteral("--set"), QStringLiteral("/camera/position/1=2.5")}, "/camera/position",
            "[0,2.5,3]");
        row("--set wins over the named flag", render,
            {QStringLiteral("--exposure"), QStringLiteral("1"), QStringLiteral("--set"),
                QStringLiteral("/view/exposureEV=2")},
            "/view/exposureEV", "2");
        row("two --set", render,
            {QStringLiteral("--set"), QStringLiteral("/view/exposureEV=3"), QStringLiteral("--set"),
                QStringLiteral("/view/gamma=2.4")},
            "/view/gamma", "2.4");
        row("sheet --exposure", QStringLiteral("sheet"),
            {QStringLiteral("--exposure"), QStringLiteral("0.5")}, "/view/exposureEV", "0.5");
        row("sheet --set", QStringLiteral("sheet"),
            {QStringLiteral("--set"), QStringLiteral("/environment/intensity=0.5")}, "/environment/intensity",
            "0.5");
    }

    void flagsSetTheirFields()
    {
        QFETCH(QString, command);
        QFETCH(QStringList, flags);
        QFETCH(QString, pointer);
        QFETCH(QString, expected);
        const QString saved = m_dir.filePath(QStringLiteral("saved.json"));
        const QString out = m_dir.filePath(QStringLiteral("out.exr"));
        QFile::remove(saved);
        QStringList arguments {command};
        arguments << flags << QStringLiteral("--save-project") << saved << QStringLiteral("--quality")
                  << QStringLiteral("draft");
        arguments << (command == QLatin1String("sheet") ? QStringLiteral("--cell") : QStringLiteral("--size"))
                  << QStringLiteral("8x8") << QStringLiteral("-o") << out;
        const facet::test::ProcessResult r = runFacet(arguments);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QFile file(saved);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QJsonObject project = QJsonDocument::fromJson(file.readAll()).object();
        const QJsonValue value = at(project, pointer);
        const QByteArray actual = value.isArray()
            ? QJsonDocument(value.toArray()).toJson(QJsonDocument::Compact)
            : value.isObject()
            ? QJsonDocument(value.toObject()).toJson(QJsonDocument::Compact)
            : QJsonDocument(QJsonArray {value}).toJson(QJsonDocument::Compact).mid(1).chopped(1);
        QCOMPARE(QString::fromUtf8(actual), expected);
        // The saved project is a project file like any other, and renders.
        std::string error;
        QVERIFY2(Project::load(saved.toStdString(), &error), error.c_str());
    }

    void badValuesAreNamed_data()
    {
        QTest::addColumn<QStringList>("flags");
        QTest::addColumn<QString>("message");
        const auto row = [](const char* name, const QStringList& flags, const char* message) {
            QTest::newRow(name) << flags << QString::fromUtf8(message);
        };
        row("fov 190", {QStringLiteral("--fov"), QStringLiteral("190")}, "--fov: 190 is outside (0, 180)");
        row("fov 0", {QStringLiteral("--fov"), QStringLiteral("0")}, "--fov: 0 is outside (0, 180)");
        row("exposure nan", {QStringLiteral("--exposure"), QStringLiteral("nan")},
            "--exposure: 'nan' is not a number");
        row("exposure 30", {QStringLiteral("--exposure"), QStringLiteral("30")},
            "--exposure: 30 is outside [-20, 20]");
        row("tone mapper", {QStringLiteral("--tone-mapper"), QStringLiteral("filmic")},
            "--tone-mapper: 'filmic' is not none, reinhard");
        row("camera 2 numbers", {QStringLiteral("--camera-position"), QStringLiteral("1,2")},
            "--camera-position: '1,2' is not x,y,z");
        row("camera inf", {QStringLiteral("--camera-target"), QStringLiteral("0,inf,0")},
            "--camera-target: '0,inf,0' is not x,y,z with finite numbers");
        row("camera at its target", {QStringLiteral("--camera-position"), QStringLiteral("0,0,0")},
            "camera.target: must differ from position");
        row("background word", {QStringLiteral("--background"), QStringLiteral("transparentish")},
            "--background: 'transparentish' is not env, blurred, transparent or color:R,G,B");
        row("background negative", {QStringLiteral("--background"), QStringLiteral("color:-1,0,0")},
            "--background: 'color:-1,0,0': a colour is linear and >= 0");
        row("env intensity", {QStringLiteral("--env-intensity"), QStringLiteral("99")},
            "--env-intensity: 99 is outside [-20, 20]");
        row("set out of range", {QStringLiteral("--set"), QStringLiteral("/view/exposureEV=30")},
            "--set '/view/exposureEV=30': view.exposureEV: 30 is outside [-20, 20]");
        row("set misspelt field", {QStringLiteral("--set"), QStringLiteral("/view/exposure=1")},
            "--set '/view/exposure=1': view.exposure: not a field of the project format");
        row("set missing parent", {QStringLiteral("--set"), QStringLiteral("/nope/x=1")},
            "--set /nope/x: /nope does not exist");
        row("set past the array",
            {QStringLiteral("--set"), QStringLiteral("/materials/3/roughness/factor=1")},
            "--set /materials/3/roughness/factor: /materials/3: not an index of the array's 1 elements");
        row("set wrong type", {QStringLiteral("--set"), QStringLiteral("/view/exposureEV=bright")},
            "--set '/view/exposureEV=bright': view.exposureEV: expected a number, got a string");
        row("set without =", {QStringLiteral("--set"), QStringLiteral("view")},
            "--set: 'view' is not PATH=VALUE");
    }

    void transparentBackgroundKeepsAlpha_data()
    {
        QTest::addColumn<QStringList>("method");
        QTest::addColumn<QString>("extension");
        for (const char* extension : {"png", "exr"}) {
            const auto row = [&](const char* name, const QStringList& method) {
                QTest::newRow(
                    qPrintable(QStringLiteral("%1, %2").arg(QLatin1String(name), QLatin1String(extension))))
                    << method << QString::fromLatin1(extension);
            };
            row("split sum", {QStringLiteral("--ibl"), QStringLiteral("split-sum")});
            row("fis (accumulated)",
                {QStringLiteral("--ibl"), QStringLiteral("fis"), QStringLiteral("--ibl-samples"),
                    QStringLiteral("64")});
            row("reference (accumulated)",
                {QStringLiteral("--ibl"), QStringLiteral("reference"), QStringLiteral("--ibl-samples"),
                    QStringLiteral("32")});
            row("cpu ground truth", {QStringLiteral("--spp"), QStringLiteral("4")});
        }
    }

    // The reference view (the unit sphere) over a transparent background: alpha 1 on the sphere,
    // 0 in the corners, fractional only on the silhouette; where alpha is 0 there is no colour
    // (EXR, premultiplied); the sphere's pixels match the same render over the environment.
    void transparentBackgroundKeepsAlpha()
    {
        QFETCH(QStringList, method);
        QFETCH(QString, extension);
        const QString transparent = m_dir.filePath(QStringLiteral("transparent.") + extension);
        const QString opaque = m_dir.filePath(QStringLiteral("opaque.") + extension);
        for (const QString& out : {transparent, opaque}) {
            QStringList arguments {QStringLiteral("render"), QStringLiteral("--reference-view"),
                QStringLiteral("--size"), QStringLiteral("48x48"), QStringLiteral("--quality"),
                QStringLiteral("draft"), QStringLiteral("--env"), QStringLiteral("uniform:0.5"),
                QStringLiteral("-o"), out};
            arguments << method;
            if (out == transparent)
                arguments << QStringLiteral("--background") << QStringLiteral("transparent");
            const facet::test::ProcessResult r = runFacet(arguments);
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        }
        std::string error;
        const std::optional<Image> image = Image::load(transparent.toStdString(), &error);
        QVERIFY2(image, error.c_str());
        const std::optional<Image> reference = Image::load(opaque.toStdString(), &error);
        QVERIFY2(reference, error.c_str());
        QCOMPARE(image->sourceChannels(), 4);
        int inside = 0, outside = 0;
        for (int y = 0; y < 48; ++y)
            for (int x = 0; x < 48; ++x) {
                const glm::vec4 p = image->at(x, y);
                const glm::vec4 q = reference->at(x, y);
                if (referenceview::isInteriorSpherePixel(x, y, 48, 48, 1)) {
                    ++inside;
                    QVERIFY2(std::abs(p.a - 1.0f) < 1e-3f,
                        qPrintable(QStringLiteral("(%1, %2) alpha %3").arg(x).arg(y).arg(p.a)));
                    QVERIFY2(glm::length(glm::vec3(p) - glm::vec3(q)) < 0.02f,
                        qPrintable(QStringLiteral(
                            "(%1, %2): (%3, %4, %5) over nothing, (%6, %7, %8) over the environment")
                                       .arg(x)
                                       .arg(y)
                                       .arg(p.r)
                                       .arg(p.g)
                                       .arg(p.b)
                                       .arg(q.r)
                                       .arg(q.g)
                                       .arg(q.b)));
                } else if (!referenceview::intersectSphere(referenceview::rayDirection(x - 1, y - 1, 48, 48))
                    && !referenceview::intersectSphere(referenceview::rayDirection(x + 1, y + 1, 48, 48))
                    && !referenceview::intersectSphere(referenceview::rayDirection(x, y, 48, 48))) {
                    ++outside;
                    QVERIFY2(
                        p.a == 0.0f, qPrintable(QStringLiteral("(%1, %2) alpha %3").arg(x).arg(y).arg(p.a)));
                    if (extension == QLatin1String("exr"))
                        QVERIFY(glm::vec3(p) == glm::vec3(0.0f));
                }
                QVERIFY(p.a >= 0.0f && p.a <= 1.0f);
            }
        QVERIFY(inside > 500 && outside > 500);
    }

    void badValuesAreNamed()
    {
        QFETCH(QStringList, flags);
        QFETCH(QString, message);
        const QString out = m_dir.filePath(QStringLiteral("never.exr"));
        const QString saved = m_dir.filePath(QStringLiteral("never.json"));
        QStringList arguments {QStringLiteral("render")};
        arguments << flags << QStringLiteral("--save-project") << saved << QStringLiteral("-o") << out;
        const facet::test::ProcessResult r = runFacet(arguments);
        QVERIFY2(r.exitCode == 2, qPrintable(QStringLiteral("exit %1: %2").arg(r.exitCode).arg(r.err)));
        QVERIFY2(
            r.err.startsWith(QStringLiteral("facet render: ")) && r.err.contains(message), qPrintable(r.err));
        QVERIFY(!QFile::exists(out));
        QVERIFY(!QFile::exists(saved));
    }
};

QTEST_GUILESS_MAIN(SceneFlagsTest)
#include "SceneFlagsTest.moc"
