#pragma once
// Lists the files the open project names that do not exist (a file of a library says which
// library and how to get it back, e.g. packaging/fetch-assets.sh for the installed CC0 samples)
// and lets the user point each one at another file ("Locate…") or search a folder for files of
// the same names ("Search Folder…").
// Non-modal: the project is already open and usable; relinking is an undoable edit
// (Document::relinkFile). It follows Document::missingFilesChanged and closes itself when none
// are left.

#include <QDialog>

class QLabel;
class QListWidget;

namespace facet {

class Document;

class MissingFilesDialog : public QDialog {
    Q_OBJECT
public:
    explicit MissingFilesDialog(Document* document, QWidget* parent = nullptr);

    // The text above the list, e.g. "2 files used by scene.json are missing. ..."
    QString message() const;
    // The list's entries as shown (the file, then any advice on a second line).
    QStringList entries() const;
    // Looks in `folder` (not recursively) for a file with each missing file's name and relinks
    // those it finds; returns how many it relinked.
    int relinkFromFolder(const QString& folder);

private:
    void refresh();
    void locateSelected();
    void searchFolder();

    Document* m_document;
    QLabel* m_message = nullptr;
    QListWidget* m_list = nullptr;
};

} // namespace facet
