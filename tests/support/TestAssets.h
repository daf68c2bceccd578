#pragma once
// glTF assets the window tests and the command-line tests open (written with support/GltfWriter,
// so every test and the `facet PATH.glb` CLI test see the same files; tests/tools/WriteTestAsset
// writes them from CTest).

#include <QByteArray>
#include <QString>

#include "core/image/Image.h"

#include <string>
#include <vector>

namespace facet {
struct Project;
}

namespace facet::test {

// Two quads side by side in the XY plane facing +Z, each a part with its own material, single-
// sided (glTF's default): "Left" (x in [-1, -0.05], material "Red": base colour (0.8, 0.05, 0.05))
// and "Right" (x in [0.05, 1], material "Blue": base colour (0.05, 0.1, 0.8) with alpha
// `rightAlpha`), y in [-1, 1]. Roughness 0.5, metallic 0. `path` ends in .glb.
bool writeTwoMaterialAsset(const QString& path, QString* error, double rightAlpha = 1.0);
// What writeTwoMaterialAsset makes, for checks.
struct TwoMaterialAsset {
    static constexpr float kLeftX0 = -1.0f, kLeftX1 = -0.05f, kRightX0 = 0.05f, kRightX1 = 1.0f;
};
// The names of a project's materials, in order; of the materials its first `parts` parts show.
std::vector<std::string> materialNames(const Project& project);
std::vector<std::string> partMaterialNames(const Project& project, std::size_t parts = 2);

// A small still life for looking at the window as an artist would: a "Base" slab (rough
// "Concrete" with a speckled texture), a "Body" sphere ("Painted Checker": a checker base colour
// texture), a "Glass" sphere ("Tinted Glass": BLEND, alpha 0.35, double-sided) and a "Lamp" sphere
// ("Lamp": emissive warm orange, strength 8). Five parts (the slab is two primitives: its top
// "Base Top" with its own material "Rubber"), five materials, textures embedded in the .glb.
bool writeShowcaseAsset(const QString& path, QString* error);

// A project for export tests, written into `folder` with its map files (uniform 8-bit PNGs):
// "Brick Wall" (base colour 32x16, normal 16x16, one ORM file read by occlusion R, roughness G and
// metallic B), "Steel" (base colour and roughness maps, 8x8) and "Gold" (constants). Returns the
// project's path, empty on failure.
QString writeTexturedProject(const QString& folder);

// A 16x8 map whose every texel and channel differs (a gradient per channel, rows and columns in
// opposite senses; 8-bit steps from 30 to 229), `channels` of them (the rest 1); `seed` shifts
// the values so that two maps differ. For tests that follow texels through an export.
facet::Image variedImage(int seed, int channels);

// An export template (core/export/ExportTemplate.h) of the given outputs (a JSON array's inside) and
// name pattern, as the bytes of its file.
QByteArray exportTemplateJson(const QByteArray& outputs, const QByteArray& fileName = "{material}_{map}");

} // namespace facet::test
