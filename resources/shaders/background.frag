// Pixels that miss the mesh: the environment (sharp), the prefiltered cubemap at a roughness
// (blurred), or a solid colour; drawn first at the far plane. Linear radiance. The sharp
// environment is the source equirect itself where the scene has it (fis, reference: bilinear,
// level 0, as core Environment::radiance), else the environment cubemap, a resampling of it that
// a wide view magnifies (a 256-texel face spans 90 degrees).
#include "common_equirect.glsl"
#include "ibl_lookup.glsl"

in vec2 vClip;

uniform mat4 uInverseViewProjection;
uniform vec3 uCameraPosition;
uniform int uBackgroundMode; // 0 environment, 1 blurred, 2 colour (core BackgroundMode)
uniform vec3 uBackgroundColor;
uniform samplerCube uEnvironmentMap;
uniform sampler2D uEnvironmentSource; // RGB32F equirect, top row first (render/EnvironmentSource)
uniform int uEnvironmentSourceBound;
uniform samplerCube uPrefilteredMap;
uniform float uPrefilteredLevels;
uniform float uBlurRoughness;
uniform mat3 uEnvironmentRotation;
uniform float uEnvironmentIntensity;
uniform float uMaxRadiance; // 65504 for RGBA16F targets (see surface.frag)
uniform float uBackgroundAlpha; // 1, or 0 when the target's alpha is the object's coverage

out vec4 fragColor;

void main()
{
    if (uBackgroundMode == 2) {
        fragColor = vec4(min(uBackgroundColor, vec3(uMaxRadiance)), uBackgroundAlpha);
        return;
    }
    vec4 farPoint = uInverseViewProjection * vec4(vClip, 1.0, 1.0);
    vec3 direction = normalize(farPoint.xyz / farPoint.w - uCameraPosition);
    vec3 d = uEnvironmentRotation * direction;
    vec3 radiance;
    if (uBackgroundMode == 1)
        radiance = textureLod(uPrefilteredMap, d, lodFromRoughness(uBlurRoughness, uPrefilteredLevels)).rgb;
    else if (uEnvironmentSourceBound != 0)
        radiance = textureLod(uEnvironmentSource, equirectTexCoord(d), 0.0).rgb;
    else
        radiance = textureLod(uEnvironmentMap, d, 0.0).rgb;
    fragColor = vec4(min(radiance * uEnvironmentIntensity, vec3(uMaxRadiance)), uBackgroundAlpha);
}
