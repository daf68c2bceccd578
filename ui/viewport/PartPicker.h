#pragma once
// Clicking a part of the object in the viewport makes its material the one the docks edit. Not a
// widget: an event filter on the ViewportWidget that only watches (it never eats an event, so the
// CameraController still orbits and pans). A left press and release within kClickSlopPixels of
// each other, without Shift (Shift + drag pans), is a click; anything that moved further was an
// orbit and picks nothing.
//
// The pick is a CPU ray cast (core/mesh/MeshPicking.h) from the document's camera through the clicked
// pixel against the mesh SceneController loaded (normalised to the unit sphere) under the model
// matrix it is drawn with (the object turntable's rotation): the nearest visible part, seen from
// behind only when its material is double-sided, as the renderer draws it. Alpha-masked holes are
// not taken into account.

#include "core/mesh/MeshPicking.h"

#include <QObject>
#include <QPointF>

#include <optional>

namespace facet {

class Document;
class SceneController;
class ViewportWidget;

class PartPicker : public QObject {
    Q_OBJECT
public:
    static constexpr double kClickSlopPixels = 4.0;

    // Install after the CameraController: filters run newest first, and this one must see the
    // press and release before the camera's filter consumes them.
    PartPicker(
        Document* document, SceneController* scene, ViewportWidget* viewport, QObject* parent = nullptr);

    // The part (sub-mesh index) under `position` (viewport widget coordinates in logical pixels,
    // continuous: the centre of the pixel a mouse event at (x, y) names is (x + 0.5, y + 0.5)), or
    // nullopt where a click would hit nothing.
    std::optional<int> partAt(const QPointF& position) const;
    // The hit itself (its part, triangle and barycentric coordinates, world position) under
    // `position`, on the mesh SceneController holds, drawn with its model matrix; the value
    // picker reads the surface there (ui/viewport/ValuePicker.h).
    std::optional<MeshHit> hitAt(const QPointF& position) const;
    // What a click at `position` does: picks the part there and makes its material current
    // (Document::setCurrentMaterial, a selection, not an undo step). Returns the part. `extend`
    // (a Ctrl-click) adds the part to the selected parts, or takes it out, instead of replacing
    // them (Assign to Selected then gives them all one material).
    std::optional<int> pickAt(const QPointF& position, bool extend = false);
    // The part's name as the file gives it ("part 3" when it has none), for messages.
    QString partName(int part) const;

Q_SIGNALS:
    // A part was clicked; `material` is now the current material; `extend`: a Ctrl-click.
    void partPicked(int part, int material, bool extend);
    // For the status bar.
    void message(const QString& text);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    Document* m_document;
    SceneController* m_scene;
    ViewportWidget* m_viewport;
    std::optional<QPointF> m_pressedAt; // a left press that may still become a click
    bool m_pressExtends = false; // the press had Ctrl: the click extends the selection
};

} // namespace facet
