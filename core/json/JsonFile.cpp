// The project-independent parts of Facet's JSON files: paths stored relative to the file,
// built-in and library specs, the format/version check, and reading/writing one object per file.
// Declared in core/project/Project.h (namespace facet::json).

#include <algorithm>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonParseError>
#include <QStorageInfo>

#include "core/json/JsonStructure.h"
#include "core/json/JsonSupport.h"
#include "core/project/AssetLibrary.h"
#include "core/project/Project.h"
#include "core/support/AtomicFile.h"
#include "core/support/FileCheck.h"

namespace facet {

namespace {

using namespace jsonsupport;

// Up to `limit` bytes of an open file, the buffer growing as they arrive. QIODevice::read(n)
// allocates all n bytes first: every project, preset and autosave read allocated
// Project::kMaxFileBytes (16 MiB) for a file of a few KiB (under AddressSanitizer, which fills
// large blocks, a test reading 800 files spent 38 s there). size() is only a hint, a file can
// grow while it is read.
QByteArray readUpTo(QFile& file, qint64 limit)
{
    constexpr qint64 kStep = 64 * 1024;
    const qint64 expected = std::clamp<qint64>(file.size() + 1, 1, limit);
    QByteArray data;
    while (data.size() < limit) {
        const qsizetype at = data.size();
        const qint64 step = std::min(std::max(expected - at, kStep), limit - at);
        data.resize(at + qsizetype(step));
        const qint64 got = file.read(data.data() + at, step);
        data.resize(at + qsizetype(std::max<qint64>(got, 0)));
        if (got < step) // the end (QFile reads on until it has `step` bytes or none are left)
            break;
    }
    return data;
}

// The mount point holding `path`, or its nearest existing ancestor (a texture may not exist yet).
QString volumeRoot(const QString& path)
{
    QFileInfo info(path);
    QString existing = info.absoluteFilePath();
    for (int guard = 0; guard < 256 && !existing.isEmpty() && !QFileInfo::exists(existing); ++guard) {
        const QString parent = QFileInfo(existing).absolutePath();
        if (parent == existing)
            break;
        existing = parent;
    }
    const QStorageInfo storage(existing);
    return storage.isValid() ? storage.rootPath() : QString();
}

// Version-1 files stored an installed sample file as a path climbing out of the project folder
// ("../../home/ana/.local/share/facet/assets/hdri/night.exr"), which breaks once the project
// moves. Such a path that leads nowhere, but names a file under ".../facet/assets/" that the
// installed library has, is taken to mean that file.
std::optional<std::string> rescuedInstalledPath(const std::string& path)
{
    static const std::string kMarker = "/facet/assets/";
    const std::size_t marker = path.rfind(kMarker);
    if (marker == std::string::npos || QFileInfo::exists(qs(path)))
        return std::nullopt;
    const std::string candidate
        = AssetLibrary::installed().folder + "/" + path.substr(marker + kMarker.size());
    if (!QFileInfo(qs(candidate)).isFile())
        return std::nullopt;
    return candidate;
}

} // namespace

namespace json {

std::string storedPath(const std::string& path, const std::string& baseDir)
{
    if (path.empty() || baseDir.empty())
        return path;
    const QString file = QDir::cleanPath(QDir::fromNativeSeparators(qs(path)));
    if (QDir::isRelativePath(file))
        return ss(file);
    const QString base = QDir::cleanPath(QDir(qs(baseDir)).absolutePath());
    // A file on another volume stays absolute: moving the project folder does not move it, and
    // on Windows no relative path crosses drives.
    const QString fileRoot = volumeRoot(file);
    const QString baseRoot = volumeRoot(base);
    if (!fileRoot.isEmpty() && !baseRoot.isEmpty() && fileRoot != baseRoot)
        return ss(file);
    const QString relative = QDir(base).relativeFilePath(file);
    if (QDir::isAbsolutePath(relative))
        return ss(file);
    return ss(relative);
}

std::string resolvedPath(const std::string& path, const std::string& baseDir)
{
    if (path.empty())
        return path;
    const QString file = QDir::fromNativeSeparators(qs(path));
    if (baseDir.empty() || QDir::isAbsolutePath(file))
        return ss(QDir::cleanPath(file));
    return ss(QDir::cleanPath(QDir(qs(baseDir)).absoluteFilePath(file)));
}

bool isBuiltinSpec(const std::string& spec)
{
    if (spec.rfind("uniform:", 0) == 0)
        return true;
    if (spec.empty() || !(spec[0] >= 'a' && spec[0] <= 'z'))
        return false;
    for (char c : spec)
        if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-'))
            return false;
    return true;
}

std::string storedSpec(const std::string& spec, const std::string& baseDir)
{
    if (spec.empty() || isBuiltinSpec(spec) || AssetLibrary::isSpec(spec))
        return spec;
    // A file in a library is stored by the library's name: the project then opens wherever the
    // library is on another machine, and wherever the project folder is moved.
    if (!baseDir.empty())
        if (const std::optional<std::string> library = AssetLibrary::specForPath(spec))
            return *library;
    const std::string stored = storedPath(spec, baseDir);
    return isBuiltinSpec(stored) || AssetLibrary::isSpec(stored) ? "./" + stored : stored;
}

std::string resolvedSpec(const std::string& spec, const std::string& baseDir)
{
    if (isBuiltinSpec(spec))
        return spec;
    // A library this machine does not have keeps its reference: the project opens, lists it as
    // missing, and saves it back unchanged unless it is relinked.
    if (AssetLibrary::isSpec(spec))
        return AssetLibrary::resolveSpec(spec, nullptr).value_or(spec);
    const std::string path = resolvedPath(spec, baseDir);
    return rescuedInstalledPath(path).value_or(path);
}

bool checkFormat(const QJsonObject& object, const char* formatName, int newestVersion, const char* what,
    std::string* problem)
{
    const QJsonValue format = object.value(QLatin1String("format"));
    if (format.isUndefined())
        return fail(std::string("\"format\" is missing: not ") + what + " file", problem);
    if (!format.isString())
        return fail(std::string("format: expected a string, got ") + typeName(format), problem);
    if (format.toString() != QLatin1String(formatName))
        return fail(
            "format: \"" + ss(format.toString()) + "\" is not \"" + formatName + "\": not " + what + " file",
            problem);
    const QJsonValue version = object.value(QLatin1String("version"));
    if (version.isUndefined())
        return fail("\"version\" is missing", problem);
    const double versionNumber = version.toDouble();
    if (!version.isDouble() || std::floor(versionNumber) != versionNumber)
        return fail(std::string("version: expected an integer, got ")
                + (version.isDouble() ? facet::number(versionNumber) : typeName(version)),
            problem);
    if (versionNumber > newestVersion)
        return fail("written by a newer Facet (version " + facet::number(versionNumber)
                + "); this Facet reads up to version " + std::to_string(newestVersion),
            problem);
    if (versionNumber < 1)
        return fail(
            "version: " + facet::number(versionNumber) + " is not a valid version (versions start at 1)",
            problem);
    return true;
}

std::optional<QJsonObject> readObjectFile(const std::string& path, qint64 maxBytes, std::string* problem)
{
    // A FIFO would block the open, a device would be read to the size limit for nothing.
    if (const FileCheck check = checkRegularFile(path); !check.ok())
        return failed(check.problem, problem);
    const QString fileName = qs(path);
    QFile file(fileName);
    if (!file.open(QIODevice::ReadOnly))
        return failed("cannot read it: " + ss(file.errorString()), problem);
    // Read one byte more than allowed to tell "at the limit" from "over it" without trusting
    // size() (a pipe or /proc file reports 0).
    const QByteArray data = readUpTo(file, maxBytes + 1);
    if (file.error() != QFileDevice::NoError)
        return failed("cannot read it: " + ss(file.errorString()), problem);
    if (data.size() > maxBytes)
        return failed("the file is larger than " + std::to_string(maxBytes / (1024 * 1024))
                + " MiB, too large to be a " + "Facet file",
            problem);
    if (data.trimmed().isEmpty())
        return failed("the file is empty", problem);

    // Before the parser: one key twice meant one value to Qt and another to other readers.
    if (const std::optional<std::string> shape
        = jsonStructureProblem(std::string_view(data.constData(), std::size_t(data.size()))))
        return failed(*shape, problem);

    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(data, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        // QJsonParseError::offset counts bytes of the UTF-8 input.
        const qsizetype offset = std::clamp<qsizetype>(parseError.offset, 0, data.size());
        return failed(
            jsonPosition(std::string_view(data.constData(), std::size_t(data.size())), std::size_t(offset))
                + ": " + ss(parseError.errorString()) + " (not valid JSON)",
            problem);
    }
    if (!document.isObject())
        return failed(std::string("expected a JSON object at the top level, got ")
                + (document.isArray() ? "an array" : "something else"),
            problem);
    return document.object();
}

bool writeObjectFile(const std::string& path, const QJsonObject& object, std::string* problem)
{
    if (path.empty())
        return fail("no file name given", problem);
    const QString fileName = qs(path);
    const QFileInfo info(fileName);
    if (info.isDir())
        return fail("is a folder, not a file", problem);
    if (!info.absoluteDir().exists())
        return fail("the folder " + ss(info.absolutePath()) + " does not exist", problem);
    const QByteArray data = QJsonDocument(object).toJson(QJsonDocument::Indented);
    // Through a temporary file, checked at every step, then an atomic rename: a failure at any
    // point (a full disk included) leaves the old file as it was (core/support/AtomicFile.h says why
    // QSaveFile could not be trusted with that).
    std::string reason;
    if (!writeFileAtomically(path, std::string_view(data.constData(), std::size_t(data.size())), &reason))
        return fail("cannot write it: " + reason, problem);
    return true;
}

} // namespace json

} // namespace facet
