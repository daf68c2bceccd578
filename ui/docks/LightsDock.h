#pragma once
// The Lights dock: the punctual lights (KHR_lights_punctual) in a list whose check boxes enable
// them; Add (directional, point, spot), Remove, Duplicate, Solo (only the selected light on; again:
// all on). The selected light's editor: name, type, colour or temperature (Kelvin), intensity in
// lux (directional) or candela (point, spot), direction as azimuth / elevation of where the light
// comes from, position, range and the spot's cone angles. Every edit is an undo step; a slider
// drag is one.

#include "ui/document/DocumentChanges.h"

#include <QDockWidget>

#include <glm/vec3.hpp>

#include <functional>
#include <vector>

class QAction;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QToolButton;

namespace facet {

class ColorButton;
enum class LightType;
struct Light;
class Document;
class ValueSlider;

class LightsDock : public QDockWidget {
    Q_OBJECT
public:
    explicit LightsDock(Document* document, QWidget* parent = nullptr);
    ~LightsDock() override;

    QListWidget* list() const { return m_list; }
    ValueSlider* intensitySlider() const { return m_intensity; }
    QAction* addLightAction(LightType type) const { return m_addActions[std::size_t(type)]; }
    QPushButton* removeButton() const { return m_remove; }
    // The selected light's index, or -1.
    int currentLight() const;

    void addLight(LightType type);
    void removeCurrent();
    void duplicateCurrent();
    void soloCurrent();

    // Azimuth (degrees about +Y from +Z toward +X) and elevation (degrees above the horizon) of
    // where a light travelling along `direction` comes from, and back.
    static void anglesFromDirection(const glm::dvec3& direction, double* azimuth, double* elevation);
    static glm::dvec3 directionFromAngles(double azimuthDegrees, double elevationDegrees);

Q_SIGNALS:
    void message(const QString& text);

private:
    void onDocumentChanged(DocumentChanges changes);
    void refreshList();
    void refreshEditor();
    void editLight(const QString& undoText, int mergeId, const std::function<void(Light&)>& change);
    void setLights(const std::vector<Light>& lights, const QString& undoText, int select);

    Document* m_document;
    QListWidget* m_list;
    QToolButton* m_add;
    std::vector<QAction*> m_addActions;
    QPushButton* m_remove;
    QPushButton* m_duplicate;
    QPushButton* m_solo;
    QWidget* m_editor;
    QLineEdit* m_name;
    QComboBox* m_type;
    QCheckBox* m_useTemperature;
    ColorButton* m_color;
    ValueSlider* m_kelvin;
    ValueSlider* m_intensity;
    ValueSlider* m_azimuth;
    ValueSlider* m_elevation;
    QDoubleSpinBox* m_position[3];
    QDoubleSpinBox* m_range;
    ValueSlider* m_innerCone;
    ValueSlider* m_outerCone;
    QLabel* m_intensityLabel;
    int m_pendingSelection = -1;
};

} // namespace facet
