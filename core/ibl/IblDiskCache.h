#pragma once
// The on-disk cache of the IBL precompute (render/IblPrecompute.h): binary files of texture
// levels (and a few doubles, e.g. SH coefficients) keyed by a 64-bit hash of what produced them
// (the environment's content hash and the settings' hash). core/ knows nothing about GL: an
// entry is plain arrays.
//
// Location: $FACET_CACHE_DIR if set (tests point it at a temporary directory), else
// QStandardPaths::CacheLocation + "/ibl". File: "<16 hex digits of the key>.fibl".
// Format (little-endian, docs/ibl.md):
//   header  : "FACETIBL" (8 bytes), uint32 version (1), uint64 key, uint32 layer count,
//             uint32 extra count, uint64 payload byte count, uint64 FNV-1a 64 of the payload
//   payload : per layer uint32 width, height, faces, level, format (1 = RGBA half, 2 = RGBA
//             float), then width * height * faces * 4 values; then `extra count` float64.
// Files are written through writeFileAtomically (core/support/AtomicFile.h: a checked temporary file,
// then an atomic rename): a reader never sees a half-written file, and a full disk leaves the
// old entry (or none) rather than an empty one. A file that is truncated, has the wrong
// magic/version/key, or whose checksum does not match is ignored with a warning (the caller
// recomputes and overwrites it).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <QString>

namespace facet {

struct IblCacheLayer {
    enum class Format : std::uint32_t { Half = 1, Float = 2 };
    int width = 0;
    int height = 0;
    int faces = 1; // 6 for a cubemap level (faces in GL order, each width * height RGBA)
    int level = 0; // mip level
    Format format = Format::Half;
    std::vector<std::uint16_t> half; // RGBA half floats (Format::Half)
    std::vector<float> single; // RGBA floats (Format::Float)

    std::size_t valueCount() const
    {
        return std::size_t(width) * std::size_t(height) * std::size_t(faces) * 4;
    }
};

struct IblCacheEntry {
    std::vector<IblCacheLayer> layers;
    std::vector<double> extra;
};

class IblDiskCache {
public:
    static constexpr std::uint32_t kVersion = 1;

    // `directory` empty: defaultDirectory().
    explicit IblDiskCache(QString directory = {});
    static QString defaultDirectory();
    const QString& directory() const { return m_directory; }

    // The key of (environment content hash, settings hash): FNV-1a 64 over both, little-endian.
    static std::uint64_t key(std::uint64_t contentHash, std::uint64_t settingsHash);
    static std::string keyHex(std::uint64_t key);
    QString pathFor(std::uint64_t key) const;

    // Writes atomically; false with "IblDiskCache::store: <path>: <reason>" on failure.
    bool store(std::uint64_t key, const IblCacheEntry& entry, std::string* error) const;
    // nullopt when there is no file (warning left empty) or it is unusable (warning set to
    // "IblDiskCache::load: <path>: <reason>; ignoring it").
    std::optional<IblCacheEntry> load(std::uint64_t key, std::string* warning) const;

private:
    QString m_directory;
};

} // namespace facet
