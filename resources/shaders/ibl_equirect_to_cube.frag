// Pass 1: resamples the equirect environment into one cubemap face (level 0). Bilinear
// (GL_LINEAR, REPEAT in s so that the u = 0/1 seam wraps, CLAMP_TO_EDGE in t), at level 0
// explicitly: implicit derivatives jump across the seam. docs/ibl.md.
#include "common_equirect.glsl"
#include "common_cubemap.glsl"

uniform sampler2D uEquirect;
uniform int uFace;
in vec2 vUv;
out vec4 fragColor;

void main()
{
    vec3 d = cubemapDirection(uFace, vUv);
    fragColor = vec4(textureLod(uEquirect, equirectTexCoord(d), 0.0).rgb, 1.0);
}
