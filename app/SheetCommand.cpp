#include "SheetCommand.h"

#include "CommandInputs.h"
#include "CommandOptions.h"
#include "MaterialFlags.h"
#include "SceneFlags.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QFileInfo>
#include <QFont>
#include <QFontMetrics>
#include <QGuiApplication>
#include <QImage>
#include <QPainter>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "core/image/Image.h"
#include "core/material/MaterialLibrary.h"
#include "core/material/MaterialPresets.h"
#include "core/project/AssetCache.h"
#include "core/project/AssetProject.h"
#include "core/project/ProjectAssets.h"
#include "core/project/WedgeSweep.h"
#include "render/FrameRenderer.h"
#include "render/HeadlessGLContext.h"
#include "render/IblSettings.h"
#include "render/Renderer.h"

namespace facet {

namespace {

struct Options {
    QCommandLineParser parser;
    QCommandLineOption help {{QStringLiteral("h"), QStringLiteral("help")}, QStringLiteral("Displays this help.")};
    QCommandLineOption materials {QStringLiteral("materials"),
        QStringLiteral("The rows: comma-separated built-in preset ids (gold, ...), preset or project files "
                       "(a project's current material), glTF assets, or PROJECT.json#NAME (a material of a "
                       "project by name or index)."),
        QStringLiteral("list")};
    QCommandLineOption envs {QStringLiteral("envs"),
        QStringLiteral("The columns: comma-separated environments (library or built-in names, image paths, "
                       "uniform:V or uniform:R,G,B)."),
        QStringLiteral("list")};
    QCommandLineOption wedge {QStringLiteral("wedge"),
        QStringLiteral("The rows sweep one parameter of the current material, the environment or the "
                       "exposure: e.g. roughness=0,0.25,0.5,0.75,1 (parameters: %1).")
            .arg(QString::fromStdString(wedgeParameterNameList())),
        QStringLiteral("axis=values")};
    QCommandLineOption wedge2 {QStringLiteral("wedge2"),
        QStringLiteral("The columns sweep a second parameter, e.g. metallic=0,1 (needs --wedge)."),
        QStringLiteral("axis=values")};
    QCommandLineOption mesh {
        QStringLiteral("mesh"), QStringLiteral("A built-in mesh name or a mesh file."), QStringLiteral("name|path")};
    QCommandLineOption cell {QStringLiteral("cell"), QStringLiteral("Cell size, default 256x256."), QStringLiteral("WxH")};
    QCommandLineOption labels {QStringLiteral("labels"),
        QStringLiteral("Row and column labels on a PNG sheet: on (default) or off."), QStringLiteral("on|off")};
    QCommandLineOption quality {
        QStringLiteral("quality"), QStringLiteral("IBL quality preset: draft, default, high."), QStringLiteral("preset")};
    QCommandLineOption ibl {QStringLiteral("ibl"),
        QStringLiteral("How the surface integrates the environment: split-sum, fis or reference (see facet render)."),
        QStringLiteral("method")};
    QCommandLineOption iblSamples {
        QStringLiteral("ibl-samples"), QStringLiteral("Samples per pixel for --ibl fis or reference."), QStringLiteral("N")};
    QCommandLineOption referenceView {QStringLiteral("reference-view"),
        QStringLiteral("Every cell uses the reference view of docs/architecture.md (unit sphere, camera at "
                       "(0,0,3), 45 degree "
                       "FOV).")};
    QCommandLineOption stats {QStringLiteral("stats"), QStringLiteral("Print timings and work counters.")};
    QCommandLineOption output {{QStringLiteral("o"), QStringLiteral("output")},
        QStringLiteral("Output image: .png (display-referred, labelled) or .exr (linear radiance, layout in the "
                       "header)."),
        QStringLiteral("file")};
    MaterialFlags materialFlags;
    SceneFlags scene;

    Options()
    {
        parser.setApplicationDescription(QStringLiteral(
            "Renders a labelled grid of a project without a display: rows are materials (or --wedge), "
            "columns environments (or --wedge2). Each cell is what 'facet render' gives for that material "
            "and environment."));
        for (const QCommandLineOption* option : {&help, &materials, &envs, &wedge, &wedge2, &mesh, &cell, &labels,
                 &quality, &ibl, &iblSamples, &referenceView, &stats, &output})
            parser.addOption(*option);
        materialFlags.addTo(parser);
        scene.addTo(parser);
        parser.addPositionalArgument(QStringLiteral("input"),
            QStringLiteral("A project file (JSON) or a glTF asset (.gltf, .glb); default: the built-in project."),
            QStringLiteral("[PROJECT.json|ASSET.glb|ASSET.gltf]"));
    }
};

// The items of a comma-separated list, trimmed; false with *error on an empty item.
bool splitList(const QString& flag, const QString& text, QStringList* items, QString* error)
{
    for (const QString& part : text.split(QLatin1Char(','))) {
        const QString item = part.trimmed();
        if (item.isEmpty()) {
            *error = QStringLiteral("--%1: '%2' has an empty item").arg(flag, text);
            return false;
        }
        items->append(item);
    }
    return true;
}

// A material named on the command line (see --materials). The message names the item.
std::optional<SheetMaterial> materialFromItem(const std::string& item, std::string* error)
{
    const std::size_t hash = item.rfind('#');
    if (hash != std::string::npos && hash > 0) {
        // PROJECT.json#NAME (a glTF asset's embedded images also use '#', but not in this form).
        const std::string file = item.substr(0, hash);
        std::string problem;
        const auto project = isAssetFileName(file) ? projectFromAsset(file, &problem) : Project::load(file, &problem);
        if (!project) {
            *error = problem;
            return std::nullopt;
        }
        const auto index = findMaterial(*project, item.substr(hash + 1), &problem);
        if (!index) {
            *error = file + ": " + problem;
            return std::nullopt;
        }
        const Material& material = project->materials[std::size_t(*index)];
        return SheetMaterial {material.name, material};
    }
    const QFileInfo info(QString::fromStdString(item));
    const bool looksLikeFile = info.exists() || item.find('/') != std::string::npos
        || info.suffix().compare(QStringLiteral("json"), Qt::CaseInsensitive) == 0 || isAssetFileName(item);
    if (!looksLikeFile) {
        const MaterialPreset* preset = findPreset(item);
        if (!preset) {
            std::string ids;
            for (const MaterialPreset& p : builtinPresets())
                ids += (ids.empty() ? "" : ", ") + p.id;
            *error = "no preset '" + item + "' (built-in: " + ids + ") and no such file";
            return std::nullopt;
        }
        return SheetMaterial {preset->id, preset->material};
    }
    std::string problem;
    if (isAssetFileName(item)) {
        const auto project = projectFromAsset(item, &problem);
        if (!project) {
            *error = problem;
            return std::nullopt;
        }
        return SheetMaterial {project->material().name, project->material()};
    }
    // A preset file or a project file: the "format" field says which.
    const auto object = json::readObjectFile(item, Project::kMaxFileBytes, &problem);
    if (!object) {
        *error = item + ": " + problem;
        return std::nullopt;
    }
    if (object->value(QStringLiteral("format")).toString() == QLatin1String(Project::kFormatName)) {
        const auto project = Project::load(item, &problem);
        if (!project) {
            *error = problem;
            return std::nullopt;
        }
        return SheetMaterial {project->material().name, project->material()};
    }
    const auto preset = loadPreset(item, &problem);
    if (!preset) {
        *error = problem;
        return std::nullopt;
    }
    return SheetMaterial {preset->displayName, preset->material};
}

} // namespace

QString SheetCommand::helpText()
{
    Options options;
    return commandHelpText(options.parser, QStringLiteral("facet sheet"));
}

std::optional<SheetRequest> SheetCommand::parse(const QStringList& arguments, QString* error, int* exitCode)
{
    Options o;
    if (!parseCommandOptions(o, arguments, QStringLiteral("facet sheet"), kExitUsage, error, exitCode))
        return std::nullopt;
    SheetRequest request;
    const QStringList positional = o.parser.positionalArguments();
    if (!checkOneInput(positional, error))
        return std::nullopt;
    const auto output = exrOrPngOutput(o.parser.isSet(o.output), o.parser.value(o.output),
        QStringLiteral("-o SHEET.png or -o SHEET.exr is required"),
        QStringLiteral("the sheet must be .png (labelled, display-referred) or .exr (linear)"), error);
    if (!output)
        return std::nullopt;
    request.outputPath = *output;
    if (o.parser.isSet(o.cell)
        && !parseImageSize(QStringLiteral("cell"), o.parser.value(o.cell), 8, kMaxCellSide, &request.cellWidth,
            &request.cellHeight, error))
        return std::nullopt;
    if (o.parser.isSet(o.labels)) {
        const QString state = o.parser.value(o.labels);
        if (state != QStringLiteral("on") && state != QStringLiteral("off")) {
            *error = QStringLiteral("--labels: '%1' is not on or off").arg(state);
            return std::nullopt;
        }
        request.labels = state == QStringLiteral("on");
    }
    const auto parseAxis = [&](const QString& flag, QString text) -> std::optional<WedgeAxis> {
        if (text.startsWith(QStringLiteral("env=")))
            text = QStringLiteral("env=") + expandInstalledNames(text.mid(4));
        std::string problem;
        auto axis = WedgeAxis::parse(text.toStdString(), &problem);
        if (!axis)
            *error = QStringLiteral("--%1: %2").arg(flag, QString::fromStdString(problem));
        return axis;
    };
    if (o.parser.isSet(o.wedge) && !(request.wedge = parseAxis(QStringLiteral("wedge"), o.parser.value(o.wedge))))
        return std::nullopt;
    if (o.parser.isSet(o.wedge2)) {
        if (!request.wedge) {
            *error = QStringLiteral("--wedge2 needs --wedge (the rows)");
            return std::nullopt;
        }
        if (!(request.wedge2 = parseAxis(QStringLiteral("wedge2"), o.parser.value(o.wedge2))))
            return std::nullopt;
    }
    // --envs with one environment beside --wedge2 is that environment for every cell (the README's
    // wedge example); several would be columns that --wedge2 already sets.
    std::optional<WedgeAxis> singleEnvironment;
    if (o.parser.isSet(o.envs)) {
        if (!(request.environments
                = parseAxis(QStringLiteral("envs"), QStringLiteral("env=") + o.parser.value(o.envs))))
            return std::nullopt;
        if (request.wedge2 && request.environments->size() == 1) {
            singleEnvironment = std::move(request.environments);
            request.environments.reset();
        } else if (request.wedge2) {
            *error = QStringLiteral(
                "--envs and --wedge2 both set the columns: give one (--wedge2 env=... sweeps "
                "environments; one --envs environment is the sheet's)");
            return std::nullopt;
        }
    }
    request.referenceView = o.parser.isSet(o.referenceView);
    request.printStats = o.parser.isSet(o.stats);

    // The project: the file, or the built-in default.
    auto input = commandInputProject(positional, QStringLiteral("sheet"), error);
    if (!input) {
        *exitCode = kExitFailure;
        return std::nullopt;
    }
    request.project = std::move(*input);
    if (singleEnvironment)
        singleEnvironment->apply(0, request.project);
    if (o.parser.isSet(o.mesh))
        request.project.view.mesh = o.parser.value(o.mesh).toStdString();
    if (o.parser.isSet(o.quality)) {
        const auto quality = iblQualityFromString(o.parser.value(o.quality).toStdString());
        if (!quality) {
            *error = QStringLiteral("--quality: '%1' is not draft, default or high").arg(o.parser.value(o.quality));
            return std::nullopt;
        }
        request.project.environment.quality = *quality;
    }
    {
        const QString method = o.parser.value(o.ibl);
        const QString samples = o.parser.value(o.iblSamples);
        if (!applyIblOptions(o.parser.isSet(o.ibl) ? &method : nullptr,
                o.parser.isSet(o.iblSamples) ? &samples : nullptr, request.project.environment, error))
            return std::nullopt;
    }
    if (o.parser.isSet(o.materials)) {
        QStringList items;
        if (!splitList(QStringLiteral("materials"), o.parser.value(o.materials), &items, error))
            return std::nullopt;
        for (const QString& item : items) {
            std::string problem;
            auto material = materialFromItem(item.toStdString(), &problem);
            if (!material) {
                *error = QStringLiteral("--materials: '%1': %2").arg(item, QString::fromStdString(problem));
                *exitCode = kExitFailure;
                return std::nullopt;
            }
            request.materials.push_back(std::move(*material));
        }
        if (request.wedge && request.materials.size() > 1) {
            *error = QStringLiteral("--wedge sets the rows: give at most one --materials item with it");
            return std::nullopt;
        }
    }
    // The material flags set every row's material (--materials items and the project's own).
    std::vector<Material*> rowMaterials;
    for (Material& material : request.project.materials)
        rowMaterials.push_back(&material);
    for (SheetMaterial& row : request.materials)
        rowMaterials.push_back(&row.material);
    if (!o.materialFlags.apply(o.parser, rowMaterials, error))
        return std::nullopt;
    if (!o.scene.apply(o.parser, request.project, {}, error))
        return std::nullopt;
    request.saveProjectPath = o.scene.saveProjectPath(o.parser).toStdString();
    const SheetGrid grid = sheetGrid(request);
    if (grid.rows.size() * grid.columns.size() > std::size_t(kMaxCells)) {
        *error = QStringLiteral("%1 x %2 cells: at most %3 in one sheet")
                     .arg(grid.rows.size())
                     .arg(grid.columns.size())
                     .arg(kMaxCells);
        return std::nullopt;
    }
    std::string problem;
    if (!request.project.validate(&problem)) {
        *error = QString::fromStdString(problem);
        return std::nullopt;
    }
    *exitCode = 0;
    return request;
}

SheetGrid sheetGrid(const SheetRequest& request)
{
    SheetGrid grid;
    if (request.wedge) {
        for (std::size_t i = 0; i < request.wedge->size(); ++i)
            grid.rows.push_back({request.wedge->label(i),
                request.materials.empty() ? nullptr : &request.materials.front(), &*request.wedge, i});
    } else if (!request.materials.empty()) {
        for (const SheetMaterial& material : request.materials)
            grid.rows.push_back({material.label, &material, nullptr, 0});
    } else {
        grid.rows.push_back({request.project.material().name, nullptr, nullptr, 0});
    }
    const WedgeAxis* columns = request.wedge2 ? &*request.wedge2
        : request.environments                ? &*request.environments
                                              : nullptr;
    if (columns) {
        for (std::size_t i = 0; i < columns->size(); ++i)
            grid.columns.push_back({columns->label(i), nullptr, columns, i});
    } else {
        // One column: the project's own environment.
        grid.columns.push_back({WedgeAxis {WedgeParameter::Environment, {}, {request.project.environment.source}}
                                    .label(0),
            nullptr, nullptr, 0});
    }
    return grid;
}

std::vector<std::string> sheetWarnings(const SheetRequest& request, const SheetGrid& grid)
{
    std::vector<std::string> warnings;
    // An axis that changes nothing in any cell (core/project/WedgeSweep, asked of every cell:
    // the other axis may set what this one needs, as --wedge2 clearcoat=0,1 does for
    // --wedge clearcoatRoughness).
    const auto check = [&](const char* option, const WedgeAxis* axis, bool rows) {
        if (!axis)
            return;
        std::vector<Project> cells;
        const std::size_t others = rows ? grid.columns.size() : grid.rows.size();
        for (std::size_t i = 0; i < others; ++i)
            cells.push_back(rows ? grid.cellProject(request, 0, i) : grid.cellProject(request, i, 0));
        const std::string reason = noEffectReasonInEvery(*axis, cells);
        if (!reason.empty())
            warnings.push_back(
                std::string(option) + " " + toString(axis->parameter) + " sweeps nothing: " + reason);
    };
    check("--wedge", request.wedge ? &*request.wedge : nullptr, true);
    check("--wedge2", request.wedge2 ? &*request.wedge2 : nullptr, false);
    return warnings;
}

Project SheetGrid::cellProject(const SheetRequest& request, std::size_t row, std::size_t column) const
{
    Project project = request.project;
    for (const Line* line : {&rows[row], &columns[column]}) {
        if (line->material)
            project.material() = line->material->material;
        if (line->axis)
            line->axis->apply(line->index, project);
    }
    return project;
}

namespace {

// The sheet with its labels drawn (PNG): margins for the labels, cells in a grid. `cells` are
// display-encoded, row by row. Needs a QGuiApplication (fonts).
Image labelledSheet(const std::vector<Image>& cells, const SheetGrid& grid, int cellWidth, int cellHeight)
{
    QFont font;
    font.setPixelSize(std::clamp(cellHeight / 14, 11, 16));
    const QFontMetrics metrics(font);
    int rowLabelWidth = 0;
    for (const SheetGrid::Line& row : grid.rows)
        rowLabelWidth = std::max(rowLabelWidth, metrics.horizontalAdvance(QString::fromStdString(row.label)));
    const int padding = metrics.height() / 2;
    const int left = std::min(rowLabelWidth + 4, 2 * cellWidth) + 2 * padding; // (+4: the painter rounds advances up)
    const int top = metrics.height() + 2 * padding;
    const int columns = int(grid.columns.size());
    const int rows = int(grid.rows.size());
    QImage sheet(left + columns * cellWidth, top + rows * cellHeight, QImage::Format_RGB888);
    sheet.fill(QColor(38, 38, 38));
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c) {
            const Image& cell = cells[std::size_t(r * columns + c)];
            for (int y = 0; y < cellHeight; ++y) {
                uchar* line = sheet.scanLine(top + r * cellHeight + y) + 3 * (left + c * cellWidth);
                for (int x = 0; x < cellWidth; ++x)
                    for (int k = 0; k < 3; ++k)
                        line[3 * x + k] = uchar(std::lround(std::clamp(cell.at(x, y)[k], 0.0f, 1.0f) * 255.0f));
            }
        }
    QPainter painter(&sheet);
    painter.setFont(font);
    painter.setPen(QColor(225, 225, 225));
    for (int c = 0; c < columns; ++c) {
        const QRect box(left + c * cellWidth, 0, cellWidth, top);
        painter.drawText(box, Qt::AlignCenter,
            metrics.elidedText(QString::fromStdString(grid.columns[std::size_t(c)].label), Qt::ElideMiddle,
                cellWidth - padding));
    }
    for (int r = 0; r < rows; ++r) {
        const QRect box(padding, top + r * cellHeight, left - 2 * padding, cellHeight);
        painter.drawText(box, Qt::AlignRight | Qt::AlignVCenter,
            metrics.elidedText(QString::fromStdString(grid.rows[std::size_t(r)].label), Qt::ElideMiddle, box.width()));
    }
    painter.end();
    Image image(sheet.width(), sheet.height());
    for (int y = 0; y < sheet.height(); ++y) {
        const uchar* line = sheet.constScanLine(y);
        for (int x = 0; x < sheet.width(); ++x)
            image.at(x, y) = glm::vec4(line[3 * x] / 255.0f, line[3 * x + 1] / 255.0f, line[3 * x + 2] / 255.0f, 1.0f);
    }
    image.setEncoding(ColorEncoding::SRGB);
    return image;
}

// The cells side by side with nothing between them (EXR, or PNG without labels).
Image plainSheet(const std::vector<Image>& cells, const SheetGrid& grid, int cellWidth, int cellHeight)
{
    const int columns = int(grid.columns.size());
    Image sheet(columns * cellWidth, int(grid.rows.size()) * cellHeight);
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const int r = int(i) / columns;
        const int c = int(i) % columns;
        for (int y = 0; y < cellHeight; ++y)
            for (int x = 0; x < cellWidth; ++x)
                sheet.at(c * cellWidth + x, r * cellHeight + y) = glm::vec4(glm::vec3(cells[i].at(x, y)), 1.0f);
    }
    sheet.setEncoding(cells.empty() ? ColorEncoding::Linear : cells.front().encoding());
    return sheet;
}

std::string joinLabels(const std::vector<SheetGrid::Line>& lines)
{
    std::string text;
    for (const SheetGrid::Line& line : lines)
        text += (text.empty() ? "" : "\n") + line.label;
    return text;
}

} // namespace

int SheetCommand::run(const SheetRequest& request)
{
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    const bool png = QFileInfo(QString::fromStdString(request.outputPath)).suffix().toLower() == QStringLiteral("png");
    const SheetGrid grid = sheetGrid(request);
    const auto fail = [](const std::string& message) {
        std::fprintf(stderr, "facet sheet: %s\n", message.c_str());
        return kExitFailure;
    };
    if (!request.saveProjectPath.empty()) {
        std::string error;
        if (!request.project.save(request.saveProjectPath, &error))
            return fail("--save-project: " + error);
    }
    for (const std::string& warning : sheetWarnings(request, grid))
        std::fprintf(stderr, "facet sheet: %s\n", warning.c_str());

    // Every cell's assets before any rendering: a missing environment, mesh or map is named and
    // nothing is rendered or written. Environments and the mesh load once (AssetCache); maps once
    // per file (MapImageCache), and the assets are kept so that nothing is decoded twice.
    AssetCache cache;
    std::vector<Project> projects;
    std::vector<ProjectAssets> assets;
    std::string error;
    for (std::size_t r = 0; r < grid.rows.size(); ++r)
        for (std::size_t c = 0; c < grid.columns.size(); ++c) {
            projects.push_back(grid.cellProject(request, r, c));
            std::string warning;
            auto loaded = loadProjectAssets(projects.back(), cache, &error, &warning);
            if (!warning.empty() && r == 0 && c == 0)
                std::fprintf(stderr, "facet sheet: %s\n", warning.c_str());
            if (!loaded)
                return fail("cell '" + grid.rows[r].label + "' x '" + grid.columns[c].label + "': " + error);
            assets.push_back(std::move(*loaded));
        }
    const auto loadedAt = Clock::now();

    // Text needs Qt's fonts, which need a QGuiApplication: the offscreen platform, no display.
    std::unique_ptr<QGuiApplication> fonts;
    if (png && request.labels) {
        static int argc = 1;
        static char name[] = "facet";
        static char* argv[] = {name, nullptr};
        qputenv("QT_QPA_PLATFORM", "offscreen");
        fonts = std::make_unique<QGuiApplication>(argc, argv);
    }

    auto context = HeadlessGLContext::create(&error);
    if (!context)
        return fail(error);
    const IblSettings settings = IblSettings::preset(request.project.environment.quality);
    std::vector<Image> cells;
    IblStats total;
    int prepared = 0; // IBL sets not found in memory: each environment once
    double renderMs = 0.0;
    int texturesUploaded = 0;
    {
        FrameRenderer frames;
        for (std::size_t i = 0; i < projects.size(); ++i) {
            IblStats stats;
            const auto scene = frames.prepare(projects[i], assets[i], settings,
                sceneOptionsFor(settings, request.referenceView), &stats, &error);
            if (!scene)
                return fail(error);
            prepared += stats.cacheHitsMemory == 0 ? 1 : 0; // computed, or read from the disk cache
            total.passesRun += stats.passesRun;
            total.cacheHitsMemory += stats.cacheHitsMemory;
            total.cacheHitsDisk += stats.cacheHitsDisk;
            total.msTotal += stats.msTotal;
            const auto cellStart = Clock::now();
            auto image = frames.renderConverged(*scene, request.cellWidth, request.cellHeight,
                png ? FrameOutput::DisplayReferred : FrameOutput::LinearRadiance, scene->sampling.samples, &error);
            if (!image)
                return fail(error);
            renderMs += std::chrono::duration<double, std::milli>(Clock::now() - cellStart).count();
            texturesUploaded += frames.renderer().lastFrameStats().texturesUploaded;
            cells.push_back(std::move(*image));
            // A row shows one material (or one wedge value of it): its textures serve the whole
            // row and go after it, so a sheet of many textured materials holds one row's maps.
            if ((i + 1) % grid.columns.size() == 0)
                frames.finishFrame();
        }
        if (!frames.precompute().lastWarning().empty())
            std::fprintf(stderr, "facet sheet: %s\n", frames.precompute().lastWarning().c_str());
    }

    bool saved = false;
    if (png && request.labels) {
        saved = labelledSheet(cells, grid, request.cellWidth, request.cellHeight)
                    .save(request.outputPath, &error, /*alpha=*/false);
    } else {
        std::vector<std::pair<std::string, std::string>> layout;
        if (!png)
            layout = {{"facet:rows", std::to_string(grid.rows.size())},
                {"facet:columns", std::to_string(grid.columns.size())},
                {"facet:cellWidth", std::to_string(request.cellWidth)},
                {"facet:cellHeight", std::to_string(request.cellHeight)}, {"facet:rowLabels", joinLabels(grid.rows)},
                {"facet:columnLabels", joinLabels(grid.columns)}};
        // A transparent background keeps the cells' alpha (a labelled sheet has an opaque page).
        const bool alpha = request.project.view.background == BackgroundMode::Transparent;
        saved = plainSheet(cells, grid, request.cellWidth, request.cellHeight)
                    .save(request.outputPath, &error, alpha, layout);
    }
    if (!saved)
        return fail(error);
    if (request.printStats) {
        const GLInfo& gl = context->info();
        std::printf("renderer: gpu\ngl_renderer: %s\ncells: %zu (%zu x %zu)\ncell: %dx%d\nquality: %s\n",
            gl.renderer.c_str(), cells.size(), grid.rows.size(), grid.columns.size(), request.cellWidth,
            request.cellHeight, toString(request.project.environment.quality));
        std::printf("ibl_method: %s\n", toString(request.project.environment.method));
        std::printf("environments_loaded: %d\nibl_environments_prepared: %d\nibl_passes_run: %d\nibl_cache_hits_memory: "
                    "%d\nibl_cache_hits_disk: %d\nibl_ms: %.1f\n",
            cache.environmentLoads(), prepared, total.passesRun, total.cacheHitsMemory, total.cacheHitsDisk,
            total.msTotal);
        std::printf("textures_uploaded: %d\n", texturesUploaded);
        std::printf("load_ms: %.1f\nrender_ms: %.1f (%.1f a cell)\ntotal_ms: %.1f\n",
            std::chrono::duration<double, std::milli>(loadedAt - start).count(), renderMs,
            renderMs / double(cells.size()), std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    }
    return 0;
}

} // namespace facet
