// Pass 4: the irradiance cubemap (one face per draw). Stores IRRADIANCE
//   E(n) = integral over the sphere of L(w) max(0, n.w) dw   (radiance x sr; NOT divided by pi)
// as a quadrature over EVERY texel t of one small level of the environment cubemap:
//   E(n) ~= sum_t L_t max(0, n.w_t) Omega_t
// with w_t the texel centre's direction and Omega_t its exact solid angle (cubeTexelSolidAngle).
// The level (uSourceLevel, uSourceSize texels a side) is a box-filtered average of the
// environment, so every bit of light is counted once and nothing from behind the surface leaks
// in except through texels that straddle the horizon. (Filtered importance sampling of the
// cosine lobe was tried first: its wide footprints near the horizon read light from behind,
// +360% on the dark side of studio.exr; docs/ibl.md.)
#include "common_math.glsl"
#include "common_cubemap.glsl"

uniform samplerCube uEnvironment;
uniform int uFace;
uniform int uSourceSize;
uniform float uSourceLevel;
in vec2 vUv;
out vec4 fragColor;

// Solid angle subtended by the part of a face (at distance 1) from (0, 0) to (x, y):
// atan(x y / sqrt(x^2 + y^2 + 1)) [e.g. Driscoll, "Cubemap texel solid angle"]; a texel's is the
// inclusion-exclusion of its four corners.
float cornerArea(float x, float y) { return atan(x * y, sqrt(x * x + y * y + 1.0)); }
float cubeTexelSolidAngle(int x, int y, int size)
{
    float inv = 2.0 / float(size);
    float x0 = float(x) * inv - 1.0;
    float y0 = float(y) * inv - 1.0;
    float x1 = x0 + inv;
    float y1 = y0 + inv;
    return cornerArea(x0, y0) - cornerArea(x0, y1) - cornerArea(x1, y0) + cornerArea(x1, y1);
}

void main()
{
    vec3 n = cubemapDirection(uFace, vUv);
    vec3 sum = vec3(0.0);
    for (int face = 0; face < 6; ++face) {
        for (int y = 0; y < uSourceSize; ++y) {
            for (int x = 0; x < uSourceSize; ++x) {
                vec3 w = cubemapDirection(face, (vec2(x, y) + 0.5) / float(uSourceSize));
                float cosine = dot(n, w);
                if (cosine <= 0.0)
                    continue;
                sum += textureLod(uEnvironment, w, uSourceLevel).rgb * (cosine * cubeTexelSolidAngle(x, y, uSourceSize));
            }
        }
    }
    fragColor = vec4(sum, 1.0);
}
