#include "ui/widgets/ColorButton.h"

#include "core/image/ToneMap.h"

#include <QColorDialog>
#include <QPainter>
#include <QPixmap>

#include <algorithm>

namespace facet {

ColorButton::ColorButton(QWidget* parent)
    : QToolButton(parent)
{
    setIconSize(QSize(40, 16));
    setToolTip(tr("Choose a colour"));
    connect(this, &QToolButton::clicked, this, &ColorButton::pick);
    setLinearColor(m_linear);
}

void ColorButton::setLinearColor(const glm::dvec3& linear)
{
    m_linear = linear;
    QPixmap swatch(iconSize());
    swatch.fill(toDisplayColor(linear));
    QPainter painter(&swatch);
    painter.setPen(palette().color(QPalette::Mid));
    painter.drawRect(swatch.rect().adjusted(0, 0, -1, -1));
    painter.end();
    setIcon(QIcon(swatch));
}

QColor ColorButton::toDisplayColor(const glm::dvec3& linear)
{
    const auto encode
        = [](double v) { return std::clamp(tonemap::linearToSrgb(std::clamp(v, 0.0, 1.0)), 0.0, 1.0); };
    return QColor::fromRgbF(float(encode(linear.x)), float(encode(linear.y)), float(encode(linear.z)));
}

glm::dvec3 ColorButton::fromDisplayColor(const QColor& color)
{
    return {tonemap::srgbToLinear(color.redF()), tonemap::srgbToLinear(color.greenF()),
        tonemap::srgbToLinear(color.blueF())};
}

void ColorButton::pick()
{
    const QColor chosen = QColorDialog::getColor(toDisplayColor(m_linear), this, tr("Choose a Colour"));
    if (!chosen.isValid())
        return;
    const glm::dvec3 linear = fromDisplayColor(chosen);
    setLinearColor(linear);
    Q_EMIT colorEdited(linear);
}

} // namespace facet
