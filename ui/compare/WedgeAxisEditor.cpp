#include "ui/compare/WedgeAxisEditor.h"

#include "ui/widgets/WindowMessages.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QRadioButton>
#include <QSignalBlocker>
#include <QSpinBox>

#include <cmath>

namespace facet {

namespace {

constexpr int kNoneData = -1; // the combo's "none" entry
constexpr int kDecimals = 3;
constexpr double kExposureSpanEV = 2.0; // a new exposure range: -2 to +2 EV, not the whole [-20, 20]

} // namespace

WedgeAxisEditor::WedgeAxisEditor(bool optional, QWidget* parent)
    : QWidget(parent)
    , m_optional(optional)
    , m_parameter(new QComboBox(this))
    , m_listMode(new QRadioButton(tr("Values"), this))
    , m_rangeMode(new QRadioButton(tr("From"), this))
    , m_values(new QLineEdit(this))
    , m_from(new QDoubleSpinBox(this))
    , m_to(new QDoubleSpinBox(this))
    , m_steps(new QSpinBox(this))
    , m_message(new QLabel(this))
{
    m_parameter->setObjectName(QStringLiteral("wedgeParameterCombo"));
    m_listMode->setObjectName(QStringLiteral("wedgeListMode"));
    m_rangeMode->setObjectName(QStringLiteral("wedgeRangeMode"));
    m_values->setObjectName(QStringLiteral("wedgeValuesEdit"));
    m_from->setObjectName(QStringLiteral("wedgeFromSpin"));
    m_to->setObjectName(QStringLiteral("wedgeToSpin"));
    m_steps->setObjectName(QStringLiteral("wedgeStepsSpin"));
    m_message->setObjectName(QStringLiteral("wedgeAxisMessage"));

    if (optional)
        m_parameter->addItem(tr("none"), kNoneData);
    for (const WedgeParameterInfo& info : wedgeParameters())
        m_parameter->addItem(QString::fromLatin1(info.name), int(info.parameter));
    m_values->setPlaceholderText(tr("e.g. 0, 0.25, 0.5, 0.75, 1"));
    m_values->setToolTip(tr("The values, separated by commas (at most %1); env takes environment names, "
                            "files or library references, or uniform:V")
                             .arg(WedgeAxis::kMaxValues));
    for (QDoubleSpinBox* spin : {m_from, m_to}) {
        spin->setDecimals(kDecimals);
        spin->setSingleStep(0.05);
        spin->setKeyboardTracking(false);
    }
    m_steps->setRange(1, WedgeAxis::kMaxValues);
    m_steps->setValue(5);
    m_steps->setSuffix(tr(" steps"));
    m_steps->setKeyboardTracking(false);
    m_message->setWordWrap(true);
    // Room for two lines, so that a message wraps instead of being cut and the dialog does not jump.
    m_message->setMinimumHeight(2 * m_message->fontMetrics().lineSpacing());
    m_message->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* modes = new QButtonGroup(this);
    modes->addButton(m_listMode);
    modes->addButton(m_rangeMode);
    m_listMode->setChecked(true);

    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->addWidget(new QLabel(tr("Parameter"), this), 0, 0);
    grid->addWidget(m_parameter, 0, 1);
    grid->addWidget(m_listMode, 1, 0);
    grid->addWidget(m_values, 1, 1);
    grid->addWidget(m_message, 2, 1);
    auto* range = new QHBoxLayout;
    range->addWidget(m_from);
    range->addWidget(new QLabel(tr("to"), this));
    range->addWidget(m_to);
    range->addWidget(new QLabel(tr("in"), this));
    range->addWidget(m_steps);
    grid->addWidget(m_rangeMode, 3, 0);
    grid->addLayout(range, 3, 1);
    grid->setColumnStretch(1, 1);

    connect(m_parameter, &QComboBox::currentIndexChanged, this, [this] {
        // Another parameter: the range starts over its whole span (exposure: a few stops).
        if (const std::optional<WedgeParameter> chosen = parameter();
            chosen && *chosen != WedgeParameter::Environment) {
            const WedgeParameterInfo& info = infoOf(*chosen);
            const bool exposure = *chosen == WedgeParameter::Exposure;
            const QSignalBlocker fromBlocker(m_from);
            const QSignalBlocker toBlocker(m_to);
            m_from->setRange(info.minimum, info.maximum);
            m_to->setRange(info.minimum, info.maximum);
            m_from->setValue(exposure ? -kExposureSpanEV : info.minimum);
            m_to->setValue(exposure ? kExposureSpanEV : info.maximum);
        }
        onParameterChanged();
    });
    connect(m_values, &QLineEdit::textChanged, this, &WedgeAxisEditor::validate);
    connect(m_rangeMode, &QRadioButton::toggled, this, [this](bool rangeChosen) {
        if (rangeChosen)
            fillFromRange();
        onParameterChanged(); // which fields are editable
    });
    for (QDoubleSpinBox* spin : {m_from, m_to})
        connect(spin, &QDoubleSpinBox::valueChanged, this, &WedgeAxisEditor::fillFromRange);
    connect(m_steps, &QSpinBox::valueChanged, this, &WedgeAxisEditor::fillFromRange);
    setAxis(optional ? std::nullopt : std::optional<WedgeAxis>(WedgeAxis::defaultRows()));
}

std::optional<WedgeParameter> WedgeAxisEditor::parameter() const
{
    const int chosen = m_parameter->currentData().toInt();
    if (chosen == kNoneData)
        return std::nullopt;
    return WedgeParameter(chosen);
}

void WedgeAxisEditor::setAxis(const std::optional<WedgeAxis>& axis)
{
    Q_ASSERT(axis || m_optional);
    {
        const QSignalBlocker blocker(m_parameter);
        m_parameter->setCurrentIndex(m_parameter->findData(axis ? int(axis->parameter) : kNoneData));
    }
    m_listMode->setChecked(true);
    onParameterChanged();
    QString list;
    if (axis) {
        // toString() is "name=v1,v2,...": the list is what follows the '='.
        const QString text = QString::fromStdString(axis->toString());
        list = text.mid(text.indexOf(QLatin1Char('=')) + 1).replace(QLatin1Char(','), QStringLiteral(", "));
    }
    m_values->setText(list);
    if (axis && !axis->isEnvironment() && !axis->values.empty()) {
        // The range starts from the axis' ends, so switching to it keeps them.
        const QSignalBlocker fromBlocker(m_from);
        const QSignalBlocker toBlocker(m_to);
        const QSignalBlocker stepsBlocker(m_steps);
        m_from->setValue(axis->values.front());
        m_to->setValue(axis->values.back());
        m_steps->setValue(int(axis->values.size()));
    }
    validate();
}

void WedgeAxisEditor::onParameterChanged()
{
    const std::optional<WedgeParameter> chosen = parameter();
    const bool numeric = chosen && *chosen != WedgeParameter::Environment;
    if (numeric) {
        // The spin boxes keep to the range the axis accepts (the validators' constants).
        const WedgeParameterInfo& info = infoOf(*chosen);
        const QSignalBlocker fromBlocker(m_from);
        const QSignalBlocker toBlocker(m_to);
        m_from->setRange(info.minimum, info.maximum);
        m_to->setRange(info.minimum, info.maximum);
    } else if (m_rangeMode->isChecked()) {
        const QSignalBlocker blocker(m_listMode);
        m_listMode->setChecked(true); // env has no numeric range; "none" has nothing
    }
    const bool range = m_rangeMode->isChecked();
    m_listMode->setEnabled(chosen.has_value());
    m_rangeMode->setEnabled(numeric);
    m_values->setEnabled(chosen.has_value());
    m_values->setReadOnly(range);
    for (QWidget* field :
        {static_cast<QWidget*>(m_from), static_cast<QWidget*>(m_to), static_cast<QWidget*>(m_steps)})
        field->setEnabled(numeric && range);
    if (range)
        fillFromRange(); // the new parameter's range may have clamped the ends
    validate();
}

QString WedgeAxisEditor::rangeList(double from, double to, int steps)
{
    QStringList values;
    for (int i = 0; i < steps; ++i) {
        const double t = steps > 1 ? double(i) / (steps - 1) : 0.0;
        double value = i == steps - 1 && steps > 1 ? to : from + (to - from) * t;
        // The spin boxes' precision: no 0.30000000000000004 in the list.
        value = std::round(value * 1e6) / 1e6;
        values.append(QString::number(value, 'g', 10));
    }
    return values.join(QStringLiteral(", "));
}

void WedgeAxisEditor::fillFromRange()
{
    if (!m_rangeMode->isChecked())
        return;
    m_values->setText(rangeList(m_from->value(), m_to->value(), m_steps->value()));
}

std::string WedgeAxisEditor::text() const
{
    const std::optional<WedgeParameter> chosen = parameter();
    if (!chosen)
        return {};
    return std::string(toString(*chosen)) + '=' + m_values->text().trimmed().toStdString();
}

void WedgeAxisEditor::validate()
{
    m_problem.clear();
    m_axis.reset();
    QString message;
    if (parameter()) {
        const std::string axisText = text();
        std::string error;
        m_axis = WedgeAxis::parse(axisText, &error);
        if (m_axis) {
            message = m_axis->size() == 1 ? tr("1 value") : tr("%1 values").arg(m_axis->size());
        } else {
            // parse()'s message names the function and repeats the text typed: the field shows
            // the text, the message says what is wrong with it.
            // So does the parameter's name (it is in the combo above): "value 2: roughness.factor:
            // 1.5 is outside [0, 1]".
            const std::string parameterName = toString(*parameter());
            std::string prefix = "WedgeAxis::parse: \"" + axisText + "\": ";
            if (error.rfind(prefix + parameterName + ": ", 0) == 0)
                prefix += parameterName + ": ";
            const QString problem = error.rfind(prefix, 0) == 0
                ? QString::fromStdString(error.substr(prefix.size()))
                : WindowMessages::fromCore(error);
            m_problem = problem.isEmpty() ? tr("not an axis") : problem;
            message = m_problem;
        }
    }
    m_message->setText(message);
    m_message->setStyleSheet(m_problem.isEmpty() ? QString() : QStringLiteral("color: #d04040;"));
    Q_EMIT edited();
}

} // namespace facet
