// Filtered importance sampling [Krivanek & Colbert 2008, "Real-time Shading with Filtered
// Importance Sampling", GPU Gems 3 ch. 20]: a sample of pdf p (per steradian) out of N stands
// for the solid angle Omega_s = 1 / (N p); a texel of a size-w cubemap level 0 covers about
// Omega_p = 4 pi / (6 w^2). Reading the source at lod = 0.5 log2(Omega_s / Omega_p) + 1 (the +1
// over-blurs a little so neighbouring samples' footprints overlap) turns the estimator into one
// of the prefiltered source: bright small sources spread instead of sparkling. docs/ibl.md.
// The pdf is floored at 1 / (2 pi), a uniform hemisphere's: a rare sample (grazing cosine, GGX
// tail) never stands for more than 2 pi / N sr. Without the floor such samples read the 1x1
// levels, whose average holds the light from BEHIND the surface: +500% irradiance on the dark
// side of studio.exr (measured; docs/ibl.md).
#include "common_math.glsl"

float filteredLod(float pdf, float sampleCount, float sourceSize, float maxLod)
{
    float omegaS = 1.0 / (sampleCount * max(pdf, 0.5 * INV_PI));
    float omegaP = 4.0 * PI / (6.0 * sourceSize * sourceSize);
    return clamp(0.5 * log2(omegaS / omegaP) + 1.0, 0.0, maxLod);
}
