#pragma once
// What the window's Compare modes show, saved in the project as "compare" (format version 3;
// docs/project-format.md, "compare", lists every field with its default and range):
//
//   single        one view (the project's environment, camera and current material)
//   environments  the current material in 2 to 9 environments at once (EnvironmentGrid)
//   ab            the current material (A) against another one (B) in one view (ABCompare)
//   wedge         the current material with one or two parameters swept (WedgeAxis rows x columns)
//   error         the current view by the real-time split sum beside a converging reference, and
//                 the per-pixel relative error between them (ErrorCompare)
//
// Plain values, like the rest of the project: the window changes them through undoable commands,
// `facet sheet` reads them. A layout keeps the settings of every mode, not only the shown one, so
// switching modes loses nothing. Which material is "current" (A, the wedge's and the grid's
// material) is Project::currentMaterial; the compare layout names a material of the project only
// as A/B's B (ABCompare::material), which removeMaterial/insertMaterial keep pointing at the same
// material when the list changes.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <QJsonObject>

#include "core/material/Material.h"
#include "core/project/Camera.h"
#include "core/project/WedgeAxis.h"

namespace facet {

struct Project;
struct EnvironmentSettings;

enum class CompareMode { Single, Environments, AB, Wedge, Error };
const char* toString(CompareMode mode); // "single", "environments", "ab", "wedge", "error"
std::optional<CompareMode> compareModeFromString(std::string_view name);

// One cell of the environment grid.
struct EnvironmentCell {
    // What Environment::fromSpec accepts (a built-in name, a path, a library reference,
    // "uniform:V"); absolute paths in memory, stored as the project's environment source is.
    std::string source = "studio";
    // True: the cell turns its environment by the grid's rotation for all (the project's
    // environment.rotationDegrees); false: by its own rotationDegrees.
    bool rotationFollowsAll = true;
    double rotationDegrees = 0.0; // about +Y; finite
    // True: the cell shows the view's exposure (view.exposureEV); false: that plus its own offset.
    bool exposureFollowsAll = true;
    double exposureOffsetEV = 0.0; // in [-20, 20] (ViewSettings's exposure range)
    // True: the cell shows the grid's shared camera (the project's camera) while the grid's cameras
    // are linked; false: its own camera below, which orbits alone.
    bool cameraLinked = true;
    Camera camera; // used when the cell's camera is not linked (EnvironmentGrid::isLinked)

    bool operator==(const EnvironmentCell&) const = default;
};

// The environment grid: the current material in each cell's environment.
struct EnvironmentGrid {
    static constexpr int kMinCells = 2;
    static constexpr int kMaxCells = 9;
    // The built-in environments a default grid adds to the project's: made by Facet, so they exist
    // on every install (the CC0 samples need packaging/fetch-assets.sh). uniform:1 is the white
    // furnace: the material's albedo without any highlight.
    static constexpr const char* kDefaultSources[] = {"studio", "sky", "uniform:1"};

    // In reading order (row by row); the window chooses the rows and columns.
    std::vector<EnvironmentCell> cells = defaultCells("studio");
    // True: orbiting any linked cell moves them all (they share the project's camera); false:
    // every cell has its own camera (the cells' cameraLinked flags are kept for when it is true again).
    bool linkedCameras = true;

    // `current` followed by the kDefaultSources that differ from it: 3 or 4 cells.
    static std::vector<EnvironmentCell> defaultCells(const std::string& current);

    // Whether cell `index` shows the shared camera: the grid's cameras are linked and so is the cell's.
    bool isLinked(std::size_t index) const;
    // What cell `index` shows: the project's environment with the cell's source (and rotation
    // unless it follows all); the project's camera, or the cell's own (isLinked); the view's
    // exposure plus the cell's offset unless it follows all (the sum may leave [-20, 20]; the
    // renderer takes any exposure).
    EnvironmentSettings environmentOf(std::size_t index, const Project& project) const;
    const Camera& cameraOf(std::size_t index, const Project& project) const;
    double exposureEVOf(std::size_t index, const Project& project) const;

    // Unlinks cell `index`'s camera, starting it from `shared` (where the cell was looking).
    void unlinkCamera(std::size_t index, const Camera& shared);
    // Sets linkedCameras; unlinking the grid starts every linked cell's camera from `shared`.
    void setLinkedCameras(bool linked, const Camera& shared);

    bool operator==(const EnvironmentGrid&) const = default;
};

// What B shows in A/B mode.
enum class BSource {
    Material, // another material of the project (ABCompare::material)
    Snapshot, // a copy of a material taken earlier (ABCompare::snapshot): undoing A's edits leaves it
    Preset, // a built-in material preset (ABCompare::preset, core/material/MaterialPresets.h)
};
const char* toString(BSource source); // "material", "snapshot", "preset"
std::optional<BSource> bSourceFromString(std::string_view name);

enum class ABLayout {
    Split, // one image, A left of the split and B right of it (same camera, pixel-aligned)
    SideBySide, // two views, A left and B right, cameras linked
};
const char* toString(ABLayout layout); // "split", "side-by-side"
std::optional<ABLayout> abLayoutFromString(std::string_view name);

// A/B: A is the project's current material, B one of three sources. Every source's field is kept
// (and saved) whichever is chosen, so switching the source back restores it.
struct ABCompare {
    BSource source = BSource::Snapshot;
    int material = 0; // BSource::Material: an index into Project::materials (always in range)
    Material snapshot; // BSource::Snapshot, with its texture paths
    std::string preset; // BSource::Preset: a built-in preset id ("gold"); empty or a known id
    double split = 0.5; // where B starts, as a fraction of the view's width from the left; [0, 1]
    ABLayout layout = ABLayout::Split;

    // The material B shows in `project` (a preset's material for BSource::Preset). Q_ASSERTs that
    // the layout is valid for the project (Project::validate).
    const Material& materialB(const Project& project) const;

    bool operator==(const ABCompare&) const = default;
};

// Wedge: the current material with `rows` (and `columns`, when there is a second axis) applied,
// one cell per value (pair): rows.size() x columns->size() cells, at most 16 x 16.
struct WedgeLayout {
    WedgeAxis rows = WedgeAxis::defaultRows(); // roughness 0, 0.25, 0.5, 0.75, 1
    std::optional<WedgeAxis> columns = WedgeAxis::defaultColumns(); // metallic 0, 1; none: one column

    std::size_t rowCount() const { return rows.size(); }
    std::size_t columnCount() const { return columns ? columns->size() : 1; }
    // `project` with the row's value (and the column's) applied: what cell (row, column) shows.
    Project cellProject(const Project& project, std::size_t row, std::size_t column) const;

    bool operator==(const WedgeLayout&) const = default;
};

// The error view: the project's view (environment, camera, current material, view settings) by
// the real-time split sum at the project's IBL quality, the same view by the `reference`
// integrator converging to `samples` per pixel, and the per-pixel relative error of the first
// against the second as a heat map from 0 to `scale` (core/image/HeatMap.h), with the relative RMSE
// over the object's covered pixels (core/image/ImageMetrics errorStats, objectMask). With
// `showNoise` the heat map shows the reference's own noise estimate instead: where it is not
// far below the error, the error is not yet measured.
struct ErrorCompare {
    static constexpr int kDefaultSamples = 1024; // the accuracy target's reference (docs/accuracy.md)
    static constexpr double kMinScale = 0.001;
    static constexpr double kMaxScale = 10.0;
    // The scales the window offers (Compare > Error Scale).
    static constexpr double kScaleChoices[] = {0.01, 0.02, 0.05, 0.1, 0.25, 0.5, 1.0};

    int samples = kDefaultSamples; // 1..kMaxIblSamples
    double scale = 0.25; // the heat map's top: relative error 0.25 (25%) is its last colour
    bool showNoise = false;

    bool operator==(const ErrorCompare&) const = default;
};

struct CompareLayout {
    CompareMode mode = CompareMode::Single;
    EnvironmentGrid environments;
    ABCompare ab;
    WedgeLayout wedge;
    ErrorCompare error;

    // The layout a project starts with: the grid holds the project's environment and the built-in
    // ones (EnvironmentGrid::defaultCells), B is a snapshot of the current material. Also what a
    // version 1 or 2 file, which has no "compare", opens with. For Project {} this equals
    // CompareLayout {}.
    static CompareLayout defaultFor(const Project& project);

    // Checks every field of every mode against a project of `materialCount` materials. On failure
    // "<field>: <problem>" with the field as the file names it, e.g.
    // "environments.cells[3].source: must not be empty ..." (the caller prefixes "compare.").
    bool validate(std::size_t materialCount, std::string* problem) const;

    // Keeps B pointing at the same material when the project's list changes. removeMaterial: call
    // it when material `index` (== `removed`) leaves the list; if B showed it, B becomes a snapshot
    // of it (nothing the user compared against disappears) and material goes to 0; a later
    // index moves down by one. insertMaterial: a material entered the list at `index` (undoing a
    // removal): indices from there move up by one. The undo of a removal should restore the
    // whole layout it saved, which also brings back BSource::Material.
    void removeMaterial(int index, const Material& removed);
    void insertMaterial(int index);
    // Every material left the list at once (an asset's materials replaced them: withAsset,
    // core/project/AssetProject.h): as removeMaterial for each of `removed`, the list before.
    void removeAllMaterials(const std::vector<Material>& removed);

    // JSON of the "compare" object (docs/project-format.md). baseDir as in Project::toJson:
    // environment specs and the snapshot's texture paths are stored relative to it.
    QJsonObject toJson(const std::string& baseDir = {}) const;
    // Reads and validates a "compare" object for a project of `materialCount` materials; keys the
    // object lacks take their values from *defaults (CompareLayout {} when null). Messages start with
    // "CompareLayout::fromJson: compare.", e.g. "... compare.ab.split: 1.5 is outside [0, 1]";
    // unknown keys are warned about in *warning (one line each), not fatal.
    static std::optional<CompareLayout> fromJson(const QJsonObject& object, const std::string& baseDir,
        std::size_t materialCount, std::string* error, std::string* warning = nullptr,
        const CompareLayout* defaults = nullptr);

    bool operator==(const CompareLayout&) const = default;
};

// A/B's "swap": B's material becomes the current material and A's becomes B. BSource::Material
// swaps the indices (currentMaterial and ab.material); Snapshot swaps the current material's value
// with the snapshot's; Preset makes B a snapshot of A and sets A to the preset's material. The
// window wraps it in one undo command.
void swapAB(Project& project);

// Makes cell `index` of the environment grid the single view: the project's environment becomes
// the cell's (source, rotation), its exposure the view's (clamped to the view's range, which the
// sum of the view's exposure and the cell's offset may leave), its camera (when unlinked) the
// project's, and the mode single.
void promoteCell(Project& project, std::size_t index);

} // namespace facet
