// Debug view ids: DEBUG_VIEW (a variant define) takes one of these; render/ShaderVariant.h's
// DebugView enum holds the same numbers and names.
#define DEBUG_NONE 0
#define DEBUG_BASE_COLOR 1
#define DEBUG_SHADING_NORMAL 2
#define DEBUG_GEOMETRIC_NORMAL 3
#define DEBUG_METALLIC 4
#define DEBUG_ROUGHNESS 5
#define DEBUG_OCCLUSION 6
#define DEBUG_D 7
#define DEBUG_V 8
#define DEBUG_F 9
#define DEBUG_IRRADIANCE 10
#define DEBUG_IBL_DIFFUSE 11
#define DEBUG_PREFILTERED_RADIANCE 12
#define DEBUG_BRDF_LUT 13
#define DEBUG_IBL_SPECULAR 14
#define DEBUG_IBL_TOTAL 15
#define DEBUG_DIRECT_LIGHT 16
#define DEBUG_WHITE_FURNACE 17
#define DEBUG_UV 18
#define DEBUG_TANGENT 19
#define DEBUG_EMISSIVE 20
#define DEBUG_ALPHA 21
#define DEBUG_NON_FINITE 22
