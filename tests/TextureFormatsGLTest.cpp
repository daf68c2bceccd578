// render/TextureCache: each kind of map goes to the GPU in its own format (a row per format: R8,
// RG8 as grey + alpha and as red + green, RGB8, RGBA8, sRGB 8-bit with and without alpha and
// expanded from grey, 16-bit, 16-bit read as sRGB, half float, half read as sRGB), whole (get)
// and in slices (request + uploadSlice), and is sampled as the CPU twin reads it
// (core/shading/MaterialInputs texelValue: swizzle, sRGB decode) at level 0, and as the 2 x 2 average of
// those at level 1 (the mipmaps made band by band, render/MipChain). Also: a texture uploading in
// slices is not ready until its last band and get() never returns it half done; anisotropy is set
// on every texture and clamped; a map wider than GL_MAX_TEXTURE_SIZE is refused with its name;
// the anisotropy policy per GL implementation (render/TextureFiltering).

#include <epoxy/gl.h>

#include "core/image/MapImage.h"
#include "core/shading/MaterialInputs.h"
#include "render/Framebuffer.h"
#include "render/GLInfo.h"
#include "render/HeadlessGLContext.h"
#include "render/TextureCache.h"
#include "render/TextureFiltering.h"

#include "TestSupport.h"

#include <QtTest/QTest>

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

using namespace facet;

namespace {

// A GL 4.5 implementation named `renderer` (GL_RENDERER), for the filtering policies.
GLInfo glInfoOf(const QString& renderer, float maxAnisotropy = 16.0f)
{
    GLInfo info;
    info.major = 4;
    info.minor = 5;
    info.renderer = renderer.toStdString();
    info.softwareRasterizer = isSoftwareRendererName(info.renderer);
    info.maxAnisotropy = maxAnisotropy;
    return info;
}

constexpr int kWidth = 24;
constexpr int kHeight = 10;

struct FormatRow {
    const char* name;
    MapLayout layout;
    MapSampleType type;
    ColorEncoding colorSpace;
    GLenum internalFormat;
    double levelZeroBound; // |GPU - twin| at level 0: exact formats, and llvmpipe's sRGB table
    double levelOneBound;  // |GPU - average of the twin's texels| at level 1: + the level's rounding
};

const std::vector<FormatRow>& formatRows()
{
    // Bounds: 8-bit, 16-bit and half samples read exactly (1e-6: float conversion); sRGB 8-bit
    // decodes through llvmpipe's table (measured: at most 1.2e-3 from the exact curve); a mipmap
    // texel is rounded to its format: half an 8-bit step (0.002), half a 16-bit step (1e-5, plus
    // the float sum: 2e-5), a half float's relative 2^-11 (1e-3), and for sRGB 8-bit half a step of
    // the encoded value, up to 0.5 / 255 x 2.4 in linear light (0.005, + the table: 0.006).
    // Averaging sRGB texels in encoded values instead of linear light would be off by up to 0.2.
    static const std::vector<FormatRow> rows = {
        {"R8 (grey)", MapLayout::Grey, MapSampleType::UInt8, ColorEncoding::Linear, GL_R8, 1e-6, 0.002},
        {"RG8 (grey+alpha)", MapLayout::GreyAlpha, MapSampleType::UInt8, ColorEncoding::Linear, GL_RG8, 1e-6, 0.002},
        {"RG8 (red+green)", MapLayout::RedGreen, MapSampleType::UInt8, ColorEncoding::Linear, GL_RG8, 1e-6, 0.002},
        {"RGB8", MapLayout::Rgb, MapSampleType::UInt8, ColorEncoding::Linear, GL_RGB8, 1e-6, 0.002},
        {"RGBA8", MapLayout::Rgba, MapSampleType::UInt8, ColorEncoding::Linear, GL_RGBA8, 1e-6, 0.002},
        {"SRGB8", MapLayout::Rgb, MapSampleType::UInt8, ColorEncoding::SRGB, GL_SRGB8, 1.5e-3, 0.006},
        {"SRGB8_ALPHA8", MapLayout::Rgba, MapSampleType::UInt8, ColorEncoding::SRGB, GL_SRGB8_ALPHA8, 1.5e-3, 0.006},
        {"SRGB8 from grey", MapLayout::Grey, MapSampleType::UInt8, ColorEncoding::SRGB, GL_SRGB8, 1.5e-3, 0.006},
        {"SRGB8_ALPHA8 from grey+alpha", MapLayout::GreyAlpha, MapSampleType::UInt8, ColorEncoding::SRGB,
         GL_SRGB8_ALPHA8, 1.5e-3, 0.006},
        {"R16 (grey)", MapLayout::Grey, MapSampleType::UInt16, ColorEncoding::Linear, GL_R16, 1e-6, 2e-5},
        {"RGB16", MapLayout::Rgb, MapSampleType::UInt16, ColorEncoding::Linear, GL_RGB16, 1e-6, 2e-5},
        {"RGBA16", MapLayout::Rgba, MapSampleType::UInt16, ColorEncoding::Linear, GL_RGBA16, 1e-6, 2e-5},
        {"RGB16F from 16-bit sRGB", MapLayout::Rgb, MapSampleType::UInt16, ColorEncoding::SRGB, GL_RGB16F, 1e-6, 1e-3},
        {"R16F (grey)", MapLayout::Grey, MapSampleType::Half, ColorEncoding::Linear, GL_R16F, 1e-6, 1e-3},
        {"RG16F (red+green)", MapLayout::RedGreen, MapSampleType::Half, ColorEncoding::Linear, GL_RG16F, 1e-6, 1e-3},
        {"RGBA16F", MapLayout::Rgba, MapSampleType::Half, ColorEncoding::Linear, GL_RGBA16F, 1e-6, 1e-3},
        {"RGBA16F from half sRGB", MapLayout::Rgba, MapSampleType::Half, ColorEncoding::SRGB, GL_RGBA16F, 1e-6, 1e-3},
    };
    return rows;
}

// Distinct values per texel and channel; half maps get values beyond 1 too.
MapImage makeMap(const FormatRow& row)
{
    MapImage map(kWidth, kHeight, row.layout, row.type);
    const float scale = row.type == MapSampleType::Half && row.colorSpace == ColorEncoding::Linear ? 4.0f : 1.0f;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            for (int c = 0; c < map.channels(); ++c)
                map.setSample(x, y, c, scale * float(((x * 7 + y * 13 + c * 5) % 17) + 1) / 18.0f);
    return map;
}

const char* kVertex = R"(#version 410 core
void main()
{
    // One triangle over the viewport.
    vec2 p = vec2((gl_VertexID & 1) * 4 - 1, (gl_VertexID & 2) * 2 - 1);
    gl_Position = vec4(p, 0.0, 1.0);
}
)";
// Each pixel reads its texel's centre of `uLevel` (no filtering between texels, the swizzle and
// the sRGB decode apply).
const char* kFragment = R"(#version 410 core
uniform sampler2D uMap;
uniform int uLevel;
out vec4 color;
void main()
{
    vec2 size = vec2(textureSize(uMap, uLevel));
    color = textureLod(uMap, gl_FragCoord.xy / size, float(uLevel));
}
)";

GLuint compile(GLenum stage, const char* source)
{
    const GLuint shader = glCreateShader(stage);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    return ok ? shader : 0;
}

} // namespace

class TextureFormatsGLTest : public QObject {
    Q_OBJECT
public:
    static void initMain() { facet::test::forgetDisplayServer(); }

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void uploadsAndSamplesLikeTheTwin_data();
    void uploadsAndSamplesLikeTheTwin();
    void slicedTextureIsNeverHalfUsed();
    void anisotropyIsSetOnEveryTexture();
    void pathlessImageGoneIsNeverReused();
    void tooLargeForThisGlIsRefused();
    void anisotropyPolicy_data();
    void anisotropyPolicy();
    void mipFilterPolicy_data();
    void mipFilterPolicy();
    void cacheAppliesTheMipFilter();

private:
    // The texels of level `level` of `texture` as the shader samples them (RGBA, row 0 bottom).
    std::vector<glm::vec4> sample(unsigned texture, int level, int width, int height);

    std::optional<HeadlessGLContext> m_context;
    GLuint m_program = 0;
    GLuint m_vao = 0;
};

void TextureFormatsGLTest::initTestCase()
{
    std::string error;
    m_context = HeadlessGLContext::create(&error);
    QVERIFY2(m_context, error.c_str());
    const GLuint vertex = compile(GL_VERTEX_SHADER, kVertex);
    const GLuint fragment = compile(GL_FRAGMENT_SHADER, kFragment);
    QVERIFY(vertex && fragment);
    m_program = glCreateProgram();
    glAttachShader(m_program, vertex);
    glAttachShader(m_program, fragment);
    glLinkProgram(m_program);
    GLint linked = 0;
    glGetProgramiv(m_program, GL_LINK_STATUS, &linked);
    QVERIFY(linked);
    glDeleteShader(vertex);
    glDeleteShader(fragment);
    glGenVertexArrays(1, &m_vao);
}

void TextureFormatsGLTest::cleanupTestCase()
{
    if (m_program)
        glDeleteProgram(m_program);
    if (m_vao)
        glDeleteVertexArrays(1, &m_vao);
    m_context.reset();
}

std::vector<glm::vec4> TextureFormatsGLTest::sample(unsigned texture, int level, int width, int height)
{
    std::string error;
    std::optional<Framebuffer> target = Framebuffer::create(width, height, FramebufferFormat::RGBA32F, &error);
    if (!target)
        return {};
    glBindFramebuffer(GL_FRAMEBUFFER, target->framebufferId());
    glViewport(0, 0, width, height);
    glUseProgram(m_program);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture);
    glUniform1i(glGetUniformLocation(m_program, "uMap"), 0);
    glUniform1i(glGetUniformLocation(m_program, "uLevel"), level);
    glBindVertexArray(m_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    std::vector<glm::vec4> texels(std::size_t(width * height));
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, texels.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return texels;
}

void TextureFormatsGLTest::uploadsAndSamplesLikeTheTwin_data()
{
    QTest::addColumn<int>("row");
    QTest::addColumn<bool>("sliced");
    for (std::size_t i = 0; i < formatRows().size(); ++i) {
        QTest::addRow("%s, whole", formatRows()[i].name) << int(i) << false;
        QTest::addRow("%s, in slices", formatRows()[i].name) << int(i) << true;
    }
}

void TextureFormatsGLTest::uploadsAndSamplesLikeTheTwin()
{
    QFETCH(int, row);
    QFETCH(bool, sliced);
    const FormatRow& r = formatRows()[std::size_t(row)];
    const auto map = std::make_shared<const MapImage>(makeMap(r));
    TextureCache cache;
    unsigned texture = 0;
    if (sliced) {
        QVERIFY(cache.request(map, "/maps/test.png", 1, r.colorSpace));
        int slices = 0;
        while (cache.hasPendingUploads() && slices < 1000) {
            cache.uploadSlice(0.0); // one band each
            ++slices;
        }
        QVERIFY(slices > 1); // level 0 and each mipmap level at least
        QVERIFY(cache.isReady("/maps/test.png", 1, r.colorSpace));
        bool uploaded = true;
        texture = cache.get(map, "/maps/test.png", 1, r.colorSpace, &uploaded);
        QVERIFY(!uploaded); // complete already
    } else {
        bool uploaded = false;
        texture = cache.get(map, "/maps/test.png", 1, r.colorSpace, &uploaded);
        QVERIFY(uploaded);
    }
    QVERIFY(texture != 0);
    QCOMPARE(glGetError(), GLenum(GL_NO_ERROR));

    glBindTexture(GL_TEXTURE_2D, texture);
    GLint internalFormat = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &internalFormat);
    QCOMPARE(GLenum(internalFormat), r.internalFormat);
    QCOMPARE(QLatin1String(MapTextureFormat::of(r.layout, r.type, r.colorSpace).name).isEmpty(), false);

    // Level 0: each texel as the CPU twin reads it (swizzled, decoded).
    const std::vector<glm::vec4> level0 = sample(texture, 0, kWidth, kHeight);
    QCOMPARE(level0.size(), std::size_t(kWidth * kHeight));
    double worst0 = 0.0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const glm::dvec4 expected = texelValue(*map, x, y, r.colorSpace);
            const glm::dvec4 actual(level0[std::size_t(y * kWidth + x)]);
            for (int c = 0; c < 4; ++c)
                worst0 = std::max(worst0, std::abs(actual[c] - expected[c]));
        }
    // Level 1: the 2 x 2 average, in linear light, of the twin's level-0 texels.
    const int width1 = kWidth / 2;
    const int height1 = kHeight / 2;
    const std::vector<glm::vec4> level1 = sample(texture, 1, width1, height1);
    double worst1 = 0.0;
    for (int y = 0; y < height1; ++y)
        for (int x = 0; x < width1; ++x) {
            const glm::dvec4 expected = 0.25
                * (texelValue(*map, 2 * x, 2 * y, r.colorSpace) + texelValue(*map, 2 * x + 1, 2 * y, r.colorSpace)
                    + texelValue(*map, 2 * x, 2 * y + 1, r.colorSpace)
                    + texelValue(*map, 2 * x + 1, 2 * y + 1, r.colorSpace));
            const glm::dvec4 actual(level1[std::size_t(y * width1 + x)]);
            for (int c = 0; c < 4; ++c)
                worst1 = std::max(worst1, std::abs(actual[c] - expected[c]) / std::max(1.0, std::abs(expected[c])));
        }
    std::printf("  %-30s %-10s level 0 max %.2e, level 1 max %.2e\n", r.name, sliced ? "sliced" : "whole", worst0,
                worst1);
    QVERIFY2(worst0 <= r.levelZeroBound, qPrintable(QStringLiteral("level 0 off by %1").arg(worst0)));
    QVERIFY2(worst1 <= r.levelOneBound, qPrintable(QStringLiteral("level 1 off by %1").arg(worst1)));
}

void TextureFormatsGLTest::slicedTextureIsNeverHalfUsed()
{
    // A 256 x 256 RGBA8 map is 256 KiB: several bands of rows, then eight mipmap levels.
    MapImage image(256, 256, MapLayout::Rgba, MapSampleType::UInt8);
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x)
            for (int c = 0; c < 4; ++c)
                image.setSample(x, y, c, 0.75f);
    const auto map = std::make_shared<const MapImage>(std::move(image));
    TextureCache cache;
    QVERIFY(cache.request(map, "/maps/big.png", 3, ColorEncoding::Linear));
    QVERIFY(!cache.isReady("/maps/big.png", 3, ColorEncoding::Linear));
    const TextureCache::SliceResult first = cache.uploadSlice(0.0);
    QCOMPARE(first.completed, 0);
    QVERIFY(cache.hasPendingUploads());
    QVERIFY(!cache.isReady("/maps/big.png", 3, ColorEncoding::Linear));
    QVERIFY(!cache.readyTimestamp("/maps/big.png", ColorEncoding::Linear));
    // get() finishes it: every texel of every level is there, none is the unwritten zero.
    bool uploaded = false;
    const unsigned texture = cache.get(map, "/maps/big.png", 3, ColorEncoding::Linear, &uploaded);
    QVERIFY(uploaded);
    QVERIFY(!cache.hasPendingUploads());
    QVERIFY(cache.isReady("/maps/big.png", 3, ColorEncoding::Linear));
    QCOMPARE(cache.readyTimestamp("/maps/big.png", ColorEncoding::Linear), std::optional<std::int64_t>(3));
    for (int level = 0, size = 256; size >= 1; ++level, size /= 2) {
        const std::vector<glm::vec4> texels = sample(texture, level, size, size);
        for (const glm::vec4& t : texels)
            QVERIFY2(std::abs(t.r - 191.0f / 255.0f) < 1e-6f && std::abs(t.a - 191.0f / 255.0f) < 1e-6f,
                qPrintable(QStringLiteral("level %1: %2").arg(level).arg(t.r)));
    }
    // Not requested by a frame any more: evicted, and its queue entry with it.
    QVERIFY(cache.request(map, "/maps/other.png", 1, ColorEncoding::Linear));
    cache.evictUnused(); // both were used or requested since the last call
    QCOMPARE(cache.size(), std::size_t(2));
    cache.evictUnused(); // neither since
    QCOMPARE(cache.size(), std::size_t(0));
    QVERIFY(!cache.hasPendingUploads());
}

void TextureFormatsGLTest::pathlessImageGoneIsNeverReused()
{
    // An image without a path is keyed by its address. Once it is gone, a new image may be made
    // at that address (the allocator reuses it); its texture must be its own, not the old one's.
    TextureCache cache;
    const auto filled = [](float value) {
        Image pixels(8, 8);
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x)
                pixels.at(x, y) = glm::vec4(value, value, value, 1.0f);
        return std::make_shared<const MapImage>(
            MapImage::fromImage(pixels, MapLayout::Grey, MapSampleType::UInt8));
    };
    auto first = filled(0.25f);
    const void* address = first.get();
    bool uploaded = false;
    QVERIFY(cache.get(first, {}, 0, ColorEncoding::Linear, &uploaded) != 0);
    QVERIFY(uploaded);
    // The same image again: a hit.
    QVERIFY(cache.get(first, {}, 0, ColorEncoding::Linear, &uploaded) != 0);
    QVERIFY(!uploaded);
    first.reset();
    auto second = filled(0.75f);
    if (second.get() != address)
        qInfo("the allocator did not reuse the address; the row still checks a new image uploads");
    const unsigned texture = cache.get(second, {}, 0, ColorEncoding::Linear, &uploaded);
    QVERIFY(uploaded);
    const std::vector<glm::vec4> texels = sample(texture, 0, 8, 8);
    QVERIFY2(std::abs(texels[0].r - 191.0f / 255.0f) < 1e-6f, qPrintable(QString::number(texels[0].r)));
}

void TextureFormatsGLTest::anisotropyIsSetOnEveryTexture()
{
    const GLInfo info = queryCurrentGLInfo();
    if (info.maxAnisotropy < 4.0f)
        QSKIP("this GL has no 4x anisotropic filtering");
    TextureCache cache;
    const auto map = std::make_shared<const MapImage>(4, 4, MapLayout::Rgb, MapSampleType::UInt8);
    const unsigned before = cache.get(map, "/maps/a.png", 1, ColorEncoding::Linear, nullptr);
    cache.setMaxAnisotropy(4.0f);
    const unsigned after = cache.get(map, "/maps/b.png", 1, ColorEncoding::Linear, nullptr);
    for (unsigned texture : {before, after}) {
        glBindTexture(GL_TEXTURE_2D, texture);
        GLfloat level = 0.0f;
        glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY, &level);
        QCOMPARE(level, 4.0f);
    }
    cache.setMaxAnisotropy(1000.0f); // clamped to what the implementation has
    QCOMPARE(cache.maxAnisotropy(), info.maxAnisotropy);
    cache.setMaxAnisotropy(0.0f);
    QCOMPARE(cache.maxAnisotropy(), 1.0f);
}

void TextureFormatsGLTest::tooLargeForThisGlIsRefused()
{
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    const auto map = std::make_shared<const MapImage>(maxSize + 1, 1, MapLayout::Grey, MapSampleType::UInt8);
    TextureCache cache;
    bool uploaded = true;
    QCOMPARE(cache.get(map, "/maps/wide.png", 1, ColorEncoding::Linear, &uploaded), 0u);
    QVERIFY(!uploaded);
    QCOMPARE(QString::fromStdString(cache.problem()),
        QStringLiteral("TextureCache: /maps/wide.png: %1x1 is larger than this OpenGL's largest texture (%2 pixels "
                       "per side)")
            .arg(maxSize + 1)
            .arg(maxSize));
    QVERIFY(!cache.request(map, "/maps/wide.png", 1, ColorEncoding::Linear));
    QCOMPARE(glGetError(), GLenum(GL_NO_ERROR));
}

void TextureFormatsGLTest::anisotropyPolicy_data()
{
    QTest::addColumn<QString>("renderer");
    QTest::addColumn<float>("maximum");
    QTest::addColumn<bool>("interactive");
    QTest::addColumn<QByteArray>("setting");
    QTest::addColumn<float>("expected");
    const QString llvmpipe = QStringLiteral("llvmpipe (LLVM 15.0.6, 256 bits)");
    const QString gpu = QStringLiteral("NVIDIA GeForce RTX 3060/PCIe/SSE2");
    QTest::newRow("llvmpipe still") << llvmpipe << 16.0f << false << QByteArray() << 1.0f;
    QTest::newRow("llvmpipe interacting") << llvmpipe << 16.0f << true << QByteArray() << 1.0f;
    QTest::newRow("llvmpipe, set 8, still") << llvmpipe << 16.0f << false << QByteArray("8") << 8.0f;
    QTest::newRow("llvmpipe, set 8, interacting") << llvmpipe << 16.0f << true << QByteArray("8") << 1.0f;
    QTest::newRow("softpipe") << QStringLiteral("softpipe") << 16.0f << false << QByteArray() << 1.0f;
    QTest::newRow("GPU still") << gpu << 16.0f << false << QByteArray() << 8.0f;
    QTest::newRow("GPU interacting") << gpu << 16.0f << true << QByteArray() << 8.0f;
    QTest::newRow("GPU, set 16") << gpu << 16.0f << false << QByteArray("16") << 16.0f;
    QTest::newRow("GPU, at most 4") << gpu << 4.0f << false << QByteArray() << 4.0f;
    QTest::newRow("GPU, no extension") << gpu << 1.0f << false << QByteArray() << 1.0f;
    QTest::newRow("GPU, bad setting") << gpu << 16.0f << false << QByteArray("lots") << 8.0f;
    QTest::newRow("GPU, setting 0") << gpu << 16.0f << false << QByteArray("0") << 8.0f;
}

void TextureFormatsGLTest::anisotropyPolicy()
{
    QFETCH(QString, renderer);
    QFETCH(float, maximum);
    QFETCH(bool, interactive);
    QFETCH(QByteArray, setting);
    QFETCH(float, expected);
    const GLInfo info = glInfoOf(renderer, maximum);
    if (setting.isEmpty())
        qunsetenv("FACET_ANISOTROPY");
    else
        qputenv("FACET_ANISOTROPY", setting);
    QCOMPARE(TextureFiltering::anisotropyFor(info, interactive), expected);
    qunsetenv("FACET_ANISOTROPY");
}

void TextureFormatsGLTest::mipFilterPolicy_data()
{
    QTest::addColumn<QString>("renderer");
    QTest::addColumn<QByteArray>("setting");
    QTest::addColumn<bool>("trilinear");
    const QString llvmpipe = QStringLiteral("llvmpipe (LLVM 15.0.6, 256 bits)");
    const QString gpu = QStringLiteral("NVIDIA GeForce RTX 3060/PCIe/SSE2");
    QTest::newRow("llvmpipe") << llvmpipe << QByteArray() << false;
    QTest::newRow("llvmpipe, set trilinear") << llvmpipe << QByteArray("trilinear") << true;
    QTest::newRow("softpipe") << QStringLiteral("softpipe") << QByteArray() << false;
    QTest::newRow("GPU") << gpu << QByteArray() << true;
    QTest::newRow("GPU, set nearest") << gpu << QByteArray("nearest") << false;
    QTest::newRow("GPU, bad setting") << gpu << QByteArray("bilinear") << true;
    QTest::newRow("llvmpipe, bad setting") << llvmpipe << QByteArray("Trilinear") << false;
}

void TextureFormatsGLTest::mipFilterPolicy()
{
    QFETCH(QString, renderer);
    QFETCH(QByteArray, setting);
    QFETCH(bool, trilinear);
    const GLInfo info = glInfoOf(renderer);
    if (setting.isEmpty())
        qunsetenv("FACET_TEXTURE_MIPS");
    else
        qputenv("FACET_TEXTURE_MIPS", setting);
    QCOMPARE(TextureFiltering::trilinear(info), trilinear);
    qunsetenv("FACET_TEXTURE_MIPS");
}

// The cache sets the filter on textures made before and after a change, and a new cache starts
// from this GL's policy.
void TextureFormatsGLTest::cacheAppliesTheMipFilter()
{
    qunsetenv("FACET_TEXTURE_MIPS");
    const auto minFilterOf = [](unsigned texture) {
        GLint filter = 0;
        glBindTexture(GL_TEXTURE_2D, texture);
        glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &filter);
        glBindTexture(GL_TEXTURE_2D, 0);
        return filter;
    };
    const auto map = std::make_shared<const MapImage>(8, 8, MapLayout::Rgb, MapSampleType::UInt8);
    TextureCache cache;
    const bool policy = TextureFiltering::trilinear(queryCurrentGLInfo());
    QCOMPARE(cache.trilinear(), policy);
    bool uploaded = false;
    const unsigned first = cache.get(map, "/maps/a.png", 1, ColorEncoding::Linear, &uploaded);
    QVERIFY(first != 0);
    QCOMPARE(minFilterOf(first), GLint(policy ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR_MIPMAP_NEAREST));
    cache.setTrilinear(!policy);
    QCOMPARE(minFilterOf(first), GLint(!policy ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR_MIPMAP_NEAREST));
    const unsigned second = cache.get(map, "/maps/b.png", 1, ColorEncoding::Linear, &uploaded);
    QCOMPARE(minFilterOf(second), GLint(!policy ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR_MIPMAP_NEAREST));
    QCOMPARE(glGetError(), GLenum(GL_NO_ERROR));
}

QTEST_GUILESS_MAIN(TextureFormatsGLTest)
#include "TextureFormatsGLTest.moc"
