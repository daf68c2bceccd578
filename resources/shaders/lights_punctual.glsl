// KHR_lights_punctual lights (directional in lux, point and spot in candela), with the glTF
// Sample Viewer's punctual.glsl names. Twins: core/shading/Punctual.h (getRangeAttenuation,
// getSpotAttenuation); render/Renderer.cpp fills the uniforms from core/project/Light.h.
#include "common_math.glsl"

const int LIGHT_DIRECTIONAL = 0;
const int LIGHT_POINT = 1;
const int LIGHT_SPOT = 2;

uniform int uLightCount;
uniform int uLightType[MAX_LIGHTS];
uniform vec3 uLightIntensity[MAX_LIGHTS]; // linear colour * intensity (lux or candela)
uniform vec3 uLightPosition[MAX_LIGHTS];
uniform vec3 uLightDirection[MAX_LIGHTS]; // unit, the direction the light travels
uniform float uLightRange[MAX_LIGHTS];    // <= 0: infinite
uniform vec2 uLightConeCos[MAX_LIGHTS];   // (cos outer, cos inner)

// clamp(1 - (d / range)^4, 0, 1)^2 / d^2; range <= 0: 1 / d^2.
float getRangeAttenuation(float range, float distance)
{
    float d2 = max(distance * distance, 1e-12);
    if (range <= 0.0)
        return 1.0 / d2;
    float ratio = distance / range;
    float window = clamp(1.0 - ratio * ratio * ratio * ratio, 0.0, 1.0);
    return window * window / d2;
}

// Squared linear ramp between the outer and inner cone cosines.
float getSpotAttenuation(vec3 pointToLight, vec3 spotDirection, float outerConeCos, float innerConeCos)
{
    float actualCos = dot(spotDirection, -pointToLight);
    if (actualCos <= outerConeCos)
        return 0.0;
    if (actualCos >= innerConeCos)
        return 1.0;
    float t = (actualCos - outerConeCos) / max(innerConeCos - outerConeCos, 1e-12);
    return t * t;
}

// Unit direction from the surface point towards light i, and the irradiance it delivers at
// normal incidence (lux-equivalent) in *irradiance.
vec3 lightDirection(int i, vec3 position, out vec3 irradiance)
{
    if (uLightType[i] == LIGHT_DIRECTIONAL) {
        irradiance = uLightIntensity[i];
        return -uLightDirection[i];
    }
    vec3 toLight = uLightPosition[i] - position;
    float distance = length(toLight);
    vec3 l = distance > 0.0 ? toLight / distance : vec3(0.0, 1.0, 0.0);
    float attenuation = getRangeAttenuation(uLightRange[i], distance);
    if (uLightType[i] == LIGHT_SPOT)
        attenuation *= getSpotAttenuation(l, uLightDirection[i], uLightConeCos[i].x, uLightConeCos[i].y);
    irradiance = uLightIntensity[i] * attenuation;
    return l;
}
