#pragma once
// The image-based-lighting precompute on the GPU (OpenGL 4.1 core, fragment-shader passes that
// render into cubemap faces and mip levels; no compute shaders). For an environment and
// IblSettings, prepare() produces IblTextures: the environment cubemap, the prefiltered specular
// cubemap, the irradiance cubemap and the SH9 irradiance coefficients. For IblSettings and a
// visibility term V, dfgTable() produces the split-sum DFG LUT integrated with that V (a frame
// needs one per V its materials use: render/RenderScene.h EnvironmentLighting).
// docs/ibl.md has each pass's equations, the layouts, the cache and measured numbers; the CPU
// twins are core/ibl/Prefilter.h, core/ibl/Irradiance.h, core/shading/DfgTable.h,
// core/ibl/SphericalHarmonics.h.
//
// Everything is computed in the environment image's frame at intensity 1: rotation and intensity
// are applied by the renderer at shading time, so changing them reruns nothing.
//
// Caching by content: results are keyed by (Environment::contentHash(), IblSettings::hash()),
// kept in memory (least recently used first out, within kMemoryBudgetBytes of GPU memory) and on disk
// (core/ibl/IblDiskCache, $FACET_CACHE_DIR or QStandardPaths::CacheLocation/ibl). A DFG LUT is keyed by
// IblSettings::dfgHash(visibility) (its size, samples and V; no environment), in memory for the object's life
// and on disk.
//
// Threading and lifetime: every call needs a GL context of one share group current (the views of
// a window share one IblPrecompute, each calling it in its own context: it keeps only shareable
// objects, textures and programs); destroy the IblPrecompute and drop every IblTextures with a
// context of that group current.

#include "core/ibl/Environment.h"
#include "core/shading/ShadingModel.h"
#include "render/DfgLut.h"
#include "render/EnvironmentSource.h"
#include "render/IblSettings.h"
#include "render/IblTextures.h"

#include <QString>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <list>
#include <map>
#include <memory>
#include <string>

namespace facet {

// What one prepare() call, and the dfgTable() calls after it, did: prepare() resets it, dfgTable()
// adds to it, so one IblStats describes an environment and the tables of its frame. Times in
// milliseconds, measured with glFinish() before reading the clock at the end of each pass (GPU
// work is asynchronous: without it a pass would look free and the next one would pay for it). A
// pass skipped thanks to a cache counts 0 ms.
struct IblStats {
    int passesRun = 0; // equirect->cube, prefilter, irradiance (0..3), + 1 per DFG LUT made
    int cacheHitsMemory = 0; // 1 when the environment's textures came from the memory cache
    int cacheHitsDisk = 0; // environment entry (0..1) + DFG LUTs loaded from disk
    int dfgShipped = 0; // DFG LUTs uploaded from the tables shipped as data (render/ShippedDfgTables.h)
    double msEquirectToCube = 0.0; // (area filter +) upload + resample + mip generation
    // 1 when the equirect was area-filtered to 4x the cube's width before the cube pass (a map
    // wider than the cube needs).
    int sourceReductions = 0;
    double msPrefilter = 0.0;
    double msIrradiance = 0.0;
    double msDfg = 0.0; // every DFG LUT made
    double msSh = 0.0; // SH9 projection on the CPU
    double msTotal = 0.0; // the whole calls, including cache look-ups and disk I/O
    // source(), which adds to these like dfgTable(): its memory-cache hits, and the time spent
    // making source textures (tables on the CPU + uploads; 0 on a hit).
    int sourceCacheHitsMemory = 0;
    double msSource = 0.0;
    // prepare() stopped because its progress callback said so (IblProgress): no result, no error
    // worth showing.
    bool cancelled = false;
};

// Where a prepare() stands, and a way to stop it (the window's lighting worker,
// ui/viewport/LightingWorker.h): called with the fraction done, from 0 to 1, after the disk look-up and
// as each face of the passes is finished on the GPU (the passes glFinish per level while a
// callback is set, so the fraction is work done, not work queued). Returning false stops the
// precompute before its next face: prepare() returns null with IblStats::cancelled and the
// error "IblPrecompute::prepare: cancelled"; nothing is cached.
using IblProgress = std::function<bool(double fraction)>;

class ShaderProgram;

class IblPrecompute {
public:
    // The memory cache's bound: the IBL sets least recently prepared are dropped (their textures
    // go when no scene holds them) once the cached sets take more GPU memory than this. 256 MiB
    // hold 12 sets of the high preset (~21 MB each) or 48 of the default (~5.3 MB): a 3x3
    // environment grid at high quality (189 MB) stays resident, so orbiting it prepares nothing.
    static constexpr std::size_t kMemoryBudgetBytes = std::size_t(256) << 20;

    // `cacheDirectory` empty: IblDiskCache::defaultDirectory(). `useDiskCache` false: memory only.
    explicit IblPrecompute(QString cacheDirectory = {}, bool useDiskCache = true);
    IblPrecompute(const IblPrecompute&) = delete;
    IblPrecompute& operator=(const IblPrecompute&) = delete;
    ~IblPrecompute(); // needs the context current

    // Needs a current GL 4.1 core context. Returns the cached result when there is one. On
    // failure returns null and sets `error` to "IblPrecompute::prepare: <problem>" (an empty
    // environment, a shader that does not compile, an incomplete framebuffer, a GL error).
    // `stats` (optional) is reset and filled.
    // `progress` (optional) is told how far it got and may stop it (IblProgress).
    std::shared_ptr<const IblTextures> prepare(const Environment& environment, const IblSettings& settings,
        IblStats* stats, std::string* error, const IblProgress& progress = {});

    // The key prepare() caches `environment` at `settings` under (the content hash and the
    // settings it would run, IblSettings::forImage).
    static std::uint64_t cacheKey(const Environment& environment, const IblSettings& settings);
    // Puts a set another IblPrecompute made (in a context of this one's share group: the
    // window's lighting worker) into the memory cache under `key` (cacheKey()), as if prepare()
    // had made it; a set already held under the key stays. holds() then says yes and prepare()
    // returns it.
    void adopt(std::uint64_t key, std::shared_ptr<const IblTextures> textures);

    // The split-sum DFG LUT of `settings` (dfgSize, dfgSamples) integrated with `visibility`
    // (ibl_dfg.frag with DFG_VISIBILITY; CPU twin DfgTable::compute(size, samples, visibility)).
    // The variant is an argument, not a default, like Filament's CubemapIBL::DFG(js, dst,
    // multiscatter, cloth), and part of the key (IblSettings::dfgHash), so a material is never
    // shaded with another V's table. Needs a current GL 4.1 core context only when the table is
    // in no cache. Returns the cached table when there is one; the `default` preset's tables are
    // shipped as data (render/ShippedDfgTables.h) and uploaded from it, with no pass and no disk
    // entry, unless setUseShippedDfgTables(false). On failure returns null and sets `error` to
    // "IblPrecompute::dfgTable: <problem>". `stats` (optional) is ADDED to, not reset.
    std::shared_ptr<const DfgLut> dfgTable(
        const IblSettings& settings, Visibility visibility, IblStats* stats, std::string* error);
    // Whether dfgTable() takes a shipped table where one is (true by default): off, it makes every
    // table as for any other settings (the tests compare the two).
    void setUseShippedDfgTables(bool use) { m_useShippedDfgTables = use; }

    // The environment at source resolution and its luminance sampling tables
    // (render/EnvironmentSource.h), for lighting that samples the image itself. Needs a current GL
    // 4.1 core context unless it is a memory hit. Cached in memory only (the tables take a few ms
    // per megapixel to build, less than reading them back), by Environment::contentHash(): rotation
    // and intensity are applied at shading time. Counted in the same memory budget as the IBL sets.
    // An image above EnvironmentSourceTextures' limits is box-filtered down, with a warning
    // (lastWarning()). On failure returns null and sets `error` to
    // "IblPrecompute::source: <problem>". `stats` (optional) is ADDED to (msSource,
    // sourceCacheHitsMemory, msTotal).
    std::shared_ptr<const EnvironmentSourceTextures> source(
        const Environment& environment, IblStats* stats, std::string* error);
    // Whether the passes' shaders have been compiled: only when a pass runs (a cache hit compiles
    // nothing).
    bool compiledPasses() const { return m_programs != nullptr; }
    // Whether source(environment) would be a memory hit.
    bool holdsSource(const Environment& environment) const;

    // Drops the in-memory results (the disk cache stays): the next prepare() reads the disk.
    void clearMemoryCache();
    // The memory cache: how many IBL sets it holds, how many environment sources, and the GPU
    // bytes of both (IblTextures::bytes() + EnvironmentSourceTextures::bytes()).
    std::size_t memoryEntries() const { return m_memory.size(); }
    std::size_t sourceEntries() const { return m_sources.size(); }
    // Whether prepare(environment, settings) would be a memory hit (no GL work, no disk read):
    // a view can then draw at once instead of announcing a precompute.
    bool holds(const Environment& environment, const IblSettings& settings) const;
    std::size_t memoryBytes() const;
    // The bound the memory cache keeps to (kMemoryBudgetBytes unless set; tests set small ones).
    // Entries go least recently used first, IBL sets and sources alike; the one just prepared or
    // made always stays, whatever its size.
    void setMemoryBudget(std::size_t bytes);
    // The last warning (e.g. a corrupt disk-cache file that was ignored); also sent to qWarning().
    const std::string& lastWarning() const { return m_lastWarning; }
    const QString& cacheDirectory() const { return m_cacheDirectory; }

private:
    struct Programs;
    bool ensurePrograms(std::string* error);
    // The DFG program for `visibility`, compiled on first use (a disk hit compiles nothing).
    const ShaderProgram* dfgProgram(Visibility visibility, std::string* error);
    void warn(const std::string& message);
    // The source textures in memory for an environment's content hash, without touching their use order.
    std::shared_ptr<const EnvironmentSourceTextures> heldSource(std::uint64_t contentHash) const;

    QString m_cacheDirectory;
    bool m_useDiskCache = true;
    bool m_useShippedDfgTables = true;
    std::unique_ptr<Programs> m_programs;
    std::array<std::unique_ptr<ShaderProgram>, kVisibilityCount> m_dfgPrograms; // by int(Visibility)
    void trimMemoryCache();

    // Cache entries, most recent first, each with the value of m_useClock at its last use (for
    // least-recently-used order across the two lists).
    template <typename T> struct MemoryEntry {
        std::uint64_t key = 0;
        std::shared_ptr<const T> value;
        std::uint64_t lastUse = 0;
    };
    std::list<MemoryEntry<IblTextures>> m_memory; // by IblDiskCache::key(contentHash, settings.hash())
    std::list<MemoryEntry<EnvironmentSourceTextures>> m_sources; // by Environment::contentHash()
    std::uint64_t m_useClock = 0;
    std::size_t m_memoryBudget = kMemoryBudgetBytes;
    std::map<std::uint64_t, std::shared_ptr<const DfgLut>> m_dfg; // by IblDiskCache::key(0, dfgHash(V))
    std::string m_lastWarning;
};

} // namespace facet
