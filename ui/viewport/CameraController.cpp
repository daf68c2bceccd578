#include "ui/viewport/CameraController.h"

#include "ui/document/Document.h"
#include "ui/viewport/SceneController.h"
#include "ui/viewport/ViewportWidget.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QWheelEvent>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace facet {

namespace {

constexpr double kMinDistance = 0.2;
constexpr double kMaxDistance = 50.0;
constexpr double kMaxElevationDegrees = 89.0;
constexpr double kDollyPerStep = 0.9; // distance factor per wheel notch (120 units)
constexpr int kMinFramingPixels = 16; // a viewport narrower (or lower) than this is not framed for

glm::dvec3 rotateAbout(const glm::dvec3& v, const glm::dvec3& axis, double degrees)
{
    return glm::dvec3(glm::rotate(glm::dmat4(1.0), glm::radians(degrees), axis) * glm::dvec4(v, 0.0));
}

bool isFlyKey(int key)
{
    return key == Qt::Key_W || key == Qt::Key_A || key == Qt::Key_S || key == Qt::Key_D || key == Qt::Key_Q
        || key == Qt::Key_E;
}

} // namespace

CameraController::CameraController(
    Document* document, SceneController* scene, ViewportWidget* viewport, QObject* parent)
    : QObject(parent)
    , m_document(document)
    , m_scene(scene)
    , m_viewport(viewport)
{
    m_viewport->installEventFilter(this);
    m_turntable.setInterval(kTickMs);
    connect(&m_turntable, &QTimer::timeout, this, &CameraController::turntableTick);
    m_flyTimer.setInterval(kTickMs);
    connect(&m_flyTimer, &QTimer::timeout, this, &CameraController::flyTick);
    connect(m_document, &Document::projectReplaced, this, &CameraController::onProjectReplaced);
    onProjectReplaced(); // the document's first project gets its first view too
}

void CameraController::onProjectReplaced()
{
    m_fit.reset();
    // A camera that is exactly the reference view was never moved (the default project, or a
    // project saved without touching the camera): show it whole in this viewport. A camera the
    // user placed stays as saved.
    if (m_document->project().camera == Camera::referenceView()) {
        m_fit = Fit::Default;
        m_fitted = m_document->project().camera;
        fitToViewport(Fit::Default, false);
    }
}

double CameraController::viewportAspect() const
{
    const int width = m_viewport->width();
    const int height = m_viewport->height();
    if (width < kMinFramingPixels || height < kMinFramingPixels)
        return 0.0;
    return double(width) / double(height);
}

void CameraController::fitToViewport(Fit fit, bool interactive)
{
    double aspect = viewportAspect();
    if (aspect <= 0.0) {
        if (!interactive)
            return; // fitted when the viewport gets a size (eventFilter, QEvent::Resize)
        aspect = 1.0; // F or Home before the viewport has a size: frame for a square
    }
    const Camera& current = m_document->project().camera;
    m_fit = fit;
    m_fitted = fit == Fit::Default ? defaultView(aspect) : framed(current, aspect);
    if (interactive)
        setCamera(m_fitted);
    else
        m_document->setCamera(m_fitted);
}

Camera CameraController::defaultView(double aspect)
{
    Camera camera = Camera::referenceView();
    const glm::dvec3 offset = camera.position - camera.target;
    const double distance = std::min(camera.framingDistance(1.0, aspect), kMaxDistance);
    // Only ever farther: in a wide viewport the reference view itself, to the last bit.
    if (distance > glm::length(offset))
        camera.position = camera.target + glm::normalize(offset) * distance;
    return camera;
}

Camera CameraController::framed(Camera camera, double aspect)
{
    // Meshes are normalised to the unit bounding sphere at the origin (core/project/ProjectAssets.h):
    // keep the view direction, aim at the origin, back off until the sphere fits with a margin.
    glm::dvec3 direction = camera.position - camera.target;
    direction = glm::length(direction) > 0.0 ? glm::normalize(direction) : glm::dvec3(0.0, 0.0, 1.0);
    camera.target = glm::dvec3(0.0);
    camera.position = direction * std::min(camera.framingDistance(1.0, aspect), kMaxDistance);
    return camera;
}

void CameraController::setCamera(const Camera& camera)
{
    m_viewport->markInteractive();
    m_document->setCamera(camera);
}

Camera CameraController::orbited(Camera camera, double deltaXPixels, double deltaYPixels)
{
    const glm::dvec3 offset = camera.position - camera.target;
    const double distance = glm::length(offset);
    if (distance <= 0.0)
        return camera;
    // Spherical coordinates about +Y: azimuth in the XZ plane, elevation from it.
    double azimuth = std::atan2(offset.x, offset.z);
    double elevation = std::asin(std::clamp(offset.y / distance, -1.0, 1.0));
    azimuth -= glm::radians(deltaXPixels * kOrbitDegreesPerPixel);
    elevation += glm::radians(deltaYPixels * kOrbitDegreesPerPixel);
    const double limit = glm::radians(kMaxElevationDegrees);
    elevation = std::clamp(elevation, -limit, limit);
    camera.position = camera.target
        + distance
            * glm::dvec3(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                std::cos(elevation) * std::cos(azimuth));
    camera.up = {0.0, 1.0, 0.0};
    return camera;
}

void CameraController::orbit(double deltaXPixels, double deltaYPixels)
{
    const Camera& camera = m_document->project().camera;
    if (glm::length(camera.position - camera.target) <= 0.0)
        return;
    setCamera(orbited(camera, deltaXPixels, deltaYPixels));
}

void CameraController::pan(double deltaXPixels, double deltaYPixels)
{
    Camera camera = m_document->project().camera;
    const glm::dvec3 forward = camera.target - camera.position;
    const double distance = glm::length(forward);
    if (distance <= 0.0)
        return;
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::dvec3 up = glm::normalize(glm::cross(right, forward));
    // One pixel moves the target plane by what a pixel covers at the target's distance.
    const double worldPerPixel = 2.0 * distance * std::tan(glm::radians(camera.verticalFovDegrees) / 2.0)
        / std::max(1, m_viewport->height());
    const glm::dvec3 move = (-deltaXPixels * right + deltaYPixels * up) * worldPerPixel;
    camera.position += move;
    camera.target += move;
    setCamera(camera);
}

Camera CameraController::dollied(Camera camera, double wheelSteps)
{
    const glm::dvec3 offset = camera.position - camera.target;
    const double distance = glm::length(offset);
    if (distance <= 0.0)
        return camera;
    const double next
        = std::clamp(distance * std::pow(kDollyPerStep, wheelSteps), kMinDistance, kMaxDistance);
    camera.position = camera.target + offset * (next / distance);
    return camera;
}

void CameraController::dolly(double wheelSteps)
{
    const Camera& camera = m_document->project().camera;
    if (glm::length(camera.position - camera.target) <= 0.0)
        return;
    setCamera(dollied(camera, wheelSteps));
}

void CameraController::frameObject()
{
    fitToViewport(Fit::Frame, true);
}

void CameraController::resetView()
{
    fitToViewport(Fit::Default, true);
}

void CameraController::look(double deltaXPixels, double deltaYPixels)
{
    Camera camera = m_document->project().camera;
    glm::dvec3 forward = camera.target - camera.position;
    const double distance = glm::length(forward);
    if (distance <= 0.0)
        return;
    forward = rotateAbout(forward, {0.0, 1.0, 0.0}, -deltaXPixels * kOrbitDegreesPerPixel);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 pitched = rotateAbout(forward, right, -deltaYPixels * kOrbitDegreesPerPixel);
    // Stop short of looking straight up or down (the up vector would flip).
    if (std::abs(glm::normalize(pitched).y) < std::sin(glm::radians(kMaxElevationDegrees)))
        forward = pitched;
    camera.target = camera.position + forward;
    camera.up = {0.0, 1.0, 0.0};
    setCamera(camera);
}

void CameraController::fly(const glm::dvec3& moveInViewSpace)
{
    Camera camera = m_document->project().camera;
    const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::dvec3 move = right * moveInViewSpace.x + glm::dvec3(0.0, 1.0, 0.0) * moveInViewSpace.y
        + forward * -moveInViewSpace.z;
    camera.position += move;
    camera.target += move;
    setCamera(camera);
}

void CameraController::setFlyMode(bool on)
{
    if (on == m_flyMode)
        return;
    m_flyMode = on;
    m_flyKeys.clear();
    m_flyTimer.stop();
    Q_EMIT flyModeChanged(on);
}

void CameraController::setTurntableRunning(bool running)
{
    if (running == m_turntable.isActive())
        return;
    if (running) {
        m_turntableClock.start();
        m_turntable.start();
    } else {
        m_turntable.stop();
        m_viewport->markInteractive(); // one refined frame follows
    }
    Q_EMIT turntableRunningChanged(running);
}

void CameraController::setTurntableTarget(TurntableTarget target)
{
    m_turntableTarget = target;
}

void CameraController::turntableTick()
{
    const double seconds = double(m_turntableClock.restart()) / 1000.0;
    const double step = kTurntableDegreesPerSecond * seconds;
    double object = m_viewport->viewState().objectTurntableDegrees;
    double environment = m_viewport->viewState().environmentTurntableDegrees;
    if (m_turntableTarget == TurntableTarget::Object)
        object = std::fmod(object + step, 360.0);
    else
        environment = std::fmod(environment + step, 360.0);
    m_viewport->markInteractive();
    m_viewport->setTurntableAngles(object, environment);
}

void CameraController::flyTick()
{
    const double seconds = double(m_flyClock.restart()) / 1000.0;
    glm::dvec3 direction(0.0);
    direction.x = (m_flyKeys.contains(Qt::Key_D) ? 1.0 : 0.0) - (m_flyKeys.contains(Qt::Key_A) ? 1.0 : 0.0);
    direction.y = (m_flyKeys.contains(Qt::Key_E) ? 1.0 : 0.0) - (m_flyKeys.contains(Qt::Key_Q) ? 1.0 : 0.0);
    direction.z = (m_flyKeys.contains(Qt::Key_S) ? 1.0 : 0.0) - (m_flyKeys.contains(Qt::Key_W) ? 1.0 : 0.0);
    if (direction == glm::dvec3(0.0))
        return;
    const double speed = kFlySpeedPerSecond * (m_flyFast ? 4.0 : 1.0);
    fly(glm::normalize(direction) * speed * seconds);
}

bool CameraController::eventFilter(QObject* watched, QEvent* event)
{
    if (watched != m_viewport)
        return false;
    switch (event->type()) {
    case QEvent::Resize:
        // The viewport changed shape: a camera the last fit set (not moved since) fits again.
        if (m_fit && m_document->project().camera == m_fitted)
            fitToViewport(*m_fit, false);
        return false;
    case QEvent::MouseButtonPress:
        return mousePress(static_cast<QMouseEvent*>(event));
    case QEvent::MouseMove:
        return mouseMove(static_cast<QMouseEvent*>(event));
    case QEvent::MouseButtonRelease:
        m_drag = Drag::None;
        return true;
    case QEvent::Wheel:
        return wheel(static_cast<QWheelEvent*>(event));
    case QEvent::KeyPress:
        return keyPress(static_cast<QKeyEvent*>(event));
    case QEvent::KeyRelease:
        return keyRelease(static_cast<QKeyEvent*>(event));
    case QEvent::FocusOut:
        m_flyKeys.clear();
        m_flyTimer.stop();
        return false;
    default:
        return false;
    }
}

bool CameraController::mousePress(QMouseEvent* event)
{
    m_lastMouse = event->position().toPoint();
    const bool shift = event->modifiers().testFlag(Qt::ShiftModifier);
    if (event->button() == Qt::MiddleButton || (event->button() == Qt::LeftButton && shift))
        m_drag = Drag::Pan;
    else if (event->button() == Qt::LeftButton)
        m_drag = m_flyMode ? Drag::Look : Drag::Orbit;
    else
        return false;
    m_viewport->setFocus(Qt::MouseFocusReason);
    return true;
}

bool CameraController::mouseMove(QMouseEvent* event)
{
    if (m_drag == Drag::None)
        return false;
    const QPoint position = event->position().toPoint();
    const QPoint delta = position - m_lastMouse;
    m_lastMouse = position;
    if (delta.isNull())
        return true;
    switch (m_drag) {
    case Drag::Orbit:
        orbit(delta.x(), delta.y());
        break;
    case Drag::Pan:
        pan(delta.x(), delta.y());
        break;
    case Drag::Look:
        look(delta.x(), delta.y());
        break;
    case Drag::None:
        break;
    }
    return true;
}

bool CameraController::wheel(QWheelEvent* event)
{
    const double steps = event->angleDelta().y() / 120.0;
    if (steps != 0.0)
        dolly(steps);
    return true;
}

bool CameraController::keyPress(QKeyEvent* event)
{
    if (m_flyMode && isFlyKey(event->key())) {
        m_flyFast = event->modifiers().testFlag(Qt::ShiftModifier);
        if (!event->isAutoRepeat()) {
            m_flyKeys.insert(event->key());
            if (!m_flyTimer.isActive()) {
                m_flyClock.start();
                m_flyTimer.start();
            }
        }
        return true;
    }
    return false;
}

bool CameraController::keyRelease(QKeyEvent* event)
{
    if (!m_flyMode || !isFlyKey(event->key()))
        return false;
    if (!event->isAutoRepeat()) {
        m_flyKeys.remove(event->key());
        if (m_flyKeys.isEmpty())
            m_flyTimer.stop();
    }
    return true;
}

} // namespace facet
