#include "ui/EnvironmentDock.h"

#include "core/Project.h"
#include "render/IblSettings.h"
#include "ui/ColorButton.h"
#include "ui/Document.h"
#include "ui/DocumentCommands.h"
#include "ui/ThumbnailLoader.h"
#include "ui/ValueSlider.h"

#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <cmath>

namespace facet {

namespace {

const QLatin1String kFoldersKey("environmentLibrary/folders");
constexpr int kSourceRole = Qt::UserRole;

QStringList environmentFiles(const QString& folder)
{
    QStringList files;
    const QDir dir(folder);
    for (const QString& entry :
        dir.entryList({QStringLiteral("*.exr"), QStringLiteral("*.hdr")}, QDir::Files, QDir::Name))
        files.append(dir.filePath(entry));
    return files;
}

} // namespace

QString EnvironmentDock::installedHdriFolder()
{
    const QString overridden = qEnvironmentVariable("FACET_ASSETS_DIR");
    const QString assets
        = overridden.isEmpty() ? QDir::homePath() + QStringLiteral("/.local/share/facet/assets") : overridden;
    return assets + QStringLiteral("/hdri");
}

EnvironmentDock::EnvironmentDock(Document* document, QWidget* parent)
    : QDockWidget(tr("Environment Library"), parent)
    , m_document(document)
    , m_thumbnails(new ThumbnailLoader(this))
    , m_library(new QListWidget(this))
    , m_rotation(new ValueSlider(-180.0, 180.0, 1, this))
    , m_exposure(new ValueSlider(kMinEV, 4.0, 2, this))
    , m_background(new QComboBox(this))
    , m_blur(new ValueSlider(0.0, 1.0, 2, this))
    , m_backgroundColor(new ColorButton(this))
    , m_quality(new QComboBox(this))
    , m_status(new QLabel(this))
    , m_busy(new QProgressBar(this))
{
    setObjectName(QStringLiteral("environmentDock"));
    m_library->setObjectName(QStringLiteral("environmentLibrary"));
    m_library->setViewMode(QListView::IconMode);
    m_library->setIconSize(QSize(kThumbnailWidth, kThumbnailWidth / 2));
    m_library->setResizeMode(QListView::Adjust);
    m_library->setMovement(QListView::Static);
    m_library->setUniformItemSizes(true);
    m_library->setWordWrap(true);
    m_library->setSelectionMode(QAbstractItemView::SingleSelection);
    m_rotation->setObjectName(QStringLiteral("environmentRotationSlider"));
    m_rotation->setSuffix(QStringLiteral("°"));
    m_exposure->setObjectName(QStringLiteral("environmentIntensitySlider"));
    m_exposure->setSuffix(tr(" EV"));
    m_exposure->setToolTip(tr("Intensity in stops: the environment's radiance is multiplied by 2^EV"));
    m_background->setObjectName(QStringLiteral("backgroundCombo"));
    m_background->addItem(tr("Environment"), int(BackgroundMode::Environment));
    m_background->addItem(tr("Blurred environment"), int(BackgroundMode::Blurred));
    m_background->addItem(tr("Solid colour"), int(BackgroundMode::Color));
    m_blur->setObjectName(QStringLiteral("backgroundBlurSlider"));
    m_blur->setToolTip(tr("The roughness whose prefiltered environment the background shows"));
    m_backgroundColor->setObjectName(QStringLiteral("backgroundColorButton"));
    m_quality->setObjectName(QStringLiteral("iblQualityCombo"));
    for (const std::string& name : IblSettings::presetNames())
        if (const auto quality = iblQualityFromString(name))
            m_quality->addItem(QString::fromStdString(name), int(*quality));
    m_status->setObjectName(QStringLiteral("environmentStatus"));
    m_status->setWordWrap(true);
    m_busy->setObjectName(QStringLiteral("environmentBusy"));
    m_busy->setRange(0, 0);
    m_busy->setMaximumHeight(8);
    m_busy->setTextVisible(false);
    m_busy->hide();

    auto* addFolderButton = new QPushButton(tr("Add Folder…"), this);
    addFolderButton->setObjectName(QStringLiteral("addEnvironmentFolderButton"));
    auto* openButton = new QPushButton(tr("Open File…"), this);
    openButton->setObjectName(QStringLiteral("openEnvironmentButton"));
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(addFolderButton);
    buttons->addWidget(openButton);
    buttons->addStretch();

    auto* content = new QWidget(this);
    auto* layout = new QVBoxLayout(content);
    layout->addWidget(m_library, 1);
    layout->addLayout(buttons);
    auto* form = new QFormLayout;
    form->addRow(tr("Rotation"), m_rotation);
    form->addRow(tr("Intensity"), m_exposure);
    form->addRow(tr("Background"), m_background);
    form->addRow(tr("Blur"), m_blur);
    form->addRow(tr("Colour"), m_backgroundColor);
    form->addRow(tr("IBL quality"), m_quality);
    layout->addLayout(form);
    layout->addWidget(m_busy);
    layout->addWidget(m_status);
    setWidget(content);

    connect(addFolderButton, &QPushButton::clicked, this, [this] {
        const QString folder = QFileDialog::getExistingDirectory(this, tr("Add Environment Folder"));
        if (!folder.isEmpty())
            addFolder(folder);
    });
    connect(openButton, &QPushButton::clicked, this, [this] {
        const QString file = QFileDialog::getOpenFileName(
            this, tr("Open Environment"), {}, tr("HDR images (*.exr *.hdr);;All files (*)"));
        if (!file.isEmpty())
            chooseEnvironment(file);
    });
    connect(m_library, &QListWidget::currentItemChanged, this,
        [this](QListWidgetItem* item) { onItemActivated(item); });
    connect(m_thumbnails, &ThumbnailLoader::ready, this,
        [this](const QString& key, const QImage& image, QSize, const QString& error, double ms) {
            m_thumbnailMs += ms;
            for (int row = 0; row < m_library->count(); ++row) {
                QListWidgetItem* item = m_library->item(row);
                if (item->data(kSourceRole).toString() != key)
                    continue;
                if (image.isNull())
                    item->setToolTip(error);
                else
                    item->setIcon(QIcon(QPixmap::fromImage(image)));
            }
        });

    const auto connectSlider = [this](ValueSlider* slider, int mergeId, const QString& undoText, auto apply) {
        connect(slider, &ValueSlider::editStarted, m_document, &Document::beginInteractiveEdit);
        connect(slider, &ValueSlider::editFinished, m_document, &Document::endInteractiveEdit);
        connect(slider, &ValueSlider::valueEdited, this, [this, mergeId, undoText, apply](double value) {
            Project project = m_document->project();
            apply(project, value);
            m_document->setProject(project, undoText, mergeId);
        });
    };
    connectSlider(m_rotation, MergeId::EnvironmentRotation, tr("Environment Rotation"),
        [](Project& p, double v) { p.environment.rotationDegrees = v; });
    connectSlider(m_exposure, MergeId::EnvironmentIntensity, tr("Environment Intensity"),
        [](Project& p, double ev) { p.environment.intensity = std::exp2(ev); });
    connectSlider(m_blur, MergeId::BackgroundBlur, tr("Background Blur"),
        [](Project& p, double v) { p.view.backgroundBlurRoughness = v; });
    connect(m_background, &QComboBox::activated, this, [this] {
        ViewSettings view = m_document->project().view;
        view.background = BackgroundMode(m_background->currentData().toInt());
        m_document->setView(view, tr("Background"));
    });
    connect(m_backgroundColor, &ColorButton::colorEdited, this, [this](const glm::dvec3& linear) {
        ViewSettings view = m_document->project().view;
        view.backgroundColor = linear;
        view.background = BackgroundMode::Color;
        m_document->setView(view, tr("Background Colour"));
    });
    connect(m_quality, &QComboBox::activated, this, [this] {
        EnvironmentSettings environment = m_document->project().environment;
        environment.quality = IblQuality(m_quality->currentData().toInt());
        m_document->setEnvironment(environment, tr("IBL Quality"));
    });
    connect(m_document, &Document::changed, this, &EnvironmentDock::onDocumentChanged);
    rebuildLibrary();
    onDocumentChanged(DocumentChange::WholeProject);
}

EnvironmentDock::~EnvironmentDock() = default;

int EnvironmentDock::pendingThumbnails() const
{
    return m_thumbnails->pending();
}

void EnvironmentDock::rebuildLibrary()
{
    const QSignalBlocker blocker(m_library);
    m_library->clear();
    addEntry(QStringLiteral("studio"), tr("Studio (built-in)"));
    addEntry(QStringLiteral("sky"), tr("Sky (built-in)"));
    QStringList folders {installedHdriFolder()};
    folders += QSettings().value(kFoldersKey).toStringList();
    folders.removeDuplicates();
    for (const QString& folder : folders)
        for (const QString& file : environmentFiles(folder))
            addEntry(QFileInfo(file).absoluteFilePath(), QFileInfo(file).completeBaseName());
}

QListWidgetItem* EnvironmentDock::addEntry(const QString& source, const QString& label)
{
    for (int row = 0; row < m_library->count(); ++row)
        if (m_library->item(row)->data(kSourceRole).toString() == source)
            return m_library->item(row);
    QPixmap placeholder(kThumbnailWidth, kThumbnailWidth / 2);
    placeholder.fill(Qt::darkGray);
    auto* item = new QListWidgetItem(QIcon(placeholder), label, m_library);
    item->setData(kSourceRole, source);
    item->setToolTip(source);
    m_thumbnails->request(
        source, source, ThumbnailLoader::Kind::Environment, QSize(kThumbnailWidth, kThumbnailWidth / 2));
    return item;
}

bool EnvironmentDock::addFolder(const QString& folder)
{
    const QStringList files = environmentFiles(folder);
    if (files.isEmpty()) {
        Q_EMIT message(tr("%1 holds no .exr or .hdr environment").arg(QDir::toNativeSeparators(folder)));
        return false;
    }
    QSettings settings;
    QStringList folders = settings.value(kFoldersKey).toStringList();
    const QString absolute = QFileInfo(folder).absoluteFilePath();
    if (!folders.contains(absolute))
        folders.append(absolute);
    settings.setValue(kFoldersKey, folders);
    const QSignalBlocker blocker(m_library);
    for (const QString& file : files)
        addEntry(QFileInfo(file).absoluteFilePath(), QFileInfo(file).completeBaseName());
    Q_EMIT message(
        tr("Added %1 environment(s) from %2").arg(files.size()).arg(QDir::toNativeSeparators(folder)));
    return true;
}

bool EnvironmentDock::chooseEnvironment(const QString& source)
{
    const bool builtin = json::isBuiltinSpec(source.toStdString());
    const QString spec = builtin ? source : QFileInfo(source).absoluteFilePath();
    if (!builtin && !QFileInfo(spec).isFile()) {
        Q_EMIT message(tr("Cannot use %1 as the environment: no such file").arg(source));
        return false;
    }
    QListWidgetItem* item = nullptr;
    {
        const QSignalBlocker blocker(m_library);
        item = addEntry(spec, builtin ? spec : QFileInfo(spec).completeBaseName());
    }
    m_library->setCurrentItem(item); // sets the document through onItemActivated
    return true;
}

void EnvironmentDock::onItemActivated(QListWidgetItem* item)
{
    if (!item)
        return;
    EnvironmentSettings environment = m_document->project().environment;
    const std::string source = item->data(kSourceRole).toString().toStdString();
    if (environment.source == source)
        return;
    environment.source = source;
    m_document->setEnvironment(environment, tr("Environment %1").arg(item->text()));
}

void EnvironmentDock::onDocumentChanged(DocumentChanges changes)
{
    const Project& project = m_document->project();
    if (changes & DocumentChange::EnvironmentSource) {
        const QString source = QString::fromStdString(project.environment.source);
        const QSignalBlocker blocker(m_library);
        QListWidgetItem* item = nullptr;
        for (int row = 0; row < m_library->count() && !item; ++row)
            if (m_library->item(row)->data(kSourceRole).toString() == source)
                item = m_library->item(row);
        if (!item && !source.startsWith(QStringLiteral("uniform:")))
            item = addEntry(source, QFileInfo(source).completeBaseName());
        m_library->setCurrentItem(item);
    }
    m_rotation->setValue(project.environment.rotationDegrees);
    m_exposure->setValue(
        project.environment.intensity > 0.0 ? std::log2(project.environment.intensity) : kMinEV);
    {
        const QSignalBlocker blocker(m_background);
        m_background->setCurrentIndex(m_background->findData(int(project.view.background)));
        const QSignalBlocker qualityBlocker(m_quality);
        m_quality->setCurrentIndex(m_quality->findData(int(project.environment.quality)));
    }
    m_blur->setValue(project.view.backgroundBlurRoughness);
    m_blur->setEnabled(project.view.background == BackgroundMode::Blurred);
    m_backgroundColor->setLinearColor(project.view.backgroundColor);
}

void EnvironmentDock::showPrecomputeStarting(const QString& name)
{
    m_status->setText(tr("Preparing the lighting of %1…").arg(name));
    m_busy->show();
}

void EnvironmentDock::showPrecomputeFinished(const QString& name, double milliseconds)
{
    m_busy->hide();
    m_status->setText(milliseconds > 0.0
            ? tr("Lighting of %1 ready (%2 ms)").arg(name).arg(milliseconds, 0, 'f', 0)
            : tr("Lighting of %1 ready (cached)").arg(name));
}

} // namespace facet
