#include "ui/UserPresets.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>

#include <algorithm>

namespace facet {

QString UserPresets::directory()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/presets");
}

std::vector<UserPreset> UserPresets::load(QStringList* problems)
{
    std::vector<UserPreset> presets;
    const QDir dir(directory());
    for (const QString& entry : dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name)) {
        const QString path = dir.filePath(entry);
        std::string error;
        std::optional<MaterialPreset> preset = loadPreset(path.toStdString(), &error);
        if (!preset) {
            if (problems)
                problems->append(QString::fromStdString(error));
            continue;
        }
        presets.push_back({std::move(*preset), path});
    }
    std::sort(presets.begin(), presets.end(), [](const UserPreset& a, const UserPreset& b) {
        return QString::fromStdString(a.preset.displayName)
                   .compare(QString::fromStdString(b.preset.displayName), Qt::CaseInsensitive)
            < 0;
    });
    return presets;
}

std::string UserPresets::idFromName(const QString& name)
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
    if (id.empty())
        id = "preset";
    const QDir dir(directory());
    std::string unique = id;
    for (int n = 2; QFileInfo::exists(dir.filePath(QString::fromStdString(unique) + QStringLiteral(".json")));
         ++n)
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
    QFile file(path);
    if (!file.remove()) {
        *error = QObject::tr("UserPresets::remove: %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

} // namespace facet
