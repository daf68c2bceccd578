// Roughness remapping and guards shared by the brdf_*.glsl chunks; twins of core/shading/Brdf.h.
#include "common_math.glsl"

// Smallest perceptual roughness (Filament's MIN_PERCEPTUAL_ROUGHNESS); alpha = r^2 (glTF 2.0).
const float kMinPerceptualRoughness = 0.045;
const float kMinAlpha = kMinPerceptualRoughness * kMinPerceptualRoughness;
// Guards denominators that vanish only where the numerators do (N.V = N.L = 0). 1e-12 in the
// double C++ twin; float keeps the same value (normal range down to 1.2e-38).
const float kMinDenominator = 1e-12;

float clampRoughness(float perceptualRoughness) { return clamp(perceptualRoughness, kMinPerceptualRoughness, 1.0); }
float alphaFromRoughness(float perceptualRoughness)
{
    float r = clampRoughness(perceptualRoughness);
    return r * r;
}

// Lambert: 1 / pi (times the diffuse colour).
float Fd_Lambert() { return INV_PI; }
