#pragma once
// The 3D view. It presents frames and nothing else: SceneController (the CPU side) keeps the
// document's scene and its loaded assets, ViewportRenderer (the GPU side, in this widget's
// context) draws them, and this widget asks for a frame when the scene changed and shows it.
// Camera input is handled by CameraController through an event filter.
//
// Render on demand: paintGL() runs only after update() (a scene change, a resize, an expose),
// never on a timer; an idle window draws nothing. While something is being dragged
// (markInteractive()) frames are drawn at kPreviewScale of the resolution, and one full frame
// follows kRefineDelayMs after the last interactive change. When the project's IBL method is fis
// or reference, that still frame then refines (ViewportRenderer::refine): one draw per paint,
// each paint chained to the next by a zero-time timer (input events run in between), until the
// method's samples are in; then nothing is drawn until the scene changes. A draw that would keep
// input waiting (over ViewportRenderer::kRefineSliceMs) is drawn in bands of rows: the paint
// draws the first, zero-time timers the others between frames without presenting anything, and
// the paint after the last shows the draw.

#include "render/GLInfo.h"
#include "ui/viewport/ViewportRenderer.h"

#include <QOpenGLWidget>
#include <QPointF>
#include <QString>
#include <QTimer>

#include <cstdint>
#include <memory>

namespace facet {

class MapUploadScheduler;
class SceneController;
class ViewShareGroup;

class ViewportWidget : public QOpenGLWidget {
    Q_OBJECT
public:
    // The empty viewport's colour (no scene, or a frame that failed), the same in R, G and B.
    static constexpr float kClearGrey = 0.18f;
    // Resolution scale of interactive frames: a quarter of the pixels (llvmpipe: ~30 ms at 720p
    // instead of ~110 ms).
    static constexpr double kPreviewScale = 0.5;
    // How long after the last interactive change the full-resolution frame is drawn.
    static constexpr int kRefineDelayMs = 250;

    explicit ViewportWidget(QWidget* parent = nullptr);
    ~ViewportWidget() override;

    // The scene to draw; the widget redraws when it changes. Without one it shows kClearGrey.
    void setSceneController(SceneController* scene);
    // The window's views share their IBL results and material textures (ui/viewport/ViewShareGroup.h).
    // Set before the widget is first shown; without one the view has resources of its own.
    void setShareGroup(std::shared_ptr<ViewShareGroup> group) { m_shareGroup = std::move(group); }
    SceneController* sceneController() const { return m_scene; }

    // The view's own additions to the project's scene (ui/viewport/ViewState.h): the live
    // turntable's angles (CameraController turns them) and View > Wireframe. A change redraws
    // (the turntable's as an interactive change: previews while it runs).
    const ViewState& viewState() const { return m_view; }
    void setTurntableAngles(double objectDegrees, double environmentDegrees);
    void setWireframe(bool on);
    // The matrix the mesh is drawn with (the object turntable's rotation); picking casts under it.
    glm::dmat4 modelMatrix() const { return m_view.modelMatrix(); }

    // What the widget's context is; valid once glInitialized() was emitted.
    const GLInfo& glInfo() const { return m_glInfo; }
    // Why the context is not good enough for Facet (below 4.1 core); empty when it is.
    const QString& glProblem() const { return m_glProblem; }

    // Frames drawn with the renderer since the context was made (the idle test counts them).
    std::uint64_t frameCount() const { return m_stats.frameNumber; }
    const ViewportFrameStats& lastFrameStats() const { return m_stats; }
    // The refinement as it stands now, bands drawn between frames included (lastFrameStats() is
    // the shown frame's).
    const FrameRenderer::Refinement& refinementNow() const
    {
        return m_renderer ? m_renderer->lastFrame().refinement : m_stats.refinement;
    }
    // Frames drawn with the previous lighting (or none) while the lighting worker made the new
    // one; frameRendered() is not emitted for them.
    std::uint64_t framesAwaitingLighting() const { return m_framesAwaitingLighting; }
    // Why the last frame failed; empty after a good frame.
    const QString& lastError() const { return m_lastError; }

    // An interaction is under way (camera drag, slider drag, turntable): draw the coming frames
    // at kPreviewScale and refine kRefineDelayMs after the last call. Also requests a frame.
    void markInteractive();
    bool isPreviewing() const { return m_previewing; }
    // What puts material maps on the GPU between frames.
    const MapUploadScheduler* mapUploads() const { return m_uploads; }

    // What the view shows, rendered again as a still at its full device size (File > Save
    // Image; ViewportRenderer::renderStill). nullopt with *error before the first frame.
    // `size` empty: the view's own device size; else that many pixels (at most kMaxStillSide a
    // side), rendered offscreen. `options`: transparent background, a turntable's turn.
    std::optional<Image> renderStill(
        FrameOutput output, std::string* error, QSize size = {}, const StillOptions& options = {});

    // What the view shows at `position` (widget coordinates in logical pixels): the shown frame's
    // linear radiance and the 8-bit value on screen (ViewportRenderer::shownPixel); both empty
    // before the first frame or outside the widget.
    ViewportRenderer::ShownPixel shownPixel(const QPointF& position);

    // The view's size in device pixels (what a still of the view's own size has).
    QSize deviceSize() const;
    QSize sizeHint() const override;

Q_SIGNALS:
    // The context exists and glInfo() describes it (emitted from initializeGL, context current).
    void glInitialized();
    // A frame was drawn (stats in lastFrameStats()), or failed (lastError() says why).
    void frameRendered();
    // The next frame runs the IBL precompute for `environmentName` (a few hundred ms on llvmpipe
    // the first time; the disk cache makes the next start fast).
    void iblPrecomputeStarting(const QString& environmentName);
    // The precompute, on the lighting worker's thread, is `fraction` (0..1) done.
    void iblPrecomputeProgress(const QString& environmentName, double fraction);
    // The precompute finished in `milliseconds` (0: it came from the cache), and a frame shows it.
    void iblPrecomputeFinished(const QString& environmentName, double milliseconds);

protected:
    void initializeGL() override;
    void paintGL() override;

private:
    void onSceneChanged(bool interactive);
    // The next band of a refinement draw in bands, between frames (nothing presented).
    void drawRefinementBand();
    void requestFrame();
    void releaseRenderer();
    // The lighting worker's signals (ui/viewport/LightingWorker.h) for this view's renderer.
    void connectLightingWorker();

    SceneController* m_scene = nullptr;
    ViewState m_view;
    std::unique_ptr<ViewportRenderer> m_renderer;
    std::shared_ptr<ViewShareGroup> m_shareGroup;
    ViewportFrameStats m_stats;
    GLInfo m_glInfo;
    QString m_glProblem;
    QString m_lastError;
    QTimer m_refineTimer;
    MapUploadScheduler* m_uploads; // map uploads between frames
    bool m_previewing = false;
    bool m_restartRefinement = true; // the scene changed since the refinement began
    bool m_announcedIbl = false;
    std::uint64_t m_framesAwaitingLighting = 0;
};

} // namespace facet
