// The material BRDF f(l, v): the brdf_*.glsl terms composed as the variant says. Twin of
// core/shading/MaterialBrdf.cpp's evaluate(), lobe by lobe, with the same selector names; the DFG LUT
// (uDfgLut, RGBA = scale, bias, E, W; core/shading/DfgTable.h) gives E for multi-scatter compensation.
#include "brdf_ggx.glsl"
#include "ibl_lookup.glsl"
#include "brdf_sheen.glsl"
#include "brdf_anisotropy.glsl"
#include "brdf_iridescence.glsl"

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

// 1 + f0 (1 - E) / E [Turquin 2019; Kulla & Conty 2017], the added part times `weight` (an
// anisotropic lobe's fade); 1 without MULTI_SCATTER.
vec3 multiScatterFactor(vec3 f0, float NoV, float perceptualRoughness, float weight)
{
#ifdef MULTI_SCATTER
    float e = max(dfgLookup(NoV, perceptualRoughness).b, 1e-6);
    return vec3(1.0) + f0 * (weight * (1.0 - e) / e);
#else
    return vec3(1.0);
#endif
}
vec3 multiScatterFactor(vec3 f0, float NoV, float perceptualRoughness)
{
    return multiScatterFactor(f0, NoV, perceptualRoughness, 1.0);
}

// The base's specular lobe's compensation, (roughness, weight): the isotropic lobe's (r, 1), or
// (MATERIAL_ANISOTROPY, v in the lobe's frame: (t.v, b.v, n.v), not zero) the anisotropic lobe's.
vec2 specularCompensation(MaterialInfo m, vec3 anisotropyV)
{
#ifdef MATERIAL_ANISOTROPY
    if (anisotropyV != vec3(0.0))
        return anisotropicCompensation(anisotropyV, m.perceptualRoughness, m.anisotropy);
#endif
    return vec2(clampRoughness(m.perceptualRoughness), 1.0);
}

// E_s(mu) = (f0 scale + f90 bias) M(f0): what the dielectric specular layer reflects.
float dielectricSpecularAlbedo(float f0, float f90, float NoV, float perceptualRoughness)
{
    vec4 t = dfgLookup(NoV, perceptualRoughness);
    return (f0 * t.r + f90 * t.g) * multiScatterFactor(vec3(f0), NoV, perceptualRoughness).x;
}

// The dielectric layer's Schlick reflectance at normal and grazing incidence; with
// KHR_materials_specular (MATERIAL_SPECULAR) f0 = min(F0(n) specularColor, 1) specular and
// f90 = specular, else (F0(n), 1). Twin of core's DielectricReflectance.
struct DielectricReflectance {
    vec3 f0;
    float f90;
};

DielectricReflectance dielectricReflectance(MaterialInfo m)
{
    DielectricReflectance layer;
#ifdef MATERIAL_SPECULAR
    float specular = saturate(m.specular);
    layer.f0 = min(f0FromIor(m.ior) * max(m.specularColor, vec3(0.0)), vec3(1.0)) * specular;
    layer.f90 = specular;
#else
    layer.f0 = vec3(f0FromIor(m.ior));
    layer.f90 = 1.0;
#endif
    return layer;
}

// The layer's Fresnel at v.h: Schlick from f0 to f90, or (FRESNEL_DIELECTRIC) the exact curve
// shifted by the tint's change of F0 and scaled by the strength. Twin of core's
// MaterialBrdf::dielectricFresnel.
vec3 dielectricFresnel(MaterialInfo m, DielectricReflectance layer, float VoH)
{
#ifdef FRESNEL_DIELECTRIC
#ifdef MATERIAL_SPECULAR
    float f0 = f0FromIor(m.ior);
    vec3 tinted = layer.f90 > 0.0 ? layer.f0 / layer.f90 : vec3(f0);
    float weight = 1.0 - pow5(1.0 - saturate(VoH));
    return saturate(layer.f90 * (vec3(F_Dielectric(VoH, m.ior)) + (tinted - f0) * weight));
#else
    return vec3(F_Dielectric(VoH, m.ior));
#endif
#else
    return F_Schlick(layer.f0, layer.f90, VoH);
#endif
}

// Kelemen & Szirmay-Kalos 2001: (1 - E_s(n.v)) (1 - E_s(n.l)) / (1 - E_s,avg), a tinted layer
// through its largest channel; E_s,avg the layer's average albedo (uDielectricAverageAlbedo for the
// material's own layer).
float couplingFactor(DielectricReflectance layer, float NoV, float NoL, float perceptualRoughness, float averageAlbedo)
{
    float f0 = max3(layer.f0);
    float eo = dielectricSpecularAlbedo(f0, layer.f90, NoV, perceptualRoughness);
    float ei = dielectricSpecularAlbedo(f0, layer.f90, NoL, perceptualRoughness);
    return max(0.0, 1.0 - eo) * max(0.0, 1.0 - ei) / max(1.0 - averageAlbedo, 1e-6);
}
float couplingFactor(DielectricReflectance layer, float NoV, float NoL, float perceptualRoughness)
{
    return couplingFactor(layer, NoV, NoL, perceptualRoughness, uDielectricAverageAlbedo);
}

// KHR_materials_iridescence: the film's Fresnel over a base of reflectance f0 at cos(theta1),
// clamped to [0, 1] (docs/shading.md, "Iridescence"). Twin of core's filmFresnel in
// MaterialBrdf::evaluate.
vec3 filmFresnel(MaterialInfo m, vec3 f0, float cosTheta)
{
    return saturate(iridescenceFresnel(m.iridescenceIor, f0, m.iridescenceThickness, cosTheta));
}

#ifdef MATERIAL_IRIDESCENCE
// E_s,avg of the film's Schlick layer (filmLayer) at the material's constant values (its roughness,
// its thickness without a texture): the energy-preserving coupling's (render/SceneFromProject).
uniform float uFilmAverageAlbedo;
#endif

// The Schlick layer the energy-preserving coupling takes the film for: F0 the smallest whose curve
// lies on or above the film's Fresnel (largest channel) at 11 angles, F90 1. Twin of core's
// filmLayer (kFilmLayerAngles).
DielectricReflectance filmLayer(MaterialInfo m, vec3 f0)
{
    const float angles[11] = float[11](1.0, 0.9, 0.8, 0.7, 0.6, 0.5, 0.4, 0.3, 0.2, 0.1, 0.05);
    float envelope = 0.0;
    for (int i = 0; i < 11; ++i) {
        float weight = pow5(1.0 - angles[i]);
        envelope = max(envelope, (max3(filmFresnel(m, f0, angles[i])) - weight) / (1.0 - weight));
    }
    DielectricReflectance layer;
    layer.f0 = vec3(saturate(envelope));
    layer.f90 = 1.0;
    return layer;
}

// filmLayer as surface.frag set it once per pixel (MaterialInfo::filmLayerF0).
DielectricReflectance filmSchlickLayer(MaterialInfo m)
{
    DielectricReflectance layer;
    layer.f0 = vec3(m.filmLayerF0);
    layer.f90 = 1.0;
    return layer;
}

// The Fresnel of the composition at v.h (the F debug view), the film's mixed in.
vec3 compositionFresnel(MaterialInfo m, float VoH)
{
    DielectricReflectance layer = dielectricReflectance(m);
#ifdef COMPOSITION_LEARNOPENGL
    vec3 f0 = mix(layer.f0, m.baseColor, m.metallic);
    vec3 F = F_Schlick(f0, mix(layer.f90, 1.0, m.metallic), VoH);
#ifdef MATERIAL_IRIDESCENCE
    F = mix(F, filmFresnel(m, f0, VoH), m.iridescence);
#endif
    return F;
#else
    vec3 fDielectric = dielectricFresnel(m, layer, VoH);
    vec3 fMetal = F_Schlick(m.baseColor, 1.0, VoH);
#ifdef MATERIAL_IRIDESCENCE
    fDielectric = mix(fDielectric, filmFresnel(m, layer.f0, VoH), m.iridescence);
    fMetal = mix(fMetal, filmFresnel(m, m.baseColor, VoH), m.iridescence);
#endif
    return mix(fDielectric, fMetal, m.metallic);
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
    vec3 anisotropyV = vec3(0.0); // v in the lobe's (t, b, n) frame; zero: isotropic
#ifdef MATERIAL_ANISOTROPY
    // The base's specular lobes (dielectric and metal) take the extension's anisotropic D and V,
    // whatever the model's pair, and a compensation of their own (docs/shading.md, "Anisotropy");
    // without a frame, the isotropic lobe.
    vec3 anisotropyT = m.anisotropy > 0.0 ? anisotropyTangent(n, m.anisotropyDirection) : vec3(0.0);
    if (anisotropyT != vec3(0.0)) {
        vec3 anisotropyB = cross(n, anisotropyT);
        vec2 anisotropyAlpha = anisotropicAlpha(m.perceptualRoughness, m.anisotropy);
        anisotropyV = vec3(dot(anisotropyT, v), dot(anisotropyB, v), NoV);
        microfacet = D_GGXAnisotropic(vec3(dot(anisotropyT, h), dot(anisotropyB, h), NoH), anisotropyAlpha)
            * V_GGXAnisotropic(anisotropyV, vec3(dot(anisotropyT, l), dot(anisotropyB, l), NoL), anisotropyAlpha);
    }
#endif
    vec2 compensation = specularCompensation(m, anisotropyV);
    DielectricReflectance layer = dielectricReflectance(m);
    vec3 lambert = baseColor * Fd_Lambert();

#ifdef COMPOSITION_LEARNOPENGL
    vec3 f0 = mix(layer.f0, baseColor, metallic);
    vec3 F = F_Schlick(f0, mix(layer.f90, 1.0, metallic), VoH);
#ifdef MATERIAL_IRIDESCENCE
    if (m.iridescence > 0.0)
        F = mix(F, filmFresnel(m, f0, VoH), m.iridescence);
#endif
    lobes.specular = microfacet * F * multiScatterFactor(f0, NoV, compensation.x, compensation.y);
#ifdef COUPLING_ENERGY_PRESERVING
    vec3 kD = vec3(couplingFactor(layer, NoV, NoL, roughness) * (1.0 - metallic));
#else
    vec3 kD = (vec3(1.0) - F) * (1.0 - metallic);
#endif
    lobes.diffuse = kD * lambert;
#else
    vec3 fDielectric = dielectricFresnel(m, layer, VoH);
    vec3 fMetal = F_Schlick(baseColor, 1.0, VoH);
    vec3 msDielectric = multiScatterFactor(layer.f0, NoV, compensation.x, compensation.y);
    vec3 msMetal = multiScatterFactor(baseColor, NoV, compensation.x, compensation.y);
#ifdef COUPLING_ENERGY_PRESERVING
    float diffuseWeight = couplingFactor(layer, NoV, NoL, roughness);
#else
    // The base keeps 1 - max_value(F(v.h)) (KHR_materials_specular; 1 - F without a tint).
    float diffuseWeight = 1.0 - max3(fDielectric);
#endif
#ifdef MATERIAL_IRIDESCENCE
    // mix(fresnel_mix(...), rgb_mix(diffuse, specular, Firid(f0)), iridescence) for the dielectric,
    // specular mix(F(baseColor), Firid(baseColor), iridescence) for the metal, the film seen at v.h.
    if (m.iridescence > 0.0) {
        if (metallic < 1.0) {
            vec3 firid = filmFresnel(m, layer.f0, VoH);
            // The energy-preserving coupling couples the base to the film's Schlick layer.
#ifdef COUPLING_ENERGY_PRESERVING
            float filmWeight = couplingFactor(filmSchlickLayer(m), NoV, NoL, roughness, uFilmAverageAlbedo);
#else
            float filmWeight = 1.0 - max3(firid);
#endif
            diffuseWeight = mix(diffuseWeight, filmWeight, m.iridescence);
            fDielectric = mix(fDielectric, firid, m.iridescence);
        }
        if (metallic > 0.0)
            fMetal = mix(fMetal, filmFresnel(m, baseColor, VoH), m.iridescence);
    }
#endif
    lobes.diffuse = (1.0 - metallic) * lambert * diffuseWeight;
    lobes.specular = (1.0 - metallic) * microfacet * fDielectric * msDielectric + metallic * microfacet * fMetal * msMetal;
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
