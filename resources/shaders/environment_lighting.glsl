// Image-based lighting. environmentLobes() dispatches on the IBL method's variant bit
// (render/ShaderVariant.h): IBL_REFERENCE integrates by Monte Carlo (ibl_reference.glsl), IBL_FIS
// by filtered importance sampling of the pixel's lobe (ibl_fis.glsl); otherwise the split sum [Karis 2013] (its lobes
// sharper than the prefiltered level 1 integrated by a few fis samples, below), from the textures of render/IblTextures
// (prefiltered specular cubemap, irradiance cubemap storing E or 9 premultiplied SH
// coefficients, DFG LUT). Twin: core/shading/SplitSum.h splitSumRadiance(); docs/rendering.md gives the
// formulas. Lookups turn world directions into the environment image's frame
// (Environment::toImageFrame: R_y(-rotation)), and radiance is multiplied by the intensity.
#include "ibl_lookup.glsl"
#include "debug_views.glsl"
#include "environment_frame.glsl"
#include "common_sampling.glsl"

uniform samplerCube uPrefilteredMap;
uniform float uPrefilteredLevels;
#ifdef IRRADIANCE_SH
uniform vec3 uIrradianceSH[9]; // c_i * A_l of the UNROTATED environment (core irradianceSHCoefficients)
#else
uniform samplerCube uIrradianceMap; // irradiance E (not / pi)
#endif

vec3 toEnvironmentFrame(vec3 d) { return uEnvironmentRotation * d; }

// Radiance prefiltered for perceptual roughness r around direction R.
vec3 prefilteredRadiance(vec3 R, float perceptualRoughness)
{
#if DEBUG_VIEW == DEBUG_WHITE_FURNACE
    return vec3(1.0); // white furnace: uniform radiance 1
#else
    float lod = lodFromRoughness(perceptualRoughness, uPrefilteredLevels);
    return textureLod(uPrefilteredMap, toEnvironmentFrame(R), lod).rgb * uEnvironmentIntensity;
#endif
}

#ifdef IRRADIANCE_SH
// Twin of core/ibl/SphericalHarmonics.h irradianceSH(const IrradianceSH9&, n).
vec3 irradianceSH(vec3 n)
{
    vec3 e = uIrradianceSH[0] * 0.282094791773878
           + uIrradianceSH[1] * (0.488602511902920 * n.y)
           + uIrradianceSH[2] * (0.488602511902920 * n.z)
           + uIrradianceSH[3] * (0.488602511902920 * n.x)
           + uIrradianceSH[4] * (1.092548430592079 * n.x * n.y)
           + uIrradianceSH[5] * (1.092548430592079 * n.y * n.z)
           + uIrradianceSH[6] * (0.315391565252520 * (3.0 * n.z * n.z - 1.0))
           + uIrradianceSH[7] * (1.092548430592079 * n.x * n.z)
           + uIrradianceSH[8] * (0.546274215296040 * (n.x * n.x - n.y * n.y));
    return max(e, vec3(0.0));
}
#endif

// Irradiance E(n) (radiance times steradians; a uniform environment L gives pi L).
vec3 irradiance(vec3 n)
{
#if DEBUG_VIEW == DEBUG_WHITE_FURNACE
    return vec3(PI);
#elif defined(IRRADIANCE_SH)
    return irradianceSH(toEnvironmentFrame(n)) * uEnvironmentIntensity;
#else
    return texture(uIrradianceMap, toEnvironmentFrame(n)).rgb * uEnvironmentIntensity;
#endif
}

// KHR_materials_iridescence under the split sum (docs/shading.md, "Iridescence"): the film's Fresnel
// averaged over a lobe with kSplitSumFilmSamples fixed points, not taken at n.v alone (its swings
// with the angle made that up to 47% wrong under uniform light). Twins of core/shading/SplitSum.h
// filmLobeFresnel and filmDiffuseFresnel, point for point.
const uint kSplitSumFilmSamples = 8u;

// Over the base's specular lobe: sum Firid(v.h_i) w_i / sum w_i, w_i = G2(v, l_i) / G1(v), h_i the
// lobe's visible normals from Hammersley points, in a frame where v lies in the xz plane.
vec3 filmLobeFresnel(MaterialInfo m, vec3 f0, float NoV, float perceptualRoughness)
{
    NoV = clamp(NoV, 1e-4, 1.0);
    float alpha = alphaFromRoughness(perceptualRoughness);
    vec3 v = vec3(sqrt(1.0 - NoV * NoV), 0.0, NoV);
    float lambdaV = 1.0 / G1_SmithGGX(NoV, alpha) - 1.0;
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    for (uint i = 0u; i < kSplitSumFilmSamples; ++i) {
        vec3 h = importanceSampleVNDF(hammersley(i, kSplitSumFilmSamples), v, alpha);
        vec3 l = reflectAbout(v, h);
        if (l.z <= 0.0)
            continue;
        float lambdaL = 1.0 / G1_SmithGGX(l.z, alpha) - 1.0;
        float weight = (1.0 + lambdaV) / (1.0 + lambdaV + lambdaL);
        sum += weight * filmFresnel(m, f0, dot(v, h));
        weights += weight;
    }
    return weights > 0.0 ? sum / weights : filmFresnel(m, f0, NoV);
}

// Over the cosine lobe of l (h = normalize(v + l)): per channel, and (w) its largest channel's mean.
vec4 filmDiffuseFresnel(MaterialInfo m, vec3 f0, float NoV)
{
    NoV = clamp(NoV, 1e-4, 1.0);
    vec3 v = vec3(sqrt(1.0 - NoV * NoV), 0.0, NoV);
    vec4 sum = vec4(0.0);
    for (uint i = 0u; i < kSplitSumFilmSamples; ++i) {
        vec3 l = sampleCosineHemisphere(hammersley(i, kSplitSumFilmSamples));
        vec3 firid = filmFresnel(m, f0, dot(v, normalize(v + l)));
        sum += vec4(firid, max3(firid));
    }
    return sum / float(kSplitSumFilmSamples);
}

// The diffuse lobe's albedo c w_d under uniform light of radiance 1, per composition (what the
// irradiance E(n) / pi is multiplied by), with the dielectric layer's (F0_d, F90_d)
// (dielectricReflectance: (F0(n), 1) without KHR_materials_specular):
// glTF:  w_d = (1 - m) ((1 - F90_d) + (F90_d - max F0_d) W(n.v)) for fresnel_mix (the albedo of
//        its base c / pi (1 - max_value(F(v.h))): the ground truth's model; (1 - F0_d) W without
//        the extension), (1 - m) (1 - E_s(n.v)) for the energy-preserving coupling.
// LearnOpenGL: w_d = ((1 - F90) + (F90 - F0) W(n.v)) (1 - m) with F0 = mix(F0_d, c, m), F90 =
//        mix(F90_d, 1, m) (kD = (1 - F(v.h)) (1 - m) per direction), or (1 - E_s(n.v)) (1 - m).
// W(n.v) is the DFG table's alpha (core/shading/DfgTable.h). Twin: core/shading/SplitSum.cpp.
vec3 environmentDiffuseAlbedo(MaterialInfo m, float NoV, float roughness)
{
    float metallic = saturate(m.metallic);
    vec3 baseColor = max(m.baseColor, vec3(0.0));
    DielectricReflectance layer = dielectricReflectance(m);
#ifdef COUPLING_ENERGY_PRESERVING
    vec3 weight = vec3(max(0.0, 1.0 - dielectricSpecularAlbedo(max3(layer.f0), layer.f90, NoV, roughness)));
#elif defined(COMPOSITION_LEARNOPENGL)
    float f90 = mix(layer.f90, 1.0, metallic);
    vec3 weight = (1.0 - f90) + (f90 - mix(layer.f0, baseColor, metallic)) * dfgLookup(NoV, roughness).a;
#else
    vec3 weight = vec3((1.0 - layer.f90) + (layer.f90 - max3(layer.f0)) * dfgLookup(NoV, roughness).a);
#endif
#ifdef MATERIAL_IRIDESCENCE
    // KHR_materials_iridescence: in the film's share the base keeps what the film leaves, averaged
    // over the cosine lobe (glTF: 1 - max_value(Firid); LearnOpenGL: 1 - Firid), or (energy-
    // preserving) 1 - E_s of the film's Schlick layer (docs/shading.md, "Iridescence"). A metal has
    // no diffuse lobe to weigh.
    if (m.iridescence > 0.0 && metallic < 1.0) {
#if defined(COUPLING_ENERGY_PRESERVING)
#ifndef COMPOSITION_LEARNOPENGL
        DielectricReflectance film = filmSchlickLayer(m);
        weight = mix(weight, vec3(max(0.0, 1.0 - dielectricSpecularAlbedo(max3(film.f0), film.f90, NoV, roughness))),
                     m.iridescence);
#endif
#elif defined(COMPOSITION_LEARNOPENGL)
        weight = mix(weight, vec3(1.0) - filmDiffuseFresnel(m, mix(layer.f0, baseColor, metallic), NoV).rgb,
                     m.iridescence);
#else
        weight = mix(weight, vec3(1.0 - filmDiffuseFresnel(m, layer.f0, NoV).a), m.iridescence);
#endif
    }
#endif
    return baseColor * weight * (1.0 - metallic);
}

// A normal-mapped (or interpolated) normal can face away from the viewer, n.v < 0, where the
// sampled methods' integrand is zero (evaluateBrdf: nothing is seen from below the surface): black
// specks along a normal-mapped mesh's silhouettes. They shade with n bent towards v until n.v =
// 1e-3 instead (the usual clamp of real-time renderers; the split sum clamps n.v itself). The
// analytic sphere of the reference view always has n.v > 0, so the ground truth's rule holds there.
vec3 facingNormal(vec3 n, vec3 v)
{
    const float minNoV = 1e-3;
    float NoV = dot(n, v);
    return NoV >= minNoV ? n : normalize(n + v * (minNoV - NoV));
}

// The methods' shared chunks, outside the #ifdefs: includes are expanded once, before the
// preprocessor runs (render/ShaderProgram), so a chunk first included inside a disabled block
// would be missing from the enabled one (common_sampling.glsl is at the top: the film's averages
// below need it). Unused functions and samplers cost nothing.
#include "environment_sampling.glsl"
#include "ibl_filtering.glsl"

uniform int uIblSampleBase; // the sampled methods' draw: samples [base, base + samples)
uniform int uIblSamples;
uniform samplerCube uEnvironmentMap; // the environment cube with its full box-filtered mip chain
uniform float uEnvironmentSize;      // its level-0 face size
uniform float uEnvironmentMaxLod;    // its last level
uniform int uEnvironmentSourceBound; // 0: no source equirect bound (fis reads the cube's levels only)
uniform int uSharpLobeSamples;       // SPLIT_SUM_SHARP_LOBES: the split sum's sharp lobes' fis samples
#include "ibl_fis.glsl"

// The split sum's light of one microfacet lobe of perceptual roughness r about its own normal n (the
// shading normal, or the clear coat's): the prefiltered radiance at the lobe's dominant direction.
// The lobe's albedo (the DFG table's scale and bias with its Fresnel) is the caller's.
vec3 splitSumLobeRadiance(vec3 n, vec3 v, float roughness)
{
    return prefilteredRadiance(specularDominantDirection(n, reflect(-v, n), roughness * roughness), roughness);
}

uniform int uSheenSamples; // MATERIAL_SHEEN under the split sum: the sheen lobe's fis samples
uniform int uAnisotropySamples; // MATERIAL_ANISOTROPY under the split sum: the stretched lobe's fis samples

// Lobes sharper than level 1: the prefiltered map's level 0 is the environment resampled into a
// small cube, and a mirror-like lobe read there is blurred and shifted by that resampling (20% at
// roughness 0.05 on forest). Those pixels integrate their own lobe instead, by a few filtered
// importance samples of the environment cube (fisLobe, the fis estimator), faded in over lod 1 to
// 0.5 so that a roughness map shows no seam. `splitSum` is the lobe's split-sum light with its
// weights (fisLobe's samples carry the same: evaluateBrdf's). render/RenderScene.h
// kSplitSumSharpLobeSamples; the variant only for materials with a lobe below level 1
// (render/Renderer.cpp splitSumSharpLobes).
vec3 withSharpLobe(vec3 splitSum, MaterialInfo m, vec3 n, vec3 v, int lobe, float roughness)
{
#ifdef SPLIT_SUM_SHARP_LOBES
    float sharp = 1.0 - smoothstep(0.5, 1.0, lodFromRoughness(roughness, uPrefilteredLevels));
    if (sharp > 0.0)
        return mix(splitSum, fisLobe(m, facingNormal(n, v), v, lobe, 0, uSharpLobeSamples, uint(uSharpLobeSamples)),
                   sharp);
#endif
    return splitSum;
}

// The split-sum lobes for the view direction v (unit, towards the viewer) at normal n:
//   specular = prefiltered(R, lod(r)) * (F0 scale + F90 bias) * M(F0)         (per lobe F0, F90)
//   diffuse  = E(n) / pi * environmentDiffuseAlbedo
//   coat     = prefiltered(R_c, lod(r_c)) * (scale_c + bias_c) * w_c, the others times 1 - w_c
// glTF:  specular = (1 - m) spec(F0_d) + m spec(c);  LearnOpenGL: F0 = mix(F0_d, c, m), spec(F0).
BrdfLobes splitSumEnvironmentLobes(MaterialInfo m, vec3 n, vec3 v)
{
    BrdfLobes lobes;
    float NoV = clamp(dot(n, v), 0.0, 1.0);
    float roughness = clampRoughness(m.perceptualRoughness);
    float metallic = saturate(m.metallic);
    vec3 baseColor = max(m.baseColor, vec3(0.0));
    vec4 dfg = dfgLookup(NoV, roughness);
    DielectricReflectance layer = dielectricReflectance(m);
    lobes.specular = vec3(0.0);
#ifdef MATERIAL_ANISOTROPY
    // A stretched lobe is integrated at the end (below): the isotropic one is not computed.
    bool stretched = m.anisotropy > 0.0 && anisotropyTangent(n, m.anisotropyDirection) != vec3(0.0);
    if (!stretched) {
#endif
    vec3 radiance = splitSumLobeRadiance(n, v, roughness);
    // KHR_materials_iridescence: the film's Fresnel averaged over the lobe times the lobe's albedo
    // with F = 1, mixed in by its strength (docs/shading.md, "Iridescence").
#ifdef COMPOSITION_LEARNOPENGL
    vec3 f0 = mix(layer.f0, baseColor, metallic);
    vec3 ms = multiScatterFactor(f0, NoV, roughness);
    vec3 specular = (f0 * dfg.r + mix(layer.f90, 1.0, metallic) * dfg.g) * ms;
#ifdef MATERIAL_IRIDESCENCE
    if (m.iridescence > 0.0)
        specular = mix(specular, filmLobeFresnel(m, f0, NoV, roughness) * (dfg.r + dfg.g) * ms, m.iridescence);
#endif
    lobes.specular = radiance * specular;
#else
    vec3 msDielectric = multiScatterFactor(layer.f0, NoV, roughness);
    vec3 msMetal = multiScatterFactor(baseColor, NoV, roughness);
    vec3 specularDielectric = (layer.f0 * dfg.r + layer.f90 * dfg.g) * msDielectric;
    vec3 specularMetal = (baseColor * dfg.r + dfg.g) * msMetal;
#ifdef MATERIAL_IRIDESCENCE
    if (m.iridescence > 0.0) {
        if (metallic < 1.0)
            specularDielectric = mix(specularDielectric,
                                     filmLobeFresnel(m, layer.f0, NoV, roughness) * (dfg.r + dfg.g) * msDielectric,
                                     m.iridescence);
        if (metallic > 0.0)
            specularMetal = mix(specularMetal, filmLobeFresnel(m, baseColor, NoV, roughness) * (dfg.r + dfg.g) * msMetal,
                                m.iridescence);
    }
#endif
    lobes.specular = radiance * mix(specularDielectric, specularMetal, metallic);
#endif
#ifdef MATERIAL_ANISOTROPY
    }
#endif
    lobes.diffuse = irradiance(n) * INV_PI * environmentDiffuseAlbedo(m, NoV, roughness);
    lobes.sheen = vec3(0.0);
#ifdef MATERIAL_SHEEN
    // The sheen: its albedo E(n.v, r_s) times its lobe's light; the base keeps its lobes' mean
    // scaling (docs/shading.md, "Sheen"). The Charlie lobe gathers light near the horizon of n
    // for every view, a ring no prefiltered lookup about one direction resembles (for the sheen
    // alone on studio the GGX map at R measured 145% relative RMSE, the irradiance 59%), so its
    // light is a few filtered samples of the environment cube, averaged with the lobe's weights.
    vec2 sheenE = sheenAlbedos(NoV, m.sheenRoughness); // E and Emax: one fetch
    lobes.diffuse *= sheenScaling(m.sheenColor, sheenE.g);
    lobes.specular *= sheenScaling(m.sheenColor, sheenE.r);
    lobes.sheen = m.sheenColor * sheenE.r * sheenLobeRadiance(m, facingNormal(n, v), v, uSheenSamples);
#endif
    lobes.coat = vec3(0.0);
#ifdef MATERIAL_CLEARCOAT
    // The coat: its prefiltered light times its lobe's albedo with F = 1 (the DFG table's scale +
    // bias), weighted by w_c; the base keeps 1 - w_c.
    vec3 nc = m.clearcoatNormal;
    float NcoV = clamp(dot(nc, v), 0.0, 1.0);
    float coatRoughness = clampRoughness(m.clearcoatRoughness);
    float coatWeight = clearcoatWeight(m, NcoV);
    lobes.diffuse *= 1.0 - coatWeight;
    lobes.specular *= 1.0 - coatWeight;
    lobes.sheen *= 1.0 - coatWeight;
    vec4 coatDfg = dfgLookup(NcoV, coatRoughness);
    lobes.coat = withSharpLobe(splitSumLobeRadiance(nc, v, coatRoughness) * ((coatDfg.r + coatDfg.g) * coatWeight),
                               m, nc, v, LOBE_COAT, coatRoughness);
#endif
#ifdef MATERIAL_ANISOTROPY
    // KHR_materials_anisotropy: the stretched lobe is a streak no prefiltered lookup about one
    // direction resembles (the Sample Viewer's bent normal measured 55% to 98% relative RMSE on
    // studio); it is integrated by uAnisotropySamples filtered samples of its own visible normals
    // instead, whose weights carry the sheen's scaling and the coat's 1 - w_c (docs/shading.md,
    // "Anisotropy").
    if (stretched) {
        lobes.specular = fisLobe(m, facingNormal(n, v), v, LOBE_SPECULAR, 0, uAnisotropySamples, uint(uAnisotropySamples));
        return lobes;
    }
#endif
    lobes.specular = withSharpLobe(lobes.specular, m, n, v, LOBE_SPECULAR, roughness);
    return lobes;
}

#ifdef IBL_REFERENCE
#include "ibl_reference.glsl"
#endif

// The environment's light leaving towards v, per lobe, before ambient occlusion.
BrdfLobes environmentLobes(MaterialInfo m, vec3 n, vec3 v)
{
#ifdef IBL_REFERENCE
    return referenceEnvironmentLobes(m, facingNormal(n, v), v);
#elif defined(IBL_FIS)
    return fisEnvironmentLobes(m, facingNormal(n, v), v);
#else
    return splitSumEnvironmentLobes(m, n, v);
#endif
}
