// Every BRDF term of core/shading/Brdf.h: include this, or only the chunk a shader needs.
#include "brdf_common.glsl"
#include "brdf_distribution.glsl"
#include "brdf_visibility.glsl"
#include "brdf_fresnel.glsl"
