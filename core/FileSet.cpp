#include "core/FileSet.h"

#include <filesystem>
#include <system_error>

namespace facet {

FileSet::FileSet(std::string folder)
    : m_folder(std::move(folder))
{
}

std::string FileSet::path(const std::string& name) const
{
    return m_folder + "/" + name;
}

std::vector<std::string> FileSet::existing(const std::vector<std::string>& names) const
{
    std::vector<std::string> found;
    for (const std::string& name : names) {
        std::error_code ignored;
        if (std::filesystem::exists(std::filesystem::symlink_status(path(name), ignored)))
            found.push_back(path(name));
    }
    return found;
}

void FileSet::aboutToWrite(const std::string& name)
{
    std::error_code ignored;
    m_pending = std::filesystem::exists(std::filesystem::symlink_status(path(name), ignored)) ? std::string()
                                                                                              : path(name);
}

void FileSet::written(const std::string& name)
{
    if (!m_pending.empty() && m_pending == path(name))
        m_new.push_back(m_pending);
    m_pending.clear();
    m_written.push_back(path(name));
}

void FileSet::removeNew()
{
    for (const std::string& created : m_new) {
        std::error_code ignored;
        std::filesystem::remove(created, ignored);
    }
    m_new.clear();
    m_written.clear();
    m_pending.clear();
}

} // namespace facet
