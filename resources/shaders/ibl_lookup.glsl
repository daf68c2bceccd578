// What a surface shader needs to read Facet's IBL textures (render/IblTextures.h). Twins of
// render/IblTextures.h: lodFromRoughness, dfgTexCoord.
//
// Prefiltered specular: level i holds perceptual roughness i / (levels - 1), so
//   lod = roughness * (levels - 1).
float lodFromRoughness(float perceptualRoughness, float mipLevels)
{
    return clamp(perceptualRoughness, 0.0, 1.0) * (mipLevels - 1.0);
}

// DFG LUT (x = n.v, y = roughness; texel i at value i / (N - 1), core/DfgTable.h): GL coordinate
// (value * (N - 1) + 0.5) / N, so a LINEAR lookup never extrapolates.
vec2 dfgTexCoord(float NoV, float perceptualRoughness, float lutSize)
{
    vec2 value = clamp(vec2(NoV, perceptualRoughness), 0.0, 1.0);
    return (value * (lutSize - 1.0) + 0.5) / lutSize;
}
