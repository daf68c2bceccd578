#pragma once
// The Compare view: ONE QOpenGLWidget that draws every cell of the project's compare mode
// (ui/compare/CompareCells.h: the environment grid, A/B split or side by side, the wedge) through one
// FrameRenderer (ui/compare/CompareRenderer.h), so an environment several cells show is precomputed once.
// Labels (the environment's name, A and B, the wedge's values on its axes) are child labels over
// the cells; the A/B divider is a thin line the mouse drags.
//
// Lighting no cell had yet (an IBL precompute: about 100 ms each on llvmpipe, a disk read when
// cached) is prepared on a lighting worker of the view's own (ui/viewport/LightingWorker: a thread with a
// GL context of the window's share group), every set the grid needs queued in turn, while the
// window stays responsive: lightingPreparing says how many, the cells wait in the loading grey,
// each is drawn as its set arrives, and lightingReady follows the last. A set the worker could
// not make is prepared on the GUI thread at the next frame, where its error is reported as
// before. Where the platform cannot run GL on a second thread, the lighting is announced first
// and prepared in a frame kAnnounceDelayMs later, once the window has shown the message.
//
// Like the single view (ViewportWidget) it renders on demand only (an idle window draws nothing),
// draws kPreviewScale frames while something is dragged and one full frame kRefineDelayMs after,
// and keeps the project's view settings (debug view, tone mapper, OCIO, exposure): each cell is a
// Project variant. Only the cells whose inputs changed are drawn again (CompareRenderer).
//
// The error view (CompareMode::Error) draws its reference a few samples per frame and repaints
// until ErrorCompare::samples are in, then stops; its labels show the numbers.
//
// Input: left drag orbits (a linked cell moves every linked cell: the shared camera; an unlinked
// cell moves alone), the wheel dollies, a drag near the A/B divider moves it, a double click on a
// grid cell promotes it to the single view, the context menu holds the per-cell edits
// (ui/compare/CompareMenus.h). Edits go through CompareController (undoable).

#include "ui/compare/CompareCells.h"
#include "ui/compare/CompareMenus.h"
#include "ui/compare/CompareRenderer.h"
#include "ui/document/DocumentAssets.h"

#include <QOpenGLWidget>
#include <QPoint>
#include <QPointer>
#include <QTimer>

#include <cstdint>
#include <memory>
#include <set>
#include <vector>

class QLabel;
class QMimeData;

namespace facet {

class CompareController;
class Document;
class LightingWorker;
class SceneController;
class ViewShareGroup;

class CompareView : public QOpenGLWidget {
    Q_OBJECT
public:
    static constexpr double kPreviewScale = 0.5; // as ViewportWidget's
    static constexpr int kRefineDelayMs = 250;
    static constexpr int kGapPixels = 2; // between cells
    static constexpr int kDividerGrabPixels = 6; // a press this close to the divider drags it
    static constexpr int kAnnounceDelayMs = 40; // lightingPreparing -> the frame that prepares it

    CompareView(
        Document* document, SceneController* scene, CompareController* controller, QWidget* parent = nullptr);
    ~CompareView() override;

    // The library the context menu offers for a cell (MainWindow: the Environment dock's list).
    void setEnvironmentChoices(EnvironmentChoicesFunction choices) { m_choices = std::move(choices); }

    const std::vector<CompareCell>& cells() const { return m_cells; }
    // The cell's rectangle in widget coordinates (a split's A and B share one).
    QRect cellRectOf(std::size_t cell) const;
    // The cell under `position` (widget coordinates), -1 in a gap or margin. In a split, A left
    // of the divider, B right of it.
    int cellAt(const QPoint& position) const;
    // The A/B divider's x in widget coordinates (-1 outside split mode).
    int dividerX() const;
    // The label painted over cell `cell` (and the wedge's axis labels: rowLabels, columnLabels).
    QString labelOf(std::size_t cell) const;
    QStringList axisLabels() const;
    // The cells' labels as shown (empty for the wedge's, whose values are on the axes).
    QStringList cellLabels() const { return m_labelTexts.mid(0, m_cellLabelCount); }

    DocumentAssets* assets() const { return m_assets; }
    // The renderer (null before the first show or without OpenGL 4.1): tests read the error
    // view's images from it.
    const CompareRenderer* renderer() const { return m_renderer.get(); }
    const CompareFrameStats& lastFrameStats() const { return m_stats; }
    std::uint64_t frameCount() const { return m_stats.frameNumber; }
    const QString& lastError() const { return m_lastError; }
    // Whether any cell waits for its environment or its lighting.
    bool isLoading() const;
    // Whether the error view's reference is converging (the view draws frame after frame until
    // it is done, then stops).
    bool isRefining() const;

    // An interaction is under way: draw previews, refine kRefineDelayMs after the last call.
    void markInteractive();
    bool isPreviewing() const { return m_previewing; }

    // Tests and the benchmark: a renderer that never touches the user's IBL disk cache. Call
    // before the widget is first shown.
    // With a share group (below), the group's setting: the single view's renderer too.
    void setUseDiskCache(bool use);
    // The window's views share their IBL results and material textures (ui/viewport/ViewShareGroup.h).
    // Set before the widget is first shown; without one the view has resources of its own.
    void setShareGroup(std::shared_ptr<ViewShareGroup> group) { m_shareGroup = std::move(group); }

Q_SIGNALS:
    void frameRendered();
    // `environments` environments need lighting this view did not hold (one per image and IBL
    // quality); the frame that prepares it follows kAnnounceDelayMs later.
    void lightingPreparing(int environments);
    // It was prepared in `milliseconds` (lookups, precomputes and tables; under 1 ms: from a cache).
    void lightingReady(int environments, double milliseconds);

protected:
    void initializeGL() override;
    void paintGL() override;
    void resizeEvent(QResizeEvent* event) override;
    void showEvent(QShowEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;
    // An Environment dock entry dropped on a grid cell shows there; dropped on the free part of
    // the grid it becomes a new cell.
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dragMoveEvent(QDragMoveEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void rebuild();
    void layoutOverlays();
    QLabel* overlayLabel(int index);
    std::vector<CompareCellDraw> cellDraws();
    void moveCamera(int cell, const std::function<Camera(const Camera&)>& move);
    void releaseRenderer();
    // With a lighting worker: queues the sets `draws` need and the view does not hold, and
    // empties those cells' environments (they draw the loading grey until the set arrives).
    void askForLighting(std::vector<CompareCellDraw>& draws);
    // The worker finished set `key`: adopted into the shared precompute, or remembered as failed.
    void lightingArrived(std::uint64_t key);
    // The error view's labels carry its numbers (CompareFrameStats::error): samples, time and
    // noise on the reference, the relative RMSE on the heat map.
    // Cell `index`'s label: its variant's name, and the samples of a converging cell (or the
    // error view's numbers).
    QString cellLabel(std::size_t index) const;
    QString errorLabel(const CompareCell& cell) const;
    // The labels of the error view's and of converging cells, after a frame.
    void updateRefiningLabels();
    // The environment source a drag from the Environment dock's list carries; empty for others.
    static QString droppedSource(const QMimeData* mime);

    Document* m_document;
    SceneController* m_scene;
    CompareController* m_controller;
    DocumentAssets* m_assets; // the document's (SceneController::documentAssets)
    QPointer<DocumentAssets> m_assetsAlive; // the window may destroy it first
    EnvironmentChoicesFunction m_choices;
    std::unique_ptr<CompareRenderer> m_renderer;
    std::shared_ptr<ViewShareGroup> m_shareGroup;
    std::vector<CompareCell> m_cells;
    std::vector<QLabel*> m_labels; // cell labels, then axis labels
    QStringList m_labelTexts;
    int m_cellLabelCount = 0;
    QWidget* m_divider;
    CompareFrameStats m_stats;
    QString m_lastError;
    QTimer m_refineTimer;
    bool m_previewing = false;
    bool m_useDiskCache = true;
    int m_lightingAnnounced = 0; // environments announced by lightingPreparing, not ready yet
    // The view's own lighting worker (null where GL cannot run on a second thread), the sets
    // asked of it and not yet arrived, the batch they belong to (sets asked for since the last
    // lightingReady, and the worker's milliseconds for them), and the sets it failed to make.
    std::shared_ptr<LightingWorker> m_lightingWorker;
    std::set<std::uint64_t> m_lightingAsked;
    int m_lightingBatch = 0;
    double m_lightingBatchMs = 0.0;
    std::set<std::uint64_t> m_lightingFailed;
    enum class Drag { None, Orbit, Divider } m_drag = Drag::None;
    int m_dragCell = -1;
    bool m_dragOpenedEdit = false;
    QPoint m_lastMouse;
};

} // namespace facet
