#pragma once
// KHR_materials_sheen's BRDF terms, in double: the sheen lobe's CPU ground truth and the albedo
// table every method reads (docs/shading.md, "Sheen"; docs/layered-lobes.md holds the extension's
// text and how other renderers read it). The CPU material BRDF (core/shading/MaterialBrdf)
// evaluates the lobe and its layering; resources/shaders/brdf_sheen.glsl is the GLSL twin, and
// render/SheenLut uploads the table.
//
//   D_Charlie(n.h, a)  = (2 + 1/a) (1 - (n.h)^2)^(1 / (2a)) / (2 pi)       a = sheenRoughness^2
//   V_Charlie          = 1 / ((1 + lambda(n.v) + lambda(n.l)) 4 n.v n.l)   (the extension's choice)
//   V_Neubelt          = 1 / (4 (n.l + n.v - n.l n.v))                      (Filament's, "Ashikhmin")
//   sheen_brdf         = sheenColor D V                                    (no Fresnel)
//   scaling            = min(1 - max3(sheenColor) E(n.v), 1 - max3(sheenColor) E(n.l))
//   f                  = sheen_brdf + scaling f_base                       (the extension's layering)
//
// [Estevez and Kulla 2017, "Production Friendly Microfacet Sheen BRDF"; Neubelt and Pettineo 2013]

#include <vector>

#include <glm/vec3.hpp>

namespace facet::shading {

// Smallest sheen alpha used: the extension's distribution is singular at roughness 0 (the glTF
// Sample Viewer clamps the roughness to 1e-6 before squaring; this keeps the exponent finite in
// double, 1/(2a) = 5e11 at most).
inline constexpr double kMinSheenAlpha = 1e-12;

// The sheen's "Charlie" distribution: a sine power, peaked where h grazes the surface.
double D_Charlie(double NoH, double sheenAlpha);
// The fitted Smith lambda of the Charlie distribution [Estevez and Kulla 2017, eq. 3 and table 1].
double lambdaSheen(double cosTheta, double sheenAlpha);
// Its height-correlated visibility, and Neubelt's cheaper one that Filament uses.
double V_Charlie(double NoV, double NoL, double sheenAlpha);
double V_Neubelt(double NoV, double NoL);

enum class SheenVisibility { Charlie, Neubelt };

// E(n.v, r): the directional albedo of the sheen lobe with sheenColor 1, integral of D V (n.l)
// over the hemisphere, by a midpoint rule in (theta, phi) of `steps` x 4 `steps` cells (the
// integrand is smooth in both; 256 steps converge to 1e-4 for r >= 0.25). The extension's albedo
// scaling of the base, 1 - max(sheenColor) E, reads it.
double sheenDirectionalAlbedo(double NoV, double sheenRoughness, SheenVisibility visibility, int steps = 256);

// E(n.v, r) tabulated on size x size texels, the DFG table's layout (core/shading/DfgTable.h):
// x = n.v, y = sheen roughness, texel i at i / (size - 1), bilinear between texels.
class SheenAlbedoTable {
public:
    SheenAlbedoTable() = default;
    // Each texel by sheenDirectionalAlbedo with `steps`, on all cores.
    static SheenAlbedoTable compute(
        int size, int steps, SheenVisibility visibility = SheenVisibility::Charlie);
    // A table from its texels, row y = roughness (size x size of them; the shipped table).
    static SheenAlbedoTable fromTexels(int size, std::vector<double> texels);
    int size() const { return m_size; }
    double texel(int x, int y) const
    {
        return m_texels[std::size_t(y) * std::size_t(m_size) + std::size_t(x)];
    }
    double sample(double NoV, double sheenRoughness) const;
    // What the sheen's reciprocal scaling takes from a Lambertian base lit from every direction:
    // Emax(n.v, r) = integral over the hemisphere of max(E(n.v, r), E(n.l, r)) (n.l) / pi dl, so
    // that the base's cosine-weighted mean scaling is 1 - max3(sheenColor) Emax (the split sum's
    // and fis's diffuse lobe; docs/shading.md, "Sheen"). Tabulated on the same texels from E (the
    // trapezoid rule over its n.l texels), bilinear between them.
    double diffuseTexel(int x, int y) const
    {
        return m_diffuse[std::size_t(y) * std::size_t(m_size) + std::size_t(x)];
    }
    double sampleDiffuse(double NoV, double sheenRoughness) const;

private:
    void computeDiffuse();
    double bilinear(const std::vector<double>& texels, double NoV, double sheenRoughness) const;

    int m_size = 0;
    std::vector<double> m_texels;
    std::vector<double> m_diffuse;
};

// The table the material BRDF and the GPU's sheen read: V_Charlie (the extension's), 64 x 64
// texels of a 512-step quadrature, shipped as data (core/shading/ShippedSheenTable.inc, written by
// tests/tools/WriteSheenTable.cpp; SheenLayeringTest recomputes texels of it), so no frame or
// ground truth waits the minutes it takes to integrate.
inline constexpr int kShippedSheenTableSize = 64;
inline constexpr int kShippedSheenTableSteps = 512;
const SheenAlbedoTable& sheenAlbedoTable();

// KHR_materials_sheen's layering: what the material under the sheen keeps towards v from l,
// min(1 - max3(c) E(n.v, r), 1 - max3(c) E(n.l, r)) (the extension's "Sheen layering", its
// reciprocal form; the README's simplified form is the n.v term alone). 1 without a sheen.
double sheenAlbedoScaling(const glm::dvec3& sheenColor, double sheenRoughness, double NoV, double NoL);

} // namespace facet::shading
