// Sample generation and importance sampling: GLSL twins of core/shading/Sampling.h (same names, same
// formulas, in float). Tangent space has the normal along +Z.
#include "common_math.glsl"

// Van der Corput radical inverse in base 2 (bits mirrored about the binary point).
float radicalInverse(uint bits)
{
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return float(bits) * 2.3283064365386963e-10; // / 2^32
}

// The i-th of n Hammersley points [Hammersley & Handscomb 1964].
vec2 hammersley(uint i, uint n) { return vec2(float(i) / float(n), radicalInverse(i)); }

// Sobol' dimensions 1 and 2 as 32-bit fractions [Sobol' 1967; Kollig & Keller 2002]: x is the
// radical inverse, y the XOR of direction numbers v_1 = 2^31, v_{k+1} = v_k ^ (v_k >> 1) over the
// set bits of s. Every aligned block of 2^m points is a (0, m, 2)-net (core/shading/Sampling.h).
uvec2 sobol2DBits(uint s)
{
    uint y = 0u;
    uint v = 0x80000000u;
    for (uint bits = s; bits != 0u; bits >>= 1u) {
        if ((bits & 1u) != 0u)
            y ^= v;
        v ^= v >> 1u;
    }
    return uvec2(bitfieldReverse(s), y);
}
// sobol2DBits / 2^32 in float (rounded: may be 1.0; samples use shiftedSobol2D).
vec2 sobol2D(uint s) { return vec2(sobol2DBits(s)) * 2.3283064365386963e-10; }

// The "pcg" hash [Jarzynski & Olano 2020, "Hash Functions for GPU Rendering", JCGT 9(3)].
uint pcgHash(uint value)
{
    uint state = value * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// A Cranley-Patterson shift per pixel, seed and strategy (nested pcg hashes; core/shading/Sampling.h).
uvec2 cranleyPattersonShift(uint x, uint y, uint seed, uint strategy)
{
    uint h = pcgHash(x + pcgHash(y + pcgHash(seed + pcgHash(strategy))));
    return uvec2(h, pcgHash(h));
}

// Sample s shifted: frac(sobol2D(s) + shift) in 32-bit fixed point, truncated to 24 bits so the
// float is exact and below 1.
vec2 shiftedSobol2D(uint s, uvec2 shift)
{
    uvec2 bits = sobol2DBits(s) + shift;
    return vec2(bits >> 8u) * 5.9604644775390625e-8;
}

// Orthonormal basis around unit n [Duff et al. 2017].
void buildOrthonormalBasis(vec3 n, out vec3 t, out vec3 b)
{
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float c = n.x * n.y * a;
    t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
    b = vec3(c, s + n.y * n.y * a, -n.y);
}
vec3 tangentToWorld(vec3 v, vec3 t, vec3 b, vec3 n) { return v.x * t + v.y * b + v.z * n; }

// 2 (v.h) h - v.
vec3 reflectAbout(vec3 v, vec3 h) { return 2.0 * dot(v, h) * h - v; }

// Cosine-weighted hemisphere through the concentric disk mapping [Shirley & Chiu 1997];
// pdf = cos(theta) / pi.
vec3 sampleCosineHemisphere(vec2 u)
{
    float sx = 2.0 * u.x - 1.0;
    float sy = 2.0 * u.y - 1.0;
    float r = 0.0;
    float phi = 0.0;
    if (sx != 0.0 || sy != 0.0) {
        if (abs(sx) > abs(sy)) {
            r = sx;
            phi = (PI / 4.0) * (sy / sx);
        } else {
            r = sy;
            phi = (PI / 2.0) - (PI / 4.0) * (sx / sy);
        }
    }
    float x = r * cos(phi);
    float y = r * sin(phi);
    return vec3(x, y, sqrt(max(0.0, 1.0 - x * x - y * y)));
}
float pdfCosineHemisphere(float cosTheta) { return max(cosTheta, 0.0) * INV_PI; }

// Classic GGX NDF sampling, h proportional to D(h) (n.h) [Walter et al. 2007, eq. 35-36].
vec3 importanceSampleGGX(vec2 u, float alpha)
{
    float phi = TWO_PI * u.x;
    float cos2Theta = (1.0 - u.y) / (1.0 + (alpha * alpha - 1.0) * u.y);
    float cosTheta = sqrt(clamp(cos2Theta, 0.0, 1.0));
    float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
    return vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

// pdf of l = reflect(v, h) for h from importanceSampleGGX: D(h) (n.h) / (4 v.h) [Walter eq. 14].
float pdfGGXReflection(float NoH, float VoH, float alpha)
{
    if (NoH <= 0.0 || VoH <= 0.0)
        return 0.0;
    float a2 = alpha * alpha;
    float f = NoH * NoH * (a2 - 1.0) + 1.0;
    return a2 / (PI * f * f) * NoH / (4.0 * VoH);
}

// Exact Smith G1 for GGX [Walter et al. 2007, eq. 34].
float G1_SmithGGX(float NoX, float alpha)
{
    float a2 = alpha * alpha;
    return 2.0 * NoX / (NoX + sqrt(a2 + (1.0 - a2) * NoX * NoX));
}

// Visible-normal sampling [Heitz 2018, "Sampling the GGX Distribution of Visible Normals", listing 1],
// with a roughness per axis (alpha.x along the frame's x, alpha.y along y: KHR_materials_anisotropy's
// alpha_t, alpha_b); twin of core's sampling::importanceSampleVNDF.
vec3 importanceSampleVNDF(vec2 u, vec3 v, vec2 alpha)
{
    vec3 vh = normalize(vec3(alpha.x * v.x, alpha.y * v.y, v.z));
    float lensq = vh.x * vh.x + vh.y * vh.y;
    vec3 t1 = lensq > 0.0 ? vec3(-vh.y, vh.x, 0.0) * inversesqrt(lensq) : vec3(1.0, 0.0, 0.0);
    vec3 t2 = cross(vh, t1);
    float r = sqrt(u.x);
    float phi = TWO_PI * u.y;
    float p1 = r * cos(phi);
    float p2 = r * sin(phi);
    float s = 0.5 * (1.0 + vh.z);
    p2 = (1.0 - s) * sqrt(max(0.0, 1.0 - p1 * p1)) + s * p2;
    vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
    return normalize(vec3(alpha.x * nh.x, alpha.y * nh.y, max(0.0, nh.z)));
}
vec3 importanceSampleVNDF(vec2 u, vec3 v, float alpha) { return importanceSampleVNDF(u, v, vec2(alpha)); }

// The same distribution by spherical caps [Dupuy and Benyoub 2023, HPG, listing 3]: no frame is
// built around v, so a fixed set of points u moves continuously with v (Heitz's frame turns with
// v's azimuth and drew a pinch where n = v in FIS's structured error). core/shading/Sampling.h has the why.
// The stretch takes a roughness per axis as Heitz's does.
vec3 importanceSampleVNDFSphericalCap(vec2 u, vec3 v, vec2 alpha)
{
    vec3 vh = normalize(vec3(alpha.x * v.x, alpha.y * v.y, v.z));
    float phi = TWO_PI * u.x;
    float z = (1.0 - u.y) * (1.0 + vh.z) - vh.z;
    float sinTheta = sqrt(clamp(1.0 - z * z, 0.0, 1.0));
    vec3 h = vec3(sinTheta * cos(phi), sinTheta * sin(phi), z) + vh;
    return normalize(vec3(alpha.x * h.x, alpha.y * h.y, max(0.0, h.z)));
}
vec3 importanceSampleVNDFSphericalCap(vec2 u, vec3 v, float alpha)
{
    return importanceSampleVNDFSphericalCap(u, v, vec2(alpha));
}
