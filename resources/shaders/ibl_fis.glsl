// IblMethod::Fis: filtered importance sampling of the pixel's own specular lobe [Colbert &
// Krivanek 2008, GPU Gems 3 ch. 20; MaterialX's FIS environment mode is the anchor]. For the
// pixel's n and v (not the split sum's n = v = R), N directions are drawn from the visible
// normals of GGX by spherical caps [Dupuy and Benyoub 2023] at the points hammersley(i, N), the
// same for every pixel (no noise while orbiting). The caps build no frame around v, so the points
// move continuously with v; Heitz's method [JCGT 7(4)] turns its frame with v's azimuth, and where
// n = v the whole pattern turned about one pixel: a pinch in the middle of a glossy sphere. The Sobol' (0, 2)-sequence instead, whose every prefix covers the
// lobe (so a partial sum would be a usable preview), measured worse: worst 23.6% against 15.5% at
// 64 samples on the five CC0 maps, and an Owen-scrambled Sobol' net per pixel [Burley 2020] worse at
// every count (docs/benchmarks.md, "Decorrelated points"). A partial run is therefore never shown;
// the window refines in levels, each a whole run (FrameRenderer::fisRefinementLevels). Each
// sample reads the environment at the mip level of its footprint
// (filteredLodAt), so the few samples estimate the lobe's integral over the prefiltered source
// rather than sparkle. The BRDF is evaluateBrdf(), per sample: stretched grazing lobes, per-sample
// Fresnel (the dielectric's exact one too) and the compensation are those of the ground truth, and
// samples below the horizon (n.l <= 0) add nothing while still counting in N (the exact
// estimator, not a fade).
//
// Sharp lobes read the source equirect itself (environmentRadiance, the ground truth's bilinear
// lookup) where a sample's footprint is below the equirect texel at its direction, blending into
// the cube's levels over one level: the cube is the equirect resampled, and a mirror lobe read
// from it is blurred by that resampling (the split sum's error at roughness 0.05).
//
// Draws may split the N samples: a draw takes samples [uIblSampleBase, uIblSampleBase +
// uIblSamples) of hammersley(., uIblSampleTotal), with the whole run's footprints, and the
// accumulated mean is the N-sample estimate (render/FrameAccumulator).
//
// Diffuse is the irradiance map times the composition's diffuse albedo (environmentDiffuseAlbedo),
// as the split sum: in a furnace it is exact.
#include "common_sampling.glsl"
#include "environment_sampling.glsl"
#include "ibl_filtering.glsl"

uniform int uIblSampleTotal;

// Radiance from world direction l for a sample of solid-angle density `pdf` out of `count`.
vec3 filteredRadiance(vec3 l, float pdf, float count)
{
#if DEBUG_VIEW == DEBUG_WHITE_FURNACE
    return vec3(1.0);
#else
    vec3 d = toEnvironmentFrame(l);
    // The equirect texel at d: (2 pi / W)(pi / H) cos(latitude) [MaterialX's distortion term].
    vec2 sourceSize = vec2(textureSize(uEnvironmentSource, 0));
    float omegaSource = 2.0 * PI * PI / (sourceSize.x * sourceSize.y) * sqrt(max(1.0 - d.y * d.y, 0.0));
    float omegaSample = 1.0 / (count * max(pdf, 0.5 * INV_PI));
    float sourceLod = omegaSource > 0.0 ? 0.5 * log2(omegaSample / omegaSource) : 1.0;
    if (uEnvironmentSourceBound == 0)
        sourceLod = 1.0;
    if (sourceLod <= 0.0)
        return environmentRadiance(l);
    float lod = filteredLodAt(pdf, count, uEnvironmentSize, uEnvironmentMaxLod, d);
    vec3 filtered = textureLod(uEnvironmentMap, d, lod).rgb * uEnvironmentIntensity;
    if (sourceLod >= 1.0)
        return filtered;
    return mix(environmentRadiance(l), filtered, sourceLod);
#endif
}

// Which microfacet lobe of evaluateBrdf() fisLobe() integrates: the base's specular lobe (about the
// shading normal, of the material's roughness) or the clear coat's (about the coat's normal, of
// the coat's roughness). Each method (split sum, fis, reference) lights every lobe through the
// same signature, lobe in, radiance out.
const int LOBE_SPECULAR = 0;
const int LOBE_COAT = 1;

// The lobe's light by `count` samples [base, base + count) of hammersley(., total) drawn from
// its own visible normals, for the pixel's own n (facing v; the lobe's normal) and v.
vec3 fisLobe(MaterialInfo m, vec3 n, vec3 v, int lobe, int base, int count, uint total)
{
    float NoV = dot(n, v);
    if (NoV < 0.0)
        return vec3(0.0); // evaluateBrdf's rule: nothing is seen from below the surface
    NoV = min(NoV, 1.0);
    float roughness = clampRoughness(lobe == LOBE_COAT ? m.clearcoatRoughness : m.perceptualRoughness);
    float alpha = roughness * roughness;
    vec3 t;
    vec3 b;
    buildOrthonormalBasis(n, t, b);
    vec3 vLocal = vec3(dot(v, t), dot(v, b), NoV);
    // The VNDF reflection density G1(v) D(h) / (4 n.v), with n.v kept off 0 (its samples then
    // graze the surface: the density is large and the footprint a texel).
    float densityScale = G1_SmithGGX(NoV, alpha) / (4.0 * max(NoV, 1e-6));
    count = max(count, 1);
    vec3 specular = vec3(0.0);
    for (int i = 0; i < count; ++i) {
        vec3 h = importanceSampleVNDFSphericalCap(hammersley(uint(base + i), total), vLocal, alpha);
        vec3 lLocal = reflectAbout(vLocal, h);
        if (lLocal.z <= 0.0)
            continue; // below the horizon: no light, still one of the N
        vec3 l = tangentToWorld(lLocal, t, b, n);
        // D from the half vector evaluateBrdf() rebuilds from v + l, not from the sampled h: for a
        // smooth lobe 1 - (n.h)^2 is near float's resolution, and the two D's must cancel
        // exactly (a white metal at roughness 0.05 read 1.6% off in a furnace from the sampled one).
        vec3 hSum = v + l;
        float NoH = saturate(dot(n, hSum / length(hSum)));
        float pdf = D_GGX(NoH, alpha) * densityScale;
        if (!(pdf > 0.0))
            continue;
        BrdfLobes f = evaluateBrdf(m, n, v, l, false);
        vec3 contribution = (lobe == LOBE_COAT ? f.coat : f.specular) * filteredRadiance(l, pdf, float(total))
            * (lLocal.z / pdf);
        if (!any(isnan(contribution)) && !any(isinf(contribution)))
            specular += contribution;
    }
    return specular / float(count);
}

BrdfLobes fisEnvironmentLobes(MaterialInfo m, vec3 n, vec3 v)
{
    BrdfLobes lobes;
    float NoV = dot(n, v);
    uint total = uint(max(uIblSampleTotal, 1));
    lobes.specular = fisLobe(m, n, v, LOBE_SPECULAR, uIblSampleBase, uIblSamples, total);
    lobes.diffuse = NoV < 0.0 ? vec3(0.0)
                              : irradiance(n) * INV_PI
            * environmentDiffuseAlbedo(m, min(NoV, 1.0), clampRoughness(m.perceptualRoughness));
    lobes.coat = vec3(0.0);
#ifdef MATERIAL_CLEARCOAT
    // The specular lobe's samples carry the coat's 1 - w already (evaluateBrdf); the diffuse
    // albedo does not.
    lobes.diffuse *= 1.0 - clearcoatWeight(m, dot(m.clearcoatNormal, v));
    lobes.coat = fisLobe(m, facingNormal(m.clearcoatNormal, v), v, LOBE_COAT, uIblSampleBase, uIblSamples, total);
#endif
    return lobes;
}
