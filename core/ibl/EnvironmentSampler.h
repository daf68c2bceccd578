#pragma once
// Importance sampling of an environment by its luminance: a piecewise-constant 2D distribution
// over the equirect texels, weighted by each texel's luminance times its solid angle
// [PBRT 3rd ed., 14.2.4 "Infinite Area Lights"].

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/ibl/Environment.h"
#include "core/ibl/EnvironmentSamplingTables.h"
#include "core/shading/Sampling.h"

namespace facet {

class EnvironmentSampler {
public:
    explicit EnvironmentSampler(const Environment& environment);

    // A world direction drawn in proportion to radiance luminance, and its pdf w.r.t. solid angle.
    glm::dvec3 sample(const glm::dvec2& u, double* pdf) const;
    // The pdf of drawing world direction `direction` (unit).
    double pdf(const glm::dvec3& direction) const;

    // The distribution as float tables for the GPU (core/ibl/EnvironmentSamplingTables.h), in the
    // distribution's row order (row r: v in [r/H, (r+1)/H), image row H-1-r), in the image's frame:
    // sampling them gives (u, v), then directionFromEquirectUv and toWorldFrame as sample() does,
    // and pdf w.r.t. solid angle = pdfUv / (2 pi^2 cos(latitude)).
    EnvironmentSamplingTables tables() const;
    const sampling::Distribution2D& distribution() const { return m_distribution; }

private:
    const Environment& m_environment;
    sampling::Distribution2D m_distribution; // x = u, y = v (row 0: v in [0, 1/H), the image's bottom row)
};

} // namespace facet
