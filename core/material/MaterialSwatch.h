#pragma once
// A material's swatch: a small sphere, lit by an environment, for the preset library (the
// Material dock's list), rendered on the CPU so that no GL context is needed and it can run on a
// worker thread. It is the real-time shading's CPU twin at icon size: the material's inputs at
// each pixel (core/shading/MaterialInputs, every map and option), its normal map in the sphere's tangent
// frame (the built-in sphere's UVs and tangents, core/mesh/MeshPrimitives makeSphere), and the split
// sum (core/shading/SplitSum splitSumRadiance with the material's BRDF and DFG table, the environment's
// SH9 irradiance, prefiltered radiance by importance sampling, core/ibl/Prefilter), then the display
// transform (exposure 0, Khronos PBR Neutral, sRGB). The view is the reference view's, looking
// down -Z at the unit sphere, orthographic so the sphere fills the swatch.

#include <array>
#include <memory>
#include <mutex>

#include "core/ibl/Environment.h"
#include "core/ibl/SphericalHarmonics.h"
#include "core/image/Image.h"
#include "core/shading/DfgTable.h"
#include "core/shading/MaterialInputs.h"
#include "core/shading/ShadingModel.h"

namespace facet {

class SwatchRenderer {
public:
    // `environment` lights every swatch (the built-in studio by default, at 256x128: its soft
    // boxes are what shows a material's roughness); `prefilterSamples` per pixel for the glossy
    // lobe.
    explicit SwatchRenderer(Environment environment = Environment::builtin(Environment::Builtin::Studio, 256),
        int prefilterSamples = 48);

    // A size x size swatch: display-referred sRGB values, alpha 1 on the sphere (edge pixels
    // partly covered: four samples each) and 0 around it. Thread-safe.
    Image render(const Material& material, const MaterialMapImages& images, int size) const;

private:
    const DfgTable& table(Visibility visibility) const;

    Environment m_environment;
    IrradianceSH9 m_irradiance;
    int m_prefilterSamples;
    mutable std::mutex m_tablesMutex;
    mutable std::array<std::unique_ptr<DfgTable>, kVisibilityCount> m_tables;
};

} // namespace facet
