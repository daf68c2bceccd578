// render/FrameAccumulator's passes over a full-screen triangle (fullscreen.vert).
// ACCUMULATE (with additive blending into a half-buffer): (k * frame.rgb, k).
// Otherwise the resolve: (A.rgb + B.rgb) / (A.a + B.a), the mean of every sample added.
in vec2 vUv;
out vec4 fragColor;

#ifdef ACCUMULATE
uniform sampler2D uFrame;
uniform float uSamples;
#else
uniform sampler2D uHalfA;
uniform sampler2D uHalfB;
#endif

void main()
{
    ivec2 texel = ivec2(gl_FragCoord.xy);
#ifdef ACCUMULATE
    fragColor = vec4(texelFetch(uFrame, texel, 0).rgb * uSamples, uSamples);
#else
    vec4 a = texelFetch(uHalfA, texel, 0);
    vec4 b = texelFetch(uHalfB, texel, 0);
    fragColor = vec4((a.rgb + b.rgb) / max(a.a + b.a, 1.0), 1.0);
#endif
}
