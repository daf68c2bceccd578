// The environment at source resolution, and its importance sampling by luminance: the GLSL twins
// of core/ibl/Environment::radiance, core/ibl/EnvironmentSampler::sample/pdf and the table search of
// core/ibl/EnvironmentSamplingTables.h (searchCdf, sampleCdf, sampleTables). The textures come from
// render/EnvironmentSource (EnvironmentSourceTextures); docs/ibl.md "Environment sampling tables".
//
// Sampling inverts the CDFs by bisection with texelFetch (GL 4.1, fragment shaders): ceil(log2 n)
// fetches per dimension, the same count for every pixel. Inversion keeps neighbouring u in
// neighbouring cells, so the stratification of the (shifted) Sobol' points survives; an alias
// table would not.
#include "common_math.glsl"
#include "common_equirect.glsl"
#include "environment_frame.glsl"

// RGB32F, W x H, rows top first (t = 0 is the image's top row), GL_LINEAR, REPEAT in s,
// CLAMP_TO_EDGE in t, one level: bilinear between texel centres as Environment::radiance.
uniform sampler2D uEnvironmentSource;
// R32F, NEAREST, CLAMP_TO_EDGE, read with texelFetch only. Rows in DISTRIBUTION order: texel
// row r is v in [r/H, (r+1)/H), image row H-1-r.
uniform sampler2D uEnvironmentConditionalCdf; // (W+1) x H: texel (i, r) = row r's CDF at i / W
uniform sampler2D uEnvironmentMarginalCdf; // (H+1) x 1: texel (i, 0) = the rows' CDF at i / H
uniform sampler2D uEnvironmentPdf; // W x H: texel (c, r) = density of (u, v) in the cell

// Radiance arriving from world direction `direction` (unit), times intensity.
vec3 environmentRadiance(vec3 direction)
{
    // Level 0 explicitly: implicit derivatives jump at the u = 0/1 seam.
    return textureLod(uEnvironmentSource, equirectTexCoord(uEnvironmentRotation * direction), 0.0).rgb
        * uEnvironmentIntensity;
}

// The largest i in [0, cells) with cdf(i) <= u, cdf(i) being texel (i, row) of `cdf`.
int searchCdf(sampler2D cdf, int row, int cells, float u)
{
    int first = 0;
    int count = cells;
    while (count > 1) {
        int halfCount = count / 2;
        if (texelFetch(cdf, ivec2(first + halfCount, row), 0).r <= u)
            first += halfCount;
        count -= halfCount;
    }
    return first;
}

// x in [0, 1) with density proportional to the CDF's steps; `cell` receives its cell.
float sampleCdf(sampler2D cdf, int row, int cells, float u, out int cell)
{
    cell = searchCdf(cdf, row, cells, u);
    float lower = texelFetch(cdf, ivec2(cell, row), 0).r;
    float width = texelFetch(cdf, ivec2(cell + 1, row), 0).r - lower;
    float du = width > 0.0 ? (u - lower) / width : 0.5;
    return min((float(cell) + clamp(du, 0.0, 1.0)) / float(cells), 0.99999994); // below 1, as on the CPU
}

// (u, v) of the image drawn with the tables' density; pdfUv w.r.t. area of the unit square.
vec2 sampleTables(vec2 u, out float pdfUv, out ivec2 cell)
{
    ivec2 size = textureSize(uEnvironmentPdf, 0);
    int row;
    int column;
    float v = sampleCdf(uEnvironmentMarginalCdf, 0, size.y, u.y, row);
    float x = sampleCdf(uEnvironmentConditionalCdf, row, size.x, u.x, column);
    cell = ivec2(column, row);
    pdfUv = texelFetch(uEnvironmentPdf, cell, 0).r;
    return vec2(x, v);
}

// A world direction drawn in proportion to the environment's (3x3 max-filtered) luminance, and
// its pdf w.r.t. solid angle: d(omega) = 2 pi^2 cos(lat) du dv.
vec3 sampleEnvironment(vec2 u, out float pdf)
{
    float pdfUv;
    ivec2 cell;
    vec2 uv = sampleTables(u, pdfUv, cell);
    // cos(lat) = sin(pi v) = sin(pi (1 - v)): from the side nearer its pole, so it keeps its
    // relative precision in the polar rows (sqrt(1 - y^2) loses it there in float).
    float cosLat = sin(PI * min(uv.y, 1.0 - uv.y));
    pdf = cosLat > 0.0 ? pdfUv / (2.0 * PI * PI * cosLat) : 0.0;
    return transpose(uEnvironmentRotation) * directionFromEquirectUv(uv);
}

// The pdf w.r.t. solid angle with which sampleEnvironment draws world direction `direction`
// (unit): for the multiple-importance weight of a direction sampled otherwise.
float environmentPdf(vec3 direction)
{
    vec3 local = uEnvironmentRotation * direction;
    float cosLat = length(local.xz);
    if (cosLat <= 0.0)
        return 0.0;
    ivec2 size = textureSize(uEnvironmentPdf, 0);
    ivec2 cell = clamp(ivec2(equirectUvFromDirection(local) * vec2(size)), ivec2(0), size - 1);
    return texelFetch(uEnvironmentPdf, cell, 0).r / (2.0 * PI * PI * cosLat);
}
