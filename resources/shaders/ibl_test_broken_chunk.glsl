// Test fixture (tests/ShaderProgramGLTest.cpp): line 5 has a deliberate compile error, so the
// error message must name this file and line 5.
float brokenChunkValue()
{
    return undeclaredIdentifierForTheTest * 2.0;
}
