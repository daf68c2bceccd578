#pragma once
// The open project and its editing history (Tiled's Document). One Document per window: it holds
// the core::Project value, the file it came from, and the QUndoStack; it emits changed() with what
// changed (ui/document/DocumentChanges.h: the kinds, and which materials, map slots, lights and view
// settings, worked out by changesBetween) after every edit, undo and redo. Panels read project()
// and edit through the setters below, which push undo commands (ui/document/DocumentCommands.h); they never
// touch the renderer. The viewport observes changed() and reloads only what changed.
//
// Undo: every setter except setCamera() is one undo step. A slider drag is ONE step:
//
//   document->beginInteractiveEdit();                       // slider pressed
//   document->setMaterial(m, tr("Roughness"), kRoughnessId); // every valueChanged while dragging
//   document->endInteractiveEdit();                          // slider released
//
// While an interactive edit is open, consecutive edits with the same non-zero mergeId merge into
// the step the first one made (QUndoCommand::mergeWith); a later drag is a new step, and a drag
// that ends where it began leaves no step at all. Outside an interactive edit nothing merges.
// Merge ids are free to choose; ui/document/DocumentCommands.h lists the ones in use.
//
// Camera moves are not undoable (as in Marmoset Toolbag and Substance): they are saved with the
// project but neither push a command nor mark the document modified.
//
// Files: open()/save()/saveAs() read and write core's "facet-project" JSON (docs/project-format.md).
// Errors come back as one message naming the file and the reason; the document is unchanged then.
// A project opens even when files it names are missing: missingFiles() lists them and
// relinkFile() points them somewhere else (undoable).

#include "core/material/MaterialPresets.h"
#include "core/project/Project.h"
#include "core/support/FileCheck.h"
#include "ui/document/DocumentChanges.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <optional>

class QUndoStack;

namespace facet {

class Document : public QObject {
    Q_OBJECT
public:
    explicit Document(QObject* parent = nullptr); // holds Project::defaultProject(), unmodified
    ~Document() override;

    const Project& project() const { return m_project; }
    QUndoStack* undoStack() const { return m_undoStack; }

    // --- Edits (each pushes one undo command unless noted; nothing happens when the value is
    // unchanged). undoText is what Edit > Undo shows, e.g. tr("Roughness"). mergeId: see above.
    void setMaterial(const Material& material, const QString& undoText, int mergeId = 0);
    void setEnvironment(const EnvironmentSettings& environment, const QString& undoText, int mergeId = 0);
    void setLights(const std::vector<Light>& lights, const QString& undoText, int mergeId = 0);
    void setView(const ViewSettings& view, const QString& undoText, int mergeId = 0);
    // The preset's look (IOR, shading, factors) on the current material; its name, texture paths
    // and per-map options (channel, colour space, invert, flip green, UV) stay, so a preset can be
    // tried on a texture set (issue 30: applying one renamed the material). A preset with
    // textures (a package, core/material/PresetPackage.h) brings its texture set instead: every map as the
    // preset has it, with alpha, sides and emissive strength. Undo text "Apply Preset <name>".
    // Returns what changed, for the status bar: "Applied Gold to “Barrel”: base colour, metallic,
    // roughness; its maps kept".
    QString applyPreset(const MaterialPreset& preset);
    // Any combination of the above as one step (e.g. assigning a folder of maps and the mesh).
    // The camera part of `project` is ignored (see setCamera).
    void setProject(const Project& project, const QString& undoText, int mergeId = 0);
    // Not undoable, does not mark the document modified; emits changed(Camera).
    void setCamera(const Camera& camera);
    // Which material the docks edit (picked from the list or by clicking a part). A selection,
    // not an edit: no undo step, not modified; emits changed(CurrentMaterial). Out of range: ignored.
    void setCurrentMaterial(int index);
    // Which material each mesh part shows and which parts are drawn: one undo step.
    void setParts(const std::vector<MeshPart>& parts, const QString& undoText);

    // Interactive edits (slider drags, colour-dialog previews): see the top of this file.
    void beginInteractiveEdit();
    void endInteractiveEdit();
    bool interactiveEditOpen() const { return m_interactionSerial != 0; }

    // --- Files
    // Replaces the project with Project::defaultProject(); clears the history, the path and the
    // missing files; unmodified. (Asking about unsaved changes is the window's job.)
    void newProject();
    // Loads `path`. On failure returns false, sets *error ("Project::load: <path>: <reason>")
    // and changes nothing; a debug view the renderer does not know is refused too
    // ("Document::open: <path>: view.debugView: unknown debug view ..."). On success the history
    // is cleared, the document is unmodified, warnings() holds the loader's notes and
    // missingFiles() the files the project names that do not exist.
    bool open(const QString& path, QString* error);
    // Opens a glTF asset (.gltf / .glb) as a new, untitled project (core/project/AssetProject.h
    // projectFromAsset: the default project with the asset's materials and parts, the asset as the
    // mesh). On failure returns false, sets *error ("importGltf: <path>: <reason>") and changes
    // nothing. On success the history is cleared, filePath() is empty (Save asks where to write
    // the project), sourceAssetPath() is the asset, displayName() names it, the document is
    // unmodified and warnings() holds the import's notes (core's wording).
    bool openAsset(const QString& path, QString* error);
    // Writes to filePath() (must not be empty) / to `path` (which becomes filePath()). On success
    // the document is unmodified. On failure the file on disk is untouched (atomic save).
    bool save(QString* error);
    bool saveAs(const QString& path, QString* error);
    // Opens `recoveryPath` (written by writeRecoveryFile) as a modified document whose filePath()
    // is the project the recovery copy was made from (empty for an untitled one).
    bool recover(const QString& recoveryPath, QString* error);
    // A copy of the current state for crash recovery; filePath() and the modified state stay.
    bool writeRecoveryFile(const QString& recoveryPath, QString* error) const;
    // The project file a recovery file was made from ("" for an untitled one, or when unreadable).
    static QString recoveryOriginalPath(const QString& recoveryPath);

    QString filePath() const { return m_filePath; }
    // Whether filePath() was rewritten or replaced on disk since this document opened or saved it (another
    // window, another program): size, times and inode against those seen then (core/support/FileCheck.h
    // FileIdentity). False for an untitled or recovered document (nothing seen yet) and while the file is
    // what was seen. Saving over such a file would lose the other writer's work without a word (issue 29):
    // the window asks first (ProjectFileController).
    bool changedOnDisk() const;
    // Opens filePath() again (discarding edits: ask first); as open().
    bool reload(QString* error);
    // The asset an untitled project was opened from (openAsset); empty otherwise, and again after
    // the project is saved, or another is opened or made.
    QString sourceAssetPath() const { return m_sourceAssetPath; }
    // What exports are named after and where they go first (issue 30: saving as barrel.json gave
    // "barrel.json.gltf", and the dialog started in the home folder): the project file's name
    // without its extension (".json", ".facet.json") or the asset's ("barrel.glb" -> "barrel"),
    // else "material"; and that file's folder, else empty.
    QString exportBaseName() const;
    QString exportFolder() const;
    // The file name without folder; "Untitled (helmet.glb)" for a project opened from an asset
    // and not saved yet; else "Untitled".
    QString displayName() const;
    bool isModified() const;

    // Texture, environment and mesh files the project names that do not exist (absolute paths,
    // each once, in material-slot order, then environment, then mesh). Updated on open, recover
    // and every edit (or undo, redo) that names other files (a map's path or colour space, the
    // environment source, the mesh, materials added or removed); a file deleted on disk meanwhile
    // shows at the next of those.
    const QStringList& missingFiles() const { return m_missingFiles; }
    // Every reference to `oldPath` (map, environment source, mesh) becomes `newPath`; one undo
    // step "Relink <file name>". Returns false if nothing referred to oldPath.
    bool relinkFile(const QString& oldPath, const QString& newPath);
    // Notes from the last open() / recover() (ignored keys), one per line; empty if none.
    const QString& warnings() const { return m_warnings; }

    // For the undo commands (ui/document/DocumentCommands.h) only: replaces the undoable part of the
    // project (everything but the camera) and emits changed() with what differs.
    void applyUndoableState(const Project& state);
    int interactionSerial() const { return m_interactionSerial; }

    // Files the project refers to changed on disk (a texture re-saved by an image editor): not
    // an edit (no undo step, the project value is the same), but observers must re-read them.
    // Emits changed(changes); SceneController reloads only files whose time changed. Kinds alone
    // (DocumentChange::MaterialMaps) name no material: every map file is checked.
    void notifyFilesChangedOnDisk(const DocumentChanges& changes) { Q_EMIT changed(changes); }

Q_SIGNALS:
    // After every change of project(): edits, undo, redo, New, Open, recovery.
    void changed(const facet::DocumentChanges& changes);
    // Another project replaced this one (New, Open, recovery), just before changed(WholeProject):
    // per-project notes (what the last folder assignment did) and view state are stale.
    void projectReplaced();
    // The modified state flipped (QUndoStack::cleanChanged, and New/Open/Save).
    void modifiedChanged(bool modified);
    // filePath() changed (Open, Save As, New, recovery).
    void filePathChanged(const QString& path);
    // missingFiles() changed.
    void missingFilesChanged(const QStringList& missing);
    // An edit was refused because the result would not be a valid project (a panel let an
    // out-of-range value through); `reason` names the field, e.g. "material.roughness.factor: ...".
    void editRejected(const QString& reason);

private:
    void push(Project after, const QString& undoText, int mergeId);
    void replaceProject(const Project& project, const QString& path, bool modified);
    void updateMissingFiles();
    void setFilePath(const QString& path);
    void updateModified();
    void rememberDiskIdentity();

    Project m_project;
    QString m_filePath;
    std::optional<FileIdentity> m_diskIdentity; // filePath() as opened or saved
    QString m_sourceAssetPath;
    QUndoStack* m_undoStack = nullptr;
    QStringList m_missingFiles;
    QString m_warnings;
    int m_interactionSerial = 0; // non-zero while an interactive edit is open
    int m_nextInteractionSerial = 1;
    bool m_forcedModified = false; // recovered documents are modified with an empty history
    bool m_lastModified = false; // what modifiedChanged() last said
};

} // namespace facet
