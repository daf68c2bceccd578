#pragma once
// The CPU side of the viewport (not a widget, no GL): observes the Document, loads what an edit
// made stale and nothing else (core/ProjectAssets.h: the environment via Environment::fromSpec, the
// mesh via loadViewMesh, each material map via Image::load), and builds the RenderScene snapshot
// the viewport's renderer draws (render/SceneFromProject.h). A roughness change loads nothing; a
// new normal map loads that map only; rotating the environment changes a number.
//
// Problems (a missing map, an unreadable environment) never stop the frame: the slot falls back
// to its factor, the environment and mesh keep their previous value (or the built-in default),
// and message() names the file and the reason for the status bar; environmentProblem() stays set
// while the project's environment is not the one shown.

#include "core/ProjectAssets.h"
#include "render/IblSettings.h"
#include "render/RenderScene.h"
#include "ui/DocumentChanges.h"

#include <QObject>
#include <QString>

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <map>
#include <string>
#include <memory>

namespace facet {

class Document;
struct IblTextures;

class SceneController : public QObject {
    Q_OBJECT
public:
    // How many loads each kind of change caused (tests check that only stale assets reload).
    struct LoadCounts {
        int environments = 0;
        int meshes = 0;
        int maps = 0;
    };

    explicit SceneController(Document* document, QObject* parent = nullptr);

    const Document* document() const { return m_document; }
    const ProjectAssets& assets() const { return m_assets; }
    const LoadCounts& loadCounts() const { return m_loadCounts; }

    // Identifies the environment image and IBL quality the IBL textures must be made for: it
    // changes when the environment source or the quality changes, not on rotation or intensity.
    std::uint64_t iblKey() const { return m_iblKey; }
    IblSettings iblSettings() const;
    // A short name of the environment in use, for messages ("studio", "forest.exr"). When the
    // project's environment could not be loaded this is the one shown instead (the previous one,
    // or the built-in studio) and environmentProblem() says why.
    QString environmentName() const;
    // Why the project's environment is not the one in use, in the window's wording and naming the
    // file ("night.exr is missing; ..."); empty when it is in use.
    const QString& environmentProblem() const { return m_environmentProblem; }

    // The frame to draw, with the environment's IBL textures (null: background-only lighting).
    RenderScene scene(const std::shared_ptr<const IblTextures>& ibl) const;

    // Viewport-only turntable angles (not part of the project, not undoable): the object turns
    // about +Y by objectTurntableDegrees, the environment by environmentTurntableDegrees on top of
    // the project's rotation.
    void setTurntableAngles(double objectDegrees, double environmentDegrees);
    double objectTurntableDegrees() const { return m_objectTurntableDegrees; }
    // The matrix the mesh of assets() is drawn with (scene().modelMatrix): the object turntable's
    // rotation about +Y, identity without one. Picking (ui/PartPicker.h) casts its rays against it.
    glm::dmat4 modelMatrix() const;
    double environmentTurntableDegrees() const { return m_environmentTurntableDegrees; }

Q_SIGNALS:
    // The scene differs from the last frame: draw again. `interactive` is true while a slider drag
    // (Document::interactiveEditOpen) or a turntable is running: the viewport may draw at reduced
    // resolution and refine afterwards.
    void sceneChanged(bool interactive);
    // A problem or a note for the status bar, naming the file, in the window's wording
    // (ui/WindowMessages.h); the precise message goes to the log.
    void message(const QString& text);
    // environmentProblem() changed.
    void environmentProblemChanged(const QString& problem);

private:
    void onDocumentChanged(DocumentChanges changes);
    void loadEnvironment();
    void applyEnvironmentSettings();
    void loadMesh();
    void loadMaps(bool all);
    void report(const std::string& text);
    void setEnvironmentProblem(const QString& problem);

    struct CachedImage {
        std::shared_ptr<const Image> image; // null: the file could not be read (reported once)
        std::int64_t timestamp = 0;
    };

    Document* m_document;
    ProjectAssets m_assets;
    std::map<std::string, CachedImage> m_images; // the decoded map files, by path
    std::string m_environmentSource; // the project's source last loaded (or tried)
    QString m_environmentProblem;
    std::string m_meshSource;
    std::uint64_t m_iblKey = 0;
    LoadCounts m_loadCounts;
    double m_objectTurntableDegrees = 0.0;
    double m_environmentTurntableDegrees = 0.0;
};

} // namespace facet
