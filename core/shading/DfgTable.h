#pragma once
// The split-sum BRDF table ("DFG" or "environment BRDF" LUT) [Karis 2013, "Real Shading in
// Unreal Engine 4"; Lagarde & de Rousiers 2014, "Moving Frostbite to PBR", section 4.9].
//
// For a specular lobe D V F with Schlick Fresnel F = F0 + (1 - F0)(1 - v.h)^5, the directional
// albedo splits into a part linear in F0:
//     E_spec(v) = integral of D V F (n.l) dl = F0 * scale(n.v, r) + bias(n.v, r)
//     scale = integral of D V (1 - Fc) (n.l) dl,   bias = integral of D V Fc (n.l) dl,   Fc = (1 - v.h)^5
// and E(n.v, r) = scale + bias is the albedo of the lobe with F = 1, the quantity that the
// multiple-scattering compensation (Turquin 2019) needs. A fourth value serves the diffuse base
// of glTF's fresnel_mix, c / pi (1 - F(v.h)) with the half vector of v and the diffuse l:
//     W(n.v) = 1/pi integral of (1 - Fc) (n.l) dl,   albedo of the base = c (1 - F0) W(n.v)
// W does not depend on roughness (the base is Lambertian); the table stores it in every row so
// that one RGBA lookup gives all four (docs/energy.md has its values).
// Axes (docs/architecture.md): x = n.v, y = perceptual roughness. Texel i of size holds the value at
// i / (size - 1), so the table's first and last texel centres sit exactly on 0 and 1 and a
// lookup never extrapolates by clamping (grazing n.v is where the albedo changes fastest). A GL
// lookup of the same value reads texture coordinate (value * (size - 1) + 0.5) / size with
// LINEAR filtering; sample() below is its CPU twin.

#include <vector>

#include "core/shading/ShadingModel.h"

namespace facet {

struct DfgValue {
    double scale = 0.0;
    double bias = 0.0;
    // W(n.v): the share of a Lambertian base's albedo that a Schlick fresnel_mix passes, over
    // (1 - F0). 1 at most; a material's base reflects c (1 - F0) W.
    double diffuseFresnelWeight = 1.0;
    // Directional albedo of the lobe with F0 = 1 (white furnace of a white metal).
    double albedo() const { return scale + bias; }
};

// The integral for one (n.v, roughness) pair, by importance sampling visible normals with
// `sampleCount` Hammersley points. `visibility` picks V (the LearnOpenGL variant's table uses
// Schlick-GGX with the IBL remapping k = alpha / 2). diffuseFresnelWeight integrates with
// cosine-distributed l on the same points.
DfgValue integrateDfg(double NoV, double perceptualRoughness, int sampleCount,
    Visibility visibility = Visibility::SmithGGXCorrelated);

class DfgTable {
public:
    DfgTable() = default;
    // size x size texels, each integrated with `sampleCount` samples, on all cores.
    static DfgTable compute(
        int size, int sampleCount, Visibility visibility = Visibility::SmithGGXCorrelated, int threads = 0);

    int size() const { return m_size; }
    int sampleCount() const { return m_sampleCount; }
    Visibility visibility() const { return m_visibility; }
    bool isEmpty() const { return m_size == 0; }

    const DfgValue& texel(int x, int y) const
    {
        return m_texels[std::size_t(y) * std::size_t(m_size) + std::size_t(x)];
    }
    // Bilinear between texels (GL_LINEAR at the coordinate documented above).
    DfgValue sample(double NoV, double perceptualRoughness) const;

    // The cosine-weighted average albedo of the F = 1 lobe, E_avg(r) = 2 * integral_0^1 E(mu) mu dmu,
    // from the table by the trapezoid rule over its n.v texels.
    double averageAlbedo(double perceptualRoughness) const;

    // Position of texel i along either axis, and the trapezoid-rule weight of texel i over [0, 1].
    static double texelPosition(int i, int size) { return size > 1 ? double(i) / double(size - 1) : 0.5; }
    static double trapezoidWeight(int i, int size)
    {
        if (size <= 1)
            return 1.0;
        const double h = 1.0 / double(size - 1);
        return (i == 0 || i == size - 1) ? 0.5 * h : h;
    }
    // Interleaved (scale, bias, albedo, diffuseFresnelWeight) floats, row y = roughness, for a GL
    // RGBA16F/32F texture: the layout ibl_dfg.frag writes.
    std::vector<float> toRgbaFloats() const;

private:
    int m_size = 0;
    int m_sampleCount = 0;
    Visibility m_visibility = Visibility::SmithGGXCorrelated;
    std::vector<DfgValue> m_texels;
};

} // namespace facet
