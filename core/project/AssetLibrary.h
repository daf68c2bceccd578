#pragma once
// Asset libraries: folders whose files a project names by the library's name instead of by a path,
// so the project opens on any machine where that library is set up, wherever its folder is
// (docs/project-format.md, "Library references"). A reference is written
//
//   library:NAME/PATH      e.g. library:installed/hdri/night.exr, library:my-hdris/loft.exr
//
// NAME is "installed" for the CC0 sample data packaging/fetch-assets.sh installs, or the name of a
// folder the user added (Environment dock, Add Folder…). A user library is named once, when it is
// added, after its folder ("My HDRIs" -> "my-hdris", made unique), and keeps that name: adding a
// folder of the same name on another machine makes the same references work there. PATH is
// relative to the library's folder, with '/' separators and no "..".
//
// The built-in procedural environments and meshes ("studio", "sky", "sphere", ...) need no library
// and keep their bare names. User libraries live in QSettings (key "assetLibraries"), which the
// window and the command line share.

#include <optional>
#include <string>
#include <vector>

namespace facet {

struct AssetLibrary {
    enum class Kind { Installed, User };
    static constexpr const char* kInstalledName = "installed";
    static constexpr const char* kSpecPrefix = "library:";

    Kind kind = Kind::User;
    std::string name; // lower-case letters, digits and '-', starting with a letter or digit
    std::string folder; // absolute and clean, '/' separators; need not exist

    // The installed CC0 sample library: packaging/fetch-assets.sh's folder, by the script's rule:
    // $FACET_ASSETS_DIR, else $XDG_DATA_HOME/facet/assets, else ~/.local/share/facet/assets.
    static AssetLibrary installed();
    // The user's libraries in the order they were added (QSettings).
    static std::vector<AssetLibrary> userLibraries();
    // installed() first, then the user's.
    static std::vector<AssetLibrary> all();
    static std::optional<AssetLibrary> named(const std::string& name);
    // Registers `folder` as a user library named after it (nameForFolder) and returns it; a folder
    // registered already keeps its library and name. Nullopt with *error ("AssetLibrary::
    // addUserLibrary: <folder>: <problem>") when the folder does not exist.
    static std::optional<AssetLibrary> addUserLibrary(const std::string& folder, std::string* error);
    // A library name for `folder`: its last component in lower case, every run of other characters
    // than letters and digits made one '-' ("My HDRIs (2k)" -> "my-hdris-2k"; "library" when
    // nothing is left), with "-2", "-3", ... appended while the name is "installed" or in `taken`.
    static std::string nameForFolder(const std::string& folder, const std::vector<AssetLibrary>& taken);
    static bool isValidName(const std::string& name);

    // Whether `spec` is a library reference (starts with "library:"), well formed or not.
    static bool isSpec(const std::string& spec);
    // The reference of an absolute path inside a library's folder ("library:installed/hdri/x.exr").
    // The installed library wins over user libraries, then the deepest folder. Nullopt elsewhere.
    static std::optional<std::string> specForPath(const std::string& absolutePath);
    // The absolute path a reference names on this machine (the file itself need not exist).
    // Nullopt with *problem ("library:foo/x.exr: ...") when it is malformed or no library has
    // that name here.
    static std::optional<std::string> resolveSpec(const std::string& spec, std::string* problem);
    // For a file that cannot be found, what the user can do, when it belongs to a library (a
    // reference, or a path inside a library's folder): e.g. "it belongs to the installed CC0
    // samples (library:installed/hdri/night.exr), which are not in /x/assets: run
    // packaging/fetch-assets.sh". Empty for other files.
    static std::string missingFileAdvice(const std::string& pathOrSpec);
    // The file a spec or path names: a library reference resolved (resolveSpec), anything else as
    // it is. On failure nullopt with *error "<function>: <problem>; <advice>" (missingFileAdvice).
    static std::optional<std::string> fileForSpec(
        const std::string& specOrPath, const char* function, std::string* error);
};

} // namespace facet
