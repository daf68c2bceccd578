#pragma once
// The material property registry: one row per number or colour an artist sets on a material, with
// what every part of Facet needs to know of it, so that each fact is written once. Its
// readers are glTF import and export (each extension's numbers and colours, GltfField), the
// project file (core/material/MaterialJson: the numbers of no map, a key each, the row's field),
// Material::validate (the ranges and the fields its messages name), the wedge
// (core/project/WedgeAxis: an axis of a material property takes its name, field, range and
// setter from here), the command line's material flags (`facet render` and `facet sheet`:
// --base-color, --metallic, --roughness, --clearcoat, --clearcoat-roughness, --sheen-color,
// --sheen-roughness, --specular, --specular-color, --anisotropy, --anisotropy-rotation, --iridescence,
// --iridescence-ior, --iridescence-thickness, --iridescence-thickness-minimum; app/MaterialFlags),
// the export templates' channel sources (ExportField) and the docks' sliders (ui/widgets/ValueSlider
// forProperty: the Material dock's, and the Texture Maps dock's factor of each map, factorPropertyOf). A
// property's default is the default Material's value, read through the row (no second copy).
// docs/architecture.md, "The material property registry", says how a new property joins.

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include <glm/vec3.hpp>

#include "core/material/Material.h"

namespace facet {

enum class MaterialProperty {
    BaseColor, // the base colour factor's RGB (linear)
    Alpha, // the base colour factor's alpha
    Metallic,
    Roughness, // perceptual
    Occlusion, // the occlusion map's strength
    Normal, // the normal map's strength
    Emissive, // the emissive factor's RGB (linear)
    EmissiveStrength, // KHR_materials_emissive_strength
    Ior, // KHR_materials_ior
    AlphaCutoff,
    Clearcoat, // KHR_materials_clearcoat: the coat's strength
    ClearcoatRoughness, // the coat's perceptual roughness
    ClearcoatNormal, // the coat's normal map strength
    SheenColor, // KHR_materials_sheen: the sheen's colour (linear)
    SheenRoughness, // the sheen's perceptual roughness
    Specular, // KHR_materials_specular: the dielectric's specular strength
    SpecularColor, // its F0 tint (linear; above 1 allowed)
    Anisotropy, // KHR_materials_anisotropy: the strength
    AnisotropyRotation, // its direction's turn from the tangent, in degrees
    Iridescence, // KHR_materials_iridescence: the film's strength
    IridescenceIor, // the film's index of refraction
    IridescenceThickness, // its thickness in nm (the thickness texture's 1; without one, the thickness)
    IridescenceThicknessMinimum, // the thickness texture's 0, nm
};
inline constexpr int kMaterialPropertyCount = 23;

// What a property holds: one number, or a linear RGB colour whose components each lie in the range.
enum class PropertyValue { Scalar, Color };

// Where glTF keeps a property of a material extension (KHR_materials_*): read and written from
// this row by core/gltf (import, export) and checked row by row by GltfExtensionsTest. Properties
// of glTF 2.0's core material (and a texture's scale or strength) have no extension here: the glTF
// code reads those from tinygltf's typed fields.
struct GltfField {
    const char* extension = nullptr; // "KHR_materials_sheen"; null: not an extension's field
    const char* field = nullptr; // "sheenRoughnessFactor"
    // What the extension means when the field is absent (a colour: each component); a field equal
    // to it is left out of an export.
    double absent = 0.0;
    // The file's units per Facet's: pi / 180 for the rotation (radians in the file, degrees here).
    double scale = 1.0;
    // The value is an angle: the file may hold any number, wrapped into the row's range on import.
    bool periodic = false;
};

// Where an export template's channels read a property (core/export/ExportTemplate's sources): the
// value the material shades with at a texel, factor and texture combined
// (core/export/TextureSetExport exportTexel).
struct ExportField {
    const char* source = nullptr; // "roughness", "baseColor"; null: no channel reads it
    // Its components' letters, each a source of its own ("baseColor.g"): "" one value, "rgb" a
    // colour's, "a" the base colour's coverage; "xyz", "xy" a unit vector's, stored v * 0.5 + 0.5.
    const char* components = "";
    // The map whose texture the source reads when it is not the row's slot (the anisotropy's
    // direction: the anisotropy texture's RG turned by the rotation).
    std::optional<MapSlot> slot = std::nullopt;
};

struct MaterialPropertyInfo {
    MaterialProperty property;
    // Its short name: the wedge axis's ("roughness", "emissiveStrength", "alpha") and the one
    // messages use for a command-line value.
    const char* name;
    // The field as the project file names it, in every message about it ("roughness.factor",
    // "ior", "baseColor.factor.a"; a colour's components add ".r", ".g", ".b").
    const char* field;
    // What people call it: the command line's help ("Perceptual roughness").
    const char* label;
    PropertyValue value;
    // The inclusive range Material::validate accepts (each component's, for a colour).
    double minimum;
    double maximum;
    // The map whose texture the factor multiplies (glTF's rule); nullopt for a field with no texture.
    std::optional<MapSlot> slot;
    // The command-line flag of `facet render` and `facet sheet` ("base-color": --base-color
    // r,g,b), or null for none; it sets every material of the project.
    const char* flag;
    GltfField gltf;
    ExportField exportField;
    // Where a slider of it ends when that is below `maximum` (the IOR's 3: every common material
    // lies below, and the spin box beside it still takes up to 5); 0: at `maximum`.
    double sliderMaximum = 0.0;
};

// Every property, in the order of the enum.
std::span<const MaterialPropertyInfo> materialProperties();
const MaterialPropertyInfo& infoOf(MaterialProperty property);
std::optional<MaterialProperty> materialPropertyFromString(std::string_view name);
// The property whose factor `slot`'s texture multiplies: the slot's colour row for a colour map
// (base colour, emissive, the sheen's and the specular colour), its scalar row otherwise.
std::optional<MaterialProperty> factorPropertyOf(MapSlot slot);

// The value of a scalar property of `material`, and setting it (a scalar map's factor keeps its
// four components equal, Material::setFactor).
double scalarOf(const Material& material, MaterialProperty property);
void setScalar(Material& material, MaterialProperty property, double value);
// A colour property's RGB; setting it keeps the factor's fourth component (the base colour's alpha).
glm::dvec3 colorOf(const Material& material, MaterialProperty property);
void setColor(Material& material, MaterialProperty property, const glm::dvec3& rgb);

// Whether `material`'s value of `property` lies in the row's range; false with *problem
// ("roughness.factor: 1.5 is outside [0, 1]", "baseColor.factor.g: -0.1 is outside [0, 1]").
bool checkProperty(const Material& material, MaterialProperty property, std::string* problem);

} // namespace facet
