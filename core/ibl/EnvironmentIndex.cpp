#include "core/ibl/EnvironmentIndex.h"
#include "core/support/Fnv1a.h"

#include "core/ibl/IblDiskCache.h"
#include "core/support/AtomicFile.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include <QByteArray>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>

namespace facet {

namespace {

constexpr const char* kFormat = "facet-environment-index";
// A record is a few hundred bytes; anything much larger is not one of ours.
constexpr qint64 kMaxRecordBytes = 64 * 1024;

std::string absolutePath(const std::string& path)
{
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(path, error);
    return error ? path : absolute.lexically_normal().string();
}

// 64-bit numbers travel as decimal strings: a JSON number is a double (53 bits), and a time in
// nanoseconds since 1970 needs 61.
QString text(std::int64_t value)
{
    return QString::number(value);
}

QString text(std::uint64_t value)
{
    return QString::number(value);
}

bool readSigned(const QJsonObject& object, const char* name, std::int64_t* value)
{
    bool ok = false;
    *value = object.value(QLatin1String(name)).toString().toLongLong(&ok);
    return ok;
}

bool readUnsigned(const QJsonObject& object, const char* name, std::uint64_t* value)
{
    bool ok = false;
    *value = object.value(QLatin1String(name)).toString().toULongLong(&ok);
    return ok;
}

} // namespace

EnvironmentIndex::EnvironmentIndex(QString directory)
    : m_directory(directory.isEmpty() ? defaultDirectory() : std::move(directory))
{
}

QString EnvironmentIndex::defaultDirectory()
{
    return IblDiskCache::defaultDirectory() + QStringLiteral("/sources");
}

QString EnvironmentIndex::recordPath(const std::string& path) const
{
    char name[17];
    std::snprintf(name, sizeof name, "%016llx",
        static_cast<unsigned long long>(Fnv1a64().addString(absolutePath(path)).value()));
    return m_directory + QLatin1Char('/') + QLatin1String(name) + QStringLiteral(".json");
}

std::optional<EnvironmentRecord> EnvironmentIndex::find(
    const std::string& path, const FileIdentity& identity) const
{
    const QString file = recordPath(path);
    // Only a regular file of a record's size is read (a link to /dev/zero would never end).
    FileIdentity own;
    if (!fileIdentity(file.toStdString(), &own) || own.size > kMaxRecordBytes)
        return std::nullopt;
    QFile input(file);
    if (!input.open(QIODevice::ReadOnly))
        return std::nullopt;
    const QJsonDocument document = QJsonDocument::fromJson(input.read(kMaxRecordBytes));
    if (!document.isObject())
        return std::nullopt;
    const QJsonObject object = document.object();
    if (object.value(QLatin1String("format")).toString() != QLatin1String(kFormat)
        || object.value(QLatin1String("version")).toInt() != kVersion
        || object.value(QLatin1String("path")).toString().toStdString() != absolutePath(path))
        return std::nullopt;
    FileIdentity stored;
    std::uint64_t hash = 0;
    if (!readSigned(object, "size", &stored.size) || !readSigned(object, "modifiedNs", &stored.modifiedNs)
        || !readSigned(object, "changedNs", &stored.changedNs)
        || !readUnsigned(object, "device", &stored.device) || !readUnsigned(object, "inode", &stored.inode)
        || !readUnsigned(object, "contentHash", &hash) || stored != identity)
        return std::nullopt;
    EnvironmentRecord record;
    record.contentHash = hash;
    record.width = object.value(QLatin1String("width")).toInt();
    record.height = object.value(QLatin1String("height")).toInt();
    record.warning = object.value(QLatin1String("warning")).toString().toStdString();
    if (record.width <= 0 || record.height <= 0)
        return std::nullopt;
    return record;
}

bool EnvironmentIndex::store(const std::string& path, const FileIdentity& identity,
    const EnvironmentRecord& record, std::string* reason) const
{
    const std::int64_t now = std::chrono::duration_cast<std::chrono::nanoseconds>(
        std::chrono::system_clock::now().time_since_epoch())
                                 .count();
    if (now - identity.modifiedNs < std::int64_t(kSettleSeconds) * 1000000000) {
        if (reason)
            *reason = "modified less than " + std::to_string(kSettleSeconds) + " s ago";
        return false;
    }
    QJsonObject object;
    object.insert(QStringLiteral("format"), QLatin1String(kFormat));
    object.insert(QStringLiteral("version"), kVersion);
    object.insert(QStringLiteral("path"), QString::fromStdString(absolutePath(path)));
    object.insert(QStringLiteral("size"), text(identity.size));
    object.insert(QStringLiteral("modifiedNs"), text(identity.modifiedNs));
    object.insert(QStringLiteral("changedNs"), text(identity.changedNs));
    object.insert(QStringLiteral("device"), text(identity.device));
    object.insert(QStringLiteral("inode"), text(identity.inode));
    object.insert(QStringLiteral("contentHash"), text(record.contentHash));
    object.insert(QStringLiteral("width"), record.width);
    object.insert(QStringLiteral("height"), record.height);
    object.insert(QStringLiteral("warning"), QString::fromStdString(record.warning));
    std::error_code error;
    std::filesystem::create_directories(m_directory.toStdString(), error);
    if (error) {
        if (reason)
            *reason = "cannot create " + m_directory.toStdString() + ": " + error.message();
        return false;
    }
    const QByteArray bytes = QJsonDocument(object).toJson(QJsonDocument::Compact);
    return writeFileAtomically(recordPath(path).toStdString(),
        std::string_view(bytes.constData(), std::size_t(bytes.size())), reason);
}

void EnvironmentIndex::forget(const std::string& path) const
{
    QFile::remove(recordPath(path));
}

} // namespace facet
