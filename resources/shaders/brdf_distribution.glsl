// Normal distribution functions; twins of core/shading/Brdf.h.
#include "brdf_common.glsl"

// GGX / Trowbridge-Reitz [Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces"].
float D_GGX(float NoH, float alpha)
{
    float a2 = alpha * alpha;
    float f = NoH * NoH * (a2 - 1.0) + 1.0;
    return a2 * INV_PI / max(f * f, kMinDenominator);
}

// Beckmann [Beckmann & Spizzichino 1963], Walter et al. 2007 eq. 25.
float D_Beckmann(float NoH, float alpha)
{
    if (NoH <= 0.0)
        return 0.0;
    float a2 = alpha * alpha;
    float cos2 = NoH * NoH;
    float tan2 = (1.0 - cos2) / cos2;
    return exp(-tan2 / a2) * INV_PI / (a2 * cos2 * cos2);
}
