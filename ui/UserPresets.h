#pragma once
// The user's material presets: one JSON file per preset ("facet-material-preset", see
// core/MaterialPresets.h) in QStandardPaths::AppDataLocation/presets. Writes are atomic (core's
// savePreset goes through writeFileAtomically); a file that does not read is reported by name
// and skipped, never deleted.

#include "core/MaterialPresets.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace facet {

struct UserPreset {
    MaterialPreset preset;
    QString path;
};

class UserPresets {
public:
    // <AppDataLocation>/presets (created on the first save).
    static QString directory();
    // Every preset file in directory(), by display name. Unreadable files go to *problems, one
    // message each ("loadPreset: <path>: <reason>").
    static std::vector<UserPreset> load(QStringList* problems);
    // A preset id made from a display name: "My Brass!" -> "my-brass"; "preset" when nothing
    // usable is left; made unique against the files already there.
    static std::string idFromName(const QString& name);
    // Saves `material` as a preset named `name` (its look: texture paths are left out). Returns
    // the file's path, or an empty string with *error set.
    static QString save(const QString& name, const Material& material, QString* error);
    // Deletes a user preset's file. False with *error when it could not be removed.
    static bool remove(const QString& path, QString* error);
};

} // namespace facet
