#pragma once
// Error of a rendered image against a ground truth over the reference view's sphere (DESIGN.md;
// core/ReferenceView.h). `facet bench` and the accuracy tests (docs/accuracy.md) measure with these,
// so that every number in docs/ means the same thing.
//
// Only interior sphere pixels count (referenceview::isInteriorSpherePixel, margin 1): the
// silhouette is where a tessellated sphere and the analytic one disagree, and the background is
// the environment, not the material. Colour is the RGB of linear radiance; alpha is ignored.

#include <cstddef>

namespace facet {

class Image;

// sqrt(sum_p |test_p - truth_p|^2 / sum_p |truth_p|^2) over the RGB of the interior sphere pixels
// p (|.| the Euclidean norm of RGB): a relative RMSE, 0 for a perfect match, 0.01 for "1%".
// It weights pixels by their brightness, so a dark region badly off counts little; use
// sphereErrorStats() for the worst pixel too.
// Returns NaN (which fails every `<` comparison of a test) when the images differ in size, have
// no interior sphere pixel, or the truth is black there.
double relativeRmse(const Image& test, const Image& truth);

struct ImageErrorStats {
    double relativeRmse = 0.0; // as relativeRmse() above
    // Per-pixel relative error |test_p - truth_p| / max(|truth_p|, floor), with
    // floor = floorFraction * mean_p |truth_p|: without a floor a nearly black pixel would
    // dominate with an error that nobody can see.
    double maxRelativeError = 0.0;
    double meanRelativeError = 0.0;
    std::size_t pixelCount = 0; // interior sphere pixels compared
};

// relativeRmse() and the per-pixel relative errors in one pass. Every field is NaN (pixelCount 0)
// in the cases where relativeRmse() returns NaN.
ImageErrorStats sphereErrorStats(const Image& test, const Image& truth, double floorFraction = 0.1);

} // namespace facet
