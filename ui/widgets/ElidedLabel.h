#pragma once
// A label for text that may be longer than its dock is wide (a file name, a material's name): each
// line is drawn elided ("rock_wall_…_basecolor.png" in the middle by default, so that the ending
// that names the map stays), and the label asks for a few characters of width, not the whole
// text, so a long name never widens its dock. text() stays the whole text; callers put it (or
// the full path) in the tooltip. Plain text only, not selectable.

#include <QLabel>

namespace facet {

class ElidedLabel : public QLabel {
    Q_OBJECT
public:
    explicit ElidedLabel(QWidget* parent = nullptr, Qt::TextElideMode mode = Qt::ElideMiddle);

    Qt::TextElideMode elideMode() const { return m_mode; }
    // The lines as drawn at the label's present width.
    QStringList displayedLines() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    QSize textBlockSize(int width) const;

    Qt::TextElideMode m_mode;
};

} // namespace facet
