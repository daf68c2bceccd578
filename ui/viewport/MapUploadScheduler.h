#pragma once
// Puts material maps on the GPU between the viewport's frames, never in one (ui/viewport/ViewportRenderer
// uploadSlice: bands of rows, mipmaps made on the way, about kSliceMs per event-loop turn), so the
// window keeps answering input while a 2K texture set goes up.
//
// A decoded map arriving (SceneController::mapsArrived) queues its upload and draws nothing: the
// frame would look the same until the texture is complete. A frame follows when a texture is
// complete: at once for the last one, at most every kProgressFrameIntervalMs for the others
// (frames drawn while maps load are reduced-resolution previews, ViewportRenderer::kLoadingScale,
// and on llvmpipe still cost ~100 ms each).
//
// Owned by the ViewportWidget, which tells it about frames (frameDrawn) and scenes.

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <functional>

class QOpenGLWidget;

namespace facet {

class SceneController;
class ViewportRenderer;

class MapUploadScheduler : public QObject {
    Q_OBJECT
public:
    static constexpr double kSliceMs = 20.0;
    static constexpr int kProgressFrameIntervalMs = 400;

    // `widget`: whose context the renderer lives in (made current for each slice) and which is
    // asked for frames; `renderer`: the widget's renderer now (null before its context exists).
    MapUploadScheduler(QOpenGLWidget* widget, std::function<ViewportRenderer*()> renderer);

    void setSceneController(const SceneController* scene);
    // A frame was drawn: it may have queued uploads.
    void frameDrawn();
    // Maps arrived in the scene (decoded): queue what they need on the GPU.
    void mapsArrived();

    // Slices run so far, and the longest (benchmarks, tests).
    int slices() const { return m_slices; }
    double longestSliceMs() const { return m_longestSliceMs; }

private:
    void slice();
    void requestFrame(bool last);

    QOpenGLWidget* m_widget;
    std::function<ViewportRenderer*()> m_renderer;
    const SceneController* m_scene = nullptr;
    QTimer m_sliceTimer; // the next slice, when the event loop is free
    QTimer m_progressTimer; // a deferred progress frame
    QElapsedTimer m_sinceFrame;
    bool m_queueArrivals = false;
    int m_slices = 0;
    double m_longestSliceMs = 0.0;
};

} // namespace facet
