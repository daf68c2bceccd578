#pragma once
// Error of a rendered image against a ground truth over a mask of pixels: the reference view's
// sphere (docs/architecture.md; core/shading/ReferenceView.h) for `facet bench` and the accuracy tests
// (docs/accuracy.md), the visible object for the window's error view (ui/compare/CompareRenderer.h), so
// that every number in docs/ and on screen means the same thing.
//
// Over the reference view only interior sphere pixels count (referenceview::isInteriorSpherePixel,
// margin 1): the silhouette is where a tessellated sphere and the analytic one disagree, and the
// background is the environment, not the material. Over any other view, objectMask() gives the
// same: the pixels the object covers whole, one pixel in from its silhouette. Colour is the RGB
// of linear radiance; alpha is ignored (except by objectMask, which reads coverage from it).

#include <cstddef>
#include <cstdint>
#include <vector>

namespace facet {

class Image;

// One byte per pixel, row-major, top row first (as Image): nonzero where a pixel counts.
using PixelMask = std::vector<std::uint8_t>;

// The reference view's interior sphere pixels of a width x height image.
PixelMask sphereMask(int width, int height);
// The pixels of `coverage` whose alpha is at least kFullCoverage and whose neighbours within
// `margin` pixels (a square) are too: the object, without its silhouette (where a test and a
// truth sampled at different sub-pixel positions disagree about which surface they see).
// Renders with RenderScene::coverageAlpha write alpha 0 where the background shows.
inline constexpr float kFullCoverage = 0.999f;
PixelMask objectMask(const Image& coverage, int margin = 1);

// sqrt(sum_p |test_p - truth_p|^2 / sum_p |truth_p|^2) over the RGB of the pixels p of `mask`
// (|.| the Euclidean norm of RGB): a relative RMSE, 0 for a perfect match, 0.01 for "1%".
// It weights pixels by their brightness, so a dark region badly off counts little; use
// errorStats() for the worst pixel too. The sphere overload counts the interior sphere pixels.
// Returns NaN (which fails every `<` comparison of a test) when the images (or the mask) differ
// in size, the mask has no pixel, or the truth is black there.
double relativeRmse(const Image& test, const Image& truth);
double relativeRmse(const Image& test, const Image& truth, const PixelMask& mask);

struct ImageErrorStats {
    double relativeRmse = 0.0; // as relativeRmse() above
    // Per-pixel relative error |test_p - truth_p| / max(|truth_p|, floor), with
    // floor = floorFraction * mean_p |truth_p|: without a floor a nearly black pixel would
    // dominate with an error that nobody can see.
    double maxRelativeError = 0.0;
    double meanRelativeError = 0.0;
    std::size_t pixelCount = 0; // pixels compared
};

// relativeRmse() and the per-pixel relative errors in one pass. Every field is NaN (pixelCount 0)
// in the cases where relativeRmse() returns NaN.
inline constexpr double kDefaultErrorFloor = 0.1;
ImageErrorStats errorStats(
    const Image& test, const Image& truth, const PixelMask& mask, double floorFraction = kDefaultErrorFloor);
ImageErrorStats sphereErrorStats(
    const Image& test, const Image& truth, double floorFraction = kDefaultErrorFloor);

// The per-pixel relative errors of errorStats() as an image's worth of values (row-major, top
// row first): NaN outside `mask`. What the error view's heat map shows. Empty when the sizes differ.
std::vector<float> relativeErrors(
    const Image& test, const Image& truth, const PixelMask& mask, double floorFraction = kDefaultErrorFloor);

// A mean's own noise per pixel with the same normalisation: sqrt(variance_p) / max(|mean_p|, floor)
// with the floor of relativeErrors() taken from `mean`; NaN outside `mask`. `variance` is the
// estimated variance of each pixel's mean (render/FrameAccumulator::variances), summed over RGB.
std::vector<float> relativeNoise(const Image& mean, const std::vector<float>& variance, const PixelMask& mask,
    double floorFraction = kDefaultErrorFloor);

// The whole mean's noise with relativeRmse()'s normalisation: sqrt(sum_p variance_p / sum_p |mean_p|^2)
// over `mask` (empty: every pixel); 0 for a black mean. What FrameAccumulator::noise reports.
double relativeNoiseRmse(const Image& mean, const std::vector<float>& variance, const PixelMask& mask = {});

} // namespace facet
