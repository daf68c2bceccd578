#include "core/project/CompareLayout.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <QJsonArray>
#include <QtGlobal>

#include "core/ibl/Environment.h"
#include "core/json/JsonReader.h"
#include "core/json/JsonSupport.h"
#include "core/material/MaterialPresets.h"
#include "core/project/Project.h"
#include "core/support/EnumNames.h"

namespace facet {

namespace {

using namespace jsonsupport;

constexpr std::pair<CompareMode, const char*> kModes[]
    = {{CompareMode::Single, "single"}, {CompareMode::Environments, "environments"}, {CompareMode::AB, "ab"},
        {CompareMode::Wedge, "wedge"}, {CompareMode::Error, "error"}};
constexpr std::pair<BSource, const char*> kBSources[]
    = {{BSource::Material, "material"}, {BSource::Snapshot, "snapshot"}, {BSource::Preset, "preset"}};
constexpr std::pair<ABLayout, const char*> kABLayouts[]
    = {{ABLayout::Split, "split"}, {ABLayout::SideBySide, "side-by-side"}};

// "1 cell; a grid shows 2 to 9", "10 cells; ..."
std::string cellCountProblem(std::size_t count)
{
    return std::to_string(count) + (count == 1 ? " cell" : " cells") + "; a grid shows "
        + std::to_string(EnvironmentGrid::kMinCells) + " to " + std::to_string(EnvironmentGrid::kMaxCells);
}

std::string presetIdList()
{
    std::string list;
    for (const MaterialPreset& preset : builtinPresets())
        list += (list.empty() ? "" : ", ") + preset.id;
    return list;
}

bool validateCell(const EnvironmentCell& cell, std::string* problem)
{
    std::string local;
    if (!Environment::checkSpec(cell.source, &local))
        return fail("source: " + local, problem);
    if (!std::isfinite(cell.rotationDegrees))
        return fail("rotationDegrees: must be finite", problem);
    // The offset alone must be a valid exposure: the same range and message as view.exposureEV.
    ViewSettings probe;
    probe.exposureEV = cell.exposureOffsetEV;
    if (!probe.validate(&local))
        return fail("exposureOffsetEV: " + local.substr(local.find(": ") + 2), problem);
    if (!cell.camera.validate(&local))
        return fail("camera." + local, problem);
    return true;
}

// ---- JSON -------------------------------------------------------------------------------

QJsonObject axisToJson(const WedgeAxis& axis, const std::string& baseDir)
{
    QJsonObject o;
    o[QLatin1String("parameter")] = QLatin1String(toString(axis.parameter));
    QJsonArray values;
    if (axis.isEnvironment())
        for (const std::string& spec : axis.environments)
            values.append(qs(json::storedSpec(spec, baseDir)));
    else
        for (double value : axis.values)
            values.append(value);
    o[QLatin1String("values")] = values;
    return o;
}

// An axis is read whole: "parameter" and "values" are both required, since values mean nothing
// without their parameter.
void readAxis(Messages& messages, const QJsonObject& object, const std::string& path,
    const std::string& baseDir, WedgeAxis& axis)
{
    ObjectReader r(messages, object, path);
    std::vector<std::pair<WedgeParameter, const char*>> table;
    for (const WedgeParameterInfo& info : wedgeParameters())
        table.emplace_back(info.parameter, info.name);
    WedgeAxis read;
    if (r.value("parameter").isUndefined())
        messages.fail(r.pathOf("parameter"), "missing (an axis needs \"parameter\" and \"values\")");
    r.enumeration("parameter", read.parameter, table);
    const std::optional<QJsonArray> values = r.array("values");
    if (!values && !messages.failed())
        messages.fail(r.pathOf("values"), "missing (an axis needs \"parameter\" and \"values\")");
    r.warnAboutUnknownKeys();
    if (!values || messages.failed())
        return;
    for (int i = 0; i < int(values->size()); ++i) {
        const QJsonValue value = values->at(i);
        const std::string where = r.pathOf("values") + "[" + std::to_string(i) + "]";
        if (read.isEnvironment() ? !value.isString() : !value.isDouble())
            return messages.fail(where,
                std::string("expected ") + (read.isEnvironment() ? "a string" : "a number") + ", got "
                    + typeName(value));
        if (read.isEnvironment())
            read.environments.push_back(json::resolvedSpec(ss(value.toString()), baseDir));
        else
            read.values.push_back(value.toDouble());
    }
    axis = std::move(read);
}

QJsonObject cellToJson(const EnvironmentCell& cell, const std::string& baseDir)
{
    QJsonObject o;
    o[QLatin1String("source")] = qs(json::storedSpec(cell.source, baseDir));
    o[QLatin1String("rotationFollowsAll")] = cell.rotationFollowsAll;
    o[QLatin1String("rotationDegrees")] = cell.rotationDegrees;
    o[QLatin1String("exposureFollowsAll")] = cell.exposureFollowsAll;
    o[QLatin1String("exposureOffsetEV")] = cell.exposureOffsetEV;
    o[QLatin1String("cameraLinked")] = cell.cameraLinked;
    o[QLatin1String("camera")] = cameraToJson(cell.camera);
    return o;
}

void readCell(Messages& messages, const QJsonObject& object, const std::string& path,
    const std::string& baseDir, EnvironmentCell& cell)
{
    ObjectReader r(messages, object, path);
    std::string source = cell.source;
    r.string("source", source);
    cell.source = json::resolvedSpec(source, baseDir);
    r.boolean("rotationFollowsAll", cell.rotationFollowsAll);
    r.number("rotationDegrees", cell.rotationDegrees);
    r.boolean("exposureFollowsAll", cell.exposureFollowsAll);
    r.number("exposureOffsetEV", cell.exposureOffsetEV);
    r.boolean("cameraLinked", cell.cameraLinked);
    if (const std::optional<QJsonObject> camera = r.object("camera"))
        readCamera(messages, *camera, r.pathOf("camera"), cell.camera);
    r.warnAboutUnknownKeys();
}

void readGrid(Messages& messages, const QJsonObject& object, const std::string& path,
    const std::string& baseDir, EnvironmentGrid& grid)
{
    ObjectReader r(messages, object, path);
    r.boolean("linkedCameras", grid.linkedCameras);
    if (const std::optional<QJsonArray> cells = r.array("cells")) {
        // Refused before reading: validate() would refuse it anyway, and a hand-made file could
        // hold a million cells.
        if (cells->size() < EnvironmentGrid::kMinCells || cells->size() > EnvironmentGrid::kMaxCells)
            messages.fail(r.pathOf("cells"), cellCountProblem(std::size_t(cells->size())));
        std::vector<EnvironmentCell> read;
        for (int i = 0; i < int(cells->size()) && !messages.failed(); ++i) {
            const std::string where = r.pathOf("cells") + "[" + std::to_string(i) + "]";
            const QJsonValue value = cells->at(i);
            if (!value.isObject())
                return messages.fail(where, std::string("expected an object, got ") + typeName(value));
            readCell(messages, value.toObject(), where, baseDir, read.emplace_back());
        }
        grid.cells = std::move(read);
    }
    r.warnAboutUnknownKeys();
}

QJsonObject abToJson(const ABCompare& ab, const std::string& baseDir)
{
    QJsonObject o;
    o[QLatin1String("source")] = QLatin1String(toString(ab.source));
    o[QLatin1String("material")] = ab.material;
    o[QLatin1String("snapshot")] = materialToJson(ab.snapshot, baseDir, true);
    o[QLatin1String("preset")] = qs(ab.preset);
    o[QLatin1String("split")] = ab.split;
    o[QLatin1String("layout")] = QLatin1String(toString(ab.layout));
    return o;
}

void readAB(Messages& messages, const QJsonObject& object, const std::string& path,
    const std::string& baseDir, ABCompare& ab)
{
    ObjectReader r(messages, object, path);
    r.enumeration("source", ab.source, kBSources);
    r.integer("material", ab.material);
    if (const std::optional<QJsonObject> snapshot = r.object("snapshot")) {
        // The snapshot is a material like those of "materials": the same reader, rules and messages.
        std::string error;
        std::string warning;
        if (std::optional<Material> material
            = materialFromJson(*snapshot, baseDir, r.pathOf("snapshot"), &error, &warning))
            ab.snapshot = std::move(*material);
        else
            messages.failWith(error);
        // One warning per line, as the other readers give them.
        for (std::size_t start = 0; start < warning.size();) {
            const std::size_t end = std::min(warning.find('\n', start), warning.size());
            messages.warnings.push_back(warning.substr(start, end - start));
            start = end + 1;
        }
    }
    r.string("preset", ab.preset);
    r.number("split", ab.split);
    r.enumeration("layout", ab.layout, kABLayouts);
    r.warnAboutUnknownKeys();
}

void readWedge(Messages& messages, const QJsonObject& object, const std::string& path,
    const std::string& baseDir, WedgeLayout& wedge)
{
    ObjectReader r(messages, object, path);
    if (const std::optional<QJsonObject> rows = r.object("rows"))
        readAxis(messages, *rows, r.pathOf("rows"), baseDir, wedge.rows);
    // null: no second axis (one column); missing: the default's.
    const QJsonValue columns = r.value("columns");
    if (columns.isNull()) {
        wedge.columns.reset();
    } else if (columns.isObject()) {
        WedgeAxis axis;
        readAxis(messages, columns.toObject(), r.pathOf("columns"), baseDir, axis);
        wedge.columns = std::move(axis);
    } else if (!columns.isUndefined()) {
        messages.fail(
            r.pathOf("columns"), std::string("expected an object or null, got ") + typeName(columns));
    }
    r.warnAboutUnknownKeys();
}

} // namespace

namespace jsonsupport {

void readCompareLayout(Messages& messages, const QJsonObject& object, const std::string& path,
    const std::string& baseDir, CompareLayout& layout)
{
    ObjectReader r(messages, object, path);
    r.enumeration("mode", layout.mode, kModes);
    if (const std::optional<QJsonObject> grid = r.object("environments"))
        readGrid(messages, *grid, r.pathOf("environments"), baseDir, layout.environments);
    if (const std::optional<QJsonObject> ab = r.object("ab"))
        readAB(messages, *ab, r.pathOf("ab"), baseDir, layout.ab);
    if (const std::optional<QJsonObject> wedge = r.object("wedge"))
        readWedge(messages, *wedge, r.pathOf("wedge"), baseDir, layout.wedge);
    if (const std::optional<QJsonObject> error = r.object("error")) {
        ObjectReader e(messages, *error, r.pathOf("error"));
        e.integer("samples", layout.error.samples);
        e.number("scale", layout.error.scale);
        e.boolean("showNoise", layout.error.showNoise);
        e.warnAboutUnknownKeys();
    }
    r.warnAboutUnknownKeys();
}

} // namespace jsonsupport

// ---- Names ------------------------------------------------------------------------------

const char* toString(CompareMode mode)
{
    return enumName(kModes, mode);
}
std::optional<CompareMode> compareModeFromString(std::string_view name)
{
    return enumFromName(kModes, name);
}
const char* toString(BSource source)
{
    return enumName(kBSources, source);
}
std::optional<BSource> bSourceFromString(std::string_view name)
{
    return enumFromName(kBSources, name);
}
const char* toString(ABLayout layout)
{
    return enumName(kABLayouts, layout);
}
std::optional<ABLayout> abLayoutFromString(std::string_view name)
{
    return enumFromName(kABLayouts, name);
}

// ---- EnvironmentGrid --------------------------------------------------------------------

std::vector<EnvironmentCell> EnvironmentGrid::defaultCells(const std::string& current)
{
    std::vector<EnvironmentCell> cells(1);
    cells.front().source = current;
    for (const char* source : kDefaultSources)
        if (current != source)
            cells.emplace_back().source = source;
    return cells;
}

bool EnvironmentGrid::isLinked(std::size_t index) const
{
    Q_ASSERT(index < cells.size());
    return linkedCameras && cells[index].cameraLinked;
}

EnvironmentSettings EnvironmentGrid::environmentOf(std::size_t index, const Project& project) const
{
    Q_ASSERT(index < cells.size());
    const EnvironmentCell& cell = cells[index];
    EnvironmentSettings environment = project.environment;
    environment.source = cell.source;
    if (!cell.rotationFollowsAll)
        environment.rotationDegrees = cell.rotationDegrees;
    return environment;
}

const Camera& EnvironmentGrid::cameraOf(std::size_t index, const Project& project) const
{
    return isLinked(index) ? project.camera : cells[index].camera;
}

double EnvironmentGrid::exposureEVOf(std::size_t index, const Project& project) const
{
    Q_ASSERT(index < cells.size());
    const EnvironmentCell& cell = cells[index];
    return project.view.exposureEV + (cell.exposureFollowsAll ? 0.0 : cell.exposureOffsetEV);
}

void EnvironmentGrid::unlinkCamera(std::size_t index, const Camera& shared)
{
    Q_ASSERT(index < cells.size());
    if (isLinked(index))
        cells[index].camera = shared;
    cells[index].cameraLinked = false;
}

void EnvironmentGrid::setLinkedCameras(bool linked, const Camera& shared)
{
    if (linkedCameras && !linked)
        for (EnvironmentCell& cell : cells)
            if (cell.cameraLinked)
                cell.camera = shared;
    linkedCameras = linked;
}

// ---- ABCompare, WedgeLayout -------------------------------------------------------------

const Material& ABCompare::materialB(const Project& project) const
{
    switch (source) {
    case BSource::Material:
        Q_ASSERT(material >= 0 && std::size_t(material) < project.materials.size());
        return project.materials[std::size_t(material)];
    case BSource::Preset: {
        const MaterialPreset* found = findPreset(preset);
        Q_ASSERT(found);
        if (found)
            return found->material;
        break;
    }
    case BSource::Snapshot:
        break;
    }
    return snapshot;
}

Project WedgeLayout::cellProject(const Project& project, std::size_t row, std::size_t column) const
{
    Q_ASSERT(row < rowCount() && column < columnCount());
    Project cell = project;
    rows.apply(row, cell);
    if (columns)
        columns->apply(column, cell);
    return cell;
}

// ---- CompareLayout ----------------------------------------------------------------------

CompareLayout CompareLayout::defaultFor(const Project& project)
{
    CompareLayout layout;
    layout.environments.cells = EnvironmentGrid::defaultCells(project.environment.source);
    // Not project.material(): this also runs on a file being read, before validation.
    if (project.currentMaterial >= 0 && std::size_t(project.currentMaterial) < project.materials.size())
        layout.ab.snapshot = project.materials[std::size_t(project.currentMaterial)];
    return layout;
}

bool CompareLayout::validate(std::size_t materialCount, std::string* problem) const
{
    std::string local;
    const std::size_t cellCount = environments.cells.size();
    if (cellCount < std::size_t(EnvironmentGrid::kMinCells)
        || cellCount > std::size_t(EnvironmentGrid::kMaxCells))
        return fail("environments.cells: " + cellCountProblem(cellCount), problem);
    for (std::size_t i = 0; i < cellCount; ++i)
        if (!validateCell(environments.cells[i], &local))
            return fail("environments.cells[" + std::to_string(i) + "]." + local, problem);

    if (ab.material < 0 || std::size_t(ab.material) >= materialCount)
        return fail("ab.material: " + std::to_string(ab.material) + " is not a material (there are "
                + std::to_string(materialCount) + ")",
            problem);
    if (!ab.snapshot.validate(&local))
        return fail("ab.snapshot." + local, problem);
    if (ab.preset.empty() && ab.source == BSource::Preset)
        return fail("ab.preset: must name a built-in preset when the source is \"preset\" (one of: "
                + presetIdList() + ")",
            problem);
    if (!ab.preset.empty() && !findPreset(ab.preset))
        return fail(
            "ab.preset: unknown preset \"" + ab.preset + "\" (the built-in presets: " + presetIdList() + ")",
            problem);
    if (!std::isfinite(ab.split) || ab.split < 0.0 || ab.split > 1.0)
        return fail("ab.split: " + number(ab.split) + " is outside [0, 1]", problem);

    if (!wedge.rows.validate(&local))
        return fail("wedge.rows." + local, problem);
    if (wedge.columns && !wedge.columns->validate(&local))
        return fail("wedge.columns." + local, problem);

    if (error.samples < 1 || error.samples > kMaxIblSamples)
        return fail("error.samples: " + std::to_string(error.samples) + " is outside [1, "
                + std::to_string(kMaxIblSamples) + "]",
            problem);
    if (!std::isfinite(error.scale) || error.scale < ErrorCompare::kMinScale
        || error.scale > ErrorCompare::kMaxScale)
        return fail("error.scale: " + number(error.scale) + " is outside [" + number(ErrorCompare::kMinScale)
                + ", " + number(ErrorCompare::kMaxScale) + "]",
            problem);
    return true;
}

void CompareLayout::removeMaterial(int index, const Material& removed)
{
    if (ab.material == index) {
        // B goes on showing what it showed, as a snapshot (the old snapshot is replaced: it was
        // not on screen, and the undo of the removal restores the whole layout).
        if (ab.source == BSource::Material) {
            ab.source = BSource::Snapshot;
            ab.snapshot = removed;
        }
        ab.material = 0;
    } else if (ab.material > index) {
        --ab.material;
    }
}

void CompareLayout::removeAllMaterials(const std::vector<Material>& removed)
{
    if (ab.source == BSource::Material && ab.material >= 0 && std::size_t(ab.material) < removed.size()) {
        ab.source = BSource::Snapshot;
        ab.snapshot = removed[std::size_t(ab.material)];
    }
    ab.material = 0;
}

void CompareLayout::insertMaterial(int index)
{
    if (ab.material >= index)
        ++ab.material;
}

QJsonObject CompareLayout::toJson(const std::string& baseDir) const
{
    QJsonObject grid;
    grid[QLatin1String("linkedCameras")] = environments.linkedCameras;
    QJsonArray cells;
    for (const EnvironmentCell& cell : environments.cells)
        cells.append(cellToJson(cell, baseDir));
    grid[QLatin1String("cells")] = cells;

    QJsonObject wedgeObject;
    wedgeObject[QLatin1String("rows")] = axisToJson(wedge.rows, baseDir);
    wedgeObject[QLatin1String("columns")]
        = wedge.columns ? QJsonValue(axisToJson(*wedge.columns, baseDir)) : QJsonValue(QJsonValue::Null);

    QJsonObject o;
    o[QLatin1String("mode")] = QLatin1String(toString(mode));
    o[QLatin1String("environments")] = grid;
    o[QLatin1String("ab")] = abToJson(ab, baseDir);
    o[QLatin1String("wedge")] = wedgeObject;
    QJsonObject errorObject;
    errorObject[QLatin1String("samples")] = error.samples;
    errorObject[QLatin1String("scale")] = error.scale;
    errorObject[QLatin1String("showNoise")] = error.showNoise;
    o[QLatin1String("error")] = errorObject;
    return o;
}

std::optional<CompareLayout> CompareLayout::fromJson(const QJsonObject& object, const std::string& baseDir,
    std::size_t materialCount, std::string* error, std::string* warning, const CompareLayout* defaults)
{
    const std::string prefix = "CompareLayout::fromJson: ";
    Messages messages;
    CompareLayout layout = defaults ? *defaults : CompareLayout {};
    readCompareLayout(messages, object, "compare", baseDir, layout);
    if (messages.failed())
        return failed(prefix + messages.error, error);
    std::string problem;
    if (!layout.validate(materialCount, &problem))
        return failed(prefix + "compare." + problem, error);
    if (warning)
        for (const std::string& line : messages.warnings)
            *warning += (warning->empty() ? "" : "\n") + prefix + line;
    return layout;
}

// ---- Operations on a project ------------------------------------------------------------

void swapAB(Project& project)
{
    ABCompare& ab = project.compare.ab;
    switch (ab.source) {
    case BSource::Material:
        std::swap(project.currentMaterial, ab.material);
        return;
    case BSource::Snapshot:
        std::swap(project.material(), ab.snapshot);
        return;
    case BSource::Preset: {
        const MaterialPreset* preset = findPreset(ab.preset);
        Q_ASSERT(preset);
        if (!preset)
            return;
        ab.snapshot = project.material();
        ab.source = BSource::Snapshot;
        project.material() = preset->material;
        return;
    }
    }
}

void promoteCell(Project& project, std::size_t index)
{
    const EnvironmentGrid& grid = project.compare.environments;
    Q_ASSERT(index < grid.cells.size());
    const EnvironmentSettings environment = grid.environmentOf(index, project);
    const Camera camera = grid.cameraOf(index, project);
    const double exposure = grid.exposureEVOf(index, project);
    project.environment = environment;
    project.camera = camera;
    // The sum of two valid exposures may leave the range a project accepts.
    project.view.exposureEV
        = std::clamp(exposure, ViewSettings::kMinExposureEV, ViewSettings::kMaxExposureEV);
    project.compare.mode = CompareMode::Single;
}

} // namespace facet
