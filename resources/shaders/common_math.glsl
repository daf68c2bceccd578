// Shared constants and tiny helpers (no dependencies). C++ twins: core/shading/Brdf.h (kPi, pow5).
const float PI = 3.14159265358979323846;
const float INV_PI = 0.31830988618379067154;
const float TWO_PI = 6.28318530717958647692;

float saturate(float x) { return clamp(x, 0.0, 1.0); }
vec3 saturate(vec3 x) { return clamp(x, vec3(0.0), vec3(1.0)); }
float sq(float x) { return x * x; }
float pow5(float x)
{
    float x2 = x * x;
    return x2 * x2 * x;
}

// The largest channel (the glTF extensions' max_value).
float max3(vec3 c) { return max(c.r, max(c.g, c.b)); }
