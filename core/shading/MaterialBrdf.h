#pragma once
// The full material BRDF f(l, v): the lobes of core/shading/Brdf.h composed as the shading model says.
// This is the CPU twin of resources/shaders/surface.frag's lobe accumulation, and what the
// ground-truth integrator integrates. docs/shading.md derives each composition.
//
// f excludes the cosine n.l. Lobes are kept apart (as the glTF Sample Viewer's pbr.frag does) so
// that debug views and tests can look at each.

#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/shading/DfgTable.h"
#include "core/shading/ShadingModel.h"
#include "core/shading/ThinFilm.h"
#include "core/shading/Transmission.h"

namespace facet {

// The material's inputs at one surface point, after textures and factors were applied
// (glTF Sample Viewer's MaterialInfo).
struct MaterialInfo {
    glm::dvec3 baseColor {1.0}; // linear
    double metallic = 0.0;
    double perceptualRoughness = 0.5; // clamped to kMinPerceptualRoughness when used
    double ior = 1.5;
    // Ambient occlusion: multiplies image-based (indirect) light only, as the real-time shader
    // does; the ground truth ignores it (it traces no occluders).
    double occlusion = 1.0;
    // Emitted radiance (emissive factor x texture x strength), added to what the surface reflects.
    glm::dvec3 emissive {0.0};
    // Coverage from the base colour's alpha (factor x texture); used by AlphaMode Mask and Blend.
    double alpha = 1.0;
    // KHR_materials_clearcoat: the coat's strength, perceptual roughness and unit normal, in the
    // space of evaluate()'s n; zero: n itself. The extension's coat normal is the geometric normal
    // unless a clearcoat normal texture perturbs it (the shader's rule, surface.frag), so a caller
    // with a base normal map sets it to the geometric or coat-mapped normal.
    double clearcoat = 0.0;
    double clearcoatRoughness = 0.0;
    glm::dvec3 clearcoatNormal {0.0};
    // KHR_materials_sheen: the sheen's colour (linear; 0: no sheen) and its roughness (the
    // Charlie distribution's, alpha = roughness^2). Under the coat, over the base
    // (core/shading/Sheen.h; docs/shading.md, "Sheen").
    glm::dvec3 sheenColor {0.0};
    double sheenRoughness = 0.0;
    bool hasSheen() const { return sheenColor.r > 0.0 || sheenColor.g > 0.0 || sheenColor.b > 0.0; }
    // KHR_materials_specular: the dielectric's specular strength ([0, 1]) and F0 tint (linear,
    // >= 0, above 1 allowed); 1 and white are the glTF default, which changes nothing.
    double specular = 1.0;
    glm::dvec3 specularColor {1.0};
    // KHR_materials_anisotropy: the strength ([0, 1], factor x texture B) and the direction the
    // base's specular highlight stretches along. materialInputs() gives the direction in the
    // tangent plane (x along the mesh's tangent, y along its bitangent: the texture's RG turned by
    // the rotation, core/shading/Anisotropy.h anisotropyDirection); a caller with a tangent frame
    // sets `anisotropyDirection`, unit and in the space of evaluate()'s n
    // (surfaceAnisotropyDirection, core/shading/MaterialInputs.h). Zero: no direction, the lobe
    // stays isotropic. The coat and the sheen are never anisotropic (docs/shading.md, "Anisotropy").
    double anisotropy = 0.0;
    glm::dvec2 anisotropyTangentDirection {1.0, 0.0};
    glm::dvec3 anisotropyDirection {0.0};
    bool hasAnisotropy() const { return anisotropy > 0.0 && anisotropyDirection != glm::dvec3(0.0); }
    // KHR_materials_iridescence: the film's strength ([0, 1], factor x texture R), index and
    // thickness (nm; the texture's G between the minimum and the maximum). Strength 0: no film.
    // The film colours the base's specular Fresnel (dielectric and metal), seen at the microfacet's
    // v.h; not the coat's, not the sheen (docs/shading.md, "Iridescence").
    double iridescence = 0.0;
    double iridescenceIor = shading::kDefaultIridescenceIor;
    double iridescenceThickness = shading::kDefaultIridescenceThicknessMaximum;
    // KHR_materials_transmission: the share of the dielectric base that is a microfacet BTDF
    // (tinted by the base colour, the base's roughness, isotropic) instead of the Lambert lobe,
    // [0, 1]. KHR_materials_volume: the thickness under the surface (scene units; 0: thin-walled,
    // the light crosses the surface without bending), the medium's attenuation colour and the
    // distance at which white light turns that colour (infinite: no absorption).
    // KHR_materials_dispersion: 20 / the Abbe number (0: none). docs/shading.md, "Transmission".
    double transmission = 0.0;
    double thickness = 0.0;
    glm::dvec3 attenuationColor {1.0};
    double attenuationDistance = std::numeric_limits<double>::infinity();
    double dispersion = 0.0;
    bool hasTransmission() const { return transmission > 0.0 && metallic < 1.0; }
    bool isThinWalled() const { return !(thickness > 0.0); }
};

// The dielectric layer's Schlick reflectance (KHR_materials_specular, "Implementation"):
//     f0  = min(((n - 1) / (n + 1))^2 specularColor, 1) specular,    f90 = specular
// which is (F0(n), 1) without the extension. Metals ignore it (their F0 is the base colour).
struct DielectricReflectance {
    glm::dvec3 f0 {0.04};
    double f90 = 1.0;
    // The largest channel of f0: the scalar the diffuse weight and the energy-preserving
    // coupling take (the extension's max_value(F)).
    double maxF0() const;
};
DielectricReflectance dielectricReflectance(const MaterialInfo& material);

// KHR_materials_iridescence: the material's film over a base of normal-incidence reflectance f0
// (the dielectric layer's f0, or the metal's base colour) seen at cos(theta1) = cosTheta: the
// extension's Firid (core/shading/ThinFilm.h) clamped to [0, 1], a reflectance (Firid alone
// reaches 1.27: docs/shading.md, "Iridescence"). evaluate() takes it at v.h, the split sum at n.v.
glm::dvec3 filmFresnel(const MaterialInfo& material, const glm::dvec3& f0, double cosTheta);
// The Schlick layer the energy-preserving coupling takes the film for: F0 the smallest whose curve
// lies on or above the film's Fresnel (largest channel) at kFilmLayerAngles, F90 1.
inline constexpr double kFilmLayerAngles[] = {1.0, 0.9, 0.8, 0.7, 0.6, 0.5, 0.4, 0.3, 0.2, 0.1, 0.05};
DielectricReflectance filmLayer(const MaterialInfo& material, const glm::dvec3& f0);

// The coat's IOR, fixed by KHR_materials_clearcoat: F0 = 0.04.
inline constexpr double kClearcoatIor = 1.5;

// What the clear coat takes of the light towards v: clearcoat x F_Schlick(0.04, 1, n.v), the
// extension's fresnel_coat weight (Schlick at n.v, not v.h, so it does not depend on l). The
// material under the coat, and its emission, are multiplied by 1 - this.
double clearcoatWeight(const MaterialInfo& material, double NoV);

// Where the light comes from. It only matters for the LearnOpenGL variant, whose Schlick-GGX
// geometry uses k = (r + 1)^2 / 8 for punctual lights and k = alpha / 2 for image-based light.
enum class LightingKind { Punctual, Environment };

// The base's lobes already carry the sheen's albedo scaling and the coat's 1 - clearcoatWeight;
// `sheen` is the sheen's own lobe, sheenColor D_Charlie V_Charlie (times the coat's 1 - w_c);
// `coat` the coat's, clearcoatWeight x D V (each zero without its layer). `transmission`, for l
// below the surface, the transmitted light (KHR_materials_transmission), under the coat and the
// sheen as the base is; every other lobe is zero there.
struct BrdfLobes {
    glm::dvec3 diffuse {0.0};
    glm::dvec3 specular {0.0};
    glm::dvec3 sheen {0.0};
    glm::dvec3 coat {0.0};
    glm::dvec3 transmission {0.0};
    glm::dvec3 total() const { return diffuse + specular + sheen + coat + transmission; }
};

// The smallest index a volume's interface refracts with: at equal indices the BTDF is a
// direction's delta, which the microfacet form cannot hold; 1.001 bends a ray by less than 0.06
// degrees at 45 degrees and reflects 2.5e-7 (docs/shading.md, "Transmission").
inline constexpr double kMinRefractiveIor = 1.001;

class MaterialBrdf {
public:
    // `albedoTable` supplies the directional albedo E(n.v, r) for multiple-scattering
    // compensation and the energy-preserving coupling; it must have been computed with the same
    // visibility term as `model` (Q_ASSERT-level contract: checked in debug builds). The table
    // is referenced, not copied: it must outlive this object.
    MaterialBrdf(const ShadingModel& model, const DfgTable& albedoTable);

    const ShadingModel& model() const { return m_model; }

    // f(l, v) for unit n, v, l (all in the same space). Zero when v is below the surface, and when
    // l is unless the material transmits (its transmission lobe alone then).
    BrdfLobes evaluate(const MaterialInfo& material, const glm::dvec3& n, const glm::dvec3& v,
        const glm::dvec3& l, LightingKind kind = LightingKind::Environment) const;

    // A volume's interface albedo tables at the material's index (entering: from 1 into it;
    // leaving: from it back to 1) for the compensation of its transmission's multiple scattering
    // (transmissionCompensation; the interior interface of core/shading/BrdfSampler). Without them
    // a volume's transmission is single scattering.
    void setInterfaceTables(std::shared_ptr<const shading::InterfaceAlbedoTable> entering,
        std::shared_ptr<const shading::InterfaceAlbedoTable> leaving);
    const shading::InterfaceAlbedoTable* leavingTable() const { return m_leaving.get(); }
    // The factor the transmission lobe's single scattering is scaled by at n.v so that what it
    // transmits and what the compensated specular layer reflects add up to all the light
    // ((1 - E_s) / T, at least 1; docs/shading.md, "Transmission"): a thin wall's T from the albedo
    // table, a volume's from the entering table (1 without one). 1 when the model turns
    // compensation off.
    double transmissionCompensation(const MaterialInfo& material, double NoV) const;

    // Multiple-scattering compensation factor for the specular lobe of reflectance f0 at n.v:
    // 1 + f0 (1 - E) / E [Turquin 2019, "Practical multiple scattering compensation for
    // microfacet models"; Kulla & Conty 2017], the added part times `weight` (an anisotropic
    // lobe's fade, shading::anisotropicCompensation). 1 when the model turns compensation off.
    glm::dvec3 multiScatterFactor(
        const glm::dvec3& f0, double NoV, double perceptualRoughness, double weight = 1.0) const;

    // Directional albedo of the dielectric specular layer (Schlick from f0 to f90) including
    // compensation, E_s(mu) = (f0 scale + f90 bias) * (1 + f0 (1 - E) / E): what the layer reflects.
    double dielectricSpecularAlbedo(
        double f0, double NoV, double perceptualRoughness, double f90 = 1.0) const;
    // Its cosine-weighted average 2 * integral E_s(mu) mu dmu (trapezoid rule over the table's n.v texels).
    double dielectricSpecularAverageAlbedo(double f0, double perceptualRoughness, double f90 = 1.0) const;
    // The exact dielectric Fresnel (ShadingModel Fresnel::Dielectric) of the layer at v.h with
    // KHR_materials_specular applied as the extension applies it to Schlick's: the F0 shift and the
    // strength, specular (F_Dielectric(v.h, n) + (f0_tinted - F0(n)) (1 - (1 - v.h)^5)).
    glm::dvec3 dielectricFresnel(
        const MaterialInfo& material, const DielectricReflectance& layer, double VoH) const;

private:
    double visibility(
        double NoV, double NoL, double alpha, double perceptualRoughness, LightingKind kind) const;
    double distribution(double NoH, double alpha) const;
    // The base's specular lobe's D V and where its compensation reads the table: the model's
    // pair at the material's roughness, or the anisotropic lobe's in its frame.
    struct SpecularShape {
        double microfacet = 0.0;
        double compensationRoughness = 0.5;
        double compensationWeight = 1.0;
    };
    SpecularShape specularShape(const MaterialInfo& material, const glm::dvec3& n, const glm::dvec3& v,
        const glm::dvec3& l, const glm::dvec3& h, double NoV, double NoL, double NoH, LightingKind kind) const;
    // The transmission lobe for l below the surface: a volume's refraction into the material's
    // index, or a thin wall's mirrored reflection lobe.
    glm::dvec3 transmissionLobe(const MaterialInfo& material, const glm::dvec3& n, const glm::dvec3& v,
        const glm::dvec3& l, double NoV, LightingKind kind) const;
    // The energy-preserving coupling's scale of the dielectric diffuse lobe.
    double couplingFactor(
        const DielectricReflectance& layer, double NoV, double NoL, double perceptualRoughness) const;

    // Per roughness row of the table, the cosine-weighted moments that make the average albedo
    // of the compensated dielectric layer a quadratic in f0 (see dielectricSpecularAverageAlbedo).
    struct RowMoments {
        double bias = 0.0; // 2 int B mu
        double scale = 0.0; // 2 int A mu
        double scaleGain = 0.0; // 2 int A (1 - E) / E mu
        double biasGain = 0.0; // 2 int B (1 - E) / E mu
    };

    ShadingModel m_model;
    const DfgTable* m_table = nullptr;
    std::shared_ptr<const shading::InterfaceAlbedoTable> m_entering;
    std::shared_ptr<const shading::InterfaceAlbedoTable> m_leaving;
    std::vector<RowMoments> m_moments;
};

} // namespace facet

namespace facet {

// The directional albedo of the material seen from n.v: integral of f(l, v) (n.l) over the
// hemisphere, by `sampleCount` Hammersley points drawn from each of the cosine and the
// visible-normal GGX distributions, combined with the balance heuristic. Deterministic. This is
// the white-furnace response of the BRDF: <= 1 for an energy-conserving material.
glm::dvec3 directionalAlbedo(const MaterialBrdf& brdf, const MaterialInfo& material, double NoV,
    int sampleCount, LightingKind kind = LightingKind::Environment);

} // namespace facet
