// Geometry / visibility terms, V = G / (4 N.L N.V); twins of core/shading/Brdf.h.
#include "brdf_common.glsl"

// Height-correlated Smith-GGX [Heitz 2014, eq. 99], the glTF 2.0 specification's V.
float V_SmithGGXCorrelated(float NoV, float NoL, float alpha)
{
    float a2 = alpha * alpha;
    float lambdaV = NoL * sqrt(NoV * NoV * (1.0 - a2) + a2);
    float lambdaL = NoV * sqrt(NoL * NoL * (1.0 - a2) + a2);
    return 0.5 / max(lambdaV + lambdaL, kMinDenominator);
}

// Separable Smith-GGX with the exact G1 [Walter et al. 2007, eq. 34].
float V_SmithGGX(float NoV, float NoL, float alpha)
{
    float a2 = alpha * alpha;
    float gV = NoV + sqrt(a2 + (1.0 - a2) * NoV * NoV);
    float gL = NoL + sqrt(a2 + (1.0 - a2) * NoL * NoL);
    return 1.0 / max(gV * gL, kMinDenominator);
}

// Schlick-GGX G1 [Schlick 1994; Karis 2013].
float G_SchlickGGX(float NoX, float k) { return NoX / max(NoX * (1.0 - k) + k, kMinDenominator); }
// Karis 2013 remappings of k: (r + 1)^2 / 8 for punctual lights, alpha / 2 for IBL.
float k_SchlickGGX_direct(float perceptualRoughness)
{
    float r = clampRoughness(perceptualRoughness) + 1.0;
    return r * r / 8.0;
}
float k_SchlickGGX_ibl(float alpha) { return alpha / 2.0; }

// Separable Smith with Schlick-GGX G1, as a visibility.
float V_SmithSchlickGGX(float NoV, float NoL, float k)
{
    float gV = NoV * (1.0 - k) + k;
    float gL = NoL * (1.0 - k) + k;
    return 0.25 / max(gV * gL, kMinDenominator);
}
