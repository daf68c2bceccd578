#include "ui/document/Document.h"

#include "core/material/PresetPackage.h"

#include "core/gltf/GltfImport.h"
#include "core/project/AssetProject.h"
#include "render/ShaderVariant.h"
#include "ui/docks/MapSlotWidget.h"
#include "ui/document/DocumentCommands.h"

#include <QDebug>
#include <QDir>
#include <QFileInfo>
#include <QJsonObject>
#include <QJsonValue>
#include <QUndoStack>

#include <utility>

namespace facet {

namespace {

// The key a recovery file adds to an ordinary project file: the project it is a copy of.
const QLatin1String kRecoveryKey("facetRecoveryOf");

QString fromStd(const std::string& text)
{
    return QString::fromStdString(text);
}

} // namespace

Document::Document(QObject* parent)
    : QObject(parent)
    , m_project(Project::defaultProject())
    , m_undoStack(new QUndoStack(this))
{
    connect(m_undoStack, &QUndoStack::cleanChanged, this, &Document::updateModified);
}

Document::~Document()
{
    // The commands point back at this document: drop them before the members they use go.
    m_undoStack->clear();
}

// --- Edits -----------------------------------------------------------------------------------

void Document::push(Project after, const QString& undoText, int mergeId)
{
    after.camera = m_project.camera;
    if (after == m_project)
        return;
    std::string problem;
    if (!after.validate(&problem)) {
        const QString reason = fromStd(problem);
        qWarning().noquote() << "Document: refused edit" << undoText << "-" << reason;
        Q_EMIT editRejected(reason);
        return;
    }
    // QUndoStack::push runs redo(), which applies `after` and emits changed().
    m_undoStack->push(new ChangeProjectCommand(this, m_project, std::move(after), undoText, mergeId));
}

void Document::setMaterial(const Material& material, const QString& undoText, int mergeId)
{
    Project after = m_project;
    after.material() = material;
    push(std::move(after), undoText, mergeId);
}

void Document::setEnvironment(const EnvironmentSettings& environment, const QString& undoText, int mergeId)
{
    Project after = m_project;
    after.environment = environment;
    push(std::move(after), undoText, mergeId);
}

void Document::setLights(const std::vector<Light>& lights, const QString& undoText, int mergeId)
{
    Project after = m_project;
    after.lights = lights;
    push(std::move(after), undoText, mergeId);
}

void Document::setView(const ViewSettings& view, const QString& undoText, int mergeId)
{
    Project after = m_project;
    after.view = view;
    push(std::move(after), undoText, mergeId);
}

void Document::setProject(const Project& project, const QString& undoText, int mergeId)
{
    push(project, undoText, mergeId);
}

QString Document::applyPreset(const MaterialPreset& preset)
{
    const Material before = m_project.material();
    Material material = before;
    const Material& look = preset.material;
    material.ior = look.ior;
    material.shading = look.shading;
    for (MapSlot slot : kAllMapSlots)
        material.map(slot).factor = look.map(slot).factor;
    if (hasTextures(look)) {
        // A preset package brings its texture set: every map as the preset has it (an empty
        // slot clears the map it replaces), and how the base colour's alpha is used.
        material.maps = look.maps;
        material.alphaMode = look.alphaMode;
        material.alphaCutoff = look.alphaCutoff;
        material.doubleSided = look.doubleSided;
        material.emissiveStrength = look.emissiveStrength;
    }
    QStringList changed;
    for (MapSlot slot : kAllMapSlots)
        if (material.map(slot).factor != before.map(slot).factor)
            changed << MapSlotWidget::title(slot).toLower();
    if (material.ior != before.ior)
        changed << tr("IOR");
    if (!(material.shading == before.shading))
        changed << tr("shading");
    const QString name = fromStd(before.name);
    const QString presetName = fromStd(preset.displayName);
    if (material == before)
        return tr("“%1” already has %2's values").arg(name, presetName);
    setMaterial(material, tr("Apply Preset %1").arg(presetName));
    QString maps;
    if (hasTextures(look))
        maps = tr("; the preset's maps replace its maps");
    else if (hasTextures(before))
        maps = tr("; its maps kept");
    return tr("Applied %1 to “%2”: %3%4")
        .arg(presetName, name, changed.isEmpty() ? tr("its maps") : changed.join(QStringLiteral(", ")), maps);
}

void Document::setCurrentMaterial(int index)
{
    if (index < 0 || std::size_t(index) >= m_project.materials.size() || index == m_project.currentMaterial)
        return;
    m_project.currentMaterial = index;
    Q_EMIT changed(DocumentChange::CurrentMaterial);
}

void Document::setParts(const std::vector<MeshPart>& parts, const QString& undoText)
{
    Project after = m_project;
    after.parts = parts;
    push(std::move(after), undoText, MergeId::None);
}

void Document::setCamera(const Camera& camera)
{
    if (camera == m_project.camera)
        return;
    m_project.camera = camera;
    Q_EMIT changed(DocumentChange::Camera);
}

void Document::beginInteractiveEdit()
{
    // Nested begins (a slider inside a dialog that opened one) stay in the outer interaction.
    if (m_interactionSerial == 0)
        m_interactionSerial = m_nextInteractionSerial++;
}

void Document::endInteractiveEdit()
{
    m_interactionSerial = 0;
}

void Document::applyUndoableState(const Project& state)
{
    Project next = state;
    next.camera = m_project.camera;
    const DocumentChanges changes = changesBetween(m_project, next);
    m_project = std::move(next);
    // Only an edit that names other files can change which of them are missing: a slider drag
    // does not look at every file on disk at each step (3072 map files: a roughness edit took
    // 29 ms with the check, 11 ms without; tests/bench/document_changes).
    constexpr DocumentChangeKinds namesFiles
        = DocumentChange::MaterialMaps | DocumentChange::EnvironmentSource | DocumentChange::Mesh;
    if (changes & namesFiles)
        updateMissingFiles();
    if (!changes.isEmpty())
        Q_EMIT changed(changes);
}

// --- Files -----------------------------------------------------------------------------------

void Document::replaceProject(const Project& project, const QString& path, bool modified)
{
    m_interactionSerial = 0;
    m_undoStack->clear();
    m_project = project;
    m_forcedModified = modified;
    setFilePath(path);
    m_diskIdentity.reset(); // open() remembers what it read; New and recovery read no such file
    updateMissingFiles();
    updateModified();
    Q_EMIT projectReplaced();
    Q_EMIT changed(DocumentChange::WholeProject);
}

void Document::newProject()
{
    m_warnings.clear();
    m_sourceAssetPath.clear();
    replaceProject(Project::defaultProject(), QString(), false);
}

bool Document::open(const QString& path, QString* error)
{
    std::string problem;
    std::string warning;
    const QString absolute = QFileInfo(path).absoluteFilePath();
    std::optional<Project> project = Project::load(absolute.toStdString(), &problem, &warning);
    if (!project) {
        *error = fromStd(problem);
        return false;
    }
    m_warnings = fromStd(warning).trimmed();
    m_sourceAssetPath.clear();
    replaceProject(*project, absolute, false);
    // What was read (a later writer changes it): a save over another writer's work asks first.
    rememberDiskIdentity();
    return true;
}

bool Document::reload(QString* error)
{
    Q_ASSERT_X(!m_filePath.isEmpty(), "Document::reload", "an untitled document has no file");
    return open(m_filePath, error);
}

bool Document::changedOnDisk() const
{
    if (m_filePath.isEmpty() || !m_diskIdentity)
        return false;
    FileIdentity now;
    // Removed: a save loses nothing (and one that is no file any more refuses the save itself).
    if (!fileIdentity(m_filePath.toStdString(), &now))
        return false;
    return now != *m_diskIdentity;
}

void Document::rememberDiskIdentity()
{
    FileIdentity identity;
    if (!m_filePath.isEmpty() && fileIdentity(m_filePath.toStdString(), &identity))
        m_diskIdentity = identity;
    else
        m_diskIdentity.reset();
}

bool Document::openAsset(const QString& path, QString* error)
{
    std::string problem;
    std::string warning;
    const QString absolute = QDir::cleanPath(QFileInfo(path).absoluteFilePath());
    const std::optional<Project> project = projectFromAsset(absolute.toStdString(), &problem, &warning);
    if (!project) {
        *error = fromStd(problem);
        return false;
    }
    m_warnings = fromStd(warning).trimmed();
    m_sourceAssetPath = absolute;
    replaceProject(*project, QString(), false);
    return true;
}

bool Document::save(QString* error)
{
    Q_ASSERT_X(!m_filePath.isEmpty(), "Document::save", "an untitled document needs saveAs()");
    return saveAs(m_filePath, error);
}

bool Document::saveAs(const QString& path, QString* error)
{
    const QString absolute = QFileInfo(path).absoluteFilePath();
    std::string problem;
    if (!m_project.save(absolute.toStdString(), &problem)) {
        *error = fromStd(problem);
        return false;
    }
    m_sourceAssetPath.clear(); // a project file of its own now
    setFilePath(absolute);
    rememberDiskIdentity();
    m_forcedModified = false;
    m_undoStack->setClean();
    updateModified();
    return true;
}

bool Document::writeRecoveryFile(const QString& recoveryPath, QString* error) const
{
    // Absolute paths (no base folder): the copy stays valid wherever the original was.
    QJsonObject object = m_project.toJson();
    object[kRecoveryKey] = m_filePath;
    std::string problem;
    if (!json::writeObjectFile(recoveryPath.toStdString(), object, &problem)) {
        *error = QStringLiteral("Document::writeRecoveryFile: %1: %2").arg(recoveryPath, fromStd(problem));
        return false;
    }
    return true;
}

QString Document::recoveryOriginalPath(const QString& recoveryPath)
{
    std::string problem;
    const auto object = json::readObjectFile(recoveryPath.toStdString(), Project::kMaxFileBytes, &problem);
    return object ? object->value(kRecoveryKey).toString() : QString();
}

bool Document::recover(const QString& recoveryPath, QString* error)
{
    std::string problem;
    std::optional<QJsonObject> object
        = json::readObjectFile(recoveryPath.toStdString(), Project::kMaxFileBytes, &problem);
    if (!object) {
        *error = QStringLiteral("Document::recover: %1: %2").arg(recoveryPath, fromStd(problem));
        return false;
    }
    const QString original = object->value(kRecoveryKey).toString();
    object->remove(kRecoveryKey);
    std::string warning;
    const std::string baseDir = QFileInfo(recoveryPath).absolutePath().toStdString();
    std::optional<Project> project = Project::fromJson(*object, baseDir, &problem, &warning);
    if (!project) {
        *error = QStringLiteral("Document::recover: %1: %2").arg(recoveryPath, fromStd(problem));
        return false;
    }
    m_warnings = fromStd(warning).trimmed();
    m_sourceAssetPath.clear();
    replaceProject(*project, original, true);
    return true;
}

QString Document::displayName() const
{
    if (!m_filePath.isEmpty())
        return QFileInfo(m_filePath).fileName();
    if (!m_sourceAssetPath.isEmpty())
        return tr("Untitled (%1)").arg(QFileInfo(m_sourceAssetPath).fileName());
    return tr("Untitled");
}

QString Document::exportBaseName() const
{
    const QString path = !m_filePath.isEmpty() ? m_filePath : m_sourceAssetPath;
    if (path.isEmpty())
        return QStringLiteral("material");
    QString name = QFileInfo(path).fileName();
    for (const QLatin1String extension :
        {QLatin1String(".facet.json"), QLatin1String(".json"), QLatin1String(".gltf"), QLatin1String(".glb")})
        if (name.endsWith(extension, Qt::CaseInsensitive)) {
            name.chop(extension.size());
            break;
        }
    return name.isEmpty() ? QStringLiteral("material") : name;
}

QString Document::exportFolder() const
{
    const QString path = !m_filePath.isEmpty() ? m_filePath : m_sourceAssetPath;
    return path.isEmpty() ? QString() : QFileInfo(path).absolutePath();
}

bool Document::isModified() const
{
    return m_forcedModified || !m_undoStack->isClean();
}

void Document::updateModified()
{
    const bool modified = isModified();
    if (modified == m_lastModified)
        return;
    m_lastModified = modified;
    Q_EMIT modifiedChanged(modified);
}

void Document::setFilePath(const QString& path)
{
    if (path == m_filePath)
        return;
    m_filePath = path;
    Q_EMIT filePathChanged(path);
}

// --- Missing files ---------------------------------------------------------------------------

void Document::updateMissingFiles()
{
    QStringList missing;
    const auto check = [&missing](const std::string& path) {
        const QString file = fromStd(path);
        if (!file.isEmpty() && !missing.contains(file) && !QFileInfo::exists(file))
            missing.append(file);
    };
    // An image embedded in a glTF asset is missing when the asset is (core/gltf/GltfImport.h).
    for (const Material& material : m_project.materials)
        for (MapSlot slot : kAllMapSlots)
            check(fileOfImagePath(material.map(slot).path));
    if (!json::isBuiltinSpec(m_project.environment.source))
        check(m_project.environment.source);
    if (!json::isBuiltinSpec(m_project.view.mesh))
        check(m_project.view.mesh);
    if (missing == m_missingFiles)
        return;
    m_missingFiles = missing;
    Q_EMIT missingFilesChanged(m_missingFiles);
}

bool Document::relinkFile(const QString& oldPath, const QString& newPath)
{
    const std::string from = oldPath.toStdString();
    const std::string to = QDir::cleanPath(QFileInfo(newPath).absoluteFilePath()).toStdString();
    Project after = m_project;
    bool found = false;
    for (Material& material : after.materials)
        for (MapSlot slot : kAllMapSlots) {
            MaterialMap& map = material.map(slot);
            if (map.path == from) {
                map.path = to;
                found = true;
            } else if (const auto embedded = parseGltfImageReference(map.path);
                       embedded && embedded->assetPath == from) {
                map.path = gltfImageReference(to, embedded->imageIndex); // the relinked asset's image
                found = true;
            }
        }
    if (after.environment.source == from) {
        after.environment.source = to;
        found = true;
    }
    if (after.view.mesh == from) {
        after.view.mesh = to;
        found = true;
    }
    if (!found)
        return false;
    push(std::move(after), tr("Relink %1").arg(QFileInfo(oldPath).fileName()), MergeId::None);
    return true;
}

} // namespace facet
