#include "core/support/AtomicFile.h"

#include <cerrno>
#include <cstdint>
#include <filesystem>
#include <random>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/support/Failure.h"

namespace facet {

namespace {

std::string errnoText(int error)
{
    return std::generic_category().message(error);
}

// The file a save replaces: a symbolic link is followed so that the link survives the save
// (what QSaveFile did, and what a user who linked a project into a folder expects). A dangling
// link is replaced like a file.
std::string targetOf(const std::string& path)
{
    std::error_code ec;
    if (!std::filesystem::is_symlink(path, ec))
        return path;
    const std::filesystem::path resolved = std::filesystem::canonical(path, ec);
    return ec ? path : resolved.string();
}

std::string folderOf(const std::string& path)
{
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    return parent.empty() ? std::string(".") : parent.string();
}

// Creates the temporary with O_EXCL under a random name, so two saves of one file (two windows,
// a save racing the autosave) never share a temporary. Returns the descriptor or -1 with errno set.
int createTemporary(const std::string& target, std::string* temporary)
{
    static const char kDigits[] = "0123456789abcdef";
    std::random_device device;
    std::mt19937 generator(device());
    std::uniform_int_distribution<int> digit(0, 15);
    for (int attempt = 0; attempt < 64; ++attempt) {
        std::string candidate = target + std::string(kAtomicTemporaryMarker);
        for (int i = 0; i < 6; ++i)
            candidate += kDigits[digit(generator)];
        // 0666 minus the umask: what a newly created file gets anyway.
        const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            *temporary = std::move(candidate);
            return fd;
        }
        if (errno != EEXIST)
            return -1;
    }
    errno = EEXIST;
    return -1;
}

} // namespace

bool writeFileAtomically(const std::string& path, std::string_view bytes, std::string* reason)
{
    if (path.empty())
        return fail("no file name given", reason);
    const std::string target = targetOf(path);

    struct stat existing { };
    const bool exists = ::stat(target.c_str(), &existing) == 0;
    if (exists && S_ISDIR(existing.st_mode))
        return fail("is a folder, not a file", reason);
    if (exists && !S_ISREG(existing.st_mode))
        return fail("is not a regular file (a device, FIFO or socket); not replacing it", reason);

    std::string temporary;
    int fd = createTemporary(target, &temporary);
    if (fd < 0) {
        const int error = errno;
        if (error == ENOENT)
            return fail("the folder " + folderOf(target) + " does not exist", reason);
        return fail(
            "cannot create a temporary file in " + folderOf(target) + ": " + errnoText(error), reason);
    }

    // From here on every failure closes and removes the temporary: the old file was never touched.
    const auto abandon = [&](const std::string& message) {
        if (fd >= 0)
            ::close(fd);
        ::unlink(temporary.c_str());
        return fail(message, reason);
    };

    // Keep the permissions the user gave the old file (e.g. a project shared read-only with a
    // group). Best effort: a file system without modes (FAT) refuses and that is fine.
    if (exists)
        (void)::fchmod(fd, existing.st_mode & 07777);

    const char* data = bytes.data();
    std::size_t left = bytes.size();
    while (left > 0) {
        const ssize_t written = ::write(fd, data, left);
        if (written < 0) {
            if (errno == EINTR)
                continue;
            return abandon(errnoText(errno));
        }
        if (written == 0) // POSIX allows it for a regular file only when nothing could be written
            return abandon("the device accepted no more bytes");
        data += written;
        left -= std::size_t(written);
    }

    // fsync: some file systems (NFS, CIFS, FUSE, thin-provisioned volumes) report a full disk or
    // an I/O error only when the data is flushed, not in write(); after the rename it would be too
    // late. EINVAL means the file system cannot sync at all.
    if (::fsync(fd) != 0 && errno != EINVAL)
        return abandon(errnoText(errno) + " (when flushing to the disk)");

    // The size the file system reports must be what was meant: a writer that lost bytes without
    // an error (the defect QSaveFile had) is caught here.
    struct stat onDisk { };
    if (::fstat(fd, &onDisk) != 0)
        return abandon("cannot check the written size: " + errnoText(errno));
    if (std::uint64_t(onDisk.st_size) != std::uint64_t(bytes.size()))
        return abandon("only " + std::to_string(onDisk.st_size) + " of " + std::to_string(bytes.size())
            + " bytes reached the disk");

    const int closed = ::close(fd);
    fd = -1;
    if (closed != 0 && errno != EINTR)
        return abandon(errnoText(errno) + " (when closing the file)");

    if (::rename(temporary.c_str(), target.c_str()) != 0)
        return abandon("cannot replace the file: " + errnoText(errno));

    // Make the rename itself durable. The new content is complete on disk already, so a failure
    // here is not a failed save.
    const int folder = ::open(folderOf(target).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (folder >= 0) {
        (void)::fsync(folder);
        ::close(folder);
    }
    return true;
}

} // namespace facet
