#include "ui/docks/ValuesDock.h"

#include "core/image/ToneMap.h"
#include "ui/docks/MapSlotWidget.h"

#include <QApplication>
#include <QCheckBox>
#include <QClipboard>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace facet {

namespace {

// Four significant digits: radiance spans decades (0.0213, 12.47, 3081).
QString number(double value)
{
    if (!std::isfinite(value))
        return QString::number(value);
    return QString::number(value, 'g', 4);
}

template <int N, typename T> QString components(const glm::vec<N, T>& v)
{
    QStringList parts;
    for (int i = 0; i < N; ++i)
        parts << number(double(v[i]));
    return parts.join(QStringLiteral("  "));
}

// A stored texel as the file holds it: whole numbers for 8- and 16-bit samples, the values of a
// half-float map.
QString storedSamples(const glm::dvec4& v, int channels, MapSampleType type)
{
    const double scale = type == MapSampleType::UInt8 ? 255.0 : type == MapSampleType::UInt16 ? 65535.0 : 0.0;
    QStringList parts;
    for (int i = 0; i < channels; ++i)
        parts << (scale > 0.0 ? QString::number(std::lround(v[i] * scale)) : number(v[i]));
    return parts.join(QStringLiteral("  ")) + QStringLiteral(" (%1)").arg(QLatin1String(toString(type)));
}

// Rec. 709 / sRGB luminance of linear RGB.
double luminance(const glm::dvec3& rgb)
{
    return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b;
}

QTreeWidgetItem* row(QTreeWidgetItem* parent, const QString& name, const QString& value = {})
{
    auto* item = new QTreeWidgetItem(parent, {name, value});
    item->setToolTip(1, value);
    return item;
}

} // namespace

ValuesDock::ValuesDock(ValuePicker* picker, QWidget* parent)
    : QDockWidget(tr("Values"), parent)
    , m_picker(picker)
{
    setObjectName(QStringLiteral("valuesDock"));
    auto* content = new QWidget(this);
    auto* layout = new QVBoxLayout(content);
    m_hint = new QLabel(content);
    m_hint->setWordWrap(true);
    m_hint->setObjectName(QStringLiteral("valuesHint"));
    layout->addWidget(m_hint);
    auto* controls = new QHBoxLayout;
    m_pinned = new QCheckBox(tr("Pinned"), content);
    m_pinned->setObjectName(QStringLiteral("valuesPinned"));
    m_pinned->setToolTip(tr("A click in the view pins the reading to that point; unpinned, it follows the "
                            "cursor (Esc in the view)"));
    auto* copy = new QPushButton(tr("Copy"), content);
    copy->setObjectName(QStringLiteral("valuesCopy"));
    copy->setToolTip(tr("Copy every row as text"));
    controls->addWidget(m_pinned);
    controls->addStretch(1);
    controls->addWidget(copy);
    layout->addLayout(controls);
    m_tree = new QTreeWidget(content);
    m_tree->setObjectName(QStringLiteral("valuesTree"));
    m_tree->setColumnCount(2);
    m_tree->setHeaderLabels({tr("Quantity"), tr("Value")});
    m_tree->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_tree->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_tree->setUniformRowHeights(true);
    m_tree->setIndentation(12);
    layout->addWidget(m_tree, 1);
    setWidget(content);

    const auto updateHint = [this] {
        m_hint->setText(!m_picker->isActive() ? tr("Turn on View > Value Picker (I) and hover the view.")
                : m_picker->isPinned()        ? tr("Pinned: click elsewhere in the view to move it.")
                                              : tr("Following the cursor: click in the view to pin."));
        m_pinned->setEnabled(m_picker->isActive());
        m_pinned->setChecked(m_picker->isPinned());
    };
    updateHint();
    connect(m_picker, &ValuePicker::activeChanged, this, updateHint);
    connect(m_picker, &ValuePicker::pinnedChanged, this, updateHint);
    connect(m_pinned, &QCheckBox::toggled, m_picker, &ValuePicker::setPinned);
    connect(m_picker, &ValuePicker::picked, this, &ValuesDock::showValue);
    connect(copy, &QPushButton::clicked, this, [this] { QApplication::clipboard()->setText(text()); });
}

void ValuesDock::showValue(const PickedValue& value)
{
    // Keep which sections the user folded.
    QSet<QString> collapsed;
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i)
        if (!m_tree->topLevelItem(i)->isExpanded())
            collapsed.insert(m_tree->topLevelItem(i)->text(0));
    m_tree->setUpdatesEnabled(false);
    m_tree->clear();
    QTreeWidgetItem* root = m_tree->invisibleRootItem();

    row(root, tr("Pixel"), QStringLiteral("%1, %2").arg(value.pixel.x()).arg(value.pixel.y()))
        ->setToolTip(1,
            tr("Device pixel from the top-left corner of the %1×%2 view")
                .arg(value.viewSize.width())
                .arg(value.viewSize.height()));
    if (value.radiance) {
        const glm::dvec3 rgb(*value.radiance);
        QTreeWidgetItem* radiance = row(root, tr("Shaded radiance"), components(rgb));
        radiance->setToolTip(0,
            tr("Linear, scene-referred RGB of the frame on screen, before exposure and tone "
               "mapping"));
        row(radiance, tr("Luminance"), number(luminance(rgb)));
        row(radiance, tr("Alpha"), number(value.radiance->a));
    } else {
        row(root, tr("Shaded radiance"), tr("not readable now (the next frame shows it)"));
    }
    if (value.display) {
        const glm::u8vec4 d = *value.display;
        QTreeWidgetItem* screen = row(root, tr("On screen (sRGB)"),
            QStringLiteral("%1  %2  %3 · #%4")
                .arg(d.r)
                .arg(d.g)
                .arg(d.b)
                .arg(QStringLiteral("%1%2%3")
                         .arg(d.r, 2, 16, QLatin1Char('0'))
                         .arg(d.g, 2, 16, QLatin1Char('0'))
                         .arg(d.b, 2, 16, QLatin1Char('0'))
                         .toUpper()));
        screen->setToolTip(0,
            tr("The 8-bit value the view shows: after exposure, tone mapping and the display "
               "encoding"));
        const glm::dvec3 decoded(tonemap::srgbToLinear(d.r / 255.0), tonemap::srgbToLinear(d.g / 255.0),
            tonemap::srgbToLinear(d.b / 255.0));
        row(screen, tr("Linear (sRGB decoded)"), components(decoded));
    }

    if (!value.surface) {
        row(root, tr("Surface"), tr("background"));
    } else {
        const PickedValue::Surface& surface = *value.surface;
        const SurfaceProbe& probe = surface.probe;
        QTreeWidgetItem* at = row(root, tr("Surface"), surface.partName);
        row(at, tr("Part"), QStringLiteral("%1 (%2)").arg(surface.partName).arg(surface.part + 1));
        row(at, tr("Material"), surface.materialName);
        row(at, tr("Position"), components(probe.position));
        row(at, tr("Normal"), components(probe.geometricNormal));
        row(at, tr("Shading normal"), components(probe.shadingNormal));
        row(at, tr("UV"), components(probe.uvs[0]));
        if (probe.uvs[1] != probe.uvs[0])
            row(at, tr("UV (set 1)"), components(probe.uvs[1]));
        if (probe.vertexColor != glm::dvec4(1.0))
            row(at, tr("Vertex colour"), components(probe.vertexColor));

        QTreeWidgetItem* maps = row(root, tr("Maps"));
        if (probe.maps.empty() && surface.mapsLoading.empty() && surface.mapProblems.empty())
            maps->setText(1, tr("none: factors only"));
        for (const MapProbe& read : probe.maps) {
            const int channels = isNormalSlot(read.slot) ? 3 : 4;
            QTreeWidgetItem* map = row(maps, MapSlotWidget::title(read.slot),
                tr("texel %1, %2 of %3×%4")
                    .arg(read.texel.x)
                    .arg(read.texel.y)
                    .arg(read.size.x)
                    .arg(read.size.y));
            row(map, tr("UV"), components(read.uv));
            row(map, tr("Texel"), QStringLiteral("%1, %2").arg(read.texel.x).arg(read.texel.y));
            row(map, tr("Stored"), storedSamples(read.stored, channels, read.sampleType));
            if (read.linear != read.stored)
                row(map, tr("Decoded (linear)"), components(glm::dvec4(read.linear)));
            row(map, tr("Filtered"), components(glm::dvec4(read.filtered)));
        }
        for (MapSlot slot : surface.mapsLoading)
            row(maps, MapSlotWidget::title(slot), tr("reading the file…"));
        for (const auto& [slot, problem] : surface.mapProblems)
            row(maps, MapSlotWidget::title(slot), problem);

        const MaterialInfo& inputs = probe.inputs;
        QTreeWidgetItem* material = row(root, tr("Material inputs"), surface.materialName);
        row(material, tr("Base colour (linear)"), components(inputs.baseColor));
        row(material, tr("Alpha"), number(inputs.alpha));
        row(material, tr("Metallic"), number(inputs.metallic));
        row(material, tr("Roughness"), number(inputs.perceptualRoughness));
        row(material, tr("Occlusion"), number(inputs.occlusion));
        if (inputs.emissive != glm::dvec3(0.0))
            row(material, tr("Emission"), components(inputs.emissive));
        if (inputs.clearcoat > 0.0) {
            row(material, tr("Clearcoat"), number(inputs.clearcoat));
            row(material, tr("Clearcoat roughness"), number(inputs.clearcoatRoughness));
            if (inputs.clearcoatNormal != glm::dvec3(0.0) && inputs.clearcoatNormal != probe.geometricNormal)
                row(material, tr("Clearcoat normal"), components(inputs.clearcoatNormal));
        }
        if (inputs.hasSheen()) {
            row(material, tr("Sheen colour (linear)"), components(inputs.sheenColor));
            row(material, tr("Sheen roughness"), number(inputs.sheenRoughness));
        }
        if (inputs.specular != 1.0 || inputs.specularColor != glm::dvec3(1.0)) {
            row(material, tr("Specular strength"), number(inputs.specular));
            row(material, tr("Specular colour (linear)"), components(inputs.specularColor));
        }
        if (inputs.anisotropy > 0.0) {
            row(material, tr("Anisotropy strength"), number(inputs.anisotropy));
            row(material, tr("Anisotropy direction (tangent plane)"), components(inputs.anisotropyTangentDirection));
            if (inputs.anisotropyDirection != glm::dvec3(0.0))
                row(material, tr("Anisotropy direction (world)"), components(inputs.anisotropyDirection));
        }
        if (inputs.iridescence > 0.0) {
            row(material, tr("Iridescence strength"), number(inputs.iridescence));
            row(material, tr("Iridescence film IOR"), number(inputs.iridescenceIor));
            row(material, tr("Iridescence thickness (nm)"), number(inputs.iridescenceThickness));
            // The film's reflectance seen head-on: what colours the highlight facing the viewer.
            const glm::dvec3 headOn = glm::mix(filmFresnel(inputs, dielectricReflectance(inputs).f0, 1.0),
                filmFresnel(inputs, inputs.baseColor, 1.0), inputs.metallic);
            row(material, tr("Iridescence Fresnel at normal incidence"), components(headOn));
        }
    }
    m_tree->expandAll();
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i)
        if (collapsed.contains(m_tree->topLevelItem(i)->text(0)))
            m_tree->topLevelItem(i)->setExpanded(false);
    m_tree->setUpdatesEnabled(true);
}

QString ValuesDock::text() const
{
    QStringList lines;
    const std::function<void(const QTreeWidgetItem*, int)> add = [&](const QTreeWidgetItem* item, int depth) {
        lines << QString(depth * 2, QLatin1Char(' ')) + item->text(0) + QLatin1Char('\t') + item->text(1);
        for (int i = 0; i < item->childCount(); ++i)
            add(item->child(i), depth + 1);
    };
    for (int i = 0; i < m_tree->topLevelItemCount(); ++i)
        add(m_tree->topLevelItem(i), 0);
    return lines.join(QLatin1Char('\n'));
}

QString ValuesDock::valueOf(const QString& path) const
{
    const QStringList names = path.split(QLatin1Char('/'));
    const QTreeWidgetItem* item = m_tree->invisibleRootItem();
    for (const QString& name : names) {
        const QTreeWidgetItem* next = nullptr;
        for (int i = 0; i < item->childCount() && !next; ++i)
            if (item->child(i)->text(0) == name)
                next = item->child(i);
        if (!next)
            return {};
        item = next;
    }
    return item->text(1);
}

} // namespace facet
