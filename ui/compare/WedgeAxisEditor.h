#pragma once
// One axis of the wedge (core/project/WedgeAxis.h) in the Wedge Axes dialog (ui/compare/WedgeAxesDialog.h):
// the parameter in a combo (every one WedgeAxis accepts; "none" first for an optional axis) and its values
// either as a list ("0, 0.25, 0.5") or as "from / to / steps" spin boxes that fill the list (evenly spaced,
// both ends included; not for env, whose values are environment specs). The list is checked while it is typed
// with WedgeAxis::parse, the axis' own rule, and the problem shown under the field; isValid() says whether
// the dialog may accept it.

#include "core/project/WedgeAxis.h"

#include <QWidget>

#include <optional>
#include <string>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QRadioButton;
class QSpinBox;

namespace facet {

class WedgeAxisEditor : public QWidget {
    Q_OBJECT
public:
    // `optional`: the combo offers "none" (no second axis) first.
    explicit WedgeAxisEditor(bool optional, QWidget* parent = nullptr);

    // Shows `axis` (nullopt: "none"; only for an optional editor) as a list of its values.
    void setAxis(const std::optional<WedgeAxis>& axis);

    // "PARAMETER=V1,V2,..." as WedgeAxis::parse reads it; empty for "none".
    std::string text() const;
    // Whether text() is an axis (or "none"); problem(): why not, in the window's wording.
    bool isValid() const { return m_problem.isEmpty(); }
    const QString& problem() const { return m_problem; }
    // The axis text() parses to, as validated; nullopt for "none" or while not valid.
    const std::optional<WedgeAxis>& axis() const { return m_axis; }

    // The widgets, for tests: objectNames wedgeParameterCombo, wedgeValuesEdit, wedgeListMode,
    // wedgeRangeMode, wedgeFromSpin, wedgeToSpin, wedgeStepsSpin, wedgeAxisMessage.
    QComboBox* parameterCombo() const { return m_parameter; }
    QLineEdit* valuesEdit() const { return m_values; }
    QRadioButton* rangeMode() const { return m_rangeMode; }
    QDoubleSpinBox* fromSpin() const { return m_from; }
    QDoubleSpinBox* toSpin() const { return m_to; }
    QSpinBox* stepsSpin() const { return m_steps; }
    QLabel* messageLabel() const { return m_message; }

    // The list a range fills: `steps` values from `from` to `to`, both included, evenly spaced
    // ("0, 0.25, 0.5, 0.75, 1"); one step gives `from`.
    static QString rangeList(double from, double to, int steps);

Q_SIGNALS:
    // The axis' text or validity changed.
    void edited();

private:
    std::optional<WedgeParameter> parameter() const;
    void onParameterChanged();
    void fillFromRange();
    void validate();

    bool m_optional;
    QComboBox* m_parameter;
    QRadioButton* m_listMode;
    QRadioButton* m_rangeMode;
    QLineEdit* m_values;
    QDoubleSpinBox* m_from;
    QDoubleSpinBox* m_to;
    QSpinBox* m_steps;
    QLabel* m_message;
    QString m_problem;
    std::optional<WedgeAxis> m_axis;
};

} // namespace facet
