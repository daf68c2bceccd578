#include "ui/dialogs/ExportDialog.h"

#include <QApplication>
#include <QComboBox>
#include <QCryptographicHash>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QVBoxLayout>

#include <filesystem>

#include "core/gltf/GltfExport.h"
#include "core/project/ProjectAssets.h"

namespace facet {

namespace {

const char* const kSettingsTemplate = "export/template";
const char* const kSettingsFolder = "export/folder";

// The settings key of the folder last chosen for the project in `projectFolder` (a hash: a path's
// slashes would make groups).
QString projectFolderKey(const QString& projectFolder)
{
    return QStringLiteral("export/projectFolders/")
        + QString::fromLatin1(
            QCryptographicHash::hash(projectFolder.toUtf8(), QCryptographicHash::Sha1).toHex());
}
const char* const kSettingsSize = "export/size";

} // namespace

ExportDialog::ExportDialog(
    const Project& project, const QString& baseName, QWidget* parent, const QString& projectFolder)
    : QDialog(parent)
    , m_project(project)
    , m_baseName(QString::fromStdString(fileNameSafe(baseName.toStdString())))
{
    setWindowTitle(tr("Export"));
    setObjectName(QStringLiteral("exportDialog"));

    m_template = new QComboBox(this);
    m_template->setObjectName(QStringLiteral("exportTemplate"));
    m_template->addItem(tr("glTF 2.0 asset (.gltf, .bin and textures)"), QStringLiteral("gltf"));
    m_template->addItem(tr("glTF 2.0 binary (.glb)"), QStringLiteral("glb"));
    m_template->insertSeparator(2);
    for (const std::string& id : ExportTemplate::builtinIds()) {
        const std::optional<ExportTemplate> t = ExportTemplate::builtin(id);
        m_template->addItem(QString::fromStdString(t ? t->name : id), QString::fromStdString(id));
    }
    auto* browseTemplateButton = new QPushButton(tr("Template File…"), this);
    connect(browseTemplateButton, &QPushButton::clicked, this, &ExportDialog::browseTemplate);
    auto* templateRow = new QHBoxLayout;
    templateRow->addWidget(m_template, 1);
    templateRow->addWidget(browseTemplateButton);

    m_materials = new QComboBox(this);
    m_materials->setObjectName(QStringLiteral("exportMaterials"));
    const int current = std::clamp(project.currentMaterial, 0, int(project.materials.size()) - 1);
    m_materials->addItem(
        tr("Current material (%1)").arg(QString::fromStdString(project.materials[std::size_t(current)].name)),
        current);
    if (project.materials.size() > 1)
        m_materials->addItem(tr("All %1 materials").arg(project.materials.size()), -1);

    m_size = new QComboBox(this);
    m_size->setObjectName(QStringLiteral("exportSize"));
    m_size->addItem(tr("The maps' own"), 0);
    for (const int size : {256, 512, 1024, 2048, 4096, 8192})
        m_size->addItem(QStringLiteral("%1").arg(size), size);

    m_bitDepth = new QComboBox(this);
    m_bitDepth->setObjectName(QStringLiteral("exportBitDepth"));
    m_bitDepth->addItem(tr("The template's"), 0);
    m_bitDepth->addItem(tr("8-bit"), 8);
    m_bitDepth->addItem(tr("16-bit"), 16);
    m_bitDepth->addItem(tr("32-bit float"), 32);

    m_folder = new QLineEdit(this);
    m_folder->setObjectName(QStringLiteral("exportFolder"));
    auto* browseFolderButton = new QPushButton(tr("Browse…"), this);
    connect(browseFolderButton, &QPushButton::clicked, this, &ExportDialog::browseFolder);
    auto* folderRow = new QHBoxLayout;
    folderRow->addWidget(m_folder, 1);
    folderRow->addWidget(browseFolderButton);

    m_preview = new QPlainTextEdit(this);
    m_preview->setObjectName(QStringLiteral("exportPreview"));
    m_preview->setReadOnly(true);
    m_preview->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_preview->setMinimumSize(760, 180); // a dry-run line of a 2K set fits
    m_status = new QLabel(this);
    m_status->setWordWrap(true);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    m_export = buttons->addButton(tr("Export"), QDialogButtonBox::AcceptRole);
    m_export->setObjectName(QStringLiteral("exportButton"));
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_export, &QPushButton::clicked, this, [this] {
        if (exportNow())
            accept();
    });

    auto* form = new QFormLayout;
    form->addRow(tr("Format:"), templateRow);
    form->addRow(tr("Materials:"), m_materials);
    form->addRow(tr("Size:"), m_size);
    form->addRow(tr("Bit depth:"), m_bitDepth);
    form->addRow(tr("Folder:"), folderRow);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(new QLabel(tr("Files:"), this));
    layout->addWidget(m_preview, 1);
    layout->addWidget(m_status);
    layout->addWidget(buttons);

    // The last choices, where they still apply.
    const QSettings settings;
    const int templateIndex
        = m_template->findData(settings.value(QLatin1String(kSettingsTemplate)).toString());
    if (templateIndex >= 0)
        m_template->setCurrentIndex(templateIndex);
    const int sizeIndex = m_size->findData(settings.value(QLatin1String(kSettingsSize), 0).toInt());
    if (sizeIndex >= 0)
        m_size->setCurrentIndex(sizeIndex);
    m_projectFolder = projectFolder;
    const QString remembered = settings.value(QLatin1String(kSettingsFolder), QDir::homePath()).toString();
    m_folder->setText(projectFolder.isEmpty()
            ? remembered
            : settings.value(projectFolderKey(projectFolder), projectFolder).toString());

    for (QComboBox* box : {m_template, m_materials, m_size, m_bitDepth})
        connect(box, &QComboBox::currentIndexChanged, this, &ExportDialog::updatePreview);
    connect(m_folder, &QLineEdit::editingFinished, this, [this] {
        if (isGltf())
            updatePreview();
    });
    updatePreview();
}

void ExportDialog::setConfirmReplace(std::function<bool(const QStringList&)> confirm)
{
    m_confirmReplace = std::move(confirm);
}

bool ExportDialog::useTemplateFile(const QString& path)
{
    std::string error;
    const std::optional<ExportTemplate> t = ExportTemplate::load(path.toStdString(), &error);
    if (!t) {
        m_status->setText(QString::fromStdString(error));
        m_message = QString::fromStdString(error);
        return false;
    }
    m_templateFiles.append(path);
    m_template->addItem(
        QStringLiteral("%1 (%2)").arg(QString::fromStdString(t->name), QFileInfo(path).fileName()), path);
    m_template->setCurrentIndex(m_template->count() - 1);
    return true;
}

void ExportDialog::setFolder(const QString& folder)
{
    m_folder->setText(folder);
}

std::optional<ExportTemplate> ExportDialog::chosenTemplate(std::string* error) const
{
    const QString id = m_template->currentData().toString();
    if (std::optional<ExportTemplate> builtin = ExportTemplate::builtin(id.toStdString()))
        return builtin;
    return ExportTemplate::load(id.toStdString(), error);
}

std::vector<Material> ExportDialog::chosenMaterials() const
{
    const int index = m_materials->currentData().toInt();
    if (index >= 0)
        return {m_project.materials[std::size_t(index)]};
    return m_project.materials;
}

TextureSetOptions ExportDialog::chosenOptions() const
{
    TextureSetOptions options;
    options.size = m_size->currentData().toInt();
    options.bitDepth = m_bitDepth->currentData().toInt();
    return options;
}

void ExportDialog::updatePreview()
{
    QApplication::setOverrideCursor(Qt::WaitCursor); // the maps are read to plan
    m_job.reset();
    m_gltfFiles.clear();
    m_problem.clear();
    std::string error;
    if (isGltf()) {
        GltfExportOptions options;
        options.binary = m_template->currentData().toString() == QStringLiteral("glb");
        options.textures = chosenOptions();
        m_gltfFiles = gltfAssetFiles(gltfPath().toStdString(), chosenMaterials(), options, &error);
    } else if (const std::optional<ExportTemplate> t = chosenTemplate(&error)) {
        m_job = TextureSetExport::prepare(*t, chosenMaterials(), chosenOptions(), &error);
    }
    QApplication::restoreOverrideCursor();
    const bool ready = m_job.has_value() || !m_gltfFiles.empty();
    if (!ready)
        m_problem = QString::fromStdString(error);
    m_preview->setPlainText(preview());
    m_status->setText(m_problem);
    m_export->setEnabled(ready);
}

QString ExportDialog::preview() const
{
    if (!m_gltfFiles.empty()) {
        QString text = tr("%1 on the view's mesh:\n").arg(QFileInfo(gltfPath()).fileName());
        for (const std::string& file : m_gltfFiles)
            text += QStringLiteral("  %1\n").arg(QFileInfo(QString::fromStdString(file)).fileName());
        return text;
    }
    return m_job ? QString::fromStdString(m_job->describeAll()) : m_problem;
}

bool ExportDialog::isGltf() const
{
    const QString id = m_template->currentData().toString();
    return id == QStringLiteral("gltf") || id == QStringLiteral("glb");
}

QString ExportDialog::gltfPath() const
{
    return QDir(m_folder->text().trimmed())
        .filePath(m_baseName + QLatin1Char('.') + m_template->currentData().toString());
}

bool ExportDialog::exportNow()
{
    if (!m_job && m_gltfFiles.empty()) {
        m_message = m_problem;
        return false;
    }
    const QString folder = m_folder->text().trimmed();
    if (folder.isEmpty()) {
        m_message = tr("Choose a folder to export into.");
        m_status->setText(m_message);
        return false;
    }
    if (isGltf())
        updatePreview(); // the folder may have changed: the asset's path with it
    FileSet probe(folder.toStdString());
    QStringList existing;
    if (isGltf()) {
        for (const std::string& path : m_gltfFiles)
            if (QFileInfo::exists(QString::fromStdString(path)))
                existing.append(QString::fromStdString(path));
    } else {
        for (const std::string& path : probe.existing(m_job->fileNames()))
            existing.append(QString::fromStdString(path));
    }
    bool replace = false;
    if (!existing.isEmpty()) {
        const auto ask = m_confirmReplace ? m_confirmReplace : [this](const QStringList& files) {
            QStringList names;
            for (const QString& file : files)
                names.append(QFileInfo(file).fileName());
            return QMessageBox::question(this, tr("Replace Files?"),
                       tr("%1 of this export's files are already in %2:\n%3\n\nReplace them?")
                           .arg(QString::number(files.size()),
                               QDir::toNativeSeparators(QFileInfo(files.first()).absolutePath()),
                               names.mid(0, 8).join(QLatin1Char('\n'))
                                   + (names.size() > 8 ? QStringLiteral("\n…") : QString())),
                       QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel)
                == QMessageBox::Yes;
        };
        if (!ask(existing)) {
            m_message = tr("Export cancelled: nothing was replaced.");
            m_status->setText(m_message);
            return false;
        }
        replace = true;
    }
    QApplication::setOverrideCursor(Qt::WaitCursor);
    std::string error;
    std::vector<std::string> written;
    bool ok = false;
    QString what;
    if (isGltf()) {
        GltfExportOptions options;
        options.binary = m_template->currentData().toString() == QStringLiteral("glb");
        options.textures = chosenOptions();
        options.generator = "Facet " FACET_VERSION;
        options.source = viewMeshGltfFile(m_project.view.mesh);
        std::string warning;
        const std::optional<Mesh> mesh
            = loadViewMesh(m_project.view.mesh, &error, &warning, m_project.view.keepUnits);
        std::vector<int> parts;
        if (m_materials->currentData().toInt() < 0)
            for (std::size_t part = 0; mesh && part < mesh->subMeshes.size(); ++part)
                parts.push_back(m_project.materialOfPart(part));
        ok = mesh
            && writeGltfAsset(gltfPath().toStdString(), *mesh, parts, chosenMaterials(), options, replace,
                &written, &error);
        what = m_template->currentText();
    } else {
        ok = m_job->write(folder.toStdString(), replace, &error, &written);
        what = QString::fromStdString(m_job->exportTemplate().name);
    }
    QApplication::restoreOverrideCursor();
    if (!ok) {
        m_message = tr("Export failed: %1").arg(QString::fromStdString(error));
        m_status->setText(m_message);
        return false;
    }
    remember();
    m_message = tr("Exported %1 to %2 (%3)")
                    .arg(written.size() == 1 ? tr("1 file") : tr("%1 files").arg(written.size()),
                        QDir::toNativeSeparators(folder), what);
    Q_EMIT exported(m_message);
    return true;
}

void ExportDialog::browseTemplate()
{
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Export Template"), QString(), tr("Export templates (*.json)"));
    if (!path.isEmpty())
        useTemplateFile(path);
}

void ExportDialog::browseFolder()
{
    const QString folder = QFileDialog::getExistingDirectory(this, tr("Export Into"), m_folder->text());
    if (!folder.isEmpty())
        m_folder->setText(folder);
}

void ExportDialog::remember() const
{
    QSettings settings;
    const QString id = m_template->currentData().toString();
    if (!m_templateFiles.contains(id))
        settings.setValue(QLatin1String(kSettingsTemplate), id);
    settings.setValue(QLatin1String(kSettingsFolder), m_folder->text().trimmed());
    if (!m_projectFolder.isEmpty())
        settings.setValue(projectFolderKey(m_projectFolder), m_folder->text().trimmed());
    settings.setValue(QLatin1String(kSettingsSize), m_size->currentData().toInt());
}

} // namespace facet
