// The display transform pass: HDR radiance * 2^EV -> tone mapper -> display encoding.
// Twin: core/image/ToneMap.h displayTransform().
#include "tonemap.glsl"

uniform sampler2D uHdr;
uniform float uExposureScale; // 2^EV, computed on the CPU
uniform int uToneMapper;
uniform int uDisplayEncoding;
uniform float uGamma;
// 1: the HDR target's alpha is coverage over a transparent background and its colour is
// premultiplied by it; the output is the display transform of the unpremultiplied colour with
// that alpha (straight alpha, as PNG stores it). 0: alpha 1, the colour as it is.
uniform int uStraightAlpha;

out vec4 fragColor;

void main()
{
    vec4 hdr = texelFetch(uHdr, ivec2(gl_FragCoord.xy), 0);
    float alpha = uStraightAlpha != 0 ? hdr.a : 1.0;
    vec3 radiance = uStraightAlpha == 0 ? hdr.rgb : alpha > 0.0 ? hdr.rgb / alpha : vec3(0.0);
    vec3 display = encodeDisplay(toneMap(uToneMapper, radiance * uExposureScale), uDisplayEncoding, uGamma);
    fragColor = vec4(display, alpha);
}
