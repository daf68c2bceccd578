#include "ui/docks/TextureMapsDock.h"

#include "core/material/MapNaming.h"
#include "ui/docks/DockScrollArea.h"
#include "ui/docks/MapSlotWidget.h"
#include "ui/document/Document.h"
#include "ui/document/DocumentCommands.h"
#include "ui/viewport/ThumbnailLoader.h"
#include "ui/widgets/DroppedFiles.h"
#include "ui/widgets/ElidedLabel.h"
#include "ui/widgets/ValueSlider.h"

#include <functional>

#include <QCheckBox>
#include <QDateTime>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFileSystemWatcher>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QMimeData>
#include <QPushButton>
#include <QTimer>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>

namespace facet {

namespace {

constexpr int kThumbnailPixels = 64;
constexpr int kReloadDelayMs = 200; // editors write a file in several steps; wait for the last

QString slotKey(MapSlot slot)
{
    return QString::fromLatin1(toString(slot));
}

} // namespace

TextureMapsDock::TextureMapsDock(Document* document, QWidget* parent)
    : QDockWidget(tr("Texture Maps"), parent)
    , m_document(document)
    , m_thumbnails(new ThumbnailLoader(this))
    , m_watcher(new QFileSystemWatcher(this))
    , m_reloadTimer(new QTimer(this))
    , m_messageLabel(new QLabel(this))
    , m_materialLabel(new ElidedLabel(this)) // a long name must not widen the dock
    , m_uvScale(new ValueSlider(0.1, 16.0, 2, this))
    , m_uvScaleV(new ValueSlider(0.1, 16.0, 2, this))
    , m_uvScaleLinked(new QCheckBox(tr("Uniform"), this))
    , m_uvOffsetU(new ValueSlider(-1.0, 1.0, 3, this))
    , m_uvOffsetV(new ValueSlider(-1.0, 1.0, 3, this))
    , m_uvRotation(new ValueSlider(-180.0, 180.0, 1, this))
{
    setObjectName(QStringLiteral("textureMapsDock"));
    setAcceptDrops(true);
    auto* content = new QWidget;
    auto* layout = new QVBoxLayout(content);
    m_materialLabel->setObjectName(QStringLiteral("textureMapsMaterialLabel"));
    m_materialLabel->setToolTip(tr("The material these maps belong to: choose another in the Materials panel "
                                   "or click a part in the viewport"));
    layout->addWidget(m_materialLabel);
    auto* folderButton = new QPushButton(tr("Assign Folder…"), content);
    folderButton->setObjectName(QStringLiteral("assignFolderButton"));
    folderButton->setToolTip(tr("Assign a texture set by file names, replacing the current set: *_basecolor, "
                                "*_normal, *_roughness, *_metallic, *_ao; packed *_orm, *_arm, "
                                "*metallicRoughness*, *_MaskMap; Unreal T_*_D, _N, _R, _M; a clear coat's "
                                "*_clearcoat, *_clearcoat_roughness, *_clearcoat_normal; a sheen's *_sheen, "
                                "*_sheen_roughness. You can also drop a folder or files here"));
    connect(folderButton, &QPushButton::clicked, this, &TextureMapsDock::assignFolder);
    layout->addWidget(folderButton);
    m_messageLabel->setObjectName(QStringLiteral("textureMapsMessage"));
    m_messageLabel->setWordWrap(true);
    // It names files: a long name (one word) is cut at the dock's edge rather than widening the
    // dock; the whole message is in the tooltip and the status bar.
    m_messageLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_messageLabel->hide();
    layout->addWidget(m_messageLabel);
    // The core slots, then each layered lobe's under its heading (shown while the lobe is on: the
    // Material dock's lobe section turns it on).
    const auto lobeBox = [&](MaterialLobe lobe, const QString& title, const char* name, const QString& tip) {
        auto* box = new QGroupBox(title, content);
        box->setObjectName(QLatin1String(name));
        box->setToolTip(tip);
        auto* boxLayout = new QVBoxLayout(box);
        boxLayout->setContentsMargins(0, 0, 0, 0);
        m_lobeSlots[std::size_t(lobe)] = box;
    };
    lobeBox(MaterialLobe::Clearcoat, tr("Clearcoat Maps"), "clearcoatMapsGroup",
        tr("KHR_materials_clearcoat's textures: the coat's strength (red), roughness (green) and normal map. "
           "Shown while the material has a clear coat (Material panel)."));
    lobeBox(MaterialLobe::Sheen, tr("Sheen Maps"), "sheenMapsGroup",
        tr("KHR_materials_sheen's textures: the sheen's colour (RGB, sRGB) and roughness (alpha; often "
           "one RGBA texture). Shown while the material has a sheen (Material panel)."));
    lobeBox(MaterialLobe::Specular, tr("Specular Maps"), "specularMapsGroup",
        tr("KHR_materials_specular's textures: the dielectric's F0 tint (RGB, sRGB) and specular strength "
           "(alpha; often one RGBA texture). Always shown: the dielectric's own reflectance."));
    lobeBox(MaterialLobe::Anisotropy, tr("Anisotropy Map"), "anisotropyMapsGroup",
        tr("KHR_materials_anisotropy's texture (linear): the direction in the tangent plane (red, green: "
           "x 2 - 1) and the strength (blue). Shown while the material is anisotropic (Material panel)."));
    lobeBox(MaterialLobe::Iridescence, tr("Iridescence Maps"), "iridescenceMapsGroup",
        tr("KHR_materials_iridescence's textures (linear): the film's strength (red) and thickness (green: 0 the "
           "minimum, 1 the maximum; often one texture). Shown while the material has a film (Material panel)."));
    for (MapSlot slot : kAllMapSlots) {
        QWidget* box = m_lobeSlots[std::size_t(lobeOf(slot))];
        QWidget* owner = box ? box : content;
        auto* widget = new MapSlotWidget(document, slot, owner);
        m_slots[std::size_t(slot)] = widget;
        connect(widget, &MapSlotWidget::message, this, &TextureMapsDock::message);
        connect(widget, &MapSlotWidget::filesDropped, this, &TextureMapsDock::assignFiles);
        auto* frame = new QFrame(owner);
        frame->setFrameShape(QFrame::StyledPanel);
        auto* frameLayout = new QVBoxLayout(frame);
        frameLayout->setContentsMargins(0, 0, 0, 0);
        frameLayout->addWidget(widget);
        (box ? box->layout() : layout)->addWidget(frame);
    }
    for (QWidget* box : m_lobeSlots)
        if (box)
            layout->addWidget(box);

    // One UV transform for the whole set (each map has its own in the project; the common case,
    // tiling a texture set, edits them together).
    auto* uvGroup = new QGroupBox(tr("UV Transform (all maps)"), content);
    auto* uvForm = new QFormLayout(uvGroup);
    m_uvScale->setObjectName(QStringLiteral("uvScaleSlider"));
    m_uvOffsetU->setObjectName(QStringLiteral("uvOffsetUSlider"));
    m_uvOffsetV->setObjectName(QStringLiteral("uvOffsetVSlider"));
    m_uvRotation->setObjectName(QStringLiteral("uvRotationSlider"));
    m_uvRotation->setSuffix(QStringLiteral("°"));
    m_uvScaleV->setObjectName(QStringLiteral("uvScaleVSlider"));
    m_uvScaleLinked->setObjectName(QStringLiteral("uvScaleLinkedCheck"));
    m_uvScaleLinked->setToolTip(tr("One scale for U and V: editing either sets both"));
    m_uvScaleLinked->setChecked(true);
    m_uvScale->setSpinRange(0.001, 1000.0);
    m_uvScaleV->setSpinRange(0.001, 1000.0);
    uvForm->addRow(tr("Scale U"), m_uvScale);
    uvForm->addRow(tr("Scale V"), m_uvScaleV);
    uvForm->addRow(QString(), m_uvScaleLinked);
    uvForm->addRow(tr("Offset U"), m_uvOffsetU);
    uvForm->addRow(tr("Offset V"), m_uvOffsetV);
    uvForm->addRow(tr("Rotation"), m_uvRotation);
    const auto connectUv = [this](ValueSlider* slider, std::function<void(UvTransform&, double)> apply) {
        connect(slider, &ValueSlider::editStarted, m_document, &Document::beginInteractiveEdit);
        connect(slider, &ValueSlider::editFinished, m_document, &Document::endInteractiveEdit);
        connect(slider, &ValueSlider::valueEdited, this, [this, apply](double value) {
            Material material = m_document->project().material();
            for (MaterialMap& map : material.maps)
                apply(map.uv, value);
            m_document->setMaterial(material, tr("UV Transform"), MergeId::UvTransform);
        });
    };
    // U and V apart (the format stores both; issue 30), or together while "Uniform" is ticked.
    connectUv(m_uvScale, [this](UvTransform& uv, double v) {
        uv.scale.x = v;
        if (m_uvScaleLinked->isChecked())
            uv.scale.y = v;
    });
    connectUv(m_uvScaleV, [this](UvTransform& uv, double v) {
        uv.scale.y = v;
        if (m_uvScaleLinked->isChecked())
            uv.scale.x = v;
    });
    connectUv(m_uvOffsetU, [](UvTransform& uv, double v) { uv.offset.x = v; });
    connectUv(m_uvOffsetV, [](UvTransform& uv, double v) { uv.offset.y = v; });
    connectUv(m_uvRotation, [](UvTransform& uv, double v) { uv.rotationDegrees = v; });
    layout->addWidget(uvGroup);
    layout->addStretch();

    setWidget(new DockScrollArea(content, this)); // a long file name or message never widens the dock

    m_reloadTimer->setSingleShot(true);
    m_reloadTimer->setInterval(kReloadDelayMs);
    connect(m_reloadTimer, &QTimer::timeout, this, &TextureMapsDock::reloadChangedFiles);
    connect(m_watcher, &QFileSystemWatcher::fileChanged, this, &TextureMapsDock::onFileChanged);
    connect(m_watcher, &QFileSystemWatcher::directoryChanged, this, &TextureMapsDock::onFolderChanged);
    connect(m_thumbnails, &ThumbnailLoader::ready, this,
        [this](const QString& key, const QImage& image, QSize sourceSize, const QString& error, double) {
            for (MapSlot slot : kAllMapSlots)
                if (m_thumbnailKeys[std::size_t(slot)] == key)
                    slotWidget(slot)->setThumbnail(image, sourceSize, error);
        });
    connect(m_document, &Document::changed, this, &TextureMapsDock::onDocumentChanged);
    // "Assigned 3 maps: …" is about this project's set: another project (New, Open, recovery) starts
    // without the note.
    connect(m_document, &Document::projectReplaced, this, [this] {
        m_messageLabel->clear();
        m_messageLabel->hide();
    });
    // ... and it goes when the step it reports is undone (issue 30: "Assigned 4 maps" stayed).
    connect(m_document->undoStack(), &QUndoStack::indexChanged, this, [this](int index) {
        if (m_reportedAt >= 0 && index < m_reportedAt) {
            m_messageLabel->clear();
            m_messageLabel->hide();
            m_reportedAt = -1;
        }
    });
    onDocumentChanged(DocumentChange::WholeProject);
}

TextureMapsDock::~TextureMapsDock() = default;

void TextureMapsDock::onDocumentChanged(DocumentChanges changes)
{
    // Another material chosen (the Materials dock, a click in the viewport): show that one.
    if (!(changes
            & (DocumentChanges(DocumentChange::MaterialFactors) | DocumentChange::MaterialMaps
                | DocumentChange::CurrentMaterial)))
        return;
    const Project& project = m_document->project();
    m_materialLabel->setText(project.materials.size() > 1
            ? tr("Material: %1 (%2 of %3)")
                  .arg(QString::fromStdString(project.material().name))
                  .arg(project.currentMaterial + 1)
                  .arg(project.materials.size())
            : tr("Material: %1").arg(QString::fromStdString(project.material().name)));
    for (MapSlotWidget* widget : m_slots)
        widget->refresh();
    for (std::size_t lobe = 0; lobe < m_lobeSlots.size(); ++lobe)
        if (m_lobeSlots[lobe])
            m_lobeSlots[lobe]->setVisible(MaterialLobe(lobe) == MaterialLobe::Specular
                || project.material().hasLobe(MaterialLobe(lobe)));
    const UvTransform& uv = m_document->project().material().map(MapSlot::BaseColor).uv;
    m_uvScale->setValue(uv.scale.x);
    m_uvScaleV->setValue(uv.scale.y);
    if (uv.scale.x != uv.scale.y)
        m_uvScaleLinked->setChecked(false); // a file's different scales are shown as they are
    m_uvOffsetU->setValue(uv.offset.x);
    m_uvOffsetV->setValue(uv.offset.y);
    m_uvRotation->setValue(uv.rotationDegrees);
    if (changes & (DocumentChanges(DocumentChange::MaterialMaps) | DocumentChange::CurrentMaterial)) {
        refreshThumbnails(false);
        watchFiles();
    }
}

void TextureMapsDock::refreshThumbnails(bool force)
{
    for (MapSlot slot : kAllMapSlots) {
        const std::string& path = m_document->project().material().map(slot).path;
        QString& key = m_thumbnailKeys[std::size_t(slot)];
        if (path.empty()) {
            key.clear();
            continue;
        }
        const QString file = QString::fromStdString(path);
        // The file's time is part of the key: a file rewritten on disk gets a new thumbnail.
        const QString wanted = slotKey(slot) + u'|' + file + u'|'
            + QString::number(QFileInfo(file).lastModified().toMSecsSinceEpoch());
        if (wanted == key && !force)
            continue;
        key = wanted;
        m_thumbnails->request(
            key, file, ThumbnailLoader::Kind::Texture, QSize(kThumbnailPixels, kThumbnailPixels));
    }
}

void TextureMapsDock::watchFiles()
{
    // The maps' files, and their folders: a file deleted and made again (an exporter that removes
    // the old set first) ends the file's watch, and only its folder tells when it is back (issue
    // 29: such a texture never reloaded).
    m_wantedFiles.clear();
    QStringList wanted;
    QStringList folders;
    for (const MaterialMap& map : m_document->project().material().maps) {
        if (!map.hasTexture())
            continue;
        const QString file = QString::fromStdString(map.path);
        m_wantedFiles.append(file);
        if (QFileInfo::exists(file))
            wanted.append(file);
        const QString folder = QFileInfo(file).absolutePath();
        if (QFileInfo(folder).isDir())
            folders.append(folder);
    }
    m_wantedFiles.removeDuplicates();
    wanted.removeDuplicates();
    folders.removeDuplicates();
    const QStringList watched = m_watcher->files();
    for (const QString& file : watched)
        if (!wanted.contains(file))
            m_watcher->removePath(file);
    for (const QString& file : wanted)
        if (!watched.contains(file))
            m_watcher->addPath(file);
    const QStringList watchedFolders = m_watcher->directories();
    for (const QString& folder : watchedFolders)
        if (!folders.contains(folder))
            m_watcher->removePath(folder);
    for (const QString& folder : folders)
        if (!watchedFolders.contains(folder))
            m_watcher->addPath(folder);
}

void TextureMapsDock::onFolderChanged(const QString& folder)
{
    // A map's file that exists again but is not watched: made anew since it was removed.
    const QStringList watched = m_watcher->files();
    for (const QString& file : std::as_const(m_wantedFiles))
        if (QFileInfo(file).absolutePath() == folder && !watched.contains(file) && QFileInfo::exists(file))
            onFileChanged(file);
}

void TextureMapsDock::onFileChanged(const QString& path)
{
    if (!m_changedFiles.contains(path))
        m_changedFiles.append(path);
    m_reloadTimer->start();
}

void TextureMapsDock::reloadChangedFiles()
{
    QStringList reloaded;
    for (const QString& file : std::as_const(m_changedFiles)) {
        // Editors often save by writing a new file and renaming it over the old one, which
        // ends the watch: watch the new file. A file removed is watched again through its folder
        // when it comes back (onFolderChanged).
        if (QFileInfo::exists(file) && !m_watcher->files().contains(file))
            m_watcher->addPath(file);
        reloaded.append(QFileInfo(file).fileName());
    }
    m_changedFiles.clear();
    if (reloaded.isEmpty())
        return;
    // The path did not change, so no edit happened: the maps may just be stale.
    m_document->notifyFilesChangedOnDisk(DocumentChange::MaterialMaps);
    Q_EMIT message(tr("Reloaded %1 (changed on disk)").arg(reloaded.join(QStringLiteral(", "))));
}

QString TextureMapsDock::assignFiles(const QStringList& paths)
{
    const MapNamingResult result = assignMapsByName(paths);
    // A folder or several files is a texture set: it replaces the whole set, so no map of the
    // previous set survives in a slot the new one does not fill. One file adds to the set.
    const bool wholeSet = paths.size() > 1
        || std::any_of(paths.begin(), paths.end(), [](const QString& p) { return QFileInfo(p).isDir(); });
    QStringList parts;
    for (const MapAssignment& assignment : result.assignments)
        parts.append(MapSlotWidget::title(assignment.slot) + QStringLiteral(" ← ")
            + QFileInfo(assignment.path).fileName()
            + MapSlotWidget::readNote(assignment.slot, assignment.channel, assignment.invert,
                assignment.flipGreen, assignment.convention));
    const auto names = [](const QStringList& files) {
        QStringList out;
        for (const QString& file : files)
            out.append(QFileInfo(file).fileName());
        return out.join(QStringLiteral(", "));
    };
    QString text;
    if (result.assignments.empty()) {
        text = tr("No texture maps found in %1: names should end in _basecolor, _normal, _metallic, "
                  "_roughness, _ao, _orm (see the Assign Folder button's tip)")
                   .arg(names(paths));
    } else {
        const Material& before = m_document->project().material();
        std::vector<MapSlot> cleared;
        const Material material = wholeSet ? withTextureSet(before, result.assignments, &cleared)
                                           : withAssignedMaps(before, result.assignments);
        m_document->setMaterial(material, tr("Assign Maps"));
        text = (result.assignments.size() == 1 ? tr("Assigned 1 map: ")
                                               : tr("Assigned %1 maps: ").arg(result.assignments.size()))
            + parts.join(QStringLiteral(", "));
        QStringList clearedParts;
        for (MapSlot slot : cleared) {
            QString part = MapSlotWidget::title(slot);
            if (slot == MapSlot::Metallic || slot == MapSlot::Roughness)
                part += tr(" (now %1)").arg(material.map(slot).factor.x);
            else if (slot == MapSlot::Clearcoat && !material.hasClearcoat())
                part += tr(" (no coat now)");
            else if (slot == MapSlot::SheenColor && !material.hasSheen())
                part += tr(" (no sheen now)");
            else if (slot == MapSlot::Anisotropy && !material.hasAnisotropy())
                part += tr(" (isotropic now)");
            else if (slot == MapSlot::Iridescence && !material.hasIridescence())
                part += tr(" (no film now)");
            clearedParts.append(part);
        }
        if (!clearedParts.isEmpty())
            text += tr("; cleared (not in this set): %1").arg(clearedParts.join(QStringLiteral(", ")));
    }
    if (!result.unmatched.isEmpty())
        text += tr("; not used: %1").arg(names(result.unmatched));
    if (!result.notImages.isEmpty())
        text += tr("; not images: %1").arg(names(result.notImages));
    report(text);
    return text;
}

void TextureMapsDock::report(const QString& text)
{
    m_messageLabel->setText(text);
    m_messageLabel->setToolTip(text);
    m_messageLabel->show();
    m_reportedAt = m_document->undoStack()->index();
    Q_EMIT message(text);
}

QString TextureMapsDock::lastMessage() const
{
    return m_messageLabel->text();
}

int TextureMapsDock::pendingThumbnails() const
{
    return m_thumbnails->pending();
}

void TextureMapsDock::assignFolder()
{
    const QString folder = QFileDialog::getExistingDirectory(this, tr("Assign Texture Folder"));
    if (!folder.isEmpty())
        assignFiles({folder});
}

void TextureMapsDock::dragEnterEvent(QDragEnterEvent* event)
{
    if (event->mimeData()->hasUrls())
        event->acceptProposedAction();
}

void TextureMapsDock::dropEvent(QDropEvent* event)
{
    const QStringList files = droppedLocalFiles(event->mimeData());
    if (files.isEmpty()) {
        report(tr("Nothing to assign: only local files and folders can be dropped"));
        return;
    }
    event->acceptProposedAction();
    assignFiles(files);
}

} // namespace facet
