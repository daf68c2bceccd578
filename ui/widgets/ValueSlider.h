#pragma once
// A labelled number control for the docks: a slider for dragging and a spin box for typing, over
// the same value in [minimum, maximum]. A slider drag is bracketed by editStarted() and
// editFinished() with valueEdited() in between, so a dock turns it into one undo step
// (Document::beginInteractiveEdit / endInteractiveEdit with a merge id); a typed value or a
// wheel step is a valueEdited() on its own. setValue() shows a value without emitting anything
// (docks call it when the document changed).
//
// setLogarithmic() spaces the slider's steps evenly in log(value) instead, for ranges over several
// decades (an emissive strength from 0.01 to 10000): the spin box still shows and takes the value
// itself, and the slider's first step is the minimum (0).

#include <QWidget>

class QDoubleSpinBox;
class QSlider;

namespace facet {

struct MaterialPropertyInfo;

class ValueSlider : public QWidget {
    Q_OBJECT
public:
    // `decimals` for the spin box; the slider has kSteps steps over the range.
    ValueSlider(double minimum, double maximum, int decimals, QWidget* parent = nullptr);

    // A material property's slider from its registry row (core/material/MaterialProperties.h): its
    // range, where the slider ends (sliderMaximum; the spin box goes on to the maximum), three
    // decimals (one for a range past 1000: a film's nanometres) and the row's label as tooltip.
    static ValueSlider* forProperty(const MaterialPropertyInfo& info, QWidget* parent = nullptr);

    static constexpr int kSteps = 1000;

    double value() const { return m_value; }
    void setValue(double value);
    void setSuffix(const QString& suffix);
    // The spin box may go beyond the slider's range up to these (e.g. intensities).
    void setSpinRange(double minimum, double maximum);
    void setSingleStep(double step);
    // Logarithmic slider: position 0 is `minimum`, positions 1..kSteps run geometrically from
    // `smallestPositive` to `maximum` (0 < smallestPositive < maximum). The spin box steps by about
    // a tenth of the value's decade (QAbstractSpinBox::AdaptiveDecimalStepType).
    void setLogarithmic(double smallestPositive);
    bool isLogarithmic() const { return m_logLowest > 0.0; }

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
    double m_logLowest = 0.0; // > 0: logarithmic slider (setLogarithmic)
};

} // namespace facet
