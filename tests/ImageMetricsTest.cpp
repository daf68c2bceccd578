// core/image/ImageMetrics: the relative RMSE and per-pixel errors over the reference view's interior
// sphere pixels, against values worked out by hand.

#include <algorithm>
#include <cmath>
#include <limits>

#include <QtTest/QTest>

#include "core/image/Image.h"
#include "core/image/ImageMetrics.h"
#include "core/shading/ReferenceView.h"

using namespace facet;

namespace {

constexpr int kSize = 32;

// `inside` on the interior sphere pixels, `outside` everywhere else.
Image sphereImage(glm::vec4 inside, glm::vec4 outside)
{
    Image image(kSize, kSize, outside);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            if (referenceview::isInteriorSpherePixel(x, y, kSize, kSize))
                image.at(x, y) = inside;
    return image;
}

std::size_t interiorPixelCount()
{
    std::size_t count = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            count += referenceview::isInteriorSpherePixel(x, y, kSize, kSize) ? 1 : 0;
    return count;
}

} // namespace

class ImageMetricsTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void identicalImagesHaveNoError()
    {
        const Image truth = sphereImage({0.3f, 0.5f, 0.7f, 1.0f}, {2.0f, 2.0f, 2.0f, 1.0f});
        const ImageErrorStats stats = sphereErrorStats(truth, truth);
        QCOMPARE(stats.relativeRmse, 0.0);
        QCOMPARE(stats.maxRelativeError, 0.0);
        QCOMPARE(stats.meanRelativeError, 0.0);
        QCOMPARE(stats.pixelCount, interiorPixelCount());
        QVERIFY(stats.pixelCount > 400); // a 32 x 32 view: the sphere covers about half the image
    }

    // A uniform 10% overestimate is a 10% relative RMSE, a 10% error on every pixel.
    void uniformScaleIsItsRelativeError()
    {
        const Image truth = sphereImage({0.2f, 0.4f, 0.8f, 1.0f}, {});
        const Image test = sphereImage({0.22f, 0.44f, 0.88f, 1.0f}, {});
        QVERIFY(std::abs(relativeRmse(test, truth) - 0.1) < 1e-6);
        const ImageErrorStats stats = sphereErrorStats(test, truth);
        QVERIFY(std::abs(stats.maxRelativeError - 0.1) < 1e-6);
        QVERIFY(std::abs(stats.meanRelativeError - 0.1) < 1e-6);
    }

    // The background and the silhouette are not the material's: they never count.
    void onlyInteriorSpherePixelsCount()
    {
        const Image truth = sphereImage({1.0f, 1.0f, 1.0f, 1.0f}, {5.0f, 5.0f, 5.0f, 1.0f});
        const Image test = sphereImage({1.0f, 1.0f, 1.0f, 0.0f}, {-100.0f, 7.0f, 0.0f, 1.0f});
        QCOMPARE(relativeRmse(test, truth), 0.0); // alpha differs too: ignored
    }

    // One pixel off: the RMSE spreads it over the sphere's energy, the max names it.
    void onePixelOff()
    {
        const Image truth = sphereImage({1.0f, 1.0f, 1.0f, 1.0f}, {});
        Image test = truth;
        test.at(kSize / 2, kSize / 2) = {1.0f, 1.0f, 4.0f, 1.0f}; // |error| = 3, |truth| = sqrt(3)
        const ImageErrorStats stats = sphereErrorStats(test, truth);
        const double n = double(interiorPixelCount());
        QVERIFY(std::abs(stats.relativeRmse - std::sqrt(9.0 / (3.0 * n))) < 1e-9);
        QVERIFY(std::abs(stats.maxRelativeError - 3.0 / std::sqrt(3.0)) < 1e-6);
        QVERIFY(std::abs(stats.meanRelativeError - 3.0 / std::sqrt(3.0) / n) < 1e-6);
    }

    // A dark pixel is judged against a fraction of the mean truth, not its own near-zero value.
    void darkPixelsUseTheFloor()
    {
        Image truth = sphereImage({1.0f, 1.0f, 1.0f, 1.0f}, {});
        truth.at(kSize / 2, kSize / 2) = {0.0f, 0.0f, 0.0f, 1.0f};
        Image test = truth;
        test.at(kSize / 2, kSize / 2) = {0.01f, 0.0f, 0.0f, 1.0f};
        const ImageErrorStats stats = sphereErrorStats(test, truth, 0.1);
        // floor = 0.1 x mean |truth| ~ 0.1 sqrt(3): the error 0.01 is ~5.8% of it.
        QVERIFY2(stats.maxRelativeError > 0.05 && stats.maxRelativeError < 0.06,
            qPrintable(QString::number(stats.maxRelativeError)));
    }

    // Mismatched or unusable input gives NaN, which fails any `error < bound` a test writes.
    void unusableInputIsNaN()
    {
        const Image truth = sphereImage({1.0f, 1.0f, 1.0f, 1.0f}, {});
        QVERIFY(std::isnan(relativeRmse(Image(16, 16), truth))); // size
        QVERIFY(std::isnan(relativeRmse(Image(), Image()))); // empty
        QVERIFY(std::isnan(relativeRmse(truth, Image(kSize, kSize)))); // black truth
        QVERIFY(std::isnan(relativeRmse(Image(2, 2), Image(2, 2, glm::vec4(1.0f))))); // no interior pixel
        Image test = truth;
        test.at(kSize / 2, kSize / 2).g = std::numeric_limits<float>::quiet_NaN();
        const ImageErrorStats stats = sphereErrorStats(test, truth);
        QVERIFY(std::isnan(stats.relativeRmse));
        QVERIFY(std::isnan(stats.maxRelativeError));
        QVERIFY(std::isnan(stats.meanRelativeError));
    }

    // The sphere functions are the mask functions over sphereMask: the same numbers.
    void sphereIsTheMaskOfTheInteriorPixels()
    {
        const PixelMask mask = sphereMask(kSize, kSize);
        QCOMPARE(mask.size(), std::size_t(kSize * kSize));
        std::size_t marked = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const bool inside = mask[std::size_t(y * kSize + x)] != 0;
                QCOMPARE(inside, referenceview::isInteriorSpherePixel(x, y, kSize, kSize));
                marked += inside ? 1 : 0;
            }
        QCOMPARE(marked, interiorPixelCount());
        const Image truth = sphereImage({0.2f, 0.4f, 0.8f, 1.0f}, {1.0f, 1.0f, 1.0f, 1.0f});
        Image test = truth;
        test.at(kSize / 2, kSize / 3) = {0.3f, 0.1f, 0.9f, 1.0f};
        const ImageErrorStats sphere = sphereErrorStats(test, truth);
        const ImageErrorStats masked = errorStats(test, truth, mask);
        QCOMPARE(masked.relativeRmse, sphere.relativeRmse);
        QCOMPARE(masked.maxRelativeError, sphere.maxRelativeError);
        QCOMPARE(masked.meanRelativeError, sphere.meanRelativeError);
        QCOMPARE(masked.pixelCount, sphere.pixelCount);
        QCOMPARE(relativeRmse(test, truth, mask), relativeRmse(test, truth));
    }

    // objectMask: fully covered pixels whose neighbours within the margin are too.
    void objectMaskKeepsTheCoveredInterior_data()
    {
        QTest::addColumn<int>("margin");
        QTest::addColumn<float>("edgeAlpha"); // a ring of partial coverage around a covered square
        QTest::addColumn<int>("expected"); // pixels marked
        // An 8 x 8 image: a covered 4 x 4 square at (2..5, 2..5) inside a ring at (1..6).
        QTest::newRow("margin 0, ring transparent") << 0 << 0.0f << 16;
        QTest::newRow("margin 1, ring transparent") << 1 << 0.0f << 4;
        QTest::newRow("margin 2, ring transparent") << 2 << 0.0f << 0;
        QTest::newRow("margin 0, ring half covered") << 0 << 0.5f << 16;
        QTest::newRow("margin 0, ring just under full") << 0 << 0.998f << 16;
        QTest::newRow("margin 0, ring covered") << 0 << 1.0f << 36;
        QTest::newRow("margin 1, ring covered") << 1 << 1.0f << 16;
    }
    void objectMaskKeepsTheCoveredInterior()
    {
        QFETCH(int, margin);
        QFETCH(float, edgeAlpha);
        QFETCH(int, expected);
        Image coverage(8, 8, glm::vec4(0.5f, 0.5f, 0.5f, 0.0f));
        for (int y = 1; y <= 6; ++y)
            for (int x = 1; x <= 6; ++x)
                coverage.at(x, y).a = (x >= 2 && x <= 5 && y >= 2 && y <= 5) ? 1.0f : edgeAlpha;
        const PixelMask mask = objectMask(coverage, margin);
        QCOMPARE(mask.size(), std::size_t(64));
        int marked = 0;
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x)
                if (mask[std::size_t(y * 8 + x)]) {
                    ++marked;
                    QVERIFY(coverage.at(x, y).a >= kFullCoverage);
                }
        QCOMPARE(marked, expected);
        // An image covered to its edges: the edge is not known to be interior.
        const PixelMask full = objectMask(Image(4, 4, glm::vec4(1.0f)), 1);
        QCOMPARE(std::count(full.begin(), full.end(), std::uint8_t(1)), std::ptrdiff_t(4));
    }

    // relativeErrors: the per-pixel values errorStats' max and mean are made of, NaN outside the mask.
    void relativeErrorsArePerPixel()
    {
        Image truth(4, 1, glm::vec4(1.0f, 1.0f, 1.0f, 1.0f));
        truth.at(3, 0) = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f); // dark: judged against the floor
        Image test = truth;
        test.at(0, 0) = glm::vec4(1.1f, 1.1f, 1.1f, 1.0f); // 10%
        test.at(1, 0) = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f); // 50%
        test.at(3, 0) = glm::vec4(0.0f, 0.0f, 0.1f, 1.0f);
        const PixelMask mask {1, 1, 0, 1};
        const std::vector<float> errors = relativeErrors(test, truth, mask);
        QCOMPARE(errors.size(), std::size_t(4));
        QVERIFY(std::abs(errors[0] - 0.1f) < 1e-6f);
        QVERIFY(std::abs(errors[1] - 0.5f) < 1e-6f);
        QVERIFY(std::isnan(errors[2]));
        // floor = 0.1 x mean |truth| over the mask = 0.1 x (2 sqrt 3) / 3
        const double floor = 0.1 * 2.0 * std::sqrt(3.0) / 3.0;
        QVERIFY(std::abs(double(errors[3]) - 0.1 / floor) < 1e-5);
        const ImageErrorStats stats = errorStats(test, truth, mask);
        QVERIFY(std::abs(stats.maxRelativeError - double(errors[3])) < 1e-6);
        QVERIFY(std::abs(stats.meanRelativeError - double(errors[0] + errors[1] + errors[3]) / 3.0) < 1e-6);
        QCOMPARE(stats.pixelCount, std::size_t(3));
        // Sizes that do not match: nothing.
        QVERIFY(relativeErrors(test, truth, PixelMask(3, 1)).empty());
        QVERIFY(relativeErrors(Image(2, 1), truth, mask).empty());
        QVERIFY(std::isnan(errorStats(test, truth, PixelMask(4, 0)).relativeRmse)); // an empty mask
    }

    // relativeNoise and relativeNoiseRmse: a standard deviation over the same normalisations.
    void noiseIsNormalisedLikeTheError()
    {
        Image mean(3, 1, glm::vec4(2.0f, 0.0f, 0.0f, 1.0f));
        const std::vector<float> variance {0.04f, 0.16f, 1.0f}; // sigma 0.2, 0.4, 1
        const PixelMask mask {1, 1, 0};
        const std::vector<float> noise = relativeNoise(mean, variance, mask);
        QVERIFY(std::abs(noise[0] - 0.1f) < 1e-6f);
        QVERIFY(std::abs(noise[1] - 0.2f) < 1e-6f);
        QVERIFY(std::isnan(noise[2]));
        // sqrt((0.04 + 0.16) / (4 + 4))
        QVERIFY(std::abs(relativeNoiseRmse(mean, variance, mask) - std::sqrt(0.2 / 8.0)) < 1e-7);
        // No mask: every pixel.
        QVERIFY(std::abs(relativeNoiseRmse(mean, variance) - std::sqrt(1.2 / 12.0)) < 1e-7);
        QCOMPARE(relativeNoiseRmse(Image(3, 1), variance), 0.0); // a black mean
        QVERIFY(relativeNoise(mean, {0.1f}, mask).empty());
    }
};

QTEST_APPLESS_MAIN(ImageMetricsTest)
#include "ImageMetricsTest.moc"
