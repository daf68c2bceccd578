#include "render/SheenLut.h"

#include <epoxy/gl.h>

#include <cstddef>
#include <vector>

#include "core/shading/Sheen.h"

namespace facet {

GLTexture makeSheenLut()
{
    const shading::SheenAlbedoTable& table = shading::sheenAlbedoTable();
    const int size = table.size();
    std::vector<float> texels(2 * std::size_t(size) * std::size_t(size));
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const std::size_t i = 2 * (std::size_t(y) * std::size_t(size) + std::size_t(x));
            texels[i] = float(table.texel(x, y));
            texels[i + 1] = float(table.diffuseTexel(x, y));
        }
    GLTexture texture = GLTexture::create(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, texture.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, size, size, 0, GL_RG, GL_FLOAT, texels.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return texture;
}

int sheenLutSize()
{
    return shading::sheenAlbedoTable().size();
}

} // namespace facet
