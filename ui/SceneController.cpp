#include "ui/SceneController.h"

#include "core/GltfImport.h"
#include "core/Project.h"
#include "render/SceneFromProject.h"
#include "ui/Document.h"
#include "ui/WindowMessages.h"

#include <QDateTime>
#include <QDebug>
#include <QFileInfo>

#include <glm/gtc/matrix_transform.hpp>

#include <functional>
#include <map>

namespace facet {

namespace {

std::int64_t modificationTime(const std::string& path)
{
    return QFileInfo(QString::fromStdString(path)).lastModified().toMSecsSinceEpoch();
}

} // namespace

SceneController::SceneController(Document* document, QObject* parent)
    : QObject(parent)
    , m_document(document)
{
    connect(m_document, &Document::changed, this, &SceneController::onDocumentChanged);
    loadEnvironment();
    loadMesh();
    loadMaps(true);
}

void SceneController::onDocumentChanged(DocumentChanges changes)
{
    // Which material the docks edit is not drawn: choosing one must not cost a frame.
    if (changes == DocumentChanges(DocumentChange::CurrentMaterial))
        return;
    if (changes.testFlag(DocumentChange::EnvironmentSource)
        && m_document->project().environment.source != m_environmentSource)
        loadEnvironment();
    else if (changes
        & (DocumentChanges(DocumentChange::EnvironmentRotation) | DocumentChange::EnvironmentIntensity))
        applyEnvironmentSettings();
    if (changes.testFlag(DocumentChange::IblQuality))
        ++m_iblKey;
    if (changes.testFlag(DocumentChange::Mesh) && m_document->project().view.mesh != m_meshSource)
        loadMesh();
    if (changes.testFlag(DocumentChange::MaterialMaps))
        loadMaps(changes == DocumentChanges(DocumentChange::WholeProject));
    Q_EMIT sceneChanged(m_document->interactiveEditOpen());
}

void SceneController::report(const std::string& text)
{
    if (text.empty())
        return;
    // The log keeps core's precise message; the window gets its wording (ui/WindowMessages.h).
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
    const std::string& source = m_document->project().environment.source;
    std::string error;
    std::string warning;
    ++m_loadCounts.environments;
    std::optional<Environment> environment = Environment::fromSpec(source, &error, &warning);
    if (!environment) {
        report("Environment: " + error);
        if (!m_assets.environment.isEmpty()) {
            // Keep showing the previous one; a relink or another choice will replace it.
            m_environmentSource = source;
            applyEnvironmentSettings();
            setEnvironmentProblem(WindowMessages::fromCore(error));
            return;
        }
        environment = Environment::builtin(Environment::Builtin::Studio);
        m_assets.environment = std::move(*environment);
        m_environmentSource = source;
        ++m_iblKey;
        applyEnvironmentSettings();
        setEnvironmentProblem(WindowMessages::fromCore(error));
        return;
    }
    report(warning);
    setEnvironmentProblem({});
    m_assets.environment = std::move(*environment);
    m_environmentSource = source;
    ++m_iblKey;
    applyEnvironmentSettings();
}

void SceneController::applyEnvironmentSettings()
{
    const EnvironmentSettings& settings = m_document->project().environment;
    m_assets.environment.setRotationDegrees(settings.rotationDegrees);
    m_assets.environment.setIntensity(settings.intensity);
}

void SceneController::loadMesh()
{
    const std::string& source = m_document->project().view.mesh;
    std::string error;
    std::string warning;
    ++m_loadCounts.meshes;
    std::optional<Mesh> mesh = loadViewMesh(source, &error, &warning);
    m_meshSource = source;
    if (!mesh) {
        report("Mesh: " + error);
        if (m_assets.mesh)
            return;
        mesh = loadViewMesh("sphere", &error);
        Q_ASSERT(mesh);
    } else {
        report(warning);
    }
    m_assets.mesh = std::make_shared<const Mesh>(std::move(*mesh));
    // A new key for every load: the renderer uploads this mesh once and never again.
    m_assets.meshKey = std::hash<std::string> {}(source) ^ std::uint64_t(modificationTime(source))
        ^ (std::uint64_t(m_loadCounts.meshes) << 48);
}

void SceneController::loadMaps(bool all)
{
    // Every material's maps; a file used by several slots or materials is decoded once (m_images,
    // by path) and reloaded only when its modification time changes.
    const Project& project = m_document->project();
    std::map<std::string, CachedImage> images;
    m_assets.maps.assign(project.materials.size(), {});
    for (std::size_t m = 0; m < project.materials.size(); ++m) {
        for (MapSlot slot : kAllMapSlots) {
            const MaterialMap& map = project.materials[m].map(slot);
            if (!map.hasTexture())
                continue;
            const std::int64_t timestamp = modificationTime(fileOfImagePath(map.path));
            auto cached = images.find(map.path);
            if (cached == images.end()) {
                const auto previous = m_images.find(map.path);
                if (!all && previous != m_images.end() && previous->second.timestamp == timestamp
                    && (previous->second.image || timestamp == 0)) {
                    cached = images.emplace(map.path, previous->second).first; // already loaded (or reported missing)
                } else {
                    CachedImage entry;
                    entry.timestamp = timestamp;
                    ++m_loadCounts.maps;
                    std::string error;
                    ImageLoadStats stats;
                    std::optional<Image> image = Image::load(map.path, &error, &stats);
                    if (!image) {
                        report(std::string(toString(slot)) + " map: " + error);
                    } else {
                        if (stats.total() > 0)
                            report(map.path + ": replaced " + std::to_string(stats.total())
                                + " NaN, Inf or negative samples");
                        entry.image = std::make_shared<const Image>(std::move(*image));
                    }
                    cached = images.emplace(map.path, std::move(entry)).first;
                }
            }
            LoadedMapImage& loaded = m_assets.maps[m][std::size_t(slot)];
            loaded.image = cached->second.image;
            loaded.path = map.path;
            loaded.timestamp = timestamp;
        }
    }
    m_images = std::move(images);
}

IblSettings SceneController::iblSettings() const
{
    const auto settings = IblSettings::preset(toString(m_document->project().environment.quality));
    Q_ASSERT(settings);
    return settings.value_or(IblSettings {});
}

QString SceneController::environmentName() const
{
    // The environment in use, which is not the project's when that one could not be loaded.
    const std::string& name = m_assets.environment.name();
    const QString source = QString::fromStdString(name);
    return json::isBuiltinSpec(name) ? source : QFileInfo(source).fileName();
}

RenderScene SceneController::scene(const std::shared_ptr<const IblTextures>& ibl) const
{
    const IblSettings settings = iblSettings();
    SceneOptions options;
    options.irradianceFromSH = settings.irradiance == IblSettings::Irradiance::SH;
    RenderScene scene = sceneFromProject(m_document->project(), m_assets, ibl, options);
    if (m_objectTurntableDegrees != 0.0)
        scene.modelMatrix = modelMatrix();
    scene.environment.rotationDegrees += m_environmentTurntableDegrees;
    return scene;
}

glm::dmat4 SceneController::modelMatrix() const
{
    return glm::rotate(glm::dmat4(1.0), glm::radians(m_objectTurntableDegrees), glm::dvec3(0.0, 1.0, 0.0));
}

void SceneController::setTurntableAngles(double objectDegrees, double environmentDegrees)
{
    if (objectDegrees == m_objectTurntableDegrees && environmentDegrees == m_environmentTurntableDegrees)
        return;
    m_objectTurntableDegrees = objectDegrees;
    m_environmentTurntableDegrees = environmentDegrees;
    Q_EMIT sceneChanged(true);
}

} // namespace facet
