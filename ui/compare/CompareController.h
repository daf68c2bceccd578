#pragma once
// The edits of the compare layout (core/project/CompareLayout.h, the project's "compare"), each one undo
// step through Document::setProject (ui/document/DocumentCommands.h); not a widget. The Compare menu and
// toolbar, the Compare view's context menu and its mouse drags (the A/B divider, an unlinked
// cell's camera) call these. A drag merges into one step (Document::beginInteractiveEdit).
//
// Cameras: the grid's linked cells show the project's camera, which moves as in the single view
// (Document::setCamera: saved, not undoable). An unlinked cell's camera is part of the saved
// layout (EnvironmentGrid's cell), so orbiting it alone is an undoable step, one per drag.

#include "core/project/CompareLayout.h"

#include <QObject>
#include <QString>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace facet {

class Document;
struct Project;

class CompareController : public QObject {
    Q_OBJECT
public:
    // Merge ids of the drags (ui/document/DocumentCommands.h: free from kFirstFree on).
    enum MergeIds : int {
        kSplitMergeId = 1101,
        kCellCameraMergeId,
        kCellRotationMergeId,
        kCellExposureMergeId
    };

    explicit CompareController(Document* document, QObject* parent = nullptr);

    const CompareLayout& layout() const;

    // Compare > Single / Environment Grid / A-B / Wedge / Error View.
    void setMode(CompareMode mode);

    // --- Environment grid
    // Cell `index` shows `spec` (an environment spec, a library path or reference).
    void setCellSource(std::size_t index, const std::string& spec);
    // A cell showing `spec` at the end (at most EnvironmentGrid::kMaxCells); false when full.
    bool addCell(const std::string& spec);
    // Removes cell `index` (at least EnvironmentGrid::kMinCells stay); false when too few.
    bool removeCell(std::size_t index);
    // The cell's own rotation (degrees) / exposure offset (EV); nullopt: follow all.
    void setCellRotation(std::size_t index, std::optional<double> rotationDegrees);
    void setCellExposure(std::size_t index, std::optional<double> offsetEV);
    // Unlinks cell `index`'s camera (it starts where the shared one is) or links it again.
    void setCellLinked(std::size_t index, bool linked);
    // Every cell's camera linked or not (EnvironmentGrid::setLinkedCameras).
    void setLinkedCameras(bool linked);
    // The camera of unlinked cell `index` (an orbit or dolly in that cell); `interactive`: part
    // of a drag (merged into one step between Document::beginInteractiveEdit and end).
    void setCellCamera(std::size_t index, const Camera& camera);
    // Compare > Compare Selected Environments: the grid's cells become `sources` in that order
    // (the first EnvironmentGrid::kMaxCells of them), each with the cell defaults (rotation and
    // exposure follow all, camera linked), and the mode environment grid: one undo step. Returns
    // how many cells it made; 0 (and no step) for fewer than EnvironmentGrid::kMinCells sources.
    int compareEnvironments(const std::vector<std::string>& sources);
    // Makes cell `index` the single view (core promoteCell: environment, exposure, camera; mode
    // single). One undo step.
    void promoteCell(std::size_t index);

    // --- A/B
    // The divider, as a fraction of the view's width (clamped to [0, 1]); merged while a drag is open.
    void setSplit(double split);
    void setABLayout(ABLayout layout);
    // B shows material `index` of the project / a snapshot of the current material now / preset `id`.
    void setBMaterial(int index);
    void takeSnapshot();
    void setBPreset(const std::string& id);
    // A and B change places (core swapAB): one undo step.
    void swap();

    // --- Wedge
    // The wedge's axes ("roughness=0,0.5,1", WedgeAxis::parse; empty columns: one column). False
    // with *error (parse's message) when a text is not an axis.
    bool setWedge(const std::string& rows, const std::string& columns, std::string* error);

    // --- Error view (ErrorCompare)
    // The heat map's top (clamped to ErrorCompare's range); whether it shows the reference's
    // noise instead of the error; the reference's samples per pixel (1..kMaxIblSamples).
    void setErrorScale(double scale);
    void setErrorShowsNoise(bool noise);
    void setErrorSamples(int samples);

private:
    // Pushes `after` (a copy of the project with its compare layout edited) as one step.
    void push(const Project& after, const QString& undoText, int mergeId = 0);

    Document* m_document;
};

} // namespace facet
