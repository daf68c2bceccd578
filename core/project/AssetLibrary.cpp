#include "core/project/AssetLibrary.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>

namespace facet {

namespace {

const QLatin1String kSettingsArray("assetLibraries");
const QLatin1String kNameKey("name");
const QLatin1String kFolderKey("folder");

QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}

std::string cleanAbsolute(const std::string& path)
{
    return QDir::cleanPath(QDir::fromNativeSeparators(QFileInfo(qs(path)).absoluteFilePath())).toStdString();
}

// "library:NAME/PATH" -> NAME and PATH, unchecked.
bool splitSpec(const std::string& spec, std::string* name, std::string* path)
{
    if (!AssetLibrary::isSpec(spec))
        return false;
    const std::string rest = spec.substr(std::char_traits<char>::length(AssetLibrary::kSpecPrefix));
    const std::size_t slash = rest.find('/');
    *name = rest.substr(0, slash);
    *path = slash == std::string::npos ? std::string() : rest.substr(slash + 1);
    return true;
}

// The library whose folder holds `cleanPath`, and the path inside it.
std::optional<std::pair<AssetLibrary, std::string>> libraryHolding(const std::string& cleanPath)
{
    std::optional<std::pair<AssetLibrary, std::string>> best;
    for (const AssetLibrary& library : AssetLibrary::all()) {
        const std::string& root = library.folder;
        if (root.empty() || cleanPath.size() <= root.size() + 1
            || cleanPath.compare(0, root.size(), root) != 0
            || (root.back() != '/' && cleanPath[root.size()] != '/'))
            continue;
        const std::size_t skip = root.back() == '/' ? root.size() : root.size() + 1;
        // The installed library comes first and wins; among user libraries the deepest folder.
        if (!best
            || (best->first.kind == AssetLibrary::Kind::User && library.kind == AssetLibrary::Kind::User
                && root.size() > best->first.folder.size()))
            best = std::make_pair(library, cleanPath.substr(skip));
    }
    return best;
}

} // namespace

AssetLibrary AssetLibrary::installed()
{
    QString folder = qEnvironmentVariable("FACET_ASSETS_DIR");
    if (folder.isEmpty()) {
        QString dataHome = qEnvironmentVariable("XDG_DATA_HOME");
        if (dataHome.isEmpty())
            dataHome = QDir::homePath() + QStringLiteral("/.local/share");
        folder = dataHome + QStringLiteral("/facet/assets");
    }
    return {Kind::Installed, kInstalledName, cleanAbsolute(folder.toStdString())};
}

std::vector<AssetLibrary> AssetLibrary::userLibraries()
{
    std::vector<AssetLibrary> libraries;
    QSettings settings;
    const int count = settings.beginReadArray(kSettingsArray);
    for (int i = 0; i < count; ++i) {
        settings.setArrayIndex(i);
        AssetLibrary library {Kind::User, settings.value(kNameKey).toString().toStdString(),
            settings.value(kFolderKey).toString().toStdString()};
        // A hand-edited or broken entry is skipped rather than resolving references wrongly.
        if (!isValidName(library.name) || library.name == kInstalledName || library.folder.empty())
            continue;
        library.folder = cleanAbsolute(library.folder);
        bool duplicate = false;
        for (const AssetLibrary& other : libraries)
            duplicate = duplicate || other.name == library.name;
        if (!duplicate)
            libraries.push_back(std::move(library));
    }
    settings.endArray();
    return libraries;
}

std::vector<AssetLibrary> AssetLibrary::all()
{
    std::vector<AssetLibrary> libraries {installed()};
    for (AssetLibrary& library : userLibraries())
        libraries.push_back(std::move(library));
    return libraries;
}

std::optional<AssetLibrary> AssetLibrary::named(const std::string& name)
{
    for (AssetLibrary& library : all())
        if (library.name == name)
            return std::move(library);
    return std::nullopt;
}

bool AssetLibrary::isValidName(const std::string& name)
{
    if (name.empty() || name.front() == '-')
        return false;
    for (char c : name)
        if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-'))
            return false;
    return true;
}

std::string AssetLibrary::nameForFolder(const std::string& folder, const std::vector<AssetLibrary>& taken)
{
    const QString base
        = QFileInfo(QDir::cleanPath(QDir::fromNativeSeparators(qs(folder)))).fileName().toLower();
    std::string name;
    bool dash = false;
    for (QChar c : base) {
        const char ascii = c.toLatin1();
        if ((ascii >= 'a' && ascii <= 'z') || (ascii >= '0' && ascii <= '9')) {
            if (dash && !name.empty())
                name += '-';
            name += ascii;
            dash = false;
        } else {
            dash = true;
        }
    }
    if (name.empty())
        name = "library";
    const auto isTaken = [&taken](const std::string& candidate) {
        if (candidate == kInstalledName)
            return true;
        for (const AssetLibrary& library : taken)
            if (library.name == candidate)
                return true;
        return false;
    };
    std::string unique = name;
    for (int suffix = 2; isTaken(unique); ++suffix)
        unique = name + "-" + std::to_string(suffix);
    return unique;
}

std::optional<AssetLibrary> AssetLibrary::addUserLibrary(const std::string& folder, std::string* error)
{
    const std::string clean = folder.empty() ? std::string() : cleanAbsolute(folder);
    if (clean.empty() || !QFileInfo(qs(clean)).isDir()) {
        if (error)
            *error = "AssetLibrary::addUserLibrary: " + (folder.empty() ? std::string("(no folder)") : folder)
                + ": no such folder";
        return std::nullopt;
    }
    std::vector<AssetLibrary> libraries = userLibraries();
    for (const AssetLibrary& library : libraries)
        if (library.folder == clean)
            return library;
    AssetLibrary added {Kind::User, nameForFolder(clean, libraries), clean};
    libraries.push_back(added);
    QSettings settings;
    settings.beginWriteArray(kSettingsArray, int(libraries.size()));
    for (int i = 0; i < int(libraries.size()); ++i) {
        settings.setArrayIndex(i);
        settings.setValue(kNameKey, qs(libraries[std::size_t(i)].name));
        settings.setValue(kFolderKey, qs(libraries[std::size_t(i)].folder));
    }
    settings.endArray();
    return added;
}

bool AssetLibrary::isSpec(const std::string& spec)
{
    return spec.rfind(kSpecPrefix, 0) == 0;
}

std::optional<std::string> AssetLibrary::specForPath(const std::string& absolutePath)
{
    if (absolutePath.empty() || QDir::isRelativePath(qs(absolutePath)))
        return std::nullopt;
    const auto held = libraryHolding(cleanAbsolute(absolutePath));
    if (!held)
        return std::nullopt;
    return kSpecPrefix + held->first.name + "/" + held->second;
}

std::optional<std::string> AssetLibrary::resolveSpec(const std::string& spec, std::string* problem)
{
    const auto fail = [&](const std::string& why) -> std::optional<std::string> {
        if (problem)
            *problem = spec + ": " + why;
        return std::nullopt;
    };
    std::string name;
    std::string path;
    if (!splitSpec(spec, &name, &path))
        return fail("not a library reference (library:NAME/PATH)");
    if (!isValidName(name))
        return fail("\"" + name
            + "\" is not a library name (lower-case letters, digits and '-'; expected library:NAME/PATH)");
    const QString clean = QDir::cleanPath(qs(path));
    if (path.empty() || path.find('\\') != std::string::npos || QDir::isAbsolutePath(qs(path))
        || clean == QLatin1String("..") || clean.startsWith(QLatin1String("../"))
        || clean == QLatin1String("."))
        return fail("expected a file path inside the library after \"" + std::string(kSpecPrefix) + name
            + "/\" (relative, '/' separators, no \"..\")");
    const std::optional<AssetLibrary> library = named(name);
    if (!library)
        return fail("no library named \"" + name + "\" on this machine");
    return library->folder + "/" + clean.toStdString();
}

std::string AssetLibrary::missingFileAdvice(const std::string& pathOrSpec)
{
    std::string spec = pathOrSpec;
    if (!isSpec(pathOrSpec)) {
        const std::optional<std::string> found = specForPath(pathOrSpec);
        if (!found)
            return {};
        spec = *found;
    }
    std::string name;
    std::string path;
    splitSpec(spec, &name, &path);
    if (!isValidName(name) || path.empty())
        return {};
    const std::optional<AssetLibrary> library = named(name);
    if (!library)
        return "it belongs to the library \"" + name
            + "\", which is not set up on this machine: add the folder that holds " + path
            + " with Add Folder in the window's Environment dock (a folder called \"" + name
            + "\" gets that name), or relink the file";
    if (library->kind == Kind::Installed) {
        const bool present = QFileInfo(qs(library->folder)).isDir();
        return "it belongs to the installed CC0 samples (" + spec + "), "
            + (present ? "and " + library->folder + " has no " + path : "which are not in " + library->folder)
            + ": run packaging/fetch-assets.sh to install them, or set FACET_ASSETS_DIR to the folder that "
              "holds them";
    }
    return "it belongs to the library \"" + name + "\" (" + library->folder + "), which has no " + path
        + ": put the file back there, or relink it";
}

std::optional<std::string> AssetLibrary::fileForSpec(
    const std::string& specOrPath, const char* function, std::string* error)
{
    if (!isSpec(specOrPath))
        return specOrPath;
    std::string problem;
    std::optional<std::string> resolved = resolveSpec(specOrPath, &problem);
    if (!resolved && error) {
        *error = std::string(function) + ": " + problem;
        if (const std::string advice = missingFileAdvice(specOrPath); !advice.empty())
            *error += "; " + advice;
    }
    return resolved;
}

} // namespace facet
