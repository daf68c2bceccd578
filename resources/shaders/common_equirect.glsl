// Direction <-> equirect mapping of shared/DESIGN.md; twins of core/Environment.h.
//   u = atan2(d.z, d.x) / (2 pi) + 0.5,   v = asin(d.y) / pi + 0.5,   v = 1 is the image's TOP row.
// Facet uploads Image rows top row first, so GL texture coordinate t = 0 is the image's top:
// sample an uploaded equirect at equirectTexCoord(d) = (u, 1 - v).
#include "common_math.glsl"

vec2 equirectUvFromDirection(vec3 d)
{
    return vec2(atan(d.z, d.x) / TWO_PI + 0.5, asin(clamp(d.y, -1.0, 1.0)) / PI + 0.5);
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
