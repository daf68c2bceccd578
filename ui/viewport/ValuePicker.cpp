#include "ui/viewport/ValuePicker.h"

#include "core/image/MapImageCache.h"
#include "core/mesh/Mesh.h"
#include "ui/document/Document.h"
#include "ui/viewport/PartPicker.h"
#include "ui/viewport/SceneController.h"
#include "ui/viewport/ViewportWidget.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QWidget>

#include <algorithm>
#include <cmath>
#include <utility>

namespace facet {

namespace {

// Where the pinned reading is: a cross over the view, white on a dark outline so that it reads
// on any picture; the mouse goes through it.
class PinMarker : public QWidget {
public:
    static constexpr int kSize = 17;
    explicit PinMarker(QWidget* parent)
        : QWidget(parent)
    {
        setObjectName(QStringLiteral("valuePickerPin"));
        setAttribute(Qt::WA_TransparentForMouseEvents);
        setAttribute(Qt::WA_TranslucentBackground);
        setFixedSize(kSize, kSize);
        hide();
    }

protected:
    void paintEvent(QPaintEvent*) override
    {
        QPainter painter(this);
        const int c = kSize / 2;
        for (const auto& [colour, width] :
            {std::pair {QColor(0, 0, 0, 200), 3}, std::pair {QColor(Qt::white), 1}}) {
            painter.setPen(QPen(colour, width));
            painter.drawLine(c, 0, c, c - 3);
            painter.drawLine(c, c + 3, c, kSize - 1);
            painter.drawLine(0, c, c - 3, c);
            painter.drawLine(c + 3, c, kSize - 1, c);
        }
    }
};

std::string imageKey(const LoadedMapImage& map)
{
    return map.path + '@' + std::to_string(map.timestamp);
}

} // namespace

ValuePicker::ValuePicker(
    Document* document, SceneController* scene, ViewportWidget* viewport, PartPicker* parts, QObject* parent)
    : QObject(parent)
    , m_document(document)
    , m_scene(scene)
    , m_viewport(viewport)
    , m_parts(parts)
{
    m_pool.setMaxThreadCount(1);
    m_viewport->installEventFilter(this);
    m_marker = new PinMarker(m_viewport);
    // A pinned reading follows what the view shows: each frame (a refinement step, an edit).
    connect(m_viewport, &ViewportWidget::frameRendered, this, [this] {
        if (m_active && m_current)
            readAgain();
    });
}

ValuePicker::~ValuePicker()
{
    m_pool.clear();
    m_pool.waitForDone();
}

void ValuePicker::setActive(bool active)
{
    if (active == m_active)
        return;
    m_active = active;
    m_viewport->setMouseTracking(active);
    if (!active) {
        // Nothing read while off, and the copies decoded for reading go.
        m_images.clear();
        m_failed.clear();
        m_imagesMaterial = -1;
        m_current.reset();
        setPinned(false);
    }
    Q_EMIT activeChanged(active);
}

void ValuePicker::setPinned(bool pinned)
{
    if (pinned == m_pinned)
        return;
    m_pinned = pinned;
    placeMarker();
    Q_EMIT pinnedChanged(pinned);
}

MaterialMapImages ValuePicker::imagesFor(
    int material, std::vector<MapSlot>* loading, std::vector<std::pair<MapSlot, QString>>* problems)
{
    MaterialMapImages images {};
    const ProjectAssets& assets = m_scene->assets();
    if (material < 0 || std::size_t(material) >= assets.maps.size())
        return images;
    if (material != m_imagesMaterial) {
        // Keep the maps of one material only: a reading is of one point.
        m_images.clear();
        m_failed.clear();
        m_imagesMaterial = material;
    }
    const Project& project = m_scene->document()->project();
    for (MapSlot slot : kAllMapSlots) {
        const LoadedMapImage& map = assets.maps[std::size_t(material)][std::size_t(slot)];
        if (!map.image || map.image->isEmpty())
            continue; // the slot's factor alone, as the view draws it
        if (std::size_t(material) < project.materials.size()
            && !project.materials[std::size_t(material)].usesSlot(slot))
            continue; // a lobe that is off: not drawn, not read
        if (map.image->hasPixels()) {
            images[std::size_t(slot)] = map.image.get();
            continue;
        }
        const std::string key = imageKey(map);
        if (const auto found = m_images.find(key); found != m_images.end()) {
            images[std::size_t(slot)] = found->second.get();
        } else if (const auto failed = m_failed.find(key); failed != m_failed.end()) {
            problems->emplace_back(slot, failed->second);
        } else {
            loading->push_back(slot);
            if (m_loading.insert(key).second) {
                m_pool.start([this, key, path = map.path] {
                    std::string error;
                    std::shared_ptr<const MapImage> image = MapImageCache::shared().load(path, &error);
                    QMetaObject::invokeMethod(
                        this,
                        [this, key, image, message = QString::fromStdString(error)] {
                            mapArrived(key, image, message);
                        },
                        Qt::QueuedConnection);
                });
            }
        }
    }
    return images;
}

void ValuePicker::mapArrived(
    const std::string& key, std::shared_ptr<const MapImage> image, const QString& error)
{
    m_loading.erase(key);
    if (!m_active)
        return;
    if (image && image->hasPixels())
        m_images[key] = std::move(image);
    else
        m_failed[key] = error.isEmpty() ? tr("the file has no pixels") : error;
    if (m_current)
        readAgain();
}

void ValuePicker::readAgain()
{
    if (m_current)
        readAt(m_current->position);
}

PickedValue ValuePicker::readAt(const QPointF& position)
{
    PickedValue value;
    value.position = position;
    const qreal ratio = m_viewport->devicePixelRatioF();
    value.pixel = QPoint(int(std::floor(position.x() * ratio)), int(std::floor(position.y() * ratio)));
    value.viewSize = m_viewport->deviceSize();
    const ViewportRenderer::ShownPixel shown = m_viewport->shownPixel(position);
    value.radiance = shown.radiance;
    value.display = shown.display;

    const std::shared_ptr<const Mesh>& mesh = m_scene->assets().mesh;
    if (const std::optional<MeshHit> hit = mesh ? m_parts->hitAt(position) : std::nullopt) {
        const Project& project = m_document->project();
        PickedValue::Surface surface;
        surface.part = int(hit->subMesh);
        surface.material = project.materialOfPart(hit->subMesh);
        surface.partName = m_parts->partName(surface.part);
        const Material& material = project.materials[std::size_t(surface.material)];
        surface.materialName = QString::fromStdString(material.name);
        const MaterialMapImages images
            = imagesFor(surface.material, &surface.mapsLoading, &surface.mapProblems);
        surface.probe = probeSurface(*mesh, m_viewport->modelMatrix(), *hit, material, images);
        value.surface = std::move(surface);
    }
    m_current = value;
    placeMarker();
    Q_EMIT picked(value);
    return value;
}

void ValuePicker::placeMarker()
{
    const bool shown = m_active && m_pinned && m_current;
    if (shown)
        m_marker->move(m_current->position.toPoint() - QPoint(PinMarker::kSize / 2, PinMarker::kSize / 2));
    m_marker->setVisible(shown);
}

void ValuePicker::pinAt(const QPointF& position)
{
    setPinned(true);
    readAt(position);
}

bool ValuePicker::eventFilter(QObject* watched, QEvent* event)
{
    if (watched != m_viewport || !m_active)
        return false;
    switch (event->type()) {
    case QEvent::MouseMove: {
        const auto* mouse = static_cast<QMouseEvent*>(event);
        if (m_pressedAt) {
            const QPointF moved = mouse->position() - *m_pressedAt;
            if (std::abs(moved.x()) + std::abs(moved.y()) > PartPicker::kClickSlopPixels)
                m_pressedAt.reset(); // an orbit, not a click
        }
        // Hovering reads; a drag (a button down) moves the camera, and the frame after it is read.
        if (!m_pinned && mouse->buttons() == Qt::NoButton)
            readAt(mouse->position() + QPointF(0.5, 0.5));
        break;
    }
    case QEvent::MouseButtonPress: {
        const auto* mouse = static_cast<QMouseEvent*>(event);
        if (mouse->button() == Qt::LeftButton && !mouse->modifiers().testFlag(Qt::ShiftModifier))
            m_pressedAt = mouse->position();
        else
            m_pressedAt.reset();
        break;
    }
    case QEvent::MouseButtonRelease: {
        const auto* mouse = static_cast<QMouseEvent*>(event);
        if (mouse->button() == Qt::LeftButton && m_pressedAt) {
            const QPointF moved = mouse->position() - *m_pressedAt;
            if (std::abs(moved.x()) + std::abs(moved.y()) <= PartPicker::kClickSlopPixels) {
                pinAt(*m_pressedAt + QPointF(0.5, 0.5));
                Q_EMIT message(tr("Values pinned at (%1, %2): click elsewhere to move the pin, Esc to follow "
                                  "the cursor")
                                   .arg(m_current->pixel.x())
                                   .arg(m_current->pixel.y()));
            }
        }
        m_pressedAt.reset();
        break;
    }
    case QEvent::KeyPress:
        if (static_cast<QKeyEvent*>(event)->key() == Qt::Key_Escape && m_pinned) {
            setPinned(false);
            Q_EMIT message(tr("Values follow the cursor"));
            return true;
        }
        break;
    default:
        break;
    }
    return false; // watch only: the camera and the part picker get every event
}

} // namespace facet
