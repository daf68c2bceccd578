#pragma once
// The error view's colour scale (ui/compare/CompareRenderer.h): a value in [0, scale] to a colour of a
// perceptually uniform sequential map, dark violet (0) through blue and green to yellow (scale),
// so that "twice the error" looks twice as far along at every level and reads in greyscale too.
// The stops are the published viridis colours (van der Walt and Smith, matplotlib's default map)
// at ninths of the range, interpolated linearly in sRGB; values above the scale show as
// kOverScale (white: off the map, not "the worst colour"), NaN (no value: outside the object)
// as nothing (the caller's background).

#include <glm/vec3.hpp>

namespace facet::heatmap {

// Display-referred sRGB in [0, 1].
inline constexpr glm::vec3 kOverScale {1.0f, 1.0f, 1.0f};

// The colour of `value` on a scale from 0 to `scale` (> 0): negative values clamp to 0, values
// above `scale` give kOverScale.
glm::vec3 color(double value, double scale);

// The colour of the fraction t in [0, 1] of the map (clamped), for legends.
glm::vec3 ramp(double t);

} // namespace facet::heatmap
