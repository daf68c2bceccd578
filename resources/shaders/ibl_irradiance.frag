// Pass 4: the irradiance cubemap (one face per draw). Stores IRRADIANCE
//   E(n) = integral over the sphere of L(w) max(0, n.w) dw   (radiance x sr; NOT divided by pi)
// as a quadrature over EVERY texel t of one small level of the environment cubemap:
//   E(n) ~= sum_t L_t max(0, n.w_t) Omega_t
// with w_t the texel centre's direction and Omega_t its exact solid angle. The level is a
// box-filtered average of the environment, so every bit of light is counted once and nothing from
// behind the surface leaks in except through texels that straddle the horizon. (Filtered
// importance sampling of the cosine lobe was tried first: its wide footprints near the horizon
// read light from behind, +360% on the dark side of studio.exr; docs/ibl.md.)
//
// The texels come as a table made once per environment on the CPU (IblPrecompute, from the level
// read back): entry i's direction w_t in row 2 (i / kTableWidth), column i % kTableWidth, and its
// L_t Omega_t in the row below. Computing w_t, Omega_t (four atan) and a cube lookup for every
// texel of every output texel cost llvmpipe 6144 x 384 of each at the default preset.
#include "common_math.glsl"
#include "common_cubemap.glsl"

const int kTableWidth = 1024;

uniform sampler2D uTexels;
uniform int uCount;
uniform int uFace;
in vec2 vUv;
out vec4 fragColor;

void main()
{
    vec3 n = cubemapDirection(uFace, vUv);
    vec3 sum = vec3(0.0);
    for (int i = 0; i < uCount; ++i) {
        ivec2 at = ivec2(i % kTableWidth, 2 * (i / kTableWidth));
        float cosine = dot(n, texelFetch(uTexels, at, 0).xyz);
        if (cosine > 0.0)
            sum += texelFetch(uTexels, at + ivec2(0, 1), 0).rgb * cosine;
    }
    fragColor = vec4(sum, 1.0);
}
