// Turntables (render/Turntable.h, core/image/VideoEncoder.h, `facet render --turntable N`): where each
// frame goes, what a turn does to the scene, the frames `facet render` writes for each subject
// (the object turning under a fixed background, the environment turning behind a fixed object),
// a transparent background kept, a video by ffmpeg (when installed), and what happens without
// ffmpeg, when ffmpeg fails (an existing file untouched) and for each wrong flag.

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcessEnvironment>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <glm/geometric.hpp>

#include "TestSupport.h"
#include "core/image/Image.h"
#include "core/image/VideoEncoder.h"
#include "render/Turntable.h"

using namespace facet;

namespace {

using Result = facet::test::ProcessResult;

Result runFacet(const QStringList& arguments, const QProcessEnvironment& extra = QProcessEnvironment())
{
    return facet::test::runWithoutDisplay(QStringLiteral(FACET_EXECUTABLE), arguments, extra);
}

QStringList args(std::initializer_list<const char*> items)
{
    return facet::test::strings(items);
}

std::optional<Image> load(const QString& path)
{
    std::string error;
    std::optional<Image> image = Image::load(path.toStdString(), &error);
    if (!image)
        qWarning("%s", error.c_str());
    return image;
}

// The largest difference of any channel between two images of one size.
float largestDifference(const Image& a, const Image& b)
{
    float largest = 0.0f;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const glm::vec4 d = glm::abs(a.at(x, y) - b.at(x, y));
            largest = std::max({largest, d.r, d.g, d.b, d.a});
        }
    return largest;
}

// The largest difference over the image's border (2 pixels wide): the background around the
// framed object.
float largestBorderDifference(const Image& a, const Image& b)
{
    float largest = 0.0f;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            if (x > 1 && y > 1 && x < a.width() - 2 && y < a.height() - 2)
                continue;
            const glm::vec4 d = glm::abs(a.at(x, y) - b.at(x, y));
            largest = std::max({largest, d.r, d.g, d.b});
        }
    return largest;
}

} // namespace

class TurntableCommandTest : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    QString path(const QString& name) const { return m_dir.filePath(name); }

private Q_SLOTS:
    void framePaths_data();
    void framePaths();
    void aTurnMovesTheObjectOrTheEnvironment_data();
    void aTurnMovesTheObjectOrTheEnvironment();
    void framesOfEachSubject_data();
    void framesOfEachSubject();
    void transparentFramesKeepTheirAlpha();
    void aVideoWithFfmpeg();
    void withoutFfmpegItSaysHow();
    void aFailedEncodeLeavesTheFileAlone();
    void wrongFlags_data();
    void wrongFlags();
};

void TurntableCommandTest::framePaths_data()
{
    QTest::addColumn<QString>("output");
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("frames");
    QTest::addColumn<QString>("expected");
    QTest::newRow("before the extension") << "turn.png" << 7 << 36 << "turn_0007.png";
    QTest::newRow("in a folder, EXR") << "out/turn.exr" << 0 << 2 << "out/turn_0000.exr";
    QTest::newRow("a run of #") << "turn_####.png" << 7 << 36 << "turn_0007.png";
    QTest::newRow("a short run of #") << "t##x.png" << 123 << 200 << "t123x.png";
    QTest::newRow("more frames than 4 digits") << "turn.png" << 12 << 20000 << "turn_00012.png";
    QTest::newRow("dots in the name") << "a.b.png" << 1 << 2 << "a.b_0001.png";
    QTest::newRow("# in the folder is a folder") << "f#/turn.png" << 3 << 4 << "f#/turn_0003.png";
}

void TurntableCommandTest::framePaths()
{
    QFETCH(QString, output);
    QFETCH(int, index);
    QFETCH(int, frames);
    QFETCH(QString, expected);
    QCOMPARE(QString::fromStdString(turntableFramePath(output.toStdString(), index, frames)), expected);
}

void TurntableCommandTest::aTurnMovesTheObjectOrTheEnvironment_data()
{
    QTest::addColumn<int>("subject");
    QTest::addColumn<double>("degrees");
    QTest::addColumn<QVector<double>>("turnedX"); // where the model matrix takes +X
    QTest::addColumn<double>("rotation"); // the environment's, from 30 degrees
    QTest::addColumn<bool>("analytic"); // the reference view's exact sphere kept
    QTest::newRow("object, 90 degrees: +X to -Z")
        << int(TurntableSubject::Object) << 90.0 << QVector<double> {0.0, 0.0, -1.0} << 30.0 << false;
    QTest::newRow("object, 180 degrees")
        << int(TurntableSubject::Object) << 180.0 << QVector<double> {-1.0, 0.0, 0.0} << 30.0 << false;
    QTest::newRow("object, 0 degrees: nothing")
        << int(TurntableSubject::Object) << 0.0 << QVector<double> {1.0, 0.0, 0.0} << 30.0 << true;
    QTest::newRow("environment, 90 degrees")
        << int(TurntableSubject::Environment) << 90.0 << QVector<double> {1.0, 0.0, 0.0} << 120.0 << true;
    QTest::newRow("environment, -45 degrees")
        << int(TurntableSubject::Environment) << -45.0 << QVector<double> {1.0, 0.0, 0.0} << -15.0 << true;
    // The frames' angles: a full turn, frame N would be frame 0.
    QCOMPARE(turntableDegrees(0, 36), 0.0);
    QCOMPARE(turntableDegrees(9, 36), 90.0);
    QCOMPARE(turntableDegrees(35, 36), 350.0);
}

void TurntableCommandTest::aTurnMovesTheObjectOrTheEnvironment()
{
    QFETCH(int, subject);
    QFETCH(double, degrees);
    QFETCH(QVector<double>, turnedX);
    QFETCH(double, rotation);
    QFETCH(bool, analytic);
    RenderScene scene;
    scene.environment.rotationDegrees = 30.0;
    scene.analyticSphere = true;
    applyTurntable(scene, TurntableSubject(subject), degrees);
    const glm::dvec4 x = scene.modelMatrix * glm::dvec4(1.0, 0.0, 0.0, 0.0);
    QVERIFY2(glm::distance(glm::dvec3(x), glm::dvec3(turnedX[0], turnedX[1], turnedX[2])) < 1e-12,
        qPrintable(QStringLiteral("+X went to %1, %2, %3").arg(x.x).arg(x.y).arg(x.z)));
    QCOMPARE(scene.environment.rotationDegrees, rotation);
    QCOMPARE(scene.analyticSphere, analytic);
}

void TurntableCommandTest::framesOfEachSubject_data()
{
    QTest::addColumn<QString>("subject");
    QTest::addColumn<QString>("output");
    QTest::newRow("object, PNG") << "object"
                                 << "object.png";
    QTest::newRow("object, EXR") << "object"
                                 << "object.exr";
    QTest::newRow("environment, PNG") << "environment"
                                      << "environment_##.png";
}

void TurntableCommandTest::framesOfEachSubject()
{
    QFETCH(QString, subject);
    QFETCH(QString, output);
    // A cube turned by a third of a turn shows another silhouette; the studio's background varies.
    const QString folder = path(QStringLiteral("frames-") + QString(output).remove(QLatin1Char('#')));
    QVERIFY(QDir().mkpath(folder));
    const Result r = runFacet(args({"render", "--mesh", "cube", "--material", "gold", "--roughness", "0.3",
                                  "--background", "env", "--size", "48x40", "--turntable", "3"})
        + QStringList {QStringLiteral("--turntable-subject"), subject, QStringLiteral("-o"),
            QDir(folder).filePath(output)});
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const QStringList written = QDir(folder).entryList(QDir::Files, QDir::Name);
    QCOMPARE(written.size(), 3);
    std::vector<Image> frames;
    for (int index = 0; index < 3; ++index) {
        const QString frame = QString::fromStdString(
            turntableFramePath(QDir(folder).filePath(output).toStdString(), index, 3));
        QVERIFY2(QFileInfo::exists(frame),
            qPrintable(frame + QStringLiteral(" missing; written: ") + written.join(QStringLiteral(", "))));
        std::optional<Image> image = load(frame);
        QVERIFY(image);
        QCOMPARE(image->width(), 48);
        QCOMPARE(image->height(), 40);
        frames.push_back(std::move(*image));
    }
    for (int index = 1; index < 3; ++index) {
        // Every frame differs from the first ...
        QVERIFY2(largestDifference(frames[0], frames[std::size_t(index)]) > 0.05f,
            qPrintable(QStringLiteral("frame %1 is frame 0").arg(index)));
        // ... and the background moves only when the environment turns.
        const float border = largestBorderDifference(frames[0], frames[std::size_t(index)]);
        if (subject == QStringLiteral("object"))
            QVERIFY2(border < 1e-3f,
                qPrintable(QStringLiteral("frame %1: background moved by %2").arg(index).arg(border)));
        else
            QVERIFY2(border > 0.02f,
                qPrintable(QStringLiteral("frame %1: background still (%2)").arg(index).arg(border)));
    }
}

void TurntableCommandTest::transparentFramesKeepTheirAlpha()
{
    const QString output = path(QStringLiteral("clear.png"));
    const Result r = runFacet(
        args({"render", "--background", "transparent", "--size", "32x32", "--turntable", "2", "-o"})
        << output);
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    for (int index = 0; index < 2; ++index) {
        std::optional<Image> frame
            = load(QString::fromStdString(turntableFramePath(output.toStdString(), index, 2)));
        QVERIFY(frame);
        QCOMPARE(frame->at(0, 0).a, 0.0f); // a corner: background
        QCOMPARE(frame->at(16, 16).a, 1.0f); // the sphere
    }
}

void TurntableCommandTest::aVideoWithFfmpeg()
{
    const QString ffmpeg = QStandardPaths::findExecutable(QStringLiteral("ffmpeg"));
    if (ffmpeg.isEmpty())
        QSKIP("ffmpeg is not installed (Debian package ffmpeg): the video is not encoded here");
    for (const char* name : {"turn.mp4", "turn.webm"}) {
        const QString output = path(QLatin1String(name));
        // An odd size: yuv420p needs even sides, the encoder pads.
        const Result r = runFacet(
            args({"render", "--size", "33x25", "--turntable", "4", "--fps", "12", "-o"}) << output);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(QFileInfo(output).size() > 0);
        QCOMPARE(QDir(m_dir.path()).entryList({QStringLiteral("turn_*")}, QDir::Files).size(),
            0); // no frames left
        const QString ffprobe = QStandardPaths::findExecutable(QStringLiteral("ffprobe"));
        if (ffprobe.isEmpty())
            continue;
        const Result probe = facet::test::runWithoutDisplay(ffprobe,
            args({"-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                "stream=nb_read_frames,width,height,r_frame_rate", "-of", "csv=p=0"})
                << output);
        QCOMPARE(probe.exitCode, 0);
        QCOMPARE(probe.out.trimmed(), QStringLiteral("34,26,12/1,4"));
    }
}

void TurntableCommandTest::withoutFfmpegItSaysHow()
{
    const QString output = path(QStringLiteral("missing.mp4"));
    QProcessEnvironment environment;
    environment.insert(QStringLiteral("FACET_FFMPEG"), path(QStringLiteral("no-such-ffmpeg")));
    const Result r = runFacet(args({"render", "--turntable", "4", "-o"}) << output, environment);
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(
        r.err.contains(QStringLiteral("missing.mp4 needs ffmpeg, which is not installed (Debian: sudo apt "
                                      "install ffmpeg); or write the frames: -o "))
            && r.err.contains(QStringLiteral("missing_####.png")),
        qPrintable(r.err));
    QVERIFY(!QFileInfo::exists(output));
}

void TurntableCommandTest::aFailedEncodeLeavesTheFileAlone()
{
    const QString output = path(QStringLiteral("kept.mp4"));
    QVERIFY(facet::test::writeText(output, QByteArray("an earlier video")));
    QProcessEnvironment environment;
    environment.insert(QStringLiteral("FACET_FFMPEG"), QStringLiteral("/bin/false"));
    const Result r
        = runFacet(args({"render", "--size", "16x16", "--turntable", "2", "-o"}) << output, environment);
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(QStringLiteral("kept.mp4: ffmpeg failed")), qPrintable(r.err));
    QFile kept(output);
    QVERIFY(kept.open(QIODevice::ReadOnly));
    QCOMPARE(kept.readAll(), QByteArray("an earlier video"));
    QCOMPARE(QDir(m_dir.path()).entryList({QStringLiteral("kept*")}, QDir::Files).size(), 1); // no temporary
}

void TurntableCommandTest::wrongFlags_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("message");
    QTest::newRow("one frame") << args({"--turntable", "1", "-o", "t.png"})
                               << "--turntable: '1' is not a whole number from 2 to 3600";
    QTest::newRow("not a number") << args({"--turntable", "many", "-o", "t.png"})
                                  << "--turntable: 'many' is not a whole number from 2 to 3600";
    QTest::newRow("a subject") << args({"--turntable", "3", "--turntable-subject", "sky", "-o", "t.png"})
                               << "--turntable-subject: 'sky' is not object or environment";
    QTest::newRow("fps") << args({"--turntable", "3", "--fps", "0", "-o", "t.mp4"})
                         << "--fps: '0' is not a whole number from 1 to 120";
    QTest::newRow("fps without a turntable")
        << args({"--fps", "24", "-o", "t.png"}) << "--fps belongs to a turntable: add --turntable N";
    QTest::newRow("subject without a turntable")
        << args({"--turntable-subject", "object", "-o", "t.png"})
        << "--turntable-subject belongs to a turntable: add --turntable N";
    QTest::newRow("a video without a turntable")
        << args({"-o", "t.mp4"}) << "-o 't.mp4': a video is a turntable's: add --turntable N";
    QTest::newRow("a GIF") << args({"--turntable", "3", "-o",
        "t.gif"}) << "-o 't.gif': the output must be .exr, .png (numbered frames) or .mp4, .webm (a video)";
    QTest::newRow("with the ground truth") << args({"--turntable", "3", "--spp", "4", "-o", "t.png"})
                                           << "--turntable renders with the GPU renderer: leave out --spp";
}

void TurntableCommandTest::wrongFlags()
{
    QFETCH(QStringList, arguments);
    QFETCH(QString, message);
    const Result r = runFacet(QStringList {QStringLiteral("render")} + arguments);
    QCOMPARE(r.exitCode, 2);
    QCOMPARE(r.err.split(QLatin1Char('\n')).value(0), QStringLiteral("facet render: ") + message);
    QVERIFY(r.out.isEmpty());
}

QTEST_GUILESS_MAIN(TurntableCommandTest)
#include "TurntableCommandTest.moc"
