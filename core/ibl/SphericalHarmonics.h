#pragma once
// Real spherical harmonics up to band l = 2 (9 coefficients per colour channel) and the
// irradiance they give through the clamped-cosine convolution.
//
//   Ramamoorthi & Hanrahan 2001, "An Efficient Representation for Irradiance Environment Maps"
//     (SIGGRAPH 2001): irradiance is a low-pass filter of radiance; bands 0..2 hold >99% of the
//     clamped-cosine kernel's energy, so 9 coefficients reproduce E(n) for SMOOTH lighting.
//   Sloan 2008, "Stupid Spherical Harmonics (SH) Tricks" (GDC): basis constants, projection,
//     rotation, ringing.
//   Filament libs/ibl (CubemapSH), MaterialX MaterialXRender/Harmonics.h: the same on the CPU.
//
// docs/irradiance.md holds the equations, the measured error of SH9 against the brute-force
// integral (core/ibl/Irradiance.h) for the sample HDRIs, and why it is large for high-contrast maps.
//
// ---------------------------------------------------------------------------------------------
// Basis and ordering (index i = l (l + 1) + m, Ramamoorthi & Hanrahan 2001, WITHOUT the
// Condon-Shortley phase: every constant is positive). For a unit direction d = (x, y, z) in the
// WORLD frame of docs/architecture.md (+Y up):
//
//   i  (l, m)   Y_lm(d)                        constant
//   0  (0,  0)  K0                              K0 = 1/2 sqrt(1/pi)  = 0.282094791773878
//   1  (1, -1)  K1 y                            K1 = sqrt(3/(4 pi))  = 0.488602511902920
//   2  (1,  0)  K1 z
//   3  (1,  1)  K1 x
//   4  (2, -2)  K2 x y                          K2 = 1/2 sqrt(15/pi) = 1.092548430592079
//   5  (2, -1)  K2 y z
//   6  (2,  0)  K20 (3 z^2 - 1)                 K20 = 1/4 sqrt(5/pi) = 0.315391565252520
//   7  (2,  1)  K2 x z
//   8  (2,  2)  K22 (x^2 - y^2)                 K22 = 1/4 sqrt(15/pi) = 0.546274215296040
//
// These are the Cartesian formulas every real-time SH implementation copies, applied to world
// (x, y, z) as they are: the basis's polar (zonal) axis is world +Z, not the +Y up axis. That is
// only a choice of basis: bands 0..2 span the same space whatever the axis, irradiance does not
// depend on it, and keeping the textbook formulas keeps the GLSL twin recognisable.
// The basis is orthonormal: integral over the sphere of Y_i Y_j = delta_ij (tested numerically).

#include <array>

#include <glm/vec3.hpp>

namespace facet {

class Environment;

// Nine RGB coefficients of a function on the sphere (radiance, unless a name says otherwise),
// in the order of the table above.
struct SH9 {
    std::array<glm::dvec3, 9> c {};
};

// SH9 coefficients already convolved with the clamped cosine: c_lm * A_l. These are the nine
// vec3 a shader needs (uniform vec3 uIrradianceSH[9]); see irradianceSH(const IrradianceSH9&, ...).
struct IrradianceSH9 {
    std::array<glm::dvec3, 9> c {};
};

namespace sh {
inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double K0 = 0.282094791773878143; // 1/2 sqrt(1/pi)
inline constexpr double K1 = 0.488602511902919921; // sqrt(3/(4 pi))
inline constexpr double K2 = 1.092548430592079070; // 1/2 sqrt(15/pi)
inline constexpr double K20 = 0.315391565252520006; // 1/4 sqrt(5/pi)
inline constexpr double K22 = 0.546274215296039535; // 1/4 sqrt(15/pi)

// Clamped-cosine convolution constants. The kernel max(0, n.w) depends on n.w only, so by the
// Funk-Hecke theorem integral max(0, n.w) Y_lm(w) dw = A_l Y_lm(n), with (P_l: Legendre)
//   A_l = 2 pi * integral_0^1 t P_l(t) dt
//   A_0 = 2 pi * integral_0^1 t dt                   = 2 pi * 1/2 = pi
//   A_1 = 2 pi * integral_0^1 t^2 dt                 = 2 pi * 1/3 = 2 pi / 3
//   A_2 = 2 pi * integral_0^1 t (3 t^2 - 1) / 2 dt   = 2 pi * 1/8 = pi / 4
// (Ramamoorthi & Hanrahan 2001: A_0 = pi, A_1 = 2pi/3, A_2 = pi/4, A_3 = 0, and
// A_4 = -pi/24 is the first band SH9 drops.)
inline constexpr double A0 = kPi;
inline constexpr double A1 = 2.0 * kPi / 3.0;
inline constexpr double A2 = kPi / 4.0;
// A_l for each of the 9 coefficients (index i -> band l).
inline constexpr std::array<double, 9> kCosineLobe = {A0, A1, A1, A1, A2, A2, A2, A2, A2};
} // namespace sh

// The nine basis functions at unit direction d, in the order above.
std::array<double, 9> shBasis(const glm::dvec3& d);

// The SH9 reconstruction sum_i c_i Y_i(d) (for radiance coefficients: the band-limited
// radiance, which rings and may go negative near bright small sources).
glm::dvec3 evaluateSH(const SH9& coefficients, const glm::dvec3& d);

// Projects the environment's radiance onto the basis:
//   L_lm = integral over the sphere of L(w) Y_lm(w) dw  ~=  sum over texels L_t Y_lm(w_t) dOmega_t
// where w_t is the texel centre's WORLD direction (the environment's rotation applied, so the
// coefficients describe the lighting as the scene sees it), L_t the texel's radiance times the
// environment's intensity, and dOmega_t the texel's exact solid angle
// (core/ibl/Irradiance.h, equirectTexelSolidAngle: (2 pi / W) (sin lat1 - sin lat0)).
// Images smaller than 512x256 have each texel split into equal sub-cells of the same radiance
// (EquirectQuadrature) so that tiny images (e.g. the 8x4 uniform environment) still integrate
// the basis accurately; the sample HDRIs (512x256) are summed texel by texel.
// An empty environment gives all-zero coefficients.
SH9 projectEquirect(const Environment& environment);

// A_l applied: the coefficients of irradiance E(n) = sum_lm A_l L_lm Y_lm(n).
IrradianceSH9 irradianceSHCoefficients(const SH9& radiance);

// Irradiance E(n) = integral over the hemisphere around n of L(w) (n.w) dw (radiance units times
// steradians) from premultiplied coefficients, clamped at zero. This is the CPU twin of the
// GLSL function the renderer uses; keep the two identical:
//
//   // uIrradianceSH[i] = c_i * A_l, from irradianceSHCoefficients(); n is the unit world normal.
//   vec3 irradianceSH(vec3 n) {
//       vec3 e = uIrradianceSH[0] * 0.282094791773878
//              + uIrradianceSH[1] * (0.488602511902920 * n.y)
//              + uIrradianceSH[2] * (0.488602511902920 * n.z)
//              + uIrradianceSH[3] * (0.488602511902920 * n.x)
//              + uIrradianceSH[4] * (1.092548430592079 * n.x * n.y)
//              + uIrradianceSH[5] * (1.092548430592079 * n.y * n.z)
//              + uIrradianceSH[6] * (0.315391565252520 * (3.0 * n.z * n.z - 1.0))
//              + uIrradianceSH[7] * (1.092548430592079 * n.x * n.z)
//              + uIrradianceSH[8] * (0.546274215296040 * (n.x * n.x - n.y * n.y));
//       return max(e, vec3(0.0)); // SH9 rings below zero under strong small sources
//   }
//
// Lambertian use: the diffuse OUTGOING radiance is Lo = albedo / pi * E(n) (the Lambert BRDF is
// albedo / pi), so under a uniform environment L, E = pi L and Lo = albedo * L (the furnace).
glm::dvec3 irradianceSH(const IrradianceSH9& irradianceCoefficients, const glm::dvec3& n);

// Same from radiance coefficients: irradianceSH(irradianceSHCoefficients(radiance), n).
glm::dvec3 irradianceSH(const SH9& radiance, const glm::dvec3& n);

} // namespace facet
