#pragma once
// Light through a surface: the rough dielectric interface of KHR_materials_transmission, the
// absorbing medium of KHR_materials_volume and the wavelength-dependent index of
// KHR_materials_dispersion, in double: what the ground truth traces (core/truth/SceneTruth) and
// the material BRDF's transmission lobe evaluates (core/shading/MaterialBrdf). docs/shading.md,
// "Transmission", derives each formula.
//
// An interface separates the side of v (index etaV) from the side of l (index etaL). Its
// microfacet BTDF for radiance [Walter et al. 2007, "Microfacet Models for Refraction through Rough
// Surfaces", eq. 21, with the radiance's (etaV / etaL)^2 of eq. 41 folded in] is
//
//     f_t(v, l) = |v.h| |l.h| etaV^2 (1 - F(v.h)) D(h) G2(v, l) / (|n.v| |n.l| (etaV v.h + etaL l.h)^2)
//               = 4 |v.h| |l.h| etaV^2 (1 - F(v.h)) D(h) V(v, l) / (etaV v.h + etaL l.h)^2
//
// with the half vector h = -(etaV v + etaL l) / |etaV v + etaL l| turned to n's side and
// V = G2 / (4 |n.v| |n.l|) the visibility the reflection takes.

#include <vector>

#include <glm/vec3.hpp>

namespace facet::shading {

// The refraction half vector of v (on etaV's side) and l (on etaL's), unit, on n's side; zero where
// etaV v + etaL l vanishes (equal indices and l = -v: no interface, which refracts nothing).
glm::dvec3 refractionHalfVector(
    const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, double etaV, double etaL);

// The refracted direction of v through the microfacet h (both unit, v.h > 0) from etaV into
// etaL; false at total internal reflection.
bool refractThrough(const glm::dvec3& v, const glm::dvec3& h, double etaV, double etaL, glm::dvec3* l);

// The BTDF's geometric factor without the Fresnel, 4 |v.h| |l.h| etaV^2 / (etaV v.h + etaL l.h)^2:
// f_t = factor x (1 - F) D V. Zero where l lies on v's side of the microfacet.
double refractionJacobianFactor(double VoH, double LoH, double etaV, double etaL);

// The density, per solid angle of l, of refracting v through a normal drawn from the distribution
// of visible normals, pdf_h = G1(v) D(h) v.h / n.v: pdf_l = pdf_h etaL^2 |l.h| / (etaV v.h + etaL l.h)^2.
double pdfVNDFRefraction(
    double NoV, double NoH, double VoH, double LoH, double alpha, double etaV, double etaL);

// The Fresnel reflectance of the interface seen at cos(theta) = VoH from etaV's side into etaL's:
// 1 at total internal reflection. `exact`: the unpolarised dielectric Fresnel; otherwise Schlick's
// F0 ((etaL - etaV) / (etaL + etaV))^2 at the angle on the rarer side, so that the two sides of
// one interface agree (Schlick taken at the denser side's angle is no reflectance: it misses total
// internal reflection).
double interfaceFresnel(double VoH, double etaV, double etaL, bool exact);

// KHR_materials_dispersion: the index at wavelength lambda (nm) of a material of index `ior` at
// 587.6 nm and dispersion 20 / V_d: max(ior + (ior - 1) dispersion / 20 (523655 / lambda^2 - 1.5168), 1).
double dispersedIor(double ior, double dispersion, double lambda);

// KHR_materials_volume: the medium's absorption coefficient per unit length, -ln(color) / distance
// per channel (infinite where a channel is 0); zero for an infinite distance.
glm::dvec3 attenuationCoefficient(const glm::dvec3& attenuationColor, double attenuationDistance);
// Beer-Lambert: what of the light survives `distance` through the medium, exp(-sigma distance).
glm::dvec3 beerLambert(const glm::dvec3& sigma, double distance);

// The rough interface's single-scattering albedo, as power, from index etaV into etaL: what of the
// light arriving along v its microfacets send back to v's side (reflected) and through
// (transmitted: radiance times (etaL / etaV)^2), over n.v and perceptual roughness on a size x
// size grid (texel i at i / (size - 1), as core/shading/DfgTable's), each texel by `samples`
// Hammersley draws of visible normals, both branches of each weighed by its Fresnel: F G2 / G1 and
// (1 - F) G2 / G1 (GGX, height-correlated Smith). A smooth interface keeps all of it; a rough one
// loses what leaves in more than one bounce among its microfacets, which the ground truth's
// compensation gives back (docs/shading.md, "Transmission").
class InterfaceAlbedoTable {
public:
    struct Value {
        double reflected = 0.0;
        double transmitted = 0.0;
        double total() const { return reflected + transmitted; }
    };
    InterfaceAlbedoTable(double etaV, double etaL, bool exactFresnel, int size = 32, int samples = 1024);
    // Bilinear between texels.
    Value sample(double NoV, double perceptualRoughness) const;
    int size() const { return m_size; }

private:
    int m_size = 0;
    std::vector<Value> m_texels;
};

} // namespace facet::shading
