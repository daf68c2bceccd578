#include "core/ibl/EnvironmentSampler.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace facet {

namespace {
constexpr double kPi = std::numbers::pi;
double luminance(const glm::vec4& c)
{
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}
} // namespace

EnvironmentSampler::EnvironmentSampler(const Environment& environment)
    : m_environment(environment)
{
    const Image& image = environment.image();
    const int w = image.width();
    const int h = image.height();
    // Radiance is looked up bilinearly, so a texel next to a bright one is bright over part of
    // its area. Weighting each texel by the largest luminance in its 3x3 neighbourhood keeps the
    // pdf from being small where the looked-up radiance is large (PBRT-v4 builds its
    // environment distribution from a conservatively filtered image for the same reason);
    // otherwise the BRDF strategy alone carries those directions, with high variance.
    std::vector<double> texelLuminance(std::size_t(w) * std::size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            texelLuminance[std::size_t(y) * std::size_t(w) + std::size_t(x)]
                = std::max(0.0, luminance(image.at(x, y)));
    std::vector<double> weights(std::size_t(w) * std::size_t(h));
    for (int row = 0; row < h; ++row) {
        // Distribution row `row` covers v in [row/h, (row+1)/h): image row h-1-row (v = 1 is the top).
        // Its solid angle per texel is (2 pi / w) (sin(lat1) - sin(lat0)), lat = pi (v - 1/2).
        const int y = h - 1 - row;
        const double lat0 = kPi * (double(row) / h - 0.5);
        const double lat1 = kPi * (double(row + 1) / h - 0.5);
        const double solidAngle = (2.0 * kPi / w) * (std::sin(lat1) - std::sin(lat0));
        for (int x = 0; x < w; ++x) {
            double brightest = 0.0;
            for (int dy = -1; dy <= 1; ++dy) {
                const int yy = std::clamp(y + dy, 0, h - 1);
                for (int dx = -1; dx <= 1; ++dx) {
                    const int xx = (x + dx + w) % w; // u wraps
                    brightest = std::max(
                        brightest, texelLuminance[std::size_t(yy) * std::size_t(w) + std::size_t(xx)]);
                }
            }
            weights[std::size_t(row) * std::size_t(w) + std::size_t(x)] = brightest * solidAngle;
        }
    }
    m_distribution = sampling::Distribution2D(weights, std::size_t(w), std::size_t(h));
}

glm::dvec3 EnvironmentSampler::sample(const glm::dvec2& u, double* pdfOut) const
{
    double pdfUv = 0.0;
    const glm::dvec2 uv = m_distribution.sampleContinuous(u, &pdfUv);
    const glm::dvec3 local = directionFromEquirectUv(uv);
    // d(omega) = cos(lat) d(phi) d(lat) = 2 pi^2 cos(lat) du dv.
    const double cosLat = std::sqrt(std::max(0.0, 1.0 - local.y * local.y));
    if (pdfOut)
        *pdfOut = cosLat > 0.0 ? pdfUv / (2.0 * kPi * kPi * cosLat) : 0.0;
    return m_environment.toWorldFrame(local);
}

EnvironmentSamplingTables EnvironmentSampler::tables() const
{
    return sampling::tablesFromDistribution(m_distribution);
}

double EnvironmentSampler::pdf(const glm::dvec3& direction) const
{
    const glm::dvec3 local = m_environment.toImageFrame(direction);
    const double cosLat = std::sqrt(std::max(0.0, 1.0 - local.y * local.y));
    if (cosLat <= 0.0)
        return 0.0;
    return m_distribution.pdf(equirectUvFromDirection(local)) / (2.0 * kPi * kPi * cosLat);
}

} // namespace facet
