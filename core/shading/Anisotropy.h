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

// The directional albedo of the anisotropic lobe with F = 1 seen from v (anisotropy frame): the
// integral of D V (n.l) over the hemisphere, estimated with `sampleCount` Hammersley points drawn
// from the visible normals (each weighs G2 / G1(v)). The white furnace of the lobe: <= 1, the
// single scattering's loss below it.
double anisotropicDirectionalAlbedo(const glm::dvec3& v, const AnisotropicAlpha& alpha, int sampleCount);

} // namespace facet::shading
