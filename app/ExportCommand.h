#pragma once
// `facet export`: a project's materials written as engine texture sets (issue 11):
//
//   facet export PROJECT.json|ASSET.glb --format
//   unreal|unity-urp|unity-hdrp|godot|gltf-textures|TEMPLATE.json
//                [--material NAME|INDEX] [--size N] [--bit-depth 8|16|32] [--dry-run] [--force] -o OUT_DIR
//
// Each material (or the one --material names) becomes the files of an export template
// (core/export/ExportTemplate.h; the built-ins are resources/export/*.json), filled by
// core/export/TextureSetExport. Every file is written atomically; nothing in OUT_DIR is replaced without
// --force (checked before anything is written), and a failed export removes the files it had
// made. --dry-run lists the files and where each channel comes from, and writes nothing.
// docs/export.md.

#include <optional>
#include <string>

#include <QString>
#include <QStringList>

#include "core/export/TextureSetExport.h"

namespace facet {

struct ExportRequest {
    QStringList input; // the positional argument (none: the default project)
    std::string format; // "gltf", "glb", a built-in template's id or a template file's path
    std::string mesh; // --mesh (gltf and glb): a built-in mesh name or a mesh file; empty: the project's
    std::optional<std::string> material; // a name or an index; all when missing
    TextureSetOptions options;
    bool dryRun = false;
    bool force = false;
    std::string outputDirectory; // a folder, or for gltf and glb also the asset's path
};

class ExportCommand {
public:
    static constexpr int kExitFailure = 1;
    static constexpr int kExitUsage = 2;

    // `arguments` are what follows "export". nullopt with *exitCode 0 (--help, text in *error) or
    // 2 (a bad flag or value, named in *error).
    static std::optional<ExportRequest> parse(const QStringList& arguments, QString* error, int* exitCode);
    static QString helpText();
    // Loads the input and its maps, plans every set, then writes (or lists them with --dry-run).
    // 1 when the input, a map or the template cannot be read, a material is not there, a file
    // exists (without --force) or cannot be written (named).
    static int run(const ExportRequest& request);

private:
    static int runGltf(const ExportRequest& request);
};

} // namespace facet
