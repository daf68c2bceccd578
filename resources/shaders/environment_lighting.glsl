// Image-based lighting. environmentLobes() dispatches on the IBL method's variant bit
// (render/ShaderVariant.h): IBL_REFERENCE integrates by Monte Carlo (ibl_reference.glsl);
// otherwise the split sum [Karis 2013], from the textures of render/IblTextures
// (prefiltered specular cubemap, irradiance cubemap storing E or 9 premultiplied SH
// coefficients, DFG LUT). Twin: core/SplitSum.h splitSumRadiance(); docs/rendering.md gives the
// formulas. Lookups turn world directions into the environment image's frame
// (Environment::toImageFrame: R_y(-rotation)), and radiance is multiplied by the intensity.
#include "ibl_lookup.glsl"
#include "debug_views.glsl"
#include "environment_frame.glsl"

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
// Twin of core/SphericalHarmonics.h irradianceSH(const IrradianceSH9&, n).
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

// The split-sum lobes for the view direction v (unit, towards the viewer) at normal n:
//   specular = prefiltered(R, lod(r)) * (F0 scale + bias) * M(F0)             (per lobe F0)
//   diffuse  = E(n) / pi * c * w_d
// glTF:  specular = (1 - m) spec(F0_d) + m spec(c);  diffuse weight w_d = (1 - m) (1 - F0_d) W(n.v)
//        for fresnel_mix (the albedo of its base c / pi (1 - F(v.h)): the ground truth's model),
//        (1 - m) (1 - E_s(n.v)) for the energy-preserving coupling.
// LearnOpenGL: F0 = mix(F0_d, c, m), specular = spec(F0), w_d = (1 - F0) W(n.v) (1 - m) (kD =
//        (1 - F(v.h)) (1 - m) per direction) or (1 - E_s(n.v)) (1 - m) (energy preserving).
// W(n.v) is the DFG table's alpha (core/DfgTable.h).
BrdfLobes splitSumEnvironmentLobes(MaterialInfo m, vec3 n, vec3 v)
{
    BrdfLobes lobes;
    float NoV = clamp(dot(n, v), 0.0, 1.0);
    float roughness = clampRoughness(m.perceptualRoughness);
    float metallic = saturate(m.metallic);
    vec3 baseColor = max(m.baseColor, vec3(0.0));
    vec3 R = specularDominantDirection(n, reflect(-v, n), roughness * roughness);
    vec3 radiance = prefilteredRadiance(R, roughness);
    vec3 diffuseLight = irradiance(n) * INV_PI;
    vec4 dfg = dfgLookup(NoV, roughness);
    float f0Dielectric = f0FromIor(m.ior);
#ifdef COMPOSITION_LEARNOPENGL
    vec3 f0 = mix(vec3(f0Dielectric), baseColor, metallic);
    lobes.specular = radiance * (f0 * dfg.r + dfg.g) * multiScatterFactor(f0, NoV, roughness);
#ifdef COUPLING_ENERGY_PRESERVING
    vec3 kD = vec3((1.0 - dielectricSpecularAlbedo(f0Dielectric, NoV, roughness)) * (1.0 - metallic));
#else
    vec3 kD = (vec3(1.0) - f0) * (dfg.a * (1.0 - metallic));
#endif
    lobes.diffuse = diffuseLight * baseColor * kD;
#else
    vec3 specularDielectric = vec3((f0Dielectric * dfg.r + dfg.g) * multiScatterFactor(vec3(f0Dielectric), NoV, roughness).x);
    vec3 specularMetal = (baseColor * dfg.r + dfg.g) * multiScatterFactor(baseColor, NoV, roughness);
    lobes.specular = radiance * mix(specularDielectric, specularMetal, metallic);
#ifdef COUPLING_ENERGY_PRESERVING
    float diffuseWeight = max(0.0, 1.0 - dielectricSpecularAlbedo(f0Dielectric, NoV, roughness));
#else
    float diffuseWeight = (1.0 - f0Dielectric) * dfg.a;
#endif
    lobes.diffuse = diffuseLight * baseColor * (diffuseWeight * (1.0 - metallic));
#endif
    return lobes;
}

#ifdef IBL_REFERENCE
#include "ibl_reference.glsl"
#endif

// The environment's light leaving towards v, per lobe, before ambient occlusion.
BrdfLobes environmentLobes(MaterialInfo m, vec3 n, vec3 v)
{
#ifdef IBL_REFERENCE
    return referenceEnvironmentLobes(m, n, v);
#else
    return splitSumEnvironmentLobes(m, n, v);
#endif
}
