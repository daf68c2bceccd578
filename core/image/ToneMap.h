#pragma once
// The display transform: exposure, tone mapping and display encoding, in double. CPU twins of
// resources/shaders/tonemap.glsl (same function names), so tests can hold the GPU pass to them.
// docs/rendering.md lists each curve with its source.
//
// Order (tonemap.frag): radiance * 2^exposureEV -> tone mapper (display-linear, [0, 1]) ->
// display encoding (sRGB piecewise or a pure gamma). Every function maps 0 to 0, is finite for
// any finite non-negative input (1e6 included), and non-decreasing along a grey ramp.

#include <glm/vec3.hpp>

#include "core/project/Project.h" // ToneMapper, DisplayEncoding, ViewSettings

namespace facet::tonemap {

// No tone mapping: clamp to [0, 1].
glm::dvec3 toneMapNone(const glm::dvec3& color);
// Reinhard et al. 2002, "Photographic Tone Reproduction for Digital Images", eq. 3: x / (1 + x),
// per channel.
glm::dvec3 toneMapReinhard(const glm::dvec3& color);
// Exponential exposure curve 1 - e^(-x), per channel (the "exposure" operator of film-like
// response, e.g. Hoffman's "Crafting physically motivated shading models", and Filament's
// "exposure"-style curves).
glm::dvec3 toneMapExposure(const glm::dvec3& color);
// ACES filmic, Stephen Hill's fit of the RRT + sRGB ODT (BakingLab, ACES.hlsl, 2016): sRGB ->
// ACES AP1-ish input matrix, rational fit, output matrix, clamp. The glTF Sample Viewer's
// toneMapACES_Hill, without its 1/0.6 exposure boost.
glm::dvec3 toneMapAcesHill(const glm::dvec3& color);
// Khronos PBR Neutral (Khronos 3D Commerce, "PBR Neutral Tone Mapping" specification, 2024,
// reference GLSL PBRNeutralToneMapping): F0-aware toe offset, highlight compression above 0.76,
// desaturation toward the new peak.
glm::dvec3 toneMapKhronosPbrNeutral(const glm::dvec3& color);
// AgX (Troy Sobotka's AgX), Benjamin Wrensch's "Minimal AgX Implementation" (iolite, 2023):
// inset matrix, log2 encoding over [-12.47393, 4.026069] EV, 6th-order polynomial fit of the
// default contrast curve, inverse matrix, then pow(2.2) back to display-linear (as three.js does)
// so the display encoding applies afterwards like for the other curves; clamped to [0, 1].
glm::dvec3 toneMapAgx(const glm::dvec3& color);

glm::dvec3 toneMap(ToneMapper mapper, const glm::dvec3& color);

// sRGB OETF, exact piecewise curve (IEC 61966-2-1): 12.92 x below 0.0031308, else
// 1.055 x^(1/2.4) - 0.055. Input clamped to [0, 1].
double linearToSrgb(double x);
double srgbToLinear(double x);
// The display encoding: sRGB piecewise, or x^(1/gamma). Input clamped to [0, 1].
glm::dvec3 encodeDisplay(const glm::dvec3& displayLinear, DisplayEncoding encoding, double gamma);

// The whole transform tonemap.frag applies: encodeDisplay(toneMap(mapper, radiance * 2^EV)).
glm::dvec3 displayTransform(
    const glm::dvec3& radiance, double exposureEV, ToneMapper mapper, DisplayEncoding encoding, double gamma);
inline glm::dvec3 displayTransform(const glm::dvec3& radiance, const ViewSettings& view)
{
    return displayTransform(radiance, view.exposureEV, view.toneMapper, view.displayEncoding, view.gamma);
}

} // namespace facet::tonemap
