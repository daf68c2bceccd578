// core/image/HeatMap: the error view's colour scale. Its ends, its stops, that it darkens nowhere along
// the way (luminance rises monotonically: "more error" never looks like less), the clamps, and
// the values off the scale.

#include "core/image/HeatMap.h"

#include <QtTest/QTest>

#include <cmath>
#include <limits>

using namespace facet;

Q_DECLARE_METATYPE(glm::vec3)

namespace {

double luminance(const glm::vec3& c)
{
    // Rec.709 weights on the sRGB-encoded values: enough to order the stops.
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

bool near(const glm::vec3& a, const glm::vec3& b, float tolerance = 1.0f / 255.0f)
{
    return std::abs(a.r - b.r) <= tolerance && std::abs(a.g - b.g) <= tolerance
        && std::abs(a.b - b.b) <= tolerance;
}

} // namespace

class HeatMapTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void values_data()
    {
        QTest::addColumn<double>("value");
        QTest::addColumn<double>("scale");
        QTest::addColumn<glm::vec3>("expected");
        const glm::vec3 first = glm::vec3(68, 1, 84) / 255.0f;
        const glm::vec3 middle = glm::vec3(33, 144, 141) / 255.0f;
        const glm::vec3 last = glm::vec3(253, 231, 37) / 255.0f;
        QTest::newRow("0") << 0.0 << 0.25 << first;
        QTest::newRow("negative clamps to 0") << -1.0 << 0.25 << first;
        QTest::newRow("half the scale") << 0.125 << 0.25 << middle;
        QTest::newRow("the scale") << 0.25 << 0.25 << last;
        QTest::newRow("just over the scale") << 0.2501 << 0.25 << heatmap::kOverScale;
        QTest::newRow("far over") << 1e9 << 0.25 << heatmap::kOverScale;
        QTest::newRow("another scale, half") << 0.5 << 1.0 << middle;
        QTest::newRow("no scale") << 0.0 << 0.0 << heatmap::kOverScale;
        QTest::newRow("between two stops")
            << 0.0625 << 1.0 << (glm::vec3(68, 1, 84) + glm::vec3(71, 44, 122)) / 2.0f / 255.0f;
    }
    void values()
    {
        QFETCH(double, value);
        QFETCH(double, scale);
        QFETCH(glm::vec3, expected);
        const glm::vec3 got = heatmap::color(value, scale);
        QVERIFY2(
            near(got, expected), qPrintable(QStringLiteral("%1 %2 %3").arg(got.r).arg(got.g).arg(got.b)));
    }

    void rampBrightensMonotonically()
    {
        double previous = -1.0;
        for (int i = 0; i <= 1000; ++i) {
            const glm::vec3 c = heatmap::ramp(i / 1000.0);
            QVERIFY(c.r >= 0.0f && c.r <= 1.0f && c.g >= 0.0f && c.g <= 1.0f && c.b >= 0.0f && c.b <= 1.0f);
            const double l = luminance(c);
            QVERIFY2(l > previous, qPrintable(QString::number(i)));
            previous = l;
        }
        // Off the map: brighter than any colour on it.
        QVERIFY(luminance(heatmap::kOverScale) > previous);
    }

    void rampClampsAndIgnoresNaN()
    {
        QVERIFY(near(heatmap::ramp(-3.0), heatmap::ramp(0.0), 0.0f));
        QVERIFY(near(heatmap::ramp(7.0), heatmap::ramp(1.0), 0.0f));
        QVERIFY(near(heatmap::ramp(std::numeric_limits<double>::quiet_NaN()), heatmap::ramp(0.0), 0.0f));
    }
};

QTEST_APPLESS_MAIN(HeatMapTest)
#include "HeatMapTest.moc"
