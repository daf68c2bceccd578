#pragma once
// Decode each map file once (docs/architecture.md: "a document owns an asset cache ... shared by
// slots, thumbnails and views"): every reader of a material map (core/project/ProjectAssets for
// `facet render`, the window's SceneController, the Texture Maps dock's thumbnails) asks here.
// A file already in memory, unchanged on disk (same modification time and size), is not decoded
// again; two threads asking for one file at once wait for one decode. Entries are weak: the
// memory goes with the last user of the image, and nothing is kept that no one shows.
//
// Thread-safe. One process-wide instance (shared()); tests may make their own.

#include <condition_variable>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "core/image/MapImage.h"

namespace facet {

class MapImageCache {
public:
    MapImageCache() = default;
    MapImageCache(const MapImageCache&) = delete;
    MapImageCache& operator=(const MapImageCache&) = delete;

    static MapImageCache& shared();

    // The map at `path` (a file or an embedded glTF image, as MapImage::load takes), decoded by
    // MapImage::load when no live copy of the unchanged file exists. Null with *error (the
    // loader's message) on failure; `stats` gets what the decode sanitised (also for a copy).
    std::shared_ptr<const MapImage> load(const std::string& path, std::string* error,
        ImageLoadStats* stats = nullptr, const MapBudget& budget = MapBudget::fromEnvironment());

    // Decodes run so far, of `path` or of every file (tests: "decoded once").
    std::uint64_t decodeCount(const std::string& path) const;
    // Whether someone still holds the decoded copy of `path` (tests: memory freed).
    bool isHeld(const std::string& path) const;
    std::uint64_t decodeCount() const;

private:
    // What identifies a file's content without reading it.
    struct FileIdentity {
        std::int64_t modified = 0; // nanoseconds, filesystem clock
        std::uintmax_t size = 0;
        bool exists = false;
        bool operator==(const FileIdentity&) const = default;
    };
    static FileIdentity identify(const std::string& path);

    struct Entry {
        FileIdentity identity;
        std::weak_ptr<const MapImage> image;
        ImageLoadStats stats;
        bool decoding = false;
        std::uint64_t generation = 0; // bumped when a decode ends
        std::string error; // of the last decode, for those who waited on it
        int waiters = 0; // threads waiting for the decode under way
        std::shared_ptr<const MapImage> handoff; // its result, until the last waiter took it
        std::uint64_t decodes = 0;
    };

    mutable std::mutex m_mutex;
    std::condition_variable m_decoded;
    std::map<std::string, Entry> m_entries; // by path; nodes are stable
    std::uint64_t m_decodes = 0;
};

} // namespace facet
