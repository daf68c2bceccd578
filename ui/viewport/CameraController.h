#pragma once
// Camera input for the viewport (not a widget): an event filter on the ViewportWidget that turns
// mouse, wheel and keys into Document::setCamera() (camera moves are saved but not undoable),
// plus the turntable, which spins the object or the environment in the view only.
//
//   left drag            orbit about the target          F        frame the object
//   middle / Shift+left  pan                             Home     reset to the default view
//   wheel                dolly                           T        turntable on/off
//   fly mode (setFlyMode): left drag looks around, W A S D move, Q E down/up, Shift faster
//
// Framing fits the object's bounding sphere to the smaller of the viewport's two fields of view
// (core/project/Camera.h framingDistance), so a tall viewport shows the whole object too. The default view
// (Home, and the first view of a project whose camera is the reference view: the default project,
// or one saved without moving the camera) is the reference view backed off as far as the viewport's
// shape needs. Until the camera is moved, a resize of the viewport fits it again (the layout
// settling at start-up, a dock dragged wider); a project's saved camera is never changed.
//
// Timers run only while the turntable is on or a fly key is held; otherwise nothing ticks.

#include "core/project/Camera.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPoint>
#include <QSet>
#include <QTimer>

#include <optional>

class QKeyEvent;
class QMouseEvent;
class QWheelEvent;

namespace facet {

class Document;
class SceneController;
class ViewportWidget;

class CameraController : public QObject {
    Q_OBJECT
public:
    enum class TurntableTarget { Object, Environment };

    static constexpr double kOrbitDegreesPerPixel = 0.3;
    static constexpr double kTurntableDegreesPerSecond = 30.0;
    static constexpr double kFlySpeedPerSecond = 1.5; // world units (the object is ~1)
    static constexpr int kTickMs = 16; // turntable and fly ticks; frames come as fast as they render

    CameraController(
        Document* document, SceneController* scene, ViewportWidget* viewport, QObject* parent = nullptr);

    // Camera operations (also bound to the keys above). Pixels are widget pixels.
    void orbit(double deltaXPixels, double deltaYPixels);
    void pan(double deltaXPixels, double deltaYPixels);
    void dolly(double wheelSteps); // > 0: closer
    // What orbit() and dolly() do to a camera (the Compare view moves its cells' cameras with them).
    static Camera orbited(Camera camera, double deltaXPixels, double deltaYPixels);
    static Camera dollied(Camera camera, double wheelSteps);
    void frameObject();
    void resetView();
    // The reference view (Camera::referenceView(), unchanged when the viewport is at least as wide
    // as tall) moved back along +Z until the unit bounding sphere fits a viewport `aspect` wide.
    static Camera defaultView(double aspect);
    // `camera` aimed at the origin along its current direction, at the distance where the unit
    // bounding sphere fits a viewport `aspect` wide.
    static Camera framed(Camera camera, double aspect);
    void look(double deltaXPixels, double deltaYPixels); // fly mode: turn the view direction
    void fly(const glm::dvec3& moveInViewSpace); // fly mode: move position and target together

    void setFlyMode(bool on);
    bool flyMode() const { return m_flyMode; }
    void setTurntableRunning(bool running);
    bool turntableRunning() const { return m_turntable.isActive(); }
    void setTurntableTarget(TurntableTarget target);
    TurntableTarget turntableTarget() const { return m_turntableTarget; }

Q_SIGNALS:
    void turntableRunningChanged(bool running);
    void flyModeChanged(bool on);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    bool mousePress(QMouseEvent* event);
    bool mouseMove(QMouseEvent* event);
    bool wheel(QWheelEvent* event);
    bool keyPress(QKeyEvent* event);
    bool keyRelease(QKeyEvent* event);
    void setCamera(const Camera& camera);
    enum class Fit { Default, Frame };
    // The viewport's width / height, or 0 while it is too small to frame for.
    double viewportAspect() const;
    // Sets the camera `fit` gives for the viewport's shape (nothing while it has none yet) and
    // remembers it, so that a resize fits again while the camera is still that one.
    void fitToViewport(Fit fit, bool interactive);
    void onProjectReplaced();
    void turntableTick();
    void flyTick();

    Document* m_document;
    SceneController* m_scene;
    ViewportWidget* m_viewport;
    enum class Drag { None, Orbit, Pan, Look } m_drag = Drag::None;
    QPoint m_lastMouse;
    bool m_flyMode = false;
    QSet<int> m_flyKeys;
    bool m_flyFast = false;
    QTimer m_flyTimer;
    QElapsedTimer m_flyClock;
    TurntableTarget m_turntableTarget = TurntableTarget::Object;
    QTimer m_turntable;
    QElapsedTimer m_turntableClock;
    std::optional<Fit> m_fit; // how the camera was last fitted; none after a project's own camera
    Camera m_fitted; // the camera that fit set (or the one waiting for a viewport size)
};

} // namespace facet
