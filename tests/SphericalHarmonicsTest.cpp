// SH9 irradiance (core/ibl/SphericalHarmonics.h) and the brute-force irradiance integral
// (core/ibl/Irradiance.h): the basis, the quadrature, closed forms, SH against brute force on
// synthetic and real environments, brute force against an independent Monte Carlo estimate,
// rotation, intensity and extreme values. docs/irradiance.md quotes the numbers printed here.

#include <QElapsedTimer>
#include <QObject>
#include <QtTest/QTest>

#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "TestSupport.h"
#include "core/ibl/Environment.h"
#include "core/ibl/EnvironmentSampler.h"
#include "core/ibl/Irradiance.h"
#include "core/ibl/SphericalHarmonics.h"
#include "core/support/Parallel.h"

using namespace facet;

namespace {

constexpr double kPi = std::numbers::pi;

double luminance(const glm::dvec3& c)
{
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

bool isFinite(const glm::dvec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Largest per-channel |a - b| / |b|.
double relativeError(const glm::dvec3& a, const glm::dvec3& b)
{
    double worst = 0.0;
    for (int i = 0; i < 3; ++i)
        worst = std::max(worst, std::abs(a[i] - b[i]) / std::abs(b[i]));
    return worst;
}

// The normal set of the accuracy measurements: the 6 axes, then 20 points of a Fibonacci sphere
// (y from 0.95 down to -0.95 in equal steps, longitude advancing by the golden angle).
std::vector<glm::dvec3> accuracyNormals()
{
    std::vector<glm::dvec3> normals = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const int count = 20;
    const double goldenAngle = kPi * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < count; ++i) {
        const double y = 1.0 - 2.0 * (i + 0.5) / count;
        const double r = std::sqrt(1.0 - y * y);
        normals.push_back({r * std::cos(goldenAngle * i), y, r * std::sin(goldenAngle * i)});
    }
    return normals;
}

// An equirect environment whose texels hold radiance(direction at the texel centre). The
// direction is computed here from docs/architecture.md's mapping, independently of core's helpers:
// row y has v = 1 - (y + 1/2)/H, lat = pi (v - 1/2); column x has u = (x + 1/2)/W,
// phi = 2 pi (u - 1/2); d = (cos lat cos phi, sin lat, cos lat sin phi).
Environment synthetic(int width, int height, const std::function<glm::dvec3(const glm::dvec3&)>& radiance)
{
    Image image(width, height, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    for (int y = 0; y < height; ++y) {
        const double lat = kPi * (0.5 - (y + 0.5) / height);
        for (int x = 0; x < width; ++x) {
            const double phi = 2.0 * kPi * ((x + 0.5) / width - 0.5);
            const glm::dvec3 d(std::cos(lat) * std::cos(phi), std::sin(lat), std::cos(lat) * std::sin(phi));
            image.at(x, y) = glm::vec4(glm::vec3(radiance(d)), 1.0f);
        }
    }
    return Environment(std::move(image), "synthetic");
}

// A smooth, colourful, positive radiance of SH order <= 2 (bands 0, 1 and 2 only):
//   L(w) = a + b w.y + c (3 w.y^2 - 1) + d w.x w.z
// With the clamped cosine as a zonal kernel each band is an eigenfunction (Funk-Hecke), so
//   E(n) = pi a + (2 pi / 3) b n.y + (pi / 4) c (3 n.y^2 - 1) + (pi / 4) d n.x n.z   (exactly).
const glm::dvec3 kA(1.0, 0.8, 1.2), kB(0.5, -0.3, 0.2), kC(0.2, 0.1, -0.15), kD(0.3, -0.4, 0.1);
glm::dvec3 lowOrderRadiance(const glm::dvec3& w)
{
    return kA + kB * w.y + kC * (3.0 * w.y * w.y - 1.0) + kD * (w.x * w.z);
}
glm::dvec3 lowOrderIrradiance(const glm::dvec3& n)
{
    return kPi * kA + (2.0 * kPi / 3.0) * kB * n.y + (kPi / 4.0) * kC * (3.0 * n.y * n.y - 1.0)
        + (kPi / 4.0) * kD * (n.x * n.z);
}

// A deterministic generator (SplitMix64), so the Monte Carlo numbers are the same everywhere.
class SplitMix64 {
public:
    explicit SplitMix64(std::uint64_t seed)
        : m_state(seed)
    {
    }
    double next()
    {
        std::uint64_t z = (m_state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        z ^= z >> 31;
        return double(z >> 11) * 0x1.0p-53;
    }

private:
    std::uint64_t m_state;
};

// Irradiance by Monte Carlo over Environment::radianceNearest (the environment's own mapping,
// rotation and intensity): a code path that shares nothing with the quadrature but the
// piecewise-constant radiance both integrate. Cosine-weighted sampling alone cannot see a sun of
// a few texels (sky: ~6 of 262k samples land on it, +-5% between seeds), so it is combined with
// core's luminance importance sampling (EnvironmentSampler) by multiple importance sampling with
// the balance heuristic (Veach 1997, ch. 9; PBRT 13.10.1): with N samples from each technique,
//   E ~= 1/N * sum over all 2N samples of L(w) max(0, n.w) / (pdf_cos(w) + pdf_env(w)),
// pdf_cos = max(0, n.w) / pi (Malley's method, PBRT 13.6.3; Duff et al. 2017 frame). Both sample
// sets are stratified on a jittered strata x strata grid. Nearest, not bilinear, lookups: bilinear
// filtering spreads a 20000-radiance sun over neighbours that both techniques rarely visit, and
// the estimate is then dominated by a few huge samples (up to 15% off with 262k samples on sky).
glm::dvec3 irradianceMonteCarlo(const Environment& environment, const glm::dvec3& n, int strata)
{
    const EnvironmentSampler sampler(environment);
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    const glm::dvec3 t(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    const glm::dvec3 s(b, sign + n.y * n.y * a, -n.y);
    SplitMix64 random(0x5eed + std::uint64_t(strata));
    glm::dvec3 sum(0.0);
    const auto contribution = [&](const glm::dvec3& w) {
        const double cosine = glm::dot(n, w);
        if (cosine <= 0.0)
            return glm::dvec3(0.0);
        const double pdfSum = cosine / kPi + sampler.pdf(w);
        return environment.radianceNearest(w) * (cosine / pdfSum);
    };
    for (int i = 0; i < strata; ++i) {
        for (int j = 0; j < strata; ++j) {
            const double u1 = (i + random.next()) / strata;
            const double u2 = (j + random.next()) / strata;
            const double r = std::sqrt(u1);
            const double phi = 2.0 * kPi * u2;
            sum += contribution(
                glm::normalize(t * (r * std::cos(phi)) + s * (r * std::sin(phi)) + n * std::sqrt(1.0 - u1)));
            double pdf = 0.0;
            const glm::dvec3 w
                = sampler.sample({(i + random.next()) / strata, (j + random.next()) / strata}, &pdf);
            if (pdf > 0.0)
                sum += contribution(w);
        }
    }
    return sum / double(strata * strata);
}

struct ShErrorStats {
    double maxAbs = 0.0; // max over normals of |E_SH / E_bf - 1| (luminance)
    double rms = 0.0; // RMS over normals of the same
    glm::dvec3 worstNormal {}; // where maxAbs is reached
    double worstSigned = 0.0; // E_SH / E_bf - 1 there
    double down = 0.0; // E_SH / E_bf - 1 for n = -Y
    double up = 0.0; // ... n = +Y
    double sideMax = 0.0; // largest signed error over the 4 horizontal axes
    double maxOfMean = 0.0; // max over normals of |E_SH - E_bf| / mean over normals of E_bf
};

ShErrorStats measureShError(const Environment& environment)
{
    const std::vector<glm::dvec3> normals = accuracyNormals();
    const std::vector<glm::dvec3> truth = IrradianceIntegrator(environment).irradiance(normals);
    const SH9 sh = projectEquirect(environment);
    ShErrorStats stats;
    double sumSquares = 0.0, meanTruth = 0.0, maxDifference = 0.0;
    stats.sideMax = -1e300;
    for (std::size_t i = 0; i < normals.size(); ++i) {
        const double fromSh = luminance(irradianceSH(sh, normals[i]));
        const double signedError = fromSh / luminance(truth[i]) - 1.0;
        meanTruth += luminance(truth[i]) / double(normals.size());
        maxDifference = std::max(maxDifference, std::abs(fromSh - luminance(truth[i])));
        sumSquares += signedError * signedError;
        if (std::abs(signedError) > stats.maxAbs) {
            stats.maxAbs = std::abs(signedError);
            stats.worstNormal = normals[i];
            stats.worstSigned = signedError;
        }
        if (i == 2)
            stats.up = signedError;
        if (i == 3)
            stats.down = signedError;
        if (i < 6 && i != 2 && i != 3)
            stats.sideMax = std::max(stats.sideMax, signedError);
    }
    stats.rms = std::sqrt(sumSquares / double(normals.size()));
    stats.maxOfMean = maxDifference / meanTruth;
    return stats;
}

std::optional<Environment> loadHdri(const QString& path)
{
    std::string error;
    std::optional<Environment> environment = Environment::load(path.toStdString(), &error);
    if (!environment)
        qWarning("%s", error.c_str());
    return environment;
}

} // namespace

class SphericalHarmonicsTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void basisIsOrthonormal();
    void basisMatchesItsTable();
    void solidAnglesSumToFourPi_data();
    void solidAnglesSumToFourPi();
    void solidAngleIsTheExactIntegral();
    void texelDirectionsFollowTheEquirectMapping();
    void uniformEnvironmentGivesPiL_data();
    void uniformEnvironmentGivesPiL();
    void lowOrderEnvironmentIsExactInSH();
    void premultipliedCoefficientsMatchTheGlslFormula();
    void clampedCosineSkyMatchesItsClosedForm();
    void realHdriShError_data();
    void realHdriShError();
    void bruteForceAgreesWithMonteCarlo_data();
    void bruteForceAgreesWithMonteCarlo();
    void rotationRotatesTheIrradianceField();
    void intensityScalesLinearly();
    void extremeRadianceStaysFinite();
    void manyNormalsAreFastAndDeterministic();
};

// ---------------------------------------------------------------------------------------------
// Basis and quadrature

void SphericalHarmonicsTest::basisIsOrthonormal()
{
    // integral Y_i Y_j dw over a 1024x512 equirect grid with exact texel solid angles. The midpoint
    // rule is exact in longitude for these degree <= 4 trigonometric polynomials and second order
    // in latitude: (pi/512)^2 ~ 4e-5 bounds the error with margin (measured: < 1e-5).
    const int width = 1024, height = 512;
    double gram[9][9] = {};
    for (int y = 0; y < height; ++y) {
        const double dOmega = equirectTexelSolidAngle(y, width, height);
        for (int x = 0; x < width; ++x) {
            const std::array<double, 9> basis = shBasis(equirectTexelDirection(x, y, width, height));
            for (int i = 0; i < 9; ++i)
                for (int j = 0; j < 9; ++j)
                    gram[i][j] += basis[std::size_t(i)] * basis[std::size_t(j)] * dOmega;
        }
    }
    double worst = 0.0;
    for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 9; ++j)
            worst = std::max(worst, std::abs(gram[i][j] - (i == j ? 1.0 : 0.0)));
    qInfo("orthonormality: max |<Y_i, Y_j> - delta_ij| = %.3g", worst);
    QVERIFY2(worst < 4e-5, qPrintable(QStringLiteral("Gram matrix off identity by %1").arg(worst)));
}

void SphericalHarmonicsTest::basisMatchesItsTable()
{
    // Spot values of the documented ordering and constants (no Condon-Shortley phase).
    const double k0 = 0.5 * std::sqrt(1.0 / kPi), k1 = std::sqrt(3.0 / (4.0 * kPi));
    const double k2 = 0.5 * std::sqrt(15.0 / kPi), k20 = 0.25 * std::sqrt(5.0 / kPi),
                 k22 = 0.25 * std::sqrt(15.0 / kPi);
    const glm::dvec3 d = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
    const std::array<double, 9> expected = {k0, k1 * d.y, k1 * d.z, k1 * d.x, k2 * d.x * d.y, k2 * d.y * d.z,
        k20 * (3.0 * d.z * d.z - 1.0), k2 * d.x * d.z, k22 * (d.x * d.x - d.y * d.y)};
    const std::array<double, 9> actual = shBasis(d);
    for (std::size_t i = 0; i < 9; ++i)
        QVERIFY2(std::abs(actual[i] - expected[i]) < 1e-14, qPrintable(QStringLiteral("Y_%1").arg(i)));
    QCOMPARE(sh::A0, kPi);
    QVERIFY(std::abs(sh::A1 - 2.0 * kPi / 3.0) < 1e-15);
    QVERIFY(std::abs(sh::A2 - kPi / 4.0) < 1e-15);
}

void SphericalHarmonicsTest::solidAnglesSumToFourPi_data()
{
    QTest::addColumn<int>("width");
    QTest::addColumn<int>("height");
    QTest::newRow("512x256") << 512 << 256;
    QTest::newRow("2048x1024") << 2048 << 1024;
    QTest::newRow("7x3") << 7 << 3;
    QTest::newRow("1x1") << 1 << 1;
    QTest::newRow("3x1000") << 3 << 1000;
}

void SphericalHarmonicsTest::solidAnglesSumToFourPi()
{
    QFETCH(int, width);
    QFETCH(int, height);
    double sum = 0.0;
    for (int y = 0; y < height; ++y)
        sum += width * equirectTexelSolidAngle(y, width, height);
    QVERIFY2(std::abs(sum - 4.0 * kPi) < 1e-9, qPrintable(QStringLiteral("sum %1").arg(sum - 4.0 * kPi)));
}

void SphericalHarmonicsTest::solidAngleIsTheExactIntegral()
{
    // Against the textbook form (2 pi / W)(sin lat1 - sin lat0), row by row; the cos(lat_c) dlat
    // dphi approximation is too large by (dlat/2) / sin(dlat/2): 2.6% for this 4-row image.
    const int width = 8, height = 4;
    double approximateSum = 0.0;
    for (int y = 0; y < height; ++y) {
        const double lat1 = kPi * (0.5 - double(y) / height), lat0 = kPi * (0.5 - double(y + 1) / height);
        const double exact = (2.0 * kPi / width) * (std::sin(lat1) - std::sin(lat0));
        QVERIFY(std::abs(equirectTexelSolidAngle(y, width, height) - exact) < 1e-15);
        approximateSum += width * std::cos(0.5 * (lat0 + lat1)) * (2.0 * kPi / width) * (kPi / height);
    }
    QVERIFY(approximateSum / (4.0 * kPi) - 1.0 > 0.02);
    // The top row of a large image: sin lat1 - sin lat0 = 1 - cos(dtheta) = 2 sin^2(dtheta/2),
    // computed without the cancellation of 1 - cos near 1 (which is only good to ~1e-8 here).
    const int big = 1 << 15;
    const double top = equirectTexelSolidAngle(0, 2 * big, big);
    const double stableTop = (2.0 * kPi / (2 * big)) * 2.0 * std::pow(std::sin(kPi / (2.0 * big)), 2.0);
    QVERIFY(std::abs(top / stableTop - 1.0) < 1e-12);
}

void SphericalHarmonicsTest::texelDirectionsFollowTheEquirectMapping()
{
    // core's texel centres map back to the texel centres through Environment's own mapping.
    const int width = 64, height = 32;
    for (int y = 0; y < height; y += 3) {
        for (int x = 0; x < width; x += 5) {
            const glm::dvec3 d = equirectTexelDirection(x, y, width, height);
            QVERIFY(std::abs(glm::length(d) - 1.0) < 1e-14);
            const glm::dvec2 uv = equirectUvFromDirection(d);
            QVERIFY2(std::abs(uv.x - (x + 0.5) / width) < 1e-12
                    && std::abs(uv.y - (1.0 - (y + 0.5) / height)) < 1e-12,
                qPrintable(QStringLiteral("texel %1,%2 -> uv %3,%4").arg(x).arg(y).arg(uv.x).arg(uv.y)));
        }
    }
    // The top row looks up (+Y), u = 0.5 looks along +X, u = 0.75 along +Z.
    QVERIFY(equirectTexelDirection(0, 0, width, height).y > 0.99);
    QVERIFY(equirectTexelDirection(width / 2, height / 2, width, height).x > 0.99);
    QVERIFY(equirectTexelDirection(3 * width / 4, height / 2, width, height).z > 0.99);
}

// ---------------------------------------------------------------------------------------------
// Closed forms

void SphericalHarmonicsTest::uniformEnvironmentGivesPiL_data()
{
    QTest::addColumn<int>("width"); // 0: Environment::uniform()
    QTest::addColumn<int>("height");
    QTest::newRow("Environment::uniform") << 0 << 0;
    QTest::newRow("512x256 image") << 512 << 256;
    QTest::newRow("5x3 image (sub-divided texels)") << 5 << 3;
}

void SphericalHarmonicsTest::uniformEnvironmentGivesPiL()
{
    QFETCH(int, width);
    QFETCH(int, height);
    const glm::dvec3 radiance(0.25, 1.0, 3.5);
    const Environment environment = width == 0
        ? Environment::uniform(radiance)
        : synthetic(width, height, [&](const glm::dvec3&) { return radiance; });
    const SH9 sh = projectEquirect(environment);
    const IrradianceIntegrator integrator(environment);
    std::vector<glm::dvec3> normals = accuracyNormals();
    normals.push_back(glm::normalize(glm::dvec3(1, 1, 1)));
    double worstSh = 0.0, worstBruteForce = 0.0;
    for (const glm::dvec3& n : normals) {
        worstSh = std::max(worstSh, relativeError(irradianceSH(sh, n), kPi * radiance));
        worstBruteForce = std::max(worstBruteForce, relativeError(integrator.irradiance(n), kPi * radiance));
    }
    qInfo("uniform: max relative error SH %.3g, brute force %.3g", worstSh, worstBruteForce);
    // SH: L_00 is exact (the solid angles sum to 4 pi); the higher coefficients are quadrature
    // error, second order in the texel size (every image here integrates on >= 512x256 cells).
    // Brute force: the cosine's variation inside the texels, most of it in those the normal's
    // horizon cuts. Both measured < 2e-5; 1e-4 leaves 5x.
    QVERIFY2(worstSh < 1e-4, qPrintable(QString::number(worstSh)));
    QVERIFY2(worstBruteForce < 1e-4, qPrintable(QString::number(worstBruteForce)));
}

void SphericalHarmonicsTest::lowOrderEnvironmentIsExactInSH()
{
    // Radiance with SH order <= 2: SH9 loses nothing, so SH irradiance, brute force and the closed
    // form agree up to the quadrature's discretisation.
    const Environment environment = synthetic(512, 256, lowOrderRadiance);
    const SH9 sh = projectEquirect(environment);
    const IrradianceIntegrator integrator(environment);
    double worstSh = 0.0, worstBruteForce = 0.0, worstShVsBruteForce = 0.0;
    for (const glm::dvec3& n : accuracyNormals()) {
        const glm::dvec3 exact = lowOrderIrradiance(n);
        const glm::dvec3 fromSh = irradianceSH(sh, n);
        const glm::dvec3 bruteForce = integrator.irradiance(n);
        worstSh = std::max(worstSh, relativeError(fromSh, exact));
        worstBruteForce = std::max(worstBruteForce, relativeError(bruteForce, exact));
        worstShVsBruteForce = std::max(worstShVsBruteForce, relativeError(fromSh, bruteForce));
    }
    qInfo("order-2 environment: max relative error SH %.3g, brute force %.3g, SH vs brute force %.3g",
        worstSh, worstBruteForce, worstShVsBruteForce);
    // Tolerance 1e-4: 5x the measured discretisation (float texels add ~1e-7).
    QVERIFY2(worstSh < 1e-4, qPrintable(QString::number(worstSh)));
    QVERIFY2(worstBruteForce < 1e-4, qPrintable(QString::number(worstBruteForce)));
    QVERIFY2(worstShVsBruteForce < 1e-4, qPrintable(QString::number(worstShVsBruteForce)));
    // And the projection recovers the coefficients themselves. In this basis (polar axis +Z):
    //   1 = Y_00 / K0,  w.y = Y_1-1 / K1,  w.x w.z = Y_21 / K2,
    //   3 w.y^2 - 1 = -(3 w.z^2 - 1)/2 - 3 (w.x^2 - w.y^2)/2 = -Y_20 / (2 K20) - 3 Y_22 / (2 K22)
    // (check at +X: -1 = 1/2 - 3/2; at +Y: 2 = 1/2 + 3/2; at +Z: -1 = -1).
    const std::array<glm::dvec3, 9> expected = {kA / sh::K0, kB / sh::K1, glm::dvec3(0.0), glm::dvec3(0.0),
        glm::dvec3(0.0), glm::dvec3(0.0), -kC / (2.0 * sh::K20), kD / sh::K2, -3.0 * kC / (2.0 * sh::K22)};
    for (std::size_t i = 0; i < 9; ++i)
        QVERIFY2(glm::length(sh.c[i] - expected[i]) < 1e-4 * glm::length(kA / sh::K0),
            qPrintable(QStringLiteral("L_%1 off by %2").arg(i).arg(glm::length(sh.c[i] - expected[i]))));
}

void SphericalHarmonicsTest::premultipliedCoefficientsMatchTheGlslFormula()
{
    const Environment environment = synthetic(256, 128, lowOrderRadiance);
    const SH9 sh = projectEquirect(environment);
    const IrradianceSH9 premultiplied = irradianceSHCoefficients(sh);
    for (std::size_t i = 0; i < 9; ++i) {
        const double expectedA = i == 0 ? kPi : (i < 4 ? 2.0 * kPi / 3.0 : kPi / 4.0);
        QVERIFY(
            relativeError(premultiplied.c[i], sh.c[i] * expectedA) < 1e-15 || glm::length(sh.c[i]) == 0.0);
    }
    for (const glm::dvec3& n : accuracyNormals()) {
        // E(n) = sum_i (A_l c_i) Y_i(n), written out as the GLSL comment in SphericalHarmonics.h has it.
        const std::array<double, 9> y = shBasis(n);
        glm::dvec3 e(0.0);
        for (std::size_t i = 0; i < 9; ++i)
            e += premultiplied.c[i] * y[i];
        QVERIFY(relativeError(irradianceSH(premultiplied, n), e) < 1e-13);
        QVERIFY(relativeError(irradianceSH(sh, n), e) < 1e-13);
    }
}

void SphericalHarmonicsTest::clampedCosineSkyMatchesItsClosedForm()
{
    // L(w) = max(0, w.y): for unit a, b at angle alpha,
    //   integral max(0, a.w) max(0, b.w) dw = (2/3) ((pi - alpha) cos(alpha) + sin(alpha)),
    // which gives E(up) = 2 pi / 3, E(horizontal) = 2/3, E(down) = 0. (Derivation: both clamped
    // cosines are zonal; expanding one in Legendre polynomials and applying Funk-Hecke to the
    // other, or directly in coordinates with the lune where both are positive.)
    const Environment environment
        = synthetic(512, 256, [](const glm::dvec3& w) { return glm::dvec3(std::max(0.0, w.y)); });
    const IrradianceIntegrator integrator(environment);
    double worst = 0.0;
    for (int k = 0; k <= 12; ++k) {
        const double alpha = kPi * k / 12.0;
        const glm::dvec3 n(
            std::sin(alpha) * std::cos(0.3 * k), std::cos(alpha), std::sin(alpha) * std::sin(0.3 * k));
        const double exact = (2.0 / 3.0) * ((kPi - alpha) * std::cos(alpha) + std::sin(alpha));
        const double e = integrator.irradiance(n).x;
        if (k == 12) {
            QVERIFY2(std::abs(e) < 1e-6, qPrintable(QStringLiteral("E(down) = %1").arg(e)));
            continue;
        }
        worst = std::max(worst, std::abs(e - exact) / exact);
    }
    qInfo("clamped-cosine sky: brute force max relative error %.3g", worst);
    // 2e-3: the kink of max(0, w.y) lies on a texel border, but the normal's own horizon cuts
    // through texels; measured ~1e-5 where E is large and 8.6e-4 at alpha = 165 deg, where E is
    // 0.012 and a handful of horizon texels carry it all.
    QVERIFY2(worst < 2e-3, qPrintable(QString::number(worst)));
    // 5e-5: midpoint rule in latitude for cos^2 (measured 1.2e-5).
    const double up = integrator.irradiance({0, 1, 0}).x;
    QVERIFY2(std::abs(up / (2.0 * kPi / 3.0) - 1.0) < 5e-5, qPrintable(QString::number(up)));
    const double side = integrator.irradiance({1, 0, 0}).x;
    QVERIFY2(std::abs(side / (2.0 / 3.0) - 1.0) < 1e-4, qPrintable(QString::number(side)));
}

// ---------------------------------------------------------------------------------------------
// Real environments

void SphericalHarmonicsTest::realHdriShError_data()
{
    // Every CC0 sample HDRI: SH9 against brute force over accuracyNormals(), relative error of
    // the luminance. Bounds are the measured values (docs/irradiance.md) plus ~10%, so a change
    // that makes SH9 or the ground truth worse fails here; minimumMax keeps the docs' claim
    // "SH9 is inaccurate for high-contrast maps" true where they make it (studio, sky, esplanade,
    // lab). The numbers are deterministic (double arithmetic, fixed normals): no noise margin
    // is needed, the 10% is headroom for compilers and loaders, not for randomness.
    QTest::addColumn<QString>("name");
    QTest::addColumn<double>("maxBound");
    QTest::addColumn<double>("rmsBound");
    QTest::addColumn<double>("minimumMax");
    const auto row = [](const char* name, double maxBound, double rmsBound, double minimumMax) {
        QTest::newRow(name) << QString::fromLatin1(name) << maxBound << rmsBound << minimumMax;
    };
    row("studio", 3.05, 0.66, 0.10);
    row("sky", 0.41, 0.21, 0.10);
    row("city", 0.16, 0.041, 0.0);
    row("sunset", 0.13, 0.036, 0.0);
    row("apartment", 0.086, 0.031, 0.0);
    row("bridge", 0.24, 0.087, 0.0);
    row("dawn", 0.21, 0.065, 0.0);
    row("esplanade", 0.37, 0.174, 0.10);
    row("forest", 0.064, 0.028, 0.0);
    row("hall", 0.127, 0.041, 0.0);
    row("lab", 0.66, 0.22, 0.10);
    row("lobby", 0.052, 0.019, 0.0);
    row("night", 0.255, 0.071, 0.0);
    row("park", 0.27, 0.077, 0.0);
    row("sunrise", 0.26, 0.102, 0.0);
    row("venice", 0.17, 0.039, 0.0);
    row("warehouse", 0.114, 0.046, 0.0);
    row("workshop", 0.2, 0.076, 0.0);
}

void SphericalHarmonicsTest::realHdriShError()
{
    QFETCH(QString, name);
    QFETCH(double, maxBound);
    QFETCH(double, rmsBound);
    QFETCH(double, minimumMax);
    const QString path = facet::test::hdriPath(name);
    FACET_REQUIRE_ASSET(path, qPrintable(name));
    const std::optional<Environment> environment = loadHdri(path);
    QVERIFY(environment);

    const ShErrorStats s = measureShError(*environment);
    // One markdown table row per HDRI (docs/irradiance.md pastes them).
    qInfo("| %-9s | %6.1f%% | %6.1f%% | %6.1f%% | %+6.1f%% | %+6.1f%% | %+6.1f%% | %+6.1f%% at (%+.2f, "
          "%+.2f, %+.2f) |",
        qPrintable(name), 100.0 * s.maxAbs, 100.0 * s.rms, 100.0 * s.maxOfMean, 100.0 * s.down, 100.0 * s.up,
        100.0 * s.sideMax, 100.0 * s.worstSigned, s.worstNormal.x, s.worstNormal.y, s.worstNormal.z);
    QVERIFY(std::isfinite(s.maxAbs) && std::isfinite(s.rms));
    QVERIFY2(s.maxAbs <= maxBound,
        qPrintable(QStringLiteral("max relative error %1 > %2").arg(s.maxAbs).arg(maxBound)));
    QVERIFY2(
        s.rms <= rmsBound, qPrintable(QStringLiteral("RMS relative error %1 > %2").arg(s.rms).arg(rmsBound)));
    if (name == QStringLiteral("studio")) {
        // The renderer's report on this map: SH9 ~30% too dark straight down, ~25% too bright at
        // the sides. Measured -30.0% at -Y and +27.2% at the worst horizontal axis (and +278% at a
        // dark near-horizontal normal, where the true irradiance is 0.33 against 14 at +Y).
        QVERIFY2(s.down < -0.25 && s.down > -0.35, qPrintable(QStringLiteral("studio, -Y: %1").arg(s.down)));
        QVERIFY2(s.sideMax > 0.20 && s.sideMax < 0.32,
            qPrintable(QStringLiteral("studio, sides: %1").arg(s.sideMax)));
    }
    QVERIFY2(s.maxAbs >= minimumMax,
        qPrintable(
            QStringLiteral("max relative error %1 < %2: docs/irradiance.md says SH9 is inaccurate here")
                .arg(s.maxAbs)
                .arg(minimumMax)));
}

void SphericalHarmonicsTest::bruteForceAgreesWithMonteCarlo_data()
{
    QTest::addColumn<QString>("name");
    QTest::newRow("studio") << QStringLiteral("studio");
    QTest::newRow("sky") << QStringLiteral("sky");
    QTest::newRow("city") << QStringLiteral("city");
    QTest::newRow("sunset") << QStringLiteral("sunset");
}

void SphericalHarmonicsTest::bruteForceAgreesWithMonteCarlo()
{
    QFETCH(QString, name);
    const QString path = facet::test::hdriPath(name);
    FACET_REQUIRE_ASSET(path, qPrintable(name));
    std::optional<Environment> environment = loadHdri(path);
    QVERIFY(environment);
    environment->setRotationDegrees(30.0); // exercise the rotation in both paths
    const IrradianceIntegrator integrator(*environment);
    const std::vector<glm::dvec3> normals = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1},
        {0, 0, -1}, glm::normalize(glm::dvec3(1, 1, 1))};
    double worst = 0.0;
    for (const glm::dvec3& n : normals) {
        const glm::dvec3 bruteForce = integrator.irradiance(n);
        const glm::dvec3 monteCarlo = irradianceMonteCarlo(*environment, n, 256);
        const double error = std::abs(luminance(monteCarlo) / luminance(bruteForce) - 1.0);
        worst = std::max(worst, error);
    }
    qInfo("%s: brute force vs Monte Carlo (2 x 65536 stratified MIS samples): max relative error %.3g",
        qPrintable(name), worst);
    // 0.5%: the Monte Carlo noise of 2 x 65536 stratified MIS samples; measured <= 0.07% on these
    // four maps (the seed is fixed, so the numbers do not change between runs).
    QVERIFY2(worst < 0.005, qPrintable(QString::number(worst)));
}

// ---------------------------------------------------------------------------------------------
// Rotation, intensity, extremes, speed

void SphericalHarmonicsTest::rotationRotatesTheIrradianceField()
{
    // A lopsided environment: a bright lobe towards image-frame direction `lobe` on a tinted
    // gradient, so no rotation about +Y leaves it unchanged.
    const glm::dvec3 lobe = glm::normalize(glm::dvec3(1.0, 0.3, 0.2));
    const Environment original = synthetic(512, 256, [&](const glm::dvec3& w) {
        return glm::dvec3(0.2, 0.3, 0.4) + glm::dvec3(0.1, 0.0, 0.05) * w.z
            + glm::dvec3(8.0, 6.0, 4.0) * std::pow(std::max(0.0, glm::dot(w, lobe)), 16.0);
    });
    Environment rotated = original;
    rotated.setRotationDegrees(90.0);

    // A quarter turn about +Y takes image +X to world +Z or -Z (the sense is Environment's).
    const glm::dvec3 xInWorld = rotated.toWorldFrame({1, 0, 0});
    QVERIFY2(std::abs(std::abs(xInWorld.z) - 1.0) < 1e-12, "a 90 degree rotation must turn +X into +-Z");

    const IrradianceIntegrator before(original), after(rotated);
    const SH9 shBefore = projectEquirect(original), shAfter = projectEquirect(rotated);
    double worstBruteForce = 0.0, worstSh = 0.0, worstChange = 0.0;
    for (const glm::dvec3& n : accuracyNormals()) {
        // The rotated environment seen from world normal n is the original seen from n taken back
        // into the image frame.
        const glm::dvec3 m = rotated.toImageFrame(n);
        worstBruteForce = std::max(worstBruteForce, relativeError(after.irradiance(n), before.irradiance(m)));
        worstSh = std::max(worstSh, relativeError(irradianceSH(shAfter, n), irradianceSH(shBefore, m)));
        worstChange = std::max(worstChange, relativeError(after.irradiance(n), before.irradiance(n)));
    }
    qInfo("rotation 90: brute force %.3g, SH %.3g (field changed by up to %.2f)", worstBruteForce, worstSh,
        worstChange);
    // 90 degrees maps the 512 columns onto themselves: equal up to rounding.
    QVERIFY2(worstBruteForce < 1e-10, qPrintable(QString::number(worstBruteForce)));
    QVERIFY2(worstSh < 1e-10, qPrintable(QString::number(worstSh)));
    QVERIFY2(worstChange > 0.5, "the test environment must not be rotation invariant");
    // The brightest irradiance follows the lobe into the world.
    const glm::dvec3 lobeInWorld = rotated.toWorldFrame(lobe);
    QVERIFY(luminance(after.irradiance(lobeInWorld)) > luminance(after.irradiance(-lobeInWorld)) * 3.0);
    QVERIFY(relativeError(after.irradiance(lobeInWorld), before.irradiance(lobe)) < 1e-10);

    // An angle that does not map texels onto texels: still equal up to rounding. Brute force:
    // n.w is what is summed and rotations keep it. SH: by the addition theorem
    // sum_m Y_lm(a) Y_lm(b) depends on a.b only, so projecting at R w and evaluating at n equals
    // projecting at w and evaluating at R^-1 n, whatever the quadrature.
    Environment oblique = original;
    oblique.setRotationDegrees(37.0);
    const SH9 shOblique = projectEquirect(oblique);
    const IrradianceIntegrator obliqueIntegrator(oblique);
    double worstObliqueSh = 0.0, worstObliqueBruteForce = 0.0;
    for (const glm::dvec3& n : accuracyNormals()) {
        const glm::dvec3 m = oblique.toImageFrame(n);
        worstObliqueSh
            = std::max(worstObliqueSh, relativeError(irradianceSH(shOblique, n), irradianceSH(shBefore, m)));
        worstObliqueBruteForce = std::max(
            worstObliqueBruteForce, relativeError(obliqueIntegrator.irradiance(n), before.irradiance(m)));
    }
    qInfo("rotation 37: brute force %.3g, SH %.3g", worstObliqueBruteForce, worstObliqueSh);
    QVERIFY2(worstObliqueSh < 1e-10, qPrintable(QString::number(worstObliqueSh)));
    QVERIFY2(worstObliqueBruteForce < 1e-10, qPrintable(QString::number(worstObliqueBruteForce)));
}

void SphericalHarmonicsTest::intensityScalesLinearly()
{
    Environment environment = synthetic(128, 64, lowOrderRadiance);
    const SH9 base = projectEquirect(environment);
    const IrradianceIntegrator baseIntegrator(environment);
    environment.setIntensity(2.5);
    const SH9 scaled = projectEquirect(environment);
    const IrradianceIntegrator scaledIntegrator(environment);
    for (const glm::dvec3& n : accuracyNormals()) {
        QVERIFY(relativeError(irradianceSH(scaled, n), 2.5 * irradianceSH(base, n)) < 1e-12);
        QVERIFY(relativeError(scaledIntegrator.irradiance(n), 2.5 * baseIntegrator.irradiance(n)) < 1e-12);
    }
    environment.setIntensity(0.0);
    QCOMPARE(IrradianceIntegrator(environment).irradiance({0, 1, 0}), glm::dvec3(0.0));
    QCOMPARE(irradianceSH(projectEquirect(environment), {0, 1, 0}), glm::dvec3(0.0));
}

void SphericalHarmonicsTest::extremeRadianceStaysFinite()
{
    // One 1e6 texel (a sun) on a 0.5 background; then a 1e-6 environment.
    const int width = 512, height = 256, sunX = 300, sunY = 60;
    Image image(width, height, glm::vec4(0.5f, 0.5f, 0.5f, 1.0f));
    image.at(sunX, sunY) = glm::vec4(1e6f, 1e6f, 1e6f, 1.0f);
    const Environment environment(std::move(image), "sun");
    const SH9 sh = projectEquirect(environment);
    for (const glm::dvec3& c : sh.c)
        QVERIFY(isFinite(c));
    const glm::dvec3 sun = equirectTexelDirection(sunX, sunY, width, height);
    const IrradianceIntegrator integrator(environment);
    std::vector<glm::dvec3> normals = accuracyNormals();
    normals.push_back(sun);
    for (const glm::dvec3& n : normals) {
        const glm::dvec3 e = integrator.irradiance(n);
        QVERIFY(isFinite(e) && e.x >= 0.0);
        const glm::dvec3 fromSh = irradianceSH(sh, n);
        QVERIFY(isFinite(fromSh) && fromSh.x >= 0.0); // clamped: SH9 rings below zero here
    }
    // Facing the sun: the background's pi * 0.5 (less the sun texel) plus the sun's 1e6 dOmega.
    const double dOmega = equirectTexelSolidAngle(sunY, width, height);
    const double expected = kPi * 0.5 + (1e6 - 0.5) * dOmega;
    const double actual = integrator.irradiance(sun).x;
    QVERIFY2(std::abs(actual / expected - 1.0) < 1e-4,
        qPrintable(QStringLiteral("%1 vs %2").arg(actual).arg(expected)));

    Environment dim = synthetic(64, 32, [](const glm::dvec3&) { return glm::dvec3(1e-6); });
    const glm::dvec3 e = IrradianceIntegrator(dim).irradiance({0, 0, 1});
    QVERIFY(std::abs(e.x / (kPi * 1e-6) - 1.0) < 1e-4);
    QVERIFY(std::abs(irradianceSH(projectEquirect(dim), {0, 0, 1}).x / (kPi * 1e-6) - 1.0) < 1e-4);

    // Degenerate inputs: an empty environment and a zero normal give zero, not NaN.
    QCOMPARE(IrradianceIntegrator(Environment()).irradiance({0, 1, 0}), glm::dvec3(0.0));
    QCOMPARE(integrator.irradiance(glm::dvec3(0.0)), glm::dvec3(0.0));
    for (const glm::dvec3& c : projectEquirect(Environment()).c)
        QCOMPARE(c, glm::dvec3(0.0));
}

void SphericalHarmonicsTest::manyNormalsAreFastAndDeterministic()
{
    const Environment environment = synthetic(512, 256, [](const glm::dvec3& w) {
        return glm::dvec3(1.0 + w.y, 0.5 + std::abs(w.x), 2.0 + 30.0 * std::pow(std::max(0.0, w.z), 50.0));
    });
    std::vector<glm::dvec3> normals;
    const int count = 400;
    const double goldenAngle = kPi * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < count; ++i) {
        const double y = 1.0 - 2.0 * (i + 0.5) / count, r = std::sqrt(1.0 - y * y);
        normals.push_back({r * std::cos(goldenAngle * i), y, r * std::sin(goldenAngle * i)});
    }
    QElapsedTimer timer;
    timer.start();
    const IrradianceIntegrator integrator(environment);
    const double buildMs = double(timer.nsecsElapsed()) * 1e-6;
    timer.restart();
    const std::vector<glm::dvec3> serial = integrator.irradiance(normals, 1);
    const double serialMs = double(timer.nsecsElapsed()) * 1e-6;
    timer.restart();
    const std::vector<glm::dvec3> parallel = integrator.irradiance(normals);
    const double parallelMs = double(timer.nsecsElapsed()) * 1e-6;
    const std::vector<glm::dvec3> threeThreads = integrator.irradiance(normals, 3);
    timer.restart();
    const SH9 sh = projectEquirect(environment);
    const double projectMs = double(timer.nsecsElapsed()) * 1e-6;
    QVERIFY(isFinite(sh.c[0]));
    qInfo("brute force, 512x256, %d normals: build %.1f ms, 1 thread %.1f ms (%.3f ms/normal), %u threads "
          "%.1f ms; "
          "projectEquirect %.1f ms",
        count, buildMs, serialMs, serialMs / count, workerCount(), parallelMs, projectMs);
    for (std::size_t i = 0; i < normals.size(); ++i) {
        // Bitwise identical whatever the thread count, and to the single-normal call.
        QCOMPARE(parallel[i], serial[i]);
        QCOMPARE(threeThreads[i], serial[i]);
        if (i % 37 == 0)
            QCOMPARE(integrator.irradiance(normals[i]), serial[i]);
    }
    // Speed is the benchmarks' to measure (a Release build: ~0.1 ms per normal); here only a bound
    // that no build, loaded or not, comes near unless the integrator hangs.
    QVERIFY2(
        parallelMs < double(facet::test::wallClockBoundMs(20000)), qPrintable(QString::number(parallelMs)));
}

QTEST_GUILESS_MAIN(SphericalHarmonicsTest)
#include "SphericalHarmonicsTest.moc"
