#include "ExportCommand.h"

#include "CommandInputs.h"
#include "CommandOptions.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QDir>
#include <QFileInfo>

#include <chrono>
#include <cstdio>

#include "core/export/ExportTemplate.h"
#include "core/gltf/GltfExport.h"
#include "core/project/ProjectAssets.h"

namespace facet {

namespace {

QString builtinList()
{
    QStringList names;
    for (const std::string& id : ExportTemplate::builtinIds())
        names.append(QString::fromStdString(id));
    return names.join(QStringLiteral(", "));
}

struct Options {
    QCommandLineParser parser;
    QCommandLineOption help {
        {QStringLiteral("h"), QStringLiteral("help")}, QStringLiteral("Displays this help.")};
    QCommandLineOption format {QStringLiteral("format"),
        QStringLiteral("What to write: gltf or glb (a glTF 2.0 asset: the materials on the mesh), a built-in "
                       "texture-set template (%1) or a template file (TEMPLATE.json, docs/export.md).")
            .arg(builtinList()),
        QStringLiteral("format")};
    QCommandLineOption material {QStringLiteral("material"),
        QStringLiteral("Export only this material: its name, or its index from 0 (default: every material)."),
        QStringLiteral("NAME|INDEX")};
    QCommandLineOption size {QStringLiteral("size"),
        QStringLiteral("The files' larger side in pixels, 1 to %1 (default: the material's largest map's; a "
                       "material without maps: 1x1).")
            .arg(TextureSetOptions::kMaxSize),
        QStringLiteral("N")};
    QCommandLineOption bitDepth {QStringLiteral("bit-depth"),
        QStringLiteral("8, 16 or 32 bits per channel for every file (default: the template's); the files' "
                       "format must hold it."),
        QStringLiteral("8|16|32")};
    QCommandLineOption mesh {QStringLiteral("mesh"),
        QStringLiteral(
            "The mesh a glTF asset carries (gltf and glb only): a built-in mesh (sphere, shaderball, "
            "...) or a mesh file (default: the project's)."),
        QStringLiteral("NAME|PATH")};
    QCommandLineOption dryRun {QStringLiteral("dry-run"),
        QStringLiteral("List the files and the source of each channel; write nothing.")};
    QCommandLineOption force {QStringLiteral("force"), QStringLiteral("Replace files already in OUT_DIR.")};
    QCommandLineOption output {{QStringLiteral("o"), QStringLiteral("output")},
        QStringLiteral("The folder to write into (made if missing); for gltf and glb also the asset's path "
                       "(.gltf, .glb)."),
        QStringLiteral("path")};

    Options()
    {
        parser.setApplicationDescription(QStringLiteral(
            "Exports a project's materials as engine texture sets: each material's factors and maps baked "
            "into the files of an export template (channel packing, normal convention, colour space, bit "
            "depth, size), named by the template's pattern."));
        for (const QCommandLineOption* option :
            {&help, &format, &material, &size, &bitDepth, &mesh, &dryRun, &force, &output})
            parser.addOption(*option);
        parser.addPositionalArgument(QStringLiteral("input"),
            QStringLiteral(
                "A project file (.json) or a glTF asset (.gltf, .glb); none: the default project."),
            QStringLiteral("[PROJECT.json|ASSET.glb]"));
    }
};

bool parseWholeNumber(
    const QString& flag, const QString& text, int minimum, int maximum, int* out, QString* error)
{
    bool ok = false;
    const int value = text.toInt(&ok);
    if (!ok || value < minimum || value > maximum) {
        *error = QStringLiteral("%1: '%2' is not a whole number from %3 to %4")
                     .arg(flag, text)
                     .arg(minimum)
                     .arg(maximum);
        return false;
    }
    *out = value;
    return true;
}

// The materials --material selects: its name (exact), else an index; all without it.
std::optional<std::vector<int>> selectMaterials(
    const Project& project, const std::optional<std::string>& selector, std::string* error)
{
    std::vector<int> indices;
    if (!selector) {
        for (int i = 0; i < int(project.materials.size()); ++i)
            indices.push_back(i);
        return indices;
    }
    for (int i = 0; i < int(project.materials.size()); ++i)
        if (project.materials[std::size_t(i)].name == *selector)
            return std::vector<int> {i};
    bool isIndex = false;
    const int index = QString::fromStdString(*selector).toInt(&isIndex);
    if (isIndex && index >= 0 && index < int(project.materials.size()))
        return std::vector<int> {index};
    std::string names;
    for (const Material& material : project.materials)
        names += (names.empty() ? "" : ", ") + material.name;
    *error = "--material: '" + *selector + "' is not a material of the input (its materials: " + names
        + "; or an index from 0 to " + std::to_string(project.materials.size() - 1) + ")";
    return std::nullopt;
}

} // namespace

int ExportCommand::runGltf(const ExportRequest& request)
{
    const auto fail = [](const std::string& message) {
        std::fprintf(stderr, "facet export: %s\n", message.c_str());
        return kExitFailure;
    };
    const auto start = std::chrono::steady_clock::now();
    QString inputError;
    const std::optional<Project> project
        = commandInputProject(request.input, QStringLiteral("export"), &inputError);
    if (!project)
        return fail(inputError.toStdString());
    std::string error;
    const std::optional<std::vector<int>> selected = selectMaterials(*project, request.material, &error);
    if (!selected)
        return fail(error);
    std::string warning;
    const std::optional<Mesh> mesh = loadViewMesh(
        request.mesh.empty() ? project->view.mesh : request.mesh, &error, &warning, project->view.keepUnits);
    if (!warning.empty())
        std::fprintf(stderr, "facet export: %s\n", warning.c_str());
    if (!mesh)
        return fail(error);
    std::vector<Material> materials;
    std::vector<int> partMaterials;
    if (request.material) {
        // One material, on every part.
        materials.push_back(project->materials[std::size_t(selected->front())]);
    } else {
        materials = project->materials;
        for (std::size_t part = 0; part < mesh->subMeshes.size(); ++part)
            partMaterials.push_back(project->materialOfPart(part));
    }

    // -o: the asset's path, or a folder to hold "<input's name>.gltf".
    const bool binary = request.format == "glb";
    std::string path = request.outputDirectory;
    const QString out = QString::fromStdString(path);
    if (!out.endsWith(QStringLiteral(".gltf"), Qt::CaseInsensitive)
        && !out.endsWith(QStringLiteral(".glb"), Qt::CaseInsensitive)) {
        QString stem = request.input.isEmpty() ? QStringLiteral("facet-material")
                                               : QFileInfo(request.input.first()).completeBaseName();
        if (stem.endsWith(QStringLiteral(".facet"))) // crate.facet.json: "crate"
            stem.chop(6);
        path = (QDir(out).filePath(stem + (binary ? QStringLiteral(".glb") : QStringLiteral(".gltf"))))
                   .toStdString();
    }
    GltfExportOptions options;
    options.binary = binary;
    options.textures = request.options;
    options.generator = "Facet " FACET_VERSION;
    options.source = viewMeshGltfFile(request.mesh.empty() ? project->view.mesh : request.mesh);
    if (request.dryRun) {
        const std::vector<std::string> files
            = gltfAssetFiles(path, materials, options, &error, mesh->hasTexCoord1);
        if (files.empty())
            return fail(error);
        std::printf("%s (glTF 2.0%s): %zu material%s on '%s', %zu files\n", path.c_str(),
            binary ? ", binary" : "", materials.size(), materials.size() == 1 ? "" : "s", mesh->name.c_str(),
            files.size());
        for (const std::string& file : files)
            std::printf("  %s\n", file.c_str());
        return 0;
    }
    std::vector<std::string> written;
    if (!writeGltfAsset(path, *mesh, partMaterials, materials, options, request.force, &written, &error)) {
        if (error.ends_with(": exists"))
            error += " (use --force to replace it)";
        return fail(error);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("facet export: wrote %s (%zu file%s, %zu material%s, %.2f s)\n", path.c_str(), written.size(),
        written.size() == 1 ? "" : "s", materials.size(), materials.size() == 1 ? "" : "s", seconds);
    return 0;
}

QString ExportCommand::helpText()
{
    Options options;
    return commandHelpText(options.parser, QStringLiteral("facet export"));
}

std::optional<ExportRequest> ExportCommand::parse(const QStringList& arguments, QString* error, int* exitCode)
{
    Options o;
    if (!parseCommandOptions(o, arguments, QStringLiteral("facet export"), kExitUsage, error, exitCode))
        return std::nullopt;
    ExportRequest request;
    request.input = o.parser.positionalArguments();
    if (!checkOneInput(request.input, error))
        return std::nullopt;
    if (!o.parser.isSet(o.format) || o.parser.value(o.format).isEmpty()) {
        *error = QStringLiteral("--format is required: %1, or a template file (TEMPLATE.json)")
                     .arg(builtinList());
        return std::nullopt;
    }
    const QString format = o.parser.value(o.format);
    const bool gltf = format == QStringLiteral("gltf") || format == QStringLiteral("glb");
    const bool isBuiltin = ExportTemplate::builtin(format.toStdString()).has_value();
    if (!gltf && !isBuiltin && !format.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive)) {
        *error = QStringLiteral("--format: '%1' is not gltf, glb, %2, or a template file (.json)")
                     .arg(format, builtinList());
        return std::nullopt;
    }
    request.format = format.toStdString();
    if (o.parser.isSet(o.mesh)) {
        if (!gltf) {
            *error = QStringLiteral(
                "--mesh: only a glTF asset (gltf, glb) carries a mesh; a texture set has none");
            return std::nullopt;
        }
        request.mesh = o.parser.value(o.mesh).toStdString();
    }
    if (gltf && o.parser.isSet(o.output)) {
        const QString out = o.parser.value(o.output);
        const bool gltfFile = out.endsWith(QStringLiteral(".gltf"), Qt::CaseInsensitive);
        const bool glbFile = out.endsWith(QStringLiteral(".glb"), Qt::CaseInsensitive);
        if ((gltfFile && format == QStringLiteral("glb")) || (glbFile && format == QStringLiteral("gltf"))) {
            *error = QStringLiteral("-o '%1': --format %2 writes a .%2 file").arg(out, format);
            return std::nullopt;
        }
    }
    if (o.parser.isSet(o.material))
        request.material = o.parser.value(o.material).toStdString();
    if (o.parser.isSet(o.size)
        && !parseWholeNumber(QStringLiteral("--size"), o.parser.value(o.size), 1, TextureSetOptions::kMaxSize,
            &request.options.size, error))
        return std::nullopt;
    if (o.parser.isSet(o.bitDepth)) {
        const QString text = o.parser.value(o.bitDepth);
        if (text != QStringLiteral("8") && text != QStringLiteral("16") && text != QStringLiteral("32")) {
            *error = QStringLiteral("--bit-depth: '%1' is not 8, 16 or 32").arg(text);
            return std::nullopt;
        }
        request.options.bitDepth = text.toInt();
    }
    request.dryRun = o.parser.isSet(o.dryRun);
    request.force = o.parser.isSet(o.force);
    if (!request.dryRun && (!o.parser.isSet(o.output) || o.parser.value(o.output).isEmpty())) {
        *error = QStringLiteral("-o OUT_DIR is required (or --dry-run)");
        return std::nullopt;
    }
    request.outputDirectory = o.parser.value(o.output).toStdString();
    return request;
}

int ExportCommand::run(const ExportRequest& request)
{
    const auto fail = [](const std::string& message) {
        std::fprintf(stderr, "facet export: %s\n", message.c_str());
        return kExitFailure;
    };
    const auto start = std::chrono::steady_clock::now();
    std::string error;
    if (request.format == "gltf" || request.format == "glb")
        return runGltf(request);
    std::optional<ExportTemplate> exportTemplate = ExportTemplate::builtin(request.format);
    if (!exportTemplate)
        exportTemplate = ExportTemplate::load(request.format, &error);
    if (!exportTemplate)
        return fail(error);

    QString inputError;
    const std::optional<Project> project
        = commandInputProject(request.input, QStringLiteral("export"), &inputError);
    if (!project)
        return fail(inputError.toStdString());
    const std::optional<std::vector<int>> selected = selectMaterials(*project, request.material, &error);
    if (!selected)
        return fail(error);

    std::vector<Material> materials;
    for (const int index : *selected)
        materials.push_back(project->materials[std::size_t(index)]);
    const std::optional<TextureSetExport> job
        = TextureSetExport::prepare(*exportTemplate, materials, request.options, &error);
    if (!job)
        return fail(error);
    if (request.dryRun) {
        std::fputs(job->describeAll().c_str(), stdout);
        return 0;
    }
    if (!job->write(request.outputDirectory, request.force, &error)) {
        if (error.ends_with(": exists"))
            error += " (use --force to replace it)";
        return fail(error);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("facet export: wrote %zu files for %zu material%s to %s (%s, %.2f s)\n",
        job->fileNames().size(), materials.size(), materials.size() == 1 ? "" : "s",
        request.outputDirectory.c_str(), exportTemplate->name.c_str(), seconds);
    return 0;
}

} // namespace facet
