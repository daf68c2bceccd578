// render/FrameAccumulator's passes over a full-screen triangle (fullscreen.vert).
// ACCUMULATE (with additive blending into a half-buffer): k * frame, alpha included (a frame's
// alpha is its coverage, 1 unless the background is transparent). Every texel of a draw has the
// same k, so the halves' sample counts are the accumulator's (uniforms), not a channel.
// Otherwise the resolve: (A + B) / (nA + nB), the mean of every sample added, coverage too.
in vec2 vUv;
out vec4 fragColor;

#ifdef ACCUMULATE
uniform sampler2D uFrame;
uniform float uSamples;
#else
uniform sampler2D uHalfA;
uniform sampler2D uHalfB;
uniform float uTotalSamples; // nA + nB
#endif

void main()
{
    ivec2 texel = ivec2(gl_FragCoord.xy);
#ifdef ACCUMULATE
    fragColor = texelFetch(uFrame, texel, 0) * uSamples;
#else
    vec4 a = texelFetch(uHalfA, texel, 0);
    vec4 b = texelFetch(uHalfB, texel, 0);
    fragColor = (a + b) / max(uTotalSamples, 1.0);
#endif
}
