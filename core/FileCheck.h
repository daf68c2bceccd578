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

} // namespace facet
