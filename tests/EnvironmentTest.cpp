// core/ibl/Environment: the equirect convention of docs/architecture.md, rotation, sampling, hashing, the
// uniform and built-in environments, loading the CC0 HDRIs and parsing specs.

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <vector>

#include <QTemporaryDir>
#include <QtTest/QTest>

#include <glm/geometric.hpp>

#include "TestSupport.h"
#include "core/ibl/Environment.h"
#include "core/ibl/EnvironmentSampler.h"

// QCOMPARE prints values it knows; teach it glm's vectors (found by argument-dependent lookup).
namespace glm {
char* toString(const glm::dvec3& v)
{
    return qstrdup(QByteArray("(" + QByteArray::number(v.x, 'g', 17) + ", " + QByteArray::number(v.y, 'g', 17)
        + ", " + QByteArray::number(v.z, 'g', 17) + ")")
                       .constData());
}
} // namespace glm

using facet::ColorEncoding;
using facet::directionFromEquirectUv;
using facet::Environment;
using facet::equirectUvFromDirection;
using facet::Image;

namespace {

constexpr double kPi = std::numbers::pi;

bool near(const glm::dvec3& a, const glm::dvec3& b, double tolerance)
{
    return glm::length(a - b) <= tolerance;
}

#define COMPARE_VEC(actual, expected, tolerance)                                                             \
    QVERIFY2(near((actual), (expected), (tolerance)),                                                        \
        qPrintable(QStringLiteral("%1 != %2")                                                                \
                       .arg(QLatin1String(glm::toString(glm::dvec3(actual))))                                \
                       .arg(QLatin1String(glm::toString(glm::dvec3(expected))))))

// Directions spread evenly over the sphere (a Fibonacci lattice), poles excluded.
std::vector<glm::dvec3> sphereDirections(int count)
{
    std::vector<glm::dvec3> directions;
    const double golden = kPi * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < count; ++i) {
        const double y = 1.0 - 2.0 * (i + 0.5) / count;
        const double r = std::sqrt(1.0 - y * y);
        directions.push_back({r * std::cos(golden * i), y, r * std::sin(golden * i)});
    }
    return directions;
}

// Mean radiance over the sphere, each texel weighted by its solid angle (cos of its latitude).
glm::dvec3 sphereMean(const Image& image)
{
    glm::dvec3 sum(0.0);
    double weights = 0.0;
    for (int y = 0; y < image.height(); ++y) {
        const double weight = std::cos(((y + 0.5) / image.height() - 0.5) * kPi);
        for (int x = 0; x < image.width(); ++x) {
            sum += glm::dvec3(glm::vec3(image.at(x, y))) * weight;
            weights += weight;
        }
    }
    return sum / weights;
}

// Integral of radiance over the solid angle of texels brighter than `threshold`.
double powerAbove(const Image& image, float threshold)
{
    double power = 0.0;
    const double texelWidth = 2.0 * kPi / image.width();
    const double texelHeight = kPi / image.height();
    for (int y = 0; y < image.height(); ++y) {
        const double solidAngle
            = texelWidth * texelHeight * std::cos(((y + 0.5) / image.height() - 0.5) * kPi);
        for (int x = 0; x < image.width(); ++x)
            if (image.at(x, y).y > threshold)
                power += double(image.at(x, y).y) * solidAngle;
    }
    return power;
}

bool allFiniteNonNegative(const Image& image)
{
    for (std::size_t i = 0; i < image.pixelCount(); ++i)
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(image.data()[i][c]) || image.data()[i][c] < 0.0f)
                return false;
    return true;
}

} // namespace

class EnvironmentTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void axesMapAsDesigned();
    void imageRowsMatchV();
    void directionUvRoundTrip();
    void brightTopRowLightsUp();
    void rotationMovesFeaturesAsDocumented();
    void intensityScales();
    void bilinearAndNearest();
    void contentHashIsStableAndSensitive();
    void constructorSanitises();
    void uniformIsConstant();
    void builtinsAreSane_data();
    void builtinsAreSane();
    void studioHasItsLights();
    void skyHasASunAt35Degrees();
    void loadsStudioHdriAndSanitisesIt();
    void loadWarnsAboutAspectAndDecodesSrgb();
    void loadErrorsNameTheFile();
    void fromSpecParses();
    void fromSpecRejectsBadValues_data();
    void fromSpecRejectsBadValues();
    void samplingTablesLayout_data();
    void samplingTablesLayout();
    void samplingTablesKeepTheMaxFilter_data();
    void samplingTablesKeepTheMaxFilter();
};

void EnvironmentTest::axesMapAsDesigned()
{
    const double e = 1e-12;
    const glm::dvec2 px = equirectUvFromDirection({1, 0, 0});
    QVERIFY(std::abs(px.x - 0.5) < e && std::abs(px.y - 0.5) < e);
    QVERIFY(std::abs(equirectUvFromDirection({0, 0, 1}).x - 0.75) < e);
    QVERIFY(std::abs(equirectUvFromDirection({0, 0, -1}).x - 0.25) < e);
    const double uMinusX = equirectUvFromDirection({-1, 0, 0}).x; // the seam: 0 or 1
    QVERIFY(std::abs(uMinusX) < e || std::abs(uMinusX - 1.0) < e);
    QVERIFY(std::abs(equirectUvFromDirection({0, 1, 0}).y - 1.0) < e);
    QVERIFY(std::abs(equirectUvFromDirection({0, -1, 0}).y) < e);
    // 45 degrees up: v = 0.75.
    QVERIFY(std::abs(equirectUvFromDirection(glm::normalize(glm::dvec3(1, 1, 0))).y - 0.75) < e);

    COMPARE_VEC(directionFromEquirectUv({0.5, 0.5}), glm::dvec3(1, 0, 0), e);
    COMPARE_VEC(directionFromEquirectUv({0.75, 0.5}), glm::dvec3(0, 0, 1), e);
    COMPARE_VEC(directionFromEquirectUv({0.25, 0.5}), glm::dvec3(0, 0, -1), e);
    COMPARE_VEC(directionFromEquirectUv({0.0, 0.5}), glm::dvec3(-1, 0, 0), e);
    COMPARE_VEC(directionFromEquirectUv({0.3, 1.0}), glm::dvec3(0, 1, 0), e);
    COMPARE_VEC(directionFromEquirectUv({0.3, 0.0}), glm::dvec3(0, -1, 0), e);
}

void EnvironmentTest::imageRowsMatchV()
{
    // Row y holds v = 1 - (y + 0.5) / H: row 0 is up, the last row down. A 4x2 image with a
    // distinct value per row shows which row each pole reads.
    Image image(4, 2);
    for (int x = 0; x < 4; ++x) {
        image.at(x, 0) = glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
        image.at(x, 1) = glm::vec4(0.0f, 0.0f, 1.0f, 1.0f);
    }
    const Environment environment(image);
    COMPARE_VEC(environment.radianceNearest({0, 1, 0}), glm::dvec3(1, 0, 0), 0.0);
    COMPARE_VEC(environment.radianceNearest({0, -1, 0}), glm::dvec3(0, 0, 1), 0.0);
    COMPARE_VEC(environment.radianceNearest(glm::normalize(glm::dvec3(1, 0.1, 0))), glm::dvec3(1, 0, 0), 0.0);
    COMPARE_VEC(
        environment.radianceNearest(glm::normalize(glm::dvec3(1, -0.1, 0))), glm::dvec3(0, 0, 1), 0.0);
}

void EnvironmentTest::directionUvRoundTrip()
{
    for (const glm::dvec3& d : sphereDirections(2000)) {
        const glm::dvec2 uv = equirectUvFromDirection(d);
        QVERIFY(uv.x >= 0.0 && uv.x <= 1.0 && uv.y >= 0.0 && uv.y <= 1.0);
        COMPARE_VEC(directionFromEquirectUv(uv), d, 1e-12);
    }
    for (int i = 0; i <= 20; ++i) {
        for (int j = 1; j < 20; ++j) {
            const glm::dvec2 uv(0.025 + 0.95 * i / 20.0, j / 20.0);
            const glm::dvec3 d = directionFromEquirectUv(uv);
            QVERIFY(std::abs(glm::length(d) - 1.0) < 1e-12);
            const glm::dvec2 back = equirectUvFromDirection(d);
            QVERIFY(std::abs(back.x - uv.x) < 1e-12 && std::abs(back.y - uv.y) < 1e-12);
        }
    }
}

void EnvironmentTest::brightTopRowLightsUp()
{
    Image image(16, 8, glm::vec4(0.1f, 0.1f, 0.1f, 1.0f));
    for (int x = 0; x < 16; ++x)
        image.at(x, 0) = glm::vec4(10.0f, 10.0f, 10.0f, 1.0f);
    const Environment environment(image, "top");
    COMPARE_VEC(environment.radiance({0, 1, 0}), glm::dvec3(10.0), 1e-9);
    COMPARE_VEC(environment.radianceNearest({0, 1, 0}), glm::dvec3(10.0), 1e-9);
    COMPARE_VEC(environment.radiance({0, -1, 0}), glm::dvec3(0.1), 1e-6);
    COMPARE_VEC(environment.radiance({1, 0, 0}), glm::dvec3(0.1), 1e-6);
    COMPARE_VEC(environment.radiance({0, 0, -1}), glm::dvec3(0.1), 1e-6);
    // Between the centres of rows 0 and 1 (v = 1 - 1/8) the light falls off linearly.
    const glm::dvec3 between = directionFromEquirectUv({0.3, 1.0 - 1.0 / 8.0});
    COMPARE_VEC(environment.radiance(between), glm::dvec3(5.05), 1e-5);
}

void EnvironmentTest::rotationMovesFeaturesAsDocumented()
{
    // A 2x2 block of bright texels centred on +X (u = 0.5, v = 0.5) of a 64x32 image.
    Image image(64, 32, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    for (int y = 15; y <= 16; ++y)
        for (int x = 31; x <= 32; ++x)
            image.at(x, y) = glm::vec4(100.0f, 100.0f, 100.0f, 1.0f);
    Environment environment(image);
    COMPARE_VEC(environment.radiance({1, 0, 0}), glm::dvec3(100.0), 1e-9);
    QCOMPARE(environment.radiance({0, 0, -1}), glm::dvec3(0.0));

    // +90 degrees: counter-clockwise seen from above, +X goes to -Z.
    environment.setRotationDegrees(90.0);
    COMPARE_VEC(environment.toWorldFrame({1, 0, 0}), glm::dvec3(0, 0, -1), 1e-12);
    COMPARE_VEC(environment.toImageFrame({0, 0, -1}), glm::dvec3(1, 0, 0), 1e-12);
    COMPARE_VEC(environment.toWorldFrame({0, 0, 1}), glm::dvec3(1, 0, 0), 1e-12);
    COMPARE_VEC(environment.toWorldFrame({0, 1, 0}), glm::dvec3(0, 1, 0), 1e-12);
    COMPARE_VEC(environment.radiance({0, 0, -1}), glm::dvec3(100.0), 1e-6);
    COMPARE_VEC(environment.radianceNearest({0, 0, -1}), glm::dvec3(100.0), 0.0);
    QCOMPARE(environment.radiance({1, 0, 0}), glm::dvec3(0.0));
    QCOMPARE(environment.radiance({0, 0, 1}), glm::dvec3(0.0));

    // The two frames are inverse to each other at any angle.
    environment.setRotationDegrees(-37.5);
    for (const glm::dvec3& d : sphereDirections(50))
        COMPARE_VEC(environment.toImageFrame(environment.toWorldFrame(d)), d, 1e-12);
    // A full turn is no turn.
    environment.setRotationDegrees(360.0);
    COMPARE_VEC(environment.radiance({1, 0, 0}), glm::dvec3(100.0), 1e-6);
    // The hash is about the pixels only.
    QCOMPARE(environment.contentHash(), Environment(image).contentHash());
}

void EnvironmentTest::intensityScales()
{
    Environment environment = Environment::builtin(Environment::Builtin::Sky, 64);
    const glm::dvec3 direction = glm::normalize(glm::dvec3(0.3, 0.4, -0.5));
    const glm::dvec3 base = environment.radiance(direction);
    const glm::dvec3 baseNearest = environment.radianceNearest(direction);
    QVERIFY(base.x > 0.0);
    const std::uint64_t hash = environment.contentHash();
    environment.setIntensity(2.5);
    COMPARE_VEC(environment.radiance(direction), 2.5 * base, 1e-12);
    COMPARE_VEC(environment.radianceNearest(direction), 2.5 * baseNearest, 1e-12);
    environment.setIntensity(0.0);
    QCOMPARE(environment.radiance(direction), glm::dvec3(0.0));
    QCOMPARE(environment.contentHash(), hash);
}

void EnvironmentTest::bilinearAndNearest()
{
    // 4x2: column values 1, 2, 4, 8 in the top row, 16x that in the bottom row.
    // Texel centres: u = 0.125, 0.375, 0.625, 0.875; v = 0.75 (top), 0.25 (bottom).
    Image image(4, 2);
    const float columns[4] = {1.0f, 2.0f, 4.0f, 8.0f};
    for (int x = 0; x < 4; ++x) {
        image.at(x, 0) = glm::vec4(columns[x], 0.0f, 0.0f, 1.0f);
        image.at(x, 1) = glm::vec4(16.0f * columns[x], 0.0f, 0.0f, 1.0f);
    }
    const Environment environment(image);
    const auto bilinear = [&](double u, double v) {
        return environment.radiance(directionFromEquirectUv({u, v})).x;
    };
    const auto nearest = [&](double u, double v) {
        return environment.radianceNearest(directionFromEquirectUv({u, v})).x;
    };
    const double e = 1e-9;
    // At a texel centre both give the texel.
    QVERIFY(std::abs(bilinear(0.375, 0.75) - 2.0) < e);
    QVERIFY(std::abs(nearest(0.375, 0.75) - 2.0) < e);
    // Half way between columns 1 and 2: the mean, against one of them.
    QVERIFY(std::abs(bilinear(0.5, 0.75) - 3.0) < e);
    QVERIFY(std::abs(nearest(0.49, 0.75) - 2.0) < e);
    QVERIFY(std::abs(nearest(0.51, 0.75) - 4.0) < e);
    // A quarter of the way from column 2 to 3: 4 + 0.25 * (8 - 4).
    QVERIFY(std::abs(bilinear(0.6875, 0.75) - 5.0) < e);
    // Wrapping in u: u = 0.0625 lies between column 3 (u = -0.125) and column 0: 0.25*8 + 0.75*1.
    QVERIFY(std::abs(bilinear(0.0625, 0.75) - 2.75) < e);
    QVERIFY(std::abs(nearest(0.0625, 0.75) - 1.0) < e);
    QVERIFY(std::abs(nearest(0.99, 0.75) - 8.0) < e);
    // Between the rows (v = 0.5) at column 0's centre: mean of 1 and 16.
    QVERIFY(std::abs(bilinear(0.125, 0.5) - 8.5) < e);
    // Clamped in v: beyond the top row's centre nothing from the bottom row leaks in.
    QVERIFY(std::abs(bilinear(0.125, 0.9) - 1.0) < e);
    QVERIFY(std::abs(bilinear(0.125, 0.1) - 16.0) < e);
}

void EnvironmentTest::contentHashIsStableAndSensitive()
{
    Image image(8, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x)
            image.at(x, y) = glm::vec4(0.125f * float(x), 0.25f * float(y), 1.0f, 1.0f);
    const std::uint64_t hash = Environment(image).contentHash();
    // Pinned: the hash keys caches on disk, so it must not change between runs, builds or
    // machines. If the algorithm changes on purpose, update this value (old caches go stale).
    QCOMPARE(hash, Q_UINT64_C(0x0f2c7edbbf4bbf89));
    QCOMPARE(Environment(image, "another name").contentHash(), hash);

    // Alpha is not radiance.
    Image alpha = image;
    alpha.at(3, 2).w = 0.5f;
    QCOMPARE(Environment(alpha).contentHash(), hash);
    // One pixel, one channel, one bit.
    Image changed = image;
    changed.at(5, 1).y = std::nextafter(changed.at(5, 1).y, 2.0f);
    QVERIFY(Environment(changed).contentHash() != hash);
    Image blue = image;
    blue.at(0, 3).z = 0.5f;
    QVERIFY(Environment(blue).contentHash() != hash);
    // Same pixels, other shape.
    Image reshaped(4, 8);
    std::copy(image.data(), image.data() + image.pixelCount(), reshaped.data());
    QVERIFY(Environment(reshaped).contentHash() != hash);
    // Built-ins and uniforms: deterministic, distinct.
    QCOMPARE(Environment::uniform(glm::dvec3(1.0)).contentHash(),
        Environment::uniform(glm::dvec3(1.0)).contentHash());
    QVERIFY(Environment::uniform(glm::dvec3(1.0)).contentHash()
        != Environment::uniform(glm::dvec3(2.0)).contentHash());
}

void EnvironmentTest::constructorSanitises()
{
    // An image made in memory gets the same guarantee as a loaded one.
    Image image(8, 4, glm::vec4(1.0f));
    image.at(0, 0) = glm::vec4(std::nanf(""), -2.0f, std::numeric_limits<float>::infinity(), 1.0f);
    const Environment environment(image);
    QVERIFY(allFiniteNonNegative(environment.image()));
    QCOMPARE(glm::dvec3(glm::vec3(environment.image().at(0, 0))), glm::dvec3(0.0, 0.0, 65504.0));
}

void EnvironmentTest::uniformIsConstant()
{
    const Environment environment = Environment::uniform({0.5, 1.0, 2.0});
    QVERIFY(environment.isUniform());
    QVERIFY(!environment.isEmpty());
    QCOMPARE(environment.name(), std::string("uniform:0.5,1,2"));
    for (const glm::dvec3& d : sphereDirections(200)) {
        QCOMPARE(environment.radiance(d), glm::dvec3(0.5, 1.0, 2.0));
        QCOMPARE(environment.radianceNearest(d), glm::dvec3(0.5, 1.0, 2.0));
    }
    QCOMPARE(environment.radiance({0, 1, 0}), glm::dvec3(0.5, 1.0, 2.0));
    QVERIFY(!Environment::builtin(Environment::Builtin::Studio, 16).isUniform());
    QVERIFY(Environment().isEmpty());
    QCOMPARE(Environment().radiance({0, 1, 0}), glm::dvec3(0.0));
}

void EnvironmentTest::builtinsAreSane_data()
{
    QTest::addColumn<int>("which");
    QTest::addColumn<QString>("name");
    QTest::newRow("studio") << int(Environment::Builtin::Studio) << QStringLiteral("studio");
    QTest::newRow("sky") << int(Environment::Builtin::Sky) << QStringLiteral("sky");
}

void EnvironmentTest::builtinsAreSane()
{
    QFETCH(int, which);
    QFETCH(QString, name);
    const auto builtin = Environment::Builtin(which);
    const Environment environment = Environment::builtin(builtin, 256);
    QCOMPARE(environment.name(), name.toStdString());
    QCOMPARE(Environment::builtinName(builtin), name.toStdString());
    QCOMPARE(Environment::builtinFromName(name.toStdString()), std::optional(builtin));
    QCOMPARE(environment.image().width(), 256);
    QCOMPARE(environment.image().height(), 128);
    QCOMPARE(Environment::builtin(builtin).image().width(), 512);
    QVERIFY(allFiniteNonNegative(environment.image()));
    // Deterministic: the same pixels every time.
    QCOMPARE(Environment::builtin(builtin, 256).contentHash(), environment.contentHash());
    QVERIFY(Environment::builtin(builtin, 128).contentHash() != environment.contentHash());
    // An exposure that suits the default camera: mean radiance between 0.3 and 3, grey-ish.
    const glm::dvec3 mean = sphereMean(environment.image());
    QVERIFY2(mean.x > 0.3 && mean.x < 3.0 && mean.y > 0.3 && mean.y < 3.0 && mean.z > 0.3 && mean.z < 3.0,
        glm::toString(mean));
    // Smooth: no texel stands out from all four neighbours by more than 50x (a lone aliasing
    // hot pixel would), except inside the lights themselves.
    const Image& image = environment.image();
    int hotPixels = 0;
    for (int y = 1; y + 1 < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const float centre = image.at(x, y).y;
            const float neighbours = std::max({image.at((x + 1) % image.width(), y).y,
                image.at((x + image.width() - 1) % image.width(), y).y, image.at(x, y - 1).y,
                image.at(x, y + 1).y});
            if (centre > 50.0f * neighbours)
                ++hotPixels;
        }
    }
    QCOMPARE(hotPixels, 0);
}

void EnvironmentTest::studioHasItsLights()
{
    const Environment studio = Environment::builtin(Environment::Builtin::Studio, 256);
    // Soft box overhead.
    const glm::dvec3 up = studio.radiance({0, 1, 0});
    QVERIFY2(up.y > 10.0 && up.y < 20.0, glm::toString(up));
    // Strip lights on the sides (toward +X and -X, 20 degrees up).
    const double elevation = 20.0 * kPi / 180.0;
    for (double side : {1.0, -1.0}) {
        const glm::dvec3 strip = studio.radiance({side * std::cos(elevation), std::sin(elevation), 0.0});
        QVERIFY2(strip.y > 5.0, glm::toString(strip));
    }
    // A grey room between them.
    const glm::dvec3 wall = studio.radiance(glm::normalize(glm::dvec3(0.0, 0.1, -1.0)));
    QVERIFY2(wall.y > 0.3 && wall.y < 0.6, glm::toString(wall));
    QVERIFY(std::abs(wall.x - wall.z) < 0.01);
    // A warm floor.
    const glm::dvec3 floor = studio.radiance({0, -1, 0});
    QVERIFY2(floor.x > floor.z && floor.y > 0.3 && floor.y < 0.7, glm::toString(floor));
}

void EnvironmentTest::skyHasASunAt35Degrees()
{
    const Environment sky = Environment::builtin(Environment::Builtin::Sky, 512);
    const Image& image = sky.image();
    // The brightest texel is the sun, a few hundred, at 35 degrees elevation.
    int brightestX = 0, brightestY = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (image.at(x, y).y > image.at(brightestX, brightestY).y) {
                brightestX = x;
                brightestY = y;
            }
    const float peak = image.at(brightestX, brightestY).y;
    QVERIFY2(peak > 200.0f && peak < 1000.0f, qPrintable(QString::number(peak)));
    const double elevationDegrees = (0.5 - (brightestY + 0.5) / image.height()) * 180.0;
    QVERIFY2(std::abs(elevationDegrees - 35.0) < 1.5, qPrintable(QString::number(elevationDegrees)));
    // A disc a few degrees wide: several texels (0.7 degrees each here), not one hot pixel.
    int sunTexels = 0;
    for (std::size_t i = 0; i < image.pixelCount(); ++i)
        if (image.data()[i].y > 100.0f)
            ++sunTexels;
    QVERIFY2(sunTexels >= 12 && sunTexels <= 200, qPrintable(QString::number(sunTexels)));
    // Anti-aliased: the sun's power (all above 10, which sky and aureole never reach) does not
    // depend on the resolution, even where a texel is wider than the sun (64: 5.6 degrees).
    // Measured: within 4% from 48 to 1024 wide; point sampling misses the sun below 100.
    const double power512 = powerAbove(image, 10.0f);
    QVERIFY2(power512 > 1.0 && power512 < 2.5, qPrintable(QString::number(power512)));
    for (int width : {64, 100, 128}) {
        const double power
            = powerAbove(Environment::builtin(Environment::Builtin::Sky, width).image(), 10.0f);
        QVERIFY2(std::abs(power / power512 - 1.0) < 0.06,
            qPrintable(QStringLiteral("%1 wide: %2 vs %3").arg(width).arg(power).arg(power512)));
    }
    // Blue-ish sky of 1-3 near the horizon, dimmer ground.
    const glm::dvec3 horizon = sky.radiance(glm::normalize(glm::dvec3(-1.0, 0.1, -0.3)));
    QVERIFY2(horizon.z > horizon.x && horizon.y > 1.0 && horizon.y < 3.0, glm::toString(horizon));
    const glm::dvec3 zenith = sky.radiance({0, 1, 0});
    QVERIFY2(zenith.z > zenith.x && zenith.y < horizon.y, glm::toString(zenith));
    const glm::dvec3 ground = sky.radiance({0, -1, 0});
    QVERIFY2(ground.y > 0.15 && ground.y < 0.35, glm::toString(ground));
}

void EnvironmentTest::loadsStudioHdriAndSanitisesIt()
{
    const QString path = facet::test::hdriPath(QStringLiteral("studio"));
    FACET_REQUIRE_ASSET(path, "hdri/studio.exr");
    // The file itself has negative samples (DWAB ringing): see them through Image::load.
    facet::ImageLoadStats stats;
    std::string error;
    const std::optional<Image> raw = Image::load(path.toStdString(), &error, &stats);
    QVERIFY2(raw, error.c_str());
    QVERIFY(stats.negativeCount > 0);
    QCOMPARE(raw->sourceChannels(), 3);

    std::string warning;
    const std::optional<Environment> environment = Environment::load(path.toStdString(), &error, &warning);
    QVERIFY2(environment, error.c_str());
    QCOMPARE(environment->image().width(), 512);
    QCOMPARE(environment->image().height(), 256);
    QCOMPARE(environment->name(), path.toStdString());
    QVERIFY(allFiniteNonNegative(environment->image()));
    const std::string expected = path.toStdString() + ": replaced 0 NaN, 0 Inf, "
        + std::to_string(stats.negativeCount) + " negative samples";
    QVERIFY2(warning.find(expected) != std::string::npos, warning.c_str());
    QVERIFY2(warning.find("2:1") == std::string::npos, warning.c_str()); // it is 2:1
    // Stable: loading twice gives the same key.
    const std::optional<Environment> again = Environment::fromSpec(path.toStdString(), &error);
    QVERIFY2(again, error.c_str());
    QCOMPARE(again->contentHash(), environment->contentHash());
    QVERIFY(environment->contentHash() != Environment::builtin(Environment::Builtin::Studio).contentHash());
}

void EnvironmentTest::loadWarnsAboutAspectAndDecodesSrgb()
{
    QTemporaryDir dir;
    // A square 8-bit PNG of 128/255 everywhere, written through Image::save (tagged sRGB).
    Image square(8, 8, glm::vec4(128.0f / 255.0f, 128.0f / 255.0f, 128.0f / 255.0f, 1.0f));
    square.setEncoding(ColorEncoding::SRGB);
    const QString path = dir.filePath(QStringLiteral("square.png"));
    std::string error;
    QVERIFY2(square.save(path.toStdString(), &error), error.c_str());

    std::string warning;
    const std::optional<Environment> environment = Environment::load(path.toStdString(), &error, &warning);
    QVERIFY2(environment, error.c_str());
    QVERIFY2(warning.find(path.toStdString() + ": 8x8 is not 2:1") != std::string::npos, warning.c_str());
    QVERIFY2(warning.find("replaced") == std::string::npos, warning.c_str()); // nothing to sanitise
    QCOMPARE(environment->image().encoding(), ColorEncoding::Linear);
    // sRGB 128/255 is linear 0.2158605.
    COMPARE_VEC(environment->radiance({0, 0, 1}), glm::dvec3(0.21586050011389926), 1e-6);
}

void EnvironmentTest::loadErrorsNameTheFile()
{
    QTemporaryDir dir;
    const std::string path = dir.filePath(QStringLiteral("nothing.exr")).toStdString();
    std::string error;
    QVERIFY(!Environment::load(path, &error));
    QVERIFY2(error.rfind("Environment::load: " + path + ": ", 0) == 0, error.c_str());
    error.clear();
    QVERIFY(!Environment::fromSpec(path, &error));
    QVERIFY2(error.rfind("Environment::load: " + path + ": ", 0) == 0, error.c_str());
}

void EnvironmentTest::fromSpecParses()
{
    std::string error;
    std::optional<Environment> environment = Environment::fromSpec("uniform:2", &error);
    QVERIFY2(environment, error.c_str());
    QVERIFY(environment->isUniform());
    QCOMPARE(environment->radiance({0, 1, 0}), glm::dvec3(2.0));

    environment = Environment::fromSpec("uniform:0.25, 0.5 ,1e-3", &error);
    QVERIFY2(environment, error.c_str());
    COMPARE_VEC(environment->radiance({1, 0, 0}), glm::dvec3(0.25, 0.5, 1e-3), 1e-9);
    environment = Environment::fromSpec("uniform:0", &error);
    QVERIFY2(environment, error.c_str());
    QCOMPARE(environment->radiance({1, 0, 0}), glm::dvec3(0.0));

    // name() is a spec that gives the environment back.
    const Environment original = Environment::uniform({0.1, 1.0 / 3.0, 1e6});
    environment = Environment::fromSpec(original.name(), &error);
    QVERIFY2(environment, error.c_str());
    QCOMPARE(environment->contentHash(), original.contentHash());

    for (const char* name : {"studio", "sky"}) {
        environment = Environment::fromSpec(name, &error);
        QVERIFY2(environment, error.c_str());
        QCOMPARE(environment->name(), std::string(name));
        QVERIFY(!environment->isUniform());
        QCOMPARE(environment->contentHash(),
            Environment::builtin(*Environment::builtinFromName(name)).contentHash());
    }
    QVERIFY(!Environment::builtinFromName("Studio"));
    QVERIFY(!Environment::builtinFromName("uniform"));
}

void EnvironmentTest::fromSpecRejectsBadValues_data()
{
    QTest::addColumn<QString>("spec");
    for (const char* spec : {"uniform:abc", "uniform:-1", "uniform:nan", "uniform:inf", "uniform:1e999",
             "uniform:1e300", "uniform:", "uniform:1,2", "uniform:1,2,3,4", "uniform:1,,2",
             "uniform:1,-0.5,2", "uniform:2x", "uniform:0x10"})
        QTest::newRow(spec) << QString::fromLatin1(spec);
}

void EnvironmentTest::fromSpecRejectsBadValues()
{
    QFETCH(QString, spec);
    std::string error;
    QVERIFY(!Environment::fromSpec(spec.toStdString(), &error));
    QVERIFY2(error.rfind("Environment::fromSpec: " + spec.toStdString() + ": ", 0) == 0, error.c_str());
    error.clear();
    QVERIFY(!Environment::fromSpec("", &error));
    QVERIFY2(error.rfind("Environment::fromSpec: ", 0) == 0, error.c_str());
}

// EnvironmentSampler::tables(): sizes, CDFs from 0 to exactly 1 and non-decreasing, the pdf a
// density over the unit square equal to the distribution's, rows in distribution order.
void EnvironmentTest::samplingTablesLayout_data()
{
    QTest::addColumn<int>("which");
    QTest::addColumn<double>("rotation");
    QTest::newRow("spot 16x8") << 0 << 0.0;
    QTest::newRow("studio 64x32") << 1 << 0.0;
    QTest::newRow("studio 64x32 rotated 40") << 1 << 40.0; // rotation is applied at shading time
    QTest::newRow("sky 128x64") << 2 << 0.0;
    QTest::newRow("uniform") << 3 << 0.0;
}

void EnvironmentTest::samplingTablesLayout()
{
    QFETCH(int, which);
    QFETCH(double, rotation);
    Environment environment;
    int brightRow = -1; // the image row of the spot
    if (which == 0) {
        Image image(16, 8, glm::vec4(0.5f));
        brightRow = 1;
        image.at(5, brightRow) = glm::vec4(400.0f);
        environment = Environment(image, "spot");
    } else if (which == 1) {
        environment = Environment::builtin(Environment::Builtin::Studio, 64);
    } else if (which == 2) {
        environment = Environment::builtin(Environment::Builtin::Sky, 128);
    } else {
        environment = Environment::uniform(glm::dvec3(2.0));
    }
    environment.setRotationDegrees(rotation);
    const facet::EnvironmentSampler sampler(environment);
    const facet::EnvironmentSamplingTables tables = sampler.tables();
    const int w = environment.image().width();
    const int h = environment.image().height();
    QCOMPARE(tables.width, w);
    QCOMPARE(tables.height, h);
    QCOMPARE(int(tables.conditionalCdf.size()), h * (w + 1));
    QCOMPARE(int(tables.marginalCdf.size()), h + 1);
    QCOMPARE(int(tables.pdfUv.size()), w * h);
    QCOMPARE(tables.bytes(), (std::size_t(h) * (w + 1) + (h + 1) + std::size_t(w) * h) * sizeof(float));
    auto checkCdf = [](std::span<const float> cdf) {
        if (cdf.front() != 0.0f || cdf.back() != 1.0f)
            return false;
        return std::is_sorted(cdf.begin(), cdf.end());
    };
    QVERIFY(checkCdf(tables.marginalCdf));
    for (int row = 0; row < h; ++row)
        QVERIFY2(checkCdf(tables.conditionalRow(row)), qPrintable(QString::number(row)));
    // A density over the unit square: the cells' pdf / (W H) sums to 1; and each is the
    // distribution's own pdf, rounded once.
    double sum = 0.0;
    double worst = 0.0;
    for (int row = 0; row < h; ++row)
        for (int column = 0; column < w; ++column) {
            const double exact = sampler.distribution().pdf({(column + 0.5) / w, (row + 0.5) / h});
            const double stored = tables.pdfAt(column, row);
            sum += stored;
            if (exact > 0.0)
                worst = std::max(worst, std::abs(stored - exact) / exact);
            else
                QCOMPARE(stored, 0.0);
        }
    QVERIFY2(
        std::abs(sum / (double(w) * h) - 1.0) < 1e-6, qPrintable(QString::number(sum / (double(w) * h))));
    QVERIFY2(worst <= 6e-8, qPrintable(QString::number(worst))); // float rounding, 2^-24
    // The pdf in solid angle is pdfUv / (2 pi^2 cos(lat)), in the image frame: the sampler's.
    const glm::dvec3 direction = glm::normalize(glm::dvec3(0.3, 0.4, -0.5));
    const glm::dvec3 local = environment.toImageFrame(direction);
    const glm::dvec2 uv = equirectUvFromDirection(local);
    const double cosLat = std::sqrt(1.0 - local.y * local.y);
    const double fromTable = facet::sampling::tablesPdf(tables, glm::vec2(uv)) / (2.0 * kPi * kPi * cosLat);
    QVERIFY2(
        std::abs(fromTable / sampler.pdf(direction) - 1.0) < 1e-6, qPrintable(QString::number(fromTable)));
    if (brightRow >= 0) {
        // Distribution row r is image row H-1-r: per unit solid angle, the marginal's steps are
        // largest (and equal, by the 3x3 maximum) at the spot's row and its two neighbours.
        auto perSolidAngle = [&](int row) {
            const double lat0 = kPi * (double(row) / h - 0.5);
            const double lat1 = kPi * (double(row + 1) / h - 0.5);
            return double(tables.marginalCdf[row + 1] - tables.marginalCdf[row])
                / (std::sin(lat1) - std::sin(lat0));
        };
        const int spot = h - 1 - brightRow;
        for (int row = 0; row < h; ++row) {
            if (std::abs(row - spot) <= 1)
                QVERIFY2(std::abs(perSolidAngle(row) / perSolidAngle(spot) - 1.0) < 1e-5,
                    qPrintable(QString::number(row)));
            else
                QVERIFY2(perSolidAngle(row) < 0.1 * perSolidAngle(spot), qPrintable(QString::number(row)));
        }
    }
    if (which == 3) // uniform: the density is the solid angle of the cells, cos(lat) 2 pi^2
        for (int row = 0; row < h; ++row) {
            const double lat0 = kPi * (double(row) / h - 0.5);
            const double lat1 = kPi * (double(row + 1) / h - 0.5);
            const double expected
                = (std::sin(lat1) - std::sin(lat0)) / 2.0 * h; // solid angle / (4 pi) * W H / W
            QVERIFY2(
                std::abs(tables.pdfAt(0, row) / expected - 1.0) < 1e-6, qPrintable(QString::number(row)));
        }
}

// The 3x3 maximum of EnvironmentSampler's weights survives into the tables: the eight
// neighbours of one bright texel get its weight (times their own row's solid angle), wrapping in
// u and clamped in v; the texels two away do not.
void EnvironmentTest::samplingTablesKeepTheMaxFilter_data()
{
    QTest::addColumn<int>("x");
    QTest::addColumn<int>("y");
    QTest::newRow("interior") << 7 << 4;
    QTest::newRow("column 0 wraps to the last") << 0 << 3;
    QTest::newRow("last column wraps to 0") << 15 << 5;
    QTest::newRow("top row clamps") << 9 << 0;
    QTest::newRow("bottom row clamps") << 2 << 7;
}

void EnvironmentTest::samplingTablesKeepTheMaxFilter()
{
    QFETCH(int, x);
    QFETCH(int, y);
    const int w = 16;
    const int h = 8;
    Image image(w, h, glm::vec4(0.01f, 0.01f, 0.01f, 1.0f));
    image.at(x, y) = glm::vec4(100.0f, 100.0f, 100.0f, 1.0f);
    const facet::EnvironmentSampler sampler(Environment(image, "max"));
    const facet::EnvironmentSamplingTables tables = sampler.tables();
    // pdf per unit solid angle of distribution row r: pdfUv / (cell solid angle * W H / 4 pi ...);
    // comparing within the block, divide by the row's solid angle (the weight's other factor).
    auto perSolidAngle = [&](int column, int imageRow) {
        const int row = h - 1 - imageRow;
        const double lat0 = kPi * (double(row) / h - 0.5);
        const double lat1 = kPi * (double(row + 1) / h - 0.5);
        return double(tables.pdfAt((column + w) % w, row)) / (std::sin(lat1) - std::sin(lat0));
    };
    const double centre = perSolidAngle(x, y);
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int yy = y + dy;
            if (yy < 0 || yy >= h)
                continue;
            const double neighbour = perSolidAngle(x + dx, yy);
            QVERIFY2(std::abs(neighbour / centre - 1.0) < 1e-6,
                qPrintable(QStringLiteral("(%1, %2): %3 vs %4").arg(dx).arg(dy).arg(neighbour).arg(centre)));
        }
    // Two texels away (same row): the background, 1e4 times dimmer.
    QVERIFY(perSolidAngle(x + 2, y) < 1e-3 * centre);
    QVERIFY(perSolidAngle(x - 2, y) < 1e-3 * centre);
}

QTEST_GUILESS_MAIN(EnvironmentTest)
#include "EnvironmentTest.moc"
