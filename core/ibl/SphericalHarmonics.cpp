#include "core/ibl/SphericalHarmonics.h"

#include <algorithm>

#include <glm/common.hpp>

#include "core/ibl/Environment.h"
#include "core/ibl/Irradiance.h"

namespace facet {

std::array<double, 9> shBasis(const glm::dvec3& d)
{
    // Ramamoorthi & Hanrahan 2001 (table in SphericalHarmonics.h).
    const double x = d.x, y = d.y, z = d.z;
    return {
        sh::K0,
        sh::K1 * y,
        sh::K1 * z,
        sh::K1 * x,
        sh::K2 * x * y,
        sh::K2 * y * z,
        sh::K20 * (3.0 * z * z - 1.0),
        sh::K2 * x * z,
        sh::K22 * (x * x - y * y),
    };
}

glm::dvec3 evaluateSH(const SH9& coefficients, const glm::dvec3& d)
{
    const std::array<double, 9> basis = shBasis(d);
    glm::dvec3 sum(0.0);
    for (std::size_t i = 0; i < 9; ++i)
        sum += coefficients.c[i] * basis[i];
    return sum;
}

SH9 projectEquirect(const Environment& environment)
{
    // L_lm = sum over cells of (L_t intensity dOmega_t) Y_lm(w_t), w_t the cell centre's world
    // direction. The cells are the texels (sub-divided for tiny images, see EquirectQuadrature).
    // Evaluating Y_lm at the centre is the midpoint rule on each texel: for the basis itself
    // (orthonormality) it is exact in longitude (cos/sin of at most 4 phi over >= 512 columns) and
    // second order in latitude, since dOmega_t itself is exact; radiance is taken as constant over
    // each texel, which is what the file stores.
    SH9 result;
    if (environment.isEmpty())
        return result;
    const EquirectQuadrature quadrature(environment);
    for (int r = 0; r < quadrature.rows(); ++r) {
        // Per-row partial sums keep the rounding of the long sum small.
        std::array<glm::dvec3, 9> row {};
        const glm::dvec3* weighted = quadrature.weightedRadianceRow(r);
        for (int c = 0; c < quadrature.columns(); ++c) {
            const std::array<double, 9> basis = shBasis(quadrature.worldDirection(c, r));
            for (std::size_t i = 0; i < 9; ++i)
                row[i] += weighted[c] * basis[i];
        }
        for (std::size_t i = 0; i < 9; ++i)
            result.c[i] += row[i];
    }
    return result;
}

IrradianceSH9 irradianceSHCoefficients(const SH9& radiance)
{
    // Funk-Hecke: the clamped cosine scales band l by A_l (constants in SphericalHarmonics.h), so
    // E_lm = A_l L_lm (Ramamoorthi & Hanrahan 2001).
    IrradianceSH9 result;
    for (std::size_t i = 0; i < 9; ++i)
        result.c[i] = radiance.c[i] * sh::kCosineLobe[i];
    return result;
}

glm::dvec3 irradianceSH(const IrradianceSH9& irradianceCoefficients, const glm::dvec3& n)
{
    // Term for term the GLSL in SphericalHarmonics.h: E(n) = sum_lm (A_l L_lm) Y_lm(n), >= 0.
    const std::array<glm::dvec3, 9>& e = irradianceCoefficients.c;
    // clang-format off
    const glm::dvec3 sum = e[0] * sh::K0
        + e[1] * (sh::K1 * n.y)
        + e[2] * (sh::K1 * n.z)
        + e[3] * (sh::K1 * n.x)
        + e[4] * (sh::K2 * n.x * n.y)
        + e[5] * (sh::K2 * n.y * n.z)
        + e[6] * (sh::K20 * (3.0 * n.z * n.z - 1.0))
        + e[7] * (sh::K2 * n.x * n.z)
        + e[8] * (sh::K22 * (n.x * n.x - n.y * n.y));
    // clang-format on
    return glm::max(sum, glm::dvec3(0.0));
}

glm::dvec3 irradianceSH(const SH9& radiance, const glm::dvec3& n)
{
    return irradianceSH(irradianceSHCoefficients(radiance), n);
}

} // namespace facet
