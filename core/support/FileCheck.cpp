#include "core/support/FileCheck.h"

#include <cerrno>
#include <filesystem>
#include <system_error>

#include <sys/stat.h>

namespace facet {

FileCheck checkRegularFile(const std::string& path)
{
    if (path.empty())
        return {FileKind::NoName, "no file name given"};
    if (path.find('\0') != std::string::npos)
        return {FileKind::BadPath, "the path holds a NUL character"};
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(path, error);
    if (error) {
        if (error.value() == ELOOP)
            return {FileKind::Loop, "is a loop of symbolic links"};
        if (error.value() == ENOENT || error.value() == ENOTDIR) {
            std::error_code linkError;
            if (std::filesystem::is_symlink(std::filesystem::symlink_status(path, linkError)))
                return {FileKind::Missing, "is a symbolic link to a file that does not exist"};
            return {FileKind::Missing, "no such file"};
        }
        return {FileKind::Unreadable, "cannot be read (" + error.message() + ")"};
    }
    if (std::filesystem::is_directory(status))
        return {FileKind::Folder, "is a folder, not a file"};
    if (!std::filesystem::is_regular_file(status))
        return {FileKind::Special, "is not a regular file (a device, pipe or socket)"};
    return {};
}

bool fileIdentity(const std::string& path, FileIdentity* identity)
{
    struct stat status { };
    if (path.empty() || path.find('\0') != std::string::npos || ::stat(path.c_str(), &status) != 0
        || !S_ISREG(status.st_mode))
        return false;
    auto nanoseconds = [](const timespec& time) {
        return std::int64_t(time.tv_sec) * 1000000000 + std::int64_t(time.tv_nsec);
    };
    identity->size = std::int64_t(status.st_size);
    identity->modifiedNs = nanoseconds(status.st_mtim);
    identity->changedNs = nanoseconds(status.st_ctim);
    identity->device = std::uint64_t(status.st_dev);
    identity->inode = std::uint64_t(status.st_ino);
    return true;
}

} // namespace facet
