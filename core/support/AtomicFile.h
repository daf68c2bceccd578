#pragma once
// The one way Facet writes a file: the file at `path` is afterwards either the complete new
// content or exactly what it was before, never empty or half-written (docs/architecture.md, "Bad input").
// Every writer goes through it: projects, presets and the autosave (core/json/JsonFile.cpp), the IBL
// disk cache (core/ibl/IblDiskCache.cpp), images (core/image/Image.cpp), the ground-truth cache, bench CSV
// and screenshots (app/).
//
// Why not QSaveFile: in Qt 6.4 QSaveFile::commit() renames the temporary over the target even
// when its final flush failed. A write smaller than QFileDevice's 16 KiB buffer only reaches the
// disk in that flush, so on a full disk a small project became a 0-byte file while save()
// reported success (issue 12, "A saved project can be lost").

#include <cstddef>
#include <string>
#include <string_view>

namespace facet {

// Writes `bytes` to `path`:
//   1. creates "<path>.tmp-XXXXXX" (random hex) in the same folder, so the rename below stays
//      on one file system; it takes the old file's permission bits when there is one;
//   2. writes every byte, checking each write(2) (short writes are continued, EINTR retried);
//   3. fsync(2)s it, so a full disk or a failing device is reported now, not after the rename;
//   4. checks that the size on disk is bytes.size();
//   5. close(2)s it (checked: network file systems report write errors there);
//   6. rename(2)s it over `path` (atomic on POSIX), then fsyncs the folder (best effort: the
//      content is complete either way; this only makes the rename survive a power cut).
// A symbolic link at `path` is followed: the file it points to is replaced, the link stays.
// On any failure the temporary is removed, the file at `path` is left as it was, and `reason`
// (optional) receives one line without the file name, e.g. "No space left on device" or "only
// 812 of 2048 bytes reached the disk": every caller prefixes it with its function and `path`
// (house style: "Project::save: /p/a.json: cannot write it: No space left on device").
// Refuses a `path` that is a folder or something other than a regular file (a device, a FIFO):
// renaming over those would replace them.
bool writeFileAtomically(const std::string& path, std::string_view bytes, std::string* reason);

// The suffix the temporaries carry ("<path>" + kAtomicTemporaryMarker + 6 hex digits), for
// tests and clean-up tools that look for leftovers.
inline constexpr std::string_view kAtomicTemporaryMarker = ".tmp-";

} // namespace facet
