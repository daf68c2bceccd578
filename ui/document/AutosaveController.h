#pragma once
// Crash recovery. While the document has unsaved changes, a copy is written every kIntervalMs to
// this session's recovery file (Document::writeRecoveryFile) under
// QStandardPaths::AppDataLocation/recovery. Saving, discarding or a clean exit removes it. Each
// session holds a QLockFile next to its file, so a file whose lock nobody holds any more was left
// by a session that crashed: orphanedRecoveryFiles() lists those for the start-up offer, and
// several Facet windows running at once never take each other's file.

#include <QLockFile>
#include <QObject>
#include <QString>
#include <QStringList>
#include <QTimer>

#include <memory>

namespace facet {

class Document;

class AutosaveController : public QObject {
    Q_OBJECT
public:
    static constexpr int kIntervalMs = 30000;

    // `directory` empty: defaultDirectory().
    explicit AutosaveController(Document* document, const QString& directory = {}, QObject* parent = nullptr);
    ~AutosaveController() override; // a clean exit: removes this session's recovery file

    static QString defaultDirectory();
    QString directory() const { return m_directory; }
    // This session's recovery file (exists only after an autosave with unsaved changes).
    QString recoveryFilePath() const { return m_recoveryPath; }

    void setIntervalMs(int milliseconds) { m_timer.setInterval(milliseconds); }
    // Writes the recovery file now if the document is modified; false (and failed()) on error.
    bool autosaveNow();

    // Recovery files of sessions that ended without removing theirs (crashed), newest first.
    QStringList orphanedRecoveryFiles() const;
    // Deletes a recovery file (after it was recovered or declined).
    static void discard(const QString& recoveryPath);

Q_SIGNALS:
    void autosaved(const QString& recoveryPath);
    void failed(const QString& message);

private:
    void onModifiedChanged(bool modified);
    void removeOwnFile();

    Document* m_document;
    QString m_directory;
    QString m_recoveryPath;
    std::unique_ptr<QLockFile> m_lock;
    QTimer m_timer;
    bool m_changedSinceAutosave = false;
};

} // namespace facet
