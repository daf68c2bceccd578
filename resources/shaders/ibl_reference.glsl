// IblMethod::Reference: the environment's light by Monte Carlo, the GLSL twin of the loop of
// core/shading/GroundTruth.cpp integrateOutgoingRadiance (same integrand, same strategies, same weights):
// each sample draws one direction from the BRDF (the lobe picked by specularSelectionProbability,
// then visible-normal GGX [Heitz 2018] or cosine) and one from the environment's luminance tables
// (environment_sampling.glsl), combined by the power heuristic [Veach 1997, ch. 9]; f is
// evaluateBrdf(), the material's own composition, and the radiance is the source equirect read
// as Environment::radiance reads it. The points differ from the CPU's: sample s of a pixel is the
// shifted Sobol' point shiftedSobol2D(s, shift) with one Cranley-Patterson shift per pixel, seed
// and strategy, so draws of k samples at increasing sampleBase add up to one longer run
// (render/FrameAccumulator); the integral is the same.
#include "common_sampling.glsl"
#include "environment_sampling.glsl"

uniform int uIblSeed; // bits of a uint32 (IblSampling::seed)

const uint kStrategyBrdf = 0u;
const uint kStrategyEnvironment = 1u;

// Twin of GroundTruth.cpp lobeSelection (Lobes::Material): the probabilities of the BRDF
// strategy's picking the coat (x) and the specular lobe (y); the diffuse lobe takes the rest.
vec2 lobeSelection(MaterialInfo m, float NoV)
{
    float metallic = saturate(m.metallic);
    vec3 baseColor = max(m.baseColor, vec3(0.0));
    DielectricReflectance layer = dielectricReflectance(m);
    vec3 f0 = mix(layer.f0, baseColor, metallic);
    const vec3 lum = vec3(0.2126, 0.7152, 0.0722);
    float specular = dot(F_Schlick(f0, mix(layer.f90, 1.0, metallic), NoV), lum);
    float diffuse = dot(baseColor, lum) * (1.0 - metallic) * (1.0 - specular);
#ifdef MATERIAL_SHEEN
    // The cosine strategy also serves the sheen, a broad lobe.
    diffuse += dot(max(m.sheenColor, vec3(0.0)), lum);
#endif
    vec2 p = vec2(0.0, diffuse <= 0.0 ? 1.0 : clamp(specular / (specular + diffuse), 0.1, 0.9));
#ifdef MATERIAL_CLEARCOAT
    if (m.clearcoat > 0.0) {
        float coat = clearcoatWeight(m, NoV);
        float base = (1.0 - coat) * (specular + max(diffuse, 0.0));
        p.x = clamp(coat / max(coat + base, 1e-12), 0.1, 0.9);
        p.y *= 1.0 - p.x;
    }
#endif
    return p;
}

float powerHeuristic(float pdfA, float pdfB)
{
    float a = pdfA * pdfA;
    float b = pdfB * pdfB;
    return a + b > 0.0 ? a / (a + b) : 0.0;
}

float pdfVndfReflection(float NoV, float NoH, float alpha)
{
    return NoH > 0.0 ? G1_SmithGGX(NoV, alpha) * D_GGX(NoH, alpha) / (4.0 * NoV) : 0.0;
}

// The specular strategy's frame (t, b about n) and roughness per axis: the anisotropy frame and
// (alpha_t, alpha_b) where the material has one (MATERIAL_ANISOTROPY), else buildOrthonormalBasis's
// frame and alpha on both axes. The coat's and the cosine strategy draw in the same frame. Twin
// of core's shading::SpecularLobeSampler.
struct SpecularStrategy {
    vec3 t;
    vec3 b;
    vec2 alpha;
    bool anisotropic;
};

SpecularStrategy specularStrategy(MaterialInfo m, vec3 n)
{
    SpecularStrategy s;
    s.anisotropic = false;
#ifdef MATERIAL_ANISOTROPY
    vec3 t = m.anisotropy > 0.0 ? anisotropyTangent(n, m.anisotropyDirection) : vec3(0.0);
    if (t != vec3(0.0)) {
        s.t = t;
        s.b = cross(n, t);
        s.alpha = anisotropicAlpha(m.perceptualRoughness, m.anisotropy);
        s.anisotropic = true;
        return s;
    }
#endif
    buildOrthonormalBasis(n, s.t, s.b);
    s.alpha = vec2(alphaFromRoughness(m.perceptualRoughness));
    return s;
}

// The specular strategy's density of world direction l (n.l > 0, n.v > 0).
float specularStrategyPdf(SpecularStrategy s, vec3 n, vec3 v, vec3 l, float NoV)
{
    vec3 h = normalize(v + l);
    if (!s.anisotropic)
        return pdfVndfReflection(NoV, dot(n, h), s.alpha.y);
    vec3 hLocal = vec3(dot(h, s.t), dot(h, s.b), dot(h, n));
    vec3 vLocal = vec3(dot(v, s.t), dot(v, s.b), NoV);
    return hLocal.z > 0.0 ? G1_GGXAnisotropic(vLocal, s.alpha) * D_GGXAnisotropic(hLocal, s.alpha) / (4.0 * NoV)
                          : 0.0;
}

// The BRDF strategy's density for world direction l: the lobe mixture (p: lobeSelection; the
// coat's visible normals are drawn about n too).
float brdfSamplingPdf(vec3 n, vec3 v, vec3 l, float NoV, SpecularStrategy specular, float coatAlpha, vec2 p)
{
    float NoL = dot(n, l);
    if (NoL <= 0.0)
        return 0.0;
    float pdf = (1.0 - p.x - p.y) * pdfCosineHemisphere(NoL);
    if (NoV > 0.0) {
        float NoH = dot(n, normalize(v + l));
        if (p.y > 0.0)
            pdf += p.y * specularStrategyPdf(specular, n, v, l, NoV);
        if (p.x > 0.0)
            pdf += p.x * pdfVndfReflection(NoV, NoH, coatAlpha);
    }
    return pdf;
}

bool isUsable(vec3 c) { return !any(isnan(c)) && !any(isinf(c)); }

// Adds f L (n.l) w / pdf of direction l to the lobes; what is not finite is dropped, as on the CPU.
void addContribution(inout BrdfLobes sum, MaterialInfo m, vec3 n, vec3 v, vec3 l, float weightOverPdf)
{
    BrdfLobes f = evaluateBrdf(m, n, v, l, false);
#if DEBUG_VIEW == DEBUG_WHITE_FURNACE
    vec3 radiance = vec3(1.0);
#else
    vec3 radiance = environmentRadiance(l);
#endif
    vec3 scale = radiance * (dot(n, l) * weightOverPdf);
    vec3 diffuse = f.diffuse * scale;
    vec3 specular = f.specular * scale;
    vec3 sheen = f.sheen * scale;
    vec3 coat = f.coat * scale;
    if (isUsable(diffuse) && isUsable(specular) && isUsable(sheen) && isUsable(coat)) {
        sum.diffuse += diffuse;
        sum.specular += specular;
        sum.sheen += sheen;
        sum.coat += coat;
    }
}

// The mean of samples [uIblSampleBase, uIblSampleBase + uIblSamples) of this pixel, per lobe.
BrdfLobes referenceEnvironmentLobes(MaterialInfo m, vec3 n, vec3 v)
{
    BrdfLobes sum;
    sum.diffuse = vec3(0.0);
    sum.specular = vec3(0.0);
    sum.sheen = vec3(0.0);
    sum.coat = vec3(0.0);
    float NoV = dot(n, v);
    if (NoV < 0.0)
        return sum; // evaluateBrdf's rule: nothing is seen from below the surface
    SpecularStrategy specular = specularStrategy(m, n);
    float coatAlpha = alphaFromRoughness(m.clearcoatRoughness);
    vec2 p = lobeSelection(m, min(NoV, 1.0));
    vec3 t = specular.t;
    vec3 b = specular.b;
    vec3 vLocal = vec3(dot(v, t), dot(v, b), NoV);
    uvec2 pixel = uvec2(gl_FragCoord.xy);
    uvec2 brdfShift = cranleyPattersonShift(pixel.x, pixel.y, uint(uIblSeed), kStrategyBrdf);
    uvec2 environmentShift = cranleyPattersonShift(pixel.x, pixel.y, uint(uIblSeed), kStrategyEnvironment);
    const float belowOne = 0.99999994;
    int count = max(uIblSamples, 1);
    for (int i = 0; i < count; ++i) {
        uint s = uint(uIblSampleBase + i);
        // BRDF strategy: the first coordinate picks the lobe and is stretched back to [0, 1).
        vec2 u = shiftedSobol2D(s, brdfShift);
        vec3 l;
        if (u.x < p.x) {
            u.x = min(u.x / p.x, belowOne);
            l = tangentToWorld(reflectAbout(vLocal, importanceSampleVNDF(u, vLocal, coatAlpha)), t, b, n);
        } else if (u.x < p.x + p.y) {
            u.x = min((u.x - p.x) / p.y, belowOne);
            l = tangentToWorld(reflectAbout(vLocal, importanceSampleVNDF(u, vLocal, specular.alpha)), t, b, n);
        } else {
            u.x = min((u.x - p.x - p.y) / (1.0 - p.x - p.y), belowOne);
            l = tangentToWorld(sampleCosineHemisphere(u), t, b, n);
        }
        float pdf = brdfSamplingPdf(n, v, l, NoV, specular, coatAlpha, p);
        if (dot(n, l) > 0.0 && pdf > 0.0)
            addContribution(sum, m, n, v, l, powerHeuristic(pdf, environmentPdf(l)) / pdf);
        // Environment strategy.
        float environmentDensity;
        l = sampleEnvironment(shiftedSobol2D(s, environmentShift), environmentDensity);
        if (dot(n, l) > 0.0 && environmentDensity > 0.0)
            addContribution(sum, m, n, v, l,
                            powerHeuristic(environmentDensity, brdfSamplingPdf(n, v, l, NoV, specular, coatAlpha, p))
                                / environmentDensity);
    }
    sum.diffuse /= float(count);
    sum.specular /= float(count);
    sum.sheen /= float(count);
    sum.coat /= float(count);
    return sum;
}
