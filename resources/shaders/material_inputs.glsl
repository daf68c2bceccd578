// The material's inputs at a fragment (the glTF Sample Viewer's MaterialInfo), from constant
// factors and, where the variant says HAS_*_MAP, one texture each. Twin of what core's
// MaterialInfo holds after textures (core/material/Material.h explains every factor).
//
// Slots (core/material/Material.h MapSlot): SLOT_BASE_COLOR, SLOT_NORMAL, ..., SLOT_SHEEN_ROUGHNESS,
// MAP_SLOT_COUNT of them, their numbers defined from MapSlot (render/ShaderVariant surfaceDefines).
// Per slot: uUvTransform (KHR_texture_transform matrix, core UvTransform::matrix()), uChannel
// (0 rgb, 1 r, 2 g, 3 b, 4 a: core MapChannel), uInvert (scalar maps: 1 - value), uTexCoord (the
// UV set, 0 or 1: glTF textureInfo.texCoord), uFlipGreen (normal maps: DirectX convention). Wraps and filters are the unit's sampler object
// (core TextureSampler, render/TextureCache samplerFor).
// sRGB-encoded maps are uploaded as GL_SRGB8_ALPHA8, so texture() returns linear values
// (decoded before filtering, as the sRGB specification intends); no decode happens here.

struct MaterialInfo {
    vec3 baseColor;            // linear
    float metallic;
    float perceptualRoughness; // clamped to kMinPerceptualRoughness where used
    float ior;
    float occlusion;           // multiplies indirect light only
    vec3 emissive;             // emitted radiance (factor x texture x strength)
    float alpha;               // base colour alpha (factor x texture), for ALPHA_MASK / ALPHA_BLEND
    // KHR_materials_clearcoat (MATERIAL_CLEARCOAT; 0 without it): strength, perceptual roughness
    // and the coat's normal (surface.frag sets it: the geometric normal, or the coat's normal map's;
    // core's MaterialInfo::clearcoatNormal).
    float clearcoat;
    float clearcoatRoughness;
    vec3 clearcoatNormal;
    // KHR_materials_sheen (MATERIAL_SHEEN; black and 0 without it): colour (linear) and
    // perceptual roughness (core's MaterialInfo::sheenColor, sheenRoughness).
    vec3 sheenColor;
    float sheenRoughness;
    // KHR_materials_specular (MATERIAL_SPECULAR; 1 and white without it): the dielectric's
    // specular strength and F0 tint (linear, may exceed 1; core's MaterialInfo::specular,
    // specularColor).
    float specular;
    vec3 specularColor;
    // KHR_materials_anisotropy (MATERIAL_ANISOTROPY; 0 without it): the strength, the direction in
    // the tangent plane (x along the tangent, y the bitangent) and, set by surface.frag from the
    // tangent frame, the direction in world space (vec3(0): none, isotropic); core's
    // MaterialInfo::anisotropy, anisotropyTangentDirection, anisotropyDirection.
    float anisotropy;
    vec2 anisotropyTangentDirection;
    vec3 anisotropyDirection;
    // KHR_materials_iridescence (MATERIAL_IRIDESCENCE; 0 without it): the film's strength, index
    // and thickness in nanometres (core's MaterialInfo::iridescence, iridescenceIor,
    // iridescenceThickness).
    float iridescence;
    float iridescenceIor;
    float iridescenceThickness;
    // Under the energy-preserving coupling: the F0 of the film's Schlick layer (brdf_compose.glsl
    // filmLayer, 11 film Fresnels), set once per pixel by surface.frag, not in every sample's
    // evaluateBrdf (core computes it per call: MaterialBrdf filmLayer).
    float filmLayerF0;
};

uniform vec4 uBaseColorFactor;
uniform float uMetallicFactor;
uniform float uRoughnessFactor;
uniform float uOcclusionStrength;
uniform float uNormalStrength;
uniform float uIor;
uniform vec3 uEmissiveFactor; // core Material::emissive(): factor x strength
#ifdef MATERIAL_CLEARCOAT
uniform float uClearcoatFactor;
uniform float uClearcoatRoughness;
#endif
#ifdef MATERIAL_SHEEN
uniform vec3 uSheenColorFactor;
uniform float uSheenRoughness;
#endif
#ifdef MATERIAL_SPECULAR
uniform float uSpecularFactor;
uniform vec3 uSpecularColorFactor;
#endif
#ifdef MATERIAL_ANISOTROPY
uniform float uAnisotropyFactor;
uniform vec2 uAnisotropyRotation; // (cos, sin) of Material::anisotropyRotationDegrees
#ifdef HAS_ANISOTROPY_MAP
uniform sampler2D uAnisotropyMap;
#endif
#endif
#ifdef MATERIAL_IRIDESCENCE
uniform float uIridescenceFactor;
uniform float uIridescenceIor;
uniform vec2 uIridescenceThickness; // (minimum, maximum) in nm: the thickness texture's 0 and 1
#ifdef HAS_IRIDESCENCE_MAP
uniform sampler2D uIridescenceMap;
#endif
#if defined(HAS_IRIDESCENCE_THICKNESS_MAP) && !defined(IRIDESCENCE_THICKNESS_TEXEL_FROM_IRIDESCENCE)
uniform sampler2D uIridescenceThicknessMap;
#endif
#endif
uniform mat3 uUvTransform[MAP_SLOT_COUNT];
uniform int uChannel[MAP_SLOT_COUNT];
uniform int uInvert[MAP_SLOT_COUNT];
uniform int uTexCoord[MAP_SLOT_COUNT];
uniform int uFlipGreen[MAP_SLOT_COUNT];

#ifdef HAS_BASE_COLOR_MAP
uniform sampler2D uBaseColorMap;
#endif
#ifdef HAS_NORMAL_MAP
uniform sampler2D uNormalMap;
#endif
#ifdef HAS_METALLIC_MAP
uniform sampler2D uMetallicMap;
#endif
// ROUGHNESS_TEXEL_FROM_METALLIC, OCCLUSION_TEXEL_FROM_*: the slot's texture is an earlier slot's
// (one packed file, same UV transform), whose texel it reuses: one fetch, no sampler of its own.
#if defined(HAS_ROUGHNESS_MAP) && !defined(ROUGHNESS_TEXEL_FROM_METALLIC)
uniform sampler2D uRoughnessMap;
#endif
#if defined(HAS_OCCLUSION_MAP) && !defined(OCCLUSION_TEXEL_FROM_METALLIC) && !defined(OCCLUSION_TEXEL_FROM_ROUGHNESS)
uniform sampler2D uOcclusionMap;
#endif
#ifdef HAS_EMISSIVE_MAP
uniform sampler2D uEmissiveMap;
#endif
#ifdef MATERIAL_CLEARCOAT
#ifdef HAS_CLEARCOAT_MAP
uniform sampler2D uClearcoatMap;
#endif
#if defined(HAS_CLEARCOAT_ROUGHNESS_MAP) && !defined(CLEARCOAT_ROUGHNESS_TEXEL_FROM_CLEARCOAT)
uniform sampler2D uClearcoatRoughnessMap;
#endif
#ifdef HAS_CLEARCOAT_NORMAL_MAP
uniform sampler2D uClearcoatNormalMap;
uniform float uClearcoatNormalStrength;
#endif
#endif
#ifdef MATERIAL_SHEEN
#ifdef HAS_SHEEN_COLOR_MAP
uniform sampler2D uSheenColorMap;
#endif
#if defined(HAS_SHEEN_ROUGHNESS_MAP) && !defined(SHEEN_ROUGHNESS_TEXEL_FROM_SHEEN_COLOR)
uniform sampler2D uSheenRoughnessMap;
#endif
#endif
#ifdef MATERIAL_SPECULAR
#ifdef HAS_SPECULAR_COLOR_MAP
uniform sampler2D uSpecularColorMap;
#endif
#if defined(HAS_SPECULAR_MAP) && !defined(SPECULAR_TEXEL_FROM_SPECULAR_COLOR)
uniform sampler2D uSpecularMap;
#endif
#endif

#ifdef HAS_TEXCOORD_1
in vec2 vUv1; // glTF TEXCOORD_1 from surface.vert
#endif

// The slot's texture coordinates: its UV set (`uv` is set 0), through its UV transform. Without
// HAS_TEXCOORD_1 the mesh has no second set (or no sampled map reads it): set 0.
vec2 mapUv(int slot, vec2 uv)
{
#ifdef HAS_TEXCOORD_1
    if (uTexCoord[slot] == 1)
        uv = vUv1;
#endif
    return (uUvTransform[slot] * vec3(uv, 1.0)).xy;
}

float pickChannel(vec4 texel, int channel)
{
    if (channel == 2)
        return texel.g;
    if (channel == 3)
        return texel.b;
    if (channel == 4)
        return texel.a;
    return texel.r; // r, or rgb on a scalar map: the red channel
}

float scalarMapValue(int slot, vec4 texel)
{
    float value = pickChannel(texel, uChannel[slot]);
    return uInvert[slot] != 0 ? 1.0 - value : value;
}

#ifdef HAS_VERTEX_COLOR
in vec4 vColor; // glTF COLOR_0 from surface.vert
#endif

MaterialInfo materialInputs(vec2 uv)
{
    MaterialInfo m;
    m.baseColor = uBaseColorFactor.rgb;
    m.alpha = uBaseColorFactor.a;
#ifdef HAS_BASE_COLOR_MAP
    vec4 base = texture(uBaseColorMap, mapUv(SLOT_BASE_COLOR, uv));
    m.baseColor *= uChannel[SLOT_BASE_COLOR] == 0 ? base.rgb : vec3(pickChannel(base, uChannel[SLOT_BASE_COLOR]));
    // A single-channel pick is a greyscale colour without coverage of its own.
    if (uChannel[SLOT_BASE_COLOR] == 0)
        m.alpha *= base.a;
#endif
#ifdef HAS_VERTEX_COLOR
    // glTF COLOR_0 multiplies the base colour and its alpha (glTF 2.0 section 3.9.2).
    m.baseColor *= vColor.rgb;
    m.alpha *= vColor.a;
#endif
    m.emissive = uEmissiveFactor;
#ifdef HAS_EMISSIVE_MAP
    m.emissive *= texture(uEmissiveMap, mapUv(SLOT_EMISSIVE, uv)).rgb;
#endif
    m.metallic = uMetallicFactor;
#ifdef HAS_METALLIC_MAP
    vec4 metallicTexel = texture(uMetallicMap, mapUv(SLOT_METALLIC, uv));
    m.metallic *= scalarMapValue(SLOT_METALLIC, metallicTexel);
#endif
    m.perceptualRoughness = uRoughnessFactor;
#ifdef HAS_ROUGHNESS_MAP
#ifdef ROUGHNESS_TEXEL_FROM_METALLIC
    vec4 roughnessTexel = metallicTexel;
#else
    vec4 roughnessTexel = texture(uRoughnessMap, mapUv(SLOT_ROUGHNESS, uv));
#endif
    m.perceptualRoughness *= scalarMapValue(SLOT_ROUGHNESS, roughnessTexel);
#endif
    m.occlusion = 1.0;
#ifdef HAS_OCCLUSION_MAP
#if defined(OCCLUSION_TEXEL_FROM_METALLIC)
    vec4 occlusionTexel = metallicTexel;
#elif defined(OCCLUSION_TEXEL_FROM_ROUGHNESS)
    vec4 occlusionTexel = roughnessTexel;
#else
    vec4 occlusionTexel = texture(uOcclusionMap, mapUv(SLOT_OCCLUSION, uv));
#endif
    // glTF occlusionTexture.strength: mix(1, ao, strength).
    m.occlusion = 1.0 + uOcclusionStrength * (scalarMapValue(SLOT_OCCLUSION, occlusionTexel) - 1.0);
#endif
    // Reflectances and occlusion are fractions: a float map beyond [0, 1] (an EXR of 5.0) must not
    // make light from nothing (issue 29: a white furnace sphere reflected 5x its light). Emission
    // is radiance and stays unbounded above.
    m.baseColor = clamp(m.baseColor, vec3(0.0), vec3(1.0));
    m.emissive = max(m.emissive, vec3(0.0));
    m.occlusion = clamp(m.occlusion, 0.0, 1.0);
    m.alpha = clamp(m.alpha, 0.0, 1.0);
    m.metallic = clamp(m.metallic, 0.0, 1.0);
    m.perceptualRoughness = clamp(m.perceptualRoughness, 0.0, 1.0);
    m.ior = uIor;
#ifdef MATERIAL_CLEARCOAT
    // Strength in R and roughness in G of the extension's textures (the slots' channels say).
    m.clearcoat = uClearcoatFactor;
#ifdef HAS_CLEARCOAT_MAP
    vec4 clearcoatTexel = texture(uClearcoatMap, mapUv(SLOT_CLEARCOAT, uv));
    m.clearcoat *= scalarMapValue(SLOT_CLEARCOAT, clearcoatTexel);
#endif
    m.clearcoatRoughness = uClearcoatRoughness;
#ifdef HAS_CLEARCOAT_ROUGHNESS_MAP
#ifdef CLEARCOAT_ROUGHNESS_TEXEL_FROM_CLEARCOAT
    vec4 clearcoatRoughnessTexel = clearcoatTexel;
#else
    vec4 clearcoatRoughnessTexel = texture(uClearcoatRoughnessMap, mapUv(SLOT_CLEARCOAT_ROUGHNESS, uv));
#endif
    m.clearcoatRoughness *= scalarMapValue(SLOT_CLEARCOAT_ROUGHNESS, clearcoatRoughnessTexel);
#endif
    m.clearcoat = clamp(m.clearcoat, 0.0, 1.0);
    m.clearcoatRoughness = clamp(m.clearcoatRoughness, 0.0, 1.0);
#else
    m.clearcoat = 0.0;
    m.clearcoatRoughness = 0.0;
#endif
    m.clearcoatNormal = vec3(0.0, 0.0, 1.0); // the caller's geometric normal replaces it
#ifdef MATERIAL_SHEEN
    // Colour in RGB (sRGB-decoded by the upload) and roughness in A of the extension's textures;
    // an sRGB texture's alpha is linear, so one packed texture feeds both with one fetch.
    m.sheenColor = uSheenColorFactor;
#ifdef HAS_SHEEN_COLOR_MAP
    vec4 sheenColorTexel = texture(uSheenColorMap, mapUv(SLOT_SHEEN_COLOR, uv));
    m.sheenColor *= sheenColorTexel.rgb;
#endif
    m.sheenRoughness = uSheenRoughness;
#ifdef HAS_SHEEN_ROUGHNESS_MAP
#ifdef SHEEN_ROUGHNESS_TEXEL_FROM_SHEEN_COLOR
    vec4 sheenRoughnessTexel = sheenColorTexel;
#else
    vec4 sheenRoughnessTexel = texture(uSheenRoughnessMap, mapUv(SLOT_SHEEN_ROUGHNESS, uv));
#endif
    m.sheenRoughness *= scalarMapValue(SLOT_SHEEN_ROUGHNESS, sheenRoughnessTexel);
#endif
    m.sheenColor = clamp(m.sheenColor, vec3(0.0), vec3(1.0));
    m.sheenRoughness = clamp(m.sheenRoughness, 0.0, 1.0);
#else
    m.sheenColor = vec3(0.0);
    m.sheenRoughness = 0.0;
#endif
#ifdef MATERIAL_SPECULAR
    // Colour in RGB (sRGB-decoded by the upload) and strength in A of the extension's textures
    // (specularColorTexture, specularTexture; often one file): the colour read first, so the
    // strength can reuse its texel. The colour may exceed 1 (its factor may).
    m.specularColor = uSpecularColorFactor;
#ifdef HAS_SPECULAR_COLOR_MAP
    vec4 specularColorTexel = texture(uSpecularColorMap, mapUv(SLOT_SPECULAR_COLOR, uv));
    m.specularColor *= specularColorTexel.rgb;
#endif
    m.specular = uSpecularFactor;
#ifdef HAS_SPECULAR_MAP
#ifdef SPECULAR_TEXEL_FROM_SPECULAR_COLOR
    vec4 specularTexel = specularColorTexel;
#else
    vec4 specularTexel = texture(uSpecularMap, mapUv(SLOT_SPECULAR, uv));
#endif
    m.specular *= scalarMapValue(SLOT_SPECULAR, specularTexel);
#endif
    m.specular = clamp(m.specular, 0.0, 1.0);
    m.specularColor = max(m.specularColor, vec3(0.0));
#else
    m.specular = 1.0;
    m.specularColor = vec3(1.0);
#endif
#ifdef MATERIAL_ANISOTROPY
    // The extension's texture: RG the direction (x 2 - 1), B the strength's multiplier; without it
    // the direction is the tangent. The rotation turns it counter-clockwise (core
    // shading::anisotropyDirection; a zero-length direction is taken as the tangent).
    m.anisotropy = uAnisotropyFactor;
    vec2 direction = vec2(1.0, 0.0);
#ifdef HAS_ANISOTROPY_MAP
    vec3 anisotropyTexel = texture(uAnisotropyMap, mapUv(SLOT_ANISOTROPY, uv)).rgb;
    direction = anisotropyTexel.rg * 2.0 - 1.0;
    m.anisotropy *= anisotropyTexel.b;
    float directionLength = length(direction);
    direction = directionLength > 1e-12 ? direction / directionLength : vec2(1.0, 0.0);
#endif
    m.anisotropy = clamp(m.anisotropy, 0.0, 1.0);
    m.anisotropyTangentDirection = mat2(uAnisotropyRotation.x, uAnisotropyRotation.y, -uAnisotropyRotation.y,
                                        uAnisotropyRotation.x) * direction;
#else
    m.anisotropy = 0.0;
    m.anisotropyTangentDirection = vec2(1.0, 0.0);
#endif
    m.anisotropyDirection = vec3(0.0); // surface.frag maps the tangent-plane direction
#ifdef MATERIAL_IRIDESCENCE
    // The strength in R and the thickness in G of the extension's textures (often one file: the
    // thickness then reuses the strength's texel); the thickness mix(minimum, maximum, G), the
    // maximum without a texture.
    m.iridescence = uIridescenceFactor;
#ifdef HAS_IRIDESCENCE_MAP
    vec4 iridescenceTexel = texture(uIridescenceMap, mapUv(SLOT_IRIDESCENCE, uv));
    m.iridescence *= scalarMapValue(SLOT_IRIDESCENCE, iridescenceTexel);
#endif
    m.iridescence = clamp(m.iridescence, 0.0, 1.0);
    m.iridescenceIor = uIridescenceIor;
    m.iridescenceThickness = uIridescenceThickness.y;
#ifdef HAS_IRIDESCENCE_THICKNESS_MAP
#ifdef IRIDESCENCE_THICKNESS_TEXEL_FROM_IRIDESCENCE
    vec4 iridescenceThicknessTexel = iridescenceTexel;
#else
    vec4 iridescenceThicknessTexel = texture(uIridescenceThicknessMap, mapUv(SLOT_IRIDESCENCE_THICKNESS, uv));
#endif
    m.iridescenceThickness = mix(uIridescenceThickness.x, uIridescenceThickness.y,
                                 scalarMapValue(SLOT_IRIDESCENCE_THICKNESS, iridescenceThicknessTexel));
#endif
    m.iridescenceThickness = max(m.iridescenceThickness, 0.0);
#else
    m.iridescence = 0.0;
    m.iridescenceIor = 1.3;
    m.iridescenceThickness = 400.0;
#endif
    return m;
}

// The shading normal: the geometric normal ng (unit, facing the viewer), perturbed by a
// tangent-space normal map (OpenGL convention, +Y green; uFlipGreen for DirectX maps) scaled in
// X and Y by the strength (glTF normalTexture.scale): the base's (HAS_NORMAL_MAP) and the coat's
// (HAS_CLEARCOAT_NORMAL_MAP, clearcoatNormalTexture). Twin of core's shadingNormal().
#ifdef HAS_TANGENT_FRAME
// The unit tangent perpendicular to ng (Gram-Schmidt: the interpolated tangent is neither), or
// vec3(0) when the tangent is degenerate.
vec3 surfaceTangent(vec3 ng, vec4 tangent)
{
    vec3 t = tangent.xyz - ng * dot(ng, tangent.xyz);
    float tLength = length(t);
    return tLength < 1e-8 ? vec3(0.0) : t / tLength;
}

vec3 mappedNormal(vec3 ng, vec4 tangent, vec4 texel, int slot, float strength)
{
    vec3 t = surfaceTangent(ng, tangent);
    if (t == vec3(0.0))
        return ng; // degenerate tangent: no frame to map in
    vec3 b = cross(ng, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
    vec3 tn = texel.rgb * 2.0 - 1.0;
    if (uFlipGreen[slot] != 0)
        tn.y = -tn.y;
    tn.xy *= strength;
    vec3 n = t * tn.x + b * tn.y + ng * tn.z;
    float nLength = length(n);
    return nLength > 1e-8 ? n / nLength : ng;
}
#endif

#ifdef MATERIAL_ANISOTROPY
// The anisotropy direction in world space: the tangent-plane direction through the frame
// (t, b = cross(ng, t) w), unit; vec3(0) where the frame degenerates. Twin of core's
// surfaceAnisotropyDirection.
vec3 anisotropyDirection(vec3 ng, vec4 tangent, vec2 tangentDirection)
{
    vec3 t = surfaceTangent(ng, tangent);
    if (t == vec3(0.0))
        return vec3(0.0);
    vec3 b = cross(ng, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
    vec3 d = t * tangentDirection.x + b * tangentDirection.y;
    float dLength = length(d);
    return dLength > 1e-8 ? d / dLength : vec3(0.0);
}
#endif

#ifdef HAS_NORMAL_MAP
vec3 shadingNormal(vec3 ng, vec4 tangent, vec2 uv)
{
    return mappedNormal(ng, tangent, texture(uNormalMap, mapUv(SLOT_NORMAL, uv)), SLOT_NORMAL, uNormalStrength);
}
#endif

#if defined(MATERIAL_CLEARCOAT) && defined(HAS_CLEARCOAT_NORMAL_MAP)
vec3 clearcoatNormal(vec3 ng, vec4 tangent, vec2 uv)
{
    return mappedNormal(ng, tangent, texture(uClearcoatNormalMap, mapUv(SLOT_CLEARCOAT_NORMAL, uv)),
                        SLOT_CLEARCOAT_NORMAL, uClearcoatNormalStrength);
}
#endif
