#include "ui/ProjectFileController.h"

#include "ui/Document.h"
#include "ui/MissingFilesDialog.h"
#include "ui/WindowMessages.h"

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
    m_lastError.clear();
    m_missingFilesMessage.clear();
    Q_EMIT statusMessage(tr("New project"));
    return true;
}

bool ProjectFileController::open()
{
    if (!maybeSave())
        return false;
    const QString start = m_document->filePath().isEmpty() ? QDir::homePath()
                                                           : QFileInfo(m_document->filePath()).absolutePath();
    const QString path
        = QFileDialog::getOpenFileName(m_dialogParent, tr("Open Project"), start, projectFilter());
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
    QString error;
    if (!m_document->open(path, &error)) {
        reportError(tr("Could not open %1: %2").arg(QDir::toNativeSeparators(path), error),
            tr("Could not open the project: %1").arg(WindowMessages::fromCore(error)));
        return false;
    }
    m_lastError.clear();
    addRecentFile(m_document->filePath());
    afterOpen();
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
    const QString start = m_document->filePath().isEmpty()
        ? QDir::home().filePath(QStringLiteral("untitled.json"))
        : m_document->filePath();
    QString path
        = QFileDialog::getSaveFileName(m_dialogParent, tr("Save Project As"), start, projectFilter());
    if (path.isEmpty())
        return false;
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".json");
    return saveToFile(path);
}

bool ProjectFileController::saveToFile(const QString& path)
{
    QString error;
    if (!m_document->saveAs(path, &error)) {
        reportError(tr("Could not save %1: %2").arg(QDir::toNativeSeparators(path), error),
            tr("Could not save the project: %1").arg(WindowMessages::fromCore(error)));
        return false;
    }
    m_lastError.clear();
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
