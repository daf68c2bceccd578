#include "ui/docks/EnvironmentDock.h"

#include "core/ibl/Environment.h"
#include "core/project/AssetLibrary.h"
#include "core/project/Project.h"
#include "render/IblSettings.h"
#include "ui/document/Document.h"
#include "ui/document/DocumentCommands.h"
#include "ui/viewport/ThumbnailLoader.h"
#include "ui/widgets/ColorButton.h"
#include "ui/widgets/ValueSlider.h"
#include "ui/widgets/WindowMessages.h"

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

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace facet {

namespace {

// Where versions before asset libraries remembered added folders; read once and moved into
// core's library list (AssetLibrary::addUserLibrary), which names each folder.
const QLatin1String kLegacyFoldersKey("environmentLibrary/folders");
constexpr int kSourceRole = Qt::UserRole;
constexpr int kSizeRole = Qt::UserRole + 1; // the image's size in pixels, once its thumbnail is made

// The entry's label and, once known, its resolution on a line of its own ("2048×1024").
QString entryText(const QString& label, QSize size)
{
    return size.isValid() ? QStringLiteral("%1\n%2×%3").arg(label).arg(size.width()).arg(size.height())
                          : label;
}

QStringList environmentFiles(const QString& folder)
{
    QStringList files;
    const QDir dir(folder);
    for (const QString& entry :
        dir.entryList({QStringLiteral("*.exr"), QStringLiteral("*.hdr")}, QDir::Files, QDir::Name))
        files.append(dir.filePath(entry));
    return files;
}

// "night_city-2k" -> "Night city 2k": a file name as a title.
QString title(const QString& baseName)
{
    QString text = baseName;
    text.replace(QLatin1Char('_'), QLatin1Char(' ')).replace(QLatin1Char('-'), QLatin1Char(' '));
    text = text.simplified();
    if (!text.isEmpty())
        text[0] = text[0].toUpper();
    return text;
}

// The library a file or reference belongs to (nullopt for a loose file) and its reference.
std::optional<std::pair<AssetLibrary, QString>> libraryOf(const QString& source)
{
    const std::string text = source.toStdString();
    const std::optional<std::string> spec
        = AssetLibrary::isSpec(text) ? std::optional<std::string>(text) : AssetLibrary::specForPath(text);
    if (!spec)
        return std::nullopt;
    const std::string rest = spec->substr(std::char_traits<char>::length(AssetLibrary::kSpecPrefix));
    const std::string name = rest.substr(0, rest.find('/'));
    AssetLibrary library
        = AssetLibrary::named(name).value_or(AssetLibrary {AssetLibrary::Kind::User, name, {}});
    return std::make_pair(std::move(library), QString::fromStdString(*spec));
}

} // namespace

QString EnvironmentDock::installedHdriFolder()
{
    return QString::fromStdString(AssetLibrary::installed().folder) + QStringLiteral("/hdri");
}

QString EnvironmentDock::entryLabel(const QString& source)
{
    if (const auto builtin = Environment::builtinFromName(source.toStdString()))
        return *builtin == Environment::Builtin::Studio ? tr("Studio (built-in)") : tr("Sky (built-in)");
    const QString name = title(QFileInfo(source).completeBaseName());
    const auto library = libraryOf(source);
    if (!library)
        return QFileInfo(source).fileName();
    if (library->first.kind == AssetLibrary::Kind::Installed)
        return tr("%1 (CC0 sample)").arg(name);
    return tr("%1 (%2)").arg(name, QString::fromStdString(library->first.name));
}

QString EnvironmentDock::entryToolTip(const QString& source)
{
    if (const auto builtin = Environment::builtinFromName(source.toStdString()))
        return *builtin == Environment::Builtin::Studio
            ? tr("Studio, built into Facet: a procedural grey room with a large soft box overhead and two "
                 "strip lights.\nNo file: the same on every computer. Saved in projects as “studio”.")
            : tr("Sky, built into Facet: a procedural clear sky with a soft sun over a ground plane.\nNo "
                 "file: the same on every computer. Saved in projects as “sky”.");
    const QString file = QFileInfo(source).fileName();
    const QString path = QDir::toNativeSeparators(source);
    const auto library = libraryOf(source);
    if (!library)
        return tr("%1\nSaved in projects relative to the project's folder.").arg(path);
    if (library->first.kind == AssetLibrary::Kind::Installed)
        return tr("%1 from Facet's installed CC0 samples (packaging/fetch-assets.sh)\n%2\nSaved in projects "
                  "as %3, found wherever the samples are installed.")
            .arg(file, path, library->second);
    return tr("%1 from your library “%2”\n%3\nSaved in projects as %4, found wherever a library of that "
              "name is set up.")
        .arg(file, QString::fromStdString(library->first.name), path, library->second);
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
    , m_method(new QComboBox(this))
    , m_status(new QLabel(this))
    , m_busy(new QProgressBar(this))
{
    setObjectName(QStringLiteral("environmentDock"));
    m_library->setObjectName(QStringLiteral("environmentLibrary"));
    m_library->setViewMode(QListView::IconMode);
    // Cells an icon wide with two lines of label, a little smaller than the thumbnails: two columns
    // fit the default dock column (a quarter of a 1200-pixel window, beside the tabs); a longer
    // label wraps, then is cut, not a wider cell.
    constexpr int kIconWidth = 112;
    m_library->setIconSize(QSize(kIconWidth, kIconWidth / 2));
    // Two lines of label and one of resolution.
    m_library->setGridSize(QSize(kIconWidth + 4, kIconWidth / 2 + 3 * fontMetrics().lineSpacing() + 8));
    m_library->setResizeMode(QListView::Adjust);
    // Two rows of cells before it scrolls (issue 30: about three cells showed until resized).
    m_library->setMinimumHeight(2 * m_library->gridSize().height() + 8);
    m_library->setMovement(QListView::Static);
    // Each item's own size, wrapped to the grid's width (uniform sizes took the size of whichever
    // item the view asked first, and could cut every label to one line).
    m_library->setUniformItemSizes(false);
    m_library->setWordWrap(true);
    // Several entries for Compare Selected Environments; a plain click still picks one.
    m_library->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_library->setDragDropMode(QAbstractItemView::DragOnly); // onto the Compare view's cells
    m_rotation->setObjectName(QStringLiteral("environmentRotationSlider"));
    m_rotation->setSuffix(QStringLiteral("°"));
    m_exposure->setObjectName(QStringLiteral("environmentIntensitySlider"));
    m_exposure->setSuffix(tr(" EV"));
    m_exposure->setToolTip(tr("Intensity in stops: the environment's radiance is multiplied by 2^EV"));
    m_background->setObjectName(QStringLiteral("backgroundCombo"));
    m_background->addItem(tr("Environment"), int(BackgroundMode::Environment));
    m_background->addItem(tr("Blurred environment"), int(BackgroundMode::Blurred));
    m_background->addItem(tr("Solid colour"), int(BackgroundMode::Color));
    m_background->addItem(
        tr("Transparent (black here, alpha in saved renders)"), int(BackgroundMode::Transparent));
    m_blur->setObjectName(QStringLiteral("backgroundBlurSlider"));
    m_blur->setToolTip(tr("The roughness whose prefiltered environment the background shows"));
    m_backgroundColor->setObjectName(QStringLiteral("backgroundColorButton"));
    m_quality->setObjectName(QStringLiteral("iblQualityCombo"));
    for (const std::string& name : IblSettings::presetNames())
        if (const auto quality = iblQualityFromString(name))
            m_quality->addItem(QString::fromStdString(name), int(*quality));
    m_method->setObjectName(QStringLiteral("iblMethodCombo"));
    m_method->addItem(tr("Split sum (real time)"), int(IblMethod::SplitSum));
    m_method->addItem(tr("FIS (importance sampled)"), int(IblMethod::Fis));
    m_method->addItem(tr("Reference (converging)"), int(IblMethod::Reference));
    m_method->setToolTip(
        tr("How the still view integrates the environment's light. While you move the camera "
           "or drag a slider the view shows the split sum; when you stop, FIS and Reference "
           "refine it to their samples (the status bar shows the progress)."));
    m_status->setObjectName(QStringLiteral("environmentStatus"));
    m_status->setWordWrap(true);
    // It names the environment: a long file name (one word) is cut at the dock's edge rather than
    // widening the dock; the whole status is in the tooltip and the status bar.
    m_status->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
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
    form->addRow(tr("Lighting"), m_method);
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
    // Not currentItemChanged: a Ctrl-click makes the clicked entry current before it joins the
    // selection, and adding an entry to a selection must not relight the view.
    connect(m_library, &QListWidget::itemSelectionChanged, this, &EnvironmentDock::onSelectionChanged);
    connect(m_thumbnails, &ThumbnailLoader::ready, this,
        [this](const QString& key, const QImage& image, QSize sourceSize, const QString& error, double ms) {
            m_thumbnailMs += ms;
            for (int row = 0; row < m_library->count(); ++row) {
                QListWidgetItem* item = m_library->item(row);
                if (item->data(kSourceRole).toString() != key)
                    continue;
                if (image.isNull()) {
                    item->setToolTip(entryToolTip(key) + QLatin1Char('\n') + WindowMessages::fromCore(error));
                } else {
                    item->setIcon(QIcon(QPixmap::fromImage(image)));
                    // Its resolution, which decides what the lighting can resolve (a 512x256 map
                    // blurs a mirror) and what it costs (issue 30).
                    item->setData(kSizeRole, sourceSize);
                    item->setText(entryText(entryLabel(key), sourceSize));
                    item->setToolTip(entryToolTip(key)
                        + tr("\n%1 × %2 pixels").arg(sourceSize.width()).arg(sourceSize.height()));
                }
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
    connect(m_method, &QComboBox::activated, this, [this] {
        EnvironmentSettings environment = m_document->project().environment;
        environment.method = IblMethod(m_method->currentData().toInt());
        environment.samples = 0; // the method's own default; a count is a split-sum error
        m_document->setEnvironment(environment, tr("Lighting Method"));
    });
    connect(m_document, &Document::changed, this, &EnvironmentDock::onDocumentChanged);
    QSettings settings;
    for (const QString& folder : settings.value(kLegacyFoldersKey).toStringList())
        AssetLibrary::addUserLibrary(folder.toStdString(), nullptr); // a folder gone since is dropped
    settings.remove(kLegacyFoldersKey);
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
    addEntry(QString::fromLatin1(Environment::builtinName(Environment::Builtin::Studio)));
    addEntry(QString::fromLatin1(Environment::builtinName(Environment::Builtin::Sky)));
    for (const AssetLibrary& library : AssetLibrary::all()) {
        // The installed samples keep their environments in hdri/; a user library is a folder of them.
        QString folder = QString::fromStdString(library.folder);
        if (library.kind == AssetLibrary::Kind::Installed)
            folder += QStringLiteral("/hdri");
        for (const QString& file : environmentFiles(folder))
            addEntry(QFileInfo(file).absoluteFilePath());
    }
}

QListWidgetItem* EnvironmentDock::addEntry(const QString& source)
{
    for (int row = 0; row < m_library->count(); ++row)
        if (m_library->item(row)->data(kSourceRole).toString() == source)
            return m_library->item(row);
    QPixmap placeholder(kThumbnailWidth, kThumbnailWidth / 2);
    placeholder.fill(Qt::darkGray);
    auto* item = new QListWidgetItem(QIcon(placeholder), entryLabel(source), m_library);
    item->setData(kSourceRole, source);
    item->setToolTip(entryToolTip(source));
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
    std::string error;
    const std::optional<AssetLibrary> library = AssetLibrary::addUserLibrary(folder.toStdString(), &error);
    if (!library) {
        Q_EMIT message(WindowMessages::fromCore(error));
        return false;
    }
    {
        const QSignalBlocker blocker(m_library);
        for (const QString& file : files) {
            // A file listed before as a loose file or under another library gets its new label.
            const QString source = QFileInfo(file).absoluteFilePath();
            QListWidgetItem* item = addEntry(source);
            item->setText(entryText(entryLabel(source), item->data(kSizeRole).toSize()));
            item->setToolTip(entryToolTip(source));
        }
    }
    Q_EMIT message(tr("Added %n environment(s) from %1 as the library “%2”; projects refer to them by that "
                      "name",
        nullptr, int(files.size()))
                       .arg(QDir::toNativeSeparators(folder), QString::fromStdString(library->name)));
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
        item = addEntry(spec);
    }
    m_library->setCurrentItem(
        item, QItemSelectionModel::ClearAndSelect); // sets the document (onSelectionChanged)
    return true;
}

QStringList EnvironmentDock::selectedSources() const
{
    // In the order of selection; an entry the dock selected itself with signals blocked (the
    // document's environment changed) is not in m_selectionOrder and follows in the list's order.
    QStringList selected;
    for (int row = 0; row < m_library->count(); ++row)
        if (m_library->item(row)->isSelected())
            selected.append(m_library->item(row)->data(kSourceRole).toString());
    QStringList sources;
    for (const QString& source : m_selectionOrder)
        if (selected.contains(source))
            sources.append(source);
    for (const QString& source : selected)
        if (!sources.contains(source))
            sources.append(source);
    return sources;
}

void EnvironmentDock::onSelectionChanged()
{
    // Entries that left the selection go, new ones join at the end (a Shift range as a block,
    // in the list's order).
    const QStringList selected = selectedSources();
    m_selectionOrder.removeIf([&selected](const QString& source) { return !selected.contains(source); });
    for (const QString& source : selected)
        if (!m_selectionOrder.contains(source))
            m_selectionOrder.append(source);
    // A plain click (or the arrow keys) selects the current entry alone: it becomes the
    // environment. A Ctrl-click that takes an entry out leaves one other selected, but the
    // current entry is the one taken out: that changes nothing.
    const QList<QListWidgetItem*> items = m_library->selectedItems();
    if (items.size() == 1 && items.front() == m_library->currentItem())
        onItemActivated(items.front());
    Q_EMIT selectionChanged(int(items.size()));
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
    m_document->setEnvironment(
        environment, tr("Environment %1").arg(item->text().section(QLatin1Char('\n'), 0, 0)));
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
            item = addEntry(source);
        m_library->setCurrentItem(item, QItemSelectionModel::ClearAndSelect);
        Q_EMIT selectionChanged(int(m_library->selectedItems().size())); // the list's own signals are blocked
    }
    m_rotation->setValue(project.environment.rotationDegrees);
    m_exposure->setValue(
        project.environment.intensity > 0.0 ? std::log2(project.environment.intensity) : kMinEV);
    {
        const QSignalBlocker blocker(m_background);
        m_background->setCurrentIndex(m_background->findData(int(project.view.background)));
        const QSignalBlocker qualityBlocker(m_quality);
        m_quality->setCurrentIndex(m_quality->findData(int(project.environment.quality)));
        const QSignalBlocker methodBlocker(m_method);
        m_method->setCurrentIndex(m_method->findData(int(project.environment.method)));
    }
    m_blur->setValue(project.view.backgroundBlurRoughness);
    m_blur->setEnabled(project.view.background == BackgroundMode::Blurred);
    m_backgroundColor->setLinearColor(project.view.backgroundColor);
}

void EnvironmentDock::showLightingStatus(const QString& text, bool busy)
{
    m_busy->setRange(0, 0); // busy, for how long unknown, until showLightingProgress says
    m_busy->setVisible(busy);
    m_status->setText(text);
    m_status->setToolTip(text);
}

void EnvironmentDock::showLightingProgress(const QString& text, double fraction)
{
    m_busy->setRange(0, 1000);
    m_busy->setValue(int(std::lround(std::clamp(fraction, 0.0, 1.0) * 1000.0)));
    m_busy->setVisible(true);
    m_status->setText(text);
    m_status->setToolTip(text);
}

} // namespace facet
