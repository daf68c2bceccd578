#include "ui/docks/LightsDock.h"

#include "render/ShaderVariant.h"
#include "ui/document/Document.h"
#include "ui/document/DocumentCommands.h"
#include "ui/widgets/ColorButton.h"
#include "ui/widgets/ValueSlider.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QPushButton>
#include <QSignalBlocker>
#include <QToolButton>
#include <QVBoxLayout>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace facet {

namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;

QString typeName(LightType type)
{
    switch (type) {
    case LightType::Directional:
        return QObject::tr("Directional");
    case LightType::Point:
        return QObject::tr("Point");
    case LightType::Spot:
        return QObject::tr("Spot");
    }
    return {};
}

} // namespace

void LightsDock::anglesFromDirection(const glm::dvec3& direction, double* azimuth, double* elevation)
{
    const glm::dvec3 toLight = -glm::normalize(direction);
    *elevation = std::asin(std::clamp(toLight.y, -1.0, 1.0)) * kDegrees;
    *azimuth = (std::abs(toLight.x) + std::abs(toLight.z) > 1e-9)
        ? std::atan2(toLight.x, toLight.z) * kDegrees
        : 0.0;
}

glm::dvec3 LightsDock::directionFromAngles(double azimuthDegrees, double elevationDegrees)
{
    const double azimuth = azimuthDegrees / kDegrees;
    const double elevation = elevationDegrees / kDegrees;
    const glm::dvec3 toLight(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
        std::cos(elevation) * std::cos(azimuth));
    return -toLight;
}

LightsDock::LightsDock(Document* document, QWidget* parent)
    : QDockWidget(tr("Lights"), parent)
    , m_document(document)
    , m_list(new QListWidget(this))
    , m_add(new QToolButton(this))
    , m_remove(new QPushButton(tr("Remove"), this))
    , m_duplicate(new QPushButton(tr("Duplicate"), this))
    , m_solo(new QPushButton(tr("Solo"), this))
    , m_editor(new QWidget(this))
    , m_name(new QLineEdit(m_editor))
    , m_type(new QComboBox(m_editor))
    , m_useTemperature(new QCheckBox(tr("Colour temperature"), m_editor))
    , m_color(new ColorButton(m_editor))
    , m_kelvin(new ValueSlider(kMinKelvin, 12000.0, 0, m_editor))
    , m_intensity(new ValueSlider(0.0, 20.0, 2, m_editor))
    , m_azimuth(new ValueSlider(-180.0, 180.0, 1, m_editor))
    , m_elevation(new ValueSlider(-90.0, 90.0, 1, m_editor))
    , m_range(new QDoubleSpinBox(m_editor))
    , m_innerCone(new ValueSlider(0.0, 90.0, 1, m_editor))
    , m_outerCone(new ValueSlider(0.0, 90.0, 1, m_editor))
    , m_intensityLabel(new QLabel(tr("Intensity"), m_editor))
{
    setObjectName(QStringLiteral("lightsDock"));
    m_list->setObjectName(QStringLiteral("lightList"));
    m_add->setObjectName(QStringLiteral("addLightButton"));
    m_add->setText(tr("Add"));
    m_add->setPopupMode(QToolButton::InstantPopup);
    auto* addMenu = new QMenu(m_add);
    for (LightType type : {LightType::Directional, LightType::Point, LightType::Spot}) {
        QAction* action = addMenu->addAction(typeName(type));
        action->setObjectName(QStringLiteral("addLightAction_%1").arg(QLatin1String(toString(type))));
        connect(action, &QAction::triggered, this, [this, type] { addLight(type); });
        m_addActions.push_back(action);
    }
    m_add->setMenu(addMenu);
    m_remove->setObjectName(QStringLiteral("removeLightButton"));
    m_duplicate->setObjectName(QStringLiteral("duplicateLightButton"));
    m_solo->setObjectName(QStringLiteral("soloLightButton"));
    m_solo->setToolTip(tr("Only the selected light on; again: every light on"));
    connect(m_remove, &QPushButton::clicked, this, &LightsDock::removeCurrent);
    connect(m_duplicate, &QPushButton::clicked, this, &LightsDock::duplicateCurrent);
    connect(m_solo, &QPushButton::clicked, this, &LightsDock::soloCurrent);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(m_add);
    buttons->addWidget(m_remove);
    buttons->addWidget(m_duplicate);
    buttons->addWidget(m_solo);

    m_name->setObjectName(QStringLiteral("lightName"));
    m_type->setObjectName(QStringLiteral("lightType"));
    for (LightType type : {LightType::Directional, LightType::Point, LightType::Spot})
        m_type->addItem(typeName(type), int(type));
    m_useTemperature->setObjectName(QStringLiteral("lightUseTemperature"));
    m_color->setObjectName(QStringLiteral("lightColorButton"));
    m_kelvin->setObjectName(QStringLiteral("lightKelvinSlider"));
    m_kelvin->setSuffix(QStringLiteral(" K"));
    m_kelvin->setSpinRange(kMinKelvin, kMaxKelvin);
    m_intensity->setObjectName(QStringLiteral("lightIntensitySlider"));
    m_intensity->setSpinRange(0.0, 1e6);
    m_azimuth->setObjectName(QStringLiteral("lightAzimuthSlider"));
    m_azimuth->setSuffix(QStringLiteral("°"));
    m_elevation->setObjectName(QStringLiteral("lightElevationSlider"));
    m_elevation->setSuffix(QStringLiteral("°"));
    m_innerCone->setObjectName(QStringLiteral("lightInnerConeSlider"));
    m_innerCone->setSuffix(QStringLiteral("°"));
    m_outerCone->setObjectName(QStringLiteral("lightOuterConeSlider"));
    m_outerCone->setSuffix(QStringLiteral("°"));
    m_range->setObjectName(QStringLiteral("lightRange"));
    m_range->setRange(0.0, 10000.0);
    m_range->setSuffix(QStringLiteral(" m"));
    m_range->setSpecialValueText(tr("infinite"));
    m_range->setKeyboardTracking(false);
    auto* positionRow = new QHBoxLayout;
    const char* axes[3] = {"X", "Y", "Z"};
    for (int i = 0; i < 3; ++i) {
        m_position[i] = new QDoubleSpinBox(m_editor);
        m_position[i]->setObjectName(QStringLiteral("lightPosition%1").arg(QLatin1String(axes[i])));
        m_position[i]->setDecimals(2);
        m_position[i]->setSingleStep(0.1);
        m_position[i]->setKeyboardTracking(false);
        // Three boxes in a row fit a narrow dock column (a quarter of a 1200-pixel window): the
        // axes are named in the row's label, not in each box, and a box asks for the width of
        // values to ±100 m (a light near the object); a farther one scrolls in its box.
        m_position[i]->setRange(-100.0, 100.0);
        m_position[i]->setMinimumWidth(m_position[i]->minimumSizeHint().width());
        m_position[i]->setRange(-1000.0, 1000.0);
        m_position[i]->setToolTip(tr("%1 (metres)").arg(QLatin1String(axes[i])));
        positionRow->addWidget(m_position[i]);
    }

    auto* form = new QFormLayout(m_editor);
    form->setContentsMargins(0, 0, 0, 0);
    form->addRow(tr("Name"), m_name);
    form->addRow(tr("Type"), m_type);
    form->addRow(QString(), m_useTemperature);
    form->addRow(tr("Colour"), m_color);
    form->addRow(tr("Temperature"), m_kelvin);
    form->addRow(m_intensityLabel, m_intensity);
    form->addRow(tr("Azimuth"), m_azimuth);
    form->addRow(tr("Elevation"), m_elevation);
    form->addRow(tr("Position X Y Z"), positionRow);
    form->addRow(tr("Range"), m_range);
    form->addRow(tr("Inner cone"), m_innerCone);
    form->addRow(tr("Outer cone"), m_outerCone);

    auto* content = new QWidget(this);
    auto* layout = new QVBoxLayout(content);
    layout->addWidget(m_list, 1);
    layout->addLayout(buttons);
    layout->addWidget(m_editor);
    setWidget(content);

    connect(m_list, &QListWidget::currentRowChanged, this, &LightsDock::refreshEditor);
    connect(m_list, &QListWidget::itemChanged, this, [this](QListWidgetItem* item) {
        const int index = m_list->row(item);
        const bool enabled = item->checkState() == Qt::Checked;
        std::vector<Light> lights = m_document->project().lights;
        if (index < 0 || std::size_t(index) >= lights.size() || lights[std::size_t(index)].enabled == enabled)
            return;
        lights[std::size_t(index)].enabled = enabled;
        setLights(lights, enabled ? tr("Enable Light") : tr("Disable Light"), index);
    });
    connect(m_name, &QLineEdit::editingFinished, this, [this] {
        const std::string name = m_name->text().trimmed().toStdString();
        if (!name.empty())
            editLight(tr("Rename Light"), MergeId::None, [&](Light& light) { light.name = name; });
    });
    connect(m_type, &QComboBox::activated, this, [this] {
        const auto type = LightType(m_type->currentData().toInt());
        editLight(tr("Light Type"), MergeId::None, [&](Light& light) {
            if (light.type == LightType::Directional && type != LightType::Directional)
                light.position = -2.0 * glm::normalize(light.direction); // from where it shone
            light.type = type;
        });
    });
    connect(m_useTemperature, &QCheckBox::clicked, this, [this](bool on) {
        editLight(tr("Light Colour Mode"), MergeId::None, [&](Light& light) { light.useTemperature = on; });
    });
    connect(m_color, &ColorButton::colorEdited, this, [this](const glm::dvec3& color) {
        editLight(tr("Light Colour"), MergeId::None, [&](Light& light) {
            light.color = glm::clamp(color, 0.0, 1.0);
            light.useTemperature = false;
        });
    });
    const auto connectSlider = [this](ValueSlider* slider, int mergeId, const QString& undoText, auto apply) {
        connect(slider, &ValueSlider::editStarted, m_document, &Document::beginInteractiveEdit);
        connect(slider, &ValueSlider::editFinished, m_document, &Document::endInteractiveEdit);
        connect(slider, &ValueSlider::valueEdited, this, [this, mergeId, undoText, apply](double value) {
            editLight(undoText, mergeId, [&](Light& light) { apply(light, value); });
        });
    };
    connectSlider(m_kelvin, MergeId::LightKelvin, tr("Light Temperature"), [](Light& l, double v) {
        l.kelvin = v;
        l.useTemperature = true;
    });
    connectSlider(m_intensity, MergeId::LightIntensity, tr("Light Intensity"),
        [](Light& l, double v) { l.intensity = v; });
    connectSlider(m_azimuth, MergeId::LightDirection, tr("Light Direction"), [](Light& l, double v) {
        double azimuth = 0.0;
        double elevation = 0.0;
        anglesFromDirection(l.direction, &azimuth, &elevation);
        l.direction = directionFromAngles(v, elevation);
    });
    connectSlider(m_elevation, MergeId::LightDirection, tr("Light Direction"), [](Light& l, double v) {
        double azimuth = 0.0;
        double elevation = 0.0;
        anglesFromDirection(l.direction, &azimuth, &elevation);
        // Straight up or down the azimuth is lost: keep a hair off the pole.
        l.direction = directionFromAngles(azimuth, std::clamp(v, -89.9, 89.9));
    });
    // KHR_lights_punctual needs inner < outer: the other angle moves out of the way.
    connectSlider(m_innerCone, MergeId::LightCone, tr("Spot Cone"), [](Light& l, double degrees) {
        l.innerConeAngle = std::min(degrees / kDegrees, l.outerConeAngle - 0.001);
        l.innerConeAngle = std::max(l.innerConeAngle, 0.0);
    });
    connectSlider(m_outerCone, MergeId::LightCone, tr("Spot Cone"), [](Light& l, double degrees) {
        l.outerConeAngle = std::clamp(degrees / kDegrees, 0.002, std::numbers::pi / 2.0);
        l.innerConeAngle = std::min(l.innerConeAngle, l.outerConeAngle - 0.001);
    });
    for (int i = 0; i < 3; ++i)
        connect(m_position[i], &QDoubleSpinBox::valueChanged, this, [this, i](double value) {
            editLight(tr("Light Position"), MergeId::None, [&](Light& light) { light.position[i] = value; });
        });
    connect(m_range, &QDoubleSpinBox::valueChanged, this, [this](double value) {
        editLight(tr("Light Range"), MergeId::None, [&](Light& light) { light.range = value; });
    });

    connect(m_document, &Document::changed, this, &LightsDock::onDocumentChanged);
    onDocumentChanged(DocumentChange::WholeProject);
}

LightsDock::~LightsDock() = default;

int LightsDock::currentLight() const
{
    const int row = m_list->currentRow();
    return row >= 0 && std::size_t(row) < m_document->project().lights.size() ? row : -1;
}

void LightsDock::onDocumentChanged(DocumentChanges changes)
{
    if (!(changes & DocumentChange::Lights))
        return;
    refreshList();
}

void LightsDock::refreshList()
{
    const std::vector<Light>& lights = m_document->project().lights;
    int selected = m_pendingSelection >= 0 ? m_pendingSelection : m_list->currentRow();
    m_pendingSelection = -1;
    {
        const QSignalBlocker blocker(m_list);
        m_list->clear();
        for (const Light& light : lights) {
            auto* item
                = new QListWidgetItem(QStringLiteral("%1 — %2, %3 %4")
                                          .arg(QString::fromStdString(light.name), typeName(light.type))
                                          .arg(light.intensity)
                                          .arg(QLatin1String(intensityUnit(light.type))),
                    m_list);
            item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
            item->setCheckState(light.enabled ? Qt::Checked : Qt::Unchecked);
        }
        selected = std::min(selected, int(lights.size()) - 1);
        if (selected < 0 && !lights.empty())
            selected = 0;
        m_list->setCurrentRow(selected);
    }
    const int count = int(lights.size());
    m_add->setEnabled(count < kMaxPunctualLights);
    m_add->setToolTip(count < kMaxPunctualLights
            ? tr("Add a light")
            : tr("The viewport draws at most %1 lights").arg(kMaxPunctualLights));
    refreshEditor();
}

void LightsDock::refreshEditor()
{
    const int index = currentLight();
    m_remove->setEnabled(index >= 0);
    m_duplicate->setEnabled(index >= 0 && int(m_document->project().lights.size()) < kMaxPunctualLights);
    m_solo->setEnabled(index >= 0);
    m_editor->setVisible(index >= 0);
    if (index < 0)
        return;
    const Light& light = m_document->project().lights[std::size_t(index)];
    const QSignalBlocker nameBlocker(m_name);
    if (!m_name->hasFocus())
        m_name->setText(QString::fromStdString(light.name));
    {
        const QSignalBlocker blocker(m_type);
        m_type->setCurrentIndex(m_type->findData(int(light.type)));
    }
    m_useTemperature->setChecked(light.useTemperature);
    m_color->setLinearColor(light.linearColor());
    m_kelvin->setValue(light.kelvin);
    m_kelvin->setEnabled(light.useTemperature);
    m_intensity->setValue(light.intensity);
    m_intensity->setSuffix(QStringLiteral(" ") + QLatin1String(intensityUnit(light.type)));
    m_intensityLabel->setText(light.type == LightType::Directional ? tr("Illuminance") : tr("Intensity"));
    double azimuth = 0.0;
    double elevation = 0.0;
    anglesFromDirection(light.direction, &azimuth, &elevation);
    m_azimuth->setValue(azimuth);
    m_elevation->setValue(elevation);
    const bool directional = light.type != LightType::Point;
    m_azimuth->setEnabled(directional);
    m_elevation->setEnabled(directional);
    for (int i = 0; i < 3; ++i) {
        const QSignalBlocker blocker(m_position[i]);
        m_position[i]->setValue(light.position[i]);
        m_position[i]->setEnabled(light.type != LightType::Directional);
    }
    {
        const QSignalBlocker blocker(m_range);
        m_range->setValue(light.range);
        m_range->setEnabled(light.type != LightType::Directional);
    }
    m_innerCone->setValue(light.innerConeAngle * kDegrees);
    m_outerCone->setValue(light.outerConeAngle * kDegrees);
    m_innerCone->setEnabled(light.type == LightType::Spot);
    m_outerCone->setEnabled(light.type == LightType::Spot);
}

void LightsDock::editLight(const QString& undoText, int mergeId, const std::function<void(Light&)>& change)
{
    const int index = currentLight();
    if (index < 0)
        return;
    std::vector<Light> lights = m_document->project().lights;
    change(lights[std::size_t(index)]);
    m_pendingSelection = index;
    m_document->setLights(lights, undoText, mergeId);
    m_pendingSelection = -1;
}

void LightsDock::setLights(const std::vector<Light>& lights, const QString& undoText, int select)
{
    m_pendingSelection = select;
    m_document->setLights(lights, undoText);
    m_pendingSelection = -1;
}

void LightsDock::addLight(LightType type)
{
    std::vector<Light> lights = m_document->project().lights;
    if (int(lights.size()) >= kMaxPunctualLights) {
        Q_EMIT message(tr("The viewport draws at most %1 lights").arg(kMaxPunctualLights));
        return;
    }
    Light light = Light::defaultDirectional();
    light.type = type;
    light.name = (typeName(type) + QStringLiteral(" %1").arg(lights.size() + 1)).toStdString();
    if (type != LightType::Directional) {
        // Where the key light shines from, 2 units out; 3 lux at the object's distance is about
        // 3 * 4 = 12 cd (inverse square), so a new point light is as bright as the key.
        light.position = -2.0 * glm::normalize(light.direction);
        light.direction = glm::normalize(light.direction);
        light.intensity = 12.0;
    }
    lights.push_back(light);
    setLights(lights, tr("Add %1 Light").arg(typeName(type)), int(lights.size()) - 1);
}

void LightsDock::removeCurrent()
{
    const int index = currentLight();
    if (index < 0)
        return;
    std::vector<Light> lights = m_document->project().lights;
    lights.erase(lights.begin() + index);
    setLights(lights, tr("Remove Light"), std::max(0, index - 1));
}

void LightsDock::duplicateCurrent()
{
    const int index = currentLight();
    if (index < 0 || int(m_document->project().lights.size()) >= kMaxPunctualLights)
        return;
    std::vector<Light> lights = m_document->project().lights;
    Light copy = lights[std::size_t(index)];
    copy.name += " copy";
    lights.insert(lights.begin() + index + 1, copy);
    setLights(lights, tr("Duplicate Light"), index + 1);
}

void LightsDock::soloCurrent()
{
    const int index = currentLight();
    if (index < 0)
        return;
    std::vector<Light> lights = m_document->project().lights;
    bool alreadySolo = true;
    for (std::size_t i = 0; i < lights.size(); ++i)
        alreadySolo = alreadySolo && lights[i].enabled == (int(i) == index);
    for (std::size_t i = 0; i < lights.size(); ++i)
        lights[i].enabled = alreadySolo || int(i) == index;
    setLights(lights, alreadySolo ? tr("Unsolo Light") : tr("Solo Light"), index);
}

} // namespace facet
