// The material BRDF f(l, v): the brdf_*.glsl terms composed as the variant says. Twin of
// core/shading/MaterialBrdf.cpp's evaluate(), lobe by lobe, with the same selector names; the DFG LUT
// (uDfgLut, RGBA = scale, bias, E, W; core/shading/DfgTable.h) gives E for multi-scatter compensation.
#include "brdf_ggx.glsl"
#include "ibl_lookup.glsl"
#include "brdf_sheen.glsl"

uniform sampler2D uDfgLut;
uniform float uDfgSize;
// E_s,avg of the compensated dielectric layer for the material's constant roughness, from
// core's MaterialBrdf::dielectricSpecularAverageAlbedo (see docs/rendering.md).
uniform float uDielectricAverageAlbedo;

// The base's lobes carry the sheen's albedo scaling and the coat's 1 - clearcoatWeight; `sheen`
// is the sheen's own lobe (times the coat's 1 - w_c), `coat` the coat's (each zero without
// MATERIAL_SHEEN, MATERIAL_CLEARCOAT). Twin of core's BrdfLobes.
struct BrdfLobes {
    vec3 diffuse;
    vec3 specular;
    vec3 sheen;
    vec3 coat;
};

vec3 lobeTotal(BrdfLobes lobes) { return lobes.diffuse + lobes.specular + lobes.sheen + lobes.coat; }

// KHR_materials_clearcoat's fresnel_coat weight at the coat's n.v: clearcoat x F_Schlick(0.04,
// 1, n.v) (the coat's IOR is 1.5). Twin of core's clearcoatWeight.
float clearcoatWeight(MaterialInfo m, float NcoV)
{
    return m.clearcoat * F_Schlick(0.04, 1.0, saturate(NcoV));
}

// (scale, bias, E, W) at (n.v, roughness), roughness clamped as core's sample() callers do.
vec4 dfgLookup(float NoV, float perceptualRoughness)
{
    return texture(uDfgLut, dfgTexCoord(NoV, clampRoughness(perceptualRoughness), uDfgSize));
}

float distribution(float NoH, float alpha)
{
#ifdef DISTRIBUTION_BECKMANN
    return D_Beckmann(NoH, alpha);
#else
    return D_GGX(NoH, alpha);
#endif
}

float visibility(float NoV, float NoL, float alpha, float perceptualRoughness, bool punctual)
{
#if defined(VISIBILITY_SCHLICK)
    float k = punctual ? k_SchlickGGX_direct(perceptualRoughness) : k_SchlickGGX_ibl(alpha);
    return V_SmithSchlickGGX(NoV, NoL, k);
#elif defined(VISIBILITY_UNCORRELATED)
    return V_SmithGGX(NoV, NoL, alpha);
#else
    return V_SmithGGXCorrelated(NoV, NoL, alpha);
#endif
}

// 1 + f0 (1 - E) / E [Turquin 2019; Kulla & Conty 2017]; 1 without MULTI_SCATTER.
vec3 multiScatterFactor(vec3 f0, float NoV, float perceptualRoughness)
{
#ifdef MULTI_SCATTER
    float e = max(dfgLookup(NoV, perceptualRoughness).b, 1e-6);
    return vec3(1.0) + f0 * ((1.0 - e) / e);
#else
    return vec3(1.0);
#endif
}

// E_s(mu) = (f0 scale + bias) M(f0): what the dielectric specular layer reflects.
float dielectricSpecularAlbedo(float f0, float NoV, float perceptualRoughness)
{
    vec4 t = dfgLookup(NoV, perceptualRoughness);
    return (f0 * t.r + t.g) * multiScatterFactor(vec3(f0), NoV, perceptualRoughness).x;
}

// Kelemen & Szirmay-Kalos 2001: (1 - E_s(n.v)) (1 - E_s(n.l)) / (1 - E_s,avg).
float couplingFactor(float f0, float NoV, float NoL, float perceptualRoughness)
{
    float eo = dielectricSpecularAlbedo(f0, NoV, perceptualRoughness);
    float ei = dielectricSpecularAlbedo(f0, NoL, perceptualRoughness);
    return max(0.0, 1.0 - eo) * max(0.0, 1.0 - ei) / max(1.0 - uDielectricAverageAlbedo, 1e-6);
}

// The Fresnel of the composition at v.h (the F debug view).
vec3 compositionFresnel(MaterialInfo m, float VoH)
{
    float f0Dielectric = f0FromIor(m.ior);
#ifdef COMPOSITION_LEARNOPENGL
    return F_Schlick(mix(vec3(f0Dielectric), m.baseColor, m.metallic), 1.0, VoH);
#else
#ifdef FRESNEL_DIELECTRIC
    float fDielectric = F_Dielectric(VoH, m.ior);
#else
    float fDielectric = F_Schlick(f0Dielectric, 1.0, VoH);
#endif
    return mix(vec3(fDielectric), F_Schlick(m.baseColor, 1.0, VoH), m.metallic);
#endif
}

BrdfLobes evaluateBrdf(MaterialInfo m, vec3 n, vec3 v, vec3 l, bool punctual)
{
    BrdfLobes lobes;
    lobes.diffuse = vec3(0.0);
    lobes.specular = vec3(0.0);
    lobes.sheen = vec3(0.0);
    lobes.coat = vec3(0.0);
    float NoL = dot(n, l);
    float NoVraw = dot(n, v);
    if (NoL <= 0.0 || NoVraw < 0.0)
        return lobes;
    float NoV = min(NoVraw, 1.0);
    vec3 hSum = v + l;
    float hLength = length(hSum);
    vec3 h = hLength > 0.0 ? hSum / hLength : n;
    float NoH = saturate(dot(n, h));
    float VoH = saturate(dot(v, h));

    float roughness = clampRoughness(m.perceptualRoughness);
    float alpha = roughness * roughness;
    float metallic = saturate(m.metallic);
    vec3 baseColor = max(m.baseColor, vec3(0.0));
    float microfacet = distribution(NoH, alpha) * visibility(NoV, NoL, alpha, roughness, punctual);
    float f0Dielectric = f0FromIor(m.ior);
    vec3 lambert = baseColor * Fd_Lambert();

#ifdef COMPOSITION_LEARNOPENGL
    vec3 f0 = mix(vec3(f0Dielectric), baseColor, metallic);
    vec3 F = F_Schlick(f0, 1.0, VoH);
    lobes.specular = microfacet * F * multiScatterFactor(f0, NoV, roughness);
#ifdef COUPLING_ENERGY_PRESERVING
    vec3 kD = vec3(couplingFactor(f0Dielectric, NoV, NoL, roughness) * (1.0 - metallic));
#else
    vec3 kD = (vec3(1.0) - F) * (1.0 - metallic);
#endif
    lobes.diffuse = kD * lambert;
#else
#ifdef FRESNEL_DIELECTRIC
    float fDielectric = F_Dielectric(VoH, m.ior);
#else
    float fDielectric = F_Schlick(f0Dielectric, 1.0, VoH);
#endif
    vec3 fMetal = F_Schlick(baseColor, 1.0, VoH);
    vec3 msDielectric = multiScatterFactor(vec3(f0Dielectric), NoV, roughness);
    vec3 msMetal = multiScatterFactor(baseColor, NoV, roughness);
    vec3 dielectricSpecular = microfacet * fDielectric * msDielectric;
#ifdef COUPLING_ENERGY_PRESERVING
    vec3 dielectricDiffuse = lambert * couplingFactor(f0Dielectric, NoV, NoL, roughness);
#else
    vec3 dielectricDiffuse = lambert * (1.0 - fDielectric);
#endif
    lobes.diffuse = (1.0 - metallic) * dielectricDiffuse;
    lobes.specular = (1.0 - metallic) * dielectricSpecular + metallic * microfacet * fMetal * msMetal;
#endif
#ifdef MATERIAL_SHEEN
    // sheen_brdf + scaling x material, the scaling reciprocal (the min of its n.v and n.l terms);
    // no Fresnel in the lobe (docs/shading.md, "Sheen").
    float sheenScaling = sheenAlbedoScaling(m.sheenColor, m.sheenRoughness, NoV, NoL);
    lobes.diffuse *= sheenScaling;
    lobes.specular *= sheenScaling;
    float sheenAlpha = m.sheenRoughness * m.sheenRoughness;
    lobes.sheen = max(m.sheenColor, vec3(0.0)) * (D_Charlie(NoH, sheenAlpha) * V_Charlie(NoV, min(NoL, 1.0), sheenAlpha));
#endif
#ifdef MATERIAL_CLEARCOAT
    // mix(material, clearcoat_brdf, clearcoat x Fc(nc.v)): the coat a GGX lobe of its own
    // roughness about its own normal, with no Fresnel inside (docs/shading.md, "Clearcoat").
    vec3 nc = m.clearcoatNormal;
    float NcoL = dot(nc, l);
    float NcoV = saturate(dot(nc, v));
    float weight = clearcoatWeight(m, NcoV);
    lobes.diffuse *= 1.0 - weight;
    lobes.specular *= 1.0 - weight;
    lobes.sheen *= 1.0 - weight; // the coat lies over the sheen
    if (NcoL > 0.0) {
        float coatRoughness = clampRoughness(m.clearcoatRoughness);
        float coatAlpha = coatRoughness * coatRoughness;
        lobes.coat = vec3(weight * distribution(saturate(dot(nc, h)), coatAlpha)
                          * visibility(NcoV, NcoL, coatAlpha, coatRoughness, punctual));
    }
#endif
    return lobes;
}
