// Debug view ids: DEBUG_VIEW (a variant define) takes one of DEBUG_NONE, DEBUG_BASE_COLOR, ...,
// which render/ShaderVariant's surfaceDefines makes from core/shading/DebugView.cpp's table (one place
// names and numbers them). Compare DEBUG_VIEW with those names, never with numbers.
#ifndef DEBUG_NONE
#error "the debug view ids are defined by render/ShaderVariant (surfaceDefines)"
#endif

#if defined(DEBUG_VIEW) && DEBUG_VIEW == DEBUG_UV_CHECKER
// 8 x 8 squares per unit of texture coordinate, light and dark, tinted red as u and green as v
// rise within each unit: a flipped or rotated island shows its tint running the other way.
vec3 uvChecker(vec2 uv)
{
    vec2 cell = floor(uv * 8.0);
    float light = mod(cell.x + cell.y, 2.0) < 0.5 ? 0.85 : 0.25;
    vec2 inUnit = fract(uv);
    return light * vec3(0.55 + 0.45 * inUnit.x, 0.55 + 0.45 * inUnit.y, 0.55);
}
#endif

#if defined(DEBUG_VIEW) && DEBUG_VIEW == DEBUG_TEXEL_DENSITY
uniform vec2 uTexelDensityMapSize; // the map measured: base colour's, else the material's largest
uniform float uTexelDensityScale; // world units per unit of the mesh's source file
uniform float uTexelDensityTarget; // texels per source unit that show green
// Texels per unit of surface at this fragment, in the source file's unit: the square root of the
// ratio of a pixel's footprint in texels to its footprint in world units (screen derivatives),
// times the world's scale. (CPU twin for tests: docs/rendering.md, "Texel density".)
float texelDensity(vec2 uv, vec3 worldPosition)
{
    vec2 uvX = dFdx(uv) * uTexelDensityMapSize;
    vec2 uvY = dFdy(uv) * uTexelDensityMapSize;
    float texelArea = abs(uvX.x * uvY.y - uvX.y * uvY.x);
    float worldArea = length(cross(dFdx(worldPosition), dFdy(worldPosition)));
    return worldArea > 0.0 ? sqrt(texelArea / worldArea) * uTexelDensityScale : 0.0;
}
// Green on target, towards blue at a quarter of it or less, towards red at four times or more.
vec3 texelDensityColor(float density)
{
    float t = clamp(log2(max(density, 1e-9) / uTexelDensityTarget) / 2.0, -1.0, 1.0);
    vec3 onTarget = vec3(0.1, 0.8, 0.1);
    return t < 0.0 ? mix(onTarget, vec3(0.1, 0.2, 0.9), -t) : mix(onTarget, vec3(0.9, 0.1, 0.1), t);
}
#endif
