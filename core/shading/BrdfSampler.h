#pragma once
// The BRDF strategy of the ground-truth integrators at one shading point (core/shading/GroundTruth,
// core/truth/SceneTruth): a lobe picked by its approximate albedo (the coat, the base's specular
// lobe, or the cosine lobe that serves the diffuse and the sheen), then a direction from that
// lobe's own distribution (visible normals for the specular lobes, anisotropic in the material's
// frame where it is; cosine-weighted for the rest); pdf() is the density of the mixture, which
// multiple importance sampling weighs against the environment's [Veach 1997, ch. 9]. Any lobe
// probabilities that give each lobe a share keep the estimators unbiased; good ones lower variance.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/shading/Anisotropy.h"
#include "core/shading/MaterialBrdf.h"

namespace facet {

// The power heuristic with beta = 2 [Veach 1997, eq. 9.13]: the weight of the strategy whose
// density is pdfA against one whose density is pdfB.
double powerHeuristic(double pdfA, double pdfB);

class BrdfSampler {
public:
    // `material` with its anisotropy direction set where it has one (in the space of n); n and v
    // unit. lambertOnly: the base colour's Lambert lobe alone (tests of the diffuse integral).
    BrdfSampler(const MaterialInfo& material, const MaterialBrdf& brdf, const glm::dvec3& n,
        const glm::dvec3& v, bool lambertOnly = false);

    // The BRDF for the direction l (world space), 0 below the surface.
    glm::dvec3 f(const glm::dvec3& l, LightingKind kind) const;
    // The mixture's density (solid angle) of l; 0 below the surface.
    double pdf(const glm::dvec3& l) const;
    // A direction drawn with u in [0, 1)^2: the first coordinate picks the lobe and is stretched
    // back to [0, 1), so each lobe keeps a stratified share of stratified points. May lie below
    // the surface (pdf() is then 0).
    glm::dvec3 sample(glm::dvec2 u) const;

private:
    const MaterialInfo& m_material;
    const MaterialBrdf& m_brdf;
    glm::dvec3 m_n;
    glm::dvec3 m_v;
    double m_NoV = 0.0;
    bool m_lambertOnly = false;
    shading::SpecularLobeSampler m_specular;
    glm::dvec3 m_t;
    glm::dvec3 m_b;
    glm::dvec3 m_vLocal;
    double m_coatAlpha = 0.0;
    // The lobes' probabilities: the coat, the specular lobe, the cosine lobe the rest.
    double m_pCoat = 0.0;
    double m_pSpecular = 0.0;
};

} // namespace facet
