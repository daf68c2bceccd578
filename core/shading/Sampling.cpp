#include "core/shading/Sampling.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace facet::sampling {

namespace {
constexpr double kPi = std::numbers::pi;

std::uint32_t reverseBits(std::uint32_t bits)
{
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return bits;
}
} // namespace

double radicalInverse(std::uint32_t bits)
{
    return double(reverseBits(bits)) * 2.3283064365386963e-10; // / 2^32
}

glm::dvec2 halton23(std::uint32_t i)
{
    double y = 0.0;
    double scale = 1.0 / 3.0;
    for (std::uint32_t k = i; k > 0; k /= 3, scale /= 3.0)
        y += double(k % 3) * scale;
    return {radicalInverse(i), y};
}

glm::dvec2 hammersley(std::uint32_t i, std::uint32_t n)
{
    return {double(i) / double(n), radicalInverse(i)};
}

glm::dvec2 shiftedHammersley(std::uint32_t i, std::uint32_t n, const glm::dvec2& shift)
{
    const glm::dvec2 u = hammersley(i, n) + shift;
    return glm::dvec2(u.x - std::floor(u.x), u.y - std::floor(u.y));
}

bool isFinite(const glm::dvec3& c)
{
    return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
}

glm::uvec2 sobol2DBits(std::uint32_t s)
{
    // Dimension 2: XOR of the direction numbers of the set bits of s, lowest bit first; the
    // direction numbers follow v_{k+1} = v_k ^ (v_k >> 1) from v_1 = 2^31 (0.1, 0.11, 0.101,
    // 0.1111, ... in binary).
    std::uint32_t y = 0u;
    for (std::uint32_t v = 1u << 31u, bits = s; bits != 0u; bits >>= 1u, v ^= v >> 1u)
        if ((bits & 1u) != 0u)
            y ^= v;
    return {reverseBits(s), y};
}

glm::dvec2 sobol2D(std::uint32_t s)
{
    const glm::uvec2 bits = sobol2DBits(s);
    return glm::dvec2(double(bits.x), double(bits.y)) * 2.3283064365386963e-10; // / 2^32
}

std::uint32_t pcgHash(std::uint32_t value)
{
    // Jarzynski & Olano 2020, section 2 ("pcg"): LCG step, then RXS-M-XS.
    const std::uint32_t state = value * 747796405u + 2891336453u;
    const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

glm::uvec2 cranleyPattersonShift(std::uint32_t x, std::uint32_t y, std::uint32_t seed, std::uint32_t strategy)
{
    const std::uint32_t h = pcgHash(x + pcgHash(y + pcgHash(seed + pcgHash(strategy))));
    return {h, pcgHash(h)};
}

glm::dvec2 shiftedSobol2D(std::uint32_t s, const glm::uvec2& shift)
{
    const glm::uvec2 bits = sobol2DBits(s) + shift; // wraps mod 2^32: the shift's frac()
    return glm::dvec2(double(bits.x >> 8u), double(bits.y >> 8u)) * 5.9604644775390625e-8; // / 2^24
}

Pcg32::Pcg32(std::uint64_t seed, std::uint64_t stream)
    : m_increment((stream << 1u) | 1u)
{
    nextUInt();
    m_state += seed;
    nextUInt();
}

std::uint32_t Pcg32::nextUInt()
{
    const std::uint64_t old = m_state;
    m_state = old * 6364136223846793005ULL + m_increment;
    const auto xorshifted = std::uint32_t(((old >> 18u) ^ old) >> 27u);
    const auto rot = std::uint32_t(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31u));
}

double Pcg32::nextDouble()
{
    // 53 random bits from two draws, so that every double in [0, 1) on the 2^-53 grid can occur.
    const std::uint64_t hi = nextUInt() >> 5u; // 27 bits
    const std::uint64_t lo = nextUInt() >> 6u; // 26 bits
    return double((hi << 26u) | lo) * (1.0 / 9007199254740992.0);
}

void buildOrthonormalBasis(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b)
{
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double c = n.x * n.y * a;
    t = {1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x};
    b = {c, sign + n.y * n.y * a, -n.y};
}

glm::dvec3 tangentToWorld(const glm::dvec3& v, const glm::dvec3& t, const glm::dvec3& b, const glm::dvec3& n)
{
    return v.x * t + v.y * b + v.z * n;
}

glm::dvec3 worldToTangent(const glm::dvec3& v, const glm::dvec3& t, const glm::dvec3& b, const glm::dvec3& n)
{
    return {glm::dot(v, t), glm::dot(v, b), glm::dot(v, n)};
}

glm::dvec3 reflectAbout(const glm::dvec3& v, const glm::dvec3& h)
{
    return 2.0 * glm::dot(v, h) * h - v;
}

glm::dvec3 sampleCosineHemisphere(const glm::dvec2& u)
{
    // Concentric mapping of the unit square to the disk keeps strata compact (Shirley & Chiu 1997).
    const double sx = 2.0 * u.x - 1.0;
    const double sy = 2.0 * u.y - 1.0;
    double r = 0.0;
    double phi = 0.0;
    if (sx != 0.0 || sy != 0.0) {
        if (std::abs(sx) > std::abs(sy)) {
            r = sx;
            phi = (kPi / 4.0) * (sy / sx);
        } else {
            r = sy;
            phi = (kPi / 2.0) - (kPi / 4.0) * (sx / sy);
        }
    }
    const double x = r * std::cos(phi);
    const double y = r * std::sin(phi);
    return {x, y, std::sqrt(std::max(0.0, 1.0 - x * x - y * y))};
}

double pdfCosineHemisphere(double cosTheta)
{
    return std::max(cosTheta, 0.0) / kPi;
}

glm::dvec3 sampleUniformSphere(const glm::dvec2& u)
{
    const double z = 1.0 - 2.0 * u.x;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = 2.0 * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

glm::dvec3 importanceSampleGGX(const glm::dvec2& u, double alpha)
{
    // Inverting the CDF of D(h) cos(theta_h): tan^2(theta) = alpha^2 u / (1 - u).
    const double phi = 2.0 * kPi * u.x;
    const double cos2Theta = (1.0 - u.y) / (1.0 + (alpha * alpha - 1.0) * u.y);
    const double cosTheta = std::sqrt(std::clamp(cos2Theta, 0.0, 1.0));
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

static double ggxD(double NoH, double alpha)
{
    const double a2 = alpha * alpha;
    const double f = NoH * NoH * (a2 - 1.0) + 1.0;
    return a2 / (kPi * f * f);
}

double pdfGGXReflection(double NoH, double VoH, double alpha)
{
    if (NoH <= 0.0 || VoH <= 0.0)
        return 0.0;
    return ggxD(NoH, alpha) * NoH / (4.0 * VoH);
}

double G1_SmithGGX(double NoX, double alpha)
{
    const double a2 = alpha * alpha;
    return 2.0 * NoX / (NoX + std::sqrt(a2 + (1.0 - a2) * NoX * NoX));
}

glm::dvec3 importanceSampleVNDF(const glm::dvec2& u, const glm::dvec3& v, double alpha)
{
    return importanceSampleVNDF(u, v, alpha, alpha);
}

glm::dvec3 importanceSampleVNDF(const glm::dvec2& u, const glm::dvec3& v, double alphaX, double alphaY)
{
    // Heitz 2018, listing 1: stretch the view to the hemisphere configuration, sample the
    // projected disk, warp the half of the disk hidden by the view, unstretch.
    const glm::dvec3 vh = glm::normalize(glm::dvec3(alphaX * v.x, alphaY * v.y, v.z));
    const double lensq = vh.x * vh.x + vh.y * vh.y;
    const glm::dvec3 t1
        = lensq > 0.0 ? glm::dvec3(-vh.y, vh.x, 0.0) / std::sqrt(lensq) : glm::dvec3(1.0, 0.0, 0.0);
    const glm::dvec3 t2 = glm::cross(vh, t1);
    const double r = std::sqrt(u.x);
    const double phi = 2.0 * kPi * u.y;
    const double p1 = r * std::cos(phi);
    double p2 = r * std::sin(phi);
    const double s = 0.5 * (1.0 + vh.z);
    p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * p2;
    const glm::dvec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
    return glm::normalize(glm::dvec3(alphaX * nh.x, alphaY * nh.y, std::max(0.0, nh.z)));
}

glm::dvec3 importanceSampleVNDFSphericalCap(const glm::dvec2& u, const glm::dvec3& v, double alpha)
{
    // Dupuy and Benyoub 2023, listing 3: in the stretched (alpha = 1) configuration the visible
    // normals are c + vh for c uniform on the spherical cap z >= -vh.z; unstretch.
    const glm::dvec3 vh = glm::normalize(glm::dvec3(alpha * v.x, alpha * v.y, v.z));
    const double phi = 2.0 * kPi * u.x;
    const double z = (1.0 - u.y) * (1.0 + vh.z) - vh.z;
    const double sinTheta = std::sqrt(std::clamp(1.0 - z * z, 0.0, 1.0));
    const glm::dvec3 h = glm::dvec3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), z) + vh;
    return glm::normalize(glm::dvec3(alpha * h.x, alpha * h.y, std::max(0.0, h.z)));
}

double pdfVNDFReflection(double NoV, double NoH, double alpha)
{
    if (NoV <= 0.0 || NoH <= 0.0)
        return 0.0;
    return G1_SmithGGX(NoV, alpha) * ggxD(NoH, alpha) / (4.0 * NoV);
}

Distribution1D::Distribution1D(std::span<const double> weights)
    : m_weights(weights.begin(), weights.end())
    , m_cdf(weights.size() + 1, 0.0)
{
    const auto n = double(m_weights.size());
    for (std::size_t i = 0; i < m_weights.size(); ++i)
        m_cdf[i + 1] = m_cdf[i] + m_weights[i] / n;
    m_integral = m_cdf.back();
    if (m_integral <= 0.0) {
        // Nothing to prefer: sample uniformly.
        std::fill(m_weights.begin(), m_weights.end(), 1.0);
        for (std::size_t i = 1; i < m_cdf.size(); ++i)
            m_cdf[i] = double(i) / n;
        m_integral = 0.0;
        return;
    }
    for (double& c : m_cdf)
        c /= m_integral;
    m_cdf.back() = 1.0;
}

double Distribution1D::sampleContinuous(double u, double* pdfOut, std::size_t* cellOut) const
{
    // The last cdf entry <= u.
    const auto it = std::upper_bound(m_cdf.begin(), m_cdf.end(), u);
    const std::size_t cell = std::clamp<std::size_t>(
        std::size_t(std::max<std::ptrdiff_t>(0, (it - m_cdf.begin()) - 1)), 0, m_weights.size() - 1);
    const double width = m_cdf[cell + 1] - m_cdf[cell];
    const double du = width > 0.0 ? (u - m_cdf[cell]) / width : 0.5;
    if (pdfOut)
        *pdfOut = pdf(cell);
    if (cellOut)
        *cellOut = cell;
    return std::min(
        (double(cell) + std::clamp(du, 0.0, 1.0)) / double(m_weights.size()), std::nextafter(1.0, 0.0));
}

double Distribution1D::pdf(std::size_t cell) const
{
    if (m_integral <= 0.0)
        return 1.0;
    return m_weights[cell] / m_integral;
}

Distribution2D::Distribution2D(std::span<const double> weights, std::size_t width, std::size_t height)
    : m_width(width)
    , m_height(height)
{
    std::vector<double> rowIntegrals(height);
    m_conditional.reserve(height);
    for (std::size_t y = 0; y < height; ++y) {
        m_conditional.emplace_back(weights.subspan(y * width, width));
        rowIntegrals[y] = m_conditional.back().integral();
    }
    m_marginal = Distribution1D(rowIntegrals);
}

glm::dvec2 Distribution2D::sampleContinuous(const glm::dvec2& u, double* pdfOut) const
{
    double pdfY = 0.0;
    double pdfX = 0.0;
    std::size_t row = 0;
    const double y = m_marginal.sampleContinuous(u.y, &pdfY, &row);
    const double x = m_conditional[row].sampleContinuous(u.x, &pdfX, nullptr);
    if (pdfOut)
        *pdfOut = pdfX * pdfY;
    return {x, y};
}

double Distribution2D::pdf(const glm::dvec2& xy) const
{
    const auto col = std::min(std::size_t(std::max(0.0, xy.x) * double(m_width)), m_width - 1);
    const auto row = std::min(std::size_t(std::max(0.0, xy.y) * double(m_height)), m_height - 1);
    return m_conditional[row].pdf(col) * m_marginal.pdf(row);
}

} // namespace facet::sampling
