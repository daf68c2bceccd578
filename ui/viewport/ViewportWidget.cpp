#include "ui/viewport/ViewportWidget.h"

#include "ui/viewport/LightingWorker.h"
#include "ui/viewport/MapUploadScheduler.h"
#include "ui/viewport/SceneController.h"
#include "ui/viewport/ViewShareGroup.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions>

#include <cmath>
#include <utility>

namespace facet {

ViewportWidget::ViewportWidget(QWidget* parent)
    : QOpenGLWidget(parent)
    , m_uploads(new MapUploadScheduler(this, [this] { return m_renderer.get(); }))
{
    setObjectName(QStringLiteral("viewport"));
    setMinimumSize(160, 120);
    setFocusPolicy(Qt::StrongFocus); // WASD and the camera keys
    m_refineTimer.setSingleShot(true);
    m_refineTimer.setInterval(kRefineDelayMs);
    connect(&m_refineTimer, &QTimer::timeout, this, [this] {
        m_previewing = false;
        update();
    });
}

ViewportWidget::~ViewportWidget()
{
    releaseRenderer();
    // QOpenGLWidget's destructor destroys the context after this object's part is gone: the
    // context's aboutToBeDestroyed must no longer reach a slot of this class by then.
    if (QOpenGLContext* glContext = context())
        disconnect(glContext, nullptr, this, nullptr);
}

void ViewportWidget::releaseRenderer()
{
    if (!m_renderer)
        return;
    makeCurrent();
    m_renderer.reset();
    doneCurrent();
}

void ViewportWidget::connectLightingWorker()
{
    LightingWorker* worker = m_renderer ? m_renderer->lightingWorker().get() : nullptr;
    if (!worker)
        return;
    // The renderer holds the worker: a signal queued before the renderer went finds none.
    connect(worker, &LightingWorker::finished, this, [this, worker](quint64 key) {
        if (!m_renderer || m_renderer->lightingWorker().get() != worker)
            return;
        makeCurrent(); // a set already held is dropped here: its textures go in the group
        const bool mine = m_renderer->lightingFinished(key);
        doneCurrent();
        if (mine)
            update();
    });
    connect(worker, &LightingWorker::progress, this, [this, worker](quint64 key, double fraction) {
        if (m_renderer && m_renderer->lightingWorker().get() == worker && m_scene
            && m_renderer->pendingLighting() == key)
            Q_EMIT iblPrecomputeProgress(m_scene->environmentName(), fraction);
    });
}

std::optional<Image> ViewportWidget::renderStill(
    FrameOutput output, std::string* error, QSize size, const StillOptions& options)
{
    if (!m_renderer || !m_scene || m_stats.frameNumber == 0) {
        *error = "the view has not drawn yet";
        return std::nullopt;
    }
    if (size.isEmpty())
        size = deviceSize();
    if (size.width() > kMaxStillSide || size.height() > kMaxStillSide) {
        *error = QStringLiteral("%1x%2 pixels is larger than the largest still, %3 a side")
                     .arg(size.width())
                     .arg(size.height())
                     .arg(kMaxStillSide)
                     .toStdString();
        return std::nullopt;
    }
    makeCurrent();
    std::optional<Image> image
        = m_renderer->renderStill(*m_scene, size.width(), size.height(), output, error, options);
    doneCurrent();
    // The still may have used the target the view's frame is held in: draw it again, so that what
    // the value picker reads is what the view shows.
    update();
    return image;
}

void ViewportWidget::drawRefinementBand()
{
    // An interaction or a change since: its frame comes through paintGL (which restarts the
    // refinement when the change needs it).
    if (!m_renderer || !m_scene || m_previewing || !isVisible())
        return;
    const QSize size = deviceSize();
    std::string error;
    makeCurrent();
    const bool more = m_renderer->continueRefinement(*m_scene, size.width(), size.height(), &error);
    doneCurrent();
    // lastFrameStats() stays the shown frame's: the draw is shown by the next paint.
    if (more)
        QTimer::singleShot(0, this, &ViewportWidget::drawRefinementBand);
    else
        update(); // the draw is complete (or the scene changed): the next frame shows it
}

ViewportRenderer::ShownPixel ViewportWidget::shownPixel(const QPointF& position)
{
    if (!m_renderer || m_stats.frameNumber == 0)
        return {};
    const qreal ratio = devicePixelRatioF();
    const QSize size = deviceSize();
    makeCurrent();
    ViewportRenderer::ShownPixel pixel = m_renderer->shownPixel(defaultFramebufferObject(), size.width(),
        size.height(), int(std::floor(position.x() * ratio)), int(std::floor(position.y() * ratio)));
    doneCurrent();
    return pixel;
}

QSize ViewportWidget::deviceSize() const
{
    const qreal ratio = devicePixelRatioF();
    return {std::max(1, int(width() * ratio)), std::max(1, int(height() * ratio))};
}

QSize ViewportWidget::sizeHint() const
{
    return {960, 640};
}

void ViewportWidget::setSceneController(SceneController* scene)
{
    if (m_scene) {
        disconnect(m_scene, nullptr, this, nullptr);
        disconnect(m_scene, nullptr, m_uploads, nullptr);
    }
    m_scene = scene;
    m_uploads->setSceneController(scene);
    m_restartRefinement = true;
    if (m_scene) {
        connect(m_scene, &SceneController::sceneChanged, this, &ViewportWidget::onSceneChanged);
        connect(m_scene, &SceneController::mapsArrived, m_uploads, &MapUploadScheduler::mapsArrived);
    }
    requestFrame();
}

void ViewportWidget::setTurntableAngles(double objectDegrees, double environmentDegrees)
{
    if (objectDegrees == m_view.objectTurntableDegrees
        && environmentDegrees == m_view.environmentTurntableDegrees)
        return;
    m_view.objectTurntableDegrees = objectDegrees;
    m_view.environmentTurntableDegrees = environmentDegrees;
    if (m_renderer)
        m_renderer->setViewState(m_view);
    onSceneChanged(true);
}

void ViewportWidget::setWireframe(bool on)
{
    if (on == m_view.wireframe)
        return;
    m_view.wireframe = on;
    if (m_renderer)
        m_renderer->setViewState(m_view);
    onSceneChanged(false);
}

void ViewportWidget::onSceneChanged(bool interactive)
{
    // A change of how the refined frame is shown only (exposure, tone mapper, OCIO, a name)
    // keeps its samples: the next refine() shows them anew, with no preview even while a slider
    // drags. Any other change previews while interactive and restarts the refinement; the
    // renderer also restarts by itself when what it sums differs (ViewportRenderer::refine).
    if (m_renderer && m_scene && !m_previewing) {
        const qreal ratio = devicePixelRatioF();
        if (m_renderer->refinesSameSamples(*m_scene, int(width() * ratio), int(height() * ratio))) {
            requestFrame();
            return;
        }
    }
    m_restartRefinement = true;
    if (interactive)
        markInteractive();
    else
        requestFrame();
}

void ViewportWidget::markInteractive()
{
    m_previewing = true;
    m_restartRefinement = true;
    m_refineTimer.start();
    requestFrame();
}

void ViewportWidget::requestFrame()
{
    if (m_scene && m_renderer && m_scene->hasScene() && !m_announcedIbl && m_renderer->needsIbl(*m_scene)) {
        m_announcedIbl = true;
        Q_EMIT iblPrecomputeStarting(m_scene->environmentName());
    }
    update();
}

void ViewportWidget::initializeGL()
{
    // render/ resolves GL through libepoxy for whichever context is current, Qt's included.
    m_glInfo = queryCurrentGLInfo();
    m_glProblem.clear();
    if (!m_glInfo.isValid())
        m_glProblem = tr("no OpenGL context");
    else if (!m_glInfo.atLeast(4, 1) || !m_glInfo.coreProfile)
        m_glProblem = m_glInfo.coreProfile ? tr("Facet needs OpenGL 4.1 core")
                                           : tr("Facet needs OpenGL 4.1 core, not a compatibility profile");
    // A context can be replaced (re-parenting, a dock torn off): drop the renderer with the old one.
    m_renderer.reset();
    if (m_glProblem.isEmpty()) {
        // A view made without a window's group (a test's lone widget) has one of its own.
        if (!m_shareGroup)
            m_shareGroup = std::make_shared<ViewShareGroup>();
        ViewShareGroup::Resources shared = m_shareGroup->acquire();
        m_renderer
            = std::make_unique<ViewportRenderer>(std::move(shared.precompute), std::move(shared.textures));
        m_renderer->setLightingWorker(std::move(shared.lighting));
        m_renderer->setViewState(m_view);
        connectLightingWorker();
    }
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &ViewportWidget::releaseRenderer,
        Qt::UniqueConnection);
    Q_EMIT glInitialized();
    if (m_scene && m_renderer && m_scene->hasScene() && m_renderer->needsIbl(*m_scene)) {
        m_announcedIbl = true;
        Q_EMIT iblPrecomputeStarting(m_scene->environmentName());
    }
}

void ViewportWidget::paintGL()
{
    // Before the project's first environment and mesh files arrive (ui/viewport/SceneController loads them
    // off the GUI thread) there is nothing to light: the clear grey, and the status bar says what
    // is loading.
    if (!m_scene || !m_renderer || !m_scene->hasScene()) {
        QOpenGLFunctions* gl = context()->functions();
        gl->glClearColor(kClearGrey, kClearGrey, kClearGrey, 1.0f);
        gl->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        return;
    }
    const qreal ratio = devicePixelRatioF();
    std::string error;
    // The still frame refines by the project's method (docs/rendering.md "Refinement"): not while
    // an interaction previews, nor while a texture set is still arriving (those frames are
    // previews too); any change of the scene starts it again.
    // Nor before the view has the environment's lighting: a frame takes it up first (from
    // memory, or asking the lighting worker), and the refinement starts after it.
    // Nor before the environment's pixels are decoded (it came from the environment index): the
    // sampled methods read them, and they arrive with a scene change.
    const bool wantsRefinement = !m_previewing && m_scene->refinementMethod() != IblMethod::SplitSum
        && m_scene->pendingMapLoads() == 0 && !m_renderer->hasPendingUploads()
        && m_scene->assets().environment.decoded();
    const bool neededIbl = m_renderer->needsIbl(*m_scene);
    const bool refining = wantsRefinement && !neededIbl;
    bool ok = false;
    if (refining) {
        ok = m_renderer->refine(*m_scene, defaultFramebufferObject(), int(width() * ratio),
            int(height() * ratio), std::exchange(m_restartRefinement, false), &error);
    } else {
        ok = m_renderer->paint(*m_scene, defaultFramebufferObject(), int(width() * ratio),
            int(height() * ratio), m_previewing ? kPreviewScale : 1.0, &error);
        m_restartRefinement = true;
    }
    m_stats = m_renderer->lastFrame();
    // The next draw of the refinement, after the events queued meanwhile (input stops it); once
    // done, nothing more is drawn until the scene changes. A draw in bands has its other bands
    // drawn between frames first (drawRefinementBands), each after the events queued meanwhile.
    if (ok && refining && m_stats.refinement.bandsDrawn > 0)
        QTimer::singleShot(0, this, &ViewportWidget::drawRefinementBand);
    else if (ok
        && ((refining && !m_stats.refinement.done())
            || (wantsRefinement && !refining && !m_stats.lightingPending)))
        QTimer::singleShot(0, this, [this] { update(); });
    m_lastError = ok ? QString() : QString::fromStdString(error);
    m_uploads->frameDrawn(); // maps the frame could not show yet go up between frames
    // Memory: once a frame shows every map from the GPU, the decoded copies go; a released map
    // needed again (a new context, another colour space) is decoded again, off this paint.
    if (std::vector<std::string> reload = m_renderer->takeReleasedMapsNeeded(); !reload.empty()) {
        QTimer::singleShot(0, m_scene, [scene = m_scene, reload] { scene->reloadMaps(reload); });
    } else if (ok && !m_stats.loadingMaps && m_stats.mapsHeldBack == 0 && m_stats.textureProblem.empty()) {
        ViewportRenderer* renderer = m_renderer.get();
        m_scene->releaseMapPixels(
            [renderer](const std::string& path, std::int64_t timestamp, ColorEncoding space) {
                return renderer->textureReady(path, timestamp, space);
            });
    }
    if (m_stats.lightingPending) {
        ++m_framesAwaitingLighting;
        // The lighting is made on the worker: this frame shows the previous one, and the frame
        // that shows the new one is announced (the tests wait for frames of the scene as it is).
        if (!m_announcedIbl) {
            m_announcedIbl = true;
            Q_EMIT iblPrecomputeStarting(m_scene->environmentName());
        }
        return;
    }
    if ((m_announcedIbl || neededIbl) && !m_renderer->needsIbl(*m_scene)) {
        m_announcedIbl = false;
        Q_EMIT iblPrecomputeFinished(m_scene->environmentName(), m_stats.iblMs);
    }
    Q_EMIT frameRendered();
}

} // namespace facet
