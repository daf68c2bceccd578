#pragma once
// What the surface shader consumes from the IBL precompute (render/IblPrecompute.h) for one
// environment. A plain struct of shared, immutable GL textures: IblPrecompute's cache and any
// number of renderers may hold the same IblTextures (std::shared_ptr<const IblTextures>); the
// textures are deleted when the last holder lets go, which must happen with the GL context
// current. The split-sum DFG LUT is not here: it depends on the material's visibility term, not
// on the environment, and comes from IblPrecompute::dfgTable (render/DfgLut.h), one per variant.
//
// Everything is in the environment IMAGE's frame, unrotated, at intensity 1: the renderer turns
// a world lookup direction into the image frame (Environment::toImageFrame, a rotation about +Y)
// and multiplies by Environment::intensity() at shading time. docs/ibl.md has the equations.

#include "render/GLTexture.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>

namespace facet {

struct IblTextures {
    // GL_TEXTURE_CUBE_MAP, RGBA16F, environment radiance, cubeSize^2 per face, full mip chain
    // (glGenerateMipmap: box-filtered) for the background and blurred backgrounds.
    std::shared_ptr<const GLTexture> environment;
    int environmentSize = 0;
    int environmentMipLevels = 0;

    // GL_TEXTURE_CUBE_MAP, RGBA16F, prefiltered specular radiance (split-sum first factor,
    // Karis 2013, n = v = r). Level i, of size prefilterSize >> i, holds perceptual roughness
    // roughnessFromLod(i, levels): read it at lodFromRoughness(r, levels) with LINEAR_MIPMAP_LINEAR.
    // Level 0 (roughness 0) is the environment itself, resampled to prefilterSize.
    std::shared_ptr<const GLTexture> prefiltered;
    int prefilteredSize = 0;
    int prefilteredMipLevels = 0;

    // GL_TEXTURE_CUBE_MAP, RGBA16F, IRRADIANCE E(n) = integral L(w) max(0, n.w) dw (radiance x sr,
    // NOT divided by pi: a uniform environment L gives pi L). Diffuse radiance = albedo / pi * E.
    // One level, LINEAR. Present whatever IblSettings::irradiance says (it is cheap).
    std::shared_ptr<const GLTexture> irradiance;
    int irradianceSize = 0;

    // SH9 irradiance coefficients, premultiplied by the cosine-lobe A_l (core/ibl/SphericalHarmonics.h
    // IrradianceSH9), in the image frame: uniform vec3 uIrradianceSH[9] of irradianceSH(n), which
    // gives E(n) (not divided by pi) like the irradiance map.
    std::array<glm::vec3, 9> irradianceSH {};

    // GPU memory the three cubemaps take (RGBA16F, 8 bytes a texel; mip chains counted level by
    // level): what IblPrecompute's memory budget counts. Default preset ~5.3 MB, high ~21 MB.
    std::size_t bytes() const
    {
        const auto cube = [](int size, int levels) {
            std::size_t total = 0;
            for (int level = 0; level < levels; ++level) {
                const std::size_t side = std::size_t(std::max(1, size >> level));
                total += 6 * side * side * 8;
            }
            return total;
        };
        return cube(environmentSize, environmentMipLevels) + cube(prefilteredSize, prefilteredMipLevels)
            + cube(irradianceSize, 1);
    }

    unsigned environmentCubemap() const { return environment ? environment->id() : 0; }
    unsigned prefilteredCubemap() const { return prefiltered ? prefiltered->id() : 0; }
    unsigned irradianceCubemap() const { return irradiance ? irradiance->id() : 0; }
};

// Level of the prefiltered cubemap for a perceptual roughness r; GLSL twin of the same name in
// resources/shaders/ibl_lookup.glsl. lod = (levels - 1) r (2 - r) [Filament, "Pre-filtered
// importance sampling" / perceptualRoughnessToLod]: the map is steep at low roughness, where a
// lobe's width changes fastest and the levels are largest, so the smooth half of the roughness
// range gets most of the levels (with 6 levels: r = 0, 0.11, 0.23, 0.37, 0.55, 1). Linear
// r (levels - 1) gave only level 1 (r = 0.2) between a mirror and r = 0.4, and blending those
// two lobes for r = 0.05 put 12% relative RMSE on a metal sphere under the CC0 studio HDRI
// (docs/ibl.md, "Roughness to level").
inline float lodFromRoughness(float perceptualRoughness, float mipLevels)
{
    const float r = std::clamp(perceptualRoughness, 0.0f, 1.0f);
    return r * (2.0f - r) * (mipLevels - 1.0f);
}
// Perceptual roughness stored in level `level` of `mipLevels` (the inverse of lodFromRoughness):
// r = 1 - sqrt(1 - level / (levels - 1)).
inline double roughnessFromLod(int level, int mipLevels)
{
    if (mipLevels <= 1)
        return 0.0;
    const double t = std::clamp(double(level) / double(mipLevels - 1), 0.0, 1.0);
    return 1.0 - std::sqrt(1.0 - t);
}

} // namespace facet
