// The display transform pass with an OpenColorIO display/view (render/OcioDisplayTransform):
// HDR radiance * 2^EV -> the view's transform, which ends in the display's encoding, so the
// result is written as it is (no encodeDisplay(), no clamp: OCIO's CPU processor, the twin in
// core/image/ColorManagement.h, does not clamp either; an 8-bit output clips). OcioDisplayTransform
// appends OCIO's generated GLSL (GPU_LANGUAGE_GLSL_4_0) after this file: it defines
// facetOcioDisplay, declared here, and the samplers and uniforms of its LUTs.

vec4 facetOcioDisplay(vec4 inPixel);

uniform sampler2D uHdr;
uniform float uExposureScale; // 2^EV, computed on the CPU
uniform int uStraightAlpha; // as tonemap.frag

out vec4 fragColor;

void main()
{
    vec4 hdr = texelFetch(uHdr, ivec2(gl_FragCoord.xy), 0);
    float alpha = uStraightAlpha != 0 ? hdr.a : 1.0;
    vec3 radiance = uStraightAlpha == 0 ? hdr.rgb : alpha > 0.0 ? hdr.rgb / alpha : vec3(0.0);
    fragColor = vec4(facetOcioDisplay(vec4(radiance * uExposureScale, 1.0)).rgb, alpha);
}
