#include "ui/viewport/PartPicker.h"

#include "core/mesh/MeshPicking.h"
#include "ui/document/Document.h"
#include "ui/viewport/SceneController.h"
#include "ui/viewport/ViewportWidget.h"

#include <QMouseEvent>

#include <algorithm>
#include <cmath>
#include <vector>

namespace facet {

PartPicker::PartPicker(Document* document, SceneController* scene, ViewportWidget* viewport, QObject* parent)
    : QObject(parent)
    , m_document(document)
    , m_scene(scene)
    , m_viewport(viewport)
{
    m_viewport->installEventFilter(this);
}

std::optional<int> PartPicker::partAt(const QPointF& position) const
{
    const std::optional<MeshHit> hit = hitAt(position);
    if (!hit)
        return std::nullopt;
    return int(hit->subMesh);
}

std::optional<MeshHit> PartPicker::hitAt(const QPointF& position) const
{
    const std::shared_ptr<const Mesh>& mesh = m_scene->assets().mesh;
    const int width = m_viewport->width();
    const int height = m_viewport->height();
    if (!mesh || width <= 0 || height <= 0)
        return std::nullopt;
    const Project& project = m_document->project();
    std::vector<PickPart> parts(std::max<std::size_t>(mesh->subMeshes.size(), 1));
    for (std::size_t p = 0; p < parts.size(); ++p) {
        parts[p].visible = project.isPartVisible(p);
        parts[p].cullsBackFaces = !project.materials[std::size_t(project.materialOfPart(p))].doubleSided;
    }
    // The renderer's image spans the widget (its resolution does not matter: a ray through the
    // same point of the image is the same ray).
    const PickRay ray = cameraRay(project.camera, width, height, {position.x(), position.y()});
    return pickMesh(*mesh, m_viewport->modelMatrix(), ray, parts);
}

QString PartPicker::partName(int part) const
{
    const std::shared_ptr<const Mesh>& mesh = m_scene->assets().mesh;
    const std::string name = !mesh                                ? std::string()
        : part >= 0 && std::size_t(part) < mesh->subMeshes.size() ? mesh->subMeshes[std::size_t(part)].name
                                                                  : mesh->name;
    return name.empty() ? tr("part %1").arg(part + 1) : QString::fromStdString(name);
}

std::optional<int> PartPicker::pickAt(const QPointF& position, bool extend)
{
    const std::optional<int> part = partAt(position);
    if (!part)
        return std::nullopt;
    const Project& project = m_document->project();
    const int material = project.materialOfPart(std::size_t(*part));
    m_document->setCurrentMaterial(material);
    const QString name = partName(*part);
    Q_EMIT message(tr("%1: material “%2”")
                       .arg(name, QString::fromStdString(project.materials[std::size_t(material)].name)));
    Q_EMIT partPicked(*part, material, extend);
    return part;
}

bool PartPicker::eventFilter(QObject* watched, QEvent* event)
{
    if (watched != m_viewport)
        return false;
    switch (event->type()) {
    case QEvent::MouseButtonPress: {
        const auto* mouse = static_cast<QMouseEvent*>(event);
        // Shift + left drags pan; other buttons are not clicks on a part.
        if (mouse->button() == Qt::LeftButton && !mouse->modifiers().testFlag(Qt::ShiftModifier)) {
            m_pressedAt = mouse->position();
            m_pressExtends = mouse->modifiers().testFlag(Qt::ControlModifier);
        } else {
            m_pressedAt.reset();
        }
        break;
    }
    case QEvent::MouseMove: {
        const auto* mouse = static_cast<QMouseEvent*>(event);
        if (m_pressedAt) {
            const QPointF moved = mouse->position() - *m_pressedAt;
            if (std::abs(moved.x()) + std::abs(moved.y()) > kClickSlopPixels)
                m_pressedAt.reset(); // an orbit, not a click
        }
        break;
    }
    case QEvent::MouseButtonRelease: {
        const auto* mouse = static_cast<QMouseEvent*>(event);
        if (mouse->button() == Qt::LeftButton && m_pressedAt) {
            const QPointF moved = mouse->position() - *m_pressedAt;
            // A mouse position names a pixel; its ray goes through that pixel's centre.
            if (std::abs(moved.x()) + std::abs(moved.y()) <= kClickSlopPixels)
                pickAt(*m_pressedAt + QPointF(0.5, 0.5), m_pressExtends);
        }
        m_pressedAt.reset();
        break;
    }
    default:
        break;
    }
    return false; // watch only: the camera gets every event
}

} // namespace facet
