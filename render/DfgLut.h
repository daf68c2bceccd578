#pragma once
// One split-sum DFG table on the GPU (render/IblPrecompute::dfgTable), tagged with what it was
// integrated with. The table depends on the BRDF's visibility term V (core/shading/DfgTable.h: scale and
// bias are integrals of D V F (n.l)), so a table is made per (IblSettings::dfgHash(V)) and a
// frame binds, for each material, the table of that material's ShadingModel::visibility
// (render/RenderScene.h EnvironmentLighting::dfgLutFor). Immutable and shared like IblTextures:
// the texture is deleted when the last holder lets go, with the GL context current.

#include "core/shading/ShadingModel.h"
#include "render/GLTexture.h"

#include <memory>

namespace facet {

struct DfgLut {
    // GL_TEXTURE_2D, RGBA16F, size^2: R = scale, G = bias, B = scale + bias (core/shading/DfgTable.h),
    // x = n.v, y = perceptual roughness; texel i holds the value at i / (N - 1), row 0 (t = 0) is
    // roughness 0. LINEAR, CLAMP_TO_EDGE; read it at dfgTexCoord(n.v, r, N).
    std::shared_ptr<const GLTexture> texture;
    int size = 0;
    int sampleCount = 0; // VNDF samples per texel
    Visibility visibility = Visibility::SmithGGXCorrelated; // the V it was integrated with

    unsigned id() const { return texture ? texture->id() : 0; }
};

} // namespace facet
