#pragma once
// Whether a path names a file that can be read to its end: the one check every reader of user
// files (images, meshes, projects, presets, the IBL cache) makes before opening, so that a device
// (/dev/zero, /dev/urandom), a FIFO, a socket, a loop of symbolic links or a path holding a NUL
// byte is refused with its reason instead of blocking, reading without end or opening another file.

#include <cstdint>
#include <string>

namespace facet {

enum class FileKind : std::uint8_t {
    Regular, // a regular file (or a symbolic link to one)
    NoName, // the path is empty
    BadPath, // the path holds a NUL byte: a C API would read a shorter path
    Missing, // nothing there, or a dangling symbolic link
    Loop, // symbolic links that lead back to themselves (ELOOP)
    Folder,
    Special, // a device, FIFO or socket
    Unreadable, // exists, but its status cannot be read (permission on a parent folder, ...)
};

struct FileCheck {
    FileKind kind = FileKind::Regular;
    std::string problem; // "" for a regular file, else why, in a user's words ("is a folder, not a file")

    bool ok() const { return kind == FileKind::Regular; }
};

// Does not open the file; follows symbolic links.
FileCheck checkRegularFile(const std::string& path);

// What tells one version of a file from another without reading it: its size, modification and
// status-change times (nanoseconds) and where it lives (device, inode), as git's index keeps
// them. A rewrite changes the times; a file renamed or copied over the path (even with its old
// modification time kept, `cp -p`) changes the inode and the status-change time, which no
// program can set back. Symbolic links are followed: the identity is the target's.
struct FileIdentity {
    std::int64_t size = 0;
    std::int64_t modifiedNs = 0;
    std::int64_t changedNs = 0;
    std::uint64_t device = 0;
    std::uint64_t inode = 0;

    bool operator==(const FileIdentity&) const = default;
};

// The identity of a regular file; false when `path` is not one (checkRegularFile says why).
bool fileIdentity(const std::string& path, FileIdentity* identity);

} // namespace facet
