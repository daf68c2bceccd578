// Test fixture (tests/ShaderProgramGLTest.cpp): uniforms and a define that switch the output.
#include "common_math.glsl"
// Not used below: included so that every shared chunk is compiled by a test.
#include "brdf_ggx.glsl"
#include "common_sampling.glsl"
#include "common_equirect.glsl"
#include "common_cubemap.glsl"
#include "ibl_lookup.glsl"
#include "ibl_filtering.glsl"
uniform vec4 uColor;
uniform float uScale;
uniform int uMode;
out vec4 fragColor;
void main()
{
#ifdef TEST_CONSTANT_OUTPUT
    fragColor = vec4(TEST_CONSTANT_OUTPUT);
#else
    fragColor = uMode == 1 ? uColor * uScale : vec4(saturate(-1.0), pow5(2.0), 0.0, 1.0);
#endif
}
