#pragma once
// An export template: which texture files a material becomes for an engine (Unreal's BaseColor,
// Normal and ORM; Unity HDRP's MaskMap; ...), each file's channels and where each channel's
// values come from, its colour space, bit depth and format. The built-in templates are data files
// (resources/export/*.json, compiled into the program); a user template is the same JSON in a
// file of the user's. docs/export.md describes the format; core/export/TextureSetExport writes the files.
//
//   {
//     "format": "facet-export-template", "version": 1,
//     "name": "Unreal Engine",
//     "fileName": "T_{material}_{map}",          // default for every output; tokens below
//     "outputs": [
//       { "map": "BC", "channels": ["baseColor.r", "baseColor.g", "baseColor.b"],
//         "colorSpace": "srgb", "bitDepth": 8, "fileFormat": "png" },
//       { "map": "N", "channels": ["normal.x", {"source": "normal.y", "invert": true}, "normal.z"],
//         "colorSpace": "linear", "bitDepth": 8, "fileFormat": "png" },
//       { "map": "E", "channels": ["emissive.r", "emissive.g", "emissive.b"], "optional": true, ... },
//       { "map": "ORM", "channels": ["occlusion", "roughness", "metallic"], ... }
//     ]
//   }
//
// A channel is a source name, a number (a constant in [0, 1]: the value the file holds, e.g. 1
// for an unused detail mask) or {"source": NAME, "invert": true} (1 - value; a smoothness from
// the roughness, a DirectX normal's green). One channel makes a grey file, two grey + alpha,
// three RGB, four RGBA.
// Sources (what the material shades with at each texel, factor and texture combined, before any
// UV transform of its own: core/shading/MaterialInputs materialInputs; each is a row's export field
// in the material property registry, core/material/MaterialProperties):
//   baseColor.r/.g/.b  linear base colour (the file's colour space encodes it)
//   baseColor.a        coverage (base colour alpha)
//   normal.x/.y/.z     the tangent-space shading normal, OpenGL convention (+Y green), strength
//                      applied, unit length, stored as n * 0.5 + 0.5
//   metallic, roughness (perceptual), occlusion (strength applied)
//   emissive.r/.g/.b   emissive colour (factor x texture, linear; the strength is a parameter)
//   clearcoat, clearcoatRoughness   the clear coat's strength and perceptual roughness
//   clearcoatNormal.x/.y/.z         the coat's tangent-space normal, as normal.x/.y/.z
//   sheenColor.r/.g/.b, sheenRoughness   the sheen's colour (linear) and perceptual roughness
//   specular, specularColor.r/.g/.b      KHR_materials_specular's strength and F0 tint (linear;
//                                        a tint above 1 is clamped by the file)
//   anisotropy                           KHR_materials_anisotropy's strength
//   anisotropyDirection.x/.y             its direction in the tangent plane (rotation applied),
//                                        unit, stored as d * 0.5 + 0.5 (the extension's RG)
//   iridescence                          KHR_materials_iridescence's strength
//   iridescenceThickness                 where the film's thickness lies between the material's
//                                        minimum (0) and maximum (1): the thickness texture's G
// Tokens of file names: {material} (its name, made safe for a file name), {map}, {size} (the
// file's width, or WxH when it is not square), {template} (the template's file name stem).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <QJsonObject>

#include "core/image/Image.h" // ColorEncoding
#include "core/material/MaterialProperties.h"

namespace facet {

// A channel's source: a material property's export field (core/material/MaterialProperties,
// MaterialPropertyInfo::exportField) and which of its components. Its name is the field's source
// and the component's letter: "roughness", "baseColor.g", "normal.x".
struct ExportSource {
    MaterialProperty property = MaterialProperty::BaseColor;
    int component = 0; // into the export field's components; 0 for a one-value source
    bool operator==(const ExportSource&) const = default;
};
std::string toString(const ExportSource& source); // "baseColor.r", "roughness"
std::optional<ExportSource> exportSourceFromString(std::string_view name);
// Every source, in the registry's order.
std::vector<ExportSource> exportSources();

struct ExportChannel {
    std::optional<ExportSource> source; // none: the constant
    double constant = 0.0; // without a source: the value the file holds
    bool invert = false; // 1 - value
    bool operator==(const ExportChannel&) const = default;
};

enum class TextureFileFormat { Png, Tga, Tiff, Exr };
const char* toString(TextureFileFormat format); // "png", "tga", "tiff", "exr"
const char* extension(TextureFileFormat format); // "png", "tga", "tif", "exr"
std::optional<TextureFileFormat> textureFileFormatFromString(std::string_view name);
// Whether `format` holds `bitDepth` (8, 16 or 32) bits per channel: PNG 8/16, TGA 8, TIFF
// 8/16/32 (32: float), EXR 16/32 (half, float).
bool holdsBitDepth(TextureFileFormat format, int bitDepth);

struct ExportOutput {
    std::string map; // the {map} token: "BaseColor", "ORM"
    std::string fileName; // the pattern without extension; empty: the template's
    std::vector<ExportChannel> channels; // 1 to 4
    ColorEncoding colorSpace = ColorEncoding::Linear; // sRGB: R, G and B are sRGB-encoded
    int bitDepth = 8; // 8, 16, 32 (float)
    TextureFileFormat fileFormat = TextureFileFormat::Png;
    // Written only for a material that uses one of the sources it reads (core/export/TextureSetExport
    // usesSource: a texture, an emissive colour other than black, a clear coat that is on): a set
    // has no black emissive file for a material that emits nothing, nor a coat mask for one
    // without a coat.
    bool optional = false;
    bool operator==(const ExportOutput&) const = default;
};

struct ExportTemplate {
    static constexpr const char* kFormatName = "facet-export-template";
    static constexpr int kFormatVersion = 1;
    static constexpr int kMaxOutputs = 16;

    std::string id; // the built-in's name ("unreal") or the file's stem
    std::string name; // what people call it: "Unreal Engine"
    std::string fileName = "{material}_{map}";
    std::vector<ExportOutput> outputs;

    // Reads and checks a template; *error names the field ("outputs[1].channels[2]: 'rough' is
    // not a source (baseColor.r, ...)"), without the file.
    static std::optional<ExportTemplate> fromJson(const QJsonObject& object, std::string* error);
    // A template file; errors "<path>: <problem>". The id is the file's stem.
    static std::optional<ExportTemplate> load(const std::string& path, std::string* error);
    // The built-in templates: "gltf-textures", "godot", "unity-hdrp", "unity-urp", "unreal".
    static const std::vector<std::string>& builtinIds();
    static std::optional<ExportTemplate> builtin(std::string_view id);

    bool operator==(const ExportTemplate&) const = default;
};

// `pattern` with its tokens replaced; false with *error naming an unknown token or an unclosed
// brace ("unknown token {colour} (known: {material}, {map}, {size}, {template})").
bool expandFileName(const std::string& pattern, const std::string& material, const std::string& map,
    const std::string& size, const std::string& templateId, std::string* out, std::string* error);
// A material name as a file name's part: letters, digits, '-', '_' and '.' kept, runs of others
// (spaces, '/', ':') become one '_', no leading '.'; empty: "Material".
std::string fileNameSafe(std::string_view name);

} // namespace facet
