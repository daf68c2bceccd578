// Fresnel terms; twins of core/shading/Brdf.h.
#include "brdf_common.glsl"

// Schlick 1994, "An Inexpensive BRDF Model for Physically-based Rendering".
vec3 F_Schlick(vec3 f0, float f90, float VoH) { return f0 + (vec3(f90) - f0) * pow5(1.0 - saturate(VoH)); }
float F_Schlick(float f0, float f90, float VoH) { return f0 + (f90 - f0) * pow5(1.0 - saturate(VoH)); }

// Exact unpolarised dielectric Fresnel [Walter et al. 2007, eq. 22]; 1 under total internal reflection.
float F_Dielectric(float cosThetaI, float ior)
{
    float c = saturate(cosThetaI);
    float g2 = ior * ior - 1.0 + c * c;
    if (g2 < 0.0)
        return 1.0;
    float g = sqrt(g2);
    float a = (g - c) / (g + c);
    float b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    return 0.5 * a * a * (1.0 + b * b);
}

// ((n - 1) / (n + 1))^2; 1.5 gives 0.04.
float f0FromIor(float ior)
{
    float r = (ior - 1.0) / (ior + 1.0);
    return r * r;
}
float iorFromF0(float f0)
{
    float s = sqrt(clamp(f0, 0.0, 0.999999));
    return (1.0 + s) / (1.0 - s);
}
