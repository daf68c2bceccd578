#pragma once
// The tables the IBL precompute's irradiance and prefilter passes read (ibl_irradiance.frag,
// ibl_prefilter.frag): RGBA32F textures of kTableWidth entries a row, made on the CPU once per
// environment or per prefiltered level, and the binding that holds one on texture unit 1 while
// a pass draws. Internal to render/ (render/IblPrecompute); a GL context must be current.

#include "render/GLTexture.h"

namespace facet {

// Entries per row of both tables (the shaders index them with the same width).
inline constexpr int kTableWidth = 1024;

// The irradiance pass's table (ibl_irradiance.frag): for every texel t of `level` (size x size a
// face) of `cube`, its centre's direction w_t and L_t Omega_t, as
// RGBA32F rows of kTableWidth entries (direction row, then radiance row). Made once per environment:
// 6 s^2 directions, solid angles and a read-back of a few KiB instead of that many per output texel.
GLTexture irradianceTexelTable(const GLTexture& cube, int size, int level);

// The samples of prefiltered level of perceptual `roughness` (core/ibl/Prefilter.h
// prefilterLobeSamples) as ibl_prefilter.frag reads them: RGBA32F rows of kTableWidth entries, each
// l in the frame of n and the source lod filtered importance sampling reads it at. *count: the
// entries; *inverseWeight: 1 / sum (n.l), 0 when no sample is above the horizon.
GLTexture prefilterSampleTable(
    double roughness, int samples, double sourceSize, double sourceMaxLod, int* count, double* inverseWeight);

// A pass's table bound to texture unit 1 while the pass draws (unit 0 holds the source cube),
// unbound when the pass ends, however it ends.
class TableBinding {
public:
    explicit TableBinding(const GLTexture& table) { bind(table.id()); }
    ~TableBinding() { bind(0); }
    TableBinding(const TableBinding&) = delete;
    TableBinding& operator=(const TableBinding&) = delete;

    static constexpr int kUnit = 1;

private:
    static void bind(unsigned id);
};

} // namespace facet
