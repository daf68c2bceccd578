#include "ui/compare/CompareView.h"

#include "core/project/ProjectAssets.h"
#include "ui/compare/CompareController.h"
#include "ui/document/Document.h"
#include "ui/document/DocumentAssets.h"
#include "ui/viewport/CameraController.h"
#include "ui/viewport/LightingWorker.h"
#include "ui/viewport/SceneController.h"
#include "ui/viewport/ViewShareGroup.h"

#include <QContextMenuEvent>
#include <QDataStream>
#include <QDragEnterEvent>
#include <QLabel>
#include <QMenu>
#include <QMimeData>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

namespace facet {

CompareView::CompareView(
    Document* document, SceneController* scene, CompareController* controller, QWidget* parent)
    : QOpenGLWidget(parent)
    , m_document(document)
    , m_scene(scene)
    , m_controller(controller)
    , m_assets(scene->documentAssets())
    , m_assetsAlive(m_assets)
    , m_divider(new QWidget(this))
{
    setObjectName(QStringLiteral("compareView"));
    setMinimumSize(160, 120);
    setFocusPolicy(Qt::StrongFocus);
    setAcceptDrops(true);
    m_divider->setObjectName(QStringLiteral("compareDivider"));
    m_divider->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_divider->setAutoFillBackground(true);
    m_divider->setStyleSheet(QStringLiteral("background: rgba(255, 255, 255, 200);"));
    m_divider->hide();
    m_refineTimer.setSingleShot(true);
    m_refineTimer.setInterval(kRefineDelayMs);
    connect(&m_refineTimer, &QTimer::timeout, this, [this] {
        m_previewing = false;
        update();
    });
    connect(m_document, &Document::changed, this, [this] {
        if (!isVisible())
            return;
        rebuild();
        if (m_document->interactiveEditOpen())
            markInteractive();
        else
            update();
    });
    // The mesh and the maps come from the single view's controller (loaded once for both).
    connect(m_scene, &SceneController::sceneChanged, this, [this] {
        if (isVisible())
            update();
    });
    connect(m_scene, &SceneController::mapsArrived, this, [this] {
        if (isVisible())
            update();
    });
    connect(m_assets, &DocumentAssets::assetArrived, this, [this] {
        layoutOverlays(); // "Loading …" labels become names
        update();
    });
}

CompareView::~CompareView()
{
    if (!m_assetsAlive.isNull())
        m_assets->forgetUser(this);
    releaseRenderer();
    // QOpenGLWidget's destructor destroys the context after this object's part is gone: the
    // context's aboutToBeDestroyed must no longer reach a slot of this class by then.
    if (QOpenGLContext* glContext = context())
        disconnect(glContext, nullptr, this, nullptr);
}

void CompareView::releaseRenderer()
{
    if (!m_renderer && !m_lightingWorker)
        return;
    makeCurrent();
    // The worker first: its thread frees what it made in its own context; the sets asked of it
    // are forgotten (a new renderer asks again).
    m_lightingWorker.reset();
    m_lightingAsked.clear();
    m_lightingFailed.clear();
    m_lightingBatch = 0;
    m_lightingBatchMs = 0.0;
    m_renderer.reset();
    doneCurrent();
}

void CompareView::setUseDiskCache(bool use)
{
    m_useDiskCache = use;
    if (m_shareGroup)
        m_shareGroup->setUseDiskCache(use);
}

void CompareView::initializeGL()
{
    m_renderer.reset();
    const GLInfo info = queryCurrentGLInfo();
    if (!info.isValid() || !info.atLeast(4, 1) || !info.coreProfile) {
        // No renderer: paintGL shows the failure grey.
    } else if (m_shareGroup) {
        ViewShareGroup::Resources shared = m_shareGroup->acquire();
        m_renderer
            = std::make_unique<CompareRenderer>(std::move(shared.precompute), std::move(shared.textures));
    } else {
        m_renderer = std::make_unique<CompareRenderer>(QString(), m_useDiskCache);
    }
    m_lightingWorker.reset();
    m_lightingAsked.clear();
    m_lightingBatch = 0;
    m_lightingBatchMs = 0.0;
    if (m_renderer) {
        // Its own worker, not the single view's: that one's requests replace each other (newest
        // wins), a grid's sets are all wanted.
        auto worker = std::make_shared<LightingWorker>(
            QString(), m_shareGroup ? m_shareGroup->useDiskCache() : m_useDiskCache);
        if (worker->isValid()) {
            // The view holds the worker: a signal queued before it went finds none.
            connect(worker.get(), &LightingWorker::finished, this, [this, w = worker.get()](quint64 key) {
                if (m_lightingWorker.get() == w)
                    lightingArrived(key);
            });
            m_lightingWorker = std::move(worker);
        }
    }
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &CompareView::releaseRenderer,
        Qt::UniqueConnection);
}

void CompareView::showEvent(QShowEvent* event)
{
    QOpenGLWidget::showEvent(event);
    rebuild();
    update();
}

void CompareView::resizeEvent(QResizeEvent* event)
{
    QOpenGLWidget::resizeEvent(event);
    layoutOverlays();
}

void CompareView::markInteractive()
{
    m_previewing = true;
    m_refineTimer.start();
    update();
}

bool CompareView::isLoading() const
{
    if (m_lightingAnnounced > 0 || !m_lightingAsked.empty())
        return true;
    for (const CompareCell& cell : m_cells)
        if (m_assets->isLoading(DocumentAssets::Kind::Environment, cell.project.environment.source))
            return true;
    return m_assets->pendingLoads() > 0;
}

void CompareView::rebuild()
{
    m_cells = compareCells(m_document->project());
    std::set<std::string> environments;
    std::set<std::string> maps;
    for (const CompareCell& cell : m_cells) {
        environments.insert(cell.project.environment.source);
        for (const Material& material : cell.project.materials)
            for (MapSlot slot : kAllMapSlots)
                if (!material.map(slot).path.empty())
                    maps.insert(material.map(slot).path);
    }
    // What the cells show stays in the document's cache; what no view shows goes.
    m_assets->setInUse(this, DocumentAssets::Kind::Environment, std::move(environments));
    m_assets->setInUse(this, DocumentAssets::Kind::Map, std::move(maps));
    layoutOverlays();
}

QRect CompareView::cellRectOf(std::size_t cell) const
{
    if (cell >= m_cells.size())
        return {};
    const Project& project = m_document->project();
    return cellRect(size(), gridShapeOf(project), m_cells[cell].row, m_cells[cell].column, kGapPixels,
        axisMargins(project));
}

int CompareView::dividerX() const
{
    const CompareLayout& layout = m_document->project().compare;
    if (layout.mode != CompareMode::AB || layout.ab.layout != ABLayout::Split || m_cells.empty())
        return -1;
    const QRect rect = cellRectOf(0);
    return rect.left() + int(std::lround(layout.ab.split * rect.width()));
}

int CompareView::cellAt(const QPoint& position) const
{
    const int divider = dividerX();
    for (std::size_t i = 0; i < m_cells.size(); ++i) {
        if (!cellRectOf(i).contains(position))
            continue;
        if (divider >= 0)
            return position.x() < divider ? 0 : 1;
        return int(i);
    }
    return -1;
}

QString CompareView::labelOf(std::size_t cell) const
{
    return int(cell) < m_cellLabelCount && cell < std::size_t(m_labelTexts.size()) ? m_labelTexts[int(cell)]
                                                                                   : QString();
}

QStringList CompareView::axisLabels() const
{
    return m_labelTexts.mid(m_cellLabelCount);
}

QLabel* CompareView::overlayLabel(int index)
{
    while (int(m_labels.size()) <= index) {
        auto* label = new QLabel(this);
        label->setObjectName(QStringLiteral("compareLabel"));
        label->setAttribute(Qt::WA_TransparentForMouseEvents);
        label->setStyleSheet(QStringLiteral("QLabel { background: rgba(0, 0, 0, 150); color: white; padding: "
                                            "1px 5px; border-radius: 3px; }"));
        m_labels.push_back(label);
    }
    return m_labels[std::size_t(index)];
}

void CompareView::layoutOverlays()
{
    const Project& project = m_document->project();
    const CompareMode mode = project.compare.mode;
    m_labelTexts.clear();
    std::vector<QRect> places; // where each label goes: top-left corner (or right-aligned for B)
    std::vector<Qt::Alignment> alignments;
    for (std::size_t i = 0; i < m_cells.size(); ++i) {
        const CompareCell& cell = m_cells[i];
        QString text = cellLabel(i);
        const std::string& source = cell.project.environment.source;
        if (m_assets->isLoading(DocumentAssets::Kind::Environment, source))
            text = tr("Loading %1…").arg(environmentLabel(source));
        else if (!m_assets->problem(DocumentAssets::Kind::Environment, source).empty())
            text = tr("%1 cannot be loaded").arg(environmentLabel(source));
        else if (mode == CompareMode::Wedge)
            text.clear(); // the values are on the axes
        m_labelTexts.append(text);
        places.push_back(cellRectOf(i));
        alignments.push_back(
            cell.role == CompareCell::Role::B && dividerX() >= 0 ? Qt::AlignRight : Qt::AlignLeft);
    }
    m_cellLabelCount = int(m_labelTexts.size());
    if (mode == CompareMode::Wedge) {
        // The rows' values left of the grid, the columns' above it.
        const WedgeLayout& wedge = project.compare.wedge;
        const GridShape shape = gridShapeOf(project);
        const QSize margins = axisMargins(project);
        for (std::size_t r = 0; r < wedge.rowCount(); ++r) {
            const QRect rect = cellRect(size(), shape, int(r), 0, kGapPixels, margins);
            m_labelTexts.append(QString::fromStdString(wedge.rows.label(r)));
            places.push_back(QRect(0, rect.center().y() - 10, margins.width() - 4, 20));
            alignments.push_back(Qt::AlignRight);
        }
        if (wedge.columns)
            for (std::size_t c = 0; c < wedge.columnCount(); ++c) {
                const QRect rect = cellRect(size(), shape, 0, int(c), kGapPixels, margins);
                m_labelTexts.append(QString::fromStdString(wedge.columns->label(c)));
                places.push_back(QRect(rect.left(), 0, rect.width(), margins.height()));
                alignments.push_back(Qt::AlignHCenter);
            }
    }
    for (int i = 0; i < int(m_labelTexts.size()); ++i) {
        QLabel* label = overlayLabel(i);
        const QString& text = m_labelTexts[i];
        label->setText(text);
        label->setVisible(!text.isEmpty() && mode != CompareMode::Single);
        label->adjustSize();
        const QRect& place = places[std::size_t(i)];
        const bool axis = i >= m_cellLabelCount;
        int x = place.left() + (axis ? 0 : 6);
        if (alignments[std::size_t(i)] & Qt::AlignRight)
            x = place.right() - label->width() - (axis ? 0 : 6);
        else if (alignments[std::size_t(i)] & Qt::AlignHCenter)
            x = place.center().x() - label->width() / 2;
        const int y = axis ? place.center().y() - label->height() / 2 : place.top() + 6;
        label->move(x, y);
        label->raise();
    }
    for (std::size_t i = std::size_t(m_labelTexts.size()); i < m_labels.size(); ++i)
        m_labels[i]->hide();
    const int divider = dividerX();
    m_divider->setVisible(divider >= 0);
    if (divider >= 0) {
        const QRect rect = cellRectOf(0);
        m_divider->setGeometry(divider, rect.top(), 1, rect.height());
        m_divider->raise();
    }
}

std::vector<CompareCellDraw> CompareView::cellDraws()
{
    // The mesh, the environments and the maps come from the document's asset cache, shared with
    // the single view (each file decoded once for both views), and are assembled as the single
    // view's are (core/project/ProjectAssets.h). A map whose pixels the single view released after
    // upload (a stand-in) is drawn from the texture both views share (ui/viewport/ViewShareGroup)
    // while that texture is there; when it is not (evicted, or a context of its own) the cache
    // decodes the file again and the slot shows its factor until it arrives.
    const ProjectAssets& shared = m_scene->assets();
    const auto mapOf = [this](std::size_t, MapSlot, const MaterialMap& source) -> LoadedMapImage {
        LoadedMapImage map {m_assets->map(source.path), source.path, m_assets->mapTimestamp(source.path)};
        if (!map.image || map.image->hasPixels()
            || (m_renderer && m_renderer->textureReady(map.path, map.timestamp, source.colorSpace)))
            return map.image ? map : LoadedMapImage {};
        m_assets->reload(DocumentAssets::Kind::Map, source.path);
        m_assets->map(source.path);
        return {};
    };

    const qreal ratio = devicePixelRatioF();
    const int heightPixels = int(std::lround(height() * ratio));
    const int divider = dividerX();
    std::vector<CompareCellDraw> draws;
    draws.reserve(m_cells.size());
    for (std::size_t i = 0; i < m_cells.size(); ++i) {
        const CompareCell& cell = m_cells[i];
        CompareCellDraw draw;
        draw.project = cell.project;
        draw.project.compare = CompareLayout {}; // not drawn: a layout edit must not redraw every cell
        switch (cell.role) {
        case CompareCell::Role::Reference:
            draw.kind = CompareCellDraw::Kind::Reference;
            draw.project.compare.error = cell.project.compare.error; // what the heat map shows
            break;
        case CompareCell::Role::Error:
            draw.kind = CompareCellDraw::Kind::Error;
            draw.project.compare.error = cell.project.compare.error;
            break;
        default:
            break;
        }
        draw.assets.mesh = shared.mesh;
        draw.assets.meshKey = shared.meshKey;
        // No mesh yet (the project's first mesh file is loading): the cell waits, as for its
        // environment.
        if (const auto environment
            = shared.mesh ? m_assets->environment(cell.project.environment.source) : nullptr) {
            draw.assets.environment = *environment;
            placeEnvironment(draw.assets.environment, cell.project.environment);
        }
        assignMaps(draw.assets, cell.project, mapOf);
        const QRect rect = cellRectOf(i);
        const int left = int(std::lround(rect.left() * ratio));
        const int right = int(std::lround((rect.right() + 1) * ratio));
        const int top = int(std::lround(rect.top() * ratio));
        const int bottom = int(std::lround((rect.bottom() + 1) * ratio));
        draw.rect = FrameRect {left, heightPixels - bottom, right - left, bottom - top};
        // A cell taller than wide (a 2x1 grid, side by side) would cut off the sides of what the
        // camera frames for a square: back it off by what framing needs for the cell's shape
        // (core/project/Camera framingDistance), so a dolly keeps its proportion in every cell.
        if (draw.rect.width < draw.rect.height && draw.rect.height > 0) {
            Camera& camera = draw.project.camera;
            const double square = camera.framingDistance(1.0, 1.0);
            const double tall = camera.framingDistance(1.0, double(draw.rect.width) / draw.rect.height);
            if (square > 0.0 && tall > square)
                camera.position = camera.target + (camera.position - camera.target) * (tall / square);
        }
        if (divider >= 0) {
            // A left of the divider, B from it on: two halves of images of one size and camera.
            const int split = int(std::lround(divider * ratio));
            if (cell.role == CompareCell::Role::A)
                draw.clip = FrameRect {left, draw.rect.y, split - left, draw.rect.height};
            else
                draw.clip = FrameRect {split, draw.rect.y, right - split, draw.rect.height};
        }
        draws.push_back(std::move(draw));
    }
    if (m_document->project().compare.mode == CompareMode::Error && !draws.empty()) {
        // One size for the error view's three images (a grid's cells may differ by a pixel): the
        // heat map is a pixel-for-pixel function of the other two. Top-left corners stay.
        int width = draws.front().rect.width;
        int height = draws.front().rect.height;
        for (const CompareCellDraw& draw : draws) {
            width = std::min(width, draw.rect.width);
            height = std::min(height, draw.rect.height);
        }
        for (CompareCellDraw& draw : draws) {
            draw.rect.y += draw.rect.height - height;
            draw.rect.width = width;
            draw.rect.height = height;
        }
    }
    return draws;
}

void CompareView::askForLighting(std::vector<CompareCellDraw>& draws)
{
    int added = 0;
    for (CompareCellDraw& draw : draws) {
        if (!m_renderer->needsLighting(draw))
            continue;
        const IblSettings settings = CompareRenderer::lightingSettingsOf(draw);
        const std::uint64_t key = IblPrecompute::cacheKey(draw.assets.environment, settings);
        if (m_lightingFailed.count(key))
            continue; // prepared in this frame, on this thread, which reports its error
        if (m_lightingAsked.insert(key).second) {
            m_lightingWorker->enqueue(draw.assets.environment, settings);
            ++added;
        }
        draw.assets.environment = Environment {};
    }
    if (added > 0) {
        m_lightingBatch += added;
        Q_EMIT lightingPreparing(m_lightingBatch);
    }
}

void CompareView::lightingArrived(std::uint64_t key)
{
    if (!m_lightingAsked.erase(key))
        return;
    std::optional<LightingWorker::Result> result = m_lightingWorker->take(key);
    if (result) {
        m_lightingBatchMs += result->stats.msTotal;
        makeCurrent(); // a set not adopted is released here, in the share group
        if (result->textures && m_renderer)
            m_renderer->adoptLighting(key, std::move(result->textures), result->stats);
        else if (!result->stats.cancelled)
            m_lightingFailed.insert(key);
        result.reset();
        doneCurrent();
    }
    update(); // lightingReady follows the frame that draws the batch's last set
}

void CompareView::paintGL()
{
    if (!m_renderer || m_cells.empty()) {
        QOpenGLFunctions* gl = context()->functions();
        const float gap = CompareRenderer::displayGrey(CompareRenderer::kGapGrey);
        gl->glClearColor(gap, gap, gap, 1.0f);
        gl->glClear(GL_COLOR_BUFFER_BIT);
        return;
    }
    const qreal ratio = devicePixelRatioF();
    std::vector<CompareCellDraw> draws = cellDraws();
    if (m_lightingWorker)
        askForLighting(draws);
    // Without a worker, lighting to prepare is announced, and prepared in a later frame: a
    // precompute blocks this thread, and the status bar can only show the message once this frame
    // has returned. Until then its cells wait in the loading grey.
    const bool announcing
        = !m_lightingWorker && m_lightingAnnounced == 0 && m_renderer->lightingToPrepare(draws) > 0;
    if (announcing) {
        m_lightingAnnounced = m_renderer->lightingToPrepare(draws);
        for (CompareCellDraw& draw : draws)
            if (m_renderer->needsLighting(draw))
                draw.assets.environment = Environment {};
        QTimer::singleShot(kAnnounceDelayMs, this, [this] { update(); });
        Q_EMIT lightingPreparing(m_lightingAnnounced);
    }
    std::string error;
    const bool ok = m_renderer->paint(draws, defaultFramebufferObject(), int(std::lround(width() * ratio)),
        int(std::lround(height() * ratio)), m_previewing ? kPreviewScale : 1.0, &error);
    m_stats = m_renderer->lastFrame();
    m_lastError = ok ? QString() : QString::fromStdString(error);
    if (!announcing && m_lightingAnnounced > 0)
        Q_EMIT lightingReady(std::exchange(m_lightingAnnounced, 0), m_stats.iblMs);
    if (m_lightingBatch > 0 && m_lightingAsked.empty())
        Q_EMIT lightingReady(std::exchange(m_lightingBatch, 0), std::exchange(m_lightingBatchMs, 0.0));
    updateRefiningLabels();
    // The error view's reference and the cells of a sampled method converge over frames: the
    // next one as soon as the event loop is free (input stays responsive between draws of about
    // ViewportRenderer::kRefineDrawBudgetMs).
    if (ok && m_renderer->isRefining())
        QTimer::singleShot(0, this, [this] {
            if (isVisible())
                update();
        });
    Q_EMIT frameRendered();
}

bool CompareView::isRefining() const
{
    return m_renderer && m_renderer->isRefining();
}

QString CompareView::cellLabel(std::size_t index) const
{
    const CompareCell& cell = m_cells[index];
    if (m_document->project().compare.mode == CompareMode::Error)
        return errorLabel(cell);
    const FrameRenderer::Refinement* refinement = m_renderer ? m_renderer->cellRefinement(index) : nullptr;
    if (!refinement || refinement->target <= 1)
        return cell.label;
    const IblMethod method = cell.project.environment.method;
    QString text = tr("%1 · %2 %3/%4 spp")
                       .arg(cell.label, method == IblMethod::Fis ? tr("FIS") : tr("Reference"))
                       .arg(refinement->samples)
                       .arg(refinement->target);
    if (refinement->noise)
        text += tr(" · noise %1%").arg(*refinement->noise * 100.0, 0, 'f', 2);
    if (refinement->done())
        text += tr(" (done)");
    return text;
}

QString CompareView::errorLabel(const CompareCell& cell) const
{
    if (!m_stats.error)
        return cell.label;
    const ErrorViewStats& error = *m_stats.error;
    const auto percent = [](double value) { return QStringLiteral("%1%").arg(value * 100.0, 0, 'f', 2); };
    if (cell.role == CompareCell::Role::Reference) {
        QString text = tr("Reference · %1/%2 spp · %3 s")
                           .arg(error.samples)
                           .arg(error.target)
                           .arg(error.seconds, 0, 'f', 1);
        if (error.noise)
            text += tr(" · noise %1").arg(percent(*error.noise));
        if (error.done())
            text += tr(" (done)");
        return text;
    }
    if (cell.role != CompareCell::Role::Error)
        return cell.label;
    if (error.showingNoise)
        return error.noise
            ? tr("Reference noise · %1 over the object").arg(percent(*error.noise))
            : tr("Reference noise · measured after %1 samples").arg(FrameRenderer::kRefinementShownAfter);
    if (!error.error)
        return tr("Relative error · measured after %1 samples").arg(FrameRenderer::kRefinementShownAfter);
    if (std::isnan(error.error->relativeRmse))
        return tr("Relative error · no object pixel to measure");
    return tr("Relative error · RMSE %1 over the object (max %2)")
        .arg(percent(error.error->relativeRmse), percent(error.error->maxRelativeError));
}

void CompareView::updateRefiningLabels()
{
    const bool wedge = m_document->project().compare.mode == CompareMode::Wedge; // values on the axes
    for (std::size_t i = 0; !wedge && i < m_cells.size() && int(i) < m_cellLabelCount && i < m_labels.size();
         ++i) {
        const CompareCell& cell = m_cells[i];
        const std::string& source = cell.project.environment.source;
        if (m_assets->isLoading(DocumentAssets::Kind::Environment, source)
            || !m_assets->problem(DocumentAssets::Kind::Environment, source).empty())
            continue; // layoutOverlays' message stands
        const QString text = cellLabel(i);
        if (m_labelTexts[int(i)] == text)
            continue;
        m_labelTexts[int(i)] = text;
        m_labels[i]->setText(text);
        m_labels[i]->adjustSize();
    }
}

void CompareView::moveCamera(int cell, const std::function<Camera(const Camera&)>& move)
{
    if (cell < 0 || std::size_t(cell) >= m_cells.size())
        return;
    const CompareCell& target = m_cells[std::size_t(cell)];
    if (target.role == CompareCell::Role::Grid)
        m_controller->setCellCamera(target.index, move(target.project.camera));
    else
        m_document->setCamera(move(m_document->project().camera)); // A/B and wedge share the camera
    markInteractive();
}

void CompareView::mousePressEvent(QMouseEvent* event)
{
    m_lastMouse = event->position().toPoint();
    if (event->button() != Qt::LeftButton)
        return QOpenGLWidget::mousePressEvent(event);
    const int divider = dividerX();
    if (divider >= 0 && std::abs(m_lastMouse.x() - divider) <= kDividerGrabPixels) {
        m_drag = Drag::Divider;
    } else {
        m_dragCell = cellAt(m_lastMouse);
        m_drag = m_dragCell >= 0 ? Drag::Orbit : Drag::None;
    }
    // One drag, one undo step (the divider, an unlinked cell's camera).
    m_dragOpenedEdit = m_drag != Drag::None && !m_document->interactiveEditOpen();
    if (m_dragOpenedEdit)
        m_document->beginInteractiveEdit();
    event->accept();
}

void CompareView::mouseMoveEvent(QMouseEvent* event)
{
    const QPoint position = event->position().toPoint();
    const QPoint delta = position - m_lastMouse;
    m_lastMouse = position;
    if (m_drag == Drag::Divider) {
        const QRect rect = cellRectOf(0);
        m_controller->setSplit(double(position.x() - rect.left()) / std::max(1, rect.width()));
        markInteractive();
    } else if (m_drag == Drag::Orbit) {
        moveCamera(m_dragCell, [delta](const Camera& camera) {
            return CameraController::orbited(camera, delta.x(), delta.y());
        });
    }
    event->accept();
}

void CompareView::mouseReleaseEvent(QMouseEvent* event)
{
    if (m_dragOpenedEdit)
        m_document->endInteractiveEdit();
    m_dragOpenedEdit = false;
    m_drag = Drag::None;
    m_dragCell = -1;
    event->accept();
}

void CompareView::mouseDoubleClickEvent(QMouseEvent* event)
{
    const int cell = cellAt(event->position().toPoint());
    if (cell >= 0 && m_cells[std::size_t(cell)].role == CompareCell::Role::Grid)
        m_controller->promoteCell(m_cells[std::size_t(cell)].index);
    event->accept();
}

void CompareView::wheelEvent(QWheelEvent* event)
{
    const double steps = event->angleDelta().y() / 120.0;
    const int cell = cellAt(event->position().toPoint());
    if (steps != 0.0 && cell >= 0)
        moveCamera(cell, [steps](const Camera& camera) { return CameraController::dollied(camera, steps); });
    event->accept();
}

void CompareView::contextMenuEvent(QContextMenuEvent* event)
{
    const int cell = cellAt(event->pos());
    if (cell < 0)
        return;
    QMenu menu(this);
    menu.setObjectName(QStringLiteral("compareCellMenu"));
    CompareMenus::fill(menu, *m_controller, m_document->project(), m_cells[std::size_t(cell)],
        m_choices ? m_choices() : EnvironmentChoices {}, this);
    if (!menu.isEmpty())
        menu.exec(event->globalPos());
}

QString CompareView::droppedSource(const QMimeData* mime)
{
    // QAbstractItemModel's drag format: per item its row, column and roles; the Environment
    // dock keeps each entry's source in Qt::UserRole.
    static const QString format = QStringLiteral("application/x-qabstractitemmodeldatalist");
    if (!mime || !mime->hasFormat(format))
        return {};
    QByteArray bytes = mime->data(format);
    QDataStream stream(&bytes, QIODevice::ReadOnly);
    int row = 0;
    int column = 0;
    QMap<int, QVariant> roles;
    stream >> row >> column >> roles;
    return stream.status() == QDataStream::Ok ? roles.value(Qt::UserRole).toString() : QString();
}

void CompareView::dragEnterEvent(QDragEnterEvent* event)
{
    if (m_document->project().compare.mode == CompareMode::Environments
        && !droppedSource(event->mimeData()).isEmpty())
        event->acceptProposedAction();
}

void CompareView::dragMoveEvent(QDragMoveEvent* event)
{
    event->acceptProposedAction();
}

void CompareView::dropEvent(QDropEvent* event)
{
    const QString source = droppedSource(event->mimeData());
    if (source.isEmpty() || m_document->project().compare.mode != CompareMode::Environments)
        return;
    const int cell = cellAt(event->position().toPoint());
    if (cell >= 0)
        m_controller->setCellSource(m_cells[std::size_t(cell)].index, source.toStdString());
    else
        m_controller->addCell(source.toStdString());
    event->acceptProposedAction();
}

} // namespace facet
