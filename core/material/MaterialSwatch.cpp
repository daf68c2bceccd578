#include "core/material/MaterialSwatch.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "core/ibl/Prefilter.h"
#include "core/image/ToneMap.h"
#include "core/shading/Anisotropy.h"
#include "core/shading/MaterialBrdf.h"
#include "core/shading/SplitSum.h"

namespace facet {

SwatchRenderer::SwatchRenderer(Environment environment, int prefilterSamples)
    : m_environment(std::move(environment))
    , m_irradiance(irradianceSHCoefficients(projectEquirect(m_environment)))
    , m_prefilterSamples(std::max(prefilterSamples, 1))
{
}

const DfgTable& SwatchRenderer::table(Visibility visibility) const
{
    const std::lock_guard lock(m_tablesMutex);
    std::unique_ptr<DfgTable>& table = m_tables[std::size_t(visibility)];
    if (!table) // small: a swatch needs no more than the renderer's draft table
        table = std::make_unique<DfgTable>(DfgTable::compute(32, 128, visibility, 1));
    return *table;
}

Image SwatchRenderer::render(const Material& material, const MaterialMapImages& images, int size) const
{
    size = std::max(size, 1);
    Image swatch(size, size, glm::vec4(0.0f));
    swatch.setEncoding(ColorEncoding::SRGB);
    const DfgTable& dfg = table(material.shading.visibility);
    const MaterialBrdf brdf(material.shading, dfg);
    // The tangent-space normal maps that apply: the base's, and the coat's while there is a coat.
    const auto normalImageOf = [&](MapSlot slot) -> const MapImage* {
        const MapImage* image = images[std::size_t(slot)];
        return material.usesSlot(slot) && material.map(slot).hasTexture() && image && !image->isEmpty()
            ? image
            : nullptr;
    };
    const MapImage* normalImage = normalImageOf(MapSlot::Normal);
    const MapImage* coatNormalImage = normalImageOf(MapSlot::ClearcoatNormal);
    const glm::dvec3 v(0.0, 0.0, 1.0); // towards the viewer

    // Four samples a pixel (a rotated grid): the silhouette is anti-aliased.
    static constexpr double kOffsets[4][2] = {{0.375, 0.125}, {0.875, 0.375}, {0.125, 0.625}, {0.625, 0.875}};
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            glm::dvec3 sum(0.0);
            int covered = 0;
            for (const auto& offset : kOffsets) {
                const double px = 2.0 * (x + offset[0]) / size - 1.0;
                const double py = 1.0 - 2.0 * (y + offset[1]) / size;
                const double r2 = px * px + py * py;
                if (r2 >= 1.0)
                    continue;
                ++covered;
                const glm::dvec3 ng(px, py, std::sqrt(1.0 - r2));
                // The built-in sphere's parametrisation (core/mesh/MeshPrimitives revolve): phi =
                // atan2(z, x), u = (pi - phi) / (2 pi), v = asin(y) / pi + 0.5; dP/du along
                // (sin phi, 0, -cos phi).
                const double phi = std::atan2(ng.z, ng.x);
                const glm::dvec2 uv((std::numbers::pi - phi) / (2.0 * std::numbers::pi),
                    std::asin(std::clamp(ng.y, -1.0, 1.0)) / std::numbers::pi + 0.5);
                const glm::dvec4 tangent(std::sin(phi), 0.0, -std::cos(phi), 1.0);
                const auto mapped = [&](MapSlot slot, const MapImage* image) {
                    const MaterialMap& map = material.map(slot);
                    return image ? shadingNormal(ng, tangent, sampleMap(map, *image, TexCoords {uv, uv}),
                               map.factor.x, map.flipGreen)
                                 : ng;
                };
                const glm::dvec3 n = mapped(MapSlot::Normal, normalImage);
                MaterialInfo inputs = materialInputs(material, images, uv);
                inputs.clearcoatNormal = mapped(MapSlot::ClearcoatNormal, coatNormalImage);
                const double NoV = std::max(glm::dot(n, v), 1e-4);
                // An anisotropic lobe's light about the Sample Viewer's bent normal, with the
                // lobe's own compensation: a swatch has no environment cube to sample the
                // stretched lobe from, as the window does (docs/shading.md, "Anisotropy").
                glm::dvec3 specularNormal = n;
                SplitSumLighting lighting;
                if (inputs.anisotropy > 0.0)
                    if (const auto frame = shading::anisotropyFrame(
                            n, surfaceAnisotropyDirection(ng, tangent, inputs.anisotropyTangentDirection))) {
                        specularNormal = shading::anisotropicBentNormal(
                            n, v, frame->t, inputs.perceptualRoughness, inputs.anisotropy);
                        lighting.anisotropicCompensation = shading::anisotropicCompensation(
                            frame->toLocal(v), inputs.perceptualRoughness, inputs.anisotropy);
                    }
                const glm::dvec3 R = glm::reflect(-v, specularNormal);
                lighting.irradiance = irradianceSH(m_irradiance, n);
                lighting.prefilteredRadiance = prefilteredRadiance(m_environment,
                    specularDominantDirection(
                        specularNormal, R, shading::alphaFromRoughness(inputs.perceptualRoughness)),
                    inputs.perceptualRoughness, m_prefilterSamples);
                if (inputs.clearcoat > 0.0) {
                    const glm::dvec3& nc = inputs.clearcoatNormal;
                    lighting.coatPrefilteredRadiance = prefilteredRadiance(m_environment,
                        specularDominantDirection(
                            nc, glm::reflect(-v, nc), shading::alphaFromRoughness(inputs.clearcoatRoughness)),
                        inputs.clearcoatRoughness, m_prefilterSamples);
                    lighting.coatNoV = std::max(glm::dot(nc, v), 1e-4);
                }
                // The sheen's light: the irradiance's mean radiance, the better of the two lookups
                // measured for the window's split sum (docs/shading.md, "Sheen"); a swatch has no
                // environment cube to sample.
                if (inputs.hasSheen())
                    lighting.sheenRadiance = lighting.irradiance / std::numbers::pi;
                const BrdfLobes lobes = splitSumRadiance(brdf, dfg, inputs, NoV, lighting);
                sum += lobes.total() * inputs.occlusion
                    + inputs.emissive * (1.0 - clearcoatWeight(inputs, lighting.coatNoV));
            }
            if (covered == 0)
                continue;
            const glm::dvec3 display = tonemap::displayTransform(
                sum / double(covered), 0.0, ToneMapper::KhronosNeutral, DisplayEncoding::SRGB, 2.2);
            swatch.at(x, y) = glm::vec4(glm::vec3(display), float(covered) / 4.0f);
        }
    }
    return swatch;
}

} // namespace facet
