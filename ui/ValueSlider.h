#pragma once
// A labelled number control for the docks: a slider for dragging and a spin box for typing, over
// the same value in [minimum, maximum]. A slider drag is bracketed by editStarted() and
// editFinished() with valueEdited() in between, so a dock turns it into one undo step
// (Document::beginInteractiveEdit / endInteractiveEdit with a merge id); a typed value or a
// wheel step is a valueEdited() on its own. setValue() shows a value without emitting anything
// (docks call it when the document changed).

#include <QWidget>

class QDoubleSpinBox;
class QSlider;

namespace facet {

class ValueSlider : public QWidget {
    Q_OBJECT
public:
    // `decimals` for the spin box; the slider has kSteps steps over the range.
    ValueSlider(double minimum, double maximum, int decimals, QWidget* parent = nullptr);

    static constexpr int kSteps = 1000;

    double value() const { return m_value; }
    void setValue(double value);
    void setSuffix(const QString& suffix);
    // The spin box may go beyond the slider's range up to these (e.g. intensities).
    void setSpinRange(double minimum, double maximum);
    void setSingleStep(double step);

    QSlider* slider() const { return m_slider; }
    QDoubleSpinBox* spinBox() const { return m_spin; }

Q_SIGNALS:
    void editStarted();
    void valueEdited(double value);
    void editFinished();

private:
    int sliderPosition(double value) const;
    double valueAt(int position) const;
    void showValue(double value);

    QSlider* m_slider;
    QDoubleSpinBox* m_spin;
    double m_minimum;
    double m_maximum;
    double m_value;
};

} // namespace facet
