#pragma once
// The microfacet BRDF terms, in double. Each function has the same name and arguments as its
// GLSL twin in resources/shaders/brdf_*.glsl; docs/shading.md holds the equations and units.
//
// Conventions: all cosines are clamped by the caller to [0, 1] (back-facing light contributes
// nothing); alpha = perceptualRoughness^2 (glTF 2.0, Burley 2012), clamped below by
// kMinAlpha. Visibility V = G / (4 N.L N.V): it already holds the microfacet denominator, so the
// specular lobe is D * V * F. Every function returns a finite, non-negative value over the whole
// clamped domain, including N.V = N.L = 0 and roughness 0 (tests/BrdfTest.cpp checks a dense grid).

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace facet::shading {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kInvPi = std::numbers::inv_pi;

// Smallest perceptual roughness a material may have. alpha = 0.045^2 ~ 0.002 keeps D_GGX at its
// peak (1 / (pi alpha^2) ~ 7.8e4) within half-float range, as Filament does (its
// MIN_PERCEPTUAL_ROUGHNESS), and keeps a mirror from becoming a Dirac delta that no sampler sees.
inline constexpr double kMinPerceptualRoughness = 0.045;
inline constexpr double kMinAlpha = kMinPerceptualRoughness * kMinPerceptualRoughness;

inline double clampRoughness(double perceptualRoughness)
{
    return std::clamp(perceptualRoughness, kMinPerceptualRoughness, 1.0);
}
// glTF 2.0 Appendix B: alpha = roughness^2.
inline double alphaFromRoughness(double perceptualRoughness)
{
    const double r = clampRoughness(perceptualRoughness);
    return r * r;
}

// Guards denominators that vanish only at the corner of the domain (N.V = N.L = 0); the
// numerators vanish there too, so any value this small gives f * N.L = 0.
inline constexpr double kMinDenominator = 1e-12;

// ---- Normal distribution functions ------------------------------------------------------

// GGX / Trowbridge-Reitz [Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces"].
inline double D_GGX(double NoH, double alpha)
{
    const double a2 = alpha * alpha;
    const double f = NoH * NoH * (a2 - 1.0) + 1.0;
    return a2 * kInvPi / std::max(f * f, kMinDenominator);
}

// Beckmann [Beckmann & Spizzichino 1963], in the form of Walter et al. 2007 eq. 25.
inline double D_Beckmann(double NoH, double alpha)
{
    if (NoH <= 0.0)
        return 0.0;
    const double a2 = alpha * alpha;
    const double cos2 = NoH * NoH;
    const double tan2 = (1.0 - cos2) / cos2;
    return std::exp(-tan2 / a2) * kInvPi / (a2 * cos2 * cos2);
}

// ---- Geometry / visibility ---------------------------------------------------------------

// Height-correlated Smith-GGX visibility [Heitz 2014, "Understanding the Masking-Shadowing
// Function in Microfacet-Based BRDFs", eq. 99], the glTF 2.0 specification's V.
inline double V_SmithGGXCorrelated(double NoV, double NoL, double alpha)
{
    const double a2 = alpha * alpha;
    const double lambdaV = NoL * std::sqrt(NoV * NoV * (1.0 - a2) + a2);
    const double lambdaL = NoV * std::sqrt(NoL * NoL * (1.0 - a2) + a2);
    return 0.5 / std::max(lambdaV + lambdaL, kMinDenominator);
}

// Separable (uncorrelated) Smith-GGX: G1(v) G1(l) / (4 N.V N.L) with the exact GGX G1
// [Walter et al. 2007, eq. 34], simplified so that it stays finite at grazing angles.
inline double V_SmithGGX(double NoV, double NoL, double alpha)
{
    const double a2 = alpha * alpha;
    const double gV = NoV + std::sqrt(a2 + (1.0 - a2) * NoV * NoV);
    const double gL = NoL + std::sqrt(a2 + (1.0 - a2) * NoL * NoL);
    return 1.0 / std::max(gV * gL, kMinDenominator);
}

// Schlick-GGX G1 [Schlick 1994; Karis 2013, "Real Shading in Unreal Engine 4"].
inline double G_SchlickGGX(double NoX, double k)
{
    return NoX / std::max(NoX * (1.0 - k) + k, kMinDenominator);
}

// Karis 2013 remappings of k: (r + 1)^2 / 8 for punctual lights (r is perceptual roughness;
// "roughness remapping" that avoids hot grazing highlights), alpha / 2 for image-based lighting.
inline double k_SchlickGGX_direct(double perceptualRoughness)
{
    const double r = clampRoughness(perceptualRoughness) + 1.0;
    return r * r / 8.0;
}
inline double k_SchlickGGX_ibl(double alpha)
{
    return alpha / 2.0;
}

// Separable Smith with the Schlick-GGX G1, as a visibility: G(v) G(l) / (4 N.V N.L). The N.X
// factors cancel, which keeps it finite at grazing angles.
inline double V_SmithSchlickGGX(double NoV, double NoL, double k)
{
    const double gV = NoV * (1.0 - k) + k;
    const double gL = NoL * (1.0 - k) + k;
    return 0.25 / std::max(gV * gL, kMinDenominator);
}

// ---- Fresnel ------------------------------------------------------------------------------

inline double pow5(double x)
{
    const double x2 = x * x;
    return x2 * x2 * x;
}

// Schlick's approximation [Schlick 1994, "An Inexpensive BRDF Model for Physically-based Rendering"].
inline glm::dvec3 F_Schlick(const glm::dvec3& f0, double f90, double VoH)
{
    return f0 + (glm::dvec3(f90) - f0) * pow5(1.0 - std::clamp(VoH, 0.0, 1.0));
}
inline double F_Schlick(double f0, double f90, double VoH)
{
    return f0 + (f90 - f0) * pow5(1.0 - std::clamp(VoH, 0.0, 1.0));
}

// Exact unpolarised Fresnel reflectance of a dielectric interface, light arriving from the
// outside medium (index 1) onto index `ior` [Walter et al. 2007, eq. 22]. 1 under total internal
// reflection (only possible when ior < 1).
inline double F_Dielectric(double cosThetaI, double ior)
{
    const double c = std::clamp(cosThetaI, 0.0, 1.0);
    const double g2 = ior * ior - 1.0 + c * c;
    if (g2 < 0.0)
        return 1.0;
    const double g = std::sqrt(g2);
    const double a = (g - c) / (g + c);
    const double b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    return 0.5 * a * a * (1.0 + b * b);
}

// Normal-incidence reflectance of a dielectric of index `ior` in air: ((n - 1) / (n + 1))^2;
// 1.5 gives 0.04 (glTF 2.0 Appendix B, KHR_materials_ior).
inline double f0FromIor(double ior)
{
    const double r = (ior - 1.0) / (ior + 1.0);
    return r * r;
}
// The inverse, for presets given by F0.
inline double iorFromF0(double f0)
{
    const double s = std::sqrt(std::clamp(f0, 0.0, 0.999999));
    return (1.0 + s) / (1.0 - s);
}

// ---- Diffuse ------------------------------------------------------------------------------

// Lambert: 1 / pi (times the diffuse colour).
inline double Fd_Lambert()
{
    return kInvPi;
}

} // namespace facet::shading
