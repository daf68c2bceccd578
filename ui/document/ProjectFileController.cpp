#include "ui/document/ProjectFileController.h"

#include "core/gltf/GltfImport.h"
#include "core/project/AssetProject.h"
#include "ui/document/Document.h"
#include "ui/document/MissingFilesDialog.h"
#include "ui/widgets/WindowMessages.h"

#include <QAbstractButton>
#include <QDebug>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QSettings>
#include <QWidget>

namespace facet {

namespace {

const QLatin1String kRecentFilesKey("recentFiles");

QString projectFilter()
{
    return ProjectFileController::tr("Facet projects (*.json);;All files (*)");
}

QString openFilter()
{
    return ProjectFileController::tr(
        "Projects and glTF assets (*.json *.gltf *.glb);;Facet projects (*.json);;"
        "glTF assets (*.gltf *.glb);;All files (*)");
}

QString assetFilter()
{
    return ProjectFileController::tr("glTF assets (*.gltf *.glb);;All files (*)");
}

QString startFolder(const Document* document)
{
    if (!document->filePath().isEmpty())
        return QFileInfo(document->filePath()).absolutePath();
    if (!document->sourceAssetPath().isEmpty())
        return QFileInfo(document->sourceAssetPath()).absolutePath();
    return QDir::homePath();
}

// "2 materials, 5 parts" for the status bar.
QString assetSummary(const Project& project)
{
    const int materials = int(project.materials.size());
    const int parts = int(project.parts.size());
    const QString m = materials == 1 ? ProjectFileController::tr("1 material")
                                     : ProjectFileController::tr("%1 materials").arg(materials);
    const QString p
        = parts == 1 ? ProjectFileController::tr("1 part") : ProjectFileController::tr("%1 parts").arg(parts);
    return m + QStringLiteral(", ") + p;
}

} // namespace

ProjectFileController::ProjectFileController(Document* document, QWidget* dialogParent, QObject* parent)
    : QObject(parent)
    , m_document(document)
    , m_dialogParent(dialogParent)
{
}

bool ProjectFileController::newProject()
{
    if (!maybeSave())
        return false;
    m_document->newProject();
    clearError();
    m_missingFilesMessage.clear();
    Q_EMIT statusMessage(tr("New project"));
    return true;
}

bool ProjectFileController::open()
{
    if (!maybeSave())
        return false;
    const QString path
        = QFileDialog::getOpenFileName(m_dialogParent, tr("Open"), startFolder(m_document), openFilter());
    if (path.isEmpty())
        return false;
    // The question was asked already; do not ask again inside openFile.
    const auto answer = m_unsavedAnswer;
    m_unsavedAnswer = QMessageBox::Discard;
    const bool opened = openFile(path);
    m_unsavedAnswer = answer;
    return opened;
}

bool ProjectFileController::openFile(const QString& path)
{
    if (!maybeSave())
        return false;
    if (isAssetFileName(path.toStdString()))
        return openAssetFile(path);
    QString error;
    if (!m_document->open(path, &error)) {
        reportError(tr("Could not open %1: %2").arg(QDir::toNativeSeparators(path), error),
            tr("Could not open the project: %1").arg(WindowMessages::fromCore(error)));
        return false;
    }
    clearError();
    addRecentFile(m_document->filePath());
    afterOpen();
    return true;
}

bool ProjectFileController::openAssetFile(const QString& path)
{
    QString error;
    if (!m_document->openAsset(path, &error)) {
        reportError(tr("Could not open %1: %2").arg(QDir::toNativeSeparators(path), error),
            tr("Could not open the asset: %1").arg(WindowMessages::fromCore(error)));
        return false;
    }
    clearError();
    addRecentFile(m_document->sourceAssetPath());
    const QString name = QFileInfo(m_document->sourceAssetPath()).fileName();
    QString text = tr("Opened %1 (%2) as a new project").arg(name, assetSummary(m_document->project()));
    if (!m_document->warnings().isEmpty())
        text += QStringLiteral("; ") + WindowMessages::fromCore(m_document->warnings());
    if (!m_document->missingFiles().isEmpty()) {
        // An external image the asset names is not there: the relink dialog finds it.
        m_missingFilesMessage = tr("%n file(s) missing; use File > Relink Missing Files to locate them",
            nullptr, int(m_document->missingFiles().size()));
        text += QStringLiteral(". ") + m_missingFilesMessage;
        Q_EMIT statusMessage(text);
        showMissingFilesDialog();
        return true;
    }
    m_missingFilesMessage.clear();
    Q_EMIT statusMessage(text);
    return true;
}

bool ProjectFileController::importAsset()
{
    const QString path = QFileDialog::getOpenFileName(
        m_dialogParent, tr("Import Asset"), startFolder(m_document), assetFilter());
    if (path.isEmpty())
        return false;
    return importAssetFile(path);
}

bool ProjectFileController::importAssetFile(const QString& path)
{
    const QString absolute = QDir::cleanPath(QFileInfo(path).absoluteFilePath());
    const QString name = QFileInfo(absolute).fileName();
    std::string problem;
    std::string warning;
    const std::optional<GltfAsset> asset = importGltf(absolute.toStdString(), &problem, &warning);
    if (!asset) {
        reportError(tr("Could not import %1: %2")
                        .arg(QDir::toNativeSeparators(absolute), QString::fromStdString(problem)),
            tr("Could not import the asset: %1").arg(WindowMessages::fromCore(problem)));
        return false;
    }
    if (!warning.empty())
        qWarning().noquote() << "facet:" << QString::fromStdString(warning);
    const Project after = withAsset(m_document->project(), *asset, absolute.toStdString());
    std::string invalid;
    if (!after.validate(&invalid)) { // importGltf clamps into range: a failure here is a bug
        reportError(tr("Could not import %1: %2")
                        .arg(QDir::toNativeSeparators(absolute), QString::fromStdString(invalid)),
            tr("Could not import %1: %2").arg(name, QString::fromStdString(invalid)));
        return false;
    }
    m_document->setProject(after, tr("Import %1").arg(name));
    clearError();
    QString text = tr("Imported %1 (%2)").arg(name, assetSummary(after));
    if (!warning.empty())
        text += QStringLiteral("; ") + WindowMessages::fromCore(warning);
    if (!m_document->missingFiles().isEmpty())
        text += tr(". %n file(s) missing; use File > Relink Missing Files to locate them", nullptr,
            int(m_document->missingFiles().size()));
    Q_EMIT statusMessage(text);
    return true;
}

void ProjectFileController::afterOpen()
{
    const QStringList& missing = m_document->missingFiles();
    if (missing.isEmpty()) {
        m_missingFilesMessage.clear();
        QString text = tr("Opened %1").arg(QDir::toNativeSeparators(m_document->filePath()));
        if (!m_document->warnings().isEmpty())
            text += QStringLiteral(" (") + m_document->warnings().section(QLatin1Char('\n'), 0, 0)
                + QStringLiteral(")");
        Q_EMIT statusMessage(text);
        return;
    }
    QStringList names;
    for (const QString& file : missing)
        names.append(QDir::toNativeSeparators(file));
    m_missingFilesMessage = tr("%1: %n file(s) missing: %2. Use File > Relink Missing Files to locate them.",
        nullptr, int(missing.size()))
                                .arg(m_document->displayName(), names.join(QStringLiteral(", ")));
    Q_EMIT statusMessage(m_missingFilesMessage);
    showMissingFilesDialog();
}

MissingFilesDialog* ProjectFileController::missingFilesDialog() const
{
    return m_missingDialog.data();
}

void ProjectFileController::showMissingFilesDialog()
{
    if (!m_missingDialog)
        m_missingDialog = new MissingFilesDialog(m_document, m_dialogParent);
    m_missingDialog->show();
    m_missingDialog->raise();
}

bool ProjectFileController::save()
{
    if (m_document->filePath().isEmpty())
        return saveAs();
    return saveToFile(m_document->filePath());
}

bool ProjectFileController::saveAs()
{
    // An untitled project opened from an asset is offered next to it, named after it.
    const QString& asset = m_document->sourceAssetPath();
    const QString start = !m_document->filePath().isEmpty() ? m_document->filePath()
        : !asset.isEmpty()                                  ? QFileInfo(asset).absoluteDir().filePath(
                                               QFileInfo(asset).completeBaseName() + QStringLiteral(".json"))
                           : QDir::home().filePath(QStringLiteral("untitled.json"));
    QString path
        = QFileDialog::getSaveFileName(m_dialogParent, tr("Save Project As"), start, projectFilter());
    if (path.isEmpty())
        return false;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".json");
    return saveToFile(path);
}

bool ProjectFileController::reload()
{
    if (m_document->filePath().isEmpty() || !maybeSave())
        return false;
    return reloadFromDisk(tr("Reloaded %1 from disk"));
}

bool ProjectFileController::reloadFromDisk(const QString& statusText)
{
    const QString path = QDir::toNativeSeparators(m_document->filePath());
    QString error;
    if (!m_document->reload(&error)) {
        reportError(tr("Could not reload %1: %2").arg(path, error),
            tr("Could not reload the project: %1").arg(WindowMessages::fromCore(error)));
        return false;
    }
    clearError();
    afterOpen();
    Q_EMIT statusMessage(statusText.arg(path));
    return true;
}

bool ProjectFileController::saveToFile(const QString& path)
{
    // Another writer's work in the file is not overwritten without a word (issue 29: two windows
    // on one project, the second save silently replaced the first).
    if (QFileInfo(path).absoluteFilePath() == m_document->filePath() && m_document->changedOnDisk()) {
        ++m_changedOnDiskQuestions;
        QMessageBox::StandardButton answer = QMessageBox::Cancel;
        if (m_changedOnDiskAnswer) {
            answer = *m_changedOnDiskAnswer;
        } else {
            QMessageBox box(QMessageBox::Warning, tr("Project Changed on Disk"),
                tr("%1 was changed on disk since you opened or saved it (by another window or "
                   "program). Overwrite it with this project, or reload it from disk and lose the "
                   "changes made here?")
                    .arg(QDir::toNativeSeparators(path)),
                QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, m_dialogParent);
            box.setObjectName(QStringLiteral("changedOnDiskBox"));
            box.button(QMessageBox::Save)->setText(tr("Overwrite"));
            box.button(QMessageBox::Discard)->setText(tr("Reload From Disk"));
            box.setDefaultButton(QMessageBox::Cancel);
            answer = QMessageBox::StandardButton(box.exec());
        }
        if (answer == QMessageBox::Discard) {
            reloadFromDisk(tr("Reloaded %1 from disk; nothing was saved"));
            return false;
        }
        if (answer != QMessageBox::Save) {
            Q_EMIT statusMessage(tr("Not saved: %1 was changed on disk").arg(QDir::toNativeSeparators(path)));
            return false;
        }
    }
    QString error;
    if (!m_document->saveAs(path, &error)) {
        reportError(tr("Could not save %1: %2").arg(QDir::toNativeSeparators(path), error),
            tr("Could not save the project: %1").arg(WindowMessages::fromCore(error)));
        return false;
    }
    clearError();
    addRecentFile(m_document->filePath());
    Q_EMIT statusMessage(tr("Saved %1").arg(QDir::toNativeSeparators(m_document->filePath())));
    return true;
}

bool ProjectFileController::maybeSave()
{
    if (!m_document->isModified())
        return true;
    QMessageBox::StandardButton answer;
    if (m_unsavedAnswer) {
        answer = *m_unsavedAnswer;
    } else {
        answer = QMessageBox::warning(m_dialogParent, tr("Unsaved Changes"),
            tr("%1 has unsaved changes. Save them?").arg(m_document->displayName()),
            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    }
    switch (answer) {
    case QMessageBox::Save:
        return save();
    case QMessageBox::Discard:
        return true;
    default:
        return false;
    }
}

void ProjectFileController::clearError()
{
    m_lastError.clear();
    Q_EMIT errorCleared();
}

void ProjectFileController::reportError(const QString& precise, const QString& text)
{
    m_lastError = precise;
    qWarning().noquote() << "facet:" << precise;
    Q_EMIT errorReported(text);
    if (!m_errorDialogs)
        return;
    // Non-modal: the window stays usable and nothing waits for a click (tests included).
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Facet"), text, QMessageBox::Ok, m_dialogParent);
    box->setObjectName(QStringLiteral("errorMessageBox"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setWindowModality(Qt::NonModal);
    box->show();
}

QStringList ProjectFileController::recentFiles() const
{
    return QSettings().value(kRecentFilesKey).toStringList();
}

void ProjectFileController::clearRecentFiles()
{
    QSettings().remove(kRecentFilesKey);
    Q_EMIT recentFilesChanged({});
}

void ProjectFileController::addRecentFile(const QString& path)
{
    QStringList files = recentFiles();
    files.removeAll(path);
    files.prepend(path);
    while (files.size() > kMaxRecentFiles)
        files.removeLast();
    QSettings().setValue(kRecentFilesKey, files);
    Q_EMIT recentFilesChanged(files);
}

} // namespace facet
