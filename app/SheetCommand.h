#pragma once
// `facet sheet`: a contact sheet without a display, a labelled grid of renders of one project.
//
//   facet sheet [PROJECT.json|ASSET.glb] [--materials LIST] [--envs LIST] [--wedge AXIS=V1,V2,...]
//       [--wedge2 AXIS=...] [--mesh NAME|PATH] [--cell WxH] [--labels on|off] [--quality PRESET]
//       [--reference-view] [--stats] -o SHEET.(png|exr)
//
// Rows are the materials (or the first wedge axis), columns the environments (or the second
// wedge axis). Every cell is the project with that row's and that column's value, rendered
// exactly as `facet render` renders it (render/FrameRenderer, the same scene options), so a cell
// equals `facet render` of the same material and environment. PNG cells go through the project's
// view transform and the sheet gets text labels; EXR is linear radiance without labels, with the
// layout in its header (facet:rows, facet:columns, facet:cellWidth, facet:cellHeight,
// facet:rowLabels, facet:columnLabels: labels joined by '\n'). docs/app.md, "Contact sheets".

#include <optional>
#include <string>
#include <vector>

#include <QString>
#include <QStringList>

#include "core/material/Material.h"
#include "core/project/Project.h"
#include "core/project/WedgeAxis.h"

namespace facet {

// One row of materials: the material and its label.
struct SheetMaterial {
    std::string label;
    Material material;
};

struct SheetRequest {
    Project project; // the file or the built-in default, with --mesh and --quality applied
    std::vector<SheetMaterial> materials; // --materials (empty: the project's current material)
    std::optional<WedgeAxis> environments; // --envs, as an env axis
    std::optional<WedgeAxis> wedge; // --wedge: the rows
    std::optional<WedgeAxis> wedge2; // --wedge2: the columns
    std::string outputPath; // .png or .exr
    int cellWidth = 256;
    int cellHeight = 256;
    bool labels = true;
    bool referenceView = false;
    bool printStats = false;
    std::string saveProjectPath; // --save-project (app/SceneFlags.h): written before rendering
};

// The grid a request describes: per row and per column, a label and what it changes.
struct SheetGrid {
    struct Line {
        std::string label;
        const SheetMaterial* material = nullptr; // a material row
        const WedgeAxis* axis = nullptr; // an axis value (env, a factor, exposure)
        std::size_t index = 0; // the value of `axis`
    };

    // What `facet sheet` warns of before rendering: a wedge axis that sweeps nothing in any cell
    // ("--wedge clearcoatRoughness sweeps nothing: clearcoatRoughness shapes the clear coat, and the
    // material has none (clearcoat 0)"; WedgeAxis::noEffectReason).
    std::vector<std::string> sheetWarnings(const SheetRequest& request, const SheetGrid& grid);
    std::vector<Line> rows;
    std::vector<Line> columns;

    // The project of the cell (row, column): the request's project with the row's material made
    // current and both lines' values applied.
    Project cellProject(const SheetRequest& request, std::size_t row, std::size_t column) const;
};
SheetGrid sheetGrid(const SheetRequest& request);

class SheetCommand {
public:
    static constexpr int kExitFailure = 1;
    static constexpr int kExitUsage = 2;
    // Cells beyond this are refused: 16 x 16 is already a 4096-pixel sheet at the default size.
    static constexpr int kMaxCells = 256;
    static constexpr int kMaxCellSide = 4096;

    // `arguments` are what follows "sheet". nullopt with *exitCode 0 (--help, text in *error),
    // 1 (an input that cannot be read) or 2 (a bad flag, named in *error).
    static std::optional<SheetRequest> parse(const QStringList& arguments, QString* error, int* exitCode);
    static QString helpText();
    // Renders every cell and writes the sheet; messages to stderr, --stats to stdout. A missing
    // environment or material is named and nothing is written.
    static int run(const SheetRequest& request);
};

} // namespace facet
