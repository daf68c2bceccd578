#pragma once
// KHR_materials_anisotropy's microfacet terms, in double: the lobe's CPU ground truth, before the
// material model and the GPU read it (docs/shading.md, "Anisotropy"; docs/layered-lobes.md holds
// the extension's text and how other renderers read it). Directions are in the anisotropy frame:
// x along the anisotropy direction t, y along b = n x t, z along the shading normal n.
//
//   alpha_t  = mix(alpha, 1, strength^2)        along t (the highlight stretches along t)
//   alpha_b  = alpha                            across; alpha = roughness^2
//   D(h)     = 1 / (pi alpha_t alpha_b ((h.t / alpha_t)^2 + (h.b / alpha_b)^2 + (h.n)^2)^2)
//   V(v, l)  = 0.5 / ((n.l) |(alpha_t t.v, alpha_b b.v, n.v)| + (n.v) |(alpha_t t.l, alpha_b b.l, n.l)|)
//
// V is Smith's height-correlated G2 / (4 n.l n.v) with the anisotropic Lambda [Heitz 2014,
// "Understanding the Masking-Shadowing Function", eq. 86 and 99]: the extension's form is that
// expression rewritten, which AnisotropyTest checks. With strength 0 both are the isotropic
// D_GGX and V_SmithGGXCorrelated of core/shading/Brdf.h.

#include <optional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace facet::shading {

// The roughnesses along and across the anisotropy direction (each clamped to kMinAlpha).
struct AnisotropicAlpha {
    double t = 0.25;
    double b = 0.25;
};
// The extension's: alpha_t = mix(alpha, 1, strength^2), alpha_b = alpha, alpha from the
// perceptual roughness as the isotropic lobe's (clampRoughness, then squared); strength clamped
// to [0, 1].
AnisotropicAlpha anisotropicAlpha(double perceptualRoughness, double strength);

// The anisotropic GGX distribution of the normal h (unit, anisotropy frame); 0 below the surface.
double D_GGXAnisotropic(const glm::dvec3& h, const AnisotropicAlpha& alpha);
// Smith's Lambda of the anisotropic GGX for the unit direction w (w.z > 0):
// (-1 + sqrt(1 + (alpha_t^2 w.x^2 + alpha_b^2 w.y^2) / w.z^2)) / 2.
double Lambda_GGXAnisotropic(const glm::dvec3& w, const AnisotropicAlpha& alpha);
// G1 = 1 / (1 + Lambda).
double G1_GGXAnisotropic(const glm::dvec3& w, const AnisotropicAlpha& alpha);
// The extension's visibility (height-correlated Smith), for unit v and l above the surface.
double V_GGXAnisotropic(const glm::dvec3& v, const glm::dvec3& l, const AnisotropicAlpha& alpha);

// A normal of the anisotropic GGX visible from v (anisotropy frame, v.z > 0), proportionally to
// G1(v) max(0, v.h) D(h) / (n.v): Heitz 2018's sampler ("Sampling the GGX Distribution of Visible
// Normals", JCGT 7(4), listing 1), whose stretch takes the two roughnesses. The reflected
// direction's pdf is G1(v) D(h) / (4 n.v).
glm::dvec3 importanceSampleVNDFAnisotropic(
    const glm::dvec2& u, const glm::dvec3& v, const AnisotropicAlpha& alpha);
double pdfVNDFReflectionAnisotropic(const glm::dvec3& v, const glm::dvec3& h, const AnisotropicAlpha& alpha);

// The anisotropy direction in the tangent plane (x along the mesh's tangent, y along its
// bitangent): the texture's direction (its RG remapped to [-1, 1]; (1, 0) without a texture)
// normalised and turned counter-clockwise by `rotation` radians (anisotropyRotation). A direction
// of zero length (a texel of RG 0.5, 0.5) is taken as (1, 0) before turning.
glm::dvec2 anisotropyDirection(const glm::dvec2& textureDirection, double rotation);

// The anisotropy frame at a surface point: t along the direction made perpendicular to the unit
// normal n (Gram-Schmidt: a tangent-space direction mapped through an interpolated or normal-mapped
// frame is not quite in n's plane), b = n x t. Where the direction is zero or along n there is no
// frame, and the lobe is isotropic there (evaluate and the samplers agree on that).
struct AnisotropyFrame {
    glm::dvec3 t {1.0, 0.0, 0.0};
    glm::dvec3 b {0.0, 1.0, 0.0};
    glm::dvec3 n {0.0, 0.0, 1.0};
    glm::dvec3 toLocal(const glm::dvec3& w) const;
    glm::dvec3 toWorld(const glm::dvec3& w) const;
};
std::optional<AnisotropyFrame> anisotropyFrame(const glm::dvec3& n, const glm::dvec3& direction);

// The visible-normal strategy of the base's specular lobe as a material shapes it, for the
// integrators (the ground truth, directionalAlbedo): the anisotropic lobe's in its frame where the
// material has one, the isotropic GGX's otherwise. Built for one shading point (n, v unit, n.v >=
// 0); directions in world space. frame() is an orthonormal frame about n the other strategies may
// use too (the anisotropy frame, or buildOrthonormalBasis's).
class SpecularLobeSampler {
public:
    SpecularLobeSampler(const glm::dvec3& n, const glm::dvec3& v, double perceptualRoughness,
        double anisotropy = 0.0, const glm::dvec3& direction = glm::dvec3(0.0));
    // The reflected direction of the visible normal drawn with u (may lie below the surface).
    glm::dvec3 sample(const glm::dvec2& u) const;
    // Its density (solid angle) for the world direction l; 0 below the surface.
    double pdf(const glm::dvec3& l) const;
    const AnisotropyFrame& frame() const { return m_frame; }
    bool isAnisotropic() const { return m_anisotropic; }

private:
    AnisotropyFrame m_frame;
    glm::dvec3 m_v;
    glm::dvec3 m_vLocal;
    AnisotropicAlpha m_alpha;
    bool m_anisotropic = false;
};

// The multiple-scattering compensation of the anisotropic lobe (Facet's; docs/shading.md,
// "Anisotropy"): the isotropic lobe's factor 1 + F0 (1 - E) / E with E the albedo table's at the
// roughness the view sees, alpha_v^2 = alpha_t^2 (t.v)^2 + alpha_b^2 (1 - (t.v)^2), the added
// energy faded by (1 - s)^2. Measured: a white metal's compensated albedo stays at or below 1.0013
// over roughness 0.05 to 1, strength 0.1 to 1, n.v 0.02 to 1 and views from along t to across it
// (the isotropic table at alpha_b alone gave up to 1.085 at grazing views along t). `vLocal` is
// v in the anisotropy frame.
struct AnisotropicCompensation {
    double perceptualRoughness = 0.5; // where the albedo table is read
    double weight = 1.0; // of the compensation's added energy
};
AnisotropicCompensation anisotropicCompensation(
    const glm::dvec3& vLocal, double perceptualRoughness, double strength);

// The bent normal of the Khronos sample renderer's image-based anisotropy at the unit normal n,
// view v and anisotropy tangent t (unit, perpendicular to n): mix(cross(cross(b, v), b), n,
// (1 - strength (1 - r))^4) normalised, b = n x t; n where that degenerates. A material swatch
// (core/material/MaterialSwatch) reads its prefiltered light about it; the window integrates the
// lobe by samples instead (docs/shading.md, "Anisotropy").
glm::dvec3 anisotropicBentNormal(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& t,
    double perceptualRoughness, double strength);

// The directional albedo of the anisotropic lobe with F = 1 seen from v (anisotropy frame): the
// integral of D V (n.l) over the hemisphere, estimated with `sampleCount` Hammersley points drawn
// from the visible normals (each weighs G2 / G1(v)). The white furnace of the lobe: <= 1, the
// single scattering's loss below it.
double anisotropicDirectionalAlbedo(const glm::dvec3& v, const AnisotropicAlpha& alpha, int sampleCount);

} // namespace facet::shading
