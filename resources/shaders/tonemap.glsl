// Tone mappers and display encodings; twins of core/image/ToneMap.h (same names, sources cited there
// and in docs/rendering.md). Input: exposed linear radiance; output: display-linear [0, 1].

vec3 toneMapNone(vec3 c) { return clamp(c, 0.0, 1.0); }

// Reinhard et al. 2002, eq. 3.
vec3 toneMapReinhard(vec3 c)
{
    c = max(c, vec3(0.0));
    return c / (1.0 + c);
}

// 1 - e^-x.
vec3 toneMapExposure(vec3 c) { return 1.0 - exp(-max(c, vec3(0.0))); }

// Hill 2016 (BakingLab ACES.hlsl). GLSL mat3 takes columns: these are the transposes of the rows
// printed in core/image/ToneMap.cpp.
vec3 toneMapAcesHill(vec3 c)
{
    const mat3 inputMatrix = mat3(0.59719, 0.07600, 0.02840, 0.35458, 0.90834, 0.13383, 0.04823, 0.01566, 0.83777);
    const mat3 outputMatrix
        = mat3(1.60475, -0.10208, -0.00327, -0.53108, 1.10813, -0.07276, -0.07367, -0.00605, 1.07602);
    vec3 v = inputMatrix * max(c, vec3(0.0));
    vec3 a = v * (v + 0.0245786) - 0.000090537;
    vec3 b = v * (0.983729 * v + 0.4329510) + 0.238081;
    return clamp(outputMatrix * (a / b), 0.0, 1.0);
}

// Khronos PBR Neutral specification, reference GLSL.
vec3 toneMapKhronosPbrNeutral(vec3 color)
{
    const float startCompression = 0.8 - 0.04;
    const float desaturation = 0.15;
    color = max(color, vec3(0.0));
    float x = min(color.r, min(color.g, color.b));
    float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
    color -= offset;
    float peak = max(color.r, max(color.g, color.b));
    if (peak < startCompression)
        return clamp(color, 0.0, 1.0);
    const float d = 1.0 - startCompression;
    float newPeak = 1.0 - d * d / (peak + d - startCompression);
    color *= newPeak / peak;
    float g = 1.0 - 1.0 / (desaturation * (peak - newPeak) + 1.0);
    return clamp(mix(color, vec3(newPeak), g), 0.0, 1.0);
}

// Wrensch 2023, "Minimal AgX Implementation", decoded to display-linear with pow(2.2).
vec3 toneMapAgx(vec3 c)
{
    const mat3 inset = mat3(0.842479062253094, 0.0423282422610123, 0.0423756549057051, 0.0784335999999992,
                            0.878468636469772, 0.0784336, 0.0792237451477643, 0.0791661274605434, 0.879142973793104);
    const mat3 outset = mat3(1.19687900512017, -0.0528968517574562, -0.0529716355144438, -0.0980208811401368,
                             1.15190312990417, -0.0980434501171241, -0.0990297440797205, -0.0989611768448433,
                             1.15107367264116);
    const float minEv = -12.47393;
    const float maxEv = 4.026069;
    vec3 v = inset * max(c, vec3(0.0));
    v = max(v, vec3(1e-10));
    v = clamp(log2(v), minEv, maxEv);
    v = (v - minEv) / (maxEv - minEv);
    vec3 x2 = v * v;
    vec3 x4 = x2 * x2;
    v = 15.5 * x4 * x2 - 40.14 * x4 * v + 31.96 * x4 - 6.868 * x2 * v + 0.4298 * x2 + 0.1191 * v - 0.00232;
    v = outset * v;
    return clamp(pow(max(v, vec3(0.0)), vec3(2.2)), 0.0, 1.0);
}

// core ToneMapper order: none, reinhard, exposure, aces, khronos-neutral, agx.
vec3 toneMap(int mapper, vec3 c)
{
    if (mapper == 1)
        return toneMapReinhard(c);
    if (mapper == 2)
        return toneMapExposure(c);
    if (mapper == 3)
        return toneMapAcesHill(c);
    if (mapper == 4)
        return toneMapKhronosPbrNeutral(c);
    if (mapper == 5)
        return toneMapAgx(c);
    return toneMapNone(c);
}

// IEC 61966-2-1 piecewise sRGB encoding.
float linearToSrgb(float x)
{
    x = clamp(x, 0.0, 1.0);
    return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

// encoding 0: sRGB, 1: pure gamma (core DisplayEncoding).
vec3 encodeDisplay(vec3 c, int encoding, float gamma)
{
    c = clamp(c, 0.0, 1.0);
    if (encoding == 0)
        return vec3(linearToSrgb(c.r), linearToSrgb(c.g), linearToSrgb(c.b));
    return pow(c, vec3(1.0 / max(gamma, 1e-3)));
}
