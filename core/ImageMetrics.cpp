#include "core/ImageMetrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>

#include "core/Image.h"
#include "core/ReferenceView.h"

namespace facet {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

ImageErrorStats invalidStats()
{
    return {kNaN, kNaN, kNaN, 0};
}

glm::dvec3 rgb(const Image& image, int x, int y)
{
    return glm::dvec3(glm::vec3(image.at(x, y)));
}

} // namespace

double relativeRmse(const Image& test, const Image& truth)
{
    return sphereErrorStats(test, truth).relativeRmse;
}

ImageErrorStats sphereErrorStats(const Image& test, const Image& truth, double floorFraction)
{
    if (test.width() != truth.width() || test.height() != truth.height() || truth.isEmpty())
        return invalidStats();
    const int width = truth.width();
    const int height = truth.height();

    // First pass: the sums of the relative RMSE and the mean truth (for the per-pixel floor).
    struct Pixel {
        double errorNorm;
        double truthNorm;
    };
    std::vector<Pixel> pixels;
    pixels.reserve(truth.pixelCount());
    double errorSquared = 0.0;
    double truthSquared = 0.0;
    double truthNormSum = 0.0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if (!referenceview::isInteriorSpherePixel(x, y, width, height))
                continue;
            const glm::dvec3 reference = rgb(truth, x, y);
            const glm::dvec3 difference = rgb(test, x, y) - reference;
            errorSquared += glm::dot(difference, difference);
            truthSquared += glm::dot(reference, reference);
            const Pixel pixel {glm::length(difference), glm::length(reference)};
            truthNormSum += pixel.truthNorm;
            pixels.push_back(pixel);
        }
    if (pixels.empty() || !(truthSquared > 0.0))
        return invalidStats();

    ImageErrorStats stats;
    stats.pixelCount = pixels.size();
    stats.relativeRmse = std::sqrt(errorSquared / truthSquared);
    const double floor = std::max(floorFraction, 0.0) * truthNormSum / double(pixels.size());
    double relativeSum = 0.0;
    for (const Pixel& pixel : pixels) {
        // NaN in `test` must not vanish in std::max: it propagates through the sum and the max.
        const double relative = pixel.errorNorm / std::max(pixel.truthNorm, floor);
        relativeSum += relative;
        stats.maxRelativeError = std::isnan(relative) ? relative : std::max(stats.maxRelativeError, relative);
        if (std::isnan(stats.maxRelativeError))
            break;
    }
    stats.meanRelativeError = std::isnan(stats.maxRelativeError) ? kNaN : relativeSum / double(pixels.size());
    return stats;
}

} // namespace facet
