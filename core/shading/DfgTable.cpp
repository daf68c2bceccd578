#include "core/shading/DfgTable.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/shading/Brdf.h"
#include "core/shading/Sampling.h"
#include "core/support/Parallel.h"

namespace facet {

using namespace shading;

DfgValue integrateDfg(double NoV, double perceptualRoughness, int sampleCount, Visibility visibility)
{
    const double alpha = alphaFromRoughness(perceptualRoughness);
    NoV = std::clamp(NoV, 1e-6, 1.0);
    const glm::dvec3 v(std::sqrt(1.0 - NoV * NoV), 0.0, NoV); // tangent space, n = +Z
    const double k = k_SchlickGGX_ibl(alpha);

    // Visible-normal sampling: pdf_l = G1(v) D(h) / (4 n.v), so the estimator of
    // D V (n.l) / pdf_l = 4 V (n.v) (n.l) / G1(v) [Heitz 2018, eq. 17 and 19]. With the
    // correlated V this is G2/G1, bounded by 1: a low-variance estimator even at grazing n.v.
    double scale = 0.0;
    double bias = 0.0;
    double diffuse = 0.0;
    const auto n = std::uint32_t(std::max(sampleCount, 1));
    for (std::uint32_t i = 0; i < n; ++i) {
        const glm::dvec2 u = sampling::hammersley(i, n);
        // fresnel_mix's diffuse base: with pdf (n.l) / pi the estimator of
        // 1/pi (1 - Fc(v.h)) (n.l) is 1 - Fc, h the half vector of v and this l. Every sample
        // counts, the first point's l on the horizon too (skipping it biased W by -1/n).
        const glm::dvec3 diffuseL = sampling::sampleCosineHemisphere(u);
        diffuse += 1.0 - pow5(1.0 - std::clamp(glm::dot(v, glm::normalize(v + diffuseL)), 0.0, 1.0));
        const glm::dvec3 h = sampling::importanceSampleVNDF(u, v, alpha);
        const glm::dvec3 l = sampling::reflectAbout(v, h);
        const double NoL = l.z;
        if (NoL <= 0.0)
            continue;
        const double VoH = std::clamp(glm::dot(v, h), 0.0, 1.0);
        double V = 0.0;
        switch (visibility) {
        case Visibility::SmithGGXCorrelated:
            V = V_SmithGGXCorrelated(NoV, NoL, alpha);
            break;
        case Visibility::SmithGGXUncorrelated:
            V = V_SmithGGX(NoV, NoL, alpha);
            break;
        case Visibility::SchlickGGX:
            V = V_SmithSchlickGGX(NoV, NoL, k);
            break;
        }
        const double weight = 4.0 * V * NoV * NoL / sampling::G1_SmithGGX(NoV, alpha);
        const double Fc = pow5(1.0 - VoH);
        scale += (1.0 - Fc) * weight;
        bias += Fc * weight;
    }
    return {scale / double(n), bias / double(n), diffuse / double(n)};
}

DfgTable DfgTable::compute(int size, int sampleCount, Visibility visibility, int threads)
{
    DfgTable table;
    table.m_size = std::max(size, 2);
    table.m_sampleCount = sampleCount;
    table.m_visibility = visibility;
    table.m_texels.resize(std::size_t(table.m_size) * std::size_t(table.m_size));
    parallelFor(
        std::size_t(table.m_size),
        [&](std::size_t y) {
            const double roughness = texelPosition(int(y), table.m_size);
            for (int x = 0; x < table.m_size; ++x) {
                const double NoV = texelPosition(x, table.m_size);
                table.m_texels[y * std::size_t(table.m_size) + std::size_t(x)]
                    = integrateDfg(NoV, roughness, sampleCount, visibility);
            }
        },
        threads);
    return table;
}

DfgValue DfgTable::sample(double NoV, double perceptualRoughness) const
{
    const double fx = std::clamp(NoV, 0.0, 1.0) * double(m_size - 1);
    const double fy = std::clamp(perceptualRoughness, 0.0, 1.0) * double(m_size - 1);
    const int x0 = int(fx);
    const int y0 = int(fy);
    const int x1 = std::min(x0 + 1, m_size - 1);
    const int y1 = std::min(y0 + 1, m_size - 1);
    const double tx = fx - x0;
    const double ty = fy - y0;
    auto lerp = [](const DfgValue& a, const DfgValue& b, double t) {
        return DfgValue {a.scale + (b.scale - a.scale) * t, a.bias + (b.bias - a.bias) * t,
            a.diffuseFresnelWeight + (b.diffuseFresnelWeight - a.diffuseFresnelWeight) * t};
    };
    return lerp(lerp(texel(x0, y0), texel(x1, y0), tx), lerp(texel(x0, y1), texel(x1, y1), tx), ty);
}

double DfgTable::averageAlbedo(double perceptualRoughness) const
{
    double sum = 0.0;
    for (int x = 0; x < m_size; ++x) {
        const double mu = texelPosition(x, m_size);
        sum += sample(mu, perceptualRoughness).albedo() * mu * trapezoidWeight(x, m_size);
    }
    return 2.0 * sum;
}

std::vector<float> DfgTable::toRgbaFloats() const
{
    std::vector<float> out;
    out.reserve(m_texels.size() * 4);
    for (const DfgValue& t : m_texels) {
        out.push_back(float(t.scale));
        out.push_back(float(t.bias));
        out.push_back(float(t.albedo()));
        out.push_back(float(t.diffuseFresnelWeight));
    }
    return out;
}

} // namespace facet
