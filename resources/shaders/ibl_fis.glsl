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
    vec3 t = vec3(0.0);
    vec3 b;
    vec2 lobeAlpha = vec2(alpha);
#ifdef MATERIAL_ANISOTROPY
    // KHR_materials_anisotropy: the base's lobe is drawn from its own stretched visible normals,
    // in the anisotropy frame (alpha_t along t, alpha_b across).
    if (lobe == LOBE_SPECULAR && m.anisotropy > 0.0)
        t = anisotropyTangent(n, m.anisotropyDirection);
#endif
    bool anisotropic = t != vec3(0.0);
    if (anisotropic) {
        b = cross(n, t);
        lobeAlpha = anisotropicAlpha(m.perceptualRoughness, m.anisotropy);
    } else {
        buildOrthonormalBasis(n, t, b);
    }
    vec3 vLocal = vec3(dot(v, t), dot(v, b), NoV);
    // The VNDF reflection density G1(v) D(h) / (4 n.v), with n.v kept off 0 (its samples then
    // graze the surface: the density is large and the footprint a texel).
    float densityScale = (anisotropic ? G1_GGXAnisotropic(vLocal, lobeAlpha) : G1_SmithGGX(NoV, alpha))
        / (4.0 * max(NoV, 1e-6));
    count = max(count, 1);
    vec3 specular = vec3(0.0);
    for (int i = 0; i < count; ++i) {
        vec3 h = importanceSampleVNDFSphericalCap(hammersley(uint(base + i), total), vLocal, lobeAlpha);
        vec3 lLocal = reflectAbout(vLocal, h);
        if (lLocal.z <= 0.0)
            continue; // below the horizon: no light, still one of the N
        vec3 l = tangentToWorld(lLocal, t, b, n);
        // D from the half vector evaluateBrdf() rebuilds from v + l, not from the sampled h: for a
        // smooth lobe 1 - (n.h)^2 is near float's resolution, and the two D's must cancel
        // exactly (a white metal at roughness 0.05 read 1.6% off in a furnace from the sampled one).
        vec3 hSum = v + l;
        vec3 hRebuilt = hSum / length(hSum);
        float NoH = saturate(dot(n, hRebuilt));
        float pdf = (anisotropic ? D_GGXAnisotropic(vec3(dot(t, hRebuilt), dot(b, hRebuilt), NoH), lobeAlpha)
                                 : D_GGX(NoH, alpha))
            * densityScale;
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

#ifdef MATERIAL_SHEEN
// A sample direction uniform over the hemisphere of n (local frame, z = n): the sheen's. The
// Charlie lobe gathers light near the horizon, where cosine-distributed samples are sparse: on
// studio, the sheen alone (roughness 0.6) measured 46%, 22% and 7% relative RMSE at 16, 64 and
// 256 cosine samples, 15%, 4.1% and 1.0% uniform (fis; docs/shading.md, "Sheen").
vec3 sheenSampleDirection(uint i, uint total)
{
    vec2 u = hammersley(i, total);
    float cosTheta = 1.0 - u.x;
    float sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
    return vec3(sinTheta * cos(2.0 * PI * u.y), sinTheta * sin(2.0 * PI * u.y), cosTheta);
}

// The sheen lobe's light by `count` samples [base, base + count) of sheenSampleDirection (density
// 1 / (2 pi)), each read at its footprint as the specular lobe's are: evaluateBrdf().sheen L (n.l)
// / pdf, the unbiased estimator (fis).
vec3 fisSheenLobe(MaterialInfo m, vec3 n, vec3 v, int base, int count, uint total)
{
    if (dot(n, v) < 0.0)
        return vec3(0.0);
    vec3 t;
    vec3 b;
    buildOrthonormalBasis(n, t, b);
    count = max(count, 1);
    const float pdf = 0.5 * INV_PI;
    vec3 sheen = vec3(0.0);
    for (int i = 0; i < count; ++i) {
        vec3 lLocal = sheenSampleDirection(uint(base + i), total);
        if (lLocal.z <= 0.0)
            continue;
        vec3 l = tangentToWorld(lLocal, t, b, n);
        vec3 contribution = evaluateBrdf(m, n, v, l, false).sheen * filteredRadiance(l, pdf, float(total))
            * (lLocal.z / pdf);
        if (!any(isnan(contribution)) && !any(isinf(contribution)))
            sheen += contribution;
    }
    return sheen / float(count);
}

// The split sum's light of the sheen lobe: the same `count` samples' radiance averaged with the
// lobe's weights D V (n.l), normalised by their sum, so that the caller's sheenColor E(n.v) is
// the lobe's albedo exactly (a uniform environment gives E, as the table does, where the sampled
// albedo alone erred by up to 1.7% at 32 samples and lifted a white furnace to 1.017). What the
// normalisation cancels is left out of the weights: D's constant, V's 4 n.v and its 1 / n.l
// against the (n.l), lambda(n.v); each sample reads the cube at one level, the footprint of a
// uniform sample at n (the samples differ only in the cube's texel size along them).
vec3 sheenLobeRadiance(MaterialInfo m, vec3 n, vec3 v, int count)
{
    float NoV = dot(n, v);
    if (NoV <= 0.0)
        return vec3(0.0);
    vec3 t;
    vec3 b;
    buildOrthonormalBasis(n, t, b);
    count = max(count, 1);
    float sheenAlpha = max(m.sheenRoughness * m.sheenRoughness, kMinSheenAlpha);
    float exponent = 0.5 / sheenAlpha;
    float lambdaV = 1.0 + lambdaSheen(min(NoV, 1.0), sheenAlpha);
#if DEBUG_VIEW != DEBUG_WHITE_FURNACE
    float lod = filteredLodAt(0.5 * INV_PI, float(count), uEnvironmentSize, uEnvironmentMaxLod, toEnvironmentFrame(n));
#endif
    vec3 sum = vec3(0.0);
    float weights = 0.0;
    for (int i = 0; i < count; ++i) {
        vec3 lLocal = sheenSampleDirection(uint(i), uint(count));
        vec3 l = tangentToWorld(lLocal, t, b, n);
        vec3 hSum = v + l;
        float NoH = dot(n, hSum) * inversesqrt(max(dot(hSum, hSum), 1e-12));
        float weight = pow(max(1.0 - NoH * NoH, 0.0), exponent) / (lambdaV + lambdaSheen(lLocal.z, sheenAlpha));
        if (!(weight > 0.0) || isinf(weight))
            continue;
#if DEBUG_VIEW == DEBUG_WHITE_FURNACE
        sum += vec3(weight);
#else
        sum += textureLod(uEnvironmentMap, toEnvironmentFrame(l), lod).rgb * (uEnvironmentIntensity * weight);
#endif
        weights += weight;
    }
    return weights > 0.0 ? sum / weights : vec3(0.0);
}
#endif

BrdfLobes fisEnvironmentLobes(MaterialInfo m, vec3 n, vec3 v)
{
    BrdfLobes lobes;
    float NoV = dot(n, v);
    uint total = uint(max(uIblSampleTotal, 1));
    lobes.specular = fisLobe(m, n, v, LOBE_SPECULAR, uIblSampleBase, uIblSamples, total);
    lobes.diffuse = NoV < 0.0 ? vec3(0.0)
                              : irradiance(n) * INV_PI
            * environmentDiffuseAlbedo(m, min(NoV, 1.0), clampRoughness(m.perceptualRoughness));
    lobes.sheen = vec3(0.0);
#ifdef MATERIAL_SHEEN
    // The specular samples carry the sheen's scaling (evaluateBrdf); the diffuse lobe takes its
    // cosine-weighted mean, as the split sum's.
    lobes.diffuse *= sheenScaling(m.sheenColor, sheenAlbedos(max(NoV, 0.0), m.sheenRoughness).g);
    lobes.sheen = fisSheenLobe(m, n, v, uIblSampleBase, uIblSamples, total);
#endif
    lobes.coat = vec3(0.0);
#ifdef MATERIAL_CLEARCOAT
    // The specular lobe's samples carry the coat's 1 - w already (evaluateBrdf); the diffuse
    // albedo does not.
    lobes.diffuse *= 1.0 - clearcoatWeight(m, dot(m.clearcoatNormal, v));
    lobes.coat = fisLobe(m, facingNormal(m.clearcoatNormal, v), v, LOBE_COAT, uIblSampleBase, uIblSamples, total);
#endif
    return lobes;
}
