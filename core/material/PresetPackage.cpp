#include "core/material/PresetPackage.h"

#include <cctype>
#include <filesystem>
#include <map>
#include <set>
#include <system_error>

#include <QFile>

#include "core/gltf/GltfImport.h"
#include "core/support/AtomicFile.h"
#include "core/support/FileSet.h"

namespace facet {

namespace fs = std::filesystem;

namespace {

// `name` without the "<slot>-" or "<slot>-<n>-" prefixes a package gives its textures.
std::string withoutSlotPrefix(std::string name)
{
    for (bool stripped = true; stripped;) {
        stripped = false;
        for (const MapSlot slot : kAllMapSlots) {
            const std::string prefix = std::string(toString(slot)) + "-";
            if (!name.starts_with(prefix) || name.size() == prefix.size())
                continue;
            std::size_t end = prefix.size();
            while (end < name.size() && std::isdigit(static_cast<unsigned char>(name[end])))
                ++end;
            const std::size_t cut
                = end > prefix.size() && end < name.size() && name[end] == '-' ? end + 1 : prefix.size();
            if (cut < name.size()) {
                name.erase(0, cut);
                stripped = true;
            }
        }
    }
    return name;
}

std::optional<std::string> readBytes(const std::string& path, std::string* problem)
{
    QFile file(QString::fromStdString(path));
    if (!file.open(QIODevice::ReadOnly)) {
        *problem = "cannot read it: " + file.errorString().toStdString();
        return std::nullopt;
    }
    const QByteArray bytes = file.readAll();
    if (file.error() != QFileDevice::NoError) {
        *problem = "cannot read it: " + file.errorString().toStdString();
        return std::nullopt;
    }
    return bytes.toStdString();
}

std::string extensionForMime(const std::string& mime)
{
    if (mime == "image/jpeg")
        return ".jpg";
    if (mime == "image/webp")
        return ".webp";
    if (mime == "image/ktx2")
        return ".ktx2";
    return ".png";
}

// A texture's bytes and the name its copy gets: a file's own name, an embedded image's
// "<asset>-image<i>.<ext>".
std::optional<std::pair<std::string, std::string>> textureSource(
    const std::string& path, std::string* problem)
{
    if (const std::optional<GltfImageReference> reference = parseGltfImageReference(path)) {
        std::string mime;
        const std::optional<std::vector<unsigned char>> bytes = readGltfImage(*reference, &mime, problem);
        if (!bytes)
            return std::nullopt;
        const std::string name = fs::path(reference->assetPath).stem().string() + "-image"
            + std::to_string(reference->imageIndex) + extensionForMime(mime);
        return std::pair {name, std::string(bytes->begin(), bytes->end())};
    }
    std::optional<std::string> bytes = readBytes(path, problem);
    if (!bytes)
        return std::nullopt;
    return std::pair {fs::path(path).filename().string(), std::move(*bytes)};
}

bool inside(const fs::path& folder, const fs::path& file)
{
    const fs::path relative = file.lexically_normal().lexically_relative(folder.lexically_normal());
    return !relative.empty() && *relative.begin() != "..";
}

} // namespace

bool hasTextures(const Material& material)
{
    for (const MapSlot slot : kAllMapSlots)
        if (material.map(slot).hasTexture())
            return true;
    return false;
}

std::optional<std::string> exportPresetPackage(
    const MaterialPreset& preset, const std::string& folder, bool replace, std::string* error)
{
    const fs::path package = fs::path(folder) / (preset.id + kPresetPackageSuffix);
    const auto fail = [&](const std::string& problem) {
        *error = "exportPresetPackage: " + package.string() + ": " + problem;
        return std::nullopt;
    };
    if (!isValidPresetId(preset.id))
        return fail("'" + preset.id + "' is not a preset id (lower-case letters, digits and '-')");
    std::error_code code;
    if (fs::exists(package, code) && !replace)
        return fail("exists");
    // Read every texture first: nothing is written for a preset that cannot travel whole.
    MaterialPreset copy = preset;
    std::map<std::string, std::string> nameOfSource; // source path -> file name in the package
    std::map<std::string, std::string> bytesOfName;
    std::set<std::string> names = {kPresetPackageIndex};
    for (const MapSlot slot : kAllMapSlots) {
        MaterialMap& map = copy.material.map(slot);
        if (!map.hasTexture())
            continue;
        auto known = nameOfSource.find(map.path);
        if (known == nameOfSource.end()) {
            std::string problem;
            std::optional<std::pair<std::string, std::string>> source = textureSource(map.path, &problem);
            if (!source)
                return fail(std::string(toString(slot)) + ": " + map.path + ": " + problem);
            // A texture that came from a package already carries a slot's prefix: not twice (issue
            // 30: "baseColor-baseColor-brick.png" after an export, an import and an export).
            const std::string stem = withoutSlotPrefix(source->first);
            std::string name = std::string(toString(slot)) + "-" + stem;
            for (int n = 2; names.count(name); ++n)
                name = std::string(toString(slot)) + "-" + std::to_string(n) + "-" + stem;
            names.insert(name);
            bytesOfName[name] = std::move(source->second);
            known = nameOfSource.emplace(map.path, name).first;
        }
        map.path = (package / known->second).string();
    }
    fs::create_directories(package, code);
    if (!fs::is_directory(package, code))
        return fail("cannot make the folder");
    // All or nothing (core/support/FileSet.h): an earlier package in the folder stays whole on failure.
    FileSet files(package.string());
    const auto abandon = [&] {
        files.discard();
        fs::remove(package, code); // only when empty: an earlier package's files stay
    };
    std::string problem;
    if (!files.begin(&problem)) {
        abandon();
        return fail(problem);
    }
    for (const auto& [name, bytes] : bytesOfName) {
        if (!writeFileAtomically(files.stagedPath(name), bytes, &problem)) {
            abandon();
            return fail(name + ": cannot write it: " + problem);
        }
        files.written(name);
    }
    // The index names its textures relative to the package, where it will be, not the staging
    // folder it is written in.
    if (!savePreset(copy, files.stagedPath(kPresetPackageIndex), &problem, /*includeTexturePaths=*/true,
            package.string())) {
        abandon();
        *error = "exportPresetPackage: " + files.named(problem);
        return std::nullopt;
    }
    files.written(kPresetPackageIndex);
    if (!files.commit(&problem)) {
        abandon();
        return fail(problem);
    }
    return package.string();
}

std::optional<MaterialPreset> loadPresetPackage(const std::string& package, std::string* error)
{
    const auto fail = [&](const std::string& problem) {
        *error = "loadPresetPackage: " + package + ": " + problem;
        return std::nullopt;
    };
    std::error_code code;
    if (!fs::is_directory(package, code))
        return fail("is not a preset package (a folder holding " + std::string(kPresetPackageIndex) + ")");
    const fs::path index = fs::path(package) / kPresetPackageIndex;
    if (!fs::exists(index, code))
        return fail(std::string("has no ") + kPresetPackageIndex);
    std::string problem;
    std::optional<MaterialPreset> preset = loadPreset(index.string(), &problem);
    if (!preset) {
        *error = "loadPresetPackage: " + problem;
        return std::nullopt;
    }
    for (const MapSlot slot : kAllMapSlots) {
        const MaterialMap& map = preset->material.map(slot);
        if (!map.hasTexture())
            continue;
        if (!inside(fs::path(package), fs::path(map.path)))
            return fail(std::string(toString(slot)) + ": " + map.path + " is outside the package");
        if (!fs::is_regular_file(map.path, code))
            return fail(std::string(toString(slot)) + ": " + map.path + " is missing");
    }
    return preset;
}

std::optional<std::string> installPresetPackage(
    const std::string& package, const std::string& library, std::string* error)
{
    std::optional<MaterialPreset> preset = loadPresetPackage(package, error);
    if (!preset)
        return std::nullopt;
    std::error_code code;
    fs::create_directories(library, code);
    std::string id = preset->id;
    for (int n = 2; fs::exists(fs::path(library) / (id + kPresetPackageSuffix), code)
         || fs::exists(fs::path(library) / (id + ".json"), code);
         ++n)
        id = preset->id + "-" + std::to_string(n);
    preset->id = id;
    std::string problem;
    std::optional<std::string> installed = exportPresetPackage(*preset, library, false, &problem);
    if (!installed) {
        *error = "installPresetPackage: " + problem;
        return std::nullopt;
    }
    return installed;
}

} // namespace facet
