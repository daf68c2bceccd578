#pragma once
// Several files written into one folder as one result (a texture set, a glTF asset and its
// textures, an IBL bake, a preset package), all or nothing (issue 29, "Data lost, mixed set").
//
// The new files are written into a staging folder inside the destination ("<folder>/.facet-new-
// XXXXXX", on the same file system, so that a rename moves each file without copying it), and only
// when every one of them is complete does commit() swap them in: each file it replaces is first
// renamed into the staging folder, then the new one renamed into place; if any rename fails the
// swapped files are put back. A disk that fills midway therefore fails in the staging folder and
// leaves the destination exactly as it was: before, `export --force` over a set exited 1 with one
// new 512 px map among old 64 px ones, and `bake --force` with 36 of 40 files from the new
// environment while ibl.json described the old one.
//
// A set that is destroyed before commit() (a writer returned early) removes its staging folder:
// the destination never sees a part of it. Writers check for files they would replace before
// writing anything (existing()).

#include <string>
#include <vector>

namespace facet {

class FileSet {
public:
    explicit FileSet(std::string folder);
    ~FileSet(); // discard()s a set not committed
    FileSet(const FileSet&) = delete;
    FileSet& operator=(const FileSet&) = delete;

    const std::string& folder() const { return m_folder; }
    // "<folder>/<name>": where `name` ends up, and the name every message gives.
    std::string path(const std::string& name) const;
    // The names of `names` already in the folder (their paths), in order.
    std::vector<std::string> existing(const std::vector<std::string>& names) const;

    // Makes the staging folder. False with *problem (one line, without the folder's name) when it
    // cannot be made: a full disk, a folder that cannot be written.
    bool begin(std::string* problem);
    // Where to write `name` now (begin() first): a file in the staging folder.
    std::string stagedPath(const std::string& name) const;
    // `message` with the staging folder's path replaced by the destination's, so that a writer's
    // message names the user's file, not a temporary.
    std::string named(std::string message) const;
    // Records that `name` was written completely to stagedPath(name).
    void written(const std::string& name);

    // Swaps the written files into the folder (all of them, or none: see above) and removes the
    // staging folder. False with *problem naming the file that could not be moved.
    bool commit(std::string* problem);
    // Removes the staging folder and all it holds; the destination is as it was. Idempotent.
    void discard();

    // The destination paths of the files committed, in the order they were written.
    const std::vector<std::string>& writtenPaths() const { return m_committed; }

private:
    std::string m_folder;
    std::string m_staging; // "" until begin()
    std::vector<std::string> m_names; // written to the staging folder, in order
    std::vector<std::string> m_committed;
};

} // namespace facet
