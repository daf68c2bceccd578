#pragma once
// The value picker (View > Value Picker, I; the Values dock shows what it reads): what the view
// shows under the cursor, and why. For a point of the viewport it reads
//   - the shaded radiance of the frame on screen (linear, scene-referred, before exposure: the
//     HDR target the frame was tone-mapped from) and the 8-bit value on screen (after exposure,
//     tone mapping and the display encoding), from the GPU (ViewportWidget::shownPixel);
//   - the surface there: a CPU ray cast (ui/viewport/PartPicker, core/mesh/MeshPicking) and, at the hit, the
//     interpolated UVs, normals and vertex colour, and each map's texel with its UV, stored and
//     decoded values and the filtered read the shader makes, and the material's inputs
//     (core/mesh/SurfaceProbe, the CPU twin of the shader's reads).
// As Mari's Pixel Analyzer and Nuke's viewer colour sampler do, it follows the cursor while the
// picker is on; a click pins the reading to a point (Esc, or the dock's Pinned box, lets it
// follow again). A pinned reading is read again after each frame (a refinement step, an edit).
//
// Maps whose decoded pixels the window let go after upload (ui/viewport/SceneController
// releaseMapPixels) are decoded again off the GUI thread for reading (core/image/MapImageCache, one
// worker): until they arrive the reading lists them as loading, and it is read again when they
// do. Only the current reading's material's maps are kept, and none once the picker is off.
//
// Not a widget: an event filter on the viewport that only watches (the camera still orbits).
// docs/app.md, "Value picker".

#include "core/image/MapImage.h"
#include "core/material/Material.h"
#include "core/mesh/SurfaceProbe.h"

#include <QObject>
#include <QPoint>
#include <QPointF>
#include <QSize>
#include <QString>
#include <QThreadPool>

class QWidget;

#include <glm/ext/vector_uint4_sized.hpp>
#include <glm/vec4.hpp>

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace facet {

class Document;
class PartPicker;
class SceneController;
class ViewportWidget;

struct PickedValue {
    QPointF position; // widget coordinates, logical pixels (a pixel's centre: x + 0.5)
    QPoint pixel; // device pixel, from the top-left corner
    QSize viewSize; // the view in device pixels
    std::optional<glm::vec4> radiance; // linear, before exposure (nullopt: not readable now)
    std::optional<glm::u8vec4> display; // on screen, 8-bit encoded
    // The surface under the point; unset over the background.
    struct Surface {
        int part = 0;
        int material = 0;
        QString partName;
        QString materialName;
        SurfaceProbe probe;
        std::vector<MapSlot> mapsLoading; // being decoded again for reading: read when they arrive
        std::vector<std::pair<MapSlot, QString>> mapProblems; // could not be read (named)
    };
    std::optional<Surface> surface;
};

class ValuePicker : public QObject {
    Q_OBJECT
public:
    ValuePicker(Document* document, SceneController* scene, ViewportWidget* viewport, PartPicker* parts,
        QObject* parent = nullptr);
    ~ValuePicker() override;

    // On: the viewport tracks the mouse and the reading follows it (until pinned). Off: nothing is
    // read and the decoded maps go.
    void setActive(bool active);
    bool isActive() const { return m_active; }
    // Pinned: the reading stays at its point (read again after each frame); otherwise it follows
    // the cursor.
    void setPinned(bool pinned);
    bool isPinned() const { return m_pinned; }

    // Reads `position` (widget coordinates) now and makes it the current reading (picked() is
    // emitted). Maps not decoded yet are asked for; the reading is made again when they arrive.
    PickedValue readAt(const QPointF& position);
    // A click at `position`: reads it and pins the reading there.
    void pinAt(const QPointF& position);
    const std::optional<PickedValue>& current() const { return m_current; }
    // Map decodes asked for and not arrived yet (tests wait for 0).
    int pendingMapLoads() const { return int(m_loading.size()); }

Q_SIGNALS:
    void picked(const facet::PickedValue& value);
    void activeChanged(bool active);
    void pinnedChanged(bool pinned);
    void message(const QString& text);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    // `material`'s images for reading (with pixels): the window's copies where it still holds
    // them, else the ones decoded here; the rest asked for (*loading) or failed (*problems).
    MaterialMapImages imagesFor(
        int material, std::vector<MapSlot>* loading, std::vector<std::pair<MapSlot, QString>>* problems);
    void mapArrived(const std::string& key, std::shared_ptr<const MapImage> image, const QString& error);
    void readAgain();
    // The cross over the view at a pinned reading (hidden otherwise).
    void placeMarker();

    Document* m_document;
    SceneController* m_scene;
    ViewportWidget* m_viewport;
    PartPicker* m_parts;
    bool m_active = false;
    bool m_pinned = false;
    std::optional<PickedValue> m_current;
    std::optional<QPointF> m_pressedAt; // a left press that may still become a click
    // Decoded again for reading, by file (path and timestamp), of the last material read.
    int m_imagesMaterial = -1;
    std::map<std::string, std::shared_ptr<const MapImage>> m_images;
    std::map<std::string, QString> m_failed;
    std::set<std::string> m_loading;
    QWidget* m_marker; // a child of the viewport
    QThreadPool m_pool; // one worker: the machine's cores are the renderer's
};

} // namespace facet
