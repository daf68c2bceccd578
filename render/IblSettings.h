#pragma once
// Quality settings of the IBL precompute (render/IblPrecompute.h). Every field changes the
// result, so every field is part of hash(), the cache key (with the environment's content hash).
// Rotation and intensity are NOT settings: they are applied at shading time, never baked. The
// split-sum DFG table's variant (the material's Visibility) is not a setting either: it is an
// argument of every DFG call and of its key, dfgHash(visibility), so no caller can leave it out.
// docs/ibl.md lists the presets and their measured times and errors.

#include "core/shading/ShadingModel.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace facet {

enum class IblQuality; // core/project/Project.h

struct IblSettings {
    enum class Irradiance {
        SH,  // the surface shader evaluates the 9 SH coefficients (cheap, ~-30%/+25% off on studio)
        Map, // the surface shader reads the irradiance cubemap (within a few % of brute force)
    };

    int cubeSize = 256;          // environment cubemap face size (level 0), full mip chain
    int prefilterSize = 128;     // prefiltered specular face size of level 0
    int prefilterMipLevels = 6;  // levels of the prefiltered cubemap (level i: roughness i / (levels - 1))
    int prefilterSamples = 128;  // GGX samples per texel (filtered importance sampling)
    int irradianceSize = 32;     // irradiance cubemap face size
    // Source texels summed per irradiance texel: the pass sums every texel of the largest level of
    // the environment cube that has at most this many (6 s^2; 1536 = 16x16 a face).
    int irradianceSamples = 384;
    int dfgSize = 32;            // DFG LUT is dfgSize x dfgSize
    int dfgSamples = 1024;       // VNDF samples per LUT texel
    Irradiance irradiance = Irradiance::Map;

    bool operator==(const IblSettings&) const = default;
    // FNV-1a 64 over every field (as int32, little-endian order of declaration): stable across runs.
    std::uint64_t hash() const;
    // The key of one DFG LUT: the fields it depends on (dfgSize, dfgSamples) and the visibility
    // term V it is integrated with [as Filament's CubemapIBL::DFG(js, dst, multiscatter, cloth)
    // takes its variant]: one table per (settings, V), in memory and on disk. Another V's table
    // put 11% RMSE (21% near the silhouette) on a LearnOpenGL metal (docs/ibl.md, "DFG LUT").
    std::uint64_t dfgHash(Visibility visibility) const;

    // Clamps every field into its valid range (sizes >= 1, levels within the size's mip chain,
    // samples >= 1); prepare() works on the sanitised copy.
    IblSettings sanitized() const;
    // The settings for an equirect image `equirectWidth` texels wide: cubeSize is a MAXIMUM, and
    // the cube gets no more than twice the image's own resolution (an equirect's width covers
    // four faces: width / 4 texels a face; 2x that keeps bilinear resampling from blurring, one
    // point of relative RMSE on the 512 x 256 CC0 maps, docs/benchmarks.md), as a power of two
    // >= 16. prefilterSize never exceeds the cube; levels are clamped to the chain. Applied by
    // IblPrecompute::prepare() (so the cache key holds what was really computed).
    IblSettings forImage(int equirectWidth) const;

    // A project's quality (EnvironmentSettings::quality) as settings.
    static IblSettings preset(IblQuality quality);
    // By name, "draft", "default", "high" (toString(IblQuality)); nullopt for an unknown name.
    static std::optional<IblSettings> preset(const std::string& name);
    static std::vector<std::string> presetNames();
};

} // namespace facet
