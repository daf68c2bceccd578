#pragma once
// The mipmap levels of a material texture, made on the CPU band by band (no GL here): the
// viewport uploads a 2K texture in slices of a few milliseconds each, and glGenerateMipmap is one
// step that cannot be sliced (on llvmpipe it took 90-170 ms for a 2048² RGB8 texture, more than
// a slice may take; made here, level 1 of it takes a few ms per band).
//
// Each level halves the previous one (floor, at least 1, as OpenGL sizes levels) with a 2 x 2
// box filter, the filter glGenerateMipmap implementations use; on an odd side the last texel
// row or column is averaged with itself. Values are filtered as the texture reads them:
// 8- and 16-bit unsigned normalised, half floats as floats, and the colour channels of sRGB
// textures in linear light (decoded, averaged, encoded: OpenGL's rule for sRGB textures), their
// alpha as it is. Results round to nearest.

#include <cstddef>
#include <vector>

namespace facet {

enum class MipFilter {
    Unorm8, // GL_R8 ... GL_RGBA8
    Srgb8, // GL_SRGB8 (3 channels), GL_SRGB8_ALPHA8 (4: the last is linear alpha)
    Unorm16, // GL_R16 ... GL_RGBA16
    Half, // GL_R16F ... GL_RGBA16F
};

class MipChain {
public:
    // `level0`: width x height texels of `channels` interleaved samples (rows bottom to top, no
    // padding), in the texture's own format; not copied, it must outlive the chain.
    MipChain(const unsigned char* level0, int width, int height, int channels, MipFilter filter);

    // Levels of a width x height texture down to 1 x 1 (OpenGL's full chain).
    static int levelCount(int width, int height);

    int levels() const { return int(m_sizes.size()); }
    int width(int level) const { return m_sizes[std::size_t(level)].first; }
    int height(int level) const { return m_sizes[std::size_t(level)].second; }
    std::size_t rowBytes(int level) const;
    // The texels of `level` (level 0: what was given; others: as far as computed).
    const unsigned char* level(int level) const;

    // Computes rows [rowBegin, rowEnd) of `level` (>= 1) from level - 1, whose rows up to
    // 2 * rowEnd must be there already.
    void computeRows(int level, int rowBegin, int rowEnd);
    // Frees the levels below `level` that were computed here (level 0 is not ours).
    void releaseBelow(int level);

private:
    const unsigned char* m_level0;
    int m_channels;
    MipFilter m_filter;
    std::vector<std::pair<int, int>> m_sizes;
    std::vector<std::vector<unsigned char>> m_levels; // [0] unused
};

} // namespace facet
