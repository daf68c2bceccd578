#include <epoxy/gl.h> // before any header that could pull in <GL/gl.h>

#include "render/IblPrecompute.h"

#include "core/ibl/IblDiskCache.h"
#include "core/ibl/Prefilter.h"
#include "core/ibl/SphericalHarmonics.h"
#include "render/GLDebug.h"
#include "render/GLPassScope.h"
#include "render/IblTables.h"
#include "render/ShaderProgram.h"
#include "render/ShippedDfgTables.h"

#include <QtGlobal>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <optional>

namespace facet {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

int mipChainLength(int size)
{
    return std::bit_width(unsigned(std::max(size, 1)));
}

// An RGBA16F cubemap of `levels` levels, level 0 `size` wide; `data` (optional) gives each
// level's 6 faces of half floats, faces in GL order.
std::shared_ptr<GLTexture> makeCubemap(
    int size, int levels, const std::vector<const IblCacheLayer*>& data = {})
{
    auto texture = std::make_shared<GLTexture>(GLTexture::create(GL_TEXTURE_CUBE_MAP));
    glBindTexture(GL_TEXTURE_CUBE_MAP, texture->id());
    for (int level = 0; level < levels; ++level) {
        const int s = std::max(size >> level, 1);
        const IblCacheLayer* layer = std::size_t(level) < data.size() ? data[std::size_t(level)] : nullptr;
        for (int face = 0; face < 6; ++face) {
            const void* pixels = layer
                ? layer->half.data() + std::size_t(face) * std::size_t(s) * std::size_t(s) * 4
                : nullptr;
            glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), level, GL_RGBA16F, s, s, 0, GL_RGBA,
                GL_HALF_FLOAT, pixels);
        }
    }
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, levels - 1);
    glTexParameteri(
        GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        glTexParameteri(GL_TEXTURE_CUBE_MAP, wrap, GL_CLAMP_TO_EDGE);
    return texture;
}

std::shared_ptr<GLTexture> makeDfgTexture(int size, const std::uint16_t* data = nullptr)
{
    auto texture = std::make_shared<GLTexture>(GLTexture::create(GL_TEXTURE_2D));
    glBindTexture(GL_TEXTURE_2D, texture->id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, size, size, 0, GL_RGBA, GL_HALF_FLOAT, data);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return texture;
}

// Every level of a cubemap as cache layers (exact half floats).
void appendCubemapLayers(const GLTexture& texture, int levels, std::vector<IblCacheLayer>& out)
{
    for (int level = 0; level < levels; ++level) {
        IblCacheLayer layer;
        layer.faces = 6;
        layer.level = level;
        for (int face = 0; face < 6; ++face) {
            const std::vector<unsigned short> pixels
                = readTextureLevelHalf(texture, face, level, &layer.width, &layer.height);
            layer.half.insert(layer.half.end(), pixels.begin(), pixels.end());
        }
        out.push_back(std::move(layer));
    }
}

} // namespace

struct IblPrecompute::Programs {
    ShaderProgram equirectToCube;
    ShaderProgram prefilterCopy;
    ShaderProgram prefilter;
    ShaderProgram irradiance;
};

IblPrecompute::IblPrecompute(QString cacheDirectory, bool useDiskCache)
    : m_cacheDirectory(
        cacheDirectory.isEmpty() ? IblDiskCache::defaultDirectory() : std::move(cacheDirectory))
    , m_useDiskCache(useDiskCache)
{
}

IblPrecompute::~IblPrecompute()
{
    m_memory.clear();
    m_sources.clear();
    m_dfg.clear();
    m_programs.reset();
    for (auto& program : m_dfgPrograms)
        program.reset();
}

void IblPrecompute::clearMemoryCache()
{
    m_memory.clear();
    m_sources.clear();
    m_dfg.clear();
}

void IblPrecompute::warn(const std::string& message)
{
    m_lastWarning = message;
    qWarning("%s", message.c_str());
}

bool IblPrecompute::ensurePrograms(std::string* error)
{
    if (m_programs)
        return true;
    auto programs = std::make_unique<Programs>();
    const ShaderStageSource vertex {ShaderStageSource::Stage::Vertex, "ibl_fullscreen.vert"};
    auto make
        = [&](ShaderProgram& out, const char* name, const char* fragment, std::vector<std::string> defines) {
              std::optional<ShaderProgram> program = ShaderProgram::create(
                  name, {vertex, {ShaderStageSource::Stage::Fragment, fragment}}, defines, error);
              if (!program)
                  return false;
              out = std::move(*program);
              return true;
          };
    if (!make(programs->equirectToCube, "iblEquirectToCube", "ibl_equirect_to_cube.frag", {})
        || !make(programs->prefilterCopy, "iblPrefilterCopy", "ibl_prefilter.frag", {"PREFILTER_COPY"})
        || !make(programs->prefilter, "iblPrefilter", "ibl_prefilter.frag", {})
        || !make(programs->irradiance, "iblIrradiance", "ibl_irradiance.frag", {})) {
        if (error)
            *error = "IblPrecompute::prepare: " + *error;
        return false;
    }
    for (ShaderProgram* p :
        {&programs->equirectToCube, &programs->prefilterCopy, &programs->prefilter, &programs->irradiance})
        p->setInt("uEnvironment", 0), p->setInt("uEquirect", 0);
    m_programs = std::move(programs);
    return true;
}

const ShaderProgram* IblPrecompute::dfgProgram(Visibility visibility, std::string* error)
{
    // ibl_dfg.frag's DFG_VISIBILITY values, spelled out so that reordering the enum cannot
    // silently select another term.
    const char* define = "DFG_VISIBILITY 0";
    switch (visibility) {
    case Visibility::SmithGGXCorrelated:
        define = "DFG_VISIBILITY 0";
        break;
    case Visibility::SmithGGXUncorrelated:
        define = "DFG_VISIBILITY 1";
        break;
    case Visibility::SchlickGGX:
        define = "DFG_VISIBILITY 2";
        break;
    }
    std::unique_ptr<ShaderProgram>& slot = m_dfgPrograms[std::size_t(visibility)];
    if (!slot) {
        std::string message;
        std::optional<ShaderProgram> program
            = ShaderProgram::create(std::string("iblDfg-") + toString(visibility),
                {{ShaderStageSource::Stage::Vertex, "ibl_fullscreen.vert"},
                    {ShaderStageSource::Stage::Fragment, "ibl_dfg.frag"}},
                {define}, &message);
        if (!program) {
            if (error)
                *error = "IblPrecompute::dfgTable: " + message;
            return nullptr;
        }
        slot = std::make_unique<ShaderProgram>(std::move(*program));
    }
    return slot.get();
}

namespace {

// Renders one full-viewport triangle into `level` of `face` (-1: a 2D texture) of `texture`.
// `caller` prefixes the error ("IblPrecompute::prepare").
bool drawInto(const GLTexture& texture, int face, int level, int size, std::string* error,
    const char* caller = "IblPrecompute::prepare")
{
    const GLenum target = face < 0 ? GLenum(GL_TEXTURE_2D) : GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, target, texture.id(), level);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        if (error)
            *error = std::string(caller) + ": framebuffer incomplete (status " + std::to_string(status)
                + ") rendering into level " + std::to_string(level);
        return false;
    }
    glViewport(0, 0, size, size);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return true;
}

} // namespace

std::shared_ptr<const DfgLut> IblPrecompute::dfgTable(
    const IblSettings& requested, Visibility visibility, IblStats* stats, std::string* error)
{
    const Clock::time_point start = Clock::now();
    IblStats ignored;
    if (!stats)
        stats = &ignored;
    auto finish = [&](std::shared_ptr<const DfgLut> result) {
        stats->msTotal += msSince(start);
        return result;
    };
    const IblSettings settings = requested.sanitized();
    // One key for memory and disk, and it holds the visibility: a table made for another V is
    // never found under this one.
    const std::uint64_t key = IblDiskCache::key(0, settings.dfgHash(visibility));
    if (const auto it = m_dfg.find(key); it != m_dfg.end())
        return finish(it->second);

    auto lut = std::make_shared<DfgLut>();
    lut->size = settings.dfgSize;
    lut->sampleCount = settings.dfgSamples;
    lut->visibility = visibility;
    GLStateGuard guard;
    if (const ShippedDfgTable* shipped
        = m_useShippedDfgTables ? findShippedDfgTable(settings.dfgHash(visibility)) : nullptr;
        shipped && shipped->size == settings.dfgSize && shipped->samples == settings.dfgSamples
        && shipped->visibility == visibility) {
        lut->texture = makeDfgTexture(settings.dfgSize, shipped->texels);
        ++stats->dfgShipped;
        m_dfg[key] = lut;
        return finish(lut);
    }
    const IblDiskCache disk(m_cacheDirectory);
    if (m_useDiskCache) {
        std::string warning;
        const std::optional<IblCacheEntry> entry = disk.load(key, &warning);
        if (!warning.empty())
            warn(warning);
        if (entry && entry->layers.size() == 1 && entry->layers[0].width == settings.dfgSize
            && entry->layers[0].height == settings.dfgSize && entry->layers[0].faces == 1
            && entry->layers[0].format == IblCacheLayer::Format::Half) {
            lut->texture = makeDfgTexture(settings.dfgSize, entry->layers[0].half.data());
            ++stats->cacheHitsDisk;
            m_dfg[key] = lut;
            return finish(lut);
        }
        if (entry)
            warn("IblDiskCache: " + disk.pathFor(key).toStdString() + ": unexpected layout; ignoring it");
    }

    const ShaderProgram* program = dfgProgram(visibility, error);
    if (!program)
        return nullptr;
    const PassObjects objects;
    while (glGetError() != GL_NO_ERROR) { }
    const Clock::time_point passStart = Clock::now();
    auto texture = makeDfgTexture(settings.dfgSize);
    program->use();
    program->setInt("uSize", settings.dfgSize);
    program->setInt("uSampleCount", settings.dfgSamples);
    if (!drawInto(*texture, -1, 0, settings.dfgSize, error, "IblPrecompute::dfgTable"))
        return nullptr;
    glFinish();
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
    if (const GLenum glError = glGetError(); glError != GL_NO_ERROR) {
        if (error)
            *error = "IblPrecompute::dfgTable: " + glErrorName(glError) + " during the pass";
        return nullptr;
    }
    stats->msDfg += msSince(passStart);
    ++stats->passesRun;
    lut->texture = texture;
    m_dfg[key] = lut;
    if (m_useDiskCache) {
        IblCacheEntry entry;
        IblCacheLayer layer;
        layer.half = readTextureLevelHalf(*texture, 0, 0, &layer.width, &layer.height);
        entry.layers.push_back(std::move(layer));
        std::string storeError;
        if (!disk.store(key, entry, &storeError))
            warn(storeError);
    }
    return finish(lut);
}

bool IblPrecompute::holds(const Environment& environment, const IblSettings& requested) const
{
    if (environment.isEmpty())
        return false;
    const IblSettings settings = requested.forImage(environment.width());
    const std::uint64_t key = IblDiskCache::key(environment.contentHash(), settings.hash());
    return std::any_of(
        m_memory.begin(), m_memory.end(), [key](const auto& entry) { return entry.key == key; });
}

bool IblPrecompute::holdsSource(const Environment& environment) const
{
    if (environment.isEmpty())
        return false;
    const std::uint64_t key = environment.contentHash();
    return std::any_of(
        m_sources.begin(), m_sources.end(), [key](const auto& entry) { return entry.key == key; });
}

std::shared_ptr<const EnvironmentSourceTextures> IblPrecompute::source(
    const Environment& environment, IblStats* stats, std::string* error)
{
    const Clock::time_point start = Clock::now();
    IblStats ignored;
    if (!stats)
        stats = &ignored;
    if (environment.isEmpty()) {
        if (error)
            *error = "IblPrecompute::source: the environment has no image";
        return nullptr;
    }
    const std::uint64_t key = environment.contentHash();
    for (auto it = m_sources.begin(); it != m_sources.end(); ++it) {
        if (it->key == key) {
            m_sources.splice(m_sources.begin(), m_sources, it);
            m_sources.front().lastUse = ++m_useClock;
            ++stats->sourceCacheHitsMemory;
            stats->msTotal += msSince(start);
            return m_sources.front().value;
        }
    }
    GLStateGuard guard;
    std::string warning;
    std::string message;
    std::shared_ptr<const EnvironmentSourceTextures> made
        = EnvironmentSourceTextures::create(environment, &warning, &message);
    if (!made) {
        if (error)
            *error = "IblPrecompute::source: " + message;
        return nullptr;
    }
    if (!warning.empty())
        warn(warning);
    m_sources.push_front({key, made, ++m_useClock});
    trimMemoryCache();
    stats->msSource += msSince(start);
    stats->msTotal += msSince(start);
    return made;
}

std::uint64_t IblPrecompute::cacheKey(const Environment& environment, const IblSettings& requested)
{
    return IblDiskCache::key(environment.contentHash(), requested.forImage(environment.width()).hash());
}

void IblPrecompute::adopt(std::uint64_t key, std::shared_ptr<const IblTextures> textures)
{
    if (!textures)
        return;
    for (auto it = m_memory.begin(); it != m_memory.end(); ++it) {
        if (it->key == key) {
            m_memory.splice(m_memory.begin(), m_memory, it);
            m_memory.front().lastUse = ++m_useClock;
            return;
        }
    }
    m_memory.push_front({key, std::move(textures), ++m_useClock});
    trimMemoryCache();
}

std::shared_ptr<const IblTextures> IblPrecompute::prepare(const Environment& environment,
    const IblSettings& requested, IblStats* statsOut, std::string* error, const IblProgress& progress)
{
    const Clock::time_point start = Clock::now();
    IblStats localStats;
    IblStats* stats = statsOut ? statsOut : &localStats;
    *stats = IblStats {};
    auto finish = [&](std::shared_ptr<const IblTextures> result) {
        stats->msTotal = msSince(start);
        return result;
    };
    if (environment.isEmpty()) {
        if (error)
            *error = "IblPrecompute::prepare: the environment has no image";
        return nullptr;
    }
    const IblSettings settings = requested.forImage(environment.width());
    const std::uint64_t key = cacheKey(environment, requested);

    // 1. Memory.
    for (auto it = m_memory.begin(); it != m_memory.end(); ++it) {
        if (it->key == key) {
            m_memory.splice(m_memory.begin(), m_memory, it);
            m_memory.front().lastUse = ++m_useClock;
            stats->cacheHitsMemory = 1;
            return finish(m_memory.front().value);
        }
    }

    // Progress: the passes' faces weighted by their texels times the samples each reads (the
    // cube pass and the prefilter's copy level as one sample, a prefiltered level as its
    // samples, the irradiance as its table), measured against the default preset's pass times
    // closely enough for a progress bar. `advance` adds a share and asks whether to go on.
    double workDone = 0.0;
    double workTotal = 0.0;
    const auto faceWork = [&](int size, double samples) { return double(size) * double(size) * samples; };
    const auto irradianceWork
        = [&] { return faceWork(settings.irradianceSize, 0.25 * settings.irradianceSamples); };
    if (progress) {
        workTotal += 6.0 * faceWork(settings.cubeSize, 4.0);
        for (int level = 0; level < settings.prefilterMipLevels; ++level)
            workTotal += 6.0
                * faceWork(std::max(settings.prefilterSize >> level, 1),
                    level == 0 ? 1.0 : double(settings.prefilterSamples));
        workTotal += 6.0 * irradianceWork();
    }
    bool cancelled = false;
    const auto advance = [&](double work, bool finishGpu) {
        if (!progress || cancelled)
            return !cancelled;
        if (finishGpu)
            glFinish();
        workDone += work;
        cancelled = !progress(workTotal > 0.0 ? std::min(workDone / workTotal, 1.0) : 1.0);
        if (cancelled) {
            stats->cancelled = true;
            if (error)
                *error = "IblPrecompute::prepare: cancelled";
        }
        return !cancelled;
    };

    GLStateGuard guard;
    const PassObjects objects;
    glActiveTexture(GL_TEXTURE0);
    // Filtering across cube faces (the prefilter reads blurred levels, where the seams would show);
    // global state, which the surface renderer wants too.
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    while (glGetError() != GL_NO_ERROR) { }

    auto result = std::make_shared<IblTextures>();
    result->environmentSize = settings.cubeSize;
    result->environmentMipLevels = mipChainLength(settings.cubeSize);
    result->prefilteredSize = settings.prefilterSize;
    result->prefilteredMipLevels = settings.prefilterMipLevels;
    result->irradianceSize = settings.irradianceSize;

    // 2. Disk.
    const IblDiskCache disk(m_cacheDirectory);
    bool fromDisk = false;
    if (m_useDiskCache) {
        std::string warning;
        const std::optional<IblCacheEntry> entry = disk.load(key, &warning);
        if (!warning.empty())
            warn(warning);
        // Layout: environment levels 0..E-1, prefiltered levels 0..P-1, irradiance; extra = SH (27).
        const int e = result->environmentMipLevels;
        const int p = result->prefilteredMipLevels;
        auto layoutMatches = [&](const IblCacheEntry& c) {
            if (int(c.layers.size()) != e + p + 1 || c.extra.size() != 27)
                return false;
            for (int i = 0; i < e + p + 1; ++i) {
                const IblCacheLayer& l = c.layers[std::size_t(i)];
                const int base = i < e ? settings.cubeSize
                    : i < e + p        ? settings.prefilterSize
                                       : settings.irradianceSize;
                const int level = i < e ? i : i < e + p ? i - e : 0;
                if (l.faces != 6 || l.level != level || l.width != std::max(base >> level, 1)
                    || l.width != l.height || l.format != IblCacheLayer::Format::Half)
                    return false;
            }
            return true;
        };
        if (entry && !layoutMatches(*entry))
            warn("IblDiskCache: " + disk.pathFor(key).toStdString() + ": unexpected layout; ignoring it");
        else if (entry) {
            std::vector<const IblCacheLayer*> envLayers, preLayers;
            for (int i = 0; i < e; ++i)
                envLayers.push_back(&entry->layers[std::size_t(i)]);
            for (int i = 0; i < p; ++i)
                preLayers.push_back(&entry->layers[std::size_t(e + i)]);
            result->environment = makeCubemap(settings.cubeSize, e, envLayers);
            result->prefiltered = makeCubemap(settings.prefilterSize, p, preLayers);
            result->irradiance = makeCubemap(settings.irradianceSize, 1, {&entry->layers.back()});
            for (std::size_t i = 0; i < 9; ++i)
                result->irradianceSH[i] = glm::vec3(float(entry->extra[3 * i]),
                    float(entry->extra[3 * i + 1]), float(entry->extra[3 * i + 2]));
            ++stats->cacheHitsDisk;
            fromDisk = true;
        }
    }

    if (!fromDisk) {
        if (!advance(0.0, false))
            return nullptr;
        // The passes' shaders are compiled only when a pass runs: a cache hit compiles nothing.
        if (!ensurePrograms(error))
            return nullptr;
        // 3a. Equirect -> cubemap, then the mip chain (box filter) for the background and as the
        // filtered source of the convolutions.
        Clock::time_point passStart = Clock::now();
        const Image& image = environment.image();
        // A map wider than the cube needs (about 4 texels of the equirect per cube texel across:
        // the same angle at the equator) is first area-filtered to that width, once: bilinear
        // reads of an 8K map into a 256 cube skip most of its texels (aliasing: a small bright
        // light is caught or missed by where it falls), and a 16K map as RGBA32F is 2 GiB of GL
        // memory (GL_OUT_OF_MEMORY on llvmpipe).
        const int neededWidth = 4 * settings.cubeSize;
        const bool reduce = image.width() > neededWidth;
        std::optional<Image> reduced;
        if (reduce) {
            const int height
                = std::max(1, int(std::lround(double(neededWidth) * image.height() / image.width())));
            reduced = image.boxFiltered(neededWidth, height);
            ++stats->sourceReductions;
        }
        const Image& source = reduce ? *reduced : image;
        // The source radiance of source(), when it is in memory at full resolution, is this very
        // texture (RGB32F instead of RGBA32F: the pass reads .rgb, with the same filtering and
        // wrapping), so it is not uploaded twice. Otherwise upload the image for this pass only.
        const std::shared_ptr<const EnvironmentSourceTextures> held
            = reduce ? nullptr : heldSource(environment.contentHash());
        GLTexture equirect;
        GLuint equirectId = 0;
        if (held && !held->downsampled()) {
            equirectId = held->radiance.id();
            ++stats->sourceCacheHitsMemory;
        } else {
            equirect = GLTexture::create(GL_TEXTURE_2D);
            equirectId = equirect.id();
            glBindTexture(GL_TEXTURE_2D, equirectId);
            // Rows top first, as Image stores them: t = 0 is the image's top row (common_equirect.glsl).
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, source.width(), source.height(), 0, GL_RGBA, GL_FLOAT,
                source.data());
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        }
        auto cube = makeCubemap(settings.cubeSize, result->environmentMipLevels);
        m_programs->equirectToCube.use();
        glBindTexture(GL_TEXTURE_2D, equirectId);
        for (int face = 0; face < 6; ++face) {
            m_programs->equirectToCube.setInt("uFace", face);
            if (!drawInto(*cube, face, 0, settings.cubeSize, error)
                || !advance(faceWork(settings.cubeSize, 4.0), true))
                return nullptr;
        }
        glBindTexture(GL_TEXTURE_CUBE_MAP, cube->id());
        glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
        glFinish();
        stats->msEquirectToCube = msSince(passStart);
        ++stats->passesRun;
        result->environment = cube;

        // 3b. Prefiltered specular: level 0 copies the environment, level i convolves with GGX
        // of roughness i / (levels - 1) by filtered importance sampling.
        passStart = Clock::now();
        auto prefiltered = makeCubemap(settings.prefilterSize, settings.prefilterMipLevels);
        glBindTexture(GL_TEXTURE_CUBE_MAP, cube->id());
        const double sourceMaxLod = double(result->environmentMipLevels - 1);
        for (int level = 0; level < settings.prefilterMipLevels; ++level) {
            const int size = std::max(settings.prefilterSize >> level, 1);
            const ShaderProgram& program = level == 0 ? m_programs->prefilterCopy : m_programs->prefilter;
            program.use();
            GLTexture samples;
            std::optional<TableBinding> bound;
            if (level == 0) {
                program.setFloat("uCopyLod",
                    float(std::max(
                        0.0, std::log2(double(settings.cubeSize) / double(settings.prefilterSize)))));
            } else {
                int count = 0;
                double inverseWeight = 0.0;
                samples = prefilterSampleTable(roughnessFromLod(level, settings.prefilterMipLevels),
                    settings.prefilterSamples, double(settings.cubeSize), sourceMaxLod, &count,
                    &inverseWeight);
                bound.emplace(samples);
                program.setInt("uSamples", TableBinding::kUnit);
                program.setInt("uCount", count);
                program.setFloat("uInverseWeight", float(inverseWeight));
            }
            for (int face = 0; face < 6; ++face) {
                program.setInt("uFace", face);
                if (!drawInto(*prefiltered, face, level, size, error)
                    || !advance(faceWork(size, level == 0 ? 1.0 : double(settings.prefilterSamples)), true))
                    return nullptr;
            }
        }
        glFinish();
        stats->msPrefilter = msSince(passStart);
        ++stats->passesRun;
        result->prefiltered = prefiltered;

        // 3c. Irradiance E(n): a quadrature over every texel of a small level of the cube.
        passStart = Clock::now();
        auto irradiance = makeCubemap(settings.irradianceSize, 1);
        glBindTexture(GL_TEXTURE_CUBE_MAP, cube->id());
        // Source level: the largest whose 6 s^2 texels are at most irradianceSamples (at least
        // 1x1), never finer than the cube's level 0.
        int sourceLevel = 0;
        while (sourceLevel + 1 < result->environmentMipLevels
            && 6LL * (settings.cubeSize >> sourceLevel) * (settings.cubeSize >> sourceLevel)
                > settings.irradianceSamples)
            ++sourceLevel;
        const GLTexture texels
            = irradianceTexelTable(*cube, std::max(settings.cubeSize >> sourceLevel, 1), sourceLevel);
        if (!texels.id()) {
            if (error)
                *error = "IblPrecompute::prepare: " + environment.name()
                    + ": the environment cube could not be read back for the irradiance";
            return nullptr;
        }
        {
            const TableBinding bound(texels);
            m_programs->irradiance.use();
            m_programs->irradiance.setInt("uTexels", TableBinding::kUnit);
            m_programs->irradiance.setInt(
                "uCount", 6 * (settings.cubeSize >> sourceLevel) * (settings.cubeSize >> sourceLevel));
            for (int face = 0; face < 6; ++face) {
                m_programs->irradiance.setInt("uFace", face);
                if (!drawInto(*irradiance, face, 0, settings.irradianceSize, error)
                    || !advance(irradianceWork(), true))
                    return nullptr;
            }
            glFinish();
        }
        stats->msIrradiance = msSince(passStart);
        ++stats->passesRun;
        result->irradiance = irradiance;

        // 3d. SH9 on the CPU, in the image frame at intensity 1 (rotation and intensity are
        // applied at shading time, like every other IBL texture).
        passStart = Clock::now();
        // From the area-filtered map when there is one: SH9 keeps only the lowest frequencies,
        // which the filter keeps (an 8K map's projection took 5.6 s, its 1K copy's 0.1 s).
        Environment imageFrame = reduce ? Environment(std::move(*reduced), environment.name()) : environment;
        imageFrame.setRotationDegrees(0.0);
        imageFrame.setIntensity(1.0);
        const IrradianceSH9 sh = irradianceSHCoefficients(projectEquirect(imageFrame));
        for (std::size_t i = 0; i < 9; ++i)
            result->irradianceSH[i] = glm::vec3(sh.c[i]);
        stats->msSh = msSince(passStart);

        if (const GLenum glError = glGetError(); glError != GL_NO_ERROR) {
            if (error)
                *error = "IblPrecompute::prepare: " + environment.name() + ": " + glErrorName(glError)
                    + " during the passes";
            return nullptr;
        }
        if (m_useDiskCache) {
            IblCacheEntry entry;
            appendCubemapLayers(*result->environment, result->environmentMipLevels, entry.layers);
            appendCubemapLayers(*result->prefiltered, result->prefilteredMipLevels, entry.layers);
            appendCubemapLayers(*result->irradiance, 1, entry.layers);
            for (const glm::dvec3& c : sh.c)
                entry.extra.insert(entry.extra.end(), {c.x, c.y, c.z});
            std::string storeError;
            if (!disk.store(key, entry, &storeError))
                warn(storeError);
        }
    }
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);

    m_memory.push_front({key, result, ++m_useClock});
    trimMemoryCache();
    return finish(result);
}

std::shared_ptr<const EnvironmentSourceTextures> IblPrecompute::heldSource(std::uint64_t contentHash) const
{
    for (const auto& entry : m_sources)
        if (entry.key == contentHash)
            return entry.value;
    return nullptr;
}

std::size_t IblPrecompute::memoryBytes() const
{
    std::size_t total = 0;
    for (const auto& entry : m_memory)
        total += entry.value->bytes();
    for (const auto& entry : m_sources)
        total += entry.value->bytes();
    return total;
}

void IblPrecompute::setMemoryBudget(std::size_t bytes)
{
    m_memoryBudget = bytes;
    trimMemoryCache();
}

void IblPrecompute::trimMemoryCache()
{
    // Least recently used out first, from whichever list holds it (each list is in use order);
    // the newest entry stays even when it alone is over budget.
    while (m_memory.size() + m_sources.size() > 1 && memoryBytes() > m_memoryBudget) {
        if (m_sources.empty() || (!m_memory.empty() && m_memory.back().lastUse < m_sources.back().lastUse))
            m_memory.pop_back();
        else
            m_sources.pop_back();
    }
}

} // namespace facet
