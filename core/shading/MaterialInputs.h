#pragma once
// The material's inputs at a surface point, from its factors and texture maps: the CPU twin of
// resources/shaders/material_inputs.glsl (same function names), so tests can hold the GPU's
// texture reads, channel picks, inversion, colour decoding, UV transforms and normal mapping to
// an independent evaluation (tests/MaterialMapsGLTest.cpp).
//
// Texture reads follow OpenGL's rules for the textures render/TextureCache makes: uv (0, 0) is the
// map's first texel (core/image/MapImage.h stores rows bottom to top), texel centres sit at
// (i + 0.5) / size, wrapped as the map's sampler says (REPEAT by default), bilinear between the
// four nearest texels of level 0 (or the nearest one, for a NEAREST magnification filter), each
// texel as the texture holds it: 8- and 16-bit samples normalised, half samples as they are, grey
// and grey + alpha expanded as the swizzle does (MapImage::texel). An sRGB-encoded 8-bit map is
// decoded per texel before filtering, as GL_SRGB8(_ALPHA8) does (the sRGB specification's
// intent); a 16-bit or float map read as sRGB holds the decoded value as a half float
// (MapImage::linearHalfFromSrgb), as the upload makes it.
// Mipmapping (the sampler's minification filter) is not modelled: compare where the GPU magnifies
// or the texture is smooth.

#include <array>
#include <optional>

#include <glm/ext/vector_int2.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/image/MapImage.h"
#include "core/material/Material.h"
#include "core/shading/MaterialBrdf.h"

namespace facet {

// One image per MapSlot (null: the slot uses its factor alone, like a variant without HAS_*_MAP).
using MaterialMapImages = std::array<const MapImage*, kMapSlotCount>;

// The value of `channel` of a texel; Rgb on a scalar map reads red (GLSL pickChannel).
double pickChannel(const glm::dvec4& texel, MapChannel channel);

// A scalar map's value: the picked channel, inverted when the map says so (GLSL scalarMapValue).
double scalarMapValue(const MaterialMap& map, const glm::dvec4& texel);

// The smallest value scalarMapValue() takes over `image` (the map's file, as loaded), its colour
// space decoded; nullopt when the image's range is not known (MapImage::texelRange).
std::optional<double> smallestScalarMapValue(const MaterialMap& map, const MapImage& image);

// The normal map's tangent-space normal: the texel (values in [0, 1], OpenGL convention +Y green;
// `flipGreen` for DirectX maps) decoded to [-1, 1], X and Y scaled by `strength` (glTF
// normalTexture.scale), unit length; (0, 0, 1) where it degenerates. What shadingNormal() maps
// into the surface's frame, and what an exported normal map stores (core/export/TextureSetExport).
glm::dvec3 tangentSpaceNormal(const glm::dvec4& normalTexel, double strength, bool flipGreen);

// The shading normal from the unit geometric normal `ng` (facing the viewer), the vertex tangent
// (xyz along dP/du, any length; w = handedness, glTF 2.0) and the normal map's texel (values in
// [0, 1], OpenGL convention +Y green; `flipGreen` for DirectX maps), X and Y scaled by `strength`
// (glTF normalTexture.scale). Returns ng where the tangent frame or the result degenerates.
glm::dvec3 shadingNormal(const glm::dvec3& ng, const glm::dvec4& tangent, const glm::dvec4& normalTexel,
    double strength, bool flipGreen);

// The anisotropy direction in world space (MaterialInfo::anisotropyDirection) from the unit
// geometric normal, the vertex tangent (as shadingNormal takes it) and the direction in the tangent
// plane (MaterialInfo::anisotropyTangentDirection): tangentDirection.x t + tangentDirection.y b,
// unit. Zero where the tangent frame degenerates (the lobe is then isotropic). GLSL
// anisotropyDirection in material_inputs.glsl.
glm::dvec3 surfaceAnisotropyDirection(
    const glm::dvec3& ng, const glm::dvec4& tangent, const glm::dvec2& tangentDirection);

// One texel (x, row from the bottom) as the GPU's texture holds it for `colorSpace`: linear RGB
// and alpha (see the top of this file).
glm::dvec4 texelValue(const MapImage& image, int x, int rowFromBottom, ColorEncoding colorSpace);

// A read of level 0 at `uv` as `sampler` wraps and magnifies (see the top of this file);
// sRGB-encoded images are decoded to linear RGB (alpha stays as it is). An empty image reads
// (0, 0, 0, 1).
glm::dvec4 sampleTexture(const MapImage& image, ColorEncoding colorSpace, const glm::dvec2& uv,
    const TextureSampler& sampler = {});

// The texel (x, row from the bottom) a read at `uv` falls in: the one NEAREST magnification takes
// (the bottom-left of LINEAR's four otherwise is not "the" texel), wrapped as `sampler` wraps.
// (0, 0) for an empty image.
glm::ivec2 texelAt(const MapImage& image, const glm::dvec2& uv, const TextureSampler& sampler = {});

// A surface point's texture coordinates, per set (TEXCOORD_0, TEXCOORD_1: core/mesh/Mesh.h Vertex::uv,
// uv1), before any map's UV transform.
using TexCoords = std::array<glm::dvec2, kTexCoordSets>;

// `map`'s texel at the point: its set of `uvs`, its UV transform, its colour space and sampler
// (GLSL texture(u*Map, mapUv(slot))).
glm::dvec4 sampleMap(const MaterialMap& map, const MapImage& image, const TexCoords& uvs);

// The material's inputs at texture coordinates `uvs` (before any UV transform: each map reads its
// own set and applies its own core/material/Material.h UvTransform): base colour and its alpha, metallic,
// perceptual roughness (clamped to [0, 1]), occlusion (glTF strength mix), emitted radiance and IOR (GLSL
// materialInputs). `vertexColor`: the interpolated glTF COLOR_0 (core/mesh/Mesh.h Vertex::color), which
// multiplies the base colour and alpha as the shader's HAS_VERTEX_COLOR does; white for a mesh without one.
MaterialInfo materialInputs(const Material& material, const MaterialMapImages& images, const TexCoords& uvs,
    const glm::dvec4& vertexColor = glm::dvec4(1.0));
// The same where both sets are `uv` (a texture set, a swatch: one parameterisation).
MaterialInfo materialInputs(const Material& material, const MaterialMapImages& images, const glm::dvec2& uv,
    const glm::dvec4& vertexColor = glm::dvec4(1.0));

} // namespace facet
