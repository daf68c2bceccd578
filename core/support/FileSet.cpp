#include "core/support/FileSet.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <stdlib.h> // mkdtemp

namespace facet {

namespace fs = std::filesystem;

namespace {

constexpr const char* kStagingPrefix = ".facet-new-";
// A replaced file waits here until the set is in place (put back if it is not).
constexpr const char* kReplacedPrefix = ".facet-old-";

bool present(const std::string& path)
{
    std::error_code ignored;
    return fs::exists(fs::symlink_status(path, ignored));
}

} // namespace

FileSet::FileSet(std::string folder)
    : m_folder(std::move(folder))
{
}

FileSet::~FileSet()
{
    discard();
}

std::string FileSet::path(const std::string& name) const
{
    return m_folder + "/" + name;
}

std::vector<std::string> FileSet::existing(const std::vector<std::string>& names) const
{
    std::vector<std::string> found;
    for (const std::string& name : names)
        if (present(path(name)))
            found.push_back(path(name));
    return found;
}

bool FileSet::begin(std::string* problem)
{
    if (!m_staging.empty())
        return true;
    std::string pattern = path(std::string(kStagingPrefix) + "XXXXXX");
    if (!::mkdtemp(pattern.data())) {
        if (problem)
            *problem = std::string("cannot make a folder to write the new files in: ") + std::strerror(errno);
        return false;
    }
    m_staging = pattern;
    return true;
}

std::string FileSet::stagedPath(const std::string& name) const
{
    return m_staging + "/" + name;
}

std::string FileSet::named(std::string message) const
{
    if (m_staging.empty())
        return message;
    for (std::size_t at = message.find(m_staging); at != std::string::npos; at = message.find(m_staging, at))
        message.replace(at, m_staging.size(), m_folder), at += m_folder.size();
    return message;
}

void FileSet::written(const std::string& name)
{
    m_names.push_back(name);
}

bool FileSet::commit(std::string* problem)
{
    struct Swap {
        std::string target;
        std::string staged;
        std::string replaced; // "" when nothing was there
    };
    std::vector<Swap> done;
    const auto undo = [&done] {
        for (auto swap = done.rbegin(); swap != done.rend(); ++swap) {
            std::error_code ignored;
            fs::rename(swap->target, swap->staged, ignored);
            if (!swap->replaced.empty())
                fs::rename(swap->replaced, swap->target, ignored);
        }
    };
    for (const std::string& name : m_names) {
        Swap swap {path(name), stagedPath(name), {}};
        std::error_code code;
        if (present(swap.target)) {
            // The new file takes the old one's permission bits, as a single atomic write does.
            const fs::file_status old = fs::status(swap.target, code);
            if (!code)
                fs::permissions(swap.staged, old.permissions(), code);
            swap.replaced = m_staging + "/" + kReplacedPrefix + name;
            fs::rename(swap.target, swap.replaced, code);
            if (code) {
                undo();
                discard();
                if (problem)
                    *problem = swap.target + ": cannot move it aside to replace it: " + code.message()
                        + " (nothing was replaced)";
                return false;
            }
        }
        fs::rename(swap.staged, swap.target, code);
        if (code) {
            if (!swap.replaced.empty()) {
                std::error_code ignored;
                fs::rename(swap.replaced, swap.target, ignored);
            }
            undo();
            discard();
            if (problem)
                *problem = swap.target + ": cannot move the new file into place: " + code.message()
                    + " (nothing was replaced)";
            return false;
        }
        done.push_back(std::move(swap));
    }
    m_committed.clear();
    for (const Swap& swap : done)
        m_committed.push_back(swap.target);
    discard(); // the replaced files, and the staging folder
    return true;
}

void FileSet::discard()
{
    if (!m_staging.empty()) {
        std::error_code ignored;
        fs::remove_all(m_staging, ignored);
    }
    m_staging.clear();
    m_names.clear();
}

} // namespace facet
