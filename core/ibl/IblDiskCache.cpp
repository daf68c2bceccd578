#include "core/ibl/IblDiskCache.h"
#include "core/support/Fnv1a.h"

#include "core/support/AtomicFile.h"
#include "core/support/FileCheck.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace facet {

namespace {

constexpr char kMagic[8] = {'F', 'A', 'C', 'E', 'T', 'I', 'B', 'L'};
constexpr std::size_t kHeaderSize = 8 + 4 + 8 + 4 + 4 + 8 + 8;
// The largest entry Facet writes (a 4096 prefiltered cube with its mips in half floats, the
// irradiance and the DFG table) is about 1.1 GiB.
constexpr qint64 kMaxEntryBytes = qint64(4) << 30;

// Little-endian writers/readers (x86 and ARM hosts are little-endian; the byte order is still
// spelled out so the format does not depend on the host).
template <typename T> void put(QByteArray& out, T value)
{
    static_assert(std::is_integral_v<T>);
    for (std::size_t i = 0; i < sizeof(T); ++i)
        out.append(char((std::uint64_t(value) >> (8 * i)) & 0xffu));
}

template <typename T> bool get(const QByteArray& in, std::size_t& at, T* value)
{
    if (at + sizeof(T) > std::size_t(in.size()))
        return false;
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < sizeof(T); ++i)
        v |= std::uint64_t(std::uint8_t(in[qsizetype(at + i)])) << (8 * i);
    *value = T(v);
    at += sizeof(T);
    return true;
}

} // namespace

IblDiskCache::IblDiskCache(QString directory)
    : m_directory(directory.isEmpty() ? defaultDirectory() : std::move(directory))
{
}

QString IblDiskCache::defaultDirectory()
{
    const QString overridden = qEnvironmentVariable("FACET_CACHE_DIR");
    if (!overridden.isEmpty())
        return overridden;
    return QStandardPaths::writableLocation(QStandardPaths::CacheLocation) + QStringLiteral("/ibl");
}

std::uint64_t IblDiskCache::key(std::uint64_t contentHash, std::uint64_t settingsHash)
{
    char bytes[16];
    for (int i = 0; i < 8; ++i) {
        bytes[i] = char((contentHash >> (8 * i)) & 0xffu);
        bytes[8 + i] = char((settingsHash >> (8 * i)) & 0xffu);
    }
    return Fnv1a64().addBytes(bytes, sizeof bytes).value();
}

std::string IblDiskCache::keyHex(std::uint64_t key)
{
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(key));
    return text;
}

QString IblDiskCache::pathFor(std::uint64_t key) const
{
    return m_directory + QLatin1Char('/') + QString::fromStdString(keyHex(key)) + QStringLiteral(".fibl");
}

bool IblDiskCache::store(std::uint64_t key, const IblCacheEntry& entry, std::string* error) const
{
    const QString path = pathFor(key);
    auto fail = [&](const std::string& reason) {
        if (error)
            *error = "IblDiskCache::store: " + path.toStdString() + ": " + reason;
        return false;
    };
    QByteArray payload;
    for (const IblCacheLayer& layer : entry.layers) {
        const std::size_t count = layer.valueCount();
        const bool half = layer.format == IblCacheLayer::Format::Half;
        if ((half ? layer.half.size() : layer.single.size()) != count || layer.width <= 0 || layer.height <= 0
            || layer.faces <= 0)
            return fail("layer sizes do not match its data");
        put<std::uint32_t>(payload, std::uint32_t(layer.width));
        put<std::uint32_t>(payload, std::uint32_t(layer.height));
        put<std::uint32_t>(payload, std::uint32_t(layer.faces));
        put<std::uint32_t>(payload, std::uint32_t(layer.level));
        put<std::uint32_t>(payload, std::uint32_t(layer.format));
        if (half) {
            for (std::uint16_t v : layer.half)
                put<std::uint16_t>(payload, v);
        } else {
            for (float v : layer.single) {
                std::uint32_t bits = 0;
                std::memcpy(&bits, &v, sizeof bits);
                put<std::uint32_t>(payload, bits);
            }
        }
    }
    for (double v : entry.extra) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &v, sizeof bits);
        put<std::uint64_t>(payload, bits);
    }

    QByteArray header;
    header.append(kMagic, sizeof kMagic);
    put<std::uint32_t>(header, kVersion);
    put<std::uint64_t>(header, key);
    put<std::uint32_t>(header, std::uint32_t(entry.layers.size()));
    put<std::uint32_t>(header, std::uint32_t(entry.extra.size()));
    put<std::uint64_t>(header, std::uint64_t(payload.size()));
    put<std::uint64_t>(header, Fnv1a64().addBytes(payload.constData(), std::size_t(payload.size())).value());

    if (!QDir().mkpath(m_directory))
        return fail("cannot create the directory");
    // One buffer, one checked atomic write: a full disk leaves the old entry (or none), never a
    // 0-byte or truncated one (core/support/AtomicFile.h).
    const QByteArray bytes = header + payload;
    // The cache owns its entries' paths: a symbolic link or a FIFO found there is removed, not
    // written through (a link to /dev/zero or elsewhere would otherwise take the entry).
    std::error_code ignored;
    const std::filesystem::file_status existing
        = std::filesystem::symlink_status(path.toStdString(), ignored);
    if (std::filesystem::is_symlink(existing) || std::filesystem::is_fifo(existing)
        || std::filesystem::is_socket(existing))
        std::filesystem::remove(path.toStdString(), ignored);
    std::string reason;
    if (!writeFileAtomically(
            path.toStdString(), std::string_view(bytes.constData(), std::size_t(bytes.size())), &reason))
        return fail("cannot write it: " + reason);
    return true;
}

std::optional<IblCacheEntry> IblDiskCache::load(std::uint64_t key, std::string* warning) const
{
    const QString path = pathFor(key);
    QFile file(path);
    if (!file.exists() && !QFileInfo(path).isSymLink())
        return std::nullopt;
    auto bad = [&](const std::string& reason) -> std::optional<IblCacheEntry> {
        if (warning)
            *warning = "IblDiskCache::load: " + path.toStdString() + ": " + reason + "; ignoring it";
        return std::nullopt;
    };
    // An entry that is a device (a link to /dev/zero), a FIFO or a link loop would be read
    // without end or block; one larger than any entry Facet writes is not one of its entries.
    if (const FileCheck check = checkRegularFile(path.toStdString()); !check.ok())
        return bad(check.problem);
    if (file.size() > kMaxEntryBytes)
        return bad("larger than " + std::to_string(kMaxEntryBytes >> 20) + " MiB, more than any entry holds");
    if (!file.open(QIODevice::ReadOnly))
        return bad(file.errorString().toStdString());
    const QByteArray data = file.readAll();
    if (std::size_t(data.size()) < kHeaderSize || std::memcmp(data.constData(), kMagic, sizeof kMagic) != 0)
        return bad("not a Facet IBL cache file (bad magic or too short)");
    std::size_t at = sizeof kMagic;
    std::uint32_t version = 0, layerCount = 0, extraCount = 0;
    std::uint64_t storedKey = 0, payloadSize = 0, checksum = 0;
    get(data, at, &version);
    get(data, at, &storedKey);
    get(data, at, &layerCount);
    get(data, at, &extraCount);
    get(data, at, &payloadSize);
    get(data, at, &checksum);
    if (version != kVersion)
        return bad("version " + std::to_string(version) + ", expected " + std::to_string(kVersion));
    if (storedKey != key)
        return bad("holds key " + keyHex(storedKey));
    if (payloadSize != std::uint64_t(data.size()) - kHeaderSize)
        return bad("truncated or padded (payload " + std::to_string(std::uint64_t(data.size()) - kHeaderSize)
            + " bytes, header says " + std::to_string(payloadSize) + ")");
    if (Fnv1a64().addBytes(data.constData() + kHeaderSize, std::size_t(payloadSize)).value() != checksum)
        return bad("checksum mismatch (corrupt)");

    IblCacheEntry entry;
    for (std::uint32_t i = 0; i < layerCount; ++i) {
        std::uint32_t w = 0, h = 0, faces = 0, level = 0, format = 0;
        if (!get(data, at, &w) || !get(data, at, &h) || !get(data, at, &faces) || !get(data, at, &level)
            || !get(data, at, &format))
            return bad("truncated layer header");
        if (w == 0 || h == 0 || faces == 0 || w > 65536 || h > 65536 || faces > 6
            || (format != 1u && format != 2u))
            return bad("bad layer header");
        IblCacheLayer layer;
        layer.width = int(w);
        layer.height = int(h);
        layer.faces = int(faces);
        layer.level = int(level);
        layer.format = IblCacheLayer::Format(format);
        const std::size_t count = layer.valueCount();
        const std::size_t bytes = count * (format == 1u ? 2u : 4u);
        if (at + bytes > std::size_t(data.size()))
            return bad("truncated layer data");
        if (format == 1u) {
            layer.half.resize(count);
            for (std::uint16_t& v : layer.half)
                get(data, at, &v);
        } else {
            layer.single.resize(count);
            for (float& v : layer.single) {
                std::uint32_t bits = 0;
                get(data, at, &bits);
                std::memcpy(&v, &bits, sizeof v);
            }
        }
        entry.layers.push_back(std::move(layer));
    }
    if (at + std::size_t(extraCount) * 8 != std::size_t(data.size()))
        return bad("payload size does not match its layers");
    entry.extra.resize(extraCount);
    for (double& v : entry.extra) {
        std::uint64_t bits = 0;
        get(data, at, &bits);
        std::memcpy(&v, &bits, sizeof v);
    }
    return entry;
}

} // namespace facet
