// The CPU twins of the tone mappers and display encodings (core/image/ToneMap.h): known values from
// their sources, 0 -> 0, monotonicity along a grey ramp, limits, finiteness over 1e-6..1e6.
// tests/RendererGLTest.cpp holds the GPU pass (tonemap.frag) to these functions.

#include "core/image/ToneMap.h"

#include <QtTest/QTest>

#include <cmath>
#include <string>

using namespace facet;
using namespace facet::tonemap;

namespace {

constexpr ToneMapper kAllMappers[] = {ToneMapper::None,     ToneMapper::Reinhard,       ToneMapper::Exposure,
                                      ToneMapper::Aces,     ToneMapper::KhronosNeutral, ToneMapper::AgX};

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

} // namespace

class ToneMappingTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void knownValues();
    void zeroMapsToZero();
    void greyRampIsMonotonicAndBounded();
    void highlightsApproachWhite();
    void extremeInputsStayFinite();
    void srgbPiecewiseCurve();
    void gammaEncoding();
    void exposureIsAPowerOfTwo();
};

void ToneMappingTest::knownValues()
{
    // Reinhard 2002 eq. 3: 1 / (1 + 1).
    QCOMPARE(toneMapReinhard(glm::dvec3(1.0)).x, 0.5);
    // 1 - e^-1.
    QVERIFY(std::abs(toneMapExposure(glm::dvec3(1.0)).y - (1.0 - std::exp(-1.0))) < 1e-15);
    // None clamps.
    QCOMPARE(toneMapNone(glm::dvec3(2.0, 0.5, -1.0)), glm::dvec3(1.0, 0.5, 0.0));
    // Khronos PBR Neutral: below the compression start the curve only subtracts the toe offset,
    // 0.04 when the smallest channel is at least 0.08, x - 6.25 x^2 below (spec, section "Toe").
    QVERIFY(std::abs(toneMapKhronosPbrNeutral(glm::dvec3(0.5)).x - 0.46) < 1e-12);
    QVERIFY(std::abs(toneMapKhronosPbrNeutral(glm::dvec3(0.05)).x - 6.25 * 0.05 * 0.05) < 1e-12);
    // At the compression start (0.76 after the offset, i.e. input 0.8) the curve is continuous.
    const double justBelow = toneMapKhronosPbrNeutral(glm::dvec3(0.8 - 1e-9)).x;
    const double justAbove = toneMapKhronosPbrNeutral(glm::dvec3(0.8 + 1e-9)).x;
    QVERIFY(std::abs(justAbove - justBelow) < 1e-8);
    // ACES (Hill): grey passes the input matrix unchanged (rows sum to 1), then the rational fit
    // gives (0.18 (0.18 + 0.0245786) - 0.000090537) / (0.18 (0.983729 0.18 + 0.432951) + 0.238081)
    // = 0.036733 / 0.347885 = 0.10559 (hence the Sample Viewer's optional 1/0.6 exposure boost).
    const double acesMidGrey = toneMapAcesHill(glm::dvec3(0.18)).x;
    QVERIFY2(std::abs(acesMidGrey - 0.10559) < 2e-4, std::to_string(acesMidGrey).c_str());
    // Grey in, grey out: the matrices' rows sum to 1 (to 5 digits).
    const glm::dvec3 acesGrey = toneMapAcesHill(glm::dvec3(0.4));
    QVERIFY(std::abs(acesGrey.x - acesGrey.y) < 1e-4 && std::abs(acesGrey.y - acesGrey.z) < 1e-4);
    // AgX: mid grey 0.18 sits at (log2(0.18) + 12.47393) / 16.49999 = 0.6061 of the log range;
    // the polynomial gives 0.4967 (display-encoded), and 0.4967^2.2 = 0.2145 display-linear
    // (the matrices keep grey grey to 1e-4).
    const glm::dvec3 agxGrey = toneMapAgx(glm::dvec3(0.18));
    QVERIFY2(std::abs(agxGrey.x - 0.2145) < 2e-3, std::to_string(agxGrey.x).c_str());
    QVERIFY(std::abs(agxGrey.x - agxGrey.y) < 1e-3 && std::abs(agxGrey.y - agxGrey.z) < 1e-3);
}

void ToneMappingTest::zeroMapsToZero()
{
    for (ToneMapper mapper : kAllMappers) {
        const glm::dvec3 out = toneMap(mapper, glm::dvec3(0.0));
        QVERIFY2(out == glm::dvec3(0.0), toString(mapper));
        QVERIFY(displayTransform(glm::dvec3(0.0), 3.0, mapper, DisplayEncoding::SRGB, 2.2) == glm::dvec3(0.0));
    }
}

void ToneMappingTest::greyRampIsMonotonicAndBounded()
{
    for (ToneMapper mapper : kAllMappers) {
        double previous = 0.0;
        for (int i = 0; i <= 1200; ++i) {
            const double x = std::pow(10.0, -6.0 + 12.0 * i / 1200.0); // 1e-6 .. 1e6
            const glm::dvec3 out = toneMap(mapper, glm::dvec3(x));
            const std::string where = std::string(toString(mapper)) + " at " + std::to_string(x);
            QVERIFY2(finite(out), where.c_str());
            QVERIFY2(out.x >= 0.0 && out.x <= 1.0, where.c_str());
            // Non-decreasing (1e-12 slack for rounding in the flat, clamped parts).
            QVERIFY2(out.x >= previous - 1e-12, (where + ": " + std::to_string(out.x) + " < "
                                                + std::to_string(previous)).c_str());
            previous = out.x;
        }
    }
}

void ToneMappingTest::highlightsApproachWhite()
{
    // Curves with a shoulder reach (close to) 1 for very bright input; None reaches it at 1.
    QCOMPARE(toneMapNone(glm::dvec3(1.0)).x, 1.0);
    QVERIFY(toneMapReinhard(glm::dvec3(1e6)).x > 0.999998);
    QCOMPARE(toneMapExposure(glm::dvec3(100.0)).x, 1.0);
    QCOMPARE(toneMapAcesHill(glm::dvec3(1e6)).x, 1.0); // the fit tends to 1.0165 and is clamped
    QVERIFY(toneMapKhronosPbrNeutral(glm::dvec3(1e6)).x > 0.9999);
    // AgX saturates at the top of its log range: the polynomial gives 0.9986 there.
    QVERIFY(toneMapAgx(glm::dvec3(1e6)).x > 0.99);
    QVERIFY(toneMapAgx(glm::dvec3(1e6)) == toneMapAgx(glm::dvec3(1e3)));
}

void ToneMappingTest::extremeInputsStayFinite()
{
    const glm::dvec3 inputs[] = {glm::dvec3(1e-30), glm::dvec3(1e6, 0.0, 1e-6), glm::dvec3(65504.0),
                                 glm::dvec3(1e30), glm::dvec3(-1.0, 2.0, 0.5)};
    for (ToneMapper mapper : kAllMappers)
        for (const glm::dvec3& in : inputs)
            for (DisplayEncoding encoding : {DisplayEncoding::SRGB, DisplayEncoding::Gamma}) {
                const glm::dvec3 out = displayTransform(in, 0.0, mapper, encoding, 2.2);
                QVERIFY2(finite(out), toString(mapper));
                QVERIFY2(glm::all(glm::greaterThanEqual(out, glm::dvec3(0.0))), toString(mapper));
                QVERIFY2(glm::all(glm::lessThanEqual(out, glm::dvec3(1.0))), toString(mapper));
            }
}

void ToneMappingTest::srgbPiecewiseCurve()
{
    QCOMPARE(linearToSrgb(0.0), 0.0);
    QCOMPARE(linearToSrgb(1.0), 1.0);
    // The two pieces meet at 0.0031308 -> 0.04045 (IEC 61966-2-1).
    QVERIFY(std::abs(linearToSrgb(0.0031308) - 0.04045) < 1e-5);
    QVERIFY(std::abs(linearToSrgb(0.5) - 0.735356983) < 1e-8);
    QVERIFY(std::abs(linearToSrgb(0.18) - 0.461356) < 1e-6);
    for (int i = 0; i <= 100; ++i) {
        const double x = i / 100.0;
        QVERIFY(std::abs(srgbToLinear(linearToSrgb(x)) - x) < 1e-12);
    }
}

void ToneMappingTest::gammaEncoding()
{
    QVERIFY(std::abs(encodeDisplay(glm::dvec3(0.5), DisplayEncoding::Gamma, 2.2).x - std::pow(0.5, 1.0 / 2.2))
            < 1e-15);
    QCOMPARE(encodeDisplay(glm::dvec3(0.25), DisplayEncoding::Gamma, 1.0).x, 0.25);
    QCOMPARE(encodeDisplay(glm::dvec3(2.0), DisplayEncoding::Gamma, 2.4).x, 1.0);
}

void ToneMappingTest::exposureIsAPowerOfTwo()
{
    // +1 EV doubles the radiance before the curve: 0.25 at +1 EV equals 0.5 at 0 EV.
    for (ToneMapper mapper : kAllMappers) {
        const glm::dvec3 a = displayTransform(glm::dvec3(0.25), 1.0, mapper, DisplayEncoding::SRGB, 2.2);
        const glm::dvec3 b = displayTransform(glm::dvec3(0.5), 0.0, mapper, DisplayEncoding::SRGB, 2.2);
        QVERIFY2(glm::all(glm::lessThan(glm::abs(a - b), glm::dvec3(1e-12))), toString(mapper));
    }
    QVERIFY(std::abs(displayTransform(glm::dvec3(0.5), -1.0, ToneMapper::None, DisplayEncoding::SRGB, 2.2).x
                     - linearToSrgb(0.25))
            < 1e-15);
}

QTEST_APPLESS_MAIN(ToneMappingTest)
#include "ToneMappingTest.moc"
