#include "ui/docks/MapSlotWidget.h"

#include "core/gltf/GltfImport.h"
#include "core/image/MapImageCache.h"
#include "core/material/MapNaming.h"
#include "core/material/MaterialList.h"
#include "core/material/MaterialProperties.h"
#include "ui/dialogs/MapInspectorDialog.h"
#include "ui/document/Document.h"
#include "ui/document/DocumentCommands.h"
#include "ui/widgets/ColorButton.h"
#include "ui/widgets/DroppedFiles.h"
#include "ui/widgets/ElidedLabel.h"
#include "ui/widgets/ValueSlider.h"
#include "ui/widgets/WindowMessages.h"

#include <QApplication>
#include <QCheckBox>
#include <QClipboard>
#include <QComboBox>
#include <QContextMenuEvent>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QMenu>
#include <QMimeData>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace facet {

namespace {

constexpr int kThumbnailSize = 64;
// The emissive strength slider's first step above 0 (ValueSlider::setLogarithmic).
constexpr double kSmallestEmissiveStrengthStep = 0.01;

int mergeIdFor(MapSlot slot)
{
    switch (slot) {
    case MapSlot::BaseColor:
        return MergeId::BaseColor;
    case MapSlot::Normal:
        return MergeId::NormalStrength;
    case MapSlot::Metallic:
        return MergeId::Metallic;
    case MapSlot::Roughness:
        return MergeId::Roughness;
    case MapSlot::Occlusion:
        return MergeId::Occlusion;
    case MapSlot::Clearcoat:
    case MapSlot::ClearcoatRoughness:
    case MapSlot::ClearcoatNormal:
    case MapSlot::SheenColor:
    case MapSlot::SheenRoughness:
    case MapSlot::Specular:
    case MapSlot::SpecularColor:
    case MapSlot::Anisotropy:
    case MapSlot::Iridescence:
    case MapSlot::IridescenceThickness:
        // The registry's row of the slot's factor: the Material dock's slider (or colour) of it
        // merges alike. (Base colour's row also holds the alpha, a row of its own.)
        for (const MaterialPropertyInfo& info : materialProperties())
            if (info.slot == slot)
                return MergeId::MaterialProperty0 + int(info.property);
        break;
    case MapSlot::Emissive:
        break;
    }
    return MergeId::None;
}

QString factorName(MapSlot slot)
{
    switch (slot) {
    case MapSlot::Normal:
        return QObject::tr("Normal Strength");
    case MapSlot::Occlusion:
        return QObject::tr("Occlusion Strength");
    case MapSlot::ClearcoatNormal:
        return QObject::tr("Clearcoat Normal Strength");
    default:
        return MapSlotWidget::title(slot);
    }
}

} // namespace

QString MapSlotWidget::title(MapSlot slot)
{
    switch (slot) {
    case MapSlot::BaseColor:
        return tr("Base Colour");
    case MapSlot::Normal:
        return tr("Normal");
    case MapSlot::Metallic:
        return tr("Metallic");
    case MapSlot::Roughness:
        return tr("Roughness");
    case MapSlot::Occlusion:
        return tr("Ambient Occlusion");
    case MapSlot::Emissive:
        return tr("Emissive");
    case MapSlot::Clearcoat:
        return tr("Clearcoat");
    case MapSlot::ClearcoatRoughness:
        return tr("Clearcoat Roughness");
    case MapSlot::ClearcoatNormal:
        return tr("Clearcoat Normal");
    case MapSlot::SheenColor:
        return tr("Sheen Colour");
    case MapSlot::SheenRoughness:
        return tr("Sheen Roughness");
    case MapSlot::Specular:
        return tr("Specular Strength");
    case MapSlot::SpecularColor:
        return tr("Specular Colour");
    case MapSlot::Anisotropy:
        return tr("Anisotropy");
    case MapSlot::Iridescence:
        return tr("Iridescence");
    case MapSlot::IridescenceThickness:
        return tr("Iridescence Thickness");
    }
    return {};
}

QString MapSlotWidget::readNote(
    MapSlot slot, MapChannel channel, bool invert, bool flipGreen, const QString& convention)
{
    QStringList parts;
    if (!convention.isEmpty())
        parts.append(convention);
    if (isScalarSlot(slot) && (channel != MapChannel::R || !convention.isEmpty())) {
        switch (channel) {
        case MapChannel::R:
            parts.append(tr("red"));
            break;
        case MapChannel::G:
            parts.append(tr("green"));
            break;
        case MapChannel::B:
            parts.append(tr("blue"));
            break;
        case MapChannel::A:
            parts.append(tr("alpha"));
            break;
        case MapChannel::Rgb:
            break;
        }
    }
    if (isScalarSlot(slot) && invert)
        parts.append(tr("inverted"));
    if (isNormalSlot(slot) && flipGreen)
        parts.append(tr("DirectX"));
    return parts.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(parts.join(QStringLiteral(", ")));
}

MapSlotWidget::MapSlotWidget(Document* document, MapSlot slot, QWidget* parent)
    : QWidget(parent)
    , m_document(document)
    , m_slot(slot)
    , m_thumbnail(new QLabel(this))
    , m_fileLabel(new ElidedLabel(this)) // a long file name must not widen the dock
    , m_clear(new QPushButton(tr("Clear"), this))
{
    const QString key = QString::fromLatin1(toString(slot));
    setObjectName(QStringLiteral("mapSlot_%1").arg(key));
    setAcceptDrops(true);
    m_thumbnail->setFixedSize(kThumbnailSize, kThumbnailSize);
    m_thumbnail->setAlignment(Qt::AlignCenter);
    m_thumbnail->setFrameShape(QFrame::StyledPanel);
    m_thumbnail->setToolTip(tr("Drop an image file here"));
    m_fileLabel->setObjectName(QStringLiteral("mapFileLabel_%1").arg(key));
    auto* open = new QPushButton(tr("Open…"), this);
    open->setObjectName(QStringLiteral("mapOpenButton_%1").arg(key));
    m_clear->setObjectName(QStringLiteral("mapClearButton_%1").arg(key));
    connect(open, &QPushButton::clicked, this, &MapSlotWidget::openFile);
    connect(m_clear, &QPushButton::clicked, this, &MapSlotWidget::clearFile);

    auto* titleLabel = new QLabel(QStringLiteral("<b>%1</b>").arg(title(slot)), this);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(open);
    buttons->addWidget(m_clear);
    buttons->addStretch();
    auto* info = new QVBoxLayout;
    info->addWidget(titleLabel);
    info->addWidget(m_fileLabel);
    info->addLayout(buttons);
    auto* header = new QHBoxLayout;
    header->addWidget(m_thumbnail);
    header->addLayout(info, 1);

    auto* form = new QFormLayout;
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    const int mergeId = mergeIdFor(slot);
    if (isColorSlot(slot)) {
        // Base colour, emissive and the sheen's colour hold a linear RGB colour (the emissive one
        // in [0, 1], its brightness in the strength below, as KHR_materials_emissive_strength
        // splits them).
        m_color = new ColorButton(this);
        m_color->setObjectName(slot == MapSlot::Emissive ? QStringLiteral("emissiveColorButton")
                                                         : key + QStringLiteral("Button"));
        form->addRow(tr("Colour"), m_color);
        connect(m_color, &ColorButton::colorEdited, this, [this](const glm::dvec3& linear) {
            MaterialMap map = m_document->project().material().map(m_slot);
            map.factor = glm::dvec4(linear, map.factor.w);
            editMap(map, m_slot == MapSlot::Emissive ? tr("Emissive Colour") : title(m_slot));
        });
        if (slot == MapSlot::Emissive) {
            // 0 to 10000 spans six decades: a logarithmic slider (each step about 1.4% brighter),
            // the exact number in the spin box.
            m_strength = new ValueSlider(0.0, Material::kMaxEmissiveStrength, 3, this);
            m_strength->setLogarithmic(kSmallestEmissiveStrengthStep);
            m_strength->setObjectName(QStringLiteral("emissiveStrengthSlider"));
            m_strength->setToolTip(tr("Multiplies the emissive colour (KHR_materials_emissive_strength): 1 "
                                      "glows like a white surface lit by the environment's 1, 100 makes a "
                                      "light source"));
            form->addRow(tr("Strength"), m_strength);
            connect(m_strength, &ValueSlider::editStarted, m_document, &Document::beginInteractiveEdit);
            connect(m_strength, &ValueSlider::editFinished, m_document, &Document::endInteractiveEdit);
            connect(m_strength, &ValueSlider::valueEdited, this, [this](double value) {
                Material material = m_document->project().material();
                material.emissiveStrength = value;
                m_document->setMaterial(material, tr("Emissive Strength"), MergeId::EmissiveStrength);
            });
        }
    } else {
        // The factor's slider from the slot's registry row (core/material/MaterialProperties.h): a
        // normal map's spans the usual 0-2 and its field what the format allows (issue 30), the
        // film's thickness nanometres, the other factors 0-1.
        const bool normal = isNormalSlot(slot);
        const bool thickness = slot == MapSlot::IridescenceThickness;
        m_factor = ValueSlider::forProperty(infoOf(*factorPropertyOf(slot)), this);
        m_factor->setObjectName(QStringLiteral("factorSlider_%1").arg(key));
        if (thickness)
            m_factor->setSuffix(tr(" nm"));
        form->addRow(
            thickness ? tr("Maximum")
                      : normal || slot == MapSlot::Occlusion || slot == MapSlot::Clearcoat ? tr("Strength")
                                                                                          : tr("Value"),
            m_factor);
        connect(m_factor, &ValueSlider::editStarted, m_document, &Document::beginInteractiveEdit);
        connect(m_factor, &ValueSlider::editFinished, m_document, &Document::endInteractiveEdit);
        connect(m_factor, &ValueSlider::valueEdited, this, [this, mergeId](double value) {
            MaterialMap map = m_document->project().material().map(m_slot);
            map.factor = glm::dvec4(value);
            editMap(map, factorName(m_slot), mergeId);
        });
    }
    if (!readsRgbOnly(slot)) {
        m_channel = new QComboBox(this);
        m_channel->setObjectName(QStringLiteral("mapChannel_%1").arg(key));
        if (slot == MapSlot::BaseColor)
            m_channel->addItem(tr("RGB"), int(MapChannel::Rgb));
        m_channel->addItem(tr("Red"), int(MapChannel::R));
        m_channel->addItem(tr("Green"), int(MapChannel::G));
        m_channel->addItem(tr("Blue"), int(MapChannel::B));
        m_channel->addItem(tr("Alpha"), int(MapChannel::A));
        m_channel->setToolTip(tr("The channel to read: ORM textures pack occlusion in red, roughness in "
                                 "green and metallic in blue"));
        form->addRow(tr("Channel"), m_channel);
        connect(m_channel, &QComboBox::activated, this, [this] {
            MaterialMap map = m_document->project().material().map(m_slot);
            map.channel = MapChannel(m_channel->currentData().toInt());
            editMap(map, tr("%1 Channel").arg(title(m_slot)));
        });
    }
    m_colorSpace = new QComboBox(this);
    m_colorSpace->setObjectName(QStringLiteral("mapColorSpace_%1").arg(key));
    m_colorSpace->addItem(tr("sRGB"), int(ColorEncoding::SRGB));
    m_colorSpace->addItem(tr("Linear (data)"), int(ColorEncoding::Linear));
    form->addRow(tr("Colour space"), m_colorSpace);
    connect(m_colorSpace, &QComboBox::activated, this, [this] {
        MaterialMap map = m_document->project().material().map(m_slot);
        map.colorSpace = ColorEncoding(m_colorSpace->currentData().toInt());
        editMap(map, tr("%1 Colour Space").arg(title(m_slot)));
    });
    if (isScalarSlot(slot)) {
        m_invert = new QCheckBox(
            slot == MapSlot::Roughness ? tr("Invert (smoothness / gloss map)") : tr("Invert"), this);
        m_invert->setObjectName(QStringLiteral("mapInvert_%1").arg(key));
        form->addRow(QString(), m_invert);
        connect(m_invert, &QCheckBox::clicked, this, [this](bool on) {
            MaterialMap map = m_document->project().material().map(m_slot);
            map.invert = on;
            editMap(map, tr("Invert %1").arg(title(m_slot)));
        });
    }
    if (isNormalSlot(slot)) {
        m_flipGreen = new QCheckBox(tr("DirectX (flip green)"), this);
        m_flipGreen->setObjectName(slot == MapSlot::Normal ? QStringLiteral("mapFlipGreen")
                                                           : QStringLiteral("mapFlipGreen_%1").arg(key));
        form->addRow(QString(), m_flipGreen);
        connect(m_flipGreen, &QCheckBox::clicked, this, [this](bool on) {
            MaterialMap map = m_document->project().material().map(m_slot);
            map.flipGreen = on;
            editMap(map, tr("Flip %1 Green").arg(title(m_slot)));
        });
    }
    m_texCoord = new QComboBox(this);
    m_texCoord->setObjectName(QStringLiteral("mapTexCoord_%1").arg(key));
    m_texCoord->addItem(tr("UV 0"), 0);
    m_texCoord->addItem(tr("UV 1"), 1);
    m_texCoord->setToolTip(tr("The texture-coordinate set the map reads (glTF TEXCOORD_0 or TEXCOORD_1: "
                              "baked occlusion and lightmaps often use the second). A mesh without a "
                              "second set reads the first."));
    form->addRow(tr("UV set"), m_texCoord);
    connect(m_texCoord, &QComboBox::activated, this, [this] {
        MaterialMap map = m_document->project().material().map(m_slot);
        map.texCoord = m_texCoord->currentData().toInt();
        editMap(map, tr("%1 UV Set").arg(title(m_slot)));
    });
    m_wrap = new QComboBox(this);
    m_wrap->setObjectName(QStringLiteral("mapWrap_%1").arg(key));
    m_wrap->addItem(tr("Repeat"), int(TextureWrap::Repeat));
    m_wrap->addItem(tr("Clamp to edge"), int(TextureWrap::ClampToEdge));
    m_wrap->addItem(tr("Mirrored repeat"), int(TextureWrap::MirroredRepeat));
    m_wrap->setToolTip(tr("How the texture continues outside [0, 1] in U and V (the glTF sampler's "
                          "wrapS and wrapT)"));
    form->addRow(tr("Wrap"), m_wrap);
    connect(m_wrap, &QComboBox::activated, this, [this] {
        const QVariant wrap = m_wrap->currentData();
        if (!wrap.isValid())
            return; // the file's mixed pair, shown as it is
        MaterialMap map = m_document->project().material().map(m_slot);
        map.sampler.wrapS = map.sampler.wrapT = TextureWrap(wrap.toInt());
        editMap(map, tr("%1 Wrap").arg(title(m_slot)));
    });

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(header);
    layout->addLayout(form);
    refresh();
}

void MapSlotWidget::refresh()
{
    const MaterialMap& map = m_document->project().material().map(m_slot);
    if (map.hasTexture()) {
        // An image embedded in a glTF asset ("helmet.glb#images/2") is named after the asset and
        // is there when the asset is (core/gltf/GltfImport.h).
        const std::optional<GltfImageReference> embedded = parseGltfImageReference(map.path);
        const QFileInfo info(QString::fromStdString(embedded ? embedded->assetPath : map.path));
        QString text = WindowMessages::fileDisplayName(QString::fromStdString(map.path));
        if (m_sourceSize.isValid())
            text += QStringLiteral("\n%1×%2").arg(m_sourceSize.width()).arg(m_sourceSize.height());
        if (!info.exists())
            text += tr("\n(missing)");
        m_fileLabel->setText(text);
        m_fileLabel->setToolTip(embedded
                ? tr("Image %1 embedded in %2").arg(embedded->imageIndex).arg(info.absoluteFilePath())
                : info.absoluteFilePath());
    } else {
        m_fileLabel->setText(tr("No file: the value below"));
        m_fileLabel->setToolTip({});
        m_thumbnail->clear();
        m_sourceSize = {};
    }
    m_clear->setEnabled(map.hasTexture());
    if (m_color)
        m_color->setLinearColor(glm::dvec3(map.factor));
    if (m_factor)
        m_factor->setValue(map.factor.x);
    if (m_strength)
        m_strength->setValue(m_document->project().material().emissiveStrength);
    const auto select = [](QComboBox* combo, int value) {
        if (!combo)
            return;
        const QSignalBlocker blocker(combo);
        combo->setCurrentIndex(combo->findData(value));
    };
    select(m_channel, int(map.channel));
    select(m_colorSpace, int(map.colorSpace));
    select(m_texCoord, map.texCoord);
    {
        // A pair the file gave (clamp in U, repeat in V) is shown as one extra item, kept until
        // the artist picks one wrap for both.
        const QSignalBlocker blocker(m_wrap);
        if (m_wrap->count() > 3)
            m_wrap->removeItem(3);
        if (map.sampler.wrapS == map.sampler.wrapT) {
            m_wrap->setCurrentIndex(m_wrap->findData(int(map.sampler.wrapS)));
        } else {
            const auto name = [this](TextureWrap wrap) {
                return wrap == TextureWrap::ClampToEdge   ? tr("clamp")
                    : wrap == TextureWrap::MirroredRepeat ? tr("mirror")
                                                          : tr("repeat");
            };
            m_wrap->addItem(tr("U %1, V %2").arg(name(map.sampler.wrapS), name(map.sampler.wrapT)));
            m_wrap->setCurrentIndex(3);
        }
    }
    if (m_invert)
        m_invert->setChecked(map.invert);
    if (m_flipGreen)
        m_flipGreen->setChecked(map.flipGreen);
    for (QWidget* option : {static_cast<QWidget*>(m_channel), static_cast<QWidget*>(m_colorSpace),
             static_cast<QWidget*>(m_invert), static_cast<QWidget*>(m_flipGreen),
             static_cast<QWidget*>(m_texCoord), static_cast<QWidget*>(m_wrap)})
        if (option)
            option->setEnabled(map.hasTexture());
}

void MapSlotWidget::setThumbnail(const QImage& image, QSize sourceSize, const QString& error)
{
    m_sourceSize = sourceSize;
    if (image.isNull()) {
        m_thumbnail->setText(tr("?"));
        m_thumbnail->setToolTip(error);
    } else {
        m_thumbnail->setPixmap(QPixmap::fromImage(image));
        m_thumbnail->setToolTip(tr("Drop an image file here"));
    }
    refresh();
}

bool MapSlotWidget::assignFile(const QString& path)
{
    const QFileInfo info(path);
    if (!info.isFile()) {
        Q_EMIT message(tr("Cannot use %1 as the %2 map: no such file").arg(path, title(m_slot)));
        return false;
    }
    if (!isImageFileName(path)) {
        Q_EMIT message(tr("Cannot use %1 as the %2 map: not an image file Facet reads (PNG, JPEG, TGA, "
                          "TIFF, EXR, HDR…)")
                           .arg(info.fileName(), title(m_slot)));
        return false;
    }
    // The channel (and invert, green flip) this slot reads, from the file's naming convention: a
    // packed ORM opened on the metallic slot reads blue, a Unity mask map on roughness reads alpha
    // inverted. A normal map whose name does not say OpenGL or DirectX keeps the slot's setting.
    const QString file = info.absoluteFilePath();
    const MapRead read = mapReadFor(m_slot, file);
    const TextureNaming naming = textureNaming(file);
    const Material& current = m_document->project().material();
    const Material material = withAssignedMaps(current,
        {MapAssignment {m_slot, file, read.channel, read.invert,
            read.flipGreen.value_or(current.map(m_slot).flipGreen), naming.convention}});
    m_document->setMaterial(material, tr("Set %1 Map").arg(title(m_slot)));
    Q_EMIT message(tr("%1 map: %2").arg(title(m_slot), info.fileName())
        + readNote(m_slot, read.channel, read.invert, material.map(m_slot).flipGreen, naming.convention));
    return true;
}

void MapSlotWidget::clearFile()
{
    MaterialMap map = m_document->project().material().map(m_slot);
    if (!map.hasTexture())
        return;
    map.path.clear();
    editMap(map, tr("Clear %1 Map").arg(title(m_slot)));
}

void MapSlotWidget::editMap(const MaterialMap& map, const QString& undoText, int mergeId)
{
    Material material = m_document->project().material();
    material.map(m_slot) = map;
    m_document->setMaterial(material, undoText, mergeId);
}

void MapSlotWidget::openFile()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Open %1 Map").arg(title(m_slot)), {},
        tr("Images (*.png *.jpg *.jpeg *.tga *.tif *.tiff *.exr *.hdr *.bmp *.webp);;All files (*)"));
    if (!path.isEmpty())
        assignFile(path);
}

void MapSlotWidget::dragEnterEvent(QDragEnterEvent* event)
{
    if (!droppedLocalFiles(event->mimeData()).isEmpty())
        event->acceptProposedAction();
}

void MapSlotWidget::dropEvent(QDropEvent* event)
{
    const QStringList files = droppedLocalFiles(event->mimeData());
    if (files.isEmpty())
        return;
    event->acceptProposedAction();
    if (files.size() == 1 && !QFileInfo(files.first()).isDir())
        assignFile(files.first());
    else
        Q_EMIT filesDropped(files);
}

namespace {
// The clipboard's form of one map: {"slot": "roughness", "material": a material object of the
// project format whose map of that slot is the copy (texture paths absolute)}, under its own MIME
// type and as text.
const char* const kMapMime = "application/x-facet-map+json";

struct CopiedMap {
    MapSlot slot = MapSlot::BaseColor;
    MaterialMap map;
};

std::optional<CopiedMap> copiedMap()
{
    const QMimeData* mime = QGuiApplication::clipboard()->mimeData();
    QByteArray json = mime ? mime->data(QLatin1String(kMapMime)) : QByteArray();
    if (json.isEmpty() && mime && mime->hasText())
        json = mime->text().toUtf8();
    const QJsonObject object = QJsonDocument::fromJson(json).object();
    const std::optional<MapSlot> slot
        = mapSlotFromString(object.value(QStringLiteral("slot")).toString().toStdString());
    if (!slot || !object.value(QStringLiteral("material")).isObject())
        return std::nullopt;
    std::string error;
    const std::optional<Material> material = materialFromJson(
        object.value(QStringLiteral("material")).toObject(), std::string(), "material", &error);
    if (!material)
        return std::nullopt;
    return CopiedMap {*slot, material->map(*slot)};
}

} // namespace

void MapSlotWidget::copyMap()
{
    const Material& material = m_document->project().material();
    QJsonObject object;
    object.insert(QStringLiteral("slot"), QString::fromLatin1(toString(m_slot)));
    object.insert(QStringLiteral("material"), materialToJson(material, std::string()));
    const QByteArray json = QJsonDocument(object).toJson(QJsonDocument::Compact);
    auto* mime = new QMimeData;
    mime->setData(QLatin1String(kMapMime), json);
    mime->setText(QString::fromUtf8(json));
    QGuiApplication::clipboard()->setMimeData(mime);
    const MaterialMap& map = material.map(m_slot);
    Q_EMIT message(map.hasTexture()
            ? tr("Copied the %1 map (%2)")
                  .arg(title(m_slot).toLower(), QFileInfo(QString::fromStdString(map.path)).fileName())
            : tr("Copied the %1 value").arg(title(m_slot).toLower()));
}

bool MapSlotWidget::pasteMap()
{
    const std::optional<CopiedMap> copied = copiedMap();
    if (!copied) {
        Q_EMIT message(tr("Paste Map: the clipboard holds no map (Copy Map on a slot first)"));
        return false;
    }
    const MaterialMap& target = m_document->project().material().map(m_slot);
    editMap(pastedMap(copied->slot, copied->map, m_slot, target), tr("Paste %1 Map").arg(title(m_slot)));
    Q_EMIT message(
        tr("Pasted the %1 map onto %2").arg(title(copied->slot).toLower(), title(m_slot).toLower()));
    return true;
}

bool MapSlotWidget::pasteValue()
{
    const std::optional<CopiedMap> copied = copiedMap();
    const std::optional<glm::dvec4> factor
        = copied ? pastedFactor(copied->slot, copied->map, m_slot) : std::nullopt;
    if (!factor) {
        Q_EMIT message(copied ? tr("Paste Value: a %1 value does not fit the %2 slot")
                                    .arg(title(copied->slot).toLower(), title(m_slot).toLower())
                              : tr("Paste Value: the clipboard holds no map (Copy Map on a slot first)"));
        return false;
    }
    MaterialMap map = m_document->project().material().map(m_slot);
    map.factor = *factor;
    editMap(map, tr("Paste %1 Value").arg(title(m_slot)));
    Q_EMIT message(
        tr("Pasted the %1 value onto %2").arg(title(copied->slot).toLower(), title(m_slot).toLower()));
    return true;
}

MapInspectorDialog* MapSlotWidget::inspectMap()
{
    const Material& material = m_document->project().material();
    const MaterialMap& map = material.map(m_slot);
    if (!map.hasTexture()) {
        Q_EMIT message(tr("Inspect Map: the %1 slot has no file").arg(title(m_slot).toLower()));
        return nullptr;
    }
    std::string error;
    QApplication::setOverrideCursor(Qt::WaitCursor);
    // Decoded again if the window let its copy go after the upload (docs/app.md "Loading texture maps").
    const std::shared_ptr<const MapImage> image = MapImageCache::shared().load(map.path, &error);
    QApplication::restoreOverrideCursor();
    if (!image) {
        Q_EMIT message(WindowMessages::fromCore(error));
        return nullptr;
    }
    auto* dialog = new MapInspectorDialog(material, m_slot, image, window());
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->show();
    return dialog;
}

void MapSlotWidget::contextMenuEvent(QContextMenuEvent* event)
{
    QMenu menu(this);
    QAction* inspect = menu.addAction(tr("Inspect Map…"), this, &MapSlotWidget::inspectMap);
    inspect->setEnabled(m_document->project().material().map(m_slot).hasTexture());
    menu.addSeparator();
    menu.addAction(tr("Copy Map"), this, &MapSlotWidget::copyMap);
    const std::optional<CopiedMap> copied = copiedMap();
    QAction* paste = menu.addAction(tr("Paste Map"), this, &MapSlotWidget::pasteMap);
    paste->setEnabled(copied.has_value());
    QAction* value = menu.addAction(tr("Paste Value"), this, &MapSlotWidget::pasteValue);
    value->setEnabled(copied && pastedFactor(copied->slot, copied->map, m_slot));
    if (m_document->project().material().map(m_slot).hasTexture()) {
        menu.addSeparator();
        menu.addAction(tr("Clear"), this, &MapSlotWidget::clearFile);
    }
    menu.exec(event->globalPos());
}

} // namespace facet
