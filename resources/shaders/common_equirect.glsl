// Direction <-> equirect mapping of docs/architecture.md; twins of core/ibl/Environment.h.
//   u = atan2(d.z, d.x) / (2 pi) + 0.5,   v = asin(d.y) / pi + 0.5,   v = 1 is the image's TOP row.
// Facet uploads Image rows top row first, so GL texture coordinate t = 0 is the image's top:
// sample an uploaded equirect at equirectTexCoord(d) = (u, 1 - v).
#include "common_math.glsl"

// The latitude is atan(y, |xz|) rather than asin(y) (the same for a unit d): Mesa's asin is a
// polynomial fit that is off by up to 3.9e-4 rad (measured on llvmpipe: v off by 1.2e-4, a third
// of a texel row of a 2048-row map; tests/EnvironmentSamplingGLTest.cpp), its atan by about 1e-6.
vec2 equirectUvFromDirection(vec3 d)
{
    return vec2(atan(d.z, d.x) / TWO_PI + 0.5, atan(d.y, length(d.xz)) / PI + 0.5);
}

vec3 directionFromEquirectUv(vec2 uv)
{
    float phi = TWO_PI * (uv.x - 0.5);
    float lat = PI * (uv.y - 0.5);
    return vec3(cos(lat) * cos(phi), sin(lat), cos(lat) * sin(phi));
}

// GL texture coordinate of direction d in an equirect uploaded top row first.
vec2 equirectTexCoord(vec3 d)
{
    vec2 uv = equirectUvFromDirection(d);
    return vec2(uv.x, 1.0 - uv.y);
}
