// Prints the white-furnace response (directional albedo) of a white material for each BRDF
// composition, over roughness and n.v: the measurements behind docs/energy.md.
// Usage: furnace_table [samples]   (deterministic; default 4096 samples per estimate)

#include <cstdio>
#include <cstdlib>

#include "core/shading/DfgTable.h"
#include "core/shading/MaterialBrdf.h"

using namespace facet;

int main(int argc, char** argv)
{
    const int samples = argc > 1 ? std::max(64, std::atoi(argv[1])) : 4096;
    const double roughness[] = {0.0, 0.1, 0.25, 0.5, 0.75, 1.0};
    const double cosines[] = {0.01, 0.05, 0.1, 0.25, 0.5, 1.0};
    struct Case {
        const char* name;
        ShadingModel model;
        double metallic;
    };
    ShadingModel gltfSingle;
    gltfSingle.multiScatter = false;
    ShadingModel gltf;
    ShadingModel preserving;
    preserving.coupling = DielectricCoupling::EnergyPreserving;
    ShadingModel learn = ShadingModel::learnOpenGL();
    learn.multiScatter = false;
    const Case cases[] = {
        {"white metal, single scattering", gltfSingle, 1.0},
        {"white metal, multi-scatter compensation", gltf, 1.0},
        {"white dielectric, glTF fresnel_mix", gltf, 0.0},
        {"white dielectric, energy-preserving coupling", preserving, 0.0},
        {"white dielectric, LearnOpenGL composition", learn, 0.0},
    };
    for (const Case& c : cases) {
        const DfgTable table = DfgTable::compute(64, 1024, c.model.visibility);
        const MaterialBrdf brdf(c.model, table);
        std::printf("\n%s (%d samples)\n\n| roughness |", c.name, samples);
        for (double mu : cosines)
            std::printf(" n.v %.2f |", mu);
        std::printf("\n|---|");
        for (std::size_t i = 0; i < std::size(cosines); ++i)
            std::printf("---|");
        std::printf("\n");
        for (double r : roughness) {
            std::printf("| %.2f |", r);
            for (double mu : cosines) {
                MaterialInfo m;
                m.baseColor = glm::dvec3(1.0);
                m.metallic = c.metallic;
                m.perceptualRoughness = r;
                std::printf(" %.3f |", directionalAlbedo(brdf, m, mu, samples).x);
            }
            std::printf("\n");
        }
    }
    return 0;
}
