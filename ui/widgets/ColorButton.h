#pragma once
// A swatch button for a linear Rec.709 colour (base colour, light colour, background). It shows
// the colour sRGB-encoded and opens a QColorDialog on click; colorEdited() carries the new
// linear colour (one edit: the dialog is modal).

#include <QToolButton>

#include <glm/vec3.hpp>

namespace facet {

class ColorButton : public QToolButton {
    Q_OBJECT
public:
    explicit ColorButton(QWidget* parent = nullptr);

    glm::dvec3 linearColor() const { return m_linear; }
    void setLinearColor(const glm::dvec3& linear);

    // sRGB-encoded QColor <-> linear Rec.709 (IEC 61966-2-1 curve), components clamped to [0, 1].
    static QColor toDisplayColor(const glm::dvec3& linear);
    static glm::dvec3 fromDisplayColor(const QColor& color);

Q_SIGNALS:
    void colorEdited(const glm::dvec3& linear);

private:
    void pick();

    glm::dvec3 m_linear {0.0};
};

} // namespace facet
