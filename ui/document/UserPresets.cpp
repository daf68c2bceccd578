#include "ui/document/UserPresets.h"

#include "core/material/PresetPackage.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>

#include <algorithm>

namespace facet {

namespace {

// A preset id from a display name, not yet unique: "My Brass!" -> "my-brass"; "preset" when
// nothing usable is left.
std::string baseId(const QString& name)
{
    std::string id;
    for (const QChar c : name.toLower()) {
        const char ascii = c.toLatin1();
        if ((ascii >= 'a' && ascii <= 'z') || (ascii >= '0' && ascii <= '9'))
            id += ascii;
        else if (!id.empty() && id.back() != '-')
            id += '-';
    }
    while (!id.empty() && id.back() == '-')
        id.pop_back();
    const auto start = std::find_if(id.begin(), id.end(), [](char c) { return c >= 'a' && c <= 'z'; });
    id.erase(id.begin(), start);
    return id.empty() ? std::string("preset") : id;
}

} // namespace

QString UserPresets::directory()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/presets");
}

namespace {

const char* const kFoldersKey = "presets/folders";

// The presets of one folder: preset files (*.json) and packages (*.facetpreset folders).
void loadFolder(
    const QString& folder, const QString& label, std::vector<UserPreset>& presets, QStringList* problems)
{
    const QDir dir(folder);
    for (const QString& entry : dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name)) {
        const QString path = dir.filePath(entry);
        std::string error;
        std::optional<MaterialPreset> preset = loadPreset(path.toStdString(), &error);
        if (!preset) {
            if (problems)
                problems->append(QString::fromStdString(error));
            continue;
        }
        presets.push_back({std::move(*preset), path, false, label});
    }
    for (const QString& entry : dir.entryList({QStringLiteral("*") + QLatin1String(kPresetPackageSuffix)},
             QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name)) {
        const QString path = dir.filePath(entry);
        std::string error;
        std::optional<MaterialPreset> preset = loadPresetPackage(path.toStdString(), &error);
        if (!preset) {
            if (problems)
                problems->append(QString::fromStdString(error));
            continue;
        }
        presets.push_back({std::move(*preset), path, true, label});
    }
}

} // namespace

std::vector<UserPreset> UserPresets::load(QStringList* problems)
{
    std::vector<UserPreset> presets;
    loadFolder(directory(), QString(), presets, problems);
    for (const QString& folder : folders())
        loadFolder(folder, QDir(folder).dirName(), presets, problems);
    std::sort(presets.begin(), presets.end(), [](const UserPreset& a, const UserPreset& b) {
        return QString::fromStdString(a.preset.displayName)
                   .compare(QString::fromStdString(b.preset.displayName), Qt::CaseInsensitive)
            < 0;
    });
    return presets;
}

std::string UserPresets::idFromName(const QString& name)
{
    const std::string id = baseId(name);
    const QDir dir(directory());
    std::string unique = id;
    const auto taken = [&dir](const std::string& candidate) {
        const QString stem = dir.filePath(QString::fromStdString(candidate));
        return QFileInfo::exists(stem + QStringLiteral(".json"))
            || QFileInfo::exists(stem + QLatin1String(kPresetPackageSuffix));
    };
    for (int n = 2; taken(unique); ++n)
        unique = id + '-' + std::to_string(n);
    Q_ASSERT(isValidPresetId(unique));
    return unique;
}

QString UserPresets::save(const QString& name, const Material& material, QString* error)
{
    const QString trimmed = name.trimmed();
    if (trimmed.isEmpty()) {
        *error = QObject::tr("UserPresets::save: the preset needs a name");
        return {};
    }
    if (!QDir().mkpath(directory())) {
        *error = QObject::tr("UserPresets::save: %1: cannot create the folder").arg(directory());
        return {};
    }
    MaterialPreset preset;
    preset.id = idFromName(trimmed);
    preset.displayName = trimmed.toStdString();
    preset.material = material;
    preset.material.name = preset.displayName;
    const QString path
        = QDir(directory()).filePath(QString::fromStdString(preset.id) + QStringLiteral(".json"));
    std::string message;
    if (!savePreset(preset, path.toStdString(), &message)) {
        *error = QString::fromStdString(message);
        return {};
    }
    return path;
}

bool UserPresets::remove(const QString& path, QString* error)
{
    if (QFileInfo(path).isDir()) {
        // A package: only a folder in the presets folder that holds a preset index.
        if (QFileInfo(path).absolutePath() != QFileInfo(directory()).absoluteFilePath()
            || !QFileInfo::exists(path + QLatin1Char('/') + QLatin1String(kPresetPackageIndex))
            || !QDir(path).removeRecursively()) {
            *error = QObject::tr("UserPresets::remove: %1: cannot remove the package").arg(path);
            return false;
        }
        return true;
    }
    QFile file(path);
    if (!file.remove()) {
        *error = QObject::tr("UserPresets::remove: %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

QStringList UserPresets::folders()
{
    return QSettings().value(QLatin1String(kFoldersKey)).toStringList();
}

bool UserPresets::addFolder(const QString& folder, QString* error)
{
    const QString absolute = QFileInfo(folder).absoluteFilePath();
    std::vector<UserPreset> found;
    QStringList problems;
    loadFolder(absolute, QString(), found, &problems);
    if (found.empty()) {
        *error = QObject::tr("%1 holds no preset (.json) or preset package (.facetpreset)%2")
                     .arg(QDir::toNativeSeparators(absolute),
                         problems.isEmpty() ? QString()
                                            : QStringLiteral(": ") + problems.join(QStringLiteral("; ")));
        return false;
    }
    QStringList list = folders();
    if (!list.contains(absolute) && absolute != QFileInfo(directory()).absoluteFilePath())
        list.append(absolute);
    QSettings().setValue(QLatin1String(kFoldersKey), list);
    return true;
}

void UserPresets::removeFolder(const QString& folder)
{
    QStringList list = folders();
    list.removeAll(QFileInfo(folder).absoluteFilePath());
    QSettings().setValue(QLatin1String(kFoldersKey), list);
}

QString UserPresets::exportPackage(
    const QString& name, const Material& material, const QString& folder, QString* error)
{
    const QString trimmed = name.trimmed();
    if (trimmed.isEmpty()) {
        *error = QObject::tr("UserPresets::exportPackage: the preset needs a name");
        return {};
    }
    MaterialPreset preset;
    // The id from the name; the package's folder is checked by exportPresetPackage.
    const std::string id = baseId(trimmed);
    preset.id = id;
    preset.displayName = trimmed.toStdString();
    preset.material = material;
    preset.material.name = preset.displayName;
    std::string problem;
    const std::optional<std::string> path
        = exportPresetPackage(preset, folder.toStdString(), false, &problem);
    if (!path) {
        *error = QString::fromStdString(problem);
        return {};
    }
    return QString::fromStdString(*path);
}

QString UserPresets::importPackage(const QString& path, QString* error)
{
    std::string problem;
    const std::optional<std::string> installed
        = installPresetPackage(path.toStdString(), directory().toStdString(), &problem);
    if (!installed) {
        *error = QString::fromStdString(problem);
        return {};
    }
    return QString::fromStdString(*installed);
}

} // namespace facet
