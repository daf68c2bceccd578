#pragma once
// Built-in material presets and user presets stored as JSON files.
//
// The built-ins take their specular colour F0 (linear) from the table in LearnOpenGL's "PBR:
// Theory" chapter (Joey de Vries), which quotes Real-Time Rendering (Akenine-Moller, Haines,
// Hoffman). Dielectrics carry the IOR that gives that F0 (iorFromF0, so f0FromIor(ior) is the table's
// value) and a plausible base colour; metals are metallic 1 with base colour = F0 (glTF 2.0: a
// metal's base colour is its F0).
//
// A user preset file is {"format": "facet-material-preset", "version": 1, "id", "name",
// "material"} with the material as in project files (docs/project-format.md); texture paths are
// left out unless asked for, so a preset is a look, not a texture set.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <QJsonObject>

#include "core/material/Material.h"

namespace facet {

struct MaterialPreset {
    std::string id; // lower-case letters, digits and '-', starting with a letter: "plastic-low"
    std::string displayName; // "Plastic (low)"; also the material's name
    Material material;

    bool operator==(const MaterialPreset&) const = default;
};

inline constexpr const char* kPresetFormatName = "facet-material-preset";
inline constexpr int kPresetFormatVersion = 1;

// Every built-in preset, in menu order; ids are unique.
const std::vector<MaterialPreset>& builtinPresets();
// The built-in preset with this id, or nullptr.
const MaterialPreset* findPreset(std::string_view id);
// True for ids of the form above.
bool isValidPresetId(std::string_view id);

// Preset <-> JSON. baseDir: the folder texture paths are relative to (empty: as they are).
QJsonObject presetToJson(
    const MaterialPreset& preset, const std::string& baseDir = {}, bool includeTexturePaths = false);
// Messages start with "presetFromJson: ".
std::optional<MaterialPreset> presetFromJson(const QJsonObject& object, const std::string& baseDir,
    std::string* error, std::string* warning = nullptr);

// Writes through writeFileAtomically (the old file stays intact on failure). Texture paths, when included,
// are stored relative to the preset file's folder, or to `textureBaseDir` when given (a file
// written in a staging folder before it moves, core/support/FileSet.h). Messages: "savePreset: <path>:
// <problem>".
bool savePreset(const MaterialPreset& preset, const std::string& path, std::string* error,
    bool includeTexturePaths = false, const std::string& textureBaseDir = {});
// Messages: "loadPreset: <path>: <json path>: <problem>".
std::optional<MaterialPreset> loadPreset(
    const std::string& path, std::string* error, std::string* warning = nullptr);

} // namespace facet
