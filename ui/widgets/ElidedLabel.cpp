#include "ui/widgets/ElidedLabel.h"

#include <QPainter>
#include <QStyle>

#include <algorithm>

namespace facet {

namespace {

// Enough for "ab…yz": what the label asks for at the least.
constexpr int kMinimumCharacters = 6;

} // namespace

ElidedLabel::ElidedLabel(QWidget* parent, Qt::TextElideMode mode)
    : QLabel(parent)
    , m_mode(mode)
{
    setTextFormat(Qt::PlainText);
    setWordWrap(false);
    // Preferred: grows to the whole text when there is room, shrinks to the minimum when not.
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Preferred);
}

QStringList ElidedLabel::displayedLines() const
{
    const int width = contentsRect().width() - 2 * std::max(margin(), 0);
    QStringList lines = text().split(QLatin1Char('\n'));
    for (QString& line : lines)
        line = fontMetrics().elidedText(line, m_mode, width);
    return lines;
}

QSize ElidedLabel::textBlockSize(int width) const
{
    const QFontMetrics metrics = fontMetrics();
    const QStringList lines = text().split(QLatin1Char('\n'));
    const int height = metrics.height() + int(lines.size() - 1) * metrics.lineSpacing();
    const int extra = 2 * (std::max(margin(), 0) + frameWidth());
    return QSize(width + extra, height + extra);
}

QSize ElidedLabel::sizeHint() const
{
    const QFontMetrics metrics = fontMetrics();
    int width = 0;
    for (const QString& line : text().split(QLatin1Char('\n')))
        width = std::max(width, metrics.horizontalAdvance(line));
    return textBlockSize(width);
}

QSize ElidedLabel::minimumSizeHint() const
{
    return textBlockSize(fontMetrics().averageCharWidth() * kMinimumCharacters);
}

void ElidedLabel::paintEvent(QPaintEvent* event)
{
    QFrame::paintEvent(event); // the frame, if any
    QPainter painter(this);
    const QFontMetrics metrics = fontMetrics();
    const int inset = std::max(margin(), 0);
    const QRect area = contentsRect().adjusted(inset, inset, -inset, -inset);
    const QStringList lines = displayedLines();
    const int blockHeight = metrics.height() + int(lines.size() - 1) * metrics.lineSpacing();
    int y = area.top();
    if (alignment() & Qt::AlignVCenter)
        y += (area.height() - blockHeight) / 2;
    else if (alignment() & Qt::AlignBottom)
        y += area.height() - blockHeight;
    const int horizontal = int(alignment() & Qt::AlignHorizontal_Mask);
    for (const QString& line : lines) {
        const QRect lineRect(area.left(), y, area.width(), metrics.height());
        style()->drawItemText(&painter, lineRect, horizontal | Qt::AlignVCenter, palette(), isEnabled(), line,
            foregroundRole());
        y += metrics.lineSpacing();
    }
}

} // namespace facet
