#pragma once
// The rows of tests/MaterialMapsGLTest.cpp (one per map input and feature: each map alone and
// together, every channel, colour space, UV transform and set, wrap and filter, each layered
// lobe's maps) and the texture files they read, written by the test into a folder of its own.

#include <functional>
#include <vector>

#include <QString>

#include <OpenImageIO/typedesc.h>

#include <glm/vec4.hpp>

#include "core/material/Material.h"

namespace facet::test {

// The side of every test texture, in texels.
inline constexpr int kMapTextureSize = 64;

// Writes an 8-bit PNG with OpenImageIO directly (not Image::save, so a bug there cannot hide one
// in the loader). `texel` gets (x, y) with y = 0 the top row and returns values in [0, 1].
bool writePng(const QString& path, int channels, const std::function<glm::dvec4(int, int)>& texel);
// The same with 16-bit samples (PNG) or float samples (EXR, written as float, read as half).
bool writeDeep(
    const QString& path, int channels, OIIO::TypeDesc type, const std::function<glm::dvec4(int, int)>& texel);
// Smooth, periodic signals: one period across the texture, so repeat wrapping has no seam and a
// mip level's box filter changes them by less than 0.5% (cos(pi / 64) for the first level).
double wave(int i, double phase = 0.0);
// `folder`/`name`.
QString file(const QString& folder, const char* name);
// Gives `slot` the texture `path`, read through `channel` in `colorSpace`.
void useMap(Material& m, MapSlot slot, const QString& path, MapChannel channel, ColorEncoding colorSpace);
// The base normal map: `folder`'s normal.png, linear.
void useNormal(Material& m, const QString& folder);

// What one row sets up on top of the default material.
struct MapRow {
    const char* name;
    std::function<void(Material&, const QString& folder)> setup;
    // The largest difference allowed at a pixel. NEAREST steps by a whole texel (up to 0.04 in
    // these textures) where the GPU and the twin round a coordinate on a texel edge differently;
    // the mean bound still tells nearest from linear (half a step on average).
    double maxBound = 0.025;
};
const std::vector<MapRow>& materialMapRows();

} // namespace facet::test
