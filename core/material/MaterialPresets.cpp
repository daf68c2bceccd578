#include "core/material/MaterialPresets.h"

#include <QFileInfo>
#include <QJsonValue>

#include "core/project/Project.h" // material JSON and the file helpers shared with project files
#include "core/support/Failure.h"

namespace facet {

namespace {

struct DielectricEntry {
    const char* id;
    const char* name;
    double f0; // linear, from the table
    glm::dvec3 baseColor; // linear
    double roughness;
};

struct MetalEntry {
    const char* id;
    const char* name;
    glm::dvec3 f0; // linear; becomes the base colour
    double roughness;
};

// F0 from the LearnOpenGL / Real-Time Rendering table. The base colours are plausible opaque
// stand-ins (Facet renders no transmission): deep water and high-index glass are dark, ruby red.
const DielectricEntry kTableDielectrics[] = {
    {"water", "Water", 0.02, {0.05, 0.12, 0.16}, 0.05},
    {"plastic-low", "Plastic (low)", 0.03, {0.7, 0.7, 0.7}, 0.45},
    {"plastic-high", "Plastic (high)", 0.05, {0.1, 0.25, 0.6}, 0.2},
    {"glass-high", "Glass (high index)", 0.08, {0.02, 0.03, 0.025}, 0.02},
    {"ruby", "Ruby", 0.08, {0.5, 0.02, 0.05}, 0.05},
    {"diamond", "Diamond", 0.17, {0.8, 0.8, 0.8}, 0.02},
};

const MetalEntry kTableMetals[] = {
    {"iron", "Iron", {0.56, 0.57, 0.58}, 0.45},
    {"copper", "Copper", {0.95, 0.64, 0.54}, 0.3},
    {"gold", "Gold", {1.00, 0.71, 0.29}, 0.25},
    {"aluminium", "Aluminium", {0.91, 0.92, 0.92}, 0.35},
    {"silver", "Silver", {0.95, 0.93, 0.88}, 0.2},
};

// Everyday dielectrics at glTF's default IOR 1.5 (F0 0.04).
const DielectricEntry kCommonDielectrics[] = {
    {"rubber", "Rubber (black)", 0.04, {0.02, 0.02, 0.02}, 0.9},
    {"painted-white", "Painted white", 0.04, {0.8, 0.8, 0.8}, 0.5},
    {"ceramic-glossy", "Ceramic (glossy)", 0.04, {0.85, 0.85, 0.82}, 0.1},
    {"car-paint-red", "Car paint (red)", 0.04, {0.5, 0.02, 0.02}, 0.2},
};

MaterialPreset makePreset(const char* id, const char* name, const glm::dvec3& baseColor, double metallic,
    double roughness, double ior)
{
    MaterialPreset preset;
    preset.id = id;
    preset.displayName = name;
    preset.material.name = name;
    preset.material.setBaseColor(baseColor);
    preset.material.setFactor(MapSlot::Metallic, metallic);
    preset.material.setFactor(MapSlot::Roughness, roughness);
    preset.material.ior = ior;
    return preset;
}

std::vector<MaterialPreset> makeBuiltinPresets()
{
    std::vector<MaterialPreset> presets;
    for (const DielectricEntry& e : kTableDielectrics)
        presets.push_back(makePreset(e.id, e.name, e.baseColor, 0.0, e.roughness, iorFromF0(e.f0)));
    for (const MetalEntry& e : kTableMetals)
        presets.push_back(makePreset(e.id, e.name, e.f0, 1.0, e.roughness, Material::kDefaultIor));
    for (const DielectricEntry& e : kCommonDielectrics)
        presets.push_back(makePreset(e.id, e.name, e.baseColor, 0.0, e.roughness, Material::kDefaultIor));
    return presets;
}

std::nullopt_t failed(const std::string& message, std::string* error)
{
    fail(message, error);
    return std::nullopt;
}

const char* typeName(const QJsonValue& value)
{
    if (value.isString())
        return "a string";
    if (value.isDouble())
        return "a number";
    if (value.isBool())
        return "a boolean";
    if (value.isArray())
        return "an array";
    if (value.isObject())
        return "an object";
    return "null";
}

// Reads a preset object; messages start at the JSON path.
std::optional<MaterialPreset> readPreset(
    const QJsonObject& object, const std::string& baseDir, std::string* problem, std::string* warning)
{
    if (!json::checkFormat(
            object, kPresetFormatName, kPresetFormatVersion, "a Facet material preset", problem))
        return std::nullopt;
    MaterialPreset preset;
    const QJsonValue id = object.value(QLatin1String("id"));
    if (id.isUndefined())
        return failed("\"id\" is missing", problem);
    if (!id.isString())
        return failed(std::string("id: expected a string, got ") + typeName(id), problem);
    preset.id = id.toString().toStdString();
    if (!isValidPresetId(preset.id))
        return failed(
            "id: \"" + preset.id + "\" must be lower-case letters, digits and '-', starting with a letter",
            problem);
    const QJsonValue name = object.value(QLatin1String("name"));
    if (name.isUndefined())
        preset.displayName = preset.id;
    else if (name.isString())
        preset.displayName = name.toString().toStdString();
    else
        return failed(std::string("name: expected a string, got ") + typeName(name), problem);
    const QJsonValue material = object.value(QLatin1String("material"));
    if (material.isUndefined())
        return failed("\"material\" is missing", problem);
    if (!material.isObject())
        return failed(std::string("material: expected an object, got ") + typeName(material), problem);
    std::string materialWarning;
    std::optional<Material> parsed
        = materialFromJson(material.toObject(), baseDir, "material", problem, &materialWarning);
    if (!parsed)
        return std::nullopt;
    preset.material = std::move(*parsed);

    std::string notes = materialWarning;
    for (auto it = object.begin(); it != object.end(); ++it) {
        static const char* const kKnown[] = {"format", "version", "generator", "id", "name", "material"};
        bool known = false;
        for (const char* key : kKnown)
            known = known || it.key() == QLatin1String(key);
        if (!known)
            notes += (notes.empty() ? "" : "\n") + it.key().toStdString() + ": unknown key, ignored";
    }
    if (warning)
        *warning = notes;
    return preset;
}

std::string prefixLines(const std::string& text, const std::string& prefix)
{
    if (text.empty())
        return text;
    std::string out = prefix;
    for (char c : text) {
        out += c;
        if (c == '\n')
            out += prefix;
    }
    return out;
}

} // namespace

const std::vector<MaterialPreset>& builtinPresets()
{
    static const std::vector<MaterialPreset> presets = makeBuiltinPresets();
    return presets;
}

const MaterialPreset* findPreset(std::string_view id)
{
    for (const MaterialPreset& preset : builtinPresets())
        if (preset.id == id)
            return &preset;
    return nullptr;
}

bool isValidPresetId(std::string_view id)
{
    if (id.empty() || !(id[0] >= 'a' && id[0] <= 'z'))
        return false;
    for (char c : id)
        if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-'))
            return false;
    return true;
}

QJsonObject presetToJson(const MaterialPreset& preset, const std::string& baseDir, bool includeTexturePaths)
{
    QJsonObject o;
    o[QLatin1String("format")] = QLatin1String(kPresetFormatName);
    o[QLatin1String("version")] = kPresetFormatVersion;
    o[QLatin1String("id")] = QString::fromStdString(preset.id);
    o[QLatin1String("name")] = QString::fromStdString(preset.displayName);
    o[QLatin1String("material")] = materialToJson(preset.material, baseDir, includeTexturePaths);
    return o;
}

std::optional<MaterialPreset> presetFromJson(
    const QJsonObject& object, const std::string& baseDir, std::string* error, std::string* warning)
{
    std::string problem;
    std::string notes;
    std::optional<MaterialPreset> preset = readPreset(object, baseDir, &problem, &notes);
    if (!preset)
        return failed("presetFromJson: " + problem, error);
    if (warning)
        *warning = prefixLines(notes, "presetFromJson: ");
    return preset;
}

bool savePreset(const MaterialPreset& preset, const std::string& path, std::string* error,
    bool includeTexturePaths, const std::string& textureBaseDir)
{
    const std::string prefix = "savePreset: " + path + ": ";
    if (!isValidPresetId(preset.id))
        return fail(prefix + "id \"" + preset.id
                + "\" must be lower-case letters, digits and '-', starting with a letter",
            error);
    std::string problem;
    if (!preset.material.validate(&problem))
        return fail(prefix + "not saved, the material is invalid: material." + problem, error);
    const std::string baseDir = !textureBaseDir.empty()
        ? textureBaseDir
        : QFileInfo(QString::fromStdString(path)).absolutePath().toStdString();
    if (!json::writeObjectFile(path, presetToJson(preset, baseDir, includeTexturePaths), &problem))
        return fail(prefix + problem, error);
    return true;
}

std::optional<MaterialPreset> loadPreset(const std::string& path, std::string* error, std::string* warning)
{
    const std::string prefix = "loadPreset: " + path + ": ";
    // A preset is a few kilobytes; the project limit is plenty.
    std::string problem;
    const std::optional<QJsonObject> object = json::readObjectFile(path, Project::kMaxFileBytes, &problem);
    if (!object)
        return failed(prefix + problem, error);
    const std::string baseDir = QFileInfo(QString::fromStdString(path)).absolutePath().toStdString();
    std::string notes;
    std::optional<MaterialPreset> preset = readPreset(*object, baseDir, &problem, &notes);
    if (!preset)
        return failed(prefix + problem, error);
    if (warning)
        *warning = prefixLines(notes, prefix);
    return preset;
}

} // namespace facet
