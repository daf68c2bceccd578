#include <epoxy/gl.h> // before any header that could pull in <GL/gl.h>

#include "render/EnvironmentSource.h"

#include "render/GLDebug.h"

#include "core/ibl/Environment.h"
#include "core/ibl/EnvironmentSampler.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace facet {

namespace {

constexpr const char* kFunction = "EnvironmentSourceTextures::create";

GLTexture makeTexture(
    int width, int height, GLenum internalFormat, GLenum format, const float* data, bool linear)
{
    GLTexture texture = GLTexture::create(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, texture.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(internalFormat), width, height, 0, format, GL_FLOAT, data);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, linear ? GL_LINEAR : GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, linear ? GL_LINEAR : GL_NEAREST);
    // The radiance wraps in u (the seam) and clamps in v (the poles), as Environment::radiance.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, linear ? GL_REPEAT : GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return texture;
}

} // namespace

glm::ivec2 EnvironmentSourceTextures::sizeFor(int width, int height, int maxTextureSize)
{
    width = std::max(width, 1);
    height = std::max(height, 1);
    // The CDF textures are one texel longer than the image's sides.
    const int glLimit = std::max(maxTextureSize - 1, 1);
    const double limitWidth = std::min(kMaxWidth, glLimit);
    const double limitHeight = std::min(kMaxHeight, glLimit);
    const double scale = std::max({double(width) / limitWidth, double(height) / limitHeight, 1.0});
    if (scale == 1.0)
        return {width, height};
    // The side that sets the scale comes out at its limit exactly (the epsilon absorbs the
    // rounding of width / (width / limit)); the other is rounded down.
    return {std::clamp(int(std::floor(width / scale + 1e-9)), 1, int(limitWidth)),
        std::clamp(int(std::floor(height / scale + 1e-9)), 1, int(limitHeight))};
}

std::shared_ptr<const EnvironmentSourceTextures> EnvironmentSourceTextures::create(
    const Environment& environment, std::string* warning, std::string* error)
{
    if (environment.isEmpty()) {
        if (error)
            *error = std::string(kFunction) + ": " + environment.name() + ": the environment has no image";
        return nullptr;
    }
    GLint maxTextureSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTextureSize);
    const Image& image = environment.image();
    const glm::ivec2 size = sizeFor(image.width(), image.height(), int(maxTextureSize));

    // The distribution and the radiance of the same pixels: the image, or its box-filtered copy
    // (an Environment at rotation 0 and intensity 1: both are applied at shading time).
    Environment source = environment;
    if (size != glm::ivec2(image.width(), image.height())) {
        source = Environment(image.boxFiltered(size.x, size.y), environment.name());
        if (warning)
            *warning = std::string(kFunction) + ": " + environment.name() + ": "
                + std::to_string(image.width()) + "x" + std::to_string(image.height())
                + " is above the source limit of "
                + std::to_string(std::min(kMaxWidth, int(maxTextureSize) - 1)) + "x"
                + std::to_string(std::min(kMaxHeight, int(maxTextureSize) - 1)) + "; box-filtered to "
                + std::to_string(size.x) + "x" + std::to_string(size.y)
                + " for the source radiance and its sampling tables";
    }
    source.setRotationDegrees(0.0);
    source.setIntensity(1.0);
    const EnvironmentSamplingTables tables = EnvironmentSampler(source).tables();

    std::vector<float> rgb(std::size_t(size.x) * std::size_t(size.y) * 3);
    const glm::vec4* pixels = source.image().data();
    for (std::size_t i = 0; i < source.image().pixelCount(); ++i)
        for (std::size_t c = 0; c < 3; ++c)
            rgb[3 * i + c] = pixels[i][int(c)];

    while (glGetError() != GL_NO_ERROR) { }
    auto result = std::make_shared<EnvironmentSourceTextures>();
    result->width = size.x;
    result->height = size.y;
    result->sourceWidth = image.width();
    result->sourceHeight = image.height();
    // Rows top first, as Image stores them: t = 0 is the image's top row (common_equirect.glsl).
    result->radiance = makeTexture(size.x, size.y, GL_RGB32F, GL_RGB, rgb.data(), true);
    result->conditionalCdf
        = makeTexture(size.x + 1, size.y, GL_R32F, GL_RED, tables.conditionalCdf.data(), false);
    result->marginalCdf = makeTexture(size.y + 1, 1, GL_R32F, GL_RED, tables.marginalCdf.data(), false);
    result->pdf = makeTexture(size.x, size.y, GL_R32F, GL_RED, tables.pdfUv.data(), false);
    if (const GLenum glError = glGetError(); glError != GL_NO_ERROR) {
        if (error)
            *error = std::string(kFunction) + ": " + environment.name() + ": " + glErrorName(glError)
                + " uploading " + std::to_string(size.x) + "x" + std::to_string(size.y) + " textures";
        return nullptr;
    }
    return result;
}

} // namespace facet
