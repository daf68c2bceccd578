#include <epoxy/gl.h> // before any header that could pull in <GL/gl.h>

#include "render/IblTables.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/ibl/Prefilter.h"

namespace facet {

namespace {

// Solid angle of the part of a cube face (at distance 1) from (0, 0) to (x, y) [Driscoll,
// "Cubemap texel solid angle"]; a texel's is the inclusion-exclusion of its four corners.
double cornerArea(double x, double y)
{
    return std::atan2(x * y, std::sqrt(x * x + y * y + 1.0));
}

double cubeTexelSolidAngle(int x, int y, int size)
{
    const double step = 2.0 / double(size);
    const double x0 = x * step - 1.0;
    const double y0 = y * step - 1.0;
    return cornerArea(x0, y0) - cornerArea(x0, y0 + step) - cornerArea(x0 + step, y0)
        + cornerArea(x0 + step, y0 + step);
}

// A table of RGBA32F entries, `width` to a row, for texelFetch (no filtering, no mipmaps).
GLTexture tableTexture(const std::vector<glm::vec4>& entries, int width)
{
    GLTexture texture = GLTexture::create(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, texture.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, int(entries.size()) / width, 0, GL_RGBA, GL_FLOAT,
        entries.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return texture;
}

} // namespace

GLTexture irradianceTexelTable(const GLTexture& cube, int size, int level)
{
    const int count = 6 * size * size;
    const int rows = 2 * ((count + kTableWidth - 1) / kTableWidth);
    std::vector<glm::vec4> table(std::size_t(kTableWidth) * std::size_t(rows), glm::vec4(0.0f));
    for (int f = 0; f < 6; ++f) {
        const std::vector<float> face = readTextureLevel(cube, f, level, nullptr, nullptr);
        if (face.size() != std::size_t(size) * std::size_t(size) * 4)
            return GLTexture {};
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const int i = (f * size + y) * size + x;
                const std::size_t at
                    = std::size_t(2 * (i / kTableWidth)) * kTableWidth + std::size_t(i % kTableWidth);
                const glm::dvec3 w = cubemapDirection(f, (x + 0.5) / size, (y + 0.5) / size);
                table[at] = glm::vec4(glm::vec3(w), 0.0f);
                const float* texel = &face[std::size_t(y * size + x) * 4];
                table[at + kTableWidth] = glm::vec4(
                    glm::vec3(texel[0], texel[1], texel[2]) * float(cubeTexelSolidAngle(x, y, size)), 0.0f);
            }
    }
    return tableTexture(table, kTableWidth);
}

GLTexture prefilterSampleTable(
    double roughness, int samples, double sourceSize, double sourceMaxLod, int* count, double* inverseWeight)
{
    const std::vector<PrefilterLobeSample> lobe = prefilterLobeSamples(roughness, samples);
    const int rows = std::max(1, int((lobe.size() + kTableWidth - 1) / kTableWidth));
    std::vector<glm::vec4> table(std::size_t(kTableWidth) * std::size_t(rows), glm::vec4(0.0f));
    double weight = 0.0;
    for (std::size_t i = 0; i < lobe.size(); ++i) {
        const double lod = filteredLod(lobe[i].pdf, double(samples), sourceSize, sourceMaxLod);
        table[i] = glm::vec4(glm::vec3(lobe[i].l), float(lod));
        weight += lobe[i].l.z;
    }
    *count = int(lobe.size());
    *inverseWeight = weight > 0.0 ? 1.0 / weight : 0.0;
    return tableTexture(table, kTableWidth);
}

void TableBinding::bind(unsigned id)
{
    glActiveTexture(GL_TEXTURE0 + kUnit);
    glBindTexture(GL_TEXTURE_2D, id);
    glActiveTexture(GL_TEXTURE0);
}

} // namespace facet
