#include "ui/document/MissingFilesDialog.h"

#include "core/project/AssetLibrary.h"
#include "ui/document/Document.h"
#include "ui/widgets/WindowMessages.h"

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
    m_list->setWordWrap(true); // a library file's advice is a sentence
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

QStringList MissingFilesDialog::entries() const
{
    QStringList texts;
    for (int row = 0; row < m_list->count(); ++row)
        texts.append(m_list->item(row)->text());
    return texts;
}

void MissingFilesDialog::refresh()
{
    const QStringList& missing = m_document->missingFiles();
    m_list->clear();
    for (const QString& file : missing) {
        // The file (as the project names it) and, for a library's file, how to get it back.
        auto* item = new QListWidgetItem(QDir::toNativeSeparators(file), m_list);
        item->setData(Qt::UserRole, file);
        const std::string advice = AssetLibrary::missingFileAdvice(file.toStdString());
        if (!advice.empty()) {
            const QString text = WindowMessages::fromCore(QString::fromStdString(advice));
            item->setText(item->text() + QStringLiteral("\n    ") + text);
            item->setToolTip(text);
        }
    }
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
    const QString missing = item->data(Qt::UserRole).toString();
    // A reference to a library this computer lacks names no folder: start in the home folder.
    const QString start = QFileInfo(missing).isAbsolute() ? QFileInfo(missing).absolutePath() : QString();
    const QString replacement
        = QFileDialog::getOpenFileName(this, tr("Locate %1").arg(QFileInfo(missing).fileName()), start);
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
