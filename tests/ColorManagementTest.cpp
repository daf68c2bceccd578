// OpenColorIO configs on the CPU (core/image/ColorManagement.h): the built-in config's displays and
// views, its transforms against values computed independently (the ACES 1.0 SDR video output of
// mid grey, the sRGB and Rec.1886 curves, identity for Raw), a config named by $OCIO, and the
// messages for broken configs and unknown names. tests/OcioGLTest.cpp holds the GPU pass to the
// CPU processors tested here.

#include "core/image/ColorManagement.h"
#include "core/image/ToneMap.h"
#include "core/project/Project.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include "TestSupport.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <sys/stat.h>

using namespace facet;
using facet::test::writeText;

namespace {

bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

bool has(const std::vector<std::string>& names, const std::string& name)
{
    return std::find(names.begin(), names.end(), name) != names.end();
}

std::array<float, 3> apply(const OCIO::ConstCPUProcessorRcPtr& processor, float r, float g, float b)
{
    std::array<float, 3> pixel {r, g, b};
    processor->applyRGB(pixel.data());
    return pixel;
}


// A minimal OCIO v2 config: one scene-linear space, a display with a square-root view (the
// inverse of an exponent of 2) and Raw, and a second display.
const char* const kSmallConfig = R"(ocio_profile_version: 2

roles:
  default: linear
  scene_linear: linear

file_rules:
  - !<Rule> {name: Default, colorspace: default}

displays:
  Test Monitor:
    - !<View> {name: Square root, colorspace: sqrt}
    - !<View> {name: Raw, colorspace: linear}
  Second Monitor:
    - !<View> {name: Raw, colorspace: linear}

active_displays: []
active_views: []

colorspaces:
  - !<ColorSpace>
    name: linear
  - !<ColorSpace>
    name: sqrt
    from_reference: !<ExponentTransform> {value: [2, 2, 2, 1], direction: inverse}
)";

// Restores $OCIO when a test function returns, however it returns.
class OcioVariableGuard {
public:
    OcioVariableGuard()
        : m_had(qEnvironmentVariableIsSet("OCIO"))
        , m_value(qgetenv("OCIO"))
    {
    }
    ~OcioVariableGuard()
    {
        if (m_had)
            qputenv("OCIO", m_value);
        else
            qunsetenv("OCIO");
    }
    OcioVariableGuard(const OcioVariableGuard&) = delete;
    OcioVariableGuard& operator=(const OcioVariableGuard&) = delete;

private:
    bool m_had;
    QByteArray m_value;
};

} // namespace

class ColorManagementTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void builtInListsDisplaysAndViews();
    void builtInConfigIsValid();
    void acesViewMidGreyAndShape();
    void untonemappedViewIsTheDisplayCurve();
    void rawViewIsIdentity();
    void unknownNamesListWhatExists();
    void environmentVariableSelectsTheConfig();
    void brokenConfigNamesTheFile();
    void specialFilesAreRefused_data();
    void specialFilesAreRefused();
    void projectOcioNamesAreCheckedAtLoad_data();
    void projectOcioNamesAreCheckedAtLoad();
};

void ColorManagementTest::builtInListsDisplaysAndViews()
{
    const ColorManagement builtIn = ColorManagement::builtIn();
    QCOMPARE(builtIn.source(), std::string(ColorManagement::kBuiltInSource));
    const std::vector<std::string> displays = builtIn.displays();
    QCOMPARE(displays, (std::vector<std::string> {"sRGB - Display", "Rec.1886 Rec.709 - Display"}));
    for (const std::string& display : displays) {
        std::string error;
        const std::optional<std::vector<std::string>> views = builtIn.views(display, &error);
        QVERIFY2(views, error.c_str());
        QCOMPARE(*views, (std::vector<std::string> {"ACES 1.0 - SDR Video", "Un-tone-mapped", "Raw"}));
    }
    QCOMPARE(builtIn.defaultDisplay(), std::string("sRGB - Display"));
    QCOMPARE(builtIn.defaultView("sRGB - Display"), std::string("ACES 1.0 - SDR Video"));
    // Facet's linear Rec.709 enters as the config's own linear Rec.709 space, no conversion.
    QVERIFY2(contains(builtIn.workingSpaceDescription(), "Linear Rec.709 (sRGB)"),
        builtIn.workingSpaceDescription().c_str());
    // Two loads are the same content: render/ caches by this key.
    QCOMPARE(ColorManagement::builtIn().identity(), builtIn.identity());
}

void ColorManagementTest::builtInConfigIsValid()
{
    // builtIn() falls back to OCIO's raw config when its own does not validate; that fallback has
    // other displays, so the test above would fail too, but this names OCIO's reason.
    const ColorManagement builtIn = ColorManagement::builtIn();
    try {
        builtIn.config()->validate();
    } catch (const OCIO::Exception& e) {
        QFAIL(e.what());
    }
}

void ColorManagementTest::acesViewMidGreyAndShape()
{
    const ColorManagement builtIn = ColorManagement::builtIn();
    std::string error;
    const OCIO::ConstCPUProcessorRcPtr aces
        = builtIn.cpuProcessor("sRGB - Display", "ACES 1.0 - SDR Video", &error);
    QVERIFY2(aces, error.c_str());

    // Expected mid grey, from the ACES 1.0 CTL (RRT.ctl, ODT.Academy.Rec709_100nits_dim.ctl): the
    // RRT's segmented spline maps 0.18 to its mid point, 4.8 cd/m^2 (48-nit normalised); the ODT's
    // 48-nit spline keeps 4.8; Y_2_linCV with white 48 and black 0.02 gives
    // (4.8 - 0.02) / (48 - 0.02) = 0.099625; the dark-to-dim surround step raises Y to 0.9811:
    // 0.104064; grey needs no glow (YC = 0.18 > 2 * 0.08) nor red modifier (no saturation). The
    // sRGB curve then gives 1.055 * 0.104064^(1/2.4) - 0.055 = 0.355954. OCIO agrees to 6 digits;
    // 2e-4 allows for its float evaluation of the splines (as B-spline curves) and matrices.
    const double expectedLinear = std::pow((4.8 - 0.02) / (48.0 - 0.02), 0.9811);
    const double expected = tonemap::linearToSrgb(expectedLinear);
    const std::array<float, 3> grey = apply(aces, 0.18f, 0.18f, 0.18f);
    QVERIFY2(std::abs(grey[0] - expected) < 2e-4,
        ("0.18 -> " + std::to_string(grey[0]) + ", expected " + std::to_string(expected)).c_str());
    // Grey in, grey out.
    QVERIFY(std::abs(grey[0] - grey[1]) < 1e-5 && std::abs(grey[1] - grey[2]) < 1e-5);

    // 0 -> 0 (the ODT's black, 0.02 nits, sits at code value 0).
    const std::array<float, 3> black = apply(aces, 0.0f, 0.0f, 0.0f);
    QVERIFY2(std::abs(black[0]) < 1e-4, std::to_string(black[0]).c_str());
    // Non-decreasing along a grey ramp 1e-5 .. 1e4 (half-stop steps), finite, and bright values
    // reach white (16 = 6.5 stops over mid grey is above 0.99).
    double previous = -1.0;
    for (double ev = -16.5; ev <= 13.5; ev += 0.5) {
        const auto x = float(std::exp2(ev));
        const std::array<float, 3> out = apply(aces, x, x, x);
        QVERIFY2(std::isfinite(out[0]), std::to_string(x).c_str());
        QVERIFY2(out[0] >= previous - 1e-6, ("not monotonic at " + std::to_string(x)).c_str());
        previous = out[0];
    }
    QVERIFY(apply(aces, 16.0f, 16.0f, 16.0f)[0] > 0.99f);
    // A saturated colour stays finite and non-negative.
    const std::array<float, 3> red = apply(aces, 1000.0f, 0.0f, 0.0f);
    for (float c : red)
        QVERIFY2(std::isfinite(c) && c >= -1e-4f, std::to_string(c).c_str());
}

void ColorManagementTest::untonemappedViewIsTheDisplayCurve()
{
    // "Un-tone-mapped" is colorimetric: linear Rec.709 -> XYZ -> the display's primaries (the
    // same, so grey stays grey) -> its curve. Grey x must come out as the sRGB curve of x
    // (core/image/ToneMap.h, IEC 61966-2-1) and as x^(1/2.4) on the Rec.1886 display. 1e-4: the
    // Bradford round trip through ACES2065-1 in float.
    const ColorManagement builtIn = ColorManagement::builtIn();
    std::string error;
    const OCIO::ConstCPUProcessorRcPtr srgb
        = builtIn.cpuProcessor("sRGB - Display", "Un-tone-mapped", &error);
    QVERIFY2(srgb, error.c_str());
    const OCIO::ConstCPUProcessorRcPtr rec1886
        = builtIn.cpuProcessor("Rec.1886 Rec.709 - Display", "Un-tone-mapped", &error);
    QVERIFY2(rec1886, error.c_str());
    for (double x : {0.0, 0.001, 0.002, 0.01, 0.18, 0.5, 1.0}) {
        const std::array<float, 3> s = apply(srgb, float(x), float(x), float(x));
        const std::array<float, 3> r = apply(rec1886, float(x), float(x), float(x));
        for (int c = 0; c < 3; ++c) {
            QVERIFY2(std::abs(s[c] - tonemap::linearToSrgb(x)) < 1e-4,
                ("sRGB " + std::to_string(x) + " -> " + std::to_string(s[c])).c_str());
            QVERIFY2(std::abs(r[c] - std::pow(x, 1.0 / 2.4)) < 1e-4,
                ("Rec.1886 " + std::to_string(x) + " -> " + std::to_string(r[c])).c_str());
        }
    }
}

void ColorManagementTest::rawViewIsIdentity()
{
    const ColorManagement builtIn = ColorManagement::builtIn();
    std::string error;
    const OCIO::ConstCPUProcessorRcPtr raw = builtIn.cpuProcessor("sRGB - Display", "Raw", &error);
    QVERIFY2(raw, error.c_str());
    QVERIFY(raw->isNoOp());
    for (const std::array<float, 3>& in : {std::array<float, 3> {0.0f, 1e-4f, 0.18f},
             std::array<float, 3> {1.0f, 16.0f, 1000.0f}, std::array<float, 3> {0.25f, 0.5f, 2.0f}}) {
        const std::array<float, 3> out = apply(raw, in[0], in[1], in[2]);
        QCOMPARE(out, in);
    }
}

void ColorManagementTest::unknownNamesListWhatExists()
{
    const ColorManagement builtIn = ColorManagement::builtIn();
    std::string error;
    QVERIFY(!builtIn.displayProcessor("sRGB - Display", "Filmic", &error));
    QVERIFY2(contains(error, "ColorManagement::displayProcessor: "), error.c_str());
    QVERIFY2(contains(error, "no view \"Filmic\""), error.c_str());
    QVERIFY2(contains(error, "\"ACES 1.0 - SDR Video\", \"Un-tone-mapped\", \"Raw\""), error.c_str());

    error.clear();
    QVERIFY(!builtIn.cpuProcessor("P3 Cinema", "Raw", &error));
    QVERIFY2(contains(error, "ColorManagement::cpuProcessor: "), error.c_str());
    QVERIFY2(contains(error, "unknown display \"P3 Cinema\""), error.c_str());
    QVERIFY2(contains(error, "\"sRGB - Display\", \"Rec.1886 Rec.709 - Display\""), error.c_str());

    error.clear();
    QVERIFY(!builtIn.views("P3 Cinema", &error));
    QVERIFY2(contains(error, "ColorManagement::views: unknown display \"P3 Cinema\""), error.c_str());
}

void ColorManagementTest::environmentVariableSelectsTheConfig()
{
    const OcioVariableGuard guard;
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = QDir(dir.path()).filePath(QStringLiteral("small.ocio"));
    QVERIFY(writeText(path, kSmallConfig));

    qputenv("OCIO", QFile::encodeName(path));
    std::string error;
    const std::optional<ColorManagement> fromEnv = ColorManagement::fromEnvironment(&error);
    QVERIFY2(fromEnv, error.c_str());
    QCOMPARE(fromEnv->source(), path.toStdString());
    QCOMPARE(fromEnv->displays(), (std::vector<std::string> {"Test Monitor", "Second Monitor"}));
    const std::optional<std::vector<std::string>> views = fromEnv->views("Test Monitor", &error);
    QVERIFY2(views, error.c_str());
    QVERIFY(has(*views, "Square root") && has(*views, "Raw"));
    QVERIFY(!has(fromEnv->displays(), "sRGB - Display")); // not the built-in config
    QVERIFY(fromEnv->identity() != ColorManagement::builtIn().identity());
    // The view really is the file's: x^(1/2).
    const OCIO::ConstCPUProcessorRcPtr root = fromEnv->cpuProcessor("Test Monitor", "Square root", &error);
    QVERIFY2(root, error.c_str());
    const std::array<float, 3> out = apply(root, 0.25f, 0.04f, 1.0f);
    QVERIFY(std::abs(out[0] - 0.5f) < 1e-5f && std::abs(out[1] - 0.2f) < 1e-5f
        && std::abs(out[2] - 1.0f) < 1e-5f);

    // An empty or unset variable means the built-in config.
    qputenv("OCIO", QByteArray());
    const std::optional<ColorManagement> empty = ColorManagement::fromEnvironment(&error);
    QVERIFY2(empty, error.c_str());
    QCOMPARE(empty->source(), std::string(ColorManagement::kBuiltInSource));
    qunsetenv("OCIO");
    const std::optional<ColorManagement> unset = ColorManagement::fromEnvironment(&error);
    QVERIFY2(unset, error.c_str());
    QCOMPARE(unset->source(), std::string(ColorManagement::kBuiltInSource));
}

void ColorManagementTest::brokenConfigNamesTheFile()
{
    const OcioVariableGuard guard;
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString broken = QDir(dir.path()).filePath(QStringLiteral("broken.ocio"));
    QVERIFY(writeText(broken, "ocio_profile_version: 2\ncolorspaces: [ {name: a\n  displays: ]]\n"));
    std::string error;
    QVERIFY(!ColorManagement::fromFile(broken.toStdString(), &error));
    QVERIFY2(contains(error,
                 "ColorManagement::fromFile: cannot load OCIO config '" + broken.toStdString() + "': "),
        error.c_str());
    // OCIO's own explanation follows (it is more than the prefix).
    QVERIFY2(error.size() > error.find("': ") + 10, error.c_str());

    // A config that parses but names a colour space it does not define fails validation.
    const QString invalid = QDir(dir.path()).filePath(QStringLiteral("invalid.ocio"));
    QVERIFY(writeText(invalid, QByteArray(kSmallConfig).replace("colorspace: sqrt", "colorspace: missing")));
    error.clear();
    QVERIFY(!ColorManagement::fromFile(invalid.toStdString(), &error));
    QVERIFY2(contains(error, invalid.toStdString()), error.c_str());

    // Missing file.
    const std::string missing = QDir(dir.path()).filePath(QStringLiteral("missing.ocio")).toStdString();
    error.clear();
    QVERIFY(!ColorManagement::fromFile(missing, &error));
    QVERIFY2(contains(error, "'" + missing + "'"), error.c_str());

    // Through $OCIO the message says where the path came from.
    qputenv("OCIO", QFile::encodeName(broken));
    error.clear();
    QVERIFY(!ColorManagement::fromEnvironment(&error));
    QVERIFY2(
        contains(error, broken.toStdString()) && contains(error, "OCIO environment variable"), error.c_str());
}

// Issue 29: $OCIO naming a FIFO blocked `facet render` and the window's start forever inside
// OCIO's open. The config goes through the file check every input does.
void ColorManagementTest::specialFilesAreRefused_data()
{
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("reason");
    QTest::newRow("a FIFO") << QStringLiteral("fifo") << QStringLiteral("is not a regular file");
    QTest::newRow("/dev/zero") << QStringLiteral("zero") << QStringLiteral("is not a regular file");
    QTest::newRow("a folder") << QStringLiteral("folder") << QStringLiteral("folder");
    QTest::newRow("a link loop") << QStringLiteral("loop") << QStringLiteral("loop of symbolic links");
}

void ColorManagementTest::specialFilesAreRefused()
{
    QFETCH(QString, kind);
    QFETCH(QString, reason);
    const OcioVariableGuard guard;
    QTemporaryDir dir;
    QString path = QDir(dir.path()).filePath(QStringLiteral("config.ocio"));
    if (kind == QLatin1String("fifo"))
        QCOMPARE(::mkfifo(QFile::encodeName(path).constData(), 0600), 0);
    else if (kind == QLatin1String("zero"))
        path = QStringLiteral("/dev/zero");
    else if (kind == QLatin1String("folder"))
        QVERIFY(QDir().mkpath(path));
    else
        QVERIFY(QFile::link(path, path));
    qputenv("OCIO", QFile::encodeName(path));
    std::string error;
    QVERIFY(!ColorManagement::fromEnvironment(&error));
    QVERIFY2(contains(error, path.toStdString()) && contains(error, reason.toStdString())
            && contains(error, "OCIO environment variable"),
        error.c_str());
}

void ColorManagementTest::projectOcioNamesAreCheckedAtLoad_data()
{
    QTest::addColumn<QString>("display");
    QTest::addColumn<QString>("view");
    QTest::addColumn<QString>("message"); // empty: loads
    QTest::newRow("built-in display and view")
        << QStringLiteral("sRGB - Display") << QStringLiteral("ACES 1.0 - SDR Video") << QString();
    QTest::newRow("unknown display") << QStringLiteral("Cinema") << QStringLiteral("Raw")
                                     << QStringLiteral("view.ocioDisplay: unknown display \"Cinema\"");
    QTest::newRow("unknown view") << QStringLiteral("sRGB - Display") << QStringLiteral("Filmic")
                                  << QStringLiteral("view.ocioView: display \"sRGB - Display\" of ");
}

// Issue 29: a project's OCIO display and view were checked only when a PNG was drawn; they are
// checked as the project opens, naming the field.
void ColorManagementTest::projectOcioNamesAreCheckedAtLoad()
{
    QFETCH(QString, display);
    QFETCH(QString, view);
    QFETCH(QString, message);
    // ColorManagement::shared() reads $OCIO once per process: the built-in config here.
    const OcioVariableGuard guard;
    qunsetenv("OCIO");
    QTemporaryDir dir;
    const QString path = QDir(dir.path()).filePath(QStringLiteral("p.json"));
    QVERIFY(writeText(path,
        QStringLiteral("{\"format\": \"facet-project\", \"version\": 1, \"view\": {\"ocioDisplay\": \"%1\", "
                       "\"ocioView\": \"%2\"}}")
            .arg(display, view)
            .toUtf8()));
    std::string error;
    const std::optional<Project> project = Project::load(path.toStdString(), &error);
    if (message.isEmpty()) {
        QVERIFY2(project, error.c_str());
        return;
    }
    QVERIFY(!project);
    QVERIFY2(contains(error, path.toStdString()) && contains(error, message.toStdString())
            && contains(error, "available: "),
        error.c_str());
}

QTEST_GUILESS_MAIN(ColorManagementTest)
#include "ColorManagementTest.moc"
