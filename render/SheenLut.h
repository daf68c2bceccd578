#pragma once
// KHR_materials_sheen's albedo table on the GPU: core/shading/Sheen.h sheenAlbedoTable() as a
// GL_TEXTURE_2D, RG32F: R = E(n.v, r), G = Emax(n.v, r) (SheenAlbedoTable::diffuseTexel); x = n.v,
// y = sheen roughness, texel i at i / (size - 1), LINEAR, CLAMP_TO_EDGE, read at
// dfgTexCoord(n.v, r, size) (resources/shaders/brdf_sheen.glsl). A renderer makes it when it first
// draws a sheen material (render/Renderer.cpp); the context must be current.

#include "render/GLTexture.h"

namespace facet {

GLTexture makeSheenLut();
int sheenLutSize(); // texels along each axis

} // namespace facet
