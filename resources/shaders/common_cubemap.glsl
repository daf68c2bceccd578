// Cubemap faces in OpenGL's order and orientation (+X, -X, +Y, -Y, +Z, -Z; OpenGL 4.6 spec,
// table 8.19). C++ twin: core/ibl/Prefilter.h, cubemapDirection().
// uv is the face's texture coordinate (s, t) in [0, 1]: texel (x, y) of a size-N face (y = row
// in memory, as uploaded/read by glTexImage2D/glGetTexImage) has uv = ((x + 0.5) / N, (y + 0.5) / N).
// With a = 2s - 1, b = 2t - 1 the (unnormalised) direction is
//   +X: ( 1, -b, -a)   -X: (-1, -b,  a)   +Y: ( a,  1,  b)
//   -Y: ( a, -1, -b)   +Z: ( a, -b,  1)   -Z: (-a, -b, -1)
vec3 cubemapDirection(int face, vec2 uv)
{
    float a = 2.0 * uv.x - 1.0;
    float b = 2.0 * uv.y - 1.0;
    vec3 d;
    if (face == 0)
        d = vec3(1.0, -b, -a);
    else if (face == 1)
        d = vec3(-1.0, -b, a);
    else if (face == 2)
        d = vec3(a, 1.0, b);
    else if (face == 3)
        d = vec3(a, -1.0, -b);
    else if (face == 4)
        d = vec3(a, -b, 1.0);
    else
        d = vec3(-a, -b, -1.0);
    return normalize(d);
}
