#include "ui/viewport/SceneController.h"

#include "core/gltf/GltfImport.h"
#include "core/project/Project.h"
#include "core/project/ProjectAssets.h"
#include "render/SceneFromProject.h"
#include "render/Turntable.h"
#include "ui/document/Document.h"
#include "ui/document/DocumentAssets.h"
#include "ui/widgets/WindowMessages.h"

#include <QDebug>
#include <QFileInfo>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <functional>
#include <map>

namespace facet {

SceneController::SceneController(Document* document, DocumentAssets* assets, QObject* parent)
    : QObject(parent)
    , m_document(document)
    , m_documentAssets(assets ? assets : new DocumentAssets(this))
    , m_documentAssetsAlive(m_documentAssets)
{
    connect(m_document, &Document::changed, this, &SceneController::onDocumentChanged);
    connect(m_documentAssets, &DocumentAssets::assetArrived, this, &SceneController::onAssetArrived);
    // The environment shown got its pixels (it came from the environment index undecoded): what
    // waits for them (a refinement by fis or reference) can start.
    connect(m_documentAssets, &DocumentAssets::environmentDecoded, this, [this](quint64 contentHash) {
        if (m_environmentHeld && m_environmentHeld->contentHash() == contentHash)
            Q_EMIT sceneChanged(false);
    });
    loadEnvironment();
    loadMesh();
    loadMaps(DocumentChange::WholeProject);
}

void SceneController::onDocumentChanged(const DocumentChanges& changes)
{
    if (changes.testFlag(DocumentChange::EnvironmentSource)
        && m_document->project().environment.source != m_environmentSource)
        loadEnvironment();
    else if (changes
        & (DocumentChangeKinds(DocumentChange::EnvironmentRotation) | DocumentChange::EnvironmentIntensity))
        applyEnvironmentSettings();
    if (changes.testFlag(DocumentChange::IblQuality))
        ++m_iblKey;
    const ViewSettings& view = m_document->project().view;
    if (changes.testFlag(DocumentChange::Mesh)
        && DocumentAssets::meshSource(view.mesh, view.keepUnits) != m_meshSource)
        loadMesh();
    if (changes.testFlag(DocumentChange::MaterialMaps))
        loadMaps(changes);
    if (isDrawn(changes))
        Q_EMIT sceneChanged(m_document->interactiveEditOpen());
}

bool SceneController::isDrawn(const DocumentChanges& changes) const
{
    constexpr DocumentChangeKinds materialKinds
        = DocumentChange::MaterialFactors | DocumentChange::MaterialMaps | DocumentChange::Shading;
    // Which material the docks edit is not drawn: choosing one must not cost a frame; nor is the
    // compare layout (the Compare view draws it). Every other kind but materials and lights is
    // (the environment, the view, the camera, the mesh, parts).
    const DocumentChangeKinds others = DocumentChangeKinds(DocumentChange::WholeProject) & ~materialKinds
        & ~DocumentChangeKinds(DocumentChange::Lights) & ~DocumentChangeKinds(DocumentChange::CurrentMaterial)
        & ~DocumentChangeKinds(DocumentChange::Compare);
    if (changes & others)
        return true;
    const Project& project = m_document->project();
    if (changes & DocumentChange::Lights) {
        if (!changes.namesLights() || changes.lightList().firstShifted() != DocumentChanges::kNone)
            return true;
        // A light's name is not drawn, nor anything of a light that stays off.
        for (const auto& [index, changed] : changes.lightEdits()) {
            const bool off = index < project.lights.size() && !project.lights[index].enabled
                && !changed.testFlag(LightProperty::Enabled);
            if ((changed & ~LightProperties(LightProperty::Name)) && !off)
                return true;
        }
    }
    if (changes & materialKinds) {
        if (!changes.namesMaterials() || changes.materialList().firstShifted() != DocumentChanges::kNone)
            return true;
        // A material's name is not drawn, nor a material that no visible part shows.
        const std::vector<bool> shown = shownMaterials();
        for (const auto& [index, change] : changes.materialEdits()) {
            MaterialChange drawn = change;
            drawn.properties &= ~MaterialFields(MaterialField::Name);
            if (!drawn.isEmpty() && index < shown.size() && shown[index])
                return true;
        }
    }
    return false;
}

std::vector<bool> SceneController::shownMaterials() const
{
    // The parts of the mesh in assets() (the one drawn), with Project::materialOfPart's rule: a
    // mesh without sub-meshes is one part showing material 0.
    const Project& project = m_document->project();
    std::vector<bool> shown(project.materials.size(), false);
    const std::size_t parts = m_assets.mesh ? std::max<std::size_t>(m_assets.mesh->subMeshes.size(), 1) : 1;
    for (std::size_t part = 0; part < parts; ++part)
        if (project.isPartVisible(part))
            shown[std::size_t(project.materialOfPart(part))] = true;
    return shown;
}

void SceneController::report(const std::string& text)
{
    if (text.empty())
        return;
    // The log keeps core's precise message; the window gets its wording (ui/widgets/WindowMessages.h).
    qWarning().noquote() << "facet:" << QString::fromStdString(text);
    Q_EMIT message(WindowMessages::fromCore(text));
}

void SceneController::setEnvironmentProblem(const QString& problem)
{
    if (problem == m_environmentProblem)
        return;
    m_environmentProblem = problem;
    Q_EMIT environmentProblemChanged(problem);
}

void SceneController::loadEnvironment()
{
    m_environmentSource = m_document->project().environment.source;
    ++m_loadCounts.environments;
    // Choosing it again (a relink, a reload) tries a file that failed before.
    m_documentAssets->retry(DocumentAssets::Kind::Environment, m_environmentSource);
    m_environmentPending = true;
    setEnvironmentProblem({}); // the previous choice's problem is not this one's
    if (!takeEnvironment())
        applyEnvironmentSettings(); // the one shown keeps the project's rotation and intensity
}

bool SceneController::takeEnvironment()
{
    if (!m_environmentPending)
        return false;
    const std::string& source = m_environmentSource;
    using Kind = DocumentAssets::Kind;
    const std::shared_ptr<const Environment> loaded = m_documentAssets->environment(source);
    m_documentAssets->setInUse(this, Kind::Environment, {source});
    const bool loading = m_documentAssets->isLoading(Kind::Environment, source);
    if (!loaded && loading) {
        announceLoading(source);
        return false; // the previous one stays until it arrives
    }
    // A file changed on disk comes back in its previous version while the new one loads: take
    // that now and stay pending for the new one.
    m_environmentPending = loading;
    if (!loaded) {
        // Keep showing the previous one (a relink or another choice will replace it), or the
        // built-in studio when there is none; the window says which, and why.
        const std::string error = m_documentAssets->problem(Kind::Environment, source);
        const bool first = m_assets.environment.isEmpty();
        if (first) {
            m_assets.environment = Environment::builtin(Environment::Builtin::Studio);
            ++m_iblKey;
        }
        applyEnvironmentSettings();
        qWarning().noquote() << "facet: Environment:" << QString::fromStdString(error);
        const QString problem = WindowMessages::fromCore(error);
        setEnvironmentProblem(problem);
        Q_EMIT message(WindowMessages::environmentNotUsed(problem, environmentName()));
        return first;
    } else {
        if (loaded == m_environmentHeld)
            return false; // the entry shown already
        m_environmentHeld = loaded;
        report(m_documentAssets->warning(Kind::Environment, source));
        setEnvironmentProblem({});
        m_assets.environment = *loaded;
    }
    ++m_iblKey;
    applyEnvironmentSettings();
    return true;
}

void SceneController::applyEnvironmentSettings()
{
    placeEnvironment(m_assets.environment, m_document->project().environment);
}

void SceneController::loadMesh()
{
    const ViewSettings& view = m_document->project().view;
    m_meshSource = DocumentAssets::meshSource(view.mesh, view.keepUnits);
    ++m_loadCounts.meshes;
    m_documentAssets->retry(DocumentAssets::Kind::Mesh, m_meshSource);
    m_meshPending = true;
    takeMesh();
}

bool SceneController::takeMesh()
{
    if (!m_meshPending)
        return false;
    const std::string& source = m_meshSource;
    using Kind = DocumentAssets::Kind;
    const std::shared_ptr<const AssetCache::LoadedMesh> loaded = m_documentAssets->mesh(source);
    m_documentAssets->setInUse(this, Kind::Mesh, {source});
    const bool loading = m_documentAssets->isLoading(Kind::Mesh, source);
    if (!loaded && loading) {
        announceLoading(source);
        return false;
    }
    m_meshPending = loading; // as for the environment: a previous version now, the new one later
    if (!loaded) {
        const std::string problem = "Mesh: " + m_documentAssets->problem(Kind::Mesh, source);
        report(problem);
        Q_EMIT problemChanged(QStringLiteral("mesh"), WindowMessages::fromCore(problem));
        if (m_assets.mesh)
            return false;
        const auto sphere = m_documentAssets->mesh("sphere");
        Q_ASSERT(sphere);
        m_assets.mesh = sphere->mesh;
        m_assets.meshKey = sphere->key;
        return true;
    }
    if (loaded == m_meshHeld)
        return false;
    m_meshHeld = loaded;
    Q_EMIT problemChanged(QStringLiteral("mesh"), {});
    report(m_documentAssets->warning(Kind::Mesh, source));
    m_assets.mesh = loaded->mesh;
    m_assets.meshKey = loaded->key;
    return true;
}

void SceneController::announceLoading(const std::string& name)
{
    // Once a load: asking again on every arrival (a grid cell's environment) would repeat it over
    // the other views' messages.
    if (name == m_announced)
        return;
    m_announced = name;
    const QString source = QString::fromStdString(name);
    Q_EMIT message(
        WindowMessages::loading(json::isBuiltinSpec(name) ? source : QFileInfo(source).fileName()));
}

void SceneController::onAssetArrived()
{
    if (!m_pendingMaps.empty())
        takeArrivedMaps();
    const int pendingBefore = pendingAssetLoads();
    const bool environment = takeEnvironment();
    const bool mesh = takeMesh();
    if (pendingAssetLoads() == 0)
        m_announced.clear();
    // A frame when something new shows, and when the last load settled (a failure too): a
    // frame after it is the project's settled look (`facet --screenshot` waits for one).
    if (environment || mesh || (pendingBefore > 0 && pendingAssetLoads() == 0))
        Q_EMIT sceneChanged(false);
}

SceneController::~SceneController()
{
    if (!m_documentAssetsAlive.isNull())
        m_documentAssets->forgetUser(this);
}

void SceneController::loadMaps(const DocumentChanges& changes)
{
    // Every material's maps; a file used by several slots or materials is loaded once (by path).
    // Only the slots whose file the change names are looked at on disk: the others keep what they
    // show, so a new normal map for material 1 never re-reads material 0's maps. A change that
    // names no slot (files changed on disk: kinds alone) looks at every file and loads those whose
    // modification time changed; a new project (WholeProject) looks at every file and tries again
    // those that failed.
    using Kind = DocumentAssets::Kind;
    const bool all = changes == DocumentChanges(DocumentChange::WholeProject);
    const Project& project = m_document->project();
    std::map<std::string, CachedImage> images;
    std::vector<std::string> lookAt;
    // A file chosen (again) for a slot: a named edit of a material that kept its place (a
    // material that moved, was added or removed is reported as changed in full).
    const std::size_t firstShifted
        = changes.namesMaterials() ? changes.materialList().firstShifted() : DocumentChanges::kNone;
    std::set<std::string> chosen;
    if (changes.namesMaterials())
        for (const auto& [index, change] : changes.materialEdits())
            if (index < project.materials.size() && index < firstShifted)
                for (MapSlot slot : kAllMapSlots)
                    if (change.map(slot).testFlag(MapProperty::Path))
                        chosen.insert(project.materials[index].map(slot).path);
    for (std::size_t m = 0; m < project.materials.size(); ++m) {
        const MaterialChange changed = changes.material(m);
        for (MapSlot slot : kAllMapSlots) {
            const MaterialMap& map = project.materials[m].map(slot);
            if (!map.hasTexture() || images.count(map.path))
                continue;
            const bool named = changed.map(slot).testFlag(MapProperty::Path);
            const auto previous = m_images.find(map.path);
            if (!all && !named && previous != m_images.end()) {
                images.emplace(map.path, previous->second); // unchanged: shown (or loading) as it is
                continue;
            }
            // Until a new decode arrives the slot shows the previous version of the file, if any,
            // and a file that failed stays failed without being reported again. Chosen again (or a
            // new project), a file that failed is tried again and its problem said again.
            CachedImage shown = previous != m_images.end() ? previous->second : CachedImage {};
            if (all || chosen.count(map.path)) {
                m_documentAssets->retry(Kind::Map, map.path);
                shown.problem.clear();
            }
            images.emplace(map.path, std::move(shown));
            lookAt.push_back(map.path);
        }
    }
    // A load of a file the project no longer names is not waited for.
    std::erase_if(m_pendingMaps, [&](const std::string& path) { return !images.count(path); });
    // A file that failed and that no slot names any more is no longer a problem.
    for (const auto& [path, entry] : m_images)
        if (!entry.problem.empty() && !images.count(path))
            Q_EMIT problemChanged(QStringLiteral("map:") + QString::fromStdString(path), {});
    m_images = std::move(images);
    std::set<std::string> inUse;
    for (const auto& entry : m_images)
        inUse.insert(entry.first);
    m_documentAssets->setInUse(this, Kind::Map, std::move(inUse));
    bool taken = false;
    for (const std::string& path : lookAt) {
        bool changed = false;
        if (fetchMap(path, &changed) && changed)
            taken = true;
    }
    publishMaps();
    if (m_pendingMaps.empty() && m_batchTotal > 0) {
        // Every load of the batch settled or went stale: the batch is over.
        m_batchLoaded = m_batchTotal;
        Q_EMIT mapLoadProgress(m_batchLoaded, m_batchTotal, double(m_batchClock.nsecsElapsed()) / 1e6);
        m_batchTotal = m_batchLoaded = 0;
    }
    if (taken)
        Q_EMIT mapsArrived(); // entries the cache held already (another view's, an earlier project's)
}

bool SceneController::fetchMap(const std::string& path, bool* changed)
{
    using Kind = DocumentAssets::Kind;
    const int loadsBefore = m_documentAssets->loads(Kind::Map);
    const std::shared_ptr<const MapImage> image = m_documentAssets->map(path);
    if (m_documentAssets->loads(Kind::Map) > loadsBefore)
        ++m_loadCounts.maps;
    if (m_documentAssets->isLoading(Kind::Map, path)) {
        if (m_pendingMaps.empty() && m_batchTotal == 0) {
            m_batchLoaded = 0;
            m_batchFailed = false;
            m_batchClock.start();
        }
        if (m_pendingMaps.insert(path).second) {
            ++m_batchTotal;
            Q_EMIT mapLoadProgress(m_batchLoaded, m_batchTotal, double(m_batchClock.nsecsElapsed()) / 1e6);
        }
        return false;
    }
    m_pendingMaps.erase(path);
    CachedImage& entry = m_images[path];
    const std::int64_t timestamp = m_documentAssets->mapTimestamp(path);
    const std::string problem = image ? std::string() : m_documentAssets->problem(Kind::Map, path);
    const bool newProblem = problem != entry.problem;
    // Another version of the file, or the first: what to say. The same file decoded again (its
    // pixels released, then wanted by a view without the texture) is taken silently.
    const bool newFile = image && (!entry.image || entry.timestamp != timestamp);
    if (changed)
        *changed = image != entry.image || newProblem;
    entry.image = image;
    entry.timestamp = timestamp;
    entry.problem = problem;
    if (!newFile && !newProblem)
        return true; // what the slot shows already, or the same file again: nothing to say
    const QString subject = QStringLiteral("map:") + QString::fromStdString(path);
    if (!image) {
        // Name the slot that wanted it (the first one, when a packed file feeds several).
        std::string slotName = "Texture";
        for (const Material& material : m_document->project().materials)
            for (MapSlot slot : kAllMapSlots)
                if (slotName == "Texture" && material.map(slot).path == path)
                    slotName = toString(slot);
        m_batchFailed = true;
        report(slotName + " map: " + entry.problem);
        Q_EMIT problemChanged(subject, WindowMessages::fromCore(slotName + " map: " + entry.problem));
    } else {
        Q_EMIT problemChanged(subject, {});
        report(m_documentAssets->warning(Kind::Map, path));
    }
    return true;
}

bool SceneController::takeArrivedMaps()
{
    using Kind = DocumentAssets::Kind;
    std::vector<std::string> arrived;
    for (const std::string& path : m_pendingMaps)
        if (!m_documentAssets->isLoading(Kind::Map, path))
            arrived.push_back(path);
    bool loaded = false;
    bool failed = false;
    int settled = 0;
    for (const std::string& path : arrived) {
        if (!fetchMap(path))
            continue; // the file changed again meanwhile: its newer version is loading
        ++settled;
        (m_images[path].image ? loaded : failed) = true;
    }
    if (settled == 0)
        return false;
    m_batchLoaded += settled;
    publishMaps();
    Q_EMIT mapLoadProgress(
        std::min(m_batchLoaded, m_batchTotal), m_batchTotal, double(m_batchClock.nsecsElapsed()) / 1e6);
    if (m_pendingMaps.empty())
        m_batchTotal = m_batchLoaded = 0;
    if (loaded)
        Q_EMIT mapsArrived();
    if (failed)
        Q_EMIT sceneChanged(m_document->interactiveEditOpen()); // its slot goes back to its factor
    return true;
}

void SceneController::publishMaps()
{
    assignMaps(m_assets, m_document->project(), [this](std::size_t, MapSlot, const MaterialMap& map) {
        const auto found = m_images.find(map.path);
        return found == m_images.end()
            ? LoadedMapImage {}
            : LoadedMapImage {found->second.image, map.path, found->second.timestamp};
    });
}

int SceneController::releaseMapPixels(
    const std::function<bool(const std::string& path, std::int64_t timestamp, ColorEncoding colorSpace)>&
        onGpu)
{
    int released = 0;
    for (auto& [path, entry] : m_images) {
        if (!entry.image || !entry.image->hasPixels() || m_pendingMaps.count(path))
            continue;
        bool everywhere = true;
        for (const Material& material : m_document->project().materials)
            for (const MaterialMap& map : material.maps)
                if (map.hasTexture() && map.path == path && !onGpu(path, entry.timestamp, map.colorSpace))
                    everywhere = false;
        if (!everywhere)
            continue;
        // One stand-in per file: the slots that share the file still share one image, and the
        // asset cache holds the same one (its pixels are gone for every view).
        std::shared_ptr<const MapImage> standIn = m_documentAssets->releaseMapPixels(path, entry.image.get());
        entry.image = standIn ? std::move(standIn)
                              : std::make_shared<const MapImage>(MapImage::withoutPixels(*entry.image));
        ++released;
    }
    if (released > 0)
        publishMaps();
    return released;
}

void SceneController::reloadMaps(const std::vector<std::string>& paths)
{
    bool taken = false;
    for (const std::string& path : paths) {
        const auto found = m_images.find(path);
        if (found == m_images.end() || !found->second.image || found->second.image->hasPixels()
            || m_pendingMaps.count(path))
            continue;
        // A copy with pixels in the cache (the Compare view had it decoded again) is taken at
        // once; else it is decoded again.
        if (const std::shared_ptr<const MapImage> cached = m_documentAssets->map(path);
            !cached || !cached->hasPixels())
            m_documentAssets->reload(DocumentAssets::Kind::Map, path);
        bool changed = false;
        if (fetchMap(path, &changed) && changed)
            taken = true;
    }
    if (!taken)
        return;
    // Decoded again by the Compare view meanwhile: there at once. Announced after the frame that
    // asked (the viewport calls this while it prepares one).
    publishMaps();
    QMetaObject::invokeMethod(
        this, [this] { Q_EMIT mapsArrived(); }, Qt::QueuedConnection);
}

std::string SceneController::mapProblem(std::size_t material, MapSlot slot) const
{
    const Project& project = m_document->project();
    if (material >= project.materials.size())
        return {};
    const MaterialMap& map = project.materials[material].map(slot);
    const auto found = map.hasTexture() ? m_images.find(map.path) : m_images.end();
    return found == m_images.end() || m_pendingMaps.count(map.path) ? std::string() : found->second.problem;
}

IblSettings SceneController::iblSettings() const
{
    return IblSettings::preset(m_document->project().environment.quality);
}

QString SceneController::environmentName() const
{
    // The environment in use, which is not the project's when that one could not be loaded.
    const std::string& name = m_assets.environment.name();
    const QString source = QString::fromStdString(name);
    return json::isBuiltinSpec(name) ? source : QFileInfo(source).fileName();
}

SceneOptions SceneController::sceneOptions(IblMethod method) const
{
    SceneOptions options = sceneOptionsFor(iblSettings(), /*referenceView=*/false);
    options.iblMethod = method;
    return options;
}

IblMethod SceneController::refinementMethod() const
{
    return m_document->project().environment.method;
}

} // namespace facet
