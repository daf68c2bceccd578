// Test helper: writes cubemapDirection(uFace, uv) and the equirect mapping of it, so
// tests/IblGLTest.cpp can hold the GLSL and C++ twins together.
#include "common_cubemap.glsl"
#include "common_equirect.glsl"

uniform int uFace;
in vec2 vUv;
out vec4 fragColor;

void main()
{
    vec3 d = cubemapDirection(uFace, vUv);
#ifdef DEBUG_EQUIRECT_UV
    fragColor = vec4(equirectUvFromDirection(d), directionFromEquirectUv(equirectUvFromDirection(d)).y, 1.0);
#else
    fragColor = vec4(d, 1.0);
#endif
}
