#include "ui/widgets/ValueSlider.h"

#include "core/material/MaterialProperties.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QSlider>

#include <algorithm>
#include <cmath>

namespace facet {

ValueSlider* ValueSlider::forProperty(const MaterialPropertyInfo& info, QWidget* parent)
{
    const double sliderMaximum = info.sliderMaximum > 0.0 ? info.sliderMaximum : info.maximum;
    // Three decimals for the fractions, one for the large ranges: the spin box's width follows its
    // longest text, and a wide one squeezes the slider in a narrow dock.
    auto* slider = new ValueSlider(info.minimum, sliderMaximum, info.maximum > 1000.0 ? 1 : 3, parent);
    if (sliderMaximum < info.maximum)
        slider->setSpinRange(info.minimum, info.maximum);
    slider->setToolTip(QString::fromUtf8(info.label));
    return slider;
}

ValueSlider::ValueSlider(double minimum, double maximum, int decimals, QWidget* parent)
    : QWidget(parent)
    , m_slider(new QSlider(Qt::Horizontal, this))
    , m_spin(new QDoubleSpinBox(this))
    , m_minimum(minimum)
    , m_maximum(maximum)
    , m_value(minimum)
{
    Q_ASSERT(maximum > minimum);
    m_slider->setRange(0, kSteps);
    m_slider->setTracking(true);
    m_spin->setRange(minimum, maximum);
    m_spin->setDecimals(decimals);
    m_spin->setSingleStep((maximum - minimum) / 100.0);
    m_spin->setKeyboardTracking(false); // typing "0.75" is one edit, not three
    m_spin->setAccelerated(true);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_slider, 1);
    layout->addWidget(m_spin);

    connect(m_slider, &QSlider::sliderPressed, this, &ValueSlider::editStarted);
    connect(m_slider, &QSlider::sliderReleased, this, &ValueSlider::editFinished);
    connect(m_slider, &QSlider::valueChanged, this, [this](int position) {
        // Clicks on the groove and keys move the slider too: each is one edit of its own.
        const double value = valueAt(position);
        m_value = value;
        const QSignalBlocker blocker(m_spin);
        m_spin->setValue(value);
        Q_EMIT valueEdited(value);
    });
    connect(m_spin, &QDoubleSpinBox::valueChanged, this, [this](double value) {
        m_value = value;
        const QSignalBlocker blocker(m_slider);
        m_slider->setValue(sliderPosition(value));
        Q_EMIT valueEdited(value);
    });
}

void ValueSlider::setValue(double value)
{
    if (m_slider->isSliderDown() && value == m_value)
        return;
    showValue(value);
}

void ValueSlider::showValue(double value)
{
    m_value = value;
    const QSignalBlocker sliderBlocker(m_slider);
    const QSignalBlocker spinBlocker(m_spin);
    m_slider->setValue(sliderPosition(value));
    m_spin->setValue(value);
}

void ValueSlider::setSuffix(const QString& suffix)
{
    m_spin->setSuffix(suffix);
}

void ValueSlider::setSpinRange(double minimum, double maximum)
{
    const QSignalBlocker blocker(m_spin);
    m_spin->setRange(minimum, maximum);
    m_spin->setValue(m_value);
}

void ValueSlider::setSingleStep(double step)
{
    m_spin->setSingleStep(step);
}

void ValueSlider::setLogarithmic(double smallestPositive)
{
    Q_ASSERT(smallestPositive > 0.0 && smallestPositive < m_maximum);
    m_logLowest = smallestPositive;
    m_spin->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
    showValue(m_value);
}

int ValueSlider::sliderPosition(double value) const
{
    if (m_logLowest > 0.0) {
        // Position 0 holds everything below the first logarithmic step (0 included).
        if (!(value > m_minimum) || value < m_logLowest * 0.999)
            return 0;
        const double t
            = std::clamp(std::log(value / m_logLowest) / std::log(m_maximum / m_logLowest), 0.0, 1.0);
        return 1 + int(std::lround(t * (kSteps - 1)));
    }
    const double t = std::clamp((value - m_minimum) / (m_maximum - m_minimum), 0.0, 1.0);
    return int(std::lround(t * kSteps));
}

double ValueSlider::valueAt(int position) const
{
    // Round to the spin box's precision so the document holds what the control shows.
    double value = m_minimum + (m_maximum - m_minimum) * double(position) / kSteps;
    if (m_logLowest > 0.0)
        value = position <= 0
            ? m_minimum
            : m_logLowest * std::pow(m_maximum / m_logLowest, double(position - 1) / (kSteps - 1));
    const double scale = std::pow(10.0, m_spin->decimals());
    return std::round(value * scale) / scale;
}

} // namespace facet
