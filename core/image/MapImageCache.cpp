#include "core/image/MapImageCache.h"

#include "core/gltf/GltfImport.h"

#include <chrono>
#include <filesystem>
#include <system_error>

namespace facet {

MapImageCache& MapImageCache::shared()
{
    static MapImageCache cache;
    return cache;
}

MapImageCache::FileIdentity MapImageCache::identify(const std::string& path)
{
    // An embedded image ("asset.glb#images/2") changes with its asset file.
    const std::string file = fileOfImagePath(path);
    std::error_code ec;
    FileIdentity identity;
    const auto modified = std::filesystem::last_write_time(file, ec);
    if (ec)
        return identity;
    const std::uintmax_t size = std::filesystem::file_size(file, ec);
    identity.modified
        = std::chrono::duration_cast<std::chrono::nanoseconds>(modified.time_since_epoch()).count();
    identity.size = ec ? 0 : size;
    identity.exists = true;
    return identity;
}

std::shared_ptr<const MapImage> MapImageCache::load(
    const std::string& path, std::string* error, ImageLoadStats* stats, const MapBudget& budget)
{
    const FileIdentity identity = identify(path);
    const auto fits = [&budget](const std::shared_ptr<const MapImage>& image) {
        return budget.check(image->width(), image->height()).empty();
    };
    std::unique_lock lock(m_mutex);
    Entry& entry = m_entries[path];
    // One decode of a path at a time. Someone decoding this very file: take that decode's
    // outcome. Decoding an older version of it: wait, then decode this one.
    while (entry.decoding) {
        const std::uint64_t generation = entry.generation;
        if (entry.identity == identity && identity.exists) {
            ++entry.waiters;
            m_decoded.wait(lock, [&] { return entry.generation != generation; });
            // The decoder's result, held for the waiters (its own caller may have dropped it).
            std::shared_ptr<const MapImage> image = entry.handoff;
            if (--entry.waiters == 0)
                entry.handoff.reset();
            if (!image) {
                if (error)
                    *error = entry.error;
                return nullptr;
            }
            if (fits(image)) {
                if (stats)
                    *stats = entry.stats;
                return image;
            }
            break; // decoded under a larger budget: decoded (and refused) again below
        }
        m_decoded.wait(lock, [&] { return entry.generation != generation; });
    }
    if (!entry.decoding && identity.exists && entry.identity == identity) {
        if (std::shared_ptr<const MapImage> image = entry.image.lock(); image && fits(image)) {
            if (stats)
                *stats = entry.stats;
            return image;
        }
    }
    while (entry.decoding) // (after the budget case above another decode may have started)
        m_decoded.wait(lock, [&] { return !entry.decoding; });

    entry.decoding = true;
    entry.identity = identity;
    ++entry.decodes;
    ++m_decodes;
    lock.unlock();

    std::string problem;
    ImageLoadStats replaced;
    std::shared_ptr<const MapImage> image;
    try {
        if (std::optional<MapImage> loaded = MapImage::load(path, &problem, &replaced, budget))
            image = std::make_shared<const MapImage>(std::move(*loaded));
    } catch (...) {
        // MapImage::load catches its own; only an allocation of the shared copy can get here.
        problem = "MapImageCache::load: " + path + ": out of memory";
    }

    lock.lock();
    entry.decoding = false;
    ++entry.generation;
    entry.image = image;
    if (entry.waiters > 0)
        entry.handoff = image;
    entry.stats = replaced;
    entry.error = image ? std::string() : problem;
    lock.unlock();
    m_decoded.notify_all();

    if (!image && error)
        *error = problem;
    if (stats)
        *stats = replaced;
    return image;
}

std::uint64_t MapImageCache::decodeCount(const std::string& path) const
{
    std::lock_guard lock(m_mutex);
    const auto found = m_entries.find(path);
    return found == m_entries.end() ? 0 : found->second.decodes;
}

bool MapImageCache::isHeld(const std::string& path) const
{
    std::lock_guard lock(m_mutex);
    const auto found = m_entries.find(path);
    return found != m_entries.end() && !found->second.image.expired();
}

std::uint64_t MapImageCache::decodeCount() const
{
    std::lock_guard lock(m_mutex);
    return m_decodes;
}

} // namespace facet
