// Pass 3: one level of the prefiltered specular cubemap (one face per draw). Split-sum
// radiance for n = v = r [Karis 2013]: sum L(l) (n.l) / sum (n.l) over l = reflect(v, h), h from
// importanceSampleGGX; since n = v, pdf_l = D(h) (n.h) / (4 v.h) = D(h) / 4. Each sample reads
// the environment cubemap at the filtered-importance-sampling lod (core/ibl/Prefilter.h filteredLod).
// The samples are the same for every texel of a level: IblPrecompute makes them once on the CPU
// (core/ibl/Prefilter.h prefilterLobeSamples, in double) and passes a table, entry i at row
// i / kTableWidth, column i % kTableWidth: l in the frame of n (z along n; l.z = n.l > 0) and its
// lod. uInverseWeight is 1 / sum (n.l). Computing hammersley, importanceSampleGGX, D and the lod
// in every texel cost llvmpipe a quarter of the pass (docs/benchmarks.md).
// PREFILTER_COPY: level 0 (roughness 0) is the environment itself, read at the source lod that
// matches this level's size.
#include "common_sampling.glsl"
#include "common_cubemap.glsl"

const int kTableWidth = 1024;

uniform samplerCube uEnvironment;
uniform int uFace;
uniform sampler2D uSamples;
uniform int uCount;
uniform float uInverseWeight;
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
    vec3 sum = vec3(0.0);
    for (int i = 0; i < uCount; ++i) {
        vec4 s = texelFetch(uSamples, ivec2(i % kTableWidth, i / kTableWidth), 0);
        sum += textureLod(uEnvironment, tangentToWorld(s.xyz, t, b, n), s.w).rgb * s.z;
    }
    fragColor = vec4(sum * uInverseWeight, 1.0);
#endif
}
