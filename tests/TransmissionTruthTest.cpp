// Transmission's CPU ground truth first (KHR_materials_transmission, volume, dispersion:
// core/shading/Transmission, the BSDF strategy's transmission lobes in core/shading/BrdfSampler,
// and the paths through volumes in core/truth/SceneTruth), held to closed forms, each a table of rows.
// - The strategy at one point, from outside (a volume's refraction, a thin wall's mirrored lobe) and
//   from inside a volume (reflection back in, refraction out, total internal reflection past the
//   critical angle): its density integrates to 1 over the sphere of directions and the estimate of
//   the BSDF's albedo with its own directions agrees with uniform directions'; a smooth interface
//   (every Fresnel reflection and refraction kept) has albedo 1, past the critical angle all of it
//   reflected.
// - The glass furnace: a clear, non-absorbing sphere under a uniform environment looks uniform
//   (every sphere pixel within 2% of L), smooth and rough, thin and volume, dispersive.
// - Beer-Lambert: the ray through the centre of a smooth absorbing sphere of index n crosses 2 units
//   of the medium each pass, so under a uniform L its pixel is
//   L (F0 + (1 - F0)^2 a / (1 - F0 a)),  a = exp(-2 sigma) per channel, sigma = -ln(colour) / distance
//   (the series of its internal reflections, each back along the axis); a thin wall absorbs nothing.
// - Dispersion: the index at the Fraunhofer lines as KHR_materials_dispersion defines it, the
//   wavelength weights white on average, and a dispersive sphere spreads colour without adding or
//   losing light.

#include <QtTest/QTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/ibl/Environment.h"
#include "core/image/ImageMetrics.h"
#include "core/shading/BrdfSampler.h"
#include "core/shading/GroundTruth.h" // albedoTable
#include "core/shading/ReferenceView.h"
#include "core/shading/Sampling.h"
#include "core/shading/ThinFilm.h"
#include "core/shading/Transmission.h"
#include "core/truth/SceneTruth.h"

#include "TestSupport.h"

using namespace facet;

namespace {

constexpr int kSize = 32;

MaterialInfo glass(double roughness, double ior, double thickness)
{
    MaterialInfo m;
    m.baseColor = glm::dvec3(1.0);
    m.perceptualRoughness = roughness;
    m.ior = ior;
    m.transmission = 1.0;
    m.thickness = thickness;
    return m;
}

SceneTruthScene sphereScene(const MaterialInfo& material, const Environment& environment)
{
    SceneTruthScene scene;
    scene.geometry.addUnitSphere();
    std::string error;
    if (!scene.geometry.commit(&error))
        qFatal("%s", error.c_str());
    scene.surfaces = {{material, ShadingModel {}}};
    scene.environment = environment;
    return scene;
}

SceneTruthSettings settings(int size, int samples, std::uint64_t seed = 1)
{
    SceneTruthSettings s;
    s.width = size;
    s.height = size;
    s.samplesPerPixel = samples;
    s.seed = seed;
    return s;
}

struct StrategyIntegrals {
    double pdfIntegral = 0.0; // of the density over the sphere (uniform directions)
    glm::dvec3 albedoUniform {0.0}; // of f |n.l|, by uniform directions
    glm::dvec3 albedoSampled {0.0}; // the same by the strategy's own directions
    glm::dvec3 reflected {0.0}; // the sampled estimate's part on v's side
    // What of the light's power is reflected and transmitted: the BTDF is radiance's, which a
    // refraction from index etaV into etaL scales by (etaV / etaL)^2 (docs/shading.md), so the
    // transmitted part is that part of the albedo times (etaL / etaV)^2.
    glm::dvec3 power {0.0};
};

StrategyIntegrals integrate(
    const MaterialInfo& material, double NoV, BrdfSampler::Mode mode, int count, bool compensated)
{
    const std::shared_ptr<const DfgTable> table = albedoTable(64, 2048, Visibility::SmithGGXCorrelated);
    MaterialBrdf brdf(ShadingModel {}, *table);
    if (compensated)
        brdf.setInterfaceTables(std::make_shared<shading::InterfaceAlbedoTable>(1.0, material.ior, false),
            std::make_shared<shading::InterfaceAlbedoTable>(material.ior, 1.0, false));
    const glm::dvec3 n(0.0, 0.0, 1.0);
    const glm::dvec3 v(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
    const BrdfSampler sampler(material, brdf, n, v, mode);
    StrategyIntegrals result;
    sampling::Pcg32 rng(7, 3);
    const double etaRatio = material.isThinWalled() ? 1.0 : material.ior;
    const double powerScale
        = mode == BrdfSampler::Mode::Interior ? 1.0 / (etaRatio * etaRatio) : etaRatio * etaRatio;
    for (int i = 0; i < count; ++i) {
        const glm::dvec2 u = sampling::hammersley(std::uint32_t(i), std::uint32_t(count));
        // Uniform directions: density 1 / (4 pi).
        const glm::dvec3 w = sampling::sampleUniformSphere(u);
        result.pdfIntegral += sampler.pdf(w) * 4.0 * std::numbers::pi;
        result.albedoUniform
            += sampler.f(w, LightingKind::Environment) * std::abs(w.z) * 4.0 * std::numbers::pi;
        // The strategy's own.
        const glm::dvec3 l = sampler.sample(u, rng.nextDouble());
        const double pdf = sampler.pdf(l);
        if (pdf > 0.0) {
            const glm::dvec3 term = sampler.f(l, LightingKind::Environment) * (std::abs(l.z) / pdf);
            result.albedoSampled += term;
            if (l.z > 0.0) {
                result.reflected += term;
                result.power += term;
            } else {
                result.power += term * powerScale;
            }
        }
    }
    result.pdfIntegral /= count;
    result.albedoUniform /= double(count);
    result.albedoSampled /= double(count);
    result.reflected /= double(count);
    result.power /= double(count);
    return result;
}

// Each sphere pixel's largest relative departure from `expected`, their mean and their count.
double worstSphereDeparture(const Image& image, double expected, int* pixels, double* mean = nullptr)
{
    double worst = 0.0;
    double sum = 0.0;
    *pixels = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            if (!referenceview::isInteriorSpherePixel(x, y, image.width(), image.height(), 1))
                continue;
            ++*pixels;
            const glm::vec4 p = image.at(x, y);
            for (int c = 0; c < 3; ++c) {
                worst = std::max(worst, std::abs(double(p[c]) - expected) / expected);
                sum += double(p[c]);
            }
        }
    if (mean)
        *mean = sum / (3.0 * std::max(*pixels, 1));
    return worst;
}

} // namespace

class TransmissionTruthTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void strategyIntegratesItsBsdf_data();
    void strategyIntegratesItsBsdf();
    void glassFurnaceIsUniform_data();
    void glassFurnaceIsUniform();
    void absorptionIsBeerLambert_data();
    void absorptionIsBeerLambert();
    void dispersionFollowsTheAbbeNumber();
    void dispersionSpreadsColourAndKeepsLight();
};

void TransmissionTruthTest::strategyIntegratesItsBsdf_data()
{
    QTest::addColumn<int>("mode"); // BrdfSampler::Mode
    QTest::addColumn<double>("roughness");
    QTest::addColumn<double>("thickness"); // 0: thin-walled
    QTest::addColumn<double>("NoV");
    // Whether the volume's interface tables compensate its multiple scattering (a thin wall's
    // compensation needs none: it always is).
    QTest::addColumn<bool>("compensated");
    // The power a smooth or compensated interface keeps (reflected and transmitted; negative: at
    // least 0.8, single scattering's loss), and how much of it is reflected back to v's side
    // (negative: not checked).
    QTest::addColumn<double>("power");
    QTest::addColumn<double>("reflected");
    const int outside = int(BrdfSampler::Mode::Full);
    const int inside = int(BrdfSampler::Mode::Interior);
    // Smooth from outside at normal incidence: Schlick's F0 = 0.04 reflected, the rest through.
    QTest::newRow("volume, smooth, outside, normal") << outside << 0.0 << 1.0 << 1.0 << false << 1.0 << 0.04;
    QTest::newRow("volume, smooth, outside, 60 deg") << outside << 0.0 << 1.0 << 0.5 << false << 1.0 << -1.0;
    QTest::newRow("volume, rough 0.3, outside, single")
        << outside << 0.3 << 1.0 << 0.7 << false << -1.0 << -1.0;
    QTest::newRow("volume, rough 0.8, outside, single")
        << outside << 0.8 << 1.0 << 0.4 << false << -1.0 << -1.0;
    QTest::newRow("volume, rough 0.3, outside") << outside << 0.3 << 1.0 << 0.7 << true << 1.0 << -1.0;
    QTest::newRow("volume, rough 0.8, outside") << outside << 0.8 << 1.0 << 0.4 << true << 1.0 << -1.0;
    QTest::newRow("volume, rough 0.3, outside, grazing")
        << outside << 0.3 << 1.0 << 0.1 << true << 1.0 << -1.0;
    QTest::newRow("thin, smooth, outside") << outside << 0.0 << 0.0 << 0.8 << false << 1.0 << -1.0;
    QTest::newRow("thin, rough 0.5, outside") << outside << 0.5 << 0.0 << 0.6 << false << 1.0 << -1.0;
    // From inside, index 1.5 to 1: the critical angle's cosine is sqrt(1 - 1/1.5^2) = 0.745.
    QTest::newRow("inside, smooth, normal") << inside << 0.0 << 1.0 << 1.0 << false << 1.0 << 0.04;
    QTest::newRow("inside, smooth, below critical") << inside << 0.0 << 1.0 << 0.85 << false << 1.0 << -1.0;
    QTest::newRow("inside, smooth, total internal reflection")
        << inside << 0.0 << 1.0 << 0.5 << false << 1.0 << 1.0;
    QTest::newRow("inside, rough 0.4, single") << inside << 0.4 << 1.0 << 0.8 << false << -1.0 << -1.0;
    QTest::newRow("inside, rough 0.4") << inside << 0.4 << 1.0 << 0.8 << true << 1.0 << -1.0;
    QTest::newRow("inside, rough 0.7, grazing") << inside << 0.7 << 1.0 << 0.3 << true << 1.0 << -1.0;
    QTest::newRow("inside, rough 0.3, critical angle")
        << inside << 0.3 << 1.0 << 0.745 << true << 1.0 << -1.0;
    QTest::newRow("inside, rough 0.3, past it") << inside << 0.3 << 1.0 << 0.6 << true << 1.0 << -1.0;
}

void TransmissionTruthTest::strategyIntegratesItsBsdf()
{
    QFETCH(int, mode);
    QFETCH(double, roughness);
    QFETCH(double, thickness);
    QFETCH(double, NoV);
    QFETCH(bool, compensated);
    QFETCH(double, power);
    QFETCH(double, reflected);
    const MaterialInfo material = glass(roughness, 1.5, thickness);
    const StrategyIntegrals r = integrate(material, NoV, BrdfSampler::Mode(mode), 1 << 16, compensated);
    qInfo("pdf integral %.4f; albedo by uniform directions %.4f, by the strategy's %.4f (reflected %.4f); "
          "power %.4f",
        r.pdfIntegral, r.albedoUniform.g, r.albedoSampled.g, r.reflected.g, r.power.g);
    if (roughness > 0.0) {
        // A density: 1 less the draws that leave their lobe's side (a reflection below the surface).
        QVERIFY2(r.pdfIntegral <= 1.01, qPrintable(QString::number(r.pdfIntegral)));
        // Smooth lobes are too narrow for uniform directions to integrate: those rows hold the
        // strategy's estimate to the closed form instead.
        QVERIFY2(r.pdfIntegral >= 0.8, qPrintable(QString::number(r.pdfIntegral)));
        QVERIFY2(std::abs(r.albedoSampled.g - r.albedoUniform.g) < 0.015 * r.albedoUniform.g,
            qPrintable(QStringLiteral("%1 against %2").arg(r.albedoSampled.g).arg(r.albedoUniform.g)));
    }
    // No power is created; rough single scattering loses some, which compensation gives back.
    QVERIFY2(r.power.g <= 1.005, qPrintable(QString::number(r.power.g)));
    QVERIFY2(r.power.g >= 0.8, qPrintable(QString::number(r.power.g)));
    if (power > 0.0)
        QVERIFY2(std::abs(r.power.g - power) < 0.005, qPrintable(QString::number(r.power.g)));
    if (reflected >= 0.0)
        QVERIFY2(std::abs(r.reflected.g - reflected) < 0.005, qPrintable(QString::number(r.reflected.g)));
    // Colourless glass stays colourless.
    QVERIFY(std::abs(r.albedoSampled.r - r.albedoSampled.b) < 1e-9);
}

void TransmissionTruthTest::glassFurnaceIsUniform_data()
{
    QTest::addColumn<double>("roughness");
    QTest::addColumn<double>("ior");
    QTest::addColumn<double>("thickness");
    QTest::addColumn<double>("dispersion");
    QTest::addColumn<double>("radiance");
    // Samples per pixel for the 2% bound with room (measured worst pixels): smooth 0.35-0.6% at
    // 1024; dispersion 2.0% at 1024 (its wavelengths' colours add noise), rough 1.3-1.45% at 4096.
    QTest::addColumn<int>("samples");
    QTest::newRow("volume, smooth, 1.5") << 0.0 << 1.5 << 1.0 << 0.0 << 1.0 << 1024;
    QTest::newRow("volume, rough 0.3, 1.5") << 0.3 << 1.5 << 1.0 << 0.0 << 1.0 << 4096;
    QTest::newRow("volume, smooth, diamond 2.42") << 0.0 << 2.42 << 1.0 << 0.0 << 2.0 << 1024;
    QTest::newRow("volume, smooth, dispersion 1") << 0.0 << 1.5 << 1.0 << 1.0 << 1.0 << 4096;
    QTest::newRow("thin, smooth") << 0.0 << 1.5 << 0.0 << 0.0 << 1.0 << 1024;
    QTest::newRow("thin, rough 0.3") << 0.3 << 1.5 << 0.0 << 0.0 << 1.0 << 4096;
}

void TransmissionTruthTest::glassFurnaceIsUniform()
{
    QFETCH(double, roughness);
    QFETCH(double, ior);
    QFETCH(double, thickness);
    QFETCH(double, dispersion);
    QFETCH(double, radiance);
    QFETCH(int, samples);
    MaterialInfo material = glass(roughness, ior, thickness);
    material.dispersion = dispersion;
    SceneTruthStats stats;
    const Image image = renderSceneTruth(
        sphereScene(material, Environment::uniform(glm::dvec3(radiance))), settings(kSize, samples), &stats);
    int pixels = 0;
    double mean = 0.0;
    const double worst = worstSphereDeparture(image, radiance, &pixels, &mean);
    qInfo("%d sphere pixels at %d spp (%.2f s): mean %.4f L, worst %.4f off L", pixels, samples,
        stats.seconds, mean / radiance, worst);
    QVERIFY(pixels > kSize * kSize / 3);
    // The bound: every sphere pixel within 2% of L.
    QVERIFY2(worst < 0.02, qPrintable(QStringLiteral("worst pixel %1 off").arg(worst)));
}

void TransmissionTruthTest::absorptionIsBeerLambert_data()
{
    QTest::addColumn<double>("thickness"); // 0: thin-walled, which absorbs nothing
    QTest::addColumn<double>("r");
    QTest::addColumn<double>("g");
    QTest::addColumn<double>("b");
    QTest::addColumn<double>("distance");
    QTest::newRow("tinted, distance 1") << 1.0 << 0.5 << 0.8 << 1.0 << 1.0;
    QTest::newRow("tinted, distance 4") << 1.0 << 0.2 << 0.6 << 0.9 << 4.0;
    QTest::newRow("opaque red channel") << 1.0 << 0.0 << 0.5 << 0.5 << 0.5;
    QTest::newRow("thin wall ignores it") << 0.0 << 0.5 << 0.8 << 1.0 << 1.0;
}

void TransmissionTruthTest::absorptionIsBeerLambert()
{
    QFETCH(double, thickness);
    QFETCH(double, r);
    QFETCH(double, g);
    QFETCH(double, b);
    QFETCH(double, distance);
    MaterialInfo material = glass(0.0, 1.5, thickness);
    material.attenuationColor = glm::dvec3(r, g, b);
    material.attenuationDistance = distance;
    // One pixel, the ray along the axis through the centre.
    const Image image
        = renderSceneTruth(sphereScene(material, Environment::uniform(glm::dvec3(1.0))), settings(1, 4096));
    const double f0 = 0.04;
    for (int c = 0; c < 3; ++c) {
        const double colour = glm::dvec3(r, g, b)[c];
        const double a = thickness > 0.0 ? (colour > 0.0 ? std::pow(colour, 2.0 / distance) : 0.0) : 1.0;
        const double expected = f0 + (1.0 - f0) * (1.0 - f0) * a / (1.0 - f0 * a);
        const double got = image.at(0, 0)[c];
        qInfo("channel %d: %.5f, expected %.5f", c, got, expected);
        QVERIFY2(std::abs(got - expected) < 0.005,
            qPrintable(QStringLiteral("channel %1: %2, expected %3").arg(c).arg(got).arg(expected)));
    }
}

void TransmissionTruthTest::dispersionFollowsTheAbbeNumber()
{
    // KHR_materials_dispersion: V_d = (n_d - 1) / (n_F - n_C) with dispersion = 20 / V_d; the d
    // line (587.56 nm) keeps the material's index.
    for (const double ior : {1.33, 1.5, 2.42})
        for (const double dispersion : {0.33, 1.0, 2.04}) {
            const double nd = shading::dispersedIor(ior, dispersion, 587.56);
            const double spread = shading::dispersedIor(ior, dispersion, 486.13)
                - shading::dispersedIor(ior, dispersion, 656.27);
            const double abbe = 20.0 / dispersion;
            QVERIFY2(std::abs(nd - ior) < 1e-4 * ior, qPrintable(QString::number(nd)));
            QVERIFY2(std::abs((nd - 1.0) / spread - abbe) < 1e-3 * abbe,
                qPrintable(QStringLiteral("V_d %1 for %2").arg((nd - 1.0) / spread).arg(abbe)));
        }
    QCOMPARE(shading::dispersedIor(1.5, 0.0, 400.0), 1.5);
    QCOMPARE(shading::dispersedIor(1.01, 30.0, 800.0), 1.0); // clamped at 1
    // The wavelength weights average to white over the band (a finer rule than their own).
    glm::dvec3 mean(0.0);
    constexpr int kSteps = 47000;
    for (int i = 0; i < kSteps; ++i)
        mean += shading::wavelengthRgbWeight(shading::kVisibleShortest
            + (i + 0.5) * (shading::kVisibleLongest - shading::kVisibleShortest) / kSteps);
    mean /= double(kSteps);
    for (int c = 0; c < 3; ++c)
        QVERIFY2(std::abs(mean[c] - 1.0) < 1e-4, qPrintable(QString::number(mean[c])));
    // Red long, blue short.
    QVERIFY(shading::wavelengthRgbWeight(650.0).r > shading::wavelengthRgbWeight(650.0).b);
    QVERIFY(shading::wavelengthRgbWeight(450.0).b > shading::wavelengthRgbWeight(450.0).r);
}

void TransmissionTruthTest::dispersionSpreadsColourAndKeepsLight()
{
    // A smooth glass sphere under the built-in sky: dispersion moves light between channels and
    // places (the image changes far beyond the noise) but neither adds nor loses any (the mean
    // radiance over the sphere stays).
    const Environment sky = Environment::builtin(Environment::Builtin::Sky, 128);
    MaterialInfo material = glass(0.0, 1.5, 1.0);
    const Image clear = renderSceneTruth(sphereScene(material, sky), settings(kSize, 256, 1));
    const Image clearAgain = renderSceneTruth(sphereScene(material, sky), settings(kSize, 256, 2));
    material.dispersion = 2.0;
    const Image dispersive = renderSceneTruth(sphereScene(material, sky), settings(kSize, 256, 1));
    // The sum of the sphere's pixels' channels.
    const auto total = [](const Image& image) {
        double sum = 0.0;
        const PixelMask mask = sphereMask(image.width(), image.height());
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                if (mask[std::size_t(y * image.width() + x)]) {
                    const glm::vec4 p = image.at(x, y);
                    sum += double(p.r) + double(p.g) + double(p.b);
                }
        return sum;
    };
    const double noise = relativeRmse(clearAgain, clear);
    const double change = relativeRmse(dispersive, clear);
    const double totalClear = total(clear);
    const double totalDispersive = total(dispersive);
    qInfo("relative RMSE: two seeds %.4f, dispersion 2 against none %.4f; total %.1f against %.1f", noise,
        change, totalDispersive, totalClear);
    QVERIFY2(change > 3.0 * noise, qPrintable(QStringLiteral("%1 against noise %2").arg(change).arg(noise)));
    QVERIFY2(std::abs(totalDispersive - totalClear) < 0.01 * totalClear,
        qPrintable(QStringLiteral("%1 against %2").arg(totalDispersive).arg(totalClear)));
}

QTEST_GUILESS_MAIN(TransmissionTruthTest)
#include "TransmissionTruthTest.moc"
