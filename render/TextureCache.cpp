#include <epoxy/gl.h>

#include "render/TextureCache.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <vector>

#include "render/GLInfo.h"
#include "render/MipChain.h"
#include "render/TextureFiltering.h"

namespace facet {

namespace {

// Rows per glTexSubImage2D: about 1 MiB, so a slice's time budget is kept to within a few ms.
constexpr std::size_t kBandBytes = std::size_t(1) << 20;

constexpr std::array<int, 4> kIdentity {GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA};
constexpr std::array<int, 4> kGrey {GL_RED, GL_RED, GL_RED, GL_ONE};
constexpr std::array<int, 4> kGreyAlpha {GL_RED, GL_RED, GL_RED, GL_GREEN};
constexpr std::array<int, 4> kRedGreen {GL_RED, GL_GREEN, GL_ZERO, GL_ONE};

std::array<int, 4> swizzleOf(MapLayout layout)
{
    switch (layout) {
    case MapLayout::Grey:
        return kGrey;
    case MapLayout::GreyAlpha:
        return kGreyAlpha;
    case MapLayout::RedGreen:
        return kRedGreen;
    case MapLayout::Rgb:
    case MapLayout::Rgba:
        break;
    }
    return kIdentity;
}

// Saves and restores what an upload changes: the active unit's 2D binding (uploading a texture
// must never unbind another one: a renderer binding map i - 1 and then uploading map i must find
// map i - 1 still bound) and the unpack state.
class UploadState {
public:
    UploadState()
    {
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &m_texture);
        glGetIntegerv(GL_UNPACK_ALIGNMENT, &m_alignment);
        glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &m_unpackBuffer);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1); // RGB8 rows of any width are not 4-aligned
        glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    }
    ~UploadState()
    {
        glBindTexture(GL_TEXTURE_2D, GLuint(m_texture));
        glPixelStorei(GL_UNPACK_ALIGNMENT, m_alignment);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, GLuint(m_unpackBuffer));
    }
    UploadState(const UploadState&) = delete;
    UploadState& operator=(const UploadState&) = delete;

private:
    GLint m_texture = 0;
    GLint m_alignment = 4;
    GLint m_unpackBuffer = 0;
};

double millisecondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

MapTextureFormat MapTextureFormat::of(MapLayout layout, MapSampleType type, ColorEncoding colorSpace)
{
    MapTextureFormat f;
    const int channels = channelCount(layout);
    static constexpr std::array<GLenum, 4> kFormats {GL_RED, GL_RG, GL_RGB, GL_RGBA};
    f.format = kFormats[std::size_t(channels - 1)];
    f.uploadChannels = channels;
    f.swizzle = swizzleOf(layout);
    const bool srgb = colorSpace == ColorEncoding::SRGB;
    if (type == MapSampleType::UInt8) {
        f.type = GL_UNSIGNED_BYTE;
        f.uploadBytesPerSample = 1;
        if (srgb) {
            // The sampler decodes sRGB before filtering (GL_SRGB8, GL_SRGB8_ALPHA8); there is no
            // 1- or 2-channel sRGB format in core OpenGL, so those expand to RGB(A).
            const bool alpha = layout == MapLayout::GreyAlpha || layout == MapLayout::Rgba;
            f.internalFormat = alpha ? GL_SRGB8_ALPHA8 : GL_SRGB8;
            f.name = alpha ? "GL_SRGB8_ALPHA8" : "GL_SRGB8";
            f.format = alpha ? GL_RGBA : GL_RGB;
            f.uploadChannels = alpha ? 4 : 3;
            f.swizzle = kIdentity;
            f.mipFilter = MipFilter::Srgb8;
            if (layout != MapLayout::Rgb && layout != MapLayout::Rgba)
                f.conversion = Conversion::ExpandToRgb;
            return f;
        }
        static constexpr std::array<GLenum, 4> kInternal {GL_R8, GL_RG8, GL_RGB8, GL_RGBA8};
        static constexpr std::array<const char*, 4> kNames {"GL_R8", "GL_RG8", "GL_RGB8", "GL_RGBA8"};
        f.internalFormat = kInternal[std::size_t(channels - 1)];
        f.name = kNames[std::size_t(channels - 1)];
        return f;
    }
    if (type == MapSampleType::UInt16 && !srgb) {
        static constexpr std::array<GLenum, 4> kInternal {GL_R16, GL_RG16, GL_RGB16, GL_RGBA16};
        static constexpr std::array<const char*, 4> kNames {"GL_R16", "GL_RG16", "GL_RGB16", "GL_RGBA16"};
        f.internalFormat = kInternal[std::size_t(channels - 1)];
        f.name = kNames[std::size_t(channels - 1)];
        f.type = GL_UNSIGNED_SHORT;
        f.uploadBytesPerSample = 2;
        f.mipFilter = MipFilter::Unorm16;
        return f;
    }
    // Half floats: float files as they are, 16-bit and float files read as sRGB decoded to linear.
    static constexpr std::array<GLenum, 4> kInternal {GL_R16F, GL_RG16F, GL_RGB16F, GL_RGBA16F};
    static constexpr std::array<const char*, 4> kNames {"GL_R16F", "GL_RG16F", "GL_RGB16F", "GL_RGBA16F"};
    f.internalFormat = kInternal[std::size_t(channels - 1)];
    f.name = kNames[std::size_t(channels - 1)];
    f.type = GL_HALF_FLOAT;
    f.uploadBytesPerSample = 2;
    f.mipFilter = MipFilter::Half;
    if (srgb)
        f.conversion = Conversion::SrgbToLinearHalf;
    return f;
}

TextureCache::TextureCache()
{
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    m_maxTextureSize = maxSize;
    const GLInfo info = queryCurrentGLInfo();
    m_maxSupportedAnisotropy = info.maxAnisotropy;
    m_textureStorage = info.atLeast(4, 2) || epoxy_has_gl_extension("GL_ARB_texture_storage");
    m_anisotropy = std::clamp(TextureFiltering::anisotropyFor(info, false), 1.0f, m_maxSupportedAnisotropy);
    m_trilinear = TextureFiltering::trilinear(info);
}

TextureCache::~TextureCache()
{
    clear();
}

void TextureCache::clear()
{
    for (auto& [key, entry] : m_textures)
        if (entry.texture)
            glDeleteTextures(1, &entry.texture);
    m_textures.clear();
    m_queue.clear();
    for (const auto& [key, sampler] : m_samplers)
        glDeleteSamplers(1, &sampler.first);
    m_samplers.clear();
}

TextureCache::Key TextureCache::keyFor(const std::shared_ptr<const MapImage>& image, const std::string& path,
    std::int64_t timestamp, ColorEncoding colorSpace)
{
    std::string name = path;
    if (name.empty()) {
        char address[64];
        std::snprintf(address, sizeof address, "<image %p>", static_cast<const void*>(image.get()));
        name = address;
    }
    return Key {name, timestamp, int(colorSpace)};
}

bool TextureCache::fits(const MapImage& image, const std::string& path)
{
    if (m_maxTextureSize > 0 && (image.width() > m_maxTextureSize || image.height() > m_maxTextureSize)) {
        m_problem = "TextureCache: " + path + ": " + std::to_string(image.width()) + "x"
            + std::to_string(image.height()) + " is larger than this OpenGL's largest texture ("
            + std::to_string(m_maxTextureSize) + " pixels per side)";
        return false;
    }
    return true;
}

bool TextureCache::hasPixels(const MapImage& image, const std::string& path)
{
    if (image.hasPixels())
        return true;
    m_problem = "TextureCache: " + path + ": the decoded map was released once on the GPU; it must be loaded again";
    return false;
}

TextureCache::Entry& TextureCache::begin(
    const Key& key, const std::shared_ptr<const MapImage>& image, ColorEncoding colorSpace)
{
    Entry& entry = m_textures[key];
    entry.image = image;
    entry.identity = image;
    entry.format = MapTextureFormat::of(image->layout(), image->sampleType(), colorSpace);
    entry.level = 0;
    entry.nextRow = 0;
    entry.complete = false;
    return entry;
}

namespace {

// The half float of a 16-bit or half sRGB-encoded sample decoded to linear, for each of the 65536
// bit patterns (MapImage::linearHalfFromSrgb, once per pattern instead of a pow per texel).
const std::vector<std::uint16_t>& linearHalfTable(MapSampleType type)
{
    static const auto make = [](MapSampleType sampleType) {
        std::vector<std::uint16_t> table(65536);
        for (std::uint32_t bits = 0; bits < 65536; ++bits) {
            const float encoded = sampleType == MapSampleType::UInt16
                ? float(bits) / 65535.0f
                : MapImage::fromHalf(std::uint16_t(bits));
            table[bits] = MapImage::linearHalfFromSrgb(encoded);
        }
        return table;
    };
    static const std::vector<std::uint16_t> fromUnorm16 = make(MapSampleType::UInt16);
    static const std::vector<std::uint16_t> fromHalf = make(MapSampleType::Half);
    return type == MapSampleType::UInt16 ? fromUnorm16 : fromHalf;
}

} // namespace

// Level-0 rows [row, row + rows) in the upload format, for formats that convert (into
// entry.converted, which holds the whole level: the mipmaps are made from it).
void TextureCache::convertRows(Entry& entry, int row, int rows)
{
    const MapImage& image = *entry.image;
    const MapTextureFormat& f = entry.format;
    const int in = image.channels();
    const int out = f.uploadChannels;
    const std::size_t texels = std::size_t(image.width()) * std::size_t(rows);
    const unsigned char* source = image.row(row);
    if (f.conversion == MapTextureFormat::Conversion::ExpandToRgb) {
        // 8-bit grey, grey + alpha or red + green into RGB(A) (sRGB only; see the format).
        unsigned char* target
            = entry.converted.data() + std::size_t(row) * std::size_t(image.width()) * std::size_t(out);
        for (std::size_t i = 0; i < texels; ++i) {
            const unsigned char* s = source + i * std::size_t(in);
            unsigned char* d = target + i * std::size_t(out);
            if (image.layout() == MapLayout::RedGreen) {
                d[0] = s[0];
                d[1] = s[1];
                d[2] = 0;
            } else {
                d[0] = d[1] = d[2] = s[0];
                if (out == 4)
                    d[3] = s[1];
            }
        }
        return;
    }
    // SrgbToLinearHalf: the colour channels decoded to linear, alpha kept, all as half floats
    // (the CPU twin reads the same numbers: MapImage::linearHalfFromSrgb).
    const std::vector<std::uint16_t>& table = linearHalfTable(image.sampleType());
    const bool hasAlpha = image.layout() == MapLayout::GreyAlpha || image.layout() == MapLayout::Rgba;
    unsigned char* target = entry.converted.data() + std::size_t(row) * image.rowBytes();
    for (std::size_t i = 0; i < texels * std::size_t(in); ++i) {
        std::uint16_t bits = 0;
        std::memcpy(&bits, source + i * 2, 2);
        const bool alpha = hasAlpha && int(i % std::size_t(in)) == in - 1;
        const std::uint16_t value = !alpha                ? table[bits]
            : image.sampleType() == MapSampleType::UInt16 ? MapImage::toHalf(float(bits) / 65535.0f)
                                                          : bits;
        std::memcpy(target + i * 2, &value, 2);
    }
}

// One band of rows of the level under way (allocating the texture first), and on to the next
// level when the band ends one. Returns the bytes uploaded.
std::size_t TextureCache::uploadBand(Entry& entry)
{
    const MapImage& image = *entry.image;
    const MapTextureFormat& f = entry.format;
    const UploadState state;
    if (!entry.texture) {
        const std::size_t level0Bytes = std::size_t(image.width()) * std::size_t(image.height())
            * std::size_t(f.uploadChannels) * std::size_t(f.uploadBytesPerSample);
        if (f.conversion != MapTextureFormat::Conversion::None)
            entry.converted.resize(level0Bytes);
        entry.mips = std::make_unique<MipChain>(
            f.conversion != MapTextureFormat::Conversion::None ? entry.converted.data() : image.data(),
            image.width(), image.height(), f.uploadChannels, f.mipFilter);
        glGenTextures(1, &entry.texture);
        glBindTexture(GL_TEXTURE_2D, entry.texture);
        // Immutable storage, all levels at once, where there is (GL 4.2, ARB_texture_storage): on
        // llvmpipe, level by level allocated the texture twice (Mesa reallocates the chain when
        // the levels come in one by one) and the first write paid for both.
        if (m_textureStorage)
            glTexStorage2D(
                GL_TEXTURE_2D, entry.mips->levels(), f.internalFormat, image.width(), image.height());
        else
            for (int level = 0; level < entry.mips->levels(); ++level)
                glTexImage2D(GL_TEXTURE_2D, level, GLint(f.internalFormat), entry.mips->width(level),
                    entry.mips->height(level), 0, f.format, f.type, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, entry.mips->levels() - 1);
    } else {
        glBindTexture(GL_TEXTURE_2D, entry.texture);
    }
    MipChain& mips = *entry.mips;
    const int level = entry.level;
    const std::size_t rowBytes = mips.rowBytes(level);
    const int rows = std::min(int(std::max<std::size_t>(1, kBandBytes / std::max<std::size_t>(rowBytes, 1))),
        mips.height(level) - entry.nextRow);
    if (level == 0) {
        if (f.conversion != MapTextureFormat::Conversion::None)
            convertRows(entry, entry.nextRow, rows);
    } else {
        // The mipmaps are made here, once per texture, a band at a time (render/MipChain.h).
        mips.computeRows(level, entry.nextRow, entry.nextRow + rows);
    }
    glTexSubImage2D(GL_TEXTURE_2D, level, 0, entry.nextRow, mips.width(level), rows, f.format, f.type,
        mips.level(level) + rowBytes * std::size_t(entry.nextRow));
    entry.nextRow += rows;
    if (entry.nextRow == mips.height(level)) {
        ++entry.level;
        entry.nextRow = 0;
        mips.releaseBelow(entry.level - 1); // the level before the one just made is done with
    }
    const std::size_t bytes = rowBytes * std::size_t(rows);
    if (level == 0)
        m_bytesUploaded += bytes;
    return bytes;
}

// Sampling state: the texture is complete.
void TextureCache::finish(Entry& entry)
{
    const UploadState state;
    glBindTexture(GL_TEXTURE_2D, entry.texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, m_trilinear ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, entry.format.swizzle.data());
    if (m_maxSupportedAnisotropy > 1.0f)
        glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY, m_anisotropy);
    entry.complete = true;
    // The GPU has it all: the CPU copies belong to whoever loaded the map.
    entry.mips.reset();
    entry.converted = {};
    entry.image.reset();
}

bool TextureCache::uploadStep(Entry& entry, std::size_t* bytes)
{
    *bytes += uploadBand(entry);
    if (entry.level < entry.mips->levels())
        return false;
    finish(entry);
    return true;
}

void TextureCache::removeFromQueue(const Key& key)
{
    m_queue.erase(std::remove(m_queue.begin(), m_queue.end(), key), m_queue.end());
}

std::map<TextureCache::Key, TextureCache::Entry>::iterator TextureCache::findCurrent(
    const Key& key, const std::shared_ptr<const MapImage>& image, const std::string& path)
{
    auto found = m_textures.find(key);
    if (found != m_textures.end() && path.empty() && found->second.identity.lock() != image) {
        if (found->second.texture)
            glDeleteTextures(1, &found->second.texture);
        removeFromQueue(key);
        m_textures.erase(found);
        return m_textures.end();
    }
    return found;
}

void TextureCache::touch(const std::string& path, std::int64_t timestamp, ColorEncoding colorSpace)
{
    if (const auto found = m_textures.find(Key {path, timestamp, int(colorSpace)}); found != m_textures.end())
        found->second.used = true;
}

unsigned TextureCache::get(const std::shared_ptr<const MapImage>& image, const std::string& path,
    std::int64_t timestamp, ColorEncoding colorSpace, bool* uploaded)
{
    if (uploaded)
        *uploaded = false;
    if (!image || image->isEmpty())
        return 0;
    const Key key = keyFor(image, path, timestamp, colorSpace);
    auto found = findCurrent(key, image, path);
    if (found == m_textures.end()) {
        if (!fits(*image, std::get<0>(key)) || !hasPixels(*image, std::get<0>(key)))
            return 0;
        begin(key, image, colorSpace);
        found = m_textures.find(key);
    }
    Entry& entry = found->second;
    if (!entry.complete) {
        // A miss, or an upload under way: all of it now (never a partial texture).
        std::size_t bytes = 0;
        while (!uploadStep(entry, &bytes)) { }
        removeFromQueue(key);
        if (uploaded)
            *uploaded = true;
    }
    entry.used = true;
    return entry.texture;
}

bool TextureCache::isReady(const std::string& path, std::int64_t timestamp, ColorEncoding colorSpace) const
{
    const auto found = m_textures.find(Key {path, timestamp, int(colorSpace)});
    return found != m_textures.end() && found->second.complete;
}

std::optional<std::int64_t> TextureCache::readyTimestamp(
    const std::string& path, ColorEncoding colorSpace) const
{
    std::optional<std::int64_t> newest;
    const Key first {path, std::numeric_limits<std::int64_t>::min(), std::numeric_limits<int>::min()};
    for (auto it = m_textures.lower_bound(first); it != m_textures.end(); ++it) {
        const auto& [name, timestamp, space] = it->first;
        if (name != path)
            break;
        if (space == int(colorSpace) && it->second.complete && (!newest || timestamp > *newest))
            newest = timestamp;
    }
    return newest;
}

bool TextureCache::request(const std::shared_ptr<const MapImage>& image, const std::string& path,
    std::int64_t timestamp, ColorEncoding colorSpace)
{
    if (!image || image->isEmpty())
        return false;
    const Key key = keyFor(image, path, timestamp, colorSpace);
    auto found = findCurrent(key, image, path);
    if (found == m_textures.end()) {
        if (!fits(*image, std::get<0>(key)) || !hasPixels(*image, std::get<0>(key)))
            return false;
        begin(key, image, colorSpace);
        m_queue.push_back(key);
        found = m_textures.find(key);
    }
    found->second.used = true;
    return true;
}

TextureCache::SliceResult TextureCache::uploadSlice(double budgetMs)
{
    SliceResult result;
    const auto start = std::chrono::steady_clock::now();
    while (!m_queue.empty()) {
        Entry& entry = m_textures.at(m_queue.front());
        if (uploadStep(entry, &result.bytes)) {
            m_queue.pop_front();
            ++result.completed;
        }
        if (millisecondsSince(start) >= budgetMs)
            break;
    }
    // Whatever the driver queued (llvmpipe copies on the calling thread, a GPU later): finished
    // here, so that the time measured is what this slice costs.
    glFinish();
    result.milliseconds = millisecondsSince(start);
    return result;
}

void TextureCache::setMaxAnisotropy(float level)
{
    level = std::clamp(level, 1.0f, m_maxSupportedAnisotropy);
    if (level == m_anisotropy)
        return;
    m_anisotropy = level;
    if (m_maxSupportedAnisotropy <= 1.0f)
        return;
    const UploadState state;
    for (auto& [key, entry] : m_textures) {
        if (!entry.complete)
            continue;
        glBindTexture(GL_TEXTURE_2D, entry.texture);
        glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY, level);
    }
    for (const auto& [key, sampler] : m_samplers)
        applySamplerState(sampler.first, sampler.second);
}

void TextureCache::setTrilinear(bool trilinear)
{
    if (trilinear == m_trilinear)
        return;
    m_trilinear = trilinear;
    const UploadState state;
    for (auto& [key, entry] : m_textures) {
        if (!entry.complete)
            continue;
        glBindTexture(GL_TEXTURE_2D, entry.texture);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, trilinear ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR_MIPMAP_NEAREST);
    }
    for (const auto& [key, sampler] : m_samplers)
        applySamplerState(sampler.first, sampler.second);
}

namespace {

GLint glWrap(TextureWrap wrap)
{
    switch (wrap) {
    case TextureWrap::ClampToEdge:
        return GL_CLAMP_TO_EDGE;
    case TextureWrap::MirroredRepeat:
        return GL_MIRRORED_REPEAT;
    case TextureWrap::Repeat:
        break;
    }
    return GL_REPEAT;
}

GLint glFilter(TextureFilter filter, GLint autoFilter)
{
    switch (filter) {
    case TextureFilter::Nearest:
        return GL_NEAREST;
    case TextureFilter::Linear:
        return GL_LINEAR;
    case TextureFilter::NearestMipmapNearest:
        return GL_NEAREST_MIPMAP_NEAREST;
    case TextureFilter::LinearMipmapNearest:
        return GL_LINEAR_MIPMAP_NEAREST;
    case TextureFilter::NearestMipmapLinear:
        return GL_NEAREST_MIPMAP_LINEAR;
    case TextureFilter::LinearMipmapLinear:
        return GL_LINEAR_MIPMAP_LINEAR;
    case TextureFilter::Auto:
        break;
    }
    return autoFilter;
}

} // namespace

void TextureCache::applySamplerState(unsigned id, const TextureSampler& sampler) const
{
    glSamplerParameteri(id, GL_TEXTURE_WRAP_S, glWrap(sampler.wrapS));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_T, glWrap(sampler.wrapT));
    glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, glFilter(sampler.magFilter, GL_LINEAR));
    glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER,
        glFilter(sampler.minFilter, m_trilinear ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR_MIPMAP_NEAREST));
    if (m_maxSupportedAnisotropy > 1.0f) {
        // Anisotropy refines linear mipmapped filtering; a file that asks for nearest texels (pixel
        // art, lookup tables) or a single level gets none, which would blur what it asked for.
        const bool linearMips = (sampler.minFilter == TextureFilter::Auto
                                    || sampler.minFilter == TextureFilter::LinearMipmapLinear)
            && sampler.magFilter != TextureFilter::Nearest;
        glSamplerParameterf(id, GL_TEXTURE_MAX_ANISOTROPY, linearMips ? m_anisotropy : 1.0f);
    }
}

unsigned TextureCache::samplerFor(const TextureSampler& sampler)
{
    if (sampler.isDefault())
        return 0;
    const std::array<int, 4> key
        = {int(sampler.wrapS), int(sampler.wrapT), int(sampler.magFilter), int(sampler.minFilter)};
    auto found = m_samplers.find(key);
    if (found != m_samplers.end())
        return found->second.first;
    GLuint id = 0;
    glGenSamplers(1, &id);
    applySamplerState(id, sampler);
    m_samplers.emplace(key, std::make_pair(unsigned(id), sampler));
    return id;
}

void TextureCache::evictUnused()
{
    for (auto it = m_textures.begin(); it != m_textures.end();) {
        if (!it->second.used) {
            if (it->second.texture)
                glDeleteTextures(1, &it->second.texture);
            removeFromQueue(it->first);
            it = m_textures.erase(it);
        } else {
            it->second.used = false;
            ++it;
        }
    }
}

} // namespace facet
