#include "ui/compare/CompareController.h"

#include "core/material/MaterialPresets.h"
#include "core/project/Project.h"
#include "core/project/WedgeAxis.h"
#include "ui/document/Document.h"

#include <algorithm>
#include <cmath>

namespace facet {

CompareController::CompareController(Document* document, QObject* parent)
    : QObject(parent)
    , m_document(document)
{
}

const CompareLayout& CompareController::layout() const
{
    return m_document->project().compare;
}

void CompareController::push(const Project& after, const QString& undoText, int mergeId)
{
    m_document->setProject(after, undoText, mergeId);
}

void CompareController::setMode(CompareMode mode)
{
    Project after = m_document->project();
    after.compare.mode = mode;
    const QString names[]
        = {tr("Single View"), tr("Environment Grid"), tr("A/B"), tr("Wedge"), tr("Error View")};
    push(after, tr("Compare: %1").arg(names[int(mode)]));
}

void CompareController::setCellSource(std::size_t index, const std::string& spec)
{
    Project after = m_document->project();
    if (index >= after.compare.environments.cells.size() || spec.empty())
        return;
    after.compare.environments.cells[index].source = spec;
    push(after, tr("Cell Environment"));
}

bool CompareController::addCell(const std::string& spec)
{
    Project after = m_document->project();
    auto& cells = after.compare.environments.cells;
    if (int(cells.size()) >= EnvironmentGrid::kMaxCells || spec.empty())
        return false;
    EnvironmentCell cell;
    cell.source = spec;
    cell.camera = after.camera;
    cells.push_back(cell);
    push(after, tr("Add Cell"));
    return true;
}

bool CompareController::removeCell(std::size_t index)
{
    Project after = m_document->project();
    auto& cells = after.compare.environments.cells;
    if (int(cells.size()) <= EnvironmentGrid::kMinCells || index >= cells.size())
        return false;
    cells.erase(cells.begin() + std::ptrdiff_t(index));
    push(after, tr("Remove Cell"));
    return true;
}

void CompareController::setCellRotation(std::size_t index, std::optional<double> rotationDegrees)
{
    Project after = m_document->project();
    if (index >= after.compare.environments.cells.size())
        return;
    EnvironmentCell& cell = after.compare.environments.cells[index];
    cell.rotationFollowsAll = !rotationDegrees;
    if (rotationDegrees)
        cell.rotationDegrees = *rotationDegrees;
    push(after, tr("Cell Rotation"), kCellRotationMergeId);
}

void CompareController::setCellExposure(std::size_t index, std::optional<double> offsetEV)
{
    Project after = m_document->project();
    if (index >= after.compare.environments.cells.size())
        return;
    EnvironmentCell& cell = after.compare.environments.cells[index];
    cell.exposureFollowsAll = !offsetEV;
    if (offsetEV)
        cell.exposureOffsetEV
            = std::clamp(*offsetEV, ViewSettings::kMinExposureEV, ViewSettings::kMaxExposureEV);
    push(after, tr("Cell Exposure"), kCellExposureMergeId);
}

void CompareController::setCellLinked(std::size_t index, bool linked)
{
    Project after = m_document->project();
    EnvironmentGrid& grid = after.compare.environments;
    if (index >= grid.cells.size())
        return;
    if (linked) {
        grid.cells[index].cameraLinked = true;
        // Linking one cell of an unlinked grid links the grid (the others keep their own flags).
        grid.linkedCameras = true;
    } else {
        grid.unlinkCamera(index, after.camera);
    }
    push(after, linked ? tr("Link Cell Camera") : tr("Unlink Cell Camera"));
}

void CompareController::setLinkedCameras(bool linked)
{
    Project after = m_document->project();
    after.compare.environments.setLinkedCameras(linked, after.camera);
    push(after, linked ? tr("Link Cameras") : tr("Unlink Cameras"));
}

void CompareController::setCellCamera(std::size_t index, const Camera& camera)
{
    const Project& project = m_document->project();
    const EnvironmentGrid& grid = project.compare.environments;
    if (index >= grid.cells.size())
        return;
    if (grid.isLinked(index)) {
        m_document->setCamera(camera); // the shared camera: saved, not an undo step
        return;
    }
    Project after = project;
    after.compare.environments.cells[index].camera = camera;
    push(after, tr("Cell Camera"), kCellCameraMergeId);
}

int CompareController::compareEnvironments(const std::vector<std::string>& sources)
{
    const std::size_t count = std::min(sources.size(), std::size_t(EnvironmentGrid::kMaxCells));
    if (int(count) < EnvironmentGrid::kMinCells)
        return 0;
    Project after = m_document->project();
    std::vector<EnvironmentCell>& cells = after.compare.environments.cells;
    cells.clear();
    for (std::size_t i = 0; i < count; ++i) {
        if (sources[i].empty())
            return 0;
        EnvironmentCell cell; // rotation and exposure follow all, camera linked
        cell.source = sources[i];
        cell.camera = after.camera; // where the cell starts if it is unlinked later (addCell's rule)
        cells.push_back(std::move(cell));
    }
    after.compare.mode = CompareMode::Environments;
    push(after, tr("Compare Selected Environments"));
    return int(count);
}

void CompareController::promoteCell(std::size_t index)
{
    const Project& project = m_document->project();
    if (index >= project.compare.environments.cells.size())
        return;
    Project after = project;
    facet::promoteCell(after, index);
    // The camera is not part of an undo step (Document): a promoted unlinked cell's view is set
    // on the document directly, after the step that changes the rest.
    const Camera camera = after.camera;
    push(after, tr("Promote Cell to Single View"));
    m_document->setCamera(camera);
}

void CompareController::setSplit(double split)
{
    Project after = m_document->project();
    after.compare.ab.split = std::clamp(split, 0.0, 1.0);
    push(after, tr("A/B Split"), kSplitMergeId);
}

void CompareController::setErrorScale(double scale)
{
    Project after = m_document->project();
    after.compare.error.scale = std::clamp(scale, ErrorCompare::kMinScale, ErrorCompare::kMaxScale);
    push(after, tr("Error Scale"));
}

void CompareController::setErrorShowsNoise(bool noise)
{
    Project after = m_document->project();
    after.compare.error.showNoise = noise;
    push(after, noise ? tr("Show Reference Noise") : tr("Show Relative Error"));
}

void CompareController::setErrorSamples(int samples)
{
    Project after = m_document->project();
    after.compare.error.samples = std::clamp(samples, 1, kMaxIblSamples);
    push(after, tr("Error View Samples"));
}

void CompareController::setABLayout(ABLayout abLayout)
{
    Project after = m_document->project();
    after.compare.ab.layout = abLayout;
    push(after, abLayout == ABLayout::Split ? tr("A/B Split View") : tr("A/B Side by Side"));
}

void CompareController::setBMaterial(int index)
{
    Project after = m_document->project();
    if (index < 0 || std::size_t(index) >= after.materials.size())
        return;
    after.compare.ab.source = BSource::Material;
    after.compare.ab.material = index;
    push(after, tr("B: Material"));
}

void CompareController::takeSnapshot()
{
    Project after = m_document->project();
    after.compare.ab.source = BSource::Snapshot;
    after.compare.ab.snapshot = after.material();
    push(after, tr("B: Snapshot"));
}

void CompareController::setBPreset(const std::string& id)
{
    if (!findPreset(id))
        return;
    Project after = m_document->project();
    after.compare.ab.source = BSource::Preset;
    after.compare.ab.preset = id;
    push(after, tr("B: Preset"));
}

void CompareController::swap()
{
    Project after = m_document->project();
    swapAB(after);
    push(after, tr("Swap A and B"));
}

bool CompareController::setWedge(const std::string& rows, const std::string& columns, std::string* error)
{
    const std::optional<WedgeAxis> rowAxis = WedgeAxis::parse(rows, error);
    if (!rowAxis)
        return false;
    std::optional<WedgeAxis> columnAxis;
    if (!columns.empty()) {
        columnAxis = WedgeAxis::parse(columns, error);
        if (!columnAxis)
            return false;
    }
    Project after = m_document->project();
    after.compare.wedge.rows = *rowAxis;
    after.compare.wedge.columns = columnAxis;
    push(after, tr("Wedge Axes"));
    return true;
}

} // namespace facet
