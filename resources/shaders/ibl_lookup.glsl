// What a surface shader needs to read Facet's IBL textures (render/IblTextures.h). Twins of
// render/IblTextures.h: lodFromRoughness, dfgTexCoord.
//
// Prefiltered specular: level i holds perceptual roughness 1 - sqrt(1 - i / (levels - 1)), so
//   lod = (levels - 1) r (2 - r)   [Filament's perceptualRoughnessToLod; render/IblTextures.h says why].
float lodFromRoughness(float perceptualRoughness, float mipLevels)
{
    float r = clamp(perceptualRoughness, 0.0, 1.0);
    return r * (2.0 - r) * (mipLevels - 1.0);
}

// The direction to read the prefiltered map at, for normal n, mirror direction R and
// alpha = roughness^2: the split sum assumes n = v = R, but a rough lobe's peak leans from R
// towards n, the more so at grazing view. Lagarde & de Rousiers 2014 ("Moving Frostbite to PBR",
// listing 22) fit lerp(n, R, s (sqrt(s) + alpha)), s = 1 - alpha. Measured against the ground
// truth over the 18 CC0 HDRIs, gold-like metal (docs/ibl.md, "Dominant direction"): mean relative
// RMSE at roughness 0.7 / 0.85 / 1 falls from 0.54 / 0.60 / 0.95 to 0.46 / 0.55 / 0.52, within
// noise of the best constant lerp at each roughness. Twin: core/shading/SplitSum.h specularDominantDirection.
vec3 specularDominantDirection(vec3 n, vec3 R, float alpha)
{
    float smoothness = clamp(1.0 - alpha, 0.0, 1.0);
    float lerpFactor = smoothness * (sqrt(smoothness) + alpha);
    return normalize(mix(n, R, lerpFactor));
}

// DFG LUT (x = n.v, y = roughness; texel i at value i / (N - 1), core/shading/DfgTable.h): GL coordinate
// (value * (N - 1) + 0.5) / N, so a LINEAR lookup never extrapolates.
vec2 dfgTexCoord(float NoV, float perceptualRoughness, float lutSize)
{
    vec2 value = clamp(vec2(NoV, perceptualRoughness), 0.0, 1.0);
    return (value * (lutSize - 1.0) + 0.5) / lutSize;
}
