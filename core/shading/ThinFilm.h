#pragma once
// KHR_materials_iridescence's thin-film Fresnel, in double: the lobe's CPU ground truth before the
// material model and the GPU read it (docs/shading.md, "Iridescence"; docs/layered-lobes.md, section
// 5, holds the extension's text and how other renderers read it).
//
// A film of index eta2 and thickness d (nanometres) lies between the outside (index 1) and the
// base, whose index comes from its normal-incidence reflectance F0 per RGB channel (the metal's
// base colour, the dielectric's f0), as if it had no extinction. Light reflected inside the film
// interferes with light reflected at its top: the reflectance of one wavelength is an Airy series in
// the phase x = 2 pi OPD / lambda + phi, OPD = 2 eta2 d cos(theta2),
//
//   R(lambda) = C0 + 2 sum_{m >= 1} Cm cos(m x),   C0 = R12 + Rs,   Cm = (Rs - T121) r123^m,
//   R12 = Schlick(((eta2 - 1) / (eta2 + 1))^2, cos theta1),   T121 = 1 - R12,
//   R23 = Schlick(((eta3 - eta2) / (eta3 + eta2))^2, cos theta2),   r123 = sqrt(R12 R23),
//   Rs  = T121^2 R23 / (1 - R12 R23),   phi = phi21 + phi23 (pi at each reflection off a denser side)
//
// [Belcour and Barla 2017, "A Practical Extension to Microfacet Theory for the Modeling of Varying
// Iridescence"]. The extension's Fresnel (iridescenceFresnel) keeps the first two orders and
// integrates each against the CIE colour matching functions in closed form, through Gaussian fits
// of their Fourier transforms; iridescenceFresnelSpectral sums every order and integrates over
// wavelength, the reference that approximation is measured against (ThinFilmTest).

#include <glm/vec3.hpp>

namespace facet::shading {

// The extension's defaults and the thickness the film fades to the bare base over (below).
inline constexpr double kDefaultIridescenceIor = 1.3;
inline constexpr double kDefaultIridescenceThicknessMinimum = 100.0; // nanometres
inline constexpr double kDefaultIridescenceThicknessMaximum = 400.0;
// Below this thickness (nm) the film's index is blended towards the outside's, so that a film of
// thickness 0 is no film: the sample renderer's smoothstep(0, 0.03, d), kept (the extension leaves
// d -> 0 open; docs/shading.md).
inline constexpr double kThinFilmFadeThickness = 0.03;
// The reflection off the base shifts the phase by pi where the base is less dense than the film
// (eta3 < eta2). Where the two indices are equal (a film of 1.5 over the default dielectric, F0
// 0.04) the test is a coin toss of rounding, and the result jumps: the extension's Schlick R23 is
// not 0 there. Facet decides it the same way in double and float: the base counts as less dense
// only below eta2 - this (docs/shading.md, "Iridescence").
inline constexpr double kThinFilmIndexTolerance = 1e-4;

struct ThinFilm {
    double ior = kDefaultIridescenceIor; // eta2, >= 1
    double thickness = kDefaultIridescenceThicknessMaximum; // d, nanometres, >= 0
};

// Firid of the extension's Implementation Notes ("Iridescence Fresnel"), as written there: the
// linear Rec.709 reflectance of the film over a base of normal-incidence reflectance baseF0 (each
// channel clamped to [0, 0.9999]) seen at cos(theta1) = cosTheta (the caller's: n.v or v.h), orders 1
// and 2 through the fitted sensitivity, the sum clamped at 0 (it is not clamped at 1: measured in
// ThinFilmTest).
glm::dvec3 iridescenceFresnel(const ThinFilm& film, const glm::dvec3& baseF0, double cosTheta);

// The same film's reflectance from its spectrum: the Airy series summed in closed form,
// C0 + 2 (Rs - T121) Re(z / (1 - z)) with z = r123 e^{i x}, integrated over 360 to 830 nm in
// `wavelengthSamples` midpoint steps against the CIE 1931 colour matching functions (Wyman, Sloan
// and Shirley's multi-lobe fit, JCGT 2(2) 2013), taken to linear Rec.709 and divided per channel by
// a flat spectrum's (illuminant E's) RGB, so that a reflectance of 1 at every wavelength is white.
// Channel c uses the film over baseF0[c], as iridescenceFresnel does.
glm::dvec3 iridescenceFresnelSpectral(
    const ThinFilm& film, const glm::dvec3& baseF0, double cosTheta, int wavelengthSamples = 940);

// The CIE 1931 2-degree colour matching functions (x, y, z) at the wavelength lambda (nm): the fit
// the spectral reference integrates against.
glm::dvec3 colourMatchingFunctions(double lambda);

// The visible band the spectral reference integrates over, and the colour one wavelength of it
// stands for in a spectral estimate: the colour matching functions at lambda taken to linear
// Rec.709, divided per channel by their mean over the band, so that wavelengths drawn uniformly
// over it average to white (1, 1, 1) (some channels are negative: a spectral colour lies outside
// Rec.709's gamut). KHR_materials_dispersion's paths draw their wavelength with it
// (core/truth/SceneTruth).
inline constexpr double kVisibleShortest = 360.0; // nm
inline constexpr double kVisibleLongest = 830.0;
glm::dvec3 wavelengthRgbWeight(double lambda);

// The film's incoherent reflectance, C0 = R12 + Rs: what both converge to as the film thickens and
// its interference averages out over the visible band.
glm::dvec3 thinFilmIncoherentReflectance(const ThinFilm& film, const glm::dvec3& baseF0, double cosTheta);

} // namespace facet::shading
