// The IBL precompute on the GPU (render/IblPrecompute) against its CPU twins in core/: cubemap
// orientation, equirect -> cube, irradiance (map and SH9 against brute force), prefiltered
// specular, no sparkle under a 1e6 sun, finiteness, and a wide map area-filtered for the cube.
// Needs a GL context (EGL, no display server). Sizes and sample counts are small: llvmpipe on 2
// cores. docs/ibl.md quotes the numbers this prints. The DFG LUT and the caches: IblCacheGLTest.

#include <epoxy/gl.h> // before any header that could pull in <GL/gl.h>

#include "core/ibl/Environment.h"
#include "core/ibl/Irradiance.h"
#include "core/ibl/Prefilter.h"
#include "core/ibl/SphericalHarmonics.h"
#include "core/shading/Brdf.h"
#include "render/Framebuffer.h"
#include "render/HeadlessGLContext.h"
#include "render/IblPrecompute.h"
#include "render/ShaderProgram.h"

#include "IblGLTestSupport.h"
#include "TestSupport.h"

#include <QtTest/QTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

using namespace facet;
using facet::test::Level;
using facet::test::readLevel;
using facet::test::smallSettings;

namespace {

glm::dvec3 texelDirection(int face, int x, int y, int size)
{
    return cubemapDirection(face, (x + 0.5) / size, (y + 0.5) / size);
}

double maxComponent(const glm::dvec3& v)
{
    return std::max({v.x, v.y, v.z});
}
double luminance(const glm::dvec3& v)
{
    return 0.2126 * v.x + 0.7152 * v.y + 0.0722 * v.z;
}

bool allFinite(const std::vector<float>& values)
{
    return std::all_of(values.begin(), values.end(), [](float v) { return std::isfinite(v); });
}

} // namespace

class IblGLTest : public QObject, protected facet::test::IblGLFixture {
    Q_OBJECT
public:
    static void initMain() { facet::test::forgetDisplayServer(); }

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();

    void cubemapDirectionTwinsAgree();
    void equirectToCubeMatchesEnvironment();
    void faceOrientation();
    void whiteFurnace();
    void irradianceAgainstBruteForce();
    void irradianceAgainstBruteForceStudioHdri();
    void prefilterAgainstCpu();
    void prefilterAgainstCpuHdri();
    void noSparkleUnderASun();
    void finiteFromNanInput();
    void wideMapIsAreaFilteredForTheCube();
};

void IblGLTest::initTestCase()
{
    initIblFixture();
}

void IblGLTest::cleanupTestCase()
{
    cleanupIblFixture();
}

void IblGLTest::cubemapDirectionTwinsAgree()
{
    std::string error;
    std::optional<ShaderProgram> program = ShaderProgram::create("direction",
        {{ShaderStageSource::Stage::Vertex, "ibl_fullscreen.vert"},
            {ShaderStageSource::Stage::Fragment, "ibl_debug_direction.frag"}},
        {}, &error);
    QVERIFY2(program, error.c_str());
    const int n = 8;
    std::optional<Framebuffer> target = Framebuffer::create(n, n, FramebufferFormat::RGBA32F, &error);
    QVERIFY2(target, error.c_str());
    GLuint vao = 0;
    glGenVertexArrays(1, &vao);
    double worst = 0.0;
    for (int face = 0; face < 6; ++face) {
        target->bind();
        glBindVertexArray(vao);
        program->use();
        program->setInt("uFace", face);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        const Image image = target->readPixels(); // top row first: GL row = n - 1 - image row
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const glm::dvec3 gpu(image.at(x, n - 1 - y));
                const glm::dvec3 cpu = texelDirection(face, x, y, n);
                worst = std::max(worst, glm::length(gpu - cpu));
                double u = 0.0, v = 0.0;
                QCOMPARE(cubemapFace(cpu, &u, &v), face);
                QVERIFY(std::abs(u - (x + 0.5) / n) < 1e-12 && std::abs(v - (y + 0.5) / n) < 1e-12);
            }
    }
    glDeleteVertexArrays(1, &vao);
    QVERIFY2(worst < 1e-6, std::to_string(worst).c_str()); // float vs double normalisation
    // The spec's table 8.19 at face centres: +X, -X, +Y, -Y, +Z, -Z.
    QCOMPARE(cubemapDirection(0, 0.5, 0.5), glm::dvec3(1, 0, 0));
    QCOMPARE(cubemapDirection(3, 0.5, 0.5), glm::dvec3(0, -1, 0));
    QCOMPARE(cubemapDirection(5, 0.5, 0.5), glm::dvec3(0, 0, -1));
    // +X face: s grows towards -Z, t grows towards -Y.
    QVERIFY(cubemapDirection(0, 1.0, 0.5).z < 0.0 && cubemapDirection(0, 0.5, 1.0).y < 0.0);
}

void IblGLTest::equirectToCubeMatchesEnvironment()
{
    Environment env = Environment::builtin(Environment::Builtin::Sky, 128);
    if (qEnvironmentVariableIsSet("IBL_DEBUG_HDRI")) {
        std::string e;
        env = *Environment::load(facet::test::hdriPath(QStringLiteral("studio")).toStdString(), &e);
    }
    IblStats stats;
    std::string error;
    const auto ibl = m_ibl->prepare(env, smallSettings(), &stats, &error);
    QVERIFY2(ibl, error.c_str());
    QCOMPARE(stats.passesRun, 3); // equirect->cube, prefilter, irradiance (the DFG LUT is dfgTable's)
    double worst = 0.0;
    for (int face = 0; face < 6; ++face) {
        const Level level = readLevel(ibl->environment, face, 0);
        QCOMPARE(level.width, 32);
        for (int y = 0; y < level.height; y += 3)
            for (int x = 0; x < level.width; x += 3) {
                const glm::dvec3 d = texelDirection(face, x, y, level.width);
                const glm::dvec3 expected = env.radiance(d);
                const glm::dvec3 actual = level.at(x, y);
                // Both bilinear at the same direction. What remains: fp16 storage (2^-11 relative)
                // and llvmpipe's 8-bit bilinear weights (up to 1/256 of the difference between the
                // 4 texels mixed). So the error is measured against 2^-10 |expected| plus 1/128 of
                // the local range (the 4 nearest equirect texels).
                glm::dvec3 lo(1e30), hi(-1e30);
                const glm::dvec2 uv = equirectUvFromDirection(d);
                for (double du : {-0.5, 0.5})
                    for (double dv : {-0.5, 0.5}) {
                        const glm::dvec3 c
                            = env.radianceNearest(directionFromEquirectUv({uv.x + du / env.image().width(),
                                std::clamp(uv.y + dv / env.image().height(), 0.0, 1.0)}));
                        lo = glm::min(lo, c);
                        hi = glm::max(hi, c);
                    }
                const glm::dvec3 allowed = glm::abs(expected) / 1024.0 + (hi - lo) / 128.0 + 1e-6;
                const double e = maxComponent(glm::abs(actual - expected) / allowed);
                if (e > worst && qEnvironmentVariableIsSet("IBL_DEBUG"))
                    qInfo("face %d texel %d,%d dir %s expected %s actual %s", face, x, y,
                        facet::test::describe(texelDirection(face, x, y, level.width)).c_str(),
                        facet::test::describe(expected).c_str(), facet::test::describe(actual).c_str());
                worst = std::max(worst, e);
            }
    }
    qInfo("equirect->cube: max error / allowed = %.3g", worst);
    QVERIFY2(worst < 1.0, std::to_string(worst).c_str());
}

void IblGLTest::faceOrientation()
{
    // Each equirect texel holds 1 + the index of the cube face its direction falls on.
    Image image(64, 32);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x) {
            const glm::dvec3 d = equirectTexelDirection(x, y, 64, 32);
            image.at(x, y) = glm::vec4(float(cubemapFace(d, nullptr, nullptr) + 1), 0.0f, 0.0f, 1.0f);
        }
    const Environment env(std::move(image), "faces");
    std::string error;
    const auto ibl = m_ibl->prepare(env, smallSettings(), nullptr, &error);
    QVERIFY2(ibl, error.c_str());
    for (int face = 0; face < 6; ++face) {
        const Level level = readLevel(ibl->environment, face, 0);
        // The middle of the face, well away from the face edges where bilinear mixes faces.
        for (int y = 12; y < 20; ++y)
            for (int x = 12; x < 20; ++x)
                QVERIFY2(level.at(x, y).x == face + 1,
                    ("face " + std::to_string(face) + " texel " + std::to_string(x) + "," + std::to_string(y)
                        + " shows " + facet::test::describe(level.at(x, y)))
                        .c_str());
    }
}

void IblGLTest::whiteFurnace()
{
    const Environment env = Environment::uniform(glm::dvec3(1.0));
    std::string error;
    const auto ibl = m_ibl->prepare(env, smallSettings(), nullptr, &error);
    QVERIFY2(ibl, error.c_str());
    for (int face = 0; face < 6; ++face) {
        for (int level = 0; level < ibl->prefilteredMipLevels; ++level) {
            const Level pre = readLevel(ibl->prefiltered, face, level);
            for (int i = 0; i < pre.width * pre.height; ++i)
                QVERIFY(std::abs(pre.at(i % pre.width, i / pre.width).x - 1.0) < 1e-3);
        }
        const Level irr = readLevel(ibl->irradiance, face, 0);
        for (int i = 0; i < irr.width * irr.height; ++i) {
            const double e = irr.at(i % irr.width, i / irr.width).y;
            // Stored irradiance E = pi L (not divided by pi). Half floats near pi are 0.002 apart,
            // and the 8x8 quadrature's cosine-at-centre error is ~0.1%.
            QVERIFY2(std::abs(e - shading::kPi) < 5e-3, std::to_string(e).c_str());
        }
    }
    QVERIFY(std::abs(double(ibl->irradianceSH[0].x) * sh::K0 - shading::kPi) < 1e-3);
}

namespace {

// Errors of the irradiance map and of SH9 against brute force, over the texel centres of the map.
struct IrradianceErrors {
    double mapWorst = 0.0, mapMean = 0.0;
    double shMin = 0.0, shMax = 0.0, shMeanAbs = 0.0;
};

IrradianceErrors irradianceErrors(const Environment& env, const IblTextures& ibl)
{
    const IrradianceIntegrator integrator(env);
    IrradianceErrors r;
    std::vector<glm::dvec3> normals;
    std::vector<glm::dvec3> gpu;
    for (int face = 0; face < 6; ++face) {
        const Level level = readLevel(ibl.irradiance, face, 0);
        for (int y = 0; y < level.height; ++y)
            for (int x = 0; x < level.width; ++x) {
                normals.push_back(texelDirection(face, x, y, level.width));
                gpu.push_back(level.at(x, y));
            }
    }
    const std::vector<glm::dvec3> truth = integrator.irradiance(normals);
    IrradianceSH9 sh;
    for (std::size_t i = 0; i < 9; ++i)
        sh.c[i] = glm::dvec3(ibl.irradianceSH[i]);
    r.shMin = std::numeric_limits<double>::max();
    r.shMax = -std::numeric_limits<double>::max();
    for (std::size_t i = 0; i < normals.size(); ++i) {
        const double t = luminance(truth[i]);
        const double mapError = luminance(gpu[i]) / t - 1.0;
        const double shError = luminance(irradianceSH(sh, normals[i])) / t - 1.0;
        if (std::abs(mapError) > r.mapWorst && qEnvironmentVariableIsSet("IBL_DEBUG"))
            qInfo("n %s truth %s gpu %s sh %s", facet::test::describe(normals[i]).c_str(),
                facet::test::describe(truth[i]).c_str(), facet::test::describe(gpu[i]).c_str(),
                facet::test::describe(irradianceSH(sh, normals[i])).c_str());
        r.mapWorst = std::max(r.mapWorst, std::abs(mapError));
        r.mapMean += std::abs(mapError);
        r.shMin = std::min(r.shMin, shError);
        r.shMax = std::max(r.shMax, shError);
        r.shMeanAbs += std::abs(shError);
    }
    r.mapMean /= double(normals.size());
    r.shMeanAbs /= double(normals.size());
    return r;
}

} // namespace

void IblGLTest::irradianceAgainstBruteForce()
{
    const Environment env = Environment::builtin(Environment::Builtin::Studio, 256);
    IblSettings settings = smallSettings();
    settings.cubeSize = 64;
    settings.irradianceSamples = 1536; // 16x16 texels a face
    std::string error;
    const auto ibl = m_ibl->prepare(env, settings, nullptr, &error);
    QVERIFY2(ibl, error.c_str());
    const IrradianceErrors e = irradianceErrors(env, *ibl);
    qInfo("builtin studio irradiance vs brute force (luminance): map max |err| %.2f%% mean %.2f%%; "
          "SH9 err %.1f%% .. %+.1f%%, mean |err| %.1f%%",
        100 * e.mapWorst, 100 * e.mapMean, 100 * e.shMin, 100 * e.shMax, 100 * e.shMeanAbs);
    // The map sums a 16x16 level (box-filtered) with exact texel solid angles; measured 0.37% max:
    // the cosine varies across the coarse texels, fp16 storage adds 0.05%.
    QVERIFY2(e.mapWorst < 0.01, std::to_string(e.mapWorst).c_str());
    QVERIFY2(e.mapMean < 0.005, std::to_string(e.mapMean).c_str());
}

void IblGLTest::irradianceAgainstBruteForceStudioHdri()
{
    const QString path = facet::test::hdriPath(QStringLiteral("studio"));
    FACET_REQUIRE_ASSET(path, "hdri/studio.exr");
    std::string error;
    const std::optional<Environment> env = Environment::load(path.toStdString(), &error);
    QVERIFY2(env, error.c_str());
    IblSettings settings = smallSettings();
    settings.cubeSize = 128;
    settings.irradianceSize = 8;
    settings.irradianceSamples = 1536;
    const auto ibl = m_ibl->prepare(*env, settings, nullptr, &error);
    QVERIFY2(ibl, error.c_str());
    const IrradianceErrors e = irradianceErrors(*env, *ibl);
    qInfo("studio.exr irradiance vs brute force (luminance): map max |err| %.2f%% mean %.2f%%; "
          "SH9 err %.1f%% .. %+.1f%%, mean |err| %.1f%%",
        100 * e.mapWorst, 100 * e.mapMean, 100 * e.shMin, 100 * e.shMax, 100 * e.shMeanAbs);
    // A high-contrast HDRI: the map stays within a few per cent, SH9 does not (docs/irradiance.md).
    // Measured: max 17.9% (the darkest normals, where a 16x16-level texel that straddles the
    // horizon holds a light), mean 0.9%.
    QVERIFY2(e.mapWorst < 0.25, std::to_string(e.mapWorst).c_str());
    QVERIFY2(e.mapMean < 0.02, std::to_string(e.mapMean).c_str());
    QVERIFY2(e.shMeanAbs > e.mapMean, "SH9 was expected to be worse than the map on studio");
}

namespace {

// GPU prefiltered texels against the CPU twin with many samples (a near-exact convolution) at a
// few texels of every level >= 1. Returns the worst relative error (luminance) per level.
// The error is relative to max(reference, mean radiance of the environment): where a texel is
// much darker than the environment's average (next to a bright light), a relative error says
// nothing about what a viewer sees.
std::vector<double> prefilterErrors(const Environment& env, const IblTextures& ibl, int cpuSamples)
{
    const double mean = luminance(projectEquirect(env).c[0] * sh::K0);
    std::vector<double> worst(std::size_t(ibl.prefilteredMipLevels), 0.0);
    for (int level = 1; level < ibl.prefilteredMipLevels; ++level) {
        const double roughness = roughnessFromLod(level, ibl.prefilteredMipLevels);
        for (int face = 0; face < 6; ++face) {
            const Level gpu = readLevel(ibl.prefiltered, face, level);
            const int step = std::max(gpu.width / 3, 1);
            for (int y = step / 2; y < gpu.height; y += step)
                for (int x = step / 2; x < gpu.width; x += step) {
                    const glm::dvec3 cpu = prefilteredRadiance(
                        env, texelDirection(face, x, y, gpu.width), roughness, cpuSamples);
                    const double e
                        = std::abs(luminance(gpu.at(x, y)) - luminance(cpu)) / std::max(luminance(cpu), mean);
                    worst[std::size_t(level)] = std::max(worst[std::size_t(level)], e);
                }
        }
    }
    return worst;
}

} // namespace

void IblGLTest::prefilterAgainstCpu()
{
    const Environment env = Environment::builtin(Environment::Builtin::Sky, 128);
    IblSettings settings = smallSettings();
    settings.cubeSize = 64;
    settings.prefilterSize = 32;
    settings.prefilterMipLevels = 5;
    settings.prefilterSamples = 128;
    std::string error;
    const auto ibl = m_ibl->prepare(env, settings, nullptr, &error);
    QVERIFY2(ibl, error.c_str());
    const std::vector<double> worst = prefilterErrors(env, *ibl, 2048);
    for (std::size_t level = 1; level < worst.size(); ++level) {
        qInfo("sky prefilter level %zu (roughness %.2f): max relative error %.2f%%", level,
            roughnessFromLod(int(level), settings.prefilterMipLevels), 100 * worst[level]);
        // Smooth sky with a soft sun: 128 filtered samples vs 2048 plain ones. Levels 1-4 hold
        // roughness 0.13, 0.29, 0.5, 1 (render/IblTextures.h roughnessFromLod). Measured 14, 15,
        // 18, 35% (with the earlier linear map, roughness 0.25, 0.5, 0.75, 1: 5, 20, 36, 35%):
        // the filtered lookups' footprints
        // (Omega_s = 1 / (N pdf), doubled by Krivanek's +1 bias) blur the sun and, near the
        // lobe's horizon, read light from below it. The bounds catch regressions and orientation
        // or scale mistakes (errors of order 100%); docs/ibl.md discusses the bias.
        const double bound[] = {0.0, 0.20, 0.30, 0.45, 0.45};
        QVERIFY2(worst[level] < bound[std::min<std::size_t>(level, 4)], std::to_string(worst[level]).c_str());
    }
}

void IblGLTest::prefilterAgainstCpuHdri()
{
    const QString path = facet::test::hdriPath(QStringLiteral("studio"));
    FACET_REQUIRE_ASSET(path, "hdri/studio.exr");
    std::string error;
    const std::optional<Environment> env = Environment::load(path.toStdString(), &error);
    QVERIFY2(env, error.c_str());
    IblSettings settings = smallSettings();
    settings.cubeSize = 128;
    settings.prefilterSize = 32;
    settings.prefilterMipLevels = 5;
    settings.prefilterSamples = 128;
    const auto ibl = m_ibl->prepare(*env, settings, nullptr, &error);
    QVERIFY2(ibl, error.c_str());
    const std::vector<double> worst = prefilterErrors(*env, *ibl, 4096);
    for (std::size_t level = 1; level < worst.size(); ++level) {
        qInfo("studio.exr prefilter level %zu (roughness %.2f): max relative error %.2f%%", level,
            roughnessFromLod(int(level), settings.prefilterMipLevels), 100 * worst[level]);
        // High contrast (small lights thousands of times the background): the filtered lookups
        // spread the lights over their footprints, so the GPU is far off next to a light. Each
        // level's bound is its measured worst texel on llvmpipe (Mesa 22.3: 78.0%, 80.1%, 84.0%,
        // 89.1%) plus an eighth of it for another driver's filtering; it was a flat 160% before.
        const double bound[] = {0.0, 0.88, 0.90, 0.95, 1.00};
        QVERIFY2(worst[level] < bound[std::min<std::size_t>(level, 4)], std::to_string(worst[level]).c_str());
    }
}

void IblGLTest::noSparkleUnderASun()
{
    Image image(128, 64, glm::vec4(0.1f, 0.1f, 0.1f, 1.0f));
    image.at(40, 20) = glm::vec4(1e6f, 1e6f, 1e6f, 1.0f);
    const Environment env(std::move(image), "sun");
    IblSettings settings = smallSettings();
    settings.cubeSize = 64;
    settings.prefilterSize = 32;
    settings.prefilterMipLevels = 5; // level 3 = roughness 0.5 (roughnessFromLod)
    settings.prefilterSamples = 64;
    std::string error;
    const auto ibl = m_ibl->prepare(env, settings, nullptr, &error);
    QVERIFY2(ibl, error.c_str());
    double worstRatio = 0.0;
    for (int face = 0; face < 6; ++face) {
        const Level level = readLevel(ibl->prefiltered, face, 3);
        QVERIFY(allFinite(level.rgba));
        for (int y = 1; y + 1 < level.height; ++y)
            for (int x = 1; x + 1 < level.width; ++x) {
                std::vector<double> around;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx)
                        if (dx || dy)
                            around.push_back(level.at(x + dx, y + dy).x);
                std::nth_element(around.begin(), around.begin() + 4, around.end());
                worstRatio = std::max(worstRatio, level.at(x, y).x / around[4]);
            }
    }
    qInfo("1e6 sun, roughness 0.5: max texel / median of its 8 neighbours = %.2f", worstRatio);
    // Without mip filtering single samples hitting the sun give isolated texels thousands of
    // times their neighbours; a smooth lobe changes by at most a few times per texel.
    QVERIFY2(worstRatio < 4.0, std::to_string(worstRatio).c_str());
}

void IblGLTest::finiteFromNanInput()
{
    Image image(64, 32, glm::vec4(0.5f));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    image.at(3, 3) = glm::vec4(nan, 1.0f, 1.0f, 1.0f);
    image.at(10, 20) = glm::vec4(inf, inf, -inf, 1.0f);
    image.at(30, 5) = glm::vec4(-5.0f, 1e30f, 0.0f, 1.0f);
    const Environment env(std::move(image), "bad"); // sanitised by the constructor
    std::string error;
    const auto ibl = m_ibl->prepare(env, smallSettings(), nullptr, &error);
    QVERIFY2(ibl, error.c_str());
    for (int face = 0; face < 6; ++face) {
        for (int level = 0; level < ibl->environmentMipLevels; ++level)
            QVERIFY(allFinite(readLevel(ibl->environment, face, level).rgba));
        for (int level = 0; level < ibl->prefilteredMipLevels; ++level)
            QVERIFY(allFinite(readLevel(ibl->prefiltered, face, level).rgba));
        QVERIFY(allFinite(readLevel(ibl->irradiance, face, 0).rgba));
    }
    for (const glm::vec3& c : ibl->irradianceSH)
        QVERIFY(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z));
}

// A map far wider than the cube needs: vertical stripes of 0 and 2, one texel each, 1024 wide
// for a 32 cube (4 x 32 = 128 needed). Bilinear reads straight from the map land anywhere between
// 0 and 2 (aliasing: what a cube texel shows depends on where its centre falls); the area filter
// to 128 wide first gives every cube texel the stripes' mean, 1.
void IblGLTest::wideMapIsAreaFilteredForTheCube()
{
    Image stripes(1024, 512);
    for (int y = 0; y < stripes.height(); ++y)
        for (int x = 0; x < stripes.width(); ++x)
            stripes.at(x, y) = glm::vec4(glm::vec3(x % 2 ? 2.0f : 0.0f), 1.0f);
    const Environment env(std::move(stripes), "stripes");
    IblPrecompute precompute(QString(), false);
    IblStats stats;
    std::string error;
    const auto ibl = precompute.prepare(env, smallSettings(), &stats, &error);
    QVERIFY2(ibl, error.c_str());
    QCOMPARE(stats.sourceReductions, 1);
    double lowest = 1e30, highest = -1e30;
    for (int face = 0; face < 6; ++face) {
        const Level level = readLevel(ibl->environment, face, 0);
        for (int y = 0; y < level.height; ++y)
            for (int x = 0; x < level.width; ++x) {
                lowest = std::min(lowest, level.at(x, y).x);
                highest = std::max(highest, level.at(x, y).x);
            }
    }
    qInfo("cube texels of 0/2 stripes: %.4f to %.4f", lowest, highest);
    QVERIFY2(
        lowest > 0.99 && highest < 1.01, qPrintable(QStringLiteral("%1 to %2").arg(lowest).arg(highest)));
    // A map no wider than needed is read as it is.
    const Environment narrow = Environment::builtin(Environment::Builtin::Sky, 128);
    QVERIFY2(precompute.prepare(narrow, smallSettings(), &stats, &error), error.c_str());
    QCOMPARE(stats.sourceReductions, 0);
}

QTEST_GUILESS_MAIN(IblGLTest)
#include "IblGLTest.moc"
