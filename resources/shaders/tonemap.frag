// The display transform pass: HDR radiance * 2^EV -> tone mapper -> display encoding.
// Twin: core/ToneMap.h displayTransform().
#include "tonemap.glsl"

uniform sampler2D uHdr;
uniform float uExposureScale; // 2^EV, computed on the CPU
uniform int uToneMapper;
uniform int uDisplayEncoding;
uniform float uGamma;

out vec4 fragColor;

void main()
{
    vec3 radiance = texelFetch(uHdr, ivec2(gl_FragCoord.xy), 0).rgb;
    vec3 display = encodeDisplay(toneMap(uToneMapper, radiance * uExposureScale), uDisplayEncoding, uGamma);
    fragColor = vec4(display, 1.0);
}
