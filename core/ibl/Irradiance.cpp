#include "core/ibl/Irradiance.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/support/Parallel.h"

namespace facet {

namespace {
constexpr double kPi = 3.14159265358979323846;

// Solid angle of one cell of row `row` in a grid of `columns` x `rows` cells covering the sphere
// (derivation in Irradiance.h): (2 pi / W) * 2 sin(theta_c) sin(dtheta / 2).
double cellSolidAngle(int row, int columns, int rows)
{
    const double dTheta = kPi / double(rows);
    const double thetaCentre = (double(row) + 0.5) * dTheta;
    return (2.0 * kPi / double(columns)) * 2.0 * std::sin(thetaCentre) * std::sin(0.5 * dTheta);
}

// Cells per texel along an axis so that the grid has at least `minimum` cells along it.
int subdivisionFor(int texels, int minimum)
{
    return texels >= minimum ? 1 : (minimum + texels - 1) / texels;
}

// E(n) over the quadrature, n already normalised; `projected` is per-call scratch for the
// longitude part of n.w.
glm::dvec3 integrateCosine(
    const EquirectQuadrature& q, const glm::dvec3& worldNormal, std::vector<double>& projected)
{
    // The environment's rotation is about +Y, which keeps dot products: n.w_world = n_image.w_image.
    const glm::dvec3 n = q.worldToImage() * worldNormal;
    const int columns = q.columns();
    // n.w = cosLat (n.x cosPhi + n.z sinPhi) + n.y sinLat: the bracket depends on the column only.
    projected.resize(std::size_t(columns));
    for (int c = 0; c < columns; ++c)
        projected[std::size_t(c)] = n.x * q.cosPhi(c) + n.z * q.sinPhi(c);
    // |n.x cosPhi + n.z sinPhi| <= |(n.x, n.z)| (Cauchy-Schwarz), which bounds n.w over a row.
    const double horizontal = std::sqrt(n.x * n.x + n.z * n.z);

    glm::dvec3 total(0.0);
    for (int r = 0; r < q.rows(); ++r) {
        const double cosLat = q.cosLat(r);
        const double vertical = n.y * q.sinLat(r);
        if (cosLat * horizontal + vertical <= 0.0)
            continue; // the whole row lies below n's horizon: max(0, n.w) = 0 for every cell
        const glm::dvec3* weighted = q.weightedRadianceRow(r);
        // One partial sum per row keeps the rounding of the 131k-term sum far below the
        // quadrature error.
        glm::dvec3 rowSum(0.0);
        if (vertical - cosLat * horizontal > 0.0) {
            // The whole row lies above the horizon: no clamp needed.
            for (int c = 0; c < columns; ++c)
                rowSum += (cosLat * projected[std::size_t(c)] + vertical) * weighted[c];
        } else {
            for (int c = 0; c < columns; ++c)
                rowSum += std::max(0.0, cosLat * projected[std::size_t(c)] + vertical) * weighted[c];
        }
        total += rowSum;
    }
    return total;
}
} // namespace

double equirectTexelSolidAngle(int row, int width, int height)
{
    return cellSolidAngle(row, width, height);
}

glm::dvec3 equirectTexelDirection(int column, int row, int width, int height)
{
    const double u = (double(column) + 0.5) / double(width);
    const double v = 1.0 - (double(row) + 0.5) / double(height);
    const double phi = 2.0 * kPi * (u - 0.5);
    const double lat = kPi * (v - 0.5);
    return {std::cos(lat) * std::cos(phi), std::sin(lat), std::cos(lat) * std::sin(phi)};
}

// ---------------------------------------------------------------------------------------------

EquirectQuadrature::EquirectQuadrature(const Environment& environment)
{
    if (environment.isEmpty())
        return;
    const Image& image = environment.image();
    const int width = image.width();
    const int height = image.height();
    m_subdivisionX = subdivisionFor(width, kMinColumns);
    m_subdivisionY = subdivisionFor(height, kMinRows);
    m_columns = width * m_subdivisionX;
    m_rows = height * m_subdivisionY;

    // The rotation as matrices, from the environment's own mapping (so that every module agrees on
    // its sense): columns are the images of the axes.
    m_imageToWorld = glm::dmat3(environment.toWorldFrame({1.0, 0.0, 0.0}),
        environment.toWorldFrame({0.0, 1.0, 0.0}), environment.toWorldFrame({0.0, 0.0, 1.0}));
    m_worldToImage = glm::dmat3(environment.toImageFrame({1.0, 0.0, 0.0}),
        environment.toImageFrame({0.0, 1.0, 0.0}), environment.toImageFrame({0.0, 0.0, 1.0}));

    m_cosPhi.resize(std::size_t(m_columns));
    m_sinPhi.resize(std::size_t(m_columns));
    for (int c = 0; c < m_columns; ++c) {
        const double phi = 2.0 * kPi * ((double(c) + 0.5) / double(m_columns) - 0.5);
        m_cosPhi[std::size_t(c)] = std::cos(phi);
        m_sinPhi[std::size_t(c)] = std::sin(phi);
    }
    m_cosLat.resize(std::size_t(m_rows));
    m_sinLat.resize(std::size_t(m_rows));
    m_solidAngle.resize(std::size_t(m_rows));
    for (int r = 0; r < m_rows; ++r) {
        // lat = pi (v - 1/2) with v = 1 - (r + 1/2)/rows; cos lat = sin theta, sin lat = cos theta.
        const double theta = kPi * (double(r) + 0.5) / double(m_rows);
        m_cosLat[std::size_t(r)] = std::sin(theta);
        m_sinLat[std::size_t(r)] = std::cos(theta);
        m_solidAngle[std::size_t(r)] = cellSolidAngle(r, m_columns, m_rows);
    }

    const double intensity = environment.intensity();
    m_weightedRadiance.resize(cellCount());
    for (int r = 0; r < m_rows; ++r) {
        const int y = r / m_subdivisionY;
        const double weight = intensity * m_solidAngle[std::size_t(r)];
        glm::dvec3* out = m_weightedRadiance.data() + std::size_t(r) * std::size_t(m_columns);
        for (int c = 0; c < m_columns; ++c) {
            const glm::vec4& texel = image.at(c / m_subdivisionX, y);
            out[c] = glm::dvec3(texel.x, texel.y, texel.z) * weight;
        }
    }
}

glm::dvec3 EquirectQuadrature::imageDirection(int column, int row) const
{
    const double cosLat = m_cosLat[std::size_t(row)];
    return {cosLat * m_cosPhi[std::size_t(column)], m_sinLat[std::size_t(row)],
        cosLat * m_sinPhi[std::size_t(column)]};
}

// ---------------------------------------------------------------------------------------------

IrradianceIntegrator::IrradianceIntegrator(const Environment& environment)
    : m_quadrature(environment)
{
}

glm::dvec3 IrradianceIntegrator::irradiance(const glm::dvec3& normal) const
{
    const double length = glm::length(normal);
    if (!(length > 0.0) || !std::isfinite(length))
        return glm::dvec3(0.0);
    std::vector<double> scratch;
    return integrateCosine(m_quadrature, normal / length, scratch);
}

std::vector<glm::dvec3> IrradianceIntegrator::irradiance(
    std::span<const glm::dvec3> normals, int threads) const
{
    // Each normal is summed whole by one thread, in the same order as irradiance(normal), so the
    // result does not depend on the thread count or scheduling.
    std::vector<glm::dvec3> result(normals.size());
    parallelFor(
        normals.size(), [&](std::size_t i) { result[i] = irradiance(normals[i]); }, threads);
    return result;
}

glm::dvec3 irradianceBruteForce(const Environment& environment, const glm::dvec3& normal)
{
    return IrradianceIntegrator(environment).irradiance(normal);
}

std::vector<glm::dvec3> irradianceBruteForce(
    const Environment& environment, std::span<const glm::dvec3> normals)
{
    return IrradianceIntegrator(environment).irradiance(normals);
}

} // namespace facet
