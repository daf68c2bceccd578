#pragma once
// A disk cache of ground-truth images (core/shading/GroundTruth.h) for `facet bench`: a 64 x 64 image at
// 1024 samples per pixel costs seconds, and a benchmark compares the same few dozen of them with
// every quality setting, run after run. Keyed by everything the image depends on (the
// environment's content hash, rotation and intensity, the material, the shading model and the
// integrator's settings), so a changed input is a miss, never a stale image.
//
// Files: <directory>/<40 hex of SHA-1 of the key text>.fgt, written with writeFileAtomically
// (core/support/AtomicFile.h):
//   "FACETGT1", uint32 version, uint32 width, uint32 height, uint32 key-text length, key text,
//   width x height x RGBA float32, all little-endian (QDataStream).
// A file whose header or key text does not match is ignored (with a warning) and overwritten.

#include <optional>
#include <string>

#include <QString>

#include "core/image/Image.h"
#include "core/shading/GroundTruth.h"

namespace facet {

class GroundTruthCache {
public:
    // Bumped when the integrator (core/shading/GroundTruth.cpp) changes what it computes, so that old
    // files stop matching.
    static constexpr int kIntegratorVersion = 1;

    // `directory` empty: defaultDirectory().
    explicit GroundTruthCache(QString directory = {});

    // $FACET_CACHE_DIR/ground-truth, else QStandardPaths::CacheLocation + "/ground-truth" (next to
    // the IBL cache of core/ibl/IblDiskCache).
    static QString defaultDirectory();

    // The text every cached image is keyed by (one line per input; thread count excluded: the
    // integrator's result does not depend on it). Empty for a scene with punctual lights, which
    // this cache does not key (the benchmark has none): such a scene is never cached.
    static std::string keyText(const GroundTruthScene& scene, const GroundTruthSettings& settings);

    // The cached image for the scene and settings, or nullopt (a miss, or an unreadable or
    // mismatching file, which sets `warning` to "GroundTruthCache::load: <path>: <reason>").
    std::optional<Image> load(
        const GroundTruthScene& scene, const GroundTruthSettings& settings, std::string* warning) const;
    // False with `error` ("GroundTruthCache::store: <path>: <reason>") when it cannot write.
    bool store(const GroundTruthScene& scene, const GroundTruthSettings& settings, const Image& image,
        std::string* error) const;

    const QString& directory() const { return m_directory; }
    QString pathFor(const std::string& keyText) const;

private:
    QString m_directory;
};

} // namespace facet
