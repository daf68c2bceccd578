#pragma once
// The CPU side of the viewport (not a widget, no GL): observes the Document, loads what an edit
// made stale and nothing else (the environment and the mesh from the document's asset cache,
// ui/document/DocumentAssets, shared with the Compare view; each material map via core/image/MapImageCache),
// and builds the RenderScene snapshot the viewport's renderer draws (render/SceneFromProject.h). A roughness
// change loads nothing; a new normal map loads that map only (the change names the material and the slot,
// ui/document/DocumentChanges.h: no other slot's file is even looked at on disk); rotating the environment
// changes a number.
//
// Nothing is decoded on the GUI thread. An environment or mesh file loads on a worker (a built-in
// environment, uniform:V or a primitive is made at once): meanwhile the frame keeps the previous
// one (none before the first: pendingAssetLoads() says so and the viewport waits), the status bar
// says what is loading (message), and the frame changes when it arrives.
//
// Maps are decoded off the GUI thread by the document's asset cache too (the edit that assigns
// them returns at once): until a map arrives its slot shows what it showed before (the previous
// version of a reloaded file) or its factor alone; each arrival is announced (mapsArrived) with
// progress (mapLoadProgress). Each file is decoded once for every slot, material, view and
// thumbnail that shows it (DocumentAssets, core/image/MapImageCache); a file beyond the map size
// budget (core/image/MapImage.h MapBudget) is refused from its header, and the slot keeps its
// factor. The frame's assets are assembled as the command line's and the Compare cells' are
// (core/project/ProjectAssets.h placeEnvironment, assignMaps).
//
// Problems (a missing map, an unreadable environment) never stop the frame: the slot falls back
// to its factor, the environment and mesh keep their previous value (or the built-in default),
// and message() names the file and the reason for the status bar; environmentProblem() stays set
// while the project's environment is not the one shown.

#include "core/project/ProjectAssets.h"
#include "render/IblSettings.h"
#include "render/RenderScene.h"
#include "render/SceneFromProject.h"
#include "ui/document/DocumentAssets.h"
#include "ui/document/DocumentChanges.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QString>

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

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

    // `assets` (shared by the window's views) must outlive this; null: a cache of its own.
    explicit SceneController(Document* document, DocumentAssets* assets = nullptr, QObject* parent = nullptr);
    ~SceneController() override; // drops queued map loads, waits for the running ones

    const Document* document() const { return m_document; }
    const ProjectAssets& assets() const { return m_assets; }
    const LoadCounts& loadCounts() const { return m_loadCounts; }
    // Map files being decoded for the project (0: every map the project names is in assets()).
    int pendingMapLoads() const { return int(m_pendingMaps.size()); }
    // The environment and mesh files loading for the project (0, 1 or 2): until they arrive the
    // frame shows the previous ones, or, before the first, nothing (hasScene() is false).
    int pendingAssetLoads() const { return int(m_environmentPending) + int(m_meshPending); }
    // Whether assets() holds an environment and a mesh to draw.
    bool hasScene() const { return !m_assets.environment.isEmpty() && m_assets.mesh != nullptr; }
    DocumentAssets* documentAssets() const { return m_documentAssets; }
    // Why a slot of material `material` shows its factor alone although it names a file (the
    // file is missing, unreadable, beyond the size budget), in core's words; empty when loaded
    // or loading.
    std::string mapProblem(std::size_t material, MapSlot slot) const;

    // Memory: frees the decoded pixels of every loaded map whose textures are complete on the GPU
    // (`onGpu(path, timestamp, colour space)` true for each colour space a slot reads the file
    // in), keeping a stand-in of its size and format (MapImage::withoutPixels: the renderer's
    // variants and shared fetches stay as they were). The viewport calls it after each frame
    // that showed every map; 2K maps are 4-16 MiB each, 4K ones 16-64 MiB. Returns how many
    // maps it released. Draws nothing.
    int releaseMapPixels(
        const std::function<bool(const std::string& path, std::int64_t timestamp, ColorEncoding colorSpace)>&
            onGpu);
    // Decodes again (off the GUI thread, as any load) the released maps among `paths` whose
    // textures the viewport no longer has (a new GL context, another colour space); one the
    // Compare view decoded again meanwhile is taken as it is.
    void reloadMaps(const std::vector<std::string>& paths);

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

    // How a frame is built from the project (FrameRenderer::prepare): by the split sum (the
    // interactive preview) or by `method` at the project's samples for it (the still frame's
    // refinement, ViewportRenderer::refine), with the IBL settings' irradiance source. A view adds
    // its own turntable and wireframe (ui/viewport/ViewState.h).
    SceneOptions sceneOptions(IblMethod method = IblMethod::SplitSum) const;
    // The method the still frame refines to: the project's environment.method (split-sum: none).
    IblMethod refinementMethod() const;

Q_SIGNALS:
    // The scene differs from the last frame: draw again. Not emitted for changes the frame does
    // not show: which material the docks edit, a material's or a light's name, a material that no
    // visible part shows, an edit of a light that stays off. `interactive` is true while a slider drag
    // (Document::interactiveEditOpen) or a turntable is running: the viewport may draw at reduced
    // resolution and refine afterwards.
    void sceneChanged(bool interactive);
    // A problem or a note for the status bar, naming the file, in the window's wording
    // (ui/widgets/WindowMessages.h); the precise message goes to the log.
    void message(const QString& text);
    // environmentProblem() changed.
    void environmentProblemChanged(const QString& problem);
    // A file the scene needs did not load (a problem that stays in view, ui/widgets/ProblemBar.h), or
    // loaded after all (`text` empty). `subject`: "mesh", or "map:" and the map's path.
    void problemChanged(const QString& subject, const QString& text);
    // Decoded maps arrived in assets(): the viewport puts them on the GPU (between frames) and
    // draws them when they are there (ui/viewport/MapUploadScheduler.h). A map that failed is a
    // sceneChanged instead (its slot goes back to its factor).
    void mapsArrived();
    // Map decoding progress: `loaded` of `total` files of the current batch (a batch starts when
    // a load starts with none pending); loaded == total when it is over. `milliseconds`: since
    // the batch started.
    void mapLoadProgress(int loaded, int total, double milliseconds);

private:
    void onDocumentChanged(const DocumentChanges& changes);
    // Whether the frame shows what changed (sceneChanged is emitted only then).
    bool isDrawn(const DocumentChanges& changes) const;
    // Per material of the project: whether a visible part of the mesh in assets() shows it.
    std::vector<bool> shownMaterials() const;
    void loadEnvironment();
    // Takes the project's environment (mesh) from the asset cache when it is there, or its
    // failure: true when assets() changed. While it loads, false (the previous one stays).
    bool takeEnvironment();
    void applyEnvironmentSettings();
    void loadMesh();
    bool takeMesh();
    void onAssetArrived();
    void announceLoading(const std::string& name);
    void loadMaps(const DocumentChanges& changes);
    // Asks the asset cache for `path`: true when its entry is settled (loaded or failed) and now
    // in m_images, false while it loads (it is then pending; its arrival is taken by
    // onAssetArrived). `changed`: whether what the slot shows changed (another image, or another
    // problem); nothing is reported when it did not.
    bool fetchMap(const std::string& path, bool* changed = nullptr);
    // Takes the pending maps that arrived: whether any did.
    bool takeArrivedMaps();
    void publishMaps();
    void report(const std::string& text);
    void setEnvironmentProblem(const QString& problem);

    struct CachedImage {
        std::shared_ptr<const MapImage> image; // null: not loaded yet, or it could not be read
        std::int64_t timestamp = 0; // of the file the image (or the failure) came from
        std::string problem; // why it could not be read (reported once)
    };

    Document* m_document;
    DocumentAssets* m_documentAssets; // the window's, or a child
    QPointer<DocumentAssets> m_documentAssetsAlive; // the window may destroy it first
    ProjectAssets m_assets;
    bool m_environmentPending = false; // m_environmentSource is loading
    bool m_meshPending = false; // m_meshSource is loading
    // The cache entries shown (a changed file's new entry replaces them when it arrives).
    std::shared_ptr<const Environment> m_environmentHeld;
    std::shared_ptr<const AssetCache::LoadedMesh> m_meshHeld;
    std::string m_announced; // the file "Loading …" was said for
    std::map<std::string, CachedImage> m_images; // the map files shown, by path
    std::set<std::string> m_pendingMaps; // the map files being decoded
    int m_batchTotal = 0;
    int m_batchLoaded = 0;
    bool m_batchFailed = false;
    QElapsedTimer m_batchClock;
    std::string m_environmentSource; // the project's source last loaded (or tried)
    QString m_environmentProblem;
    std::string m_meshSource;
    std::uint64_t m_iblKey = 0;
    LoadCounts m_loadCounts;
};

} // namespace facet
