// The display transform pass with an OpenColorIO display/view (render/OcioDisplayTransform):
// HDR radiance * 2^EV -> the view's transform, which ends in the display's encoding, so the
// result is written as it is (no encodeDisplay(), no clamp: OCIO's CPU processor, the twin in
// core/ColorManagement.h, does not clamp either; an 8-bit output clips). OcioDisplayTransform
// appends OCIO's generated GLSL (GPU_LANGUAGE_GLSL_4_0) after this file: it defines
// facetOcioDisplay, declared here, and the samplers and uniforms of its LUTs.

vec4 facetOcioDisplay(vec4 inPixel);

uniform sampler2D uHdr;
uniform float uExposureScale; // 2^EV, computed on the CPU

out vec4 fragColor;

void main()
{
    vec3 radiance = texelFetch(uHdr, ivec2(gl_FragCoord.xy), 0).rgb;
    fragColor = vec4(facetOcioDisplay(vec4(radiance * uExposureScale, 1.0)).rgb, 1.0);
}
