// Test fixture (tests/EnvironmentSamplingGLTest.cpp): writes what environment_sampling.glsl and
// the sequence functions of common_sampling.glsl compute for each pixel, so the test can hold
// them against their C++ twins. uMode picks the output; pixel (x, y) is gl_FragCoord - 0.5.
#include "common_sampling.glsl"
#include "environment_sampling.glsl"

#ifdef FIXTURE_MODE
// One mode compiled alone (the cost rows): llvmpipe runs every branch of a uniform `if` under a
// mask, so a program holding all modes would time them all.
const int uMode = FIXTURE_MODE;
#else
uniform int uMode;
#endif
uniform uint uSeed;
uniform uint uStrategy;
uniform uint uSampleIndex; // mode 6, 7: the sample of the sequence every pixel takes
out vec4 fragColor;

// A 32-bit value as two exact floats (high and low 16 bits): float targets cannot carry it whole.
vec2 split(uint value) { return vec2(float(value >> 16u), float(value & 0xffffu)); }

void main()
{
    uvec2 pixel = uvec2(gl_FragCoord.xy);
    vec2 size = vec2(textureSize(uEnvironmentPdf, 0)); // unused by most modes; keeps the uniform
    uint index = pixel.y * 4096u + pixel.x;
    // Grids of 64 x 64 pixels, offset from the pixel centres by irrational-looking fractions so
    // that no point falls on a texel edge of a power-of-two map, or a uniform row's CDF step.
    vec2 gridPoint = (floor(gl_FragCoord.xy) + vec2(0.3183099, 0.2718282)) / vec2(64.0);
    if (uMode == 0) { // a sample for u = gridPoint: direction, pdf
        float pdf;
        vec3 d = sampleEnvironment(gridPoint, pdf);
        fragColor = vec4(d, pdf);
    } else if (uMode == 1) { // the world direction at equirect (u, v) = gridPoint: d, environmentPdf
        vec3 d = directionFromEquirectUv(gridPoint);
        fragColor = vec4(d, environmentPdf(d));
    } else if (uMode == 2) { // the same direction's radiance
        fragColor = vec4(environmentRadiance(directionFromEquirectUv(gridPoint)), size.x);
    } else if (uMode == 8) { // the direction's equirect uv (image frame)
        vec3 d = directionFromEquirectUv(gridPoint);
        fragColor = vec4(equirectUvFromDirection(uEnvironmentRotation * d), (uEnvironmentRotation * d).xy);
    } else if (uMode == 3) { // sobol2DBits of the pixel's index
        uvec2 bits = sobol2DBits(index);
        fragColor = vec4(split(bits.x), split(bits.y));
    } else if (uMode == 4) { // pcgHash of the index, the pixel's shift (x)
        fragColor = vec4(split(pcgHash(index)), split(cranleyPattersonShift(pixel.x, pixel.y, uSeed, uStrategy).x));
    } else if (uMode == 5) { // shiftedSobol2D of the index with the pixel's shift, sobol2D
        fragColor = vec4(shiftedSobol2D(index, cranleyPattersonShift(pixel.x, pixel.y, uSeed, uStrategy)),
                         sobol2D(index));
    } else if (uMode == 6) { // cost: one environment sample as an integrator takes it
        vec2 u = shiftedSobol2D(uSampleIndex, cranleyPattersonShift(pixel.x, pixel.y, uSeed, 1u));
        float pdf;
        vec3 d = sampleEnvironment(u, pdf);
        fragColor = vec4(environmentRadiance(d) / max(pdf, 1e-30), environmentPdf(d));
    } else if (uMode == 9) { // cost floor: the pass itself, writing the pixel's coordinates
        fragColor = vec4(gl_FragCoord.xy, 0.0, 1.0);
    } else { // cost baseline: the same sequence and a radiance lookup, no search
        vec2 u = shiftedSobol2D(uSampleIndex, cranleyPattersonShift(pixel.x, pixel.y, uSeed, 1u));
        vec3 d = directionFromEquirectUv(u);
        fragColor = vec4(environmentRadiance(d), u.x);
    }
}
