#pragma once
// A wedge axis: one parameter of a look and the values a grid of cells sweeps it through, e.g.
// "roughness=0,0.25,0.5,0.75,1". The window's Wedge mode shows one or two axes (rows x columns,
// core/project/CompareLayout.h) and `facet sheet --wedge A --wedge2 B` renders them; both start from the
// project and apply one value of each axis to a copy of it per cell (apply()).
//
// Parameters (docs/project-format.md, "Wedge axes", has the table with ranges):
//   metallic, roughness, occlusion, normal   the factor of that map of the current material
//                                            (the file's "metallic.factor", ...; a map's texture
//                                            is multiplied by it, as in glTF)
//   ior, emissiveStrength, alphaCutoff       the current material's field of that name
//   alpha                                    the base colour's alpha ("baseColor.factor" [3])
//   env                                      the environment: specs as Environment::fromSpec
//                                            accepts (built-in names, paths, library references,
//                                            uniform:V); the project's rotation and intensity stay
//   exposure                                 view.exposureEV, in EV (stops)
// The ranges are those Material::validate and ViewSettings::validate accept (a value they would
// refuse in a project is refused in an axis too, with their message), so a cell is always a valid
// project. Base colour RGB, emissive colour and UV transforms are not axes: they are not one scalar.

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace facet {

struct Project;
enum class MaterialProperty;

enum class WedgeParameter {
    Metallic,
    Roughness,
    Occlusion,
    Normal,
    Ior,
    EmissiveStrength,
    AlphaCutoff,
    Alpha,
    Clearcoat,
    ClearcoatRoughness,
    SheenRoughness,
    Specular,
    Anisotropy,
    AnisotropyRotation,
    Iridescence,
    IridescenceIor,
    IridescenceThickness,
    Environment,
    Exposure,
};

// One row of the parameter table.
struct WedgeParameterInfo {
    WedgeParameter parameter;
    const char* name; // as parse() and the project file write it: "roughness", "env", ...
    const char* field; // what it sets, as the project file names it: "roughness.factor", "view.exposureEV"
    // The range a value must lie in (inclusive; the constants Material and ViewSettings validate
    // with). Meaningless for env.
    double minimum;
    double maximum;
    // The material property the axis sets (core/material/MaterialProperties.h); nullopt for env
    // and exposure.
    std::optional<MaterialProperty> property;
};

// Every parameter, in the order of the enum (the order the docs and messages list them).
std::span<const WedgeParameterInfo> wedgeParameters();
const WedgeParameterInfo& infoOf(WedgeParameter parameter);
const char* toString(WedgeParameter parameter); // infoOf(parameter).name
std::optional<WedgeParameter> wedgeParameterFromString(std::string_view name);
// "metallic, roughness, occlusion, normal, ior, emissiveStrength, alphaCutoff, alpha, env, exposure"
std::string wedgeParameterNameList();

struct WedgeAxis {
    // More values are refused: 16 x 16 cells is already a 4096 x 4096 sheet at 256-pixel cells.
    static constexpr int kMaxValues = 16;

    WedgeParameter parameter = WedgeParameter::Roughness;
    std::vector<double> values; // every parameter but env: the numbers, in cell order
    // env: the specs, in cell order. parse() keeps them as written (a command line's relative
    // path is the caller's to resolve); a project file's are resolved against its folder.
    std::vector<std::string> environments;

    // Roughness 0, 0.25, 0.5, 0.75, 1 and metallic 0, 1: the default wedge (rows x columns).
    static WedgeAxis defaultRows();
    static WedgeAxis defaultColumns();

    bool isEnvironment() const { return parameter == WedgeParameter::Environment; }
    // How many cells the axis has (values or environments, whichever the parameter uses).
    std::size_t size() const { return isEnvironment() ? environments.size() : values.size(); }

    // Reads "PARAMETER=V1,V2,..." (the form of `facet sheet --wedge`): numbers as C++ reads them
    // ("0.5", "1e-3", "+1"; spaces around a value are ignored), env values as specs. A uniform:R,G,B
    // spec keeps the two numbers after it ("env=studio,uniform:1,0.5,0.25,sky" is three cells); a
    // path containing a comma cannot be named here. On failure nullopt and *error is
    // "WedgeAxis::parse: \"TEXT\": PROBLEM", where PROBLEM names the parameter or the value:
    // unknown parameter (listing the known ones), no values, an empty value, a value that is not a
    // number, one out of range (Material/ViewSettings validation's message), more than kMaxValues.
    static std::optional<WedgeAxis> parse(std::string_view text, std::string* error);
    // The inverse of parse(): "roughness=0,0.25,0.5" (shortest round-trip numbers).
    std::string toString() const;

    // Checks the value count (1 to kMaxValues), that the list the parameter does not use is
    // empty, and each value (numbers by Material's or ViewSettings's rule, specs by
    // Environment::checkSpec). On failure "<field>: <problem>" with the field as the project file
    // names it (both lists are its "values"), e.g. "values[2]: roughness.factor: 1.5 is outside
    // [0, 1]" (the caller prefixes the axis' path).
    bool validate(std::string* problem) const;

    // Sets value `index` (< size()) in `project`: the current material's field, the environment's
    // source or the view's exposure. The rest of the project stays as it is.
    void apply(std::size_t index, Project& project) const;
    // A cell's label: "roughness 0.25", "ior 1.45", "exposure +1 EV", "env studio" (a file or a
    // library reference by its base name: "env night" for .../hdri/night.exr).
    std::string label(std::size_t index) const;

    // Why sweeping this axis changes nothing in `project`, or empty: alphaCutoff without alpha mode
    // "mask", alpha with mode "opaque", emissiveStrength with a black emissive factor, normal or
    // occlusion strength without a texture in that map, ior on a metal (metallic 1, no texture).
    // For `facet sheet` and the window to warn; the axis is still valid.
    std::string noEffectReason(const Project& project) const;

    bool operator==(const WedgeAxis&) const = default;
};

} // namespace facet
