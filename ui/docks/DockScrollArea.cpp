#include "ui/docks/DockScrollArea.h"

#include <QComboBox>
#include <QEvent>
#include <QFormLayout>
#include <QLayout>
#include <QPushButton>
#include <QScrollBar>
#include <QStyle>

#include <algorithm>

namespace facet {

DockScrollArea::DockScrollArea(QWidget* content, QWidget* parent)
    : QScrollArea(parent)
{
    setFrameShape(QFrame::NoFrame);
    setWidgetResizable(false); // fitContent() sizes it
    setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    setVerticalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    fitToColumn(content);
    setWidget(content); // installs this as the content's event filter
    fitContent();
}

void DockScrollArea::fitToColumn(QWidget* content)
{
    constexpr int kComboCharacters = 10;
    for (QComboBox* combo : content->findChildren<QComboBox*>()) {
        combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        combo->setMinimumContentsLength(kComboCharacters);
        // The policy resets the size hint but not the minimum one, already worked out from the
        // longest item when the dock laid itself out: the new hint is the minimum.
        combo->setMinimumWidth(combo->sizeHint().width());
    }
    for (QFormLayout* form : content->findChildren<QFormLayout*>())
        form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    // A push button asks for at least 80 pixels (QCommonStyle), three in a row more than a quarter
    // of a 1200-pixel window: it may shrink to its text.
    for (QPushButton* button : content->findChildren<QPushButton*>()) {
        if (button->text().isEmpty())
            continue;
        const int margins = 2
            * (button->style()->pixelMetric(QStyle::PM_ButtonMargin, nullptr, button)
                + button->style()->pixelMetric(QStyle::PM_DefaultFrameWidth, nullptr, button));
        button->setMinimumWidth(
            button->fontMetrics().horizontalAdvance(QString(button->text()).remove(QLatin1Char('&')))
            + margins);
    }
}

int DockScrollArea::minimumHeightFor(int width) const
{
    const QWidget* content = widget();
    const int minimum = std::max(content->minimumSizeHint().height(), content->minimumHeight());
    const QLayout* layout = content->layout();
    if (!layout || !layout->hasHeightForWidth())
        return minimum;
    return std::max(minimum, layout->totalMinimumHeightForWidth(width));
}

QSize DockScrollArea::contentSizeFor(QSize area, bool* needsVerticalBar) const
{
    const QWidget* content = widget();
    const int minimumWidth = std::max(content->minimumSizeHint().width(), content->minimumWidth());
    int width = std::max(area.width(), minimumWidth);
    int height = minimumHeightFor(width);
    const bool scrolls = height > area.height();
    if (scrolls) {
        // The vertical bar takes its width from the viewport.
        width = std::max(area.width() - verticalScrollBar()->sizeHint().width(), minimumWidth);
        height = minimumHeightFor(width);
    }
    if (needsVerticalBar)
        *needsVerticalBar = scrolls;
    return {width, std::max(height, area.height())};
}

void DockScrollArea::fitContent()
{
    if (!widget())
        return;
    const QSize size = contentSizeFor(maximumViewportSize());
    if (widget()->size() != size)
        widget()->resize(size);
}

bool DockScrollArea::eventFilter(QObject* watched, QEvent* event)
{
    // The content's layout changed (a light's editor shown, a row added): size it again.
    const bool result = QScrollArea::eventFilter(watched, event);
    if (watched == widget() && event->type() == QEvent::LayoutRequest)
        fitContent();
    return result;
}

void DockScrollArea::resizeEvent(QResizeEvent* event)
{
    QScrollArea::resizeEvent(event);
    fitContent();
}

} // namespace facet
