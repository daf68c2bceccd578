#include "ui/viewport/MapUploadScheduler.h"

#include "ui/viewport/SceneController.h"
#include "ui/viewport/ViewportRenderer.h"

#include <QOpenGLWidget>

#include <algorithm>

namespace facet {

MapUploadScheduler::MapUploadScheduler(QOpenGLWidget* widget, std::function<ViewportRenderer*()> renderer)
    : QObject(widget)
    , m_widget(widget)
    , m_renderer(std::move(renderer))
{
    m_sliceTimer.setSingleShot(true);
    m_sliceTimer.setInterval(0);
    connect(&m_sliceTimer, &QTimer::timeout, this, &MapUploadScheduler::slice);
    m_progressTimer.setSingleShot(true);
    connect(&m_progressTimer, &QTimer::timeout, m_widget, qOverload<>(&QOpenGLWidget::update));
    m_sinceFrame.start();
}

void MapUploadScheduler::setSceneController(const SceneController* scene)
{
    m_scene = scene;
}

void MapUploadScheduler::frameDrawn()
{
    m_sinceFrame.start();
    m_progressTimer.stop();
    ViewportRenderer* renderer = m_renderer();
    if (renderer && renderer->hasPendingUploads())
        m_sliceTimer.start();
}

void MapUploadScheduler::mapsArrived()
{
    m_queueArrivals = true;
    m_sliceTimer.start();
}

void MapUploadScheduler::requestFrame(bool last)
{
    const qint64 since = m_sinceFrame.elapsed();
    if (last || since >= kProgressFrameIntervalMs) {
        m_progressTimer.stop();
        m_widget->update();
    } else if (!m_progressTimer.isActive()) {
        m_progressTimer.start(int(kProgressFrameIntervalMs - since));
    }
}

void MapUploadScheduler::slice()
{
    ViewportRenderer* renderer = m_renderer();
    if (!renderer || !m_scene)
        return;
    m_widget->makeCurrent();
    const bool arrival = m_queueArrivals;
    m_queueArrivals = false;
    // Maps that arrived and are not on the GPU yet (a file seen before may be there already).
    const int waiting = arrival ? renderer->queueUploads(*m_scene) : 0;
    ViewportRenderer::UploadProgress progress;
    if (renderer->hasPendingUploads()) {
        progress = renderer->uploadSlice(kSliceMs);
        ++m_slices;
        m_longestSliceMs = std::max(m_longestSliceMs, progress.milliseconds);
    }
    m_widget->doneCurrent();
    const bool loading = progress.pending > 0 || m_scene->pendingMapLoads() > 0;
    // A frame for a texture complete, or for maps that arrived with their textures there already.
    if (progress.completed > 0 || (arrival && waiting == 0))
        requestFrame(!loading);
    if (progress.pending > 0)
        m_sliceTimer.start();
}

} // namespace facet
