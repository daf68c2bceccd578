#pragma once
// What Environment::load learned from an environment file, remembered by the file's identity
// (core/support/FileCheck.h FileIdentity: size, times, device, inode), so that loading the same file again
// needs no decoding: its content hash (the key of every IBL cache entry), the size of the image
// Facet keeps and the warnings its decoding gave. With the IBL disk cache holding the lighting, a
// warm `facet render` of an 8192x4096 EXR never decodes it (issue 12, "Large HDRIs").
//
// One small JSON file per environment path: "<IblDiskCache::defaultDirectory()>/sources/<16 hex
// digits of FNV-1a 64 of the absolute path>.json", written atomically (core/support/AtomicFile.h), holding
// the path (a hash collision reads as a miss), the identity and the record. docs/ibl.md "Environment
// index".
//
// A record is stored only when the file did not change while it was decoded and its modification
// time is more than kSettleSeconds old: a file written in the same clock tick as it was read
// could change again without changing its times (git's "racy clean" rule). A record that no longer
// matches the file is a miss; a record whose file turns out to decode to other pixels is forgotten.

#include "core/support/FileCheck.h"

#include <cstdint>
#include <optional>
#include <string>

#include <QString>

namespace facet {

struct EnvironmentRecord {
    std::uint64_t contentHash = 0; // Environment::contentHash() of the kept image
    int width = 0; // the kept image (an image over Environment::kMaxWidth is kept box-filtered)
    int height = 0;
    std::string warning; // Environment::load's warning lines, "" for none
};

class EnvironmentIndex {
public:
    // Bumped whenever what Environment::load keeps of a file changes (decoding, sanitising, the
    // size limit), so that records of an older Facet are misses.
    static constexpr int kVersion = 1;
    static constexpr int kSettleSeconds = 2;

    // `directory` empty: IblDiskCache::defaultDirectory() + "/sources".
    explicit EnvironmentIndex(QString directory = {});
    static QString defaultDirectory();
    QString recordPath(const std::string& path) const;

    // The record of the file at `path` when it still has `identity`; nullopt otherwise (no
    // record, another file's, an older version's, or unreadable: all misses, never an error).
    std::optional<EnvironmentRecord> find(const std::string& path, const FileIdentity& identity) const;
    // Remembers `record` for the file at `path`. False (and nothing written) when the file is too
    // recent to be trusted (see above) or the write fails; `reason` says why. A failure only costs
    // the next load its decoding.
    bool store(const std::string& path, const FileIdentity& identity, const EnvironmentRecord& record,
        std::string* reason = nullptr) const;
    // Removes the record of `path`, if any.
    void forget(const std::string& path) const;

private:
    QString m_directory;
};

} // namespace facet
