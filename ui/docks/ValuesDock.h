#pragma once
// The Values dock: what the value picker (ui/viewport/ValuePicker.h) read, as a tree of rows an artist can
// copy: the pixel, the shaded radiance (linear, before exposure) and the value on screen (8-bit
// and hex, and what it decodes to as sRGB); the surface (part, material, position, normals, UVs,
// vertex colour); each map's texel (file, UV after its transform, texel of the map's size, stored,
// decoded and filtered values); and the material's inputs there (base colour, metallic,
// roughness, occlusion, emission, alpha). Hidden until the picker is first turned on.

#include "ui/viewport/ValuePicker.h"

#include <QDockWidget>

class QCheckBox;
class QLabel;
class QTreeWidget;
class QTreeWidgetItem;

namespace facet {

class ValuesDock : public QDockWidget {
    Q_OBJECT
public:
    explicit ValuesDock(ValuePicker* picker, QWidget* parent = nullptr);

    QTreeWidget* tree() const { return m_tree; }
    // The tree as text, one "name<TAB>value" line a row, sections indented (the Copy button).
    QString text() const;
    // The value of the row `path` names ("Shaded radiance", "Maps/Roughness/Texel"), empty when
    // there is none (tests read rows by name).
    QString valueOf(const QString& path) const;

    // The rows for `value` (what picked() carries).
    void showValue(const PickedValue& value);

private:
    ValuePicker* m_picker;
    QLabel* m_hint;
    QCheckBox* m_pinned;
    QTreeWidget* m_tree;
};

} // namespace facet
