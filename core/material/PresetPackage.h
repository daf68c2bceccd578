#pragma once
// A material preset with its textures, as one self-contained folder that another Facet imports
// into its preset library with one action (issue 11, "Preset files"):
//
//   <id>.facetpreset/
//     preset.json        {"format": "facet-material-preset", ...} with texture paths relative to
//                        the folder (core/material/MaterialPresets.h; docs/project-format.md "Presets")
//     <slot>-<name>.png  a copy of each texture file, once however many slots read it; an image
//                        embedded in a glTF asset is written out as its own file
//
// A package holds nothing outside itself: loading one refuses a texture path that leaves the
// folder or a file that is missing, naming it. Writing one is all or nothing (core/support/FileSet: a
// failed copy removes what it made; nothing is replaced without `replace`).

#include <optional>
#include <string>

#include "core/material/MaterialPresets.h"

namespace facet {

inline constexpr const char* kPresetPackageSuffix = ".facetpreset";
inline constexpr const char* kPresetPackageIndex = "preset.json";

// Writes `preset` (its material's textures included) as "<folder>/<preset.id>.facetpreset".
// Returns the package's path; nullopt with *error ("exportPresetPackage: <path>: <problem>", a
// texture that cannot be read named with its slot).
std::optional<std::string> exportPresetPackage(
    const MaterialPreset& preset, const std::string& folder, bool replace, std::string* error);

// Reads a package: the preset with absolute texture paths inside it. nullopt with *error
// ("loadPresetPackage: <path>: <problem>").
std::optional<MaterialPreset> loadPresetPackage(const std::string& package, std::string* error);

// Copies the package at `package` into the preset library folder `library`, under its id made
// unique there ("brass", "brass-2", ...). Returns the installed package's path.
std::optional<std::string> installPresetPackage(
    const std::string& package, const std::string& library, std::string* error);

// Whether a material reads any texture (a preset that needs a package to travel).
bool hasTextures(const Material& material);

} // namespace facet
