// KHR_materials_anisotropy's microfacet terms (MATERIAL_ANISOTROPY), in the anisotropy frame (t
// along the direction, b = n x t, n): twin of core/shading/Anisotropy.h, whose header states the
// formulas (docs/shading.md, "Anisotropy").
#include "brdf_common.glsl"

// (alpha_t, alpha_b) = (mix(alpha, 1, strength^2), alpha): the roughness along and across t.
vec2 anisotropicAlpha(float perceptualRoughness, float strength)
{
    float alpha = alphaFromRoughness(perceptualRoughness);
    float s = saturate(strength);
    return vec2(mix(alpha, 1.0, s * s), alpha);
}

// D of the half vector h given in the frame. The form of the extension's sample implementation,
// a2 w2^2 / pi with f = (alpha_b h.t, alpha_t h.b, a2 h.n), which keeps a sharp lobe's peak
// within float range; the same number as core's D_GGXAnisotropic.
float D_GGXAnisotropic(vec3 h, vec2 alpha)
{
    if (h.z <= 0.0)
        return 0.0;
    float a2 = alpha.x * alpha.y;
    vec3 f = vec3(alpha.y * h.x, alpha.x * h.y, a2 * h.z);
    float w2 = a2 / max(dot(f, f), kMinDenominator);
    return a2 * w2 * w2 * INV_PI;
}

// Smith's height-correlated visibility of the anisotropic GGX, v and l in the frame.
float V_GGXAnisotropic(vec3 v, vec3 l, vec2 alpha)
{
    float NoV = max(v.z, 0.0);
    float NoL = max(l.z, 0.0);
    float lambdaV = NoL * length(vec3(alpha.x * v.x, alpha.y * v.y, NoV));
    float lambdaL = NoV * length(vec3(alpha.x * l.x, alpha.y * l.y, NoL));
    return 0.5 / max(lambdaV + lambdaL, kMinDenominator);
}

// Smith's G1 of the anisotropic GGX for w in the frame (w.z > 0): 1 / (1 + Lambda).
float G1_GGXAnisotropic(vec3 w, vec2 alpha)
{
    float z2 = max(w.z * w.z, kMinDenominator);
    float projected = alpha.x * alpha.x * w.x * w.x + alpha.y * alpha.y * w.y * w.y;
    return 2.0 / (1.0 + sqrt(1.0 + projected / z2));
}

// Where the anisotropic lobe's multiple-scattering compensation reads the isotropic table, and its
// weight: (perceptual roughness of alpha_v^2 = alpha_t^2 (t.v)^2 + alpha_b^2 (1 - (t.v)^2),
// (1 - s)^2), v in the frame. Twin of core's shading::anisotropicCompensation.
vec2 anisotropicCompensation(vec3 vLocal, float perceptualRoughness, float strength)
{
    vec2 alpha = anisotropicAlpha(perceptualRoughness, strength);
    float tv2 = min(vLocal.x * vLocal.x, 1.0);
    float alphaV = sqrt(alpha.x * alpha.x * tv2 + alpha.y * alpha.y * (1.0 - tv2));
    float fade = 1.0 - saturate(strength);
    return vec2(sqrt(alphaV), fade * fade);
}

// The anisotropy frame's tangent at n: the direction made perpendicular to n (Gram-Schmidt);
// vec3(0) where there is none (the lobe is then isotropic). Twin of core's anisotropyFrame.
vec3 anisotropyTangent(vec3 n, vec3 direction)
{
    vec3 inPlane = direction - n * dot(n, direction);
    float inPlaneLength = length(inPlane);
    return inPlaneLength > 1e-6 ? inPlane / inPlaneLength : vec3(0.0);
}
