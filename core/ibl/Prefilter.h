#pragma once
// CPU twins, in double, of the GPU IBL precompute (render/IblPrecompute.h,
// resources/shaders/ibl_*.glsl): the cubemap face orientation and the prefiltered specular
// radiance. docs/ibl.md holds the equations.

#include <vector>

#include <glm/vec3.hpp>

namespace facet {

class Environment;

// Unit direction of texture coordinate (u, v) in [0, 1]^2 of cubemap face `face` (0..5 = +X, -X,
// +Y, -Y, +Z, -Z, OpenGL order and orientation, OpenGL 4.6 table 8.19). Texel (x, y) of a
// size-N face, y being the row index in GL memory order, is at ((x + 0.5) / N, (y + 0.5) / N).
// With a = 2u - 1, b = 2v - 1 the direction is normalize of
//   +X: ( 1, -b, -a)   -X: (-1, -b,  a)   +Y: ( a,  1,  b)
//   -Y: ( a, -1, -b)   +Z: ( a, -b,  1)   -Z: (-a, -b, -1)
// GLSL twin: resources/shaders/common_cubemap.glsl.
glm::dvec3 cubemapDirection(int face, double u, double v);

// The inverse: the face holding direction d (largest |component|, ties to the lower face index)
// and its texture coordinate.
int cubemapFace(const glm::dvec3& d, double* u, double* v);

// One sample of a split-sum lobe (n = v = R) in the frame of n (z along n): l = reflect(n, h) for
// h = importanceSampleGGX(hammersley(i, N), alpha), its weight n.l = l.z (> 0), and its pdf as a
// direction of l, D(h) (n.h) / (4 v.h) = D(h) / 4 when v = n.
struct PrefilterLobeSample {
    glm::dvec3 l;
    double pdf = 0.0;
};
// The samples of the lobe of perceptual `roughness` from N = `samples` Hammersley points, in
// order, those at or below the horizon (n.l <= 0: they add nothing) left out. They are the same
// for every R, so they are made once: prefilteredRadiance rotates them about R, and the GPU pass
// gets them as a table (render/IblPrecompute.cpp) instead of computing them in every texel.
std::vector<PrefilterLobeSample> prefilterLobeSamples(double roughness, int samples);

// Split-sum prefiltered radiance [Karis 2013] around reflection direction R with n = v = R:
//   L_pre(R) = sum_i L(l_i) (n.l_i) / sum_i (n.l_i),
// l_i = reflect(R, h_i), h_i = importanceSampleGGX(hammersley(i, samples), alpha) about R,
// alpha = alphaFromRoughness(roughness). Reads Environment::radiance (bilinear, the
// environment's rotation and intensity applied: use rotation 0 and intensity 1 to compare with
// the GPU's image-frame result). The GPU adds source-mip filtering (filteredLod); with many
// samples both converge to the same convolution.
glm::dvec3 prefilteredRadiance(
    const Environment& environment, const glm::dvec3& R, double roughness, int samples);

// Filtered importance sampling [Krivanek & Colbert 2008]: the source level for a sample of
// solid-angle pdf `pdf` out of `sampleCount`, for a cubemap source of face size `sourceSize`:
//   Omega_s = 1 / (N pdf),  Omega_p = 4 pi / (6 w^2),  lod = 0.5 log2(Omega_s / Omega_p) + 1,
// clamped to [0, maxLod], with pdf floored at 1 / (2 pi) (a uniform hemisphere's: a rare
// grazing or tail sample must not read a level that averages light from behind). The lods the
// prefilter pass reads its samples at (render/IblPrecompute.cpp makes them with the samples).
double filteredLod(double pdf, double sampleCount, double sourceSize, double maxLod);
// The solid angle of the texel of a size-w cubemap face at direction d (unit):
// (2/w)^2 / (1 + a^2 + b^2)^(3/2) = 4 |d|_max^3 / w^2, a and b the face coordinates. The texels
// of a face sum to 4 pi / 6.
double cubeTexelSolidAngle(const glm::dvec3& d, double sourceSize);
// filteredLod against the texel at d (cubeTexelSolidAngle) instead of the face average, and
// without its +1 (measured: the blur is Fis's bias): lod = 0.5 log2(Omega_s / Omega_p(d)),
// clamped to [0, maxLod]. What IblMethod::Fis reads its samples at. GLSL twin:
// resources/shaders/ibl_filtering.glsl.
double filteredLodAt(double pdf, double sampleCount, double sourceSize, double maxLod, const glm::dvec3& d);

} // namespace facet
