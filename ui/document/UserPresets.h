#pragma once
// The user's material presets: one JSON file per preset ("facet-material-preset", see
// core/material/MaterialPresets.h) in QStandardPaths::AppDataLocation/presets. Writes are atomic (core's
// savePreset goes through writeFileAtomically); a file that does not read is reported by name
// and skipped, never deleted.

#include "core/material/MaterialPresets.h"

#include <QString>
#include <QStringList>

#include <vector>

namespace facet {

struct UserPreset {
    MaterialPreset preset;
    QString path; // the preset's file, or a package's folder (core/material/PresetPackage.h)
    bool package = false; // with its textures: applying it brings them
    QString folder; // empty: the user's own presets folder; else an added preset folder
};

class UserPresets {
public:
    // <AppDataLocation>/presets (created on the first save).
    static QString directory();
    // Every preset file and preset package (<id>.facetpreset folders) in directory() and in the
    // added folders (folders()), by display name. Unreadable files go to *problems, one
    // message each ("loadPreset: <path>: <reason>").
    static std::vector<UserPreset> load(QStringList* problems);
    // A preset id made from a display name: "My Brass!" -> "my-brass"; "preset" when nothing
    // usable is left; made unique against the files already there.
    static std::string idFromName(const QString& name);
    // Saves `material` as a preset named `name` (its look: texture paths are left out). Returns
    // the file's path, or an empty string with *error set.
    static QString save(const QString& name, const Material& material, QString* error);
    // Preset folders added like environment folders (a team's shared library, a download):
    // listed with the user's own presets, never written to. Kept in QSettings ("presets/folders").
    static QStringList folders();
    // Adds `folder` when it holds at least one preset or package. False with *error otherwise.
    static bool addFolder(const QString& folder, QString* error);
    static void removeFolder(const QString& folder);
    // Deletes a user preset's file, or a package's folder. False with *error when it could not
    // be removed.
    static bool remove(const QString& path, QString* error);
    // Writes `material` (with its textures) as a preset package named `name` into `folder`, for
    // another Facet to import. Returns the package's path, or empty with *error.
    static QString exportPackage(
        const QString& name, const Material& material, const QString& folder, QString* error);
    // Copies the package at `path` into directory() (its id made unique). Returns the installed
    // package's path, or empty with *error naming the problem.
    static QString importPackage(const QString& path, QString* error);
};

} // namespace facet
