// KHR_materials_anisotropy's terms (core/shading/Anisotropy), the lobe's CPU ground truth before
// any renderer reads it: the roughnesses the extension derives; at strength 0 the isotropic GGX
// terms exactly; the distribution's projected area 1 for every pair of roughnesses (a quadrature
// independent of the sampler); the extension's visibility equal to Smith's height-correlated G2
// with the anisotropic Lambda; the visible-normal sampler's pdf agreeing with a uniform
// estimator of the same integral; the direction's rotation; and the lobe's white furnace, which
// never exceeds 1 and whose single-scattering loss is printed per row (docs/shading.md,
// "Anisotropy").

#include <algorithm>
#include <cmath>

#include <QtTest/QTest>

#include <glm/geometric.hpp>

#include "TestSupport.h"
#include "core/shading/Anisotropy.h"
#include "core/shading/Brdf.h"
#include "core/shading/Sampling.h"

using namespace facet;
using namespace facet::shading;

namespace {

using test::direction;

// Pairs of roughnesses: isotropic, stretched along t, the extension's strongest (alpha_t 1).
const AnisotropicAlpha kAlphas[] = {{0.25, 0.25}, {0.6, 0.1}, {1.0, 0.05}, {0.3, 0.9}, {0.02, 0.5}};

} // namespace

class AnisotropyTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    // alpha_t = mix(alpha, 1, strength^2), alpha_b = alpha (README, "Anisotropy"), alpha the
    // isotropic lobe's (the roughness clamped to 0.045, squared).
    void roughnessesFollowTheExtension_data()
    {
        QTest::addColumn<double>("roughness");
        QTest::addColumn<double>("strength");
        QTest::addColumn<double>("alphaT");
        QTest::addColumn<double>("alphaB");
        QTest::newRow("strength 0: isotropic") << 0.5 << 0.0 << 0.25 << 0.25;
        QTest::newRow("strength 0.5") << 0.5 << 0.5 << 0.25 + 0.75 * 0.25 << 0.25;
        QTest::newRow("strength 1: alpha_t 1") << 0.3 << 1.0 << 1.0 << 0.09;
        QTest::newRow("roughness 0 clamped") << 0.0 << 0.0 << kMinAlpha << kMinAlpha;
        QTest::newRow("strength above 1 clamped") << 0.5 << 3.0 << 1.0 << 0.25;
        QTest::newRow("negative strength clamped") << 0.5 << -1.0 << 0.25 << 0.25;
    }
    void roughnessesFollowTheExtension()
    {
        QFETCH(double, roughness);
        QFETCH(double, strength);
        QFETCH(double, alphaT);
        QFETCH(double, alphaB);
        const AnisotropicAlpha a = anisotropicAlpha(roughness, strength);
        QVERIFY2(std::abs(a.t - alphaT) < 1e-12, qPrintable(QString::number(a.t)));
        QVERIFY2(std::abs(a.b - alphaB) < 1e-12, qPrintable(QString::number(a.b)));
    }

    // Equal roughnesses are the isotropic lobe: D_GGX and V_SmithGGXCorrelated, at every angle
    // (to 1e-10 relative: the two forms round differently near the peak of a mirror, D ~ 7.8e4).
    void isotropicLimitIsGgx_data()
    {
        QTest::addColumn<double>("roughness");
        for (double r : {0.045, 0.2, 0.5, 0.8, 1.0})
            QTest::addRow("roughness %g", r) << r;
    }
    void isotropicLimitIsGgx()
    {
        QFETCH(double, roughness);
        const AnisotropicAlpha a = anisotropicAlpha(roughness, 0.0);
        const double alpha = alphaFromRoughness(roughness);
        for (double NoV : {1.0, 0.7, 0.3, 0.05})
            for (double NoL : {1.0, 0.5, 0.1})
                for (double phi : {0.0, 1.0, 2.5, 4.0}) {
                    const glm::dvec3 v = direction(NoV, 0.3);
                    const glm::dvec3 l = direction(NoL, phi);
                    const glm::dvec3 h = glm::normalize(v + l);
                    const double d = D_GGX(h.z, alpha);
                    QVERIFY2(std::abs(D_GGXAnisotropic(h, a) - d) <= 1e-10 * std::max(1.0, d),
                        qPrintable(QStringLiteral("D %1 != %2").arg(D_GGXAnisotropic(h, a)).arg(d)));
                    const double vis = V_SmithGGXCorrelated(NoV, NoL, alpha);
                    QVERIFY2(std::abs(V_GGXAnisotropic(v, l, a) - vis) <= 1e-10 * std::max(1.0, vis),
                        qPrintable(QStringLiteral("V %1 != %2").arg(V_GGXAnisotropic(v, l, a)).arg(vis)));
                }
    }

    // The integral of D(h) (n.h) over the hemisphere of normals is 1 for every pair. Midpoint
    // rule in azimuth and in x = tan^2(theta), where D (n.h) dw = D cos^4(theta) dx dphi / 2,
    // mapped to [0, 1) by x = s (y / (1 - y))^2 with s the smaller alpha squared (so the peak's
    // width in x holds many steps): independent of the sampler below.
    void distributionHasUnitProjectedArea_data()
    {
        QTest::addColumn<double>("alphaT");
        QTest::addColumn<double>("alphaB");
        for (const AnisotropicAlpha& a : kAlphas)
            QTest::addRow("alpha_t %g, alpha_b %g", a.t, a.b) << a.t << a.b;
    }
    void distributionHasUnitProjectedArea()
    {
        QFETCH(double, alphaT);
        QFETCH(double, alphaB);
        const AnisotropicAlpha a {alphaT, alphaB};
        constexpr int kPhi = 512;
        constexpr int kY = 8192;
        const double scale = std::min(alphaT, alphaB) * std::min(alphaT, alphaB);
        double sum = 0.0;
        for (int i = 0; i < kPhi; ++i) {
            const double phi = 2.0 * kPi * (i + 0.5) / kPhi;
            for (int j = 0; j < kY; ++j) {
                const double y = (j + 0.5) / kY;
                const double t = y / (1.0 - y);
                const double x = scale * t * t;
                const double dxdy = 2.0 * scale * t / ((1.0 - y) * (1.0 - y));
                const double cos2 = 1.0 / (1.0 + x);
                const double cosTheta = std::sqrt(cos2);
                const glm::dvec3 h = direction(cosTheta, phi);
                sum += D_GGXAnisotropic(h, a) * cos2 * cos2 * 0.5 * dxdy;
            }
        }
        const double area = sum * (2.0 * kPi / kPhi) / kY;
        qInfo("projected area %.6f", area);
        QVERIFY2(std::abs(area - 1.0) < 2e-3, qPrintable(QString::number(area)));
    }

    // The extension's V is Smith's height-correlated G2 = 1 / (1 + Lambda(v) + Lambda(l)) over
    // 4 n.v n.l, with the anisotropic Lambda; and G1 = 1 / (1 + Lambda).
    void visibilityIsHeightCorrelatedSmith()
    {
        for (const AnisotropicAlpha& a : kAlphas)
            for (double NoV : {1.0, 0.6, 0.2, 0.02})
                for (double NoL : {0.9, 0.4, 0.05})
                    for (double phi : {0.0, 0.8, 1.6, 3.0}) {
                        const glm::dvec3 v = direction(NoV, 0.4);
                        const glm::dvec3 l = direction(NoL, phi);
                        const double g2
                            = 1.0 / (1.0 + Lambda_GGXAnisotropic(v, a) + Lambda_GGXAnisotropic(l, a));
                        const double expected = g2 / (4.0 * NoV * NoL);
                        const double actual = V_GGXAnisotropic(v, l, a);
                        QVERIFY2(std::abs(actual - expected) <= 1e-9 * expected,
                            qPrintable(QStringLiteral("%1 != %2").arg(actual).arg(expected)));
                    }
    }

    // The visible-normal sampler draws what its pdf says: the albedo of the lobe (F = 1)
    // estimated with its samples agrees with a plain quadrature over the hemisphere of l, for
    // views along t, along b and between, grazing included.
    void samplerMatchesItsPdf_data()
    {
        QTest::addColumn<double>("alphaT");
        QTest::addColumn<double>("alphaB");
        QTest::addColumn<double>("NoV");
        QTest::addColumn<double>("phi"); // the view's azimuth from t
        for (const AnisotropicAlpha& a :
            {AnisotropicAlpha {0.6, 0.1}, AnisotropicAlpha {0.3, 0.9}, AnisotropicAlpha {1.0, 0.2}})
            for (double NoV : {0.9, 0.4, 0.1})
                for (double phi : {0.0, 0.8, 1.5708})
                    QTest::addRow("alpha (%g, %g), n.v %g, azimuth %g", a.t, a.b, NoV, phi)
                        << a.t << a.b << NoV << phi;
    }
    void samplerMatchesItsPdf()
    {
        QFETCH(double, alphaT);
        QFETCH(double, alphaB);
        QFETCH(double, NoV);
        QFETCH(double, phi);
        const AnisotropicAlpha a {alphaT, alphaB};
        const glm::dvec3 v = direction(NoV, phi);
        const double sampled = anisotropicDirectionalAlbedo(v, a, 1 << 16);
        // Quadrature over l: midpoint in cos(theta) and azimuth (the lobes are at least 0.1 wide).
        constexpr int kTheta = 1024;
        constexpr int kPhi = 1024;
        double sum = 0.0;
        for (int i = 0; i < kTheta; ++i) {
            const double cosTheta = (i + 0.5) / kTheta;
            for (int j = 0; j < kPhi; ++j) {
                const glm::dvec3 l = direction(cosTheta, 2.0 * kPi * (j + 0.5) / kPhi);
                const glm::dvec3 h = glm::normalize(v + l);
                sum += D_GGXAnisotropic(h, a) * V_GGXAnisotropic(v, l, a) * cosTheta;
            }
        }
        const double quadrature = sum * (2.0 * kPi / kPhi) / kTheta;
        qInfo("albedo: sampled %.5f, quadrature %.5f", sampled, quadrature);
        QVERIFY2(std::abs(sampled - quadrature) < 0.01 * std::max(quadrature, 0.1),
            qPrintable(QStringLiteral("%1 != %2").arg(sampled).arg(quadrature)));
        // The sampler's own pdf integrates to 1 over the directions it draws.
        double pdfSum = 0.0;
        for (int i = 0; i < kTheta; ++i) {
            const double cosTheta = (i + 0.5) / kTheta;
            for (int j = 0; j < kPhi; ++j) {
                const glm::dvec3 l = direction(cosTheta, 2.0 * kPi * (j + 0.5) / kPhi);
                pdfSum += pdfVNDFReflectionAnisotropic(v, glm::normalize(v + l), a);
            }
        }
        const double pdfIntegral = pdfSum * (2.0 * kPi / kPhi) / kTheta;
        // Below the horizon the reflected samples are lost (their share is what the furnace loses).
        QVERIFY2(pdfIntegral <= 1.0 + 5e-3 && pdfIntegral >= sampled - 5e-3,
            qPrintable(QString::number(pdfIntegral)));
    }

    // anisotropyRotation turns the direction counter-clockwise in the tangent plane; a
    // zero-length texture direction is t.
    void directionTurnsCounterClockwise_data()
    {
        QTest::addColumn<glm::dvec2>("texture");
        QTest::addColumn<double>("rotation");
        QTest::addColumn<glm::dvec2>("expected");
        const double quarter = kPi / 2.0;
        QTest::newRow("no texture, no rotation") << glm::dvec2(1.0, 0.0) << 0.0 << glm::dvec2(1.0, 0.0);
        QTest::newRow("a quarter turn: along b") << glm::dvec2(1.0, 0.0) << quarter << glm::dvec2(0.0, 1.0);
        QTest::newRow("texture along b, a quarter back")
            << glm::dvec2(0.0, 1.0) << -quarter << glm::dvec2(1.0, 0.0);
        QTest::newRow("texture unnormalised") << glm::dvec2(0.0, -0.3) << 0.0 << glm::dvec2(0.0, -1.0);
        QTest::newRow("zero length: t") << glm::dvec2(0.0) << quarter << glm::dvec2(0.0, 1.0);
    }
    void directionTurnsCounterClockwise()
    {
        QFETCH(glm::dvec2, texture);
        QFETCH(double, rotation);
        QFETCH(glm::dvec2, expected);
        const glm::dvec2 d = anisotropyDirection(texture, rotation);
        QVERIFY2(glm::length(d - expected) < 1e-12, qPrintable(QStringLiteral("(%1, %2)").arg(d.x).arg(d.y)));
    }

    // The lobe's white furnace (F = 1): never above 1; what single scattering loses grows with
    // roughness along either axis and at grazing views (the extension defines no compensation).
    void furnaceNeverGains()
    {
        double lowest = 1.0;
        double highest = 0.0;
        for (double roughness : {0.1, 0.5, 1.0})
            for (double strength : {0.0, 0.5, 1.0})
                for (double NoV : {1.0, 0.5, 0.1})
                    for (double phi : {0.0, 1.5708}) {
                        const double e = anisotropicDirectionalAlbedo(
                            direction(NoV, phi), anisotropicAlpha(roughness, strength), 4096);
                        lowest = std::min(lowest, e);
                        highest = std::max(highest, e);
                        QVERIFY2(e <= 1.0 + 1e-3,
                            qPrintable(QStringLiteral("%1 at roughness %2, strength %3, n.v %4")
                                           .arg(e)
                                           .arg(roughness)
                                           .arg(strength)
                                           .arg(NoV)));
                    }
        qInfo("anisotropic lobe albedo in [%.4f, %.4f]", lowest, highest);
    }
};

QTEST_APPLESS_MAIN(AnisotropyTest)
#include "AnisotropyTest.moc"
