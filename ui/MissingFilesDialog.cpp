#include "ui/MissingFilesDialog.h"

#include "ui/Document.h"

#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace facet {

MissingFilesDialog::MissingFilesDialog(Document* document, QWidget* parent)
    : QDialog(parent)
    , m_document(document)
    , m_message(new QLabel(this))
    , m_list(new QListWidget(this))
{
    setObjectName(QStringLiteral("missingFilesDialog"));
    setWindowTitle(tr("Missing Files"));
    setModal(false);
    m_message->setWordWrap(true);
    m_list->setObjectName(QStringLiteral("missingFilesList"));
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    QPushButton* locate = buttons->addButton(tr("&Locate…"), QDialogButtonBox::ActionRole);
    QPushButton* search = buttons->addButton(tr("&Search Folder…"), QDialogButtonBox::ActionRole);
    connect(locate, &QPushButton::clicked, this, &MissingFilesDialog::locateSelected);
    connect(search, &QPushButton::clicked, this, &MissingFilesDialog::searchFolder);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_message);
    layout->addWidget(m_list);
    layout->addWidget(buttons);
    connect(m_document, &Document::missingFilesChanged, this, &MissingFilesDialog::refresh);
    refresh();
}

QString MissingFilesDialog::message() const
{
    return m_message->text();
}

void MissingFilesDialog::refresh()
{
    const QStringList& missing = m_document->missingFiles();
    m_list->clear();
    m_list->addItems(missing);
    if (!missing.isEmpty())
        m_list->setCurrentRow(0);
    m_message->setText(tr("%n file(s) used by %1 are missing. The project is open without them; locate "
                          "each file, or search a folder for files of the same names.",
        nullptr, int(missing.size()))
                           .arg(m_document->displayName()));
    if (missing.isEmpty() && isVisible())
        accept();
}

void MissingFilesDialog::locateSelected()
{
    const QListWidgetItem* item = m_list->currentItem();
    if (!item)
        return;
    const QString missing = item->text();
    const QString replacement = QFileDialog::getOpenFileName(
        this, tr("Locate %1").arg(QFileInfo(missing).fileName()), QFileInfo(missing).absolutePath());
    if (!replacement.isEmpty())
        m_document->relinkFile(missing, replacement);
}

void MissingFilesDialog::searchFolder()
{
    const QString folder = QFileDialog::getExistingDirectory(this, tr("Search Folder"));
    if (!folder.isEmpty())
        relinkFromFolder(folder);
}

int MissingFilesDialog::relinkFromFolder(const QString& folder)
{
    int relinked = 0;
    const QStringList missing = m_document->missingFiles();
    for (const QString& file : missing) {
        const QString candidate = QDir(folder).filePath(QFileInfo(file).fileName());
        if (QFileInfo::exists(candidate) && m_document->relinkFile(file, candidate))
            ++relinked;
    }
    return relinked;
}

} // namespace facet
