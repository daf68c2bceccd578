#pragma once
// Brute-force irradiance of an equirectangular environment: the ground truth that SH9
// (core/ibl/SphericalHarmonics.h), the renderer's irradiance map and the accuracy tests are
// measured against. docs/irradiance.md holds the equations, the measured errors and timings.
//
//   E(n) = integral over the sphere of L(w) max(0, n.w) dw
//        ~= sum over every texel t of L_t max(0, n.w_t) dOmega_t
//
// The radiance of a texel is taken as constant over it (what the file stores), dOmega_t is the
// texel's EXACT solid angle, and the cosine is evaluated at the texel centre w_t. The only
// discretisation error is therefore the variation of the cosine across one texel (second order
// in the texel size, plus the texels the horizon n.w = 0 cuts through): about 1e-5 relative at
// 512x256 for smooth lighting.
//
// ---------------------------------------------------------------------------------------------
// Solid angle of an equirect texel. Image row y (0 = top) of an H-row image covers
// v in [1 - (y+1)/H, 1 - y/H] (docs/architecture.md: v = 1 is the top row), i.e. latitude
// lat = (v - 1/2) pi in [lat0, lat1] = [pi (1/2 - (y+1)/H), pi (1/2 - y/H)], and 1/W of the full
// turn in longitude. With dOmega = cos(lat) dlat dphi:
//   Omega = (2 pi / W) * integral_{lat0}^{lat1} cos(lat) dlat = (2 pi / W) (sin lat1 - sin lat0)
// exactly. In colatitude theta = pi/2 - lat, theta_c = pi (y + 1/2)/H, dtheta = pi/H:
//   sin lat1 - sin lat0 = cos(theta_c - dtheta/2) - cos(theta_c + dtheta/2)
//                       = 2 sin(theta_c) sin(dtheta/2)
// which is the form computed (no cancellation near the poles). The usual approximation
//   Omega ~= cos(lat_c) (2 pi / W) (pi / H) = (2 pi / W) sin(theta_c) dtheta
// is this with sin(dtheta/2) replaced by dtheta/2: too large by the factor
// (dtheta/2) / sin(dtheta/2) ~= 1 + dtheta^2/24 (6.3e-6 at H = 256, 11% at H = 2). The exact form
// telescopes: W texels times (2 pi / W) (sin lat1 - sin lat0), summed over the rows, is
// 2 pi (sin(pi/2) - sin(-pi/2)) = 4 pi for any W x H.

#include <cstddef>
#include <span>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "core/ibl/Environment.h"

namespace facet {

// Exact solid angle (steradians) of any texel of row `row` (0 = top) of a width x height equirect
// image; every texel of a row has the same.
double equirectTexelSolidAngle(int row, int width, int height);

// Unit direction of the centre of texel (column, row) of a width x height equirect image, in the
// image's own frame (docs/architecture.md mapping; u = (column + 1/2)/W, v = 1 - (row + 1/2)/H):
//   phi = 2 pi (u - 1/2), lat = pi (v - 1/2), d = (cos lat cos phi, sin lat, cos lat sin phi).
glm::dvec3 equirectTexelDirection(int column, int row, int width, int height);

// An environment as quadrature cells: the texels, or, for images too small to integrate
// smooth functions on (fewer than kMinColumns columns or kMinRows rows, e.g. a 1x1 uniform
// environment), each texel split into equal sub-cells of the same radiance. Cell (column, row)
// holds its image-frame direction, its exact solid angle and its radiance times the
// environment's intensity times that solid angle.
class EquirectQuadrature {
public:
    static constexpr int kMinColumns = 512;
    static constexpr int kMinRows = 256;

    EquirectQuadrature() = default;
    explicit EquirectQuadrature(const Environment& environment);

    int columns() const { return m_columns; }
    int rows() const { return m_rows; }
    std::size_t cellCount() const { return std::size_t(m_columns) * std::size_t(m_rows); }
    // Sub-cells per texel along each axis (1 for images of at least kMinColumns x kMinRows, such as
    // the 512x256 sample HDRIs).
    int subdivisionX() const { return m_subdivisionX; }
    int subdivisionY() const { return m_subdivisionY; }

    // Cell centre direction in the image frame: (cosLat cosPhi, sinLat, cosLat sinPhi).
    double cosPhi(int column) const { return m_cosPhi[std::size_t(column)]; }
    double sinPhi(int column) const { return m_sinPhi[std::size_t(column)]; }
    double cosLat(int row) const { return m_cosLat[std::size_t(row)]; }
    double sinLat(int row) const { return m_sinLat[std::size_t(row)]; }
    glm::dvec3 imageDirection(int column, int row) const;
    // The same, rotated into the world frame (the environment's rotation applied).
    glm::dvec3 worldDirection(int column, int row) const
    {
        return m_imageToWorld * imageDirection(column, row);
    }
    double solidAngle(int row) const { return m_solidAngle[std::size_t(row)]; }
    // L * intensity * dOmega of a cell (radiance units times steradians).
    const glm::dvec3& weightedRadiance(int column, int row) const
    {
        return m_weightedRadiance[std::size_t(row) * std::size_t(m_columns) + std::size_t(column)];
    }
    const glm::dvec3* weightedRadianceRow(int row) const
    {
        return m_weightedRadiance.data() + std::size_t(row) * std::size_t(m_columns);
    }

    // Environment::toWorldFrame / toImageFrame as matrices (a rotation about +Y).
    const glm::dmat3& imageToWorld() const { return m_imageToWorld; }
    const glm::dmat3& worldToImage() const { return m_worldToImage; }

private:
    int m_columns = 0;
    int m_rows = 0;
    int m_subdivisionX = 1;
    int m_subdivisionY = 1;
    std::vector<double> m_cosPhi, m_sinPhi, m_cosLat, m_sinLat, m_solidAngle;
    std::vector<glm::dvec3> m_weightedRadiance;
    glm::dmat3 m_imageToWorld {1.0};
    glm::dmat3 m_worldToImage {1.0};
};

// Holds one environment's quadrature so that many normals are cheap: about 0.12 ms per normal
// for a 512x256 map on one core (docs/irradiance.md has the measured numbers). Results
// are deterministic: each normal is summed by one thread in a fixed order.
class IrradianceIntegrator {
public:
    explicit IrradianceIntegrator(const Environment& environment);

    // E(n) for a unit world normal n (radiance units times steradians; E = pi L in a uniform
    // environment of radiance L). The diffuse outgoing radiance is albedo / pi * E.
    glm::dvec3 irradiance(const glm::dvec3& normal) const;

    // E(n) for every normal, on up to `threads` threads (0: the hardware's concurrency).
    // Identical to calling irradiance() for each, whatever the thread count.
    std::vector<glm::dvec3> irradiance(std::span<const glm::dvec3> normals, int threads = 0) const;

    const EquirectQuadrature& quadrature() const { return m_quadrature; }

private:
    EquirectQuadrature m_quadrature;
};

// One-off conveniences (each builds the quadrature: a few ms for 512x256; keep an
// IrradianceIntegrator to evaluate many normals of one environment).
glm::dvec3 irradianceBruteForce(const Environment& environment, const glm::dvec3& normal);
std::vector<glm::dvec3> irradianceBruteForce(
    const Environment& environment, std::span<const glm::dvec3> normals);

} // namespace facet
