#pragma once
// KHR_materials_sheen's BRDF terms, in double: the first step of the sheen lobe, its CPU ground
// truth (docs/shading.md, "Sheen"; docs/layered-lobes.md holds the extension's text and how other
// renderers read it). Not a material property yet: no material, shader or file reads these.
//
//   D_Charlie(n.h, a)  = (2 + 1/a) (1 - (n.h)^2)^(1 / (2a)) / (2 pi)       a = sheenRoughness^2
//   V_Charlie          = 1 / ((1 + lambda(n.v) + lambda(n.l)) 4 n.v n.l)   (the extension's choice)
//   V_Neubelt          = 1 / (4 (n.l + n.v - n.l n.v))                      (Filament's, "Ashikhmin")
//   sheen_brdf         = sheenColor D V                                    (no Fresnel)
//
// [Estevez and Kulla 2017, "Production Friendly Microfacet Sheen BRDF"; Neubelt and Pettineo 2013]

namespace facet::shading {

// Smallest sheen alpha used: the extension's distribution is singular at roughness 0 (the glTF
// Sample Viewer clamps the roughness to 1e-6 before squaring; this keeps the exponent finite in
// double, 1/(2a) = 5e11 at most).
inline constexpr double kMinSheenAlpha = 1e-12;

// The sheen's "Charlie" distribution: a sine power, peaked where h grazes the surface.
double D_Charlie(double NoH, double sheenAlpha);
// The fitted Smith lambda of the Charlie distribution [Estevez and Kulla 2017, eq. 3 and table 1].
double lambdaSheen(double cosTheta, double sheenAlpha);
// Its height-correlated visibility, and Neubelt's cheaper one that Filament uses.
double V_Charlie(double NoV, double NoL, double sheenAlpha);
double V_Neubelt(double NoV, double NoL);

enum class SheenVisibility { Charlie, Neubelt };

// E(n.v, r): the directional albedo of the sheen lobe with sheenColor 1, integral of D V (n.l)
// over the hemisphere, by a midpoint rule in (theta, phi) of `steps` x 4 `steps` cells (the
// integrand is smooth in both; 256 steps converge to 1e-4 for r >= 0.25). The extension's albedo
// scaling of the base, 1 - max(sheenColor) E, reads it.
double sheenDirectionalAlbedo(double NoV, double sheenRoughness, SheenVisibility visibility, int steps = 256);

} // namespace facet::shading
