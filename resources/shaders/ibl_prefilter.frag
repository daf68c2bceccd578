// Pass 3: one level of the prefiltered specular cubemap (one face per draw). Split-sum
// radiance for n = v = r [Karis 2013]: sum L(l) (n.l) / sum (n.l) over l = reflect(v, h), h from
// importanceSampleGGX; since n = v, pdf_l = D(h) (n.h) / (4 v.h) = D(h) / 4. Each sample reads
// the environment cubemap at the filtered-importance-sampling lod (ibl_filtering.glsl).
// PREFILTER_COPY: level 0 (roughness 0) is the environment itself, read at the source lod that
// matches this level's size.
#include "common_sampling.glsl"
#include "common_cubemap.glsl"
#include "brdf_distribution.glsl"
#include "ibl_filtering.glsl"

uniform samplerCube uEnvironment;
uniform int uFace;
uniform float uRoughness;   // perceptual roughness of this level
uniform int uSampleCount;
uniform float uSourceSize;  // environment cubemap level-0 size
uniform float uSourceMaxLod;
uniform float uCopyLod;     // PREFILTER_COPY: log2(sourceSize / levelSize)
in vec2 vUv;
out vec4 fragColor;

void main()
{
    vec3 n = cubemapDirection(uFace, vUv);
#ifdef PREFILTER_COPY
    fragColor = vec4(textureLod(uEnvironment, n, uCopyLod).rgb, 1.0);
#else
    vec3 t, b;
    buildOrthonormalBasis(n, t, b);
    float alpha = alphaFromRoughness(uRoughness);
    uint count = uint(max(uSampleCount, 1));
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    for (uint i = 0u; i < count; ++i) {
        vec3 hTangent = importanceSampleGGX(hammersley(i, count), alpha);
        vec3 h = tangentToWorld(hTangent, t, b, n);
        vec3 l = reflectAbout(n, h);
        float NoL = dot(n, l);
        if (NoL <= 0.0)
            continue;
        float pdf = D_GGX(hTangent.z, alpha) * 0.25;
        float lod = filteredLod(pdf, float(count), uSourceSize, uSourceMaxLod);
        sum += textureLod(uEnvironment, l, lod).rgb * NoL;
        weight += NoL;
    }
    fragColor = vec4(sum / max(weight, 1e-8), 1.0);
#endif
}
