#pragma once
// An environment at its source resolution on the GPU, for lighting that reads the image itself
// instead of the resampled cubemaps: the radiance (RGB32F) and the luminance sampling tables of
// core/ibl/EnvironmentSampler (R32F), read by resources/shaders/environment_sampling.glsl. Made and
// cached by IblPrecompute::source() (by Environment::contentHash(): rotation and intensity are
// applied at shading time), shared like IblTextures: immutable, held by std::shared_ptr<const>,
// deleted with a context of the share group current. docs/ibl.md "Environment sampling tables".
//
// Size limits: the conditional CDF is W + 1 texels wide and the marginal H + 1, so W and H are
// kept at most GL_MAX_TEXTURE_SIZE - 1; and at most kMaxWidth x kMaxHeight (4096 x 2048: 96 MiB of
// RGB32F plus 64 MiB of tables) to bound memory. A larger image is box-filtered down (same
// aspect, Image::boxFiltered) with a warning; radiance and tables then describe that smaller image,
// so they stay consistent with each other (but no longer equal Environment::radiance texel for texel).

#include "render/GLTexture.h"

#include <glm/vec2.hpp>

#include <cstddef>
#include <memory>
#include <string>

namespace facet {

class Environment;

struct EnvironmentSourceTextures {
    static constexpr int kMaxWidth = 4096;
    static constexpr int kMaxHeight = 2048;

    // GL_TEXTURE_2D, GL_RGB32F, width x height, rows top first (t = 0 is the image's top row),
    // GL_LINEAR, WRAP_S REPEAT, WRAP_T CLAMP_TO_EDGE, one level: read with textureLod(.., 0) at
    // equirectTexCoord(d), it is Environment::radiance's bilinear lookup (at intensity 1).
    GLTexture radiance;
    // GL_TEXTURE_2D, GL_R32F, GL_NEAREST, CLAMP_TO_EDGE, read with texelFetch. Rows in the
    // distribution's order (row r: v in [r/H, (r+1)/H), image row H-1-r): the tables of
    // EnvironmentSampler::tables() (core/ibl/EnvironmentSamplingTables.h) as they are.
    GLTexture conditionalCdf; // (width + 1) x height
    GLTexture marginalCdf; // (height + 1) x 1
    GLTexture pdf; // width x height: pdfUv
    int width = 0;
    int height = 0;
    // The environment image's size: larger than width x height when it was box-filtered down.
    int sourceWidth = 0;
    int sourceHeight = 0;

    bool downsampled() const { return width != sourceWidth || height != sourceHeight; }
    // GPU memory: 12 bytes a radiance texel, 4 a table entry. A 512 x 256 CC0 map: 1.5 MiB + 1.0 MiB.
    std::size_t bytes() const
    {
        const auto w = std::size_t(width);
        const auto h = std::size_t(height);
        return 12 * w * h + 4 * ((w + 1) * h + (h + 1) + w * h);
    }

    // The size the textures get for a width x height image when GL allows textures up to
    // maxTextureSize wide: the image's own if it fits, else the largest of the same aspect (each
    // side rounded down, at least 1) within the limits above.
    static glm::ivec2 sizeFor(int width, int height, int maxTextureSize);

    // Builds the tables on the CPU (EnvironmentSampler over the image, or over its box-filtered
    // copy) and uploads the four textures. Needs a current GL context; changes the GL_TEXTURE_2D
    // binding of the active unit and the unpack state (IblPrecompute restores them). On failure
    // returns null and sets `error` to "EnvironmentSourceTextures::create: <name>: <problem>" (an
    // empty environment, a GL error such as GL_OUT_OF_MEMORY). `warning` gets a line when the
    // image was box-filtered down.
    static std::shared_ptr<const EnvironmentSourceTextures> create(
        const Environment& environment, std::string* warning, std::string* error);
};

} // namespace facet
