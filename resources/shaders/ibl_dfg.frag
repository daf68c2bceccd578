// The split-sum DFG table on the GPU; twin of core/shading/DfgTable.cpp integrateDfg() (visible-normal
// sampling, Hammersley points). Texel (x, y) of an N x N target holds n.v = x / (N - 1) and
// perceptual roughness y / (N - 1) (core/shading/DfgTable.h), R = scale, G = bias, B = scale + bias,
// A = W(n.v), the share of a Lambertian base that glTF's fresnel_mix passes, over (1 - F0).
// DFG_VISIBILITY: 0 SmithGGXCorrelated (default), 1 SmithGGX, 2 SchlickGGX (k = alpha / 2); set by
// IblPrecompute::dfgTable from the Visibility it is asked for (one table per variant).
#include "common_sampling.glsl"
#include "brdf_visibility.glsl"

#ifndef DFG_VISIBILITY
#define DFG_VISIBILITY 0
#endif

uniform int uSize;
uniform int uSampleCount;
out vec4 fragColor;

void main()
{
    vec2 texel = floor(gl_FragCoord.xy);
    float denom = float(max(uSize - 1, 1));
    float NoV = clamp(texel.x / denom, 1e-6, 1.0);
    float alpha = alphaFromRoughness(texel.y / denom);
    vec3 v = vec3(sqrt(1.0 - NoV * NoV), 0.0, NoV);
    float k = k_SchlickGGX_ibl(alpha);
    float scale = 0.0;
    float bias = 0.0;
    float diffuse = 0.0;
    uint n = uint(max(uSampleCount, 1));
    for (uint i = 0u; i < n; ++i) {
        vec2 u = hammersley(i, n);
        // fresnel_mix's base: with pdf (n.l) / pi the estimator of 1/pi (1 - Fc(v.h)) (n.l) is
        // 1 - Fc. Every sample counts, the first point's l on the horizon too (v + l never vanishes).
        vec3 diffuseL = sampleCosineHemisphere(u);
        diffuse += 1.0 - pow5(1.0 - saturate(dot(v, normalize(v + diffuseL))));
        vec3 h = importanceSampleVNDF(u, v, alpha);
        vec3 l = reflectAbout(v, h);
        float NoL = l.z;
        if (NoL <= 0.0)
            continue;
        float VoH = saturate(dot(v, h));
#if DFG_VISIBILITY == 1
        float V = V_SmithGGX(NoV, NoL, alpha);
#elif DFG_VISIBILITY == 2
        float V = V_SmithSchlickGGX(NoV, NoL, k);
#else
        float V = V_SmithGGXCorrelated(NoV, NoL, alpha);
#endif
        // pdf_l = G1(v) D / (4 n.v): D V (n.l) / pdf_l = 4 V (n.v) (n.l) / G1(v) [Heitz 2018].
        float weight = 4.0 * V * NoV * NoL / G1_SmithGGX(NoV, alpha);
        float Fc = pow5(1.0 - VoH);
        scale += (1.0 - Fc) * weight;
        bias += Fc * weight;
    }
    scale /= float(n);
    bias /= float(n);
    fragColor = vec4(scale, bias, scale + bias, diffuse / float(n));
}
