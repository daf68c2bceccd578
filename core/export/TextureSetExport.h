#pragma once
// A material written as an engine's texture set (issue 11, "Engine texture sets"): the files of an
// export template (core/export/ExportTemplate.h), each channel filled from what the material shades with
// at each texel (its factors and maps combined as core/shading/MaterialInputs materialInputs does: channel
// picks, inversion, colour decoding, occlusion strength, the normal's strength and DirectX flip,
// each map's UV transform), then resized to the file's size (OpenImageIO's filtered resize) and
// encoded for the file's colour space (sRGB: the exact piecewise curve) and bit depth.
//
// Size: every file of a set has the size of the material's largest map (the largest width and
// height over its textures), or 1x1 for a material of constants alone; TextureSetOptions::size
// scales that so the larger side is `size`, the aspect kept. A map smaller than the set is
// sampled bilinearly at the set's texel centres (as the GPU magnifies it); a map of the set's
// size with no UV transform is copied texel for texel.

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/export/ExportTemplate.h"
#include "core/image/ImageWriter.h"
#include "core/material/Material.h"
#include "core/shading/MaterialInputs.h"
#include "core/support/FileSet.h"

namespace facet {

struct TextureSetOptions {
    static constexpr int kMaxSize = 8192;
    int size = 0; // the files' larger side; 0: the material's largest map's
    int bitDepth = 0; // 8, 16 or 32 for every file; 0: each output's own
};

struct PlannedTexture {
    std::string fileName; // with its extension
    ExportOutput output; // the bit depth override applied
    int width = 0;
    int height = 0;
};

struct TextureSetPlan {
    std::string templateId;
    std::string materialName;
    int sourceWidth = 1; // the size the material is evaluated at: its largest map's, or 1x1
    int sourceHeight = 1;
    std::vector<PlannedTexture> files;
    std::vector<std::string> skipped; // optional outputs the material does not need ({map} values)
};

// What a template's sources read at one texel of the material: per registry row with an export
// field, its components (a colour's linear RGB, a normal's unit x, y, z: tangent space, OpenGL
// convention; the anisotropy's direction in the tangent plane, rotation applied; the emissive
// colour without its strength; the film's thickness as (d - minimum) / (maximum - minimum), 1 where
// they are equal). Rows without one stay zero.
struct ExportTexel {
    std::array<glm::dvec4, kMaterialPropertyCount> values {};
    glm::dvec4& operator[](MaterialProperty property) { return values[std::size_t(property)]; }
    const glm::dvec4& operator[](MaterialProperty property) const { return values[std::size_t(property)]; }
};
ExportTexel exportTexel(const Material& material, const MaterialMapImages& images, const glm::dvec2& uv);
// A source's value in a texel ([0, 1] for every source but emissive: a unit vector is stored as
// v * 0.5 + 0.5). Without a source: channel.constant; then inverted when channel.invert.
double channelValue(const ExportChannel& channel, const ExportTexel& texel);

// Whether the material uses `slot` beyond a neutral constant (ExportOutput::optional): a
// texture, and for emissive also a colour other than black. Base colour, metallic and roughness
// always; the coat's strength and roughness while the coat is on (Material::usesSlot), its normal
// map when it has a texture.
bool slotHasContent(const Material& material, MapSlot slot);
// The map a source reads: its export field's slot, else its row's.
std::optional<MapSlot> slotOf(const ExportSource& source);
// The same for a template's source: its map's slotHasContent.
bool usesSource(const Material& material, const ExportSource& source);

// The files `exportTemplate` writes for `material` (file names expanded, sizes from the maps'):
// nullopt with *error for a bit depth the format cannot hold ("unreal's BC is png, which holds 8
// or 16 bits, not 32"), a size out of range, or two files of one name.
std::optional<TextureSetPlan> planTextureSet(const ExportTemplate& exportTemplate, const Material& material,
    const MaterialMapImages& images, const TextureSetOptions& options, std::string* error);

// One line of a dry run: "T_Brass_ORM.png  2048x2048  RGB 8-bit linear: R occlusion, G roughness,
// B metallic".
std::string describe(const PlannedTexture& texture);

// A file's values before encoding: width x height x channels floats, rows top first (texture
// coordinate v = 1 at the top row, MapImage's convention), linear, inversion applied, resized.
std::vector<float> renderTexture(const PlannedTexture& texture, const TextureSetPlan& plan,
    const Material& material, const MaterialMapImages& images);
// The file's stored values from renderTexture's: sRGB-encoded where the output says so (the
// colour channels: the first of 1 or 2, the first three of 3 or 4; never alpha or constants).
void encodeTexture(const PlannedTexture& texture, std::vector<float>& values);

// How a planned texture is stored (channels, sample format, colour tag, alpha).
ImageFileSpec textureFileSpec(const PlannedTexture& texture);

// Renders, encodes and writes each file of `plan` into `files`' staging folder (begin() first;
// the caller commit()s the set when every file is written, core/support/FileSet.h). False with *error
// naming the file where it will go ("<path>: cannot write: No space left on device").
bool writeTextureSet(const TextureSetPlan& plan, const Material& material, const MaterialMapImages& images,
    FileSet& files, std::string* error);

// A whole export: the sets of several materials of one template, planned together (every map
// read, once however many slots and materials share it; every file named) before anything is
// written, then written as one set of files: what `facet export` and the window's File > Export
// Texture Set run.
class TextureSetExport {
public:
    // Reads the materials' maps (core/image/MapImageCache) and plans each set. nullopt with *error: a
    // map that cannot be read ("material 'Steel', roughness: MapImage::load: ...: no such file"),
    // a plan refused (planTextureSet, prefixed "material 'Steel': "), or two materials naming one
    // file.
    static std::optional<TextureSetExport> prepare(const ExportTemplate& exportTemplate,
        const std::vector<Material>& materials, const TextureSetOptions& options, std::string* error);

    const ExportTemplate& exportTemplate() const { return m_template; }
    const std::vector<TextureSetPlan>& plans() const { return m_plans; }
    // The stored values of file `index` of plan `plan` (renderTexture, then encodeTexture). Empty
    // with *error ("<file>: resizing to WxH: <why>") when the image codec cannot resize them.
    std::vector<float> fileValues(std::size_t plan, std::size_t index, std::string* error) const;
    // Every file name, in writing order.
    std::vector<std::string> fileNames() const;
    // What --dry-run prints: per material a heading, a line per file (describe()), the optional
    // outputs left out.
    std::string describeAll() const;

    // Writes every file into `folder` (made when missing). Files already there are refused
    // unless `replace` (checked before the first write: "<path>: exists"). On a failed write the
    // files this export made are removed and *error names the file. *written gets the paths.
    bool write(const std::string& folder, bool replace, std::string* error,
        std::vector<std::string>* written = nullptr) const;

private:
    struct Source {
        Material material;
        std::vector<std::shared_ptr<const MapImage>> keep;
        MaterialMapImages images {};
    };
    ExportTemplate m_template;
    std::vector<std::shared_ptr<Source>> m_sources; // shared: the images point into `keep`
    std::vector<TextureSetPlan> m_plans;
};

} // namespace facet
