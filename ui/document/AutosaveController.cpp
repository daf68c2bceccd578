#include "ui/document/AutosaveController.h"

#include "ui/document/Document.h"
#include "ui/widgets/WindowMessages.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDebug>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>

#include <algorithm>

namespace facet {

namespace {

const QLatin1String kRecoverySuffix(".facet-recovery.json");

QString lockPathFor(const QString& recoveryPath)
{
    QString path = recoveryPath;
    path.chop(kRecoverySuffix.size());
    return path + QStringLiteral(".lock");
}

} // namespace

QString AutosaveController::defaultDirectory()
{
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/recovery");
}

AutosaveController::AutosaveController(Document* document, const QString& directory, QObject* parent)
    : QObject(parent)
    , m_document(document)
    , m_directory(directory.isEmpty() ? defaultDirectory() : directory)
{
    QDir().mkpath(m_directory);
    const QString base = QStringLiteral("%1/session-%2-%3")
                             .arg(m_directory)
                             .arg(QCoreApplication::applicationPid())
                             .arg(QDateTime::currentMSecsSinceEpoch());
    m_recoveryPath = base + kRecoverySuffix;
    m_lock = std::make_unique<QLockFile>(lockPathFor(m_recoveryPath));
    m_lock->setStaleLockTime(0); // only a dead owner makes a lock stale, never its age
    if (!m_lock->tryLock(0))
        m_lock.reset(); // still autosaves; others may then offer this file after a crash only

    m_timer.setInterval(kIntervalMs);
    connect(&m_timer, &QTimer::timeout, this, &AutosaveController::autosaveNow);
    connect(m_document, &Document::modifiedChanged, this, &AutosaveController::onModifiedChanged);
    connect(m_document, &Document::changed, this, [this] { m_changedSinceAutosave = true; });
    connect(m_document, &Document::filePathChanged, this, [this] { m_changedSinceAutosave = true; });
    onModifiedChanged(m_document->isModified());
}

AutosaveController::~AutosaveController()
{
    removeOwnFile();
}

void AutosaveController::onModifiedChanged(bool modified)
{
    if (modified) {
        m_changedSinceAutosave = true;
        if (!m_timer.isActive())
            m_timer.start();
    } else {
        m_timer.stop();
        removeOwnFile(); // saved, or back at the saved state: nothing to recover
    }
}

bool AutosaveController::autosaveNow()
{
    if (!m_document->isModified() || !m_changedSinceAutosave)
        return true;
    QString error;
    if (!m_document->writeRecoveryFile(m_recoveryPath, &error)) {
        qWarning().noquote() << "facet: autosave failed:" << error;
        Q_EMIT failed(tr("Autosave failed: %1").arg(WindowMessages::fromCore(error)));
        return false;
    }
    m_changedSinceAutosave = false;
    Q_EMIT autosaved(m_recoveryPath);
    return true;
}

void AutosaveController::removeOwnFile()
{
    QFile::remove(m_recoveryPath);
}

QStringList AutosaveController::orphanedRecoveryFiles() const
{
    QFileInfoList files
        = QDir(m_directory)
              .entryInfoList({QStringLiteral("session-*") + kRecoverySuffix}, QDir::Files, QDir::Time);
    QStringList orphans;
    for (const QFileInfo& file : files) {
        const QString path = file.absoluteFilePath();
        if (path == QFileInfo(m_recoveryPath).absoluteFilePath())
            continue;
        QLockFile lock(lockPathFor(path));
        lock.setStaleLockTime(0);
        if (!lock.tryLock(0))
            continue; // its session is still running
        lock.unlock();
        orphans.append(path);
    }
    return orphans;
}

void AutosaveController::discard(const QString& recoveryPath)
{
    QFile::remove(recoveryPath);
}

} // namespace facet
