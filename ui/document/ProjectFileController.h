#pragma once
// File > New, Open, Open Recent, Import Asset, Save, Save As and the question before unsaved
// changes are lost
// (not a widget: it owns no window, only the dialogs it opens on `dialogParent`). Every failure
// reaches the user as a message naming the file and the reason, in the window's wording:
// errorReported() (MainWindow puts it in the status bar) and a non-modal message box; nothing is
// silently skipped. After an open
// with missing files it says so and shows the MissingFilesDialog.
//
// glTF assets (.gltf, .glb): Open (and Open Recent, and `facet PATH.glb`) makes an untitled
// project of one (Document::openAsset); Import Asset puts one into the current project, replacing
// its mesh, materials and parts in one undo step and keeping the environment, lights, camera and
// view settings (core/project/AssetProject.h withAsset). The import's notes (missing images, extensions
// Facet does not read) reach the status bar in the window's wording.
//
// Tests drive the *File(path) functions, which show no file dialog, and answer the unsaved-changes
// question with setUnsavedChangesAnswer() so that no modal box waits for a click.

#include <QMessageBox>
#include <QObject>
#include <QPointer>
#include <QString>
#include <QStringList>

#include <optional>

class QWidget;

namespace facet {

class Document;
class MissingFilesDialog;

class ProjectFileController : public QObject {
    Q_OBJECT
public:
    static constexpr int kMaxRecentFiles = 8;

    ProjectFileController(Document* document, QWidget* dialogParent, QObject* parent = nullptr);

    // Menu entry points (may show dialogs). Each returns whether it went ahead.
    bool newProject();
    bool open(); // asks for a file (a project or a glTF asset)
    bool importAsset(); // asks for a glTF asset
    bool save(); // Save As when untitled
    bool saveAs(); // asks for a file
    // File > Reload From Disk: the project file as it is on disk now (after the unsaved-changes
    // question). False for an untitled project.
    bool reload();
    // The same without file dialogs. openFile asks about unsaved changes first (maybeSave); a
    // .gltf / .glb opens as an untitled project made from the asset.
    bool openFile(const QString& path);
    // Replaces the current project's mesh, materials and parts with the asset's: one undo step
    // "Import <file name>". No question about unsaved changes (nothing is lost: Undo).
    bool importAssetFile(const QString& path);
    // Saving over the document's own file when another writer changed it since it was opened or
    // saved (Document::changedOnDisk: a second window, a text editor, a sync tool) asks first:
    // Overwrite (QMessageBox::Save), Reload From Disk (QMessageBox::Discard: this window's
    // changes are dropped and the file's read) or Cancel (the file and the document unchanged).
    bool saveToFile(const QString& path);
    // Asks "Save changes to X?" when the document is modified: Save (then true if saved), Discard
    // (true), Cancel (false). True at once when unmodified.
    bool maybeSave();
    // Test hook: answer maybeSave() with `answer` instead of asking (nullopt: ask again).
    void setUnsavedChangesAnswer(std::optional<QMessageBox::StandardButton> answer)
    {
        m_unsavedAnswer = answer;
    }
    // Test hook: answer the changed-on-disk question with `answer` instead of asking; and how many
    // times it was put.
    void setChangedOnDiskAnswer(std::optional<QMessageBox::StandardButton> answer)
    {
        m_changedOnDiskAnswer = answer;
    }
    int changedOnDiskQuestions() const { return m_changedOnDiskQuestions; }
    // Test hook: report errors in the status bar only, without message boxes.
    void setErrorDialogsEnabled(bool enabled) { m_errorDialogs = enabled; }

    QStringList recentFiles() const; // most recent first, from QSettings
    void clearRecentFiles();
    // The last error message, precise (core's message with the function and the full path, for
    // stderr and logs; the window shows it in its own wording, ui/widgets/WindowMessages.h); "" if none
    // since the last success. And the last missing-files note.
    const QString& lastError() const { return m_lastError; }
    const QString& missingFilesMessage() const { return m_missingFilesMessage; }
    // The relink dialog (null until a project with missing files was opened).
    MissingFilesDialog* missingFilesDialog() const;
    void showMissingFilesDialog();

Q_SIGNALS:
    void recentFilesChanged(const QStringList& files);
    // Something for the status bar (successes and notes).
    void statusMessage(const QString& text);
    // A failure, naming the file and the reason.
    void errorReported(const QString& text);
    // An open, save, reload or import succeeded: an earlier failure's message is stale.
    void errorCleared();

private:
    // `precise` goes to lastError() and the log, `text` (window wording) to the window.
    void reportError(const QString& precise, const QString& text);
    void clearError();
    // Document::reload with the window's messages; `statusText` has a %1 for the file.
    bool reloadFromDisk(const QString& statusText);
    void addRecentFile(const QString& path);
    void afterOpen();
    bool openAssetFile(const QString& path);

    Document* m_document;
    QWidget* m_dialogParent;
    QPointer<MissingFilesDialog> m_missingDialog;
    std::optional<QMessageBox::StandardButton> m_unsavedAnswer;
    std::optional<QMessageBox::StandardButton> m_changedOnDiskAnswer;
    int m_changedOnDiskQuestions = 0;
    bool m_errorDialogs = true;
    QString m_lastError;
    QString m_missingFilesMessage;
};

} // namespace facet
