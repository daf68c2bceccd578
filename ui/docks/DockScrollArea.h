#pragma once
// A dock's content in a scroll area (MainWindow::addDock puts every dock's content in one), so
// that what a dock holds never sets its width: a scroll area's minimum size does not depend on its
// content, and the dock column keeps the width the layout or the user gave it however many lights
// or however long a name it shows.
//
// It sizes the content itself rather than with QScrollArea::setWidgetResizable(true): that one
// gives content whose layout has a height-for-width (any word-wrapped label) its *preferred*
// height for the width, so a dock with a list and a wrapped note scrolls as a whole long before
// its list has shrunk. Here the content gets the viewport's width and height, or its minimum
// height for that width when that is more (then it scrolls), and its minimum width when the dock
// is narrower than that (then it scrolls sideways).

#include <QScrollArea>

namespace facet {

class DockScrollArea : public QScrollArea {
    Q_OBJECT
public:
    // Takes `content` (fitToColumn first).
    explicit DockScrollArea(QWidget* content, QWidget* parent = nullptr);

    // Lets the widgets in `content` share a narrow column (a quarter of the window) instead of
    // each asking for its longest text: a combo box asks for ten characters and shows its item
    // elided (its list shows every item whole), a form row whose label and field do not fit side
    // by side puts the field under its label, a push button may shrink to its text. Widgets made
    // later (rows of a list) are not touched.
    static void fitToColumn(QWidget* content);

    // The content's size for a viewport of `area` (without scroll bars), and whether it then
    // needs the vertical scroll bar.
    QSize contentSizeFor(QSize area, bool* needsVerticalBar = nullptr) const;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    void fitContent();
    int minimumHeightFor(int width) const;
};

} // namespace facet
