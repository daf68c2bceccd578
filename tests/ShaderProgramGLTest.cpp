// render/ShaderProgram: assembly (version, defines, includes, #line), driver-log mapping, compile
// and link errors that name the file and line, and uniform setters. Needs a GL context (EGL,
// no display server).

#include <epoxy/gl.h> // before any header that could pull in <GL/gl.h>

#include "render/Framebuffer.h"
#include "render/HeadlessGLContext.h"
#include "render/ShaderProgram.h"

#include <QtTest/QTest>

#include "TestSupport.h"

#include <optional>
#include <string>

using namespace facet;

namespace {

const std::vector<ShaderStageSource> kUniformStages = {
    {ShaderStageSource::Stage::Vertex, "ibl_fullscreen.vert"},
    {ShaderStageSource::Stage::Fragment, "ibl_test_uniforms.frag"},
};

// Draws a full-viewport triangle with `program` into a fresh 4x4 RGBA32F target; returns pixel (1, 2).
glm::vec4 renderOnePixel(const ShaderProgram& program)
{
    std::string error;
    std::optional<Framebuffer> target = Framebuffer::create(4, 4, FramebufferFormat::RGBA32F, &error);
    if (!target)
        return glm::vec4(-1.0f);
    target->clear(glm::vec4(0.0f));
    GLuint vao = 0;
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glDisable(GL_DEPTH_TEST);
    program.use();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDeleteVertexArrays(1, &vao);
    return target->readPixels().at(1, 2);
}

} // namespace

class ShaderProgramGLTest : public QObject {
    Q_OBJECT
public:
    static void initMain()
    {
        facet::test::forgetDisplayServer();
    }

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase() { m_context.reset(); }

    void assemblesVersionDefinesAndIncludesOnce();
    void missingIncludeIsAClearError();
    void missingStageFileIsAClearError();
    void mapsMesaAndNvidiaLogs();
    void compileErrorNamesTheIncludedChunk();
    void definesSwitchCodePaths();
    void uniformsReachTheShader();
    void moveKeepsTheProgram();
    void iblShadersCompile();

private:
    std::optional<HeadlessGLContext> m_context;
};

void ShaderProgramGLTest::initTestCase()
{
    std::string error;
    m_context = HeadlessGLContext::create(&error);
    QVERIFY2(m_context, error.c_str());
}

void ShaderProgramGLTest::assemblesVersionDefinesAndIncludesOnce()
{
    std::string error;
    const std::optional<AssembledShader> shader
        = assembleShader("brdf_ggx.glsl", {"FOO", "BAR 3"}, "#version 410 core", &error);
    QVERIFY2(shader, error.c_str());
    const std::string& s = shader->source;
    QVERIFY(s.rfind("#version 410 core\n#define FOO\n#define BAR 3\n", 0) == 0);
    // brdf_common.glsl and common_math.glsl are included by every brdf chunk: once each.
    auto count = [&s](const std::string& needle) {
        int n = 0;
        for (std::size_t at = s.find(needle); at != std::string::npos; at = s.find(needle, at + 1))
            ++n;
        return n;
    };
    QCOMPARE(count("float pow5(float x)"), 1);
    QCOMPARE(count("float clampRoughness("), 1);
    QCOMPARE(count("float D_GGX("), 1);
    QCOMPARE(count("#include"), 0);
    // Every file has an id, and a "#line 1 <id>" opens it.
    for (std::size_t id = 1; id < shader->fileNames.size(); ++id)
        QVERIFY2(s.find("#line " + std::to_string(id * 100000 + 1) + " " + std::to_string(id) + "\n") != std::string::npos, shader->fileNames[id].c_str());
    QCOMPARE(shader->fileNames[1], std::string("brdf_ggx.glsl"));
    QVERIFY(std::find(shader->fileNames.begin(), shader->fileNames.end(), "common_math.glsl") != shader->fileNames.end());
}

void ShaderProgramGLTest::missingIncludeIsAClearError()
{
    std::string error;
    QVERIFY(!assembleShader("ibl_test_missing_include.frag", {}, "#version 410 core", &error));
    QVERIFY2(error.find("ibl_test_missing_include.frag:3: cannot include \"no_such_chunk.glsl\"") != std::string::npos,
        error.c_str());

    error.clear();
    QVERIFY(!ShaderProgram::create("missing",
        {{ShaderStageSource::Stage::Vertex, "ibl_fullscreen.vert"},
         {ShaderStageSource::Stage::Fragment, "ibl_test_missing_include.frag"}},
        {}, &error));
    QVERIFY2(error.rfind("ShaderProgram missing: ibl_test_missing_include.frag:3: cannot include", 0) == 0, error.c_str());
}

void ShaderProgramGLTest::missingStageFileIsAClearError()
{
    std::string error;
    QVERIFY(!ShaderProgram::create("nofile", {{ShaderStageSource::Stage::Fragment, "no_such_stage.frag"}}, {}, &error));
    QVERIFY2(error.rfind("ShaderProgram nofile: cannot read shader \"no_such_stage.frag\"", 0) == 0, error.c_str());
}

void ShaderProgramGLTest::mapsMesaAndNvidiaLogs()
{
    const std::vector<std::string> names = {"<defines>", "surface.frag", "brdf_ggx.glsl"};
    // Mesa / llvmpipe.
    QCOMPARE(mapShaderLog("0:12(5): error: `foo' undeclared\n", names),
        std::string("<defines>:12(5): error: `foo' undeclared"));
    QCOMPARE(mapShaderLog("2:7(13): error: syntax error\n1:3(1): warning: unused", names),
        std::string("brdf_ggx.glsl:7(13): error: syntax error\nsurface.frag:3(1): warning: unused"));
    // NVIDIA.
    QCOMPARE(mapShaderLog("1(42) : error C1008: undefined variable \"foo\"", names),
        std::string("surface.frag:42 : error C1008: undefined variable \"foo\""));
    // AMD / ANGLE style.
    QCOMPARE(mapShaderLog("ERROR: 2:9: 'x' : undeclared identifier", names),
        std::string("ERROR: brdf_ggx.glsl:9: 'x' : undeclared identifier"));
    // Lines offset by id * 100000 (ShaderProgram.cpp, kLineStride) name their file whatever
    // source number the driver printed (Mesa prints 0 inside expressions).
    QCOMPARE(mapShaderLog("0:200005(9): error: x", names), std::string("brdf_ggx.glsl:5(9): error: x"));
    QCOMPARE(mapShaderLog("2(100042) : error C0000: y", names), std::string("surface.frag:42 : error C0000: y"));
    // An id the program does not know stays a number; text without a location is kept.
    QCOMPARE(mapShaderLog("7:1(1): error: x", names), std::string("7:1(1): error: x"));
    QCOMPARE(mapShaderLog("linker error", names), std::string("linker error"));
}

void ShaderProgramGLTest::compileErrorNamesTheIncludedChunk()
{
    std::string error;
    const std::optional<ShaderProgram> program = ShaderProgram::create("broken",
        {{ShaderStageSource::Stage::Vertex, "ibl_fullscreen.vert"},
         {ShaderStageSource::Stage::Fragment, "ibl_test_broken.frag"}},
        {"SOME_DEFINE"}, &error);
    QVERIFY(!program);
    qInfo("%s", error.c_str());
    QVERIFY2(error.rfind("ShaderProgram broken: ibl_test_broken_chunk.glsl:5", 0) == 0, error.c_str());
    // Every line of the log names a file; none is left as a bare number or the preamble.
    QVERIFY2(error.find("<defines>") == std::string::npos, error.c_str());
    QVERIFY2(error.find("undeclaredIdentifierForTheTest") != std::string::npos, error.c_str());
}

void ShaderProgramGLTest::definesSwitchCodePaths()
{
    std::string error;
    std::optional<ShaderProgram> constant
        = ShaderProgram::create("constant", kUniformStages, {"TEST_CONSTANT_OUTPUT 0.75"}, &error);
    QVERIFY2(constant, error.c_str());
    QCOMPARE(renderOnePixel(*constant), glm::vec4(0.75f));

    std::optional<ShaderProgram> plain = ShaderProgram::create("plain", kUniformStages, {}, &error);
    QVERIFY2(plain, error.c_str());
    plain->setInt("uMode", 0);
    // saturate(-1) = 0, pow5(2) = 32 from common_math.glsl.
    QCOMPARE(renderOnePixel(*plain), glm::vec4(0.0f, 32.0f, 0.0f, 1.0f));
    // The constant variant has no uniforms left: setting one is a no-op, its location -1.
    QCOMPARE(constant->uniformLocation("uColor"), -1);
    constant->setVec4("uColor", 1.0f, 2.0f, 3.0f, 4.0f);
    QCOMPARE(glGetError(), GLenum(GL_NO_ERROR));
}

void ShaderProgramGLTest::uniformsReachTheShader()
{
    std::string error;
    std::optional<ShaderProgram> program = ShaderProgram::create("uniforms", kUniformStages, {}, &error);
    QVERIFY2(program, error.c_str());
    QVERIFY(program->isValid());
    QCOMPARE(program->name(), std::string("uniforms"));
    program->setInt("uMode", 1);
    program->setVec4("uColor", 0.5f, -2.0f, 1000.0f, 1.0f);
    program->setFloat("uScale", 2.0f);
    // The location is GL's, also when it comes from the cache (the second lookup), and a name the
    // program does not have is -1 (setting it is then a no-op, as GL's -1 is).
    const int location = program->uniformLocation("uColor");
    QVERIFY(location >= 0);
    QCOMPARE(location, glGetUniformLocation(program->id(), "uColor"));
    QCOMPARE(program->uniformLocation("uColor"), location);
    QCOMPARE(program->uniformLocation("uScale"), glGetUniformLocation(program->id(), "uScale"));
    QVERIFY(program->uniformLocation("uScale") != location);
    QCOMPARE(program->uniformLocation("uNoSuchUniform"), -1);
    QCOMPARE(renderOnePixel(*program), glm::vec4(1.0f, -4.0f, 2000.0f, 2.0f));
    program->setFloat("uScale", 0.5f);
    QCOMPARE(renderOnePixel(*program), glm::vec4(0.25f, -1.0f, 500.0f, 0.5f));
    QCOMPARE(glGetError(), GLenum(GL_NO_ERROR));
}

void ShaderProgramGLTest::moveKeepsTheProgram()
{
    std::string error;
    std::optional<ShaderProgram> program = ShaderProgram::create("moved", kUniformStages, {}, &error);
    QVERIFY2(program, error.c_str());
    const unsigned id = program->id();
    ShaderProgram moved = std::move(*program);
    QCOMPARE(moved.id(), id);
    QVERIFY(!program->isValid());
    QVERIFY(glIsProgram(id));
    moved.setInt("uMode", 1);
    moved.setVec4("uColor", 1.0f, 1.0f, 1.0f, 1.0f);
    moved.setFloat("uScale", 3.0f);
    QCOMPARE(renderOnePixel(moved), glm::vec4(3.0f));
}

void ShaderProgramGLTest::iblShadersCompile()
{
    // Every chunk compiles on its own inside a trivial fragment stage (catches typos in chunks
    // that no pass includes yet, e.g. brdf_fresnel.glsl for the surface shader).
    for (const char* stage : {"ibl_equirect_to_cube.frag", "ibl_dfg.frag", "ibl_prefilter.frag", "ibl_irradiance.frag",
                              "ibl_debug_direction.frag"}) {
        std::string error;
        const std::optional<ShaderProgram> program = ShaderProgram::create(stage,
            {{ShaderStageSource::Stage::Vertex, "ibl_fullscreen.vert"}, {ShaderStageSource::Stage::Fragment, stage}}, {},
            &error);
        QVERIFY2(program, error.c_str());
    }
}

QTEST_GUILESS_MAIN(ShaderProgramGLTest)
#include "ShaderProgramGLTest.moc"
