#pragma once
// The test material of the texture-set export tests (TextureSetExportTest, TextureSetFormatsTest)
// and what they do with it: a set written into a folder, a file read back with OpenImageIO.
// Compiled into those tests only.

#include "core/export/TextureSetExport.h"
#include "core/image/MapImage.h"
#include "core/material/Material.h"
#include "core/shading/MaterialInputs.h"

#include <QString>

#include <OpenImageIO/typedesc.h>

#include <optional>
#include <string>
#include <vector>

namespace facet::test {

// The test material's maps: uniform 4x4 8-bit textures, every channel a different value.
inline constexpr int kBase[4] = {51, 102, 153, 204}; // sRGB RGB, linear alpha
inline constexpr int kNormal[3] = {160, 100, 230}; // OpenGL tangent-space normal, encoded
inline constexpr int kPacked[3] = {178, 77, 230}; // R occlusion, G roughness, B metallic (an ORM file)
inline constexpr int kEmissive[3] = {128, 64, 32}; // sRGB

MapImage uniformMap(int width, int height, const int* values, int channels);

struct TestMaterial {
    Material material;
    MapImage base = uniformMap(4, 4, kBase, 4);
    MapImage normal = uniformMap(4, 4, kNormal, 3);
    MapImage packed = uniformMap(4, 4, kPacked, 3);
    MapImage emissive = uniformMap(4, 4, kEmissive, 3);
    bool withFactors = false;

    explicit TestMaterial(bool factors);

    MaterialMapImages images() const;

    // What a channel naming `source` must hold, as a linear value, worked out here from the
    // texels and factors (the glTF 2.0 rules), not by core/.
    double expected(const QString& source) const;
};

struct ReadBack {
    int width = 0;
    int height = 0;
    int channels = 0;
    OIIO::TypeDesc format;
    std::string colorSpace;
    std::vector<float> values; // as stored, normalised
};

std::optional<ReadBack> readBack(const QString& path);

// Writes `plan` into `folder` and returns the files' paths; fails the test on an error.
bool writeSet(const TextureSetPlan& plan, const TestMaterial& test, const QString& folder, std::string* error);

} // namespace facet::test
