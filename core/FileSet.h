#pragma once
// Several files written into one folder as one result (a texture set, an IBL bake): each file is
// written atomically (core/AtomicFile.h), and when a later one fails, the files this set made are
// removed again, so the folder holds the whole set or what it held before (files it replaced
// stay replaced: each is complete, and the old content is gone with the rename). Writers check
// for files they would replace before writing anything (existing()).

#include <string>
#include <vector>

namespace facet {

class FileSet {
public:
    explicit FileSet(std::string folder);

    const std::string& folder() const { return m_folder; }
    // "<folder>/<name>".
    std::string path(const std::string& name) const;
    // The names of `names` already in the folder (their paths), in order.
    std::vector<std::string> existing(const std::vector<std::string>& names) const;

    // Call before writing `name`; then written() after it succeeded.
    void aboutToWrite(const std::string& name);
    void written(const std::string& name);
    // Removes the files this set created (not those it replaced); the set is empty afterwards.
    void removeNew();

    const std::vector<std::string>& writtenPaths() const { return m_written; }

private:
    std::string m_folder;
    std::string m_pending; // the file being written, when it did not exist before
    std::vector<std::string> m_new;
    std::vector<std::string> m_written;
};

} // namespace facet
