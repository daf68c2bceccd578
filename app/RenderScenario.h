#pragma once
// `facet render --scenario JSON`: the one argument the glTF render-fidelity harness
// (KhronosGroup glTF-Render-Fidelity; docs/fidelity.md) gives its offline renderers,
//
//   {"scenario": {"name", "model", "lighting", "dimensions": {"width", "height"},
//                 "target": {"x", "y", "z"}, "orbit": {"theta", "phi", "radius"},
//                 "verticalFoV", "renderSkybox"}, "outputFile"}
//
// read with the harness's conventions (its config reader's defaults for missing fields: 768 x 768,
// target 0, orbit (0, 90, 1), 45 degrees, lighting lightroom_14b.hdr, no skybox):
// - the model keeps its own units (ViewSettings::keepUnits); target and radius are in them;
// - the camera sits at target + radius (sin phi sin theta, cos phi, sin phi cos theta), angles in
//   degrees (theta about +Y from +Z, phi from +Y), and looks at the target; radius 0 puts it at
//   the target looking along -that direction; +Y is up;
// - the image is twice `dimensions` on each side (the harness compares at a device pixel ratio of
//   2, and its Cycles renderer renders at twice the size too);
// - the environment is the lighting file as it is: Facet's equirect mapping is three.js's and
//   Cycles' (the image's centre column faces +X), intensity 1;
// - the output is tone-mapped as the harness's three.js and Cycles renderers do it: ACES filmic
//   (Hill's fit) of the radiance times 1 / 0.6, sRGB-encoded; over a transparent background
//   (straight alpha) unless renderSkybox is true.
// Paths (model, lighting, outputFile) are absolute or relative to the working folder. A bad
// scenario is refused with a message naming the field ("scenario.orbit.phi: expected a number,
// got a string"), and nothing is written.

#include <optional>
#include <string>

#include <QString>

#include "core/project/Project.h"

namespace facet {

struct RenderScenario {
    std::string name;
    Project project; // the model's project (its materials), camera, lighting, view
    std::string outputPath;
    int width = 0; // the image: twice the scenario's dimensions
    int height = 0;
};

// Reads the argument. nullopt with *error naming the field or the file.
std::optional<RenderScenario> readRenderScenario(const QString& json, QString* error);

} // namespace facet
