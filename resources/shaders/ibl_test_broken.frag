// Test fixture (tests/ShaderProgramGLTest.cpp): includes a chunk with an error.
#include "common_math.glsl"
#include "ibl_test_broken_chunk.glsl"
out vec4 fragColor;
void main() { fragColor = vec4(brokenChunkValue()); }
