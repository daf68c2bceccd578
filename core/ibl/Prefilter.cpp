#include "core/ibl/Prefilter.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>

#include "core/ibl/Environment.h"
#include "core/shading/Brdf.h"
#include "core/shading/Sampling.h"

namespace facet {

glm::dvec3 cubemapDirection(int face, double u, double v)
{
    const double a = 2.0 * u - 1.0;
    const double b = 2.0 * v - 1.0;
    glm::dvec3 d;
    switch (face) {
    case 0:
        d = {1.0, -b, -a};
        break;
    case 1:
        d = {-1.0, -b, a};
        break;
    case 2:
        d = {a, 1.0, b};
        break;
    case 3:
        d = {a, -1.0, -b};
        break;
    case 4:
        d = {a, -b, 1.0};
        break;
    default:
        d = {-a, -b, -1.0};
        break;
    }
    return glm::normalize(d);
}

int cubemapFace(const glm::dvec3& d, double* u, double* v)
{
    const glm::dvec3 a = glm::abs(d);
    int face = 0;
    double sc = 0.0;
    double tc = 0.0;
    double ma = 1.0;
    if (a.x >= a.y && a.x >= a.z) {
        face = d.x >= 0.0 ? 0 : 1;
        ma = a.x;
        sc = d.x >= 0.0 ? -d.z : d.z;
        tc = -d.y;
    } else if (a.y >= a.z) {
        face = d.y >= 0.0 ? 2 : 3;
        ma = a.y;
        sc = d.x;
        tc = d.y >= 0.0 ? d.z : -d.z;
    } else {
        face = d.z >= 0.0 ? 4 : 5;
        ma = a.z;
        sc = d.z >= 0.0 ? d.x : -d.x;
        tc = -d.y;
    }
    if (u)
        *u = 0.5 * (sc / ma + 1.0);
    if (v)
        *v = 0.5 * (tc / ma + 1.0);
    return face;
}

std::vector<PrefilterLobeSample> prefilterLobeSamples(double roughness, int samples)
{
    const double alpha = shading::alphaFromRoughness(roughness);
    const auto count = std::uint32_t(std::max(samples, 1));
    const glm::dvec3 n(0.0, 0.0, 1.0);
    std::vector<PrefilterLobeSample> result;
    result.reserve(count);
    for (std::uint32_t i = 0; i < count; ++i) {
        const glm::dvec3 h = sampling::importanceSampleGGX(sampling::hammersley(i, count), alpha);
        // v = n: l = reflect(n, h); the weight n.l (Karis 2013) sharpens the lobe to match the
        // n = v = r assumption's loss of the stretched reflection lobe.
        const glm::dvec3 l = sampling::reflectAbout(n, h);
        if (l.z <= 0.0)
            continue;
        result.push_back({l, shading::D_GGX(h.z, alpha) * 0.25});
    }
    return result;
}

glm::dvec3 prefilteredRadiance(
    const Environment& environment, const glm::dvec3& R, double roughness, int samples)
{
    const glm::dvec3 n = glm::normalize(R);
    glm::dvec3 t;
    glm::dvec3 b;
    sampling::buildOrthonormalBasis(n, t, b);
    glm::dvec3 sum(0.0);
    double weight = 0.0;
    for (const PrefilterLobeSample& sample : prefilterLobeSamples(roughness, samples)) {
        sum += environment.radiance(sampling::tangentToWorld(sample.l, t, b, n)) * sample.l.z;
        weight += sample.l.z;
    }
    return weight > 0.0 ? sum / weight : glm::dvec3(0.0);
}

double filteredLod(double pdf, double sampleCount, double sourceSize, double maxLod)
{
    const double omegaS = 1.0 / (sampleCount * std::max(pdf, 0.5 * shading::kInvPi));
    const double omegaP = 4.0 * shading::kPi / (6.0 * sourceSize * sourceSize);
    return std::clamp(0.5 * std::log2(omegaS / omegaP) + 1.0, 0.0, maxLod);
}

double cubeTexelSolidAngle(const glm::dvec3& d, double sourceSize)
{
    const double major = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
    return 4.0 * major * major * major / (sourceSize * sourceSize);
}

double filteredLodAt(double pdf, double sampleCount, double sourceSize, double maxLod, const glm::dvec3& d)
{
    const double omegaS = 1.0 / (sampleCount * std::max(pdf, 0.5 * shading::kInvPi));
    return std::clamp(0.5 * std::log2(omegaS / cubeTexelSolidAngle(d, sourceSize)), 0.0, maxLod);
}

} // namespace facet
