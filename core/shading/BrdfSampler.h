#pragma once
// The BRDF strategy of the ground-truth integrators at one shading point (core/shading/GroundTruth,
// core/truth/SceneTruth): a lobe picked by its approximate albedo (the coat, the base's specular
// lobe, or the cosine lobe that serves the diffuse and the sheen), then a direction from that
// lobe's own distribution (visible normals for the specular lobes, anisotropic in the material's
// frame where it is; cosine-weighted for the rest). A transmitting material's specular lobe and
// transmission share one isotropic visible normal, reflected or, by what each carries there,
// refracted through it (a volume) or reflected and mirrored through the surface (a thin wall);
// pdf() is the density of the mixture, which multiple importance sampling weighs against the
// environment's [Veach 1997, ch. 9]. Any lobe probabilities that give each lobe a share keep the
// estimators unbiased; good ones lower variance.
//
// Inside a volume (Mode::Interior) the surface is the bare rough dielectric interface from the
// material's index out to 1: Fresnel-weighted reflection back in (total internal reflection past
// the critical angle) and the BTDF out, tinted by the base colour (docs/shading.md, "Transmission").

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
    enum class Mode {
        Full, // the material's BRDF, and its transmission where it transmits, seen from outside
        LambertOnly, // the base colour's Lambert lobe alone (tests of the diffuse integral)
        Interior, // the material's volume boundary seen from inside (v inside the medium)
    };
    // `material` with its anisotropy direction set where it has one (in the space of n); n and v
    // unit, n on v's side.
    BrdfSampler(const MaterialInfo& material, const MaterialBrdf& brdf, const glm::dvec3& n,
        const glm::dvec3& v, Mode mode = Mode::Full);

    // The BSDF for the direction l (world space): the reflection above the surface, the
    // transmission below it (0 where the material lets nothing through).
    glm::dvec3 f(const glm::dvec3& l, LightingKind kind) const;
    // The mixture's density (solid angle) of l.
    double pdf(const glm::dvec3& l) const;
    // A direction drawn with u in [0, 1)^2 (and uFresnel in [0, 1), which the interior's choice
    // between reflection and refraction takes): the first coordinate picks the lobe and is
    // stretched back to [0, 1), so each lobe keeps a stratified share of stratified points. May
    // be a direction pdf() gives 0 (below an opaque surface).
    glm::dvec3 sample(glm::dvec2 u, double uFresnel = 0.5) const;
    // Whether f can be non-zero below the surface.
    bool transmits() const { return m_pSplit > 0.0 || m_mode == Mode::Interior; }

private:
    // The interior interface's lobes: its Fresnel at v.h, and f and pdf for l either side.
    double interiorFresnel(double VoH) const;
    glm::dvec3 interiorF(const glm::dvec3& l) const;
    double interiorPdf(const glm::dvec3& l) const;
    glm::dvec3 interiorSample(const glm::dvec2& u, double uFresnel) const;
    // A transmitting material's split strategy: the share of the light a visible normal at v.h
    // reflects (the rest it transmits), the density of a transmitted direction's normal (and its
    // v.h), and a direction.
    double reflectShare(double VoH) const;
    double transmissionPdf(const glm::dvec3& l, double* VoH) const;
    glm::dvec3 splitSample(const glm::dvec2& u, double uFresnel) const;

    const MaterialInfo& m_material;
    const MaterialBrdf& m_brdf;
    glm::dvec3 m_n;
    glm::dvec3 m_v;
    double m_NoV = 0.0;
    Mode m_mode = Mode::Full;
    shading::SpecularLobeSampler m_specular;
    glm::dvec3 m_t;
    glm::dvec3 m_b;
    glm::dvec3 m_vLocal;
    double m_coatAlpha = 0.0;
    double m_alpha = 0.0; // the base's isotropic alpha: the transmission's and the interior's
    double m_ior = 1.5; // the volume's index (kMinRefractiveIor at least)
    double m_interiorCompensation = 1.0;
    DielectricReflectance m_layer;
    // The lobes' probabilities: the coat, the specular lobe (an opaque material's), a transmitting
    // material's specular reflection and transmission split by Fresnel, the cosine lobe the rest.
    double m_pCoat = 0.0;
    double m_pSpecular = 0.0;
    double m_pSplit = 0.0;
};

} // namespace facet
