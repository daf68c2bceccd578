// Filtered importance sampling [Krivanek & Colbert 2008, "Real-time Shading with Filtered
// Importance Sampling", GPU Gems 3 ch. 20]: a sample of pdf p (per steradian) out of N stands
// for the solid angle Omega_s = 1 / (N p); reading the source cube at the level whose texels
// cover about that much turns the estimator into one of the prefiltered source: bright small
// sources spread instead of sparkling. The prefiltered levels' lods are made on the CPU with the
// samples (core/ibl/Prefilter.h filteredLod: face-average texel, +1 bias; docs/ibl.md pass 3).
// The pdf is floored at 1 / (2 pi), a uniform hemisphere's: a rare sample (grazing cosine, GGX
// tail) never stands for more than 2 pi / N sr. Without the floor such samples read the 1x1
// levels, whose average holds the light from BEHIND the surface: +500% irradiance on the dark
// side of studio.exr (measured; docs/ibl.md).
#include "common_math.glsl"

// The footprint against the texel the lookup actually reads (Filament's pre-filtered importance
// sampling; Colbert & Krivanek eq. 13 with the exact texel): a cube texel of a size-w face at
// unit direction d spans Omega_p(d) = (2/w)^2 / (1 + a^2 + b^2)^(3/2) = 4 |d|_max^3 / w^2 (a, b
// the face coordinates), from 4/w^2 at a face's centre to 0.77/w^2 at its corner, where
// the prefilter's face average 4 pi / (6 w^2) = 2.09/w^2 reads too sharp a level at the centre and
// too blurred a one at the corners. lod = 0.5 log2(Omega_s / Omega_p(d)), without filteredLod's
// +1: for IblMethod::Fis the +1's blur is bias (64 samples, five CC0 maps, 64^2 reference view:
// median 2.22% / worst 27.3% with it, 1.84% / 15.5% without; +0.5 and -0.5 measured worse;
// docs/benchmarks.md "IBL methods"). Twin: core/ibl/Prefilter.h filteredLodAt.
float cubeTexelSolidAngle(vec3 d, float size)
{
    vec3 a = abs(d);
    float major = max(a.x, max(a.y, a.z));
    return 4.0 * major * major * major / (size * size);
}

float filteredLodAt(float pdf, float sampleCount, float sourceSize, float maxLod, vec3 d)
{
    float omegaS = 1.0 / (sampleCount * max(pdf, 0.5 * INV_PI));
    return clamp(0.5 * log2(omegaS / cubeTexelSolidAngle(d, sourceSize)), 0.0, maxLod);
}
