#include "core/shading/Sheen.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/shading/Brdf.h"
#include "core/support/Parallel.h"

namespace facet::shading {

double D_Charlie(double NoH, double sheenAlpha)
{
    const double a = std::max(sheenAlpha, kMinSheenAlpha);
    const double sin2 = std::max(1.0 - NoH * NoH, 0.0);
    return (2.0 + 1.0 / a) * std::pow(sin2, 0.5 / a) / (2.0 * kPi);
}

namespace {

// The fit l(x) of the extension's sheen visibility, interpolated in (1 - a)^2.
double fitL(double x, double sheenAlpha)
{
    const double t = (1.0 - sheenAlpha) * (1.0 - sheenAlpha);
    const auto mix = [t](double lo, double hi) { return lo + (hi - lo) * t; };
    const double a = mix(21.5473, 25.3245);
    const double b = mix(3.82987, 3.32435);
    const double c = mix(0.19823, 0.16801);
    const double d = mix(-1.97760, -1.27393);
    const double e = mix(-4.32054, -4.85967);
    return a / (1.0 + b * std::pow(x, c)) + d * x + e;
}

} // namespace

double lambdaSheen(double cosTheta, double sheenAlpha)
{
    const double a = std::clamp(sheenAlpha, kMinSheenAlpha, 1.0);
    const double c = std::abs(cosTheta);
    return c < 0.5 ? std::exp(fitL(c, a)) : std::exp(2.0 * fitL(0.5, a) - fitL(1.0 - c, a));
}

double V_Charlie(double NoV, double NoL, double sheenAlpha)
{
    const double denominator
        = (1.0 + lambdaSheen(NoV, sheenAlpha) + lambdaSheen(NoL, sheenAlpha)) * 4.0 * NoV * NoL;
    return 1.0 / std::max(denominator, kMinDenominator);
}

double V_Neubelt(double NoV, double NoL)
{
    return 1.0 / std::max(4.0 * (NoL + NoV - NoL * NoV), kMinDenominator);
}

double sheenDirectionalAlbedo(double NoV, double sheenRoughness, SheenVisibility visibility, int steps)
{
    NoV = std::clamp(NoV, 1e-6, 1.0);
    const double alpha = std::clamp(sheenRoughness, 0.0, 1.0) * std::clamp(sheenRoughness, 0.0, 1.0);
    const glm::dvec3 v(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
    const int thetaSteps = std::max(steps, 1);
    const int phiSteps = 4 * thetaSteps;
    const double dTheta = 0.5 * kPi / thetaSteps;
    const double dPhi = 2.0 * kPi / phiSteps;
    double sum = 0.0;
    for (int i = 0; i < thetaSteps; ++i) {
        const double theta = (i + 0.5) * dTheta;
        const double NoL = std::cos(theta);
        const double sinTheta = std::sin(theta);
        const double V
            = visibility == SheenVisibility::Charlie ? V_Charlie(NoV, NoL, alpha) : V_Neubelt(NoV, NoL);
        double ring = 0.0;
        for (int j = 0; j < phiSteps; ++j) {
            const double phi = (j + 0.5) * dPhi;
            const glm::dvec3 l(sinTheta * std::cos(phi), sinTheta * std::sin(phi), NoL);
            const glm::dvec3 h = glm::normalize(v + l);
            ring += D_Charlie(h.z, alpha);
        }
        sum += ring * V * NoL * sinTheta;
    }
    return sum * dTheta * dPhi;
}

SheenAlbedoTable SheenAlbedoTable::compute(int size, int steps, SheenVisibility visibility)
{
    SheenAlbedoTable table;
    table.m_size = std::max(size, 2);
    table.m_texels.assign(std::size_t(table.m_size) * std::size_t(table.m_size), 0.0);
    const double last = double(table.m_size - 1);
    parallelFor(std::size_t(table.m_size), [&](std::size_t y) {
        for (int x = 0; x < table.m_size; ++x)
            table.m_texels[y * std::size_t(table.m_size) + std::size_t(x)]
                = sheenDirectionalAlbedo(double(x) / last, double(y) / last, visibility, steps);
    });
    table.computeDiffuse();
    return table;
}

void SheenAlbedoTable::computeDiffuse()
{
    // Emax(mu_v) = integral_0^1 max(E(mu_v), E(mu_l)) 2 mu_l dmu_l, the trapezoid rule over the
    // n.l texels (the cosine-weighted hemisphere is 2 mu dmu in mu).
    m_diffuse.assign(m_texels.size(), 0.0);
    const double h = 1.0 / double(m_size - 1);
    for (int y = 0; y < m_size; ++y)
        for (int x = 0; x < m_size; ++x) {
            double sum = 0.0;
            for (int i = 0; i < m_size; ++i) {
                const double mu = double(i) * h;
                const double weight = (i == 0 || i == m_size - 1) ? 0.5 * h : h;
                sum += std::max(texel(x, y), texel(i, y)) * 2.0 * mu * weight;
            }
            m_diffuse[std::size_t(y) * std::size_t(m_size) + std::size_t(x)] = sum;
        }
}

SheenAlbedoTable SheenAlbedoTable::fromTexels(int size, std::vector<double> texels)
{
    SheenAlbedoTable table;
    if (size >= 2 && texels.size() == std::size_t(size) * std::size_t(size)) {
        table.m_size = size;
        table.m_texels = std::move(texels);
        table.computeDiffuse();
    }
    return table;
}

double SheenAlbedoTable::sample(double NoV, double sheenRoughness) const
{
    return bilinear(m_texels, NoV, sheenRoughness);
}

double SheenAlbedoTable::sampleDiffuse(double NoV, double sheenRoughness) const
{
    return bilinear(m_diffuse, NoV, sheenRoughness);
}

double SheenAlbedoTable::bilinear(const std::vector<double>& texels, double NoV, double sheenRoughness) const
{
    if (m_size == 0)
        return 0.0;
    const auto at
        = [&](int x, int y) { return texels[std::size_t(y) * std::size_t(m_size) + std::size_t(x)]; };
    const double last = double(m_size - 1);
    const double fx = std::clamp(NoV, 0.0, 1.0) * last;
    const double fy = std::clamp(sheenRoughness, 0.0, 1.0) * last;
    const int x0 = std::min(int(fx), m_size - 2);
    const int y0 = std::min(int(fy), m_size - 2);
    const double tx = fx - x0;
    const double ty = fy - y0;
    const double bottom = at(x0, y0) + (at(x0 + 1, y0) - at(x0, y0)) * tx;
    const double top = at(x0, y0 + 1) + (at(x0 + 1, y0 + 1) - at(x0, y0 + 1)) * tx;
    return bottom + (top - bottom) * ty;
}

namespace {
#include "core/shading/ShippedSheenTable.inc"
static_assert(std::size(kShippedSheenTexels) == std::size_t(kShippedSheenTableSize * kShippedSheenTableSize));
} // namespace

const SheenAlbedoTable& sheenAlbedoTable()
{
    static const SheenAlbedoTable table = SheenAlbedoTable::fromTexels(kShippedSheenTableSize,
        std::vector<double>(std::begin(kShippedSheenTexels), std::end(kShippedSheenTexels)));
    return table;
}

double sheenAlbedoScaling(const glm::dvec3& sheenColor, double sheenRoughness, double NoV, double NoL)
{
    const double strength = std::max({sheenColor.r, sheenColor.g, sheenColor.b, 0.0});
    if (strength <= 0.0)
        return 1.0;
    const SheenAlbedoTable& table = sheenAlbedoTable();
    const double e = std::max(table.sample(NoV, sheenRoughness), table.sample(NoL, sheenRoughness));
    return std::max(1.0 - strength * e, 0.0);
}

} // namespace facet::shading
