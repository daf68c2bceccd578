// The surface pass: material inputs -> image-based light (split sum) + punctual lights, lobes
// kept apart (glTF Sample Viewer's pbr.frag), written as linear HDR radiance. Variants: see
// render/ShaderVariant.h. Twin of core/shading/MaterialBrdf.cpp (lights) and core/shading/SplitSum.cpp (IBL).
#include "debug_views.glsl"
#include "material_inputs.glsl"
#include "brdf_compose.glsl"
#include "environment_lighting.glsl"
#ifdef HAS_PUNCTUAL_LIGHTS
#include "lights_punctual.glsl"
#endif

in vec3 vWorldPosition;
in vec3 vNormal;
in vec2 vUv;
#ifdef HAS_TANGENT_FRAME
in vec4 vTangent;
#endif

uniform vec3 uCameraPosition;
// The largest value the target holds: 65504 for RGBA16F, so radiance beyond it (a 1e6 sun)
// saturates instead of becoming +Inf, which tone mappers would turn into NaN.
uniform float uMaxRadiance;
#ifdef ALPHA_MASK
uniform float uAlphaCutoff;
#endif

out vec4 fragColor;

void main()
{
    vec3 v = normalize(uCameraPosition - vWorldPosition);
    vec3 ng = normalize(vNormal);
    if (!gl_FrontFacing)
        ng = -ng; // two-sided: shade the side the camera sees
#ifdef ANALYTIC_SPHERE_NORMAL
    // The unit sphere itself (model = identity), hit by this pixel's ray from the camera: the
    // ground truth's n and v (core/shading/ReferenceView.h intersectSphere). The mesh's faces lie inside
    // the sphere, so every fragment's ray hits it.
    {
        vec3 direction = normalize(vWorldPosition - uCameraPosition);
        float b = dot(uCameraPosition, direction);
        float c = dot(uCameraPosition, uCameraPosition) - 1.0;
        float discriminant = b * b - c;
        if (discriminant >= 0.0) {
            ng = normalize(uCameraPosition + (-b - sqrt(discriminant)) * direction);
            v = -direction;
        }
    }
#endif
    MaterialInfo m = materialInputs(vUv);
    // KHR_materials_clearcoat: the coat's own normal map, else the geometric normal.
#if defined(MATERIAL_CLEARCOAT) && defined(HAS_CLEARCOAT_NORMAL_MAP)
    m.clearcoatNormal = clearcoatNormal(ng, vTangent, vUv);
#else
    m.clearcoatNormal = ng;
#endif
#ifdef ALPHA_MASK
    // glTF alphaMode MASK: below the cutoff nothing is drawn, above it the surface is opaque.
    if (m.alpha < uAlphaCutoff)
        discard;
#endif
#if DEBUG_VIEW == DEBUG_WHITE_FURNACE
    m.baseColor = vec3(1.0);
    m.occlusion = 1.0;
#endif
#ifdef HAS_NORMAL_MAP
    vec3 n = shadingNormal(ng, vTangent, vUv);
#else
    vec3 n = ng;
#endif
#ifdef MATERIAL_ANISOTROPY
    // KHR_materials_anisotropy: the tangent-plane direction through the surface's tangent frame;
    // the reference view's analytic sphere takes its own tangent, the sphere mesh's dP/du, as the
    // ground truth does (core/shading/ReferenceView.h sphereTangent).
#ifdef ANALYTIC_SPHERE_NORMAL
    vec4 anisotropyFrameTangent = vec4(ng.z, 0.0, -ng.x, 1.0);
#else
    vec4 anisotropyFrameTangent = vTangent;
#endif
    m.anisotropyDirection = anisotropyDirection(ng, anisotropyFrameTangent, m.anisotropyTangentDirection);
#endif
#if defined(MATERIAL_IRIDESCENCE) && defined(COUPLING_ENERGY_PRESERVING)
    m.filmLayerF0 = filmLayer(m, dielectricReflectance(m).f0).f0.x;
#endif
    // Normal-mapped normals may face away from the viewer: keep n.v >= 0 consistent with core's
    // evaluate(), which returns zero below the surface.

    BrdfLobes ibl = environmentLobes(m, n, v);
    vec3 direct = vec3(0.0);
#ifdef HAS_PUNCTUAL_LIGHTS
    for (int i = 0; i < uLightCount; ++i) {
        vec3 lightIrradiance;
        vec3 l = lightDirection(i, vWorldPosition, lightIrradiance);
        float NoL = dot(n, l);
        if (NoL <= 0.0)
            continue;
        BrdfLobes f = evaluateBrdf(m, n, v, l, true);
        direct += lobeTotal(f) * lightIrradiance * NoL;
    }
#endif
    // Ambient occlusion darkens indirect light only (the coat's reflection too, as the glTF
    // Sample Viewer does).
    vec3 indirect = lobeTotal(ibl) * m.occlusion;
    // Emission is not occluded: it leaves the surface itself, through the coat's 1 - w_c
    // (KHR_materials_clearcoat's coated_emission).
    vec3 emission = m.emissive;
#ifdef MATERIAL_CLEARCOAT
    emission *= 1.0 - clearcoatWeight(m, dot(m.clearcoatNormal, v));
#endif
    vec3 color = indirect + direct + emission;
#ifdef MATERIAL_UNLIT
    // KHR_materials_unlit: the base colour (factor x texture x vertex colour) is the radiance; the
    // lighting above is dead code the compiler drops (debug views still show it).
    color = m.baseColor;
#endif

#if DEBUG_VIEW != DEBUG_NONE
    // The l that the D, V and F views evaluate: the first light, else the mirror direction.
    vec3 debugL = reflect(-v, n);
#ifdef HAS_PUNCTUAL_LIGHTS
    if (uLightCount > 0) {
        vec3 unused;
        debugL = lightDirection(0, vWorldPosition, unused);
    }
#endif
    float debugNoV = clamp(dot(n, v), 0.0, 1.0);
    float debugNoL = clamp(dot(n, debugL), 0.0, 1.0);
    vec3 debugH = normalize(v + debugL);
    float debugR = clampRoughness(m.perceptualRoughness);
#endif
#if DEBUG_VIEW == DEBUG_BASE_COLOR
    color = m.baseColor;
#elif DEBUG_VIEW == DEBUG_SHADING_NORMAL
    color = n * 0.5 + 0.5;
#elif DEBUG_VIEW == DEBUG_GEOMETRIC_NORMAL
    color = ng * 0.5 + 0.5;
#elif DEBUG_VIEW == DEBUG_METALLIC
    color = vec3(m.metallic);
#elif DEBUG_VIEW == DEBUG_ROUGHNESS
    color = vec3(debugR);
#elif DEBUG_VIEW == DEBUG_OCCLUSION
    color = vec3(m.occlusion);
#elif DEBUG_VIEW == DEBUG_CLEARCOAT
    color = vec3(m.clearcoat);
#elif DEBUG_VIEW == DEBUG_CLEARCOAT_ROUGHNESS
    color = vec3(m.clearcoatRoughness);
#elif DEBUG_VIEW == DEBUG_CLEARCOAT_NORMAL
    color = m.clearcoatNormal * 0.5 + 0.5;
#elif DEBUG_VIEW == DEBUG_SHEEN_COLOR
    color = m.sheenColor;
#elif DEBUG_VIEW == DEBUG_SHEEN_ROUGHNESS
    color = vec3(m.sheenRoughness);
#elif DEBUG_VIEW == DEBUG_SPECULAR
    color = vec3(m.specular);
#elif DEBUG_VIEW == DEBUG_SPECULAR_COLOR
    color = m.specularColor;
#elif DEBUG_VIEW == DEBUG_ANISOTROPY
    color = vec3(m.anisotropy);
#elif DEBUG_VIEW == DEBUG_ANISOTROPY_DIRECTION
    color = m.anisotropyDirection * 0.5 + 0.5;
#elif DEBUG_VIEW == DEBUG_IRIDESCENCE
    color = vec3(m.iridescence);
#elif DEBUG_VIEW == DEBUG_IRIDESCENCE_THICKNESS
    color = vec3(m.iridescence > 0.0 ? m.iridescenceThickness / 1000.0 : 0.0);
#elif DEBUG_VIEW == DEBUG_IRIDESCENCE_FRESNEL
#ifdef MATERIAL_IRIDESCENCE
    float filmNoV = saturate(dot(n, v));
    color = mix(filmFresnel(m, dielectricReflectance(m).f0, filmNoV), filmFresnel(m, m.baseColor, filmNoV),
                m.metallic);
#else
    color = vec3(0.0);
#endif
#elif DEBUG_VIEW == DEBUG_DISTRIBUTION
    color = vec3(distribution(saturate(dot(n, debugH)), debugR * debugR));
#elif DEBUG_VIEW == DEBUG_VISIBILITY
    color = vec3(visibility(debugNoV, debugNoL, debugR * debugR, debugR, true));
#elif DEBUG_VIEW == DEBUG_FRESNEL
    color = compositionFresnel(m, saturate(dot(v, debugH)));
#elif DEBUG_VIEW == DEBUG_IRRADIANCE
    color = irradiance(n) * INV_PI;
#elif DEBUG_VIEW == DEBUG_IBL_DIFFUSE
    color = ibl.diffuse * m.occlusion;
#elif DEBUG_VIEW == DEBUG_PREFILTERED_RADIANCE
    color = prefilteredRadiance(specularDominantDirection(n, reflect(-v, n), debugR * debugR), debugR);
#elif DEBUG_VIEW == DEBUG_BRDF_LUT
    color = dfgLookup(debugNoV, debugR).rgb;
#elif DEBUG_VIEW == DEBUG_IBL_SPECULAR
    color = (ibl.specular + ibl.sheen + ibl.coat) * m.occlusion;
#elif DEBUG_VIEW == DEBUG_IBL_TOTAL
    color = indirect;
#elif DEBUG_VIEW == DEBUG_DIRECT_LIGHT
    color = direct;
#elif DEBUG_VIEW == DEBUG_WHITE_FURNACE
    color = lobeTotal(ibl);
#elif DEBUG_VIEW == DEBUG_UV
    color = vec3(vUv, 0.0);
#elif DEBUG_VIEW == DEBUG_NON_FINITE
    // 1 where the shaded radiance is NaN, infinite or negative before the guard below hides it
    // (tests of numerical stability read this; artists see where a material breaks).
    color = vec3(any(isnan(color)) || any(isinf(color)) || any(lessThan(color, vec3(0.0))) ? 1.0 : 0.0);
#elif DEBUG_VIEW == DEBUG_EMISSIVE
    color = m.emissive;
#elif DEBUG_VIEW == DEBUG_ALPHA
    color = vec3(m.alpha);
#elif DEBUG_VIEW == DEBUG_UV_CHECKER
    color = uvChecker(vUv) * (0.35 + 0.65 * debugNoV);
#elif DEBUG_VIEW == DEBUG_TEXEL_DENSITY
    color = texelDensityColor(texelDensity(vUv, vWorldPosition)) * (0.35 + 0.65 * debugNoV);
#elif DEBUG_VIEW == DEBUG_TANGENT
#ifdef HAS_TANGENT_FRAME
    color = surfaceTangent(ng, vTangent) * 0.5 + 0.5;
#else
    color = vec3(0.5);
#endif
#endif
    if (any(isnan(color)))
        color = vec3(0.0);
    color = min(color, vec3(uMaxRadiance));
#if defined(ALPHA_BLEND) && DEBUG_VIEW != DEBUG_ALPHA && DEBUG_VIEW != DEBUG_NON_FINITE
    // glTF alphaMode BLEND: "over" with premultiplied colour (blend ONE, ONE_MINUS_SRC_ALPHA).
    // Debug views blend too, so the parts behind a glass stay visible in them; the alpha and
    // non-finite views are the exceptions, shown opaque.
    fragColor = vec4(color * m.alpha, m.alpha);
#else
    fragColor = vec4(color, 1.0);
#endif
}
