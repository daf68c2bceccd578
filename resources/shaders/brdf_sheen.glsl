// KHR_materials_sheen's terms (MATERIAL_SHEEN): the Charlie distribution, its fitted visibility and
// the lobe's directional albedo E(n.v, r) from the shipped table (uSheenLut). Twins of
// core/shading/Sheen.h (D_Charlie, lambdaSheen, V_Charlie, sheenAlbedoTable, sheenAlbedoScaling);
// docs/shading.md, "Sheen", has the formulas.
#include "brdf_common.glsl"
#include "ibl_lookup.glsl"

// R = E(n.v, r), G = Emax(n.v, r); x = n.v, y = sheen roughness (core sheenAlbedoTable).
uniform sampler2D uSheenLut;
uniform float uSheenLutSize;

// Smallest sheen alpha: the distribution is singular at roughness 0 (core kMinSheenAlpha).
const float kMinSheenAlpha = 1e-12;

float D_Charlie(float NoH, float sheenAlpha)
{
    float a = max(sheenAlpha, kMinSheenAlpha);
    float sin2 = max(1.0 - NoH * NoH, 0.0);
    return (2.0 + 1.0 / a) * pow(sin2, 0.5 / a) / (2.0 * PI);
}

// The fit l(x) of the extension's sheen visibility, interpolated in (1 - a)^2.
float sheenFitL(float x, float sheenAlpha)
{
    float t = (1.0 - sheenAlpha) * (1.0 - sheenAlpha);
    float a = mix(21.5473, 25.3245, t);
    float b = mix(3.82987, 3.32435, t);
    float c = mix(0.19823, 0.16801, t);
    float d = mix(-1.97760, -1.27393, t);
    float e = mix(-4.32054, -4.85967, t);
    return a / (1.0 + b * pow(x, c)) + d * x + e;
}

float lambdaSheen(float cosTheta, float sheenAlpha)
{
    float a = clamp(sheenAlpha, kMinSheenAlpha, 1.0);
    float c = abs(cosTheta);
    return c < 0.5 ? exp(sheenFitL(c, a)) : exp(2.0 * sheenFitL(0.5, a) - sheenFitL(1.0 - c, a));
}

float V_Charlie(float NoV, float NoL, float sheenAlpha)
{
    float denominator = (1.0 + lambdaSheen(NoV, sheenAlpha) + lambdaSheen(NoL, sheenAlpha)) * 4.0 * NoV * NoL;
    return 1.0 / max(denominator, kMinDenominator);
}

// E(n.v, r): the sheen lobe's albedo with colour 1.
float sheenAlbedo(float NoV, float sheenRoughness)
{
    return texture(uSheenLut, dfgTexCoord(NoV, sheenRoughness, uSheenLutSize)).r;
}
// E(n.v, r) and Emax(n.v, r) in one fetch.
vec2 sheenAlbedos(float NoV, float sheenRoughness)
{
    return texture(uSheenLut, dfgTexCoord(NoV, sheenRoughness, uSheenLutSize)).rg;
}

// The scaling of the base's image-based lobes (the split sum's and fis's), 1 - max3(c) e: the
// specular lobe's light arrives near the mirror direction, where n.l ~ n.v, so it keeps
// 1 - max3(c) E(n.v) (e = sheenAlbedos().r); the diffuse lobe's arrives from the whole hemisphere,
// and keeps its cosine-weighted mean of the reciprocal scaling, 1 - max3(c) Emax(n.v) (e =
// sheenAlbedos().g; core SheenAlbedoTable::sampleDiffuse).
float sheenScaling(vec3 sheenColor, float e)
{
    return max(1.0 - max(max3(sheenColor), 0.0) * e, 0.0);
}

// What the material under the sheen keeps towards v from l: min(1 - max3(c) E(n.v), 1 - max3(c)
// E(n.l)), the extension's reciprocal form; 1 without a sheen.
float sheenAlbedoScaling(vec3 sheenColor, float sheenRoughness, float NoV, float NoL)
{
    float strength = max(max3(sheenColor), 0.0);
    if (strength <= 0.0)
        return 1.0;
    float e = max(sheenAlbedo(NoV, sheenRoughness), sheenAlbedo(NoL, sheenRoughness));
    return max(1.0 - strength * e, 0.0);
}
