// Test fixture (tests/ShaderProgramGLTest.cpp): includes a chunk that does not exist.
#include "common_math.glsl"
#include "no_such_chunk.glsl"
out vec4 fragColor;
void main() { fragColor = vec4(PI); }
