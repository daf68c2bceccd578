#pragma once
// How much anisotropic filtering material textures get, chosen from the GL implementation.
//
// Anisotropic filtering takes up to N trilinear fetches per texel read where a surface is seen
// at a grazing angle. On a GPU that is nearly free; on a software rasteriser (llvmpipe, where
// every fetch is CPU time) 8x made a frame of five 2048² maps 6-13x slower than the untextured
// sphere (issue 8: 1.9-4.4 s against 0.15-0.33 s). So: the setting (8x by default) on hardware,
// none by default on software rasterisers, and none there while the user interacts whatever the
// setting (the refined frame after it gets the setting). docs/benchmarks.md, "Texture maps", has
// the measured cost of each level.

#include "render/GLInfo.h"

namespace facet {

struct TextureFiltering {
    // The default setting on hardware (what Facet used everywhere before) and on software
    // rasterisers (measured: docs/benchmarks.md), and the level while interacting on software.
    // On llvmpipe (Mesa 22.3) any anisotropy takes the sampler's slow path: five 2K maps at
    // 1280x720 cost ~2x the untextured frame at 1x and 5-6x at 2x to 16x alike
    // (tests/bench/texture_maps), so the software default is none.
    static constexpr float kHardwareDefault = 8.0f;
    static constexpr float kSoftwareDefault = 1.0f;
    static constexpr float kSoftwareInteractive = 1.0f;

    // The setting: FACET_ANISOTROPY (a number from 1 to 16) when it is set, else the default for
    // the implementation; never above its maximum (info.maxAnisotropy; 1 without the extension).
    static float setting(const GLInfo& info);
    // What a frame uses: the setting, but at most kSoftwareInteractive on a software rasteriser
    // while interacting (`interactive`: the viewport's reduced-resolution frames).
    static float anisotropyFor(const GLInfo& info, bool interactive);

    // Whether a minified texture blends its two nearest mip levels (trilinear,
    // GL_LINEAR_MIPMAP_LINEAR) or reads the nearer one (GL_LINEAR_MIPMAP_NEAREST): trilinear on
    // hardware, where it is free; the nearer level on software rasterisers, where the second
    // level's fetch made a frame of five 2K maps ~25% slower (2.05x the untextured frame against
    // 1.65x, tests/bench/texture_maps; docs/benchmarks.md). FACET_TEXTURE_MIPS=trilinear or
    // nearest overrides either default.
    static bool trilinear(const GLInfo& info);
};

} // namespace facet
