#include "core/image/ImageMetrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "core/image/Image.h"
#include "core/shading/ReferenceView.h"

namespace facet {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

ImageErrorStats invalidStats()
{
    return {kNaN, kNaN, kNaN, 0};
}

glm::dvec3 rgb(const Image& image, std::size_t index)
{
    return glm::dvec3(glm::vec3(image.data()[index]));
}

bool fits(const Image& image, const PixelMask& mask)
{
    return !image.isEmpty() && mask.size() == image.pixelCount();
}

// The floor of the per-pixel relative errors: floorFraction times the mean |truth| over the mask.
double errorFloor(const Image& truth, const PixelMask& mask, double floorFraction)
{
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < mask.size(); ++i)
        if (mask[i]) {
            sum += glm::length(rgb(truth, i));
            ++count;
        }
    return count ? std::max(floorFraction, 0.0) * sum / double(count) : 0.0;
}

} // namespace

PixelMask sphereMask(int width, int height)
{
    PixelMask mask(std::size_t(std::max(width, 0)) * std::size_t(std::max(height, 0)), 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            mask[std::size_t(y) * std::size_t(width) + std::size_t(x)]
                = referenceview::isInteriorSpherePixel(x, y, width, height) ? 1 : 0;
    return mask;
}

PixelMask objectMask(const Image& coverage, int margin)
{
    const int width = coverage.width();
    const int height = coverage.height();
    PixelMask mask(coverage.pixelCount(), 0);
    margin = std::max(margin, 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            bool whole = true;
            for (int dy = -margin; dy <= margin && whole; ++dy)
                for (int dx = -margin; dx <= margin && whole; ++dx) {
                    const int sx = x + dx;
                    const int sy = y + dy;
                    // Beyond the image's edge nothing is known to be covered: the object's
                    // continuation there may be its silhouette.
                    whole = sx >= 0 && sy >= 0 && sx < width && sy < height
                        && coverage.at(sx, sy).a >= kFullCoverage;
                }
            mask[std::size_t(y) * std::size_t(width) + std::size_t(x)] = whole ? 1 : 0;
        }
    return mask;
}

double relativeRmse(const Image& test, const Image& truth)
{
    return sphereErrorStats(test, truth).relativeRmse;
}

double relativeRmse(const Image& test, const Image& truth, const PixelMask& mask)
{
    return errorStats(test, truth, mask).relativeRmse;
}

ImageErrorStats sphereErrorStats(const Image& test, const Image& truth, double floorFraction)
{
    return errorStats(test, truth, sphereMask(truth.width(), truth.height()), floorFraction);
}

std::vector<float> relativeErrors(
    const Image& test, const Image& truth, const PixelMask& mask, double floorFraction)
{
    if (test.width() != truth.width() || test.height() != truth.height() || !fits(truth, mask))
        return {};
    const double floor = errorFloor(truth, mask, floorFraction);
    std::vector<float> errors(mask.size(), std::numeric_limits<float>::quiet_NaN());
    for (std::size_t i = 0; i < mask.size(); ++i)
        if (mask[i]) {
            const glm::dvec3 reference = rgb(truth, i);
            // NaN in `test` must not vanish in std::max: it stays NaN here.
            errors[i]
                = float(glm::length(rgb(test, i) - reference) / std::max(glm::length(reference), floor));
        }
    return errors;
}

std::vector<float> relativeNoise(
    const Image& mean, const std::vector<float>& variance, const PixelMask& mask, double floorFraction)
{
    if (!fits(mean, mask) || variance.size() != mask.size())
        return {};
    const double floor = errorFloor(mean, mask, floorFraction);
    std::vector<float> noise(mask.size(), std::numeric_limits<float>::quiet_NaN());
    for (std::size_t i = 0; i < mask.size(); ++i)
        if (mask[i])
            noise[i] = float(
                std::sqrt(std::max(double(variance[i]), 0.0)) / std::max(glm::length(rgb(mean, i)), floor));
    return noise;
}

double relativeNoiseRmse(const Image& mean, const std::vector<float>& variance, const PixelMask& mask)
{
    double sumVariance = 0.0;
    double signal = 0.0;
    const std::size_t count = std::min(variance.size(), mean.pixelCount());
    for (std::size_t i = 0; i < count; ++i) {
        if (!mask.empty() && (i >= mask.size() || !mask[i]))
            continue;
        const glm::dvec3 m = rgb(mean, i);
        sumVariance += double(variance[i]);
        signal += glm::dot(m, m);
    }
    return signal > 0.0 ? std::sqrt(sumVariance / signal) : 0.0;
}

ImageErrorStats errorStats(const Image& test, const Image& truth, const PixelMask& mask, double floorFraction)
{
    if (test.width() != truth.width() || test.height() != truth.height() || !fits(truth, mask))
        return invalidStats();
    double errorSquared = 0.0;
    double truthSquared = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < mask.size(); ++i)
        if (mask[i]) {
            const glm::dvec3 reference = rgb(truth, i);
            const glm::dvec3 difference = rgb(test, i) - reference;
            errorSquared += glm::dot(difference, difference);
            truthSquared += glm::dot(reference, reference);
            ++count;
        }
    if (count == 0 || !(truthSquared > 0.0))
        return invalidStats();

    ImageErrorStats stats;
    stats.pixelCount = count;
    stats.relativeRmse = std::sqrt(errorSquared / truthSquared);
    double relativeSum = 0.0;
    const std::vector<float> errors = relativeErrors(test, truth, mask, floorFraction);
    for (std::size_t i = 0; i < mask.size(); ++i) {
        if (!mask[i])
            continue;
        const double relative = errors[i];
        relativeSum += relative;
        stats.maxRelativeError = std::isnan(relative) ? relative : std::max(stats.maxRelativeError, relative);
        if (std::isnan(stats.maxRelativeError))
            break;
    }
    stats.meanRelativeError = std::isnan(stats.maxRelativeError) ? kNaN : relativeSum / double(count);
    return stats;
}

} // namespace facet
