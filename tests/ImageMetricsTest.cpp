// core/ImageMetrics: the relative RMSE and per-pixel errors over the reference view's interior
// sphere pixels, against values worked out by hand.

#include <cmath>
#include <limits>

#include <QtTest/QTest>

#include "core/Image.h"
#include "core/ImageMetrics.h"
#include "core/ReferenceView.h"

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
};

QTEST_APPLESS_MAIN(ImageMetricsTest)
#include "ImageMetricsTest.moc"
