#include "BakeCommand.h"

#include "CommandInputs.h"
#include "CommandOptions.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <array>
#include <chrono>
#include <cstdio>
#include <memory>

#include "core/ibl/Environment.h"
#include "core/image/Image.h"
#include "core/support/AtomicFile.h"
#include "core/support/FileSet.h"
#include "render/DfgLut.h"
#include "render/GLTexture.h"
#include "render/HeadlessGLContext.h"
#include "render/IblPrecompute.h"
#include "render/IblTextures.h"

namespace facet {

namespace {

struct Options {
    QCommandLineParser parser;
    QCommandLineOption help {
        {QStringLiteral("h"), QStringLiteral("help")}, QStringLiteral("Displays this help.")};
    QCommandLineOption quality {QStringLiteral("quality"),
        QStringLiteral("IBL quality preset: draft, default (the default) or high: the sizes and samples the "
                       "renderer uses."),
        QStringLiteral("preset")};
    QCommandLineOption iblSize {QStringLiteral("ibl-size"),
        QStringLiteral("The prefiltered cubemap's level-0 face size, %1 to %2 (default: the preset's). The "
                       "environment cube grows to it; neither exceeds twice the image's own resolution "
                       "(ibl.json says what was made).")
            .arg(BakeCommand::kMinIblSize)
            .arg(BakeCommand::kMaxIblSize),
        QStringLiteral("N")};
    QCommandLineOption cubeSize {QStringLiteral("cube-size"),
        QStringLiteral(
            "The environment cube's level-0 face size, %1 to %2, at least --ibl-size (default: the "
            "preset's, grown to --ibl-size). Like --ibl-size, at most twice the image's width / 4.")
            .arg(BakeCommand::kMinIblSize)
            .arg(BakeCommand::kMaxIblSize),
        QStringLiteral("N")};
    QCommandLineOption samples {QStringLiteral("samples"),
        QStringLiteral(
            "GGX samples per texel of the prefiltered levels, 1 to 65536 (default: the preset's)."),
        QStringLiteral("N")};
    QCommandLineOption force {
        QStringLiteral("force"), QStringLiteral("Replace files of an earlier bake in OUT_DIR.")};
    QCommandLineOption output {{QStringLiteral("o"), QStringLiteral("output")},
        QStringLiteral("The folder to write into (made if missing)."), QStringLiteral("dir")};

    Options()
    {
        parser.setApplicationDescription(QStringLiteral(
            "Bakes an environment's image-based lighting as the renderer computes it: every level of the "
            "prefiltered specular cubemap, the irradiance cubemap and its SH9 coefficients, and the "
            "split-sum "
            "DFG table of each visibility term, as linear EXR files (one a cube face), with ibl.json, the "
            "index and its conventions."));
        for (const QCommandLineOption* option :
            {&help, &quality, &iblSize, &cubeSize, &samples, &force, &output})
            parser.addOption(*option);
        parser.addPositionalArgument(QStringLiteral("environment"),
            QStringLiteral(
                "An equirect image (.exr, .hdr, ...), a built-in name (studio, sky), an installed CC0 "
                "sample's name (night, ...), a library reference or uniform:VALUE."),
            QStringLiteral("ENV.(exr|hdr)|NAME"));
    }
};

std::string prefilteredName(int level, const std::string& face)
{
    return "prefiltered_m" + std::to_string(level) + "_" + face + ".exr";
}

std::string irradianceName(const std::string& face)
{
    return "irradiance_" + face + ".exr";
}

std::string dfgName(Visibility visibility)
{
    return std::string("dfg_") + toString(visibility) + ".exr";
}

// One level of a texture (one face of a cubemap) as read back: GL's row 0 (t = 0) is the image's
// first (top) row, as ibl.json says.
Image levelImage(const GLTexture& texture, int face, int level)
{
    int width = 0;
    int height = 0;
    const std::vector<float> texels = readTextureLevel(texture, face, level, &width, &height);
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float* t = &texels[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4];
            image.at(x, y) = glm::vec4(t[0], t[1], t[2], t[3]);
        }
    return image;
}

QJsonArray vec3Array(const glm::vec3& v)
{
    return QJsonArray {double(v.x), double(v.y), double(v.z)};
}

} // namespace

const std::vector<std::string>& bakeFaceNames()
{
    static const std::vector<std::string> names = {"px", "nx", "py", "ny", "pz", "nz"};
    return names;
}

std::vector<std::string> bakeFileNames(int prefilteredLevels)
{
    std::vector<std::string> names;
    for (int level = 0; level < prefilteredLevels; ++level)
        for (const std::string& face : bakeFaceNames())
            names.push_back(prefilteredName(level, face));
    for (const std::string& face : bakeFaceNames())
        names.push_back(irradianceName(face));
    for (int v = 0; v < kVisibilityCount; ++v)
        names.push_back(dfgName(Visibility(v)));
    names.push_back(BakeCommand::kIndexName);
    return names;
}

QString BakeCommand::helpText()
{
    Options options;
    return commandHelpText(options.parser, QStringLiteral("facet bake"));
}

std::optional<BakeRequest> BakeCommand::parse(const QStringList& arguments, QString* error, int* exitCode)
{
    Options o;
    if (!parseCommandOptions(o, arguments, QStringLiteral("facet bake"), kExitUsage, error, exitCode))
        return std::nullopt;
    const QStringList positional = o.parser.positionalArguments();
    if (positional.isEmpty()) {
        *error
            = QStringLiteral("an environment is required: an image file, a built-in name (studio, sky) or an "
                             "installed CC0 sample's name");
        return std::nullopt;
    }
    if (positional.size() > 1) {
        *error = QStringLiteral("one environment at a time, got %1: %2")
                     .arg(positional.size())
                     .arg(positional.join(QStringLiteral(", ")));
        return std::nullopt;
    }
    BakeRequest request;
    request.environmentSpec = expandInstalledName(positional.first().trimmed()).toStdString();
    std::string problem;
    if (!Environment::checkSpec(request.environmentSpec, &problem)) {
        *error = QString::fromStdString(problem);
        return std::nullopt;
    }
    if (!o.parser.isSet(o.output) || o.parser.value(o.output).isEmpty()) {
        *error = QStringLiteral("-o OUT_DIR is required");
        return std::nullopt;
    }
    request.outputDirectory = o.parser.value(o.output).toStdString();
    if (o.parser.isSet(o.quality))
        request.quality = o.parser.value(o.quality).toStdString();
    const std::optional<IblSettings> settings = IblSettings::preset(request.quality);
    if (!settings) {
        QStringList names;
        for (const std::string& name : IblSettings::presetNames())
            names.append(QString::fromStdString(name));
        *error = QStringLiteral("--quality: '%1' is not %2")
                     .arg(QString::fromStdString(request.quality), names.join(QStringLiteral(", ")));
        return std::nullopt;
    }
    request.settings = *settings;
    // A whole-number option within [low, high]; nullopt with *error naming it otherwise.
    const auto wholeNumber = [&](const QCommandLineOption& option, int low, int high) -> std::optional<int> {
        bool ok = false;
        const QString text = o.parser.value(option);
        const int value = text.toInt(&ok);
        if (ok && value >= low && value <= high)
            return value;
        *error = QStringLiteral("--%1: '%2' is not a whole number from %3 to %4")
                     .arg(option.names().constFirst(), text)
                     .arg(low)
                     .arg(high);
        return std::nullopt;
    };
    if (o.parser.isSet(o.iblSize)) {
        const std::optional<int> size = wholeNumber(o.iblSize, kMinIblSize, kMaxIblSize);
        if (!size)
            return std::nullopt;
        request.settings.prefilterSize = *size;
        request.settings.cubeSize = std::max(request.settings.cubeSize, *size);
    }
    if (o.parser.isSet(o.cubeSize)) {
        const std::optional<int> size = wholeNumber(o.cubeSize, kMinIblSize, kMaxIblSize);
        if (!size)
            return std::nullopt;
        if (*size < request.settings.prefilterSize) {
            *error = QStringLiteral("--cube-size: %1 is smaller than the prefiltered cube (%2): the "
                                    "prefiltered levels are read from the environment cube")
                         .arg(*size)
                         .arg(request.settings.prefilterSize);
            return std::nullopt;
        }
        request.settings.cubeSize = *size;
    }
    if (o.parser.isSet(o.samples)) {
        const std::optional<int> count = wholeNumber(o.samples, 1, 65536);
        if (!count)
            return std::nullopt;
        request.settings.prefilterSamples = *count;
    }
    request.force = o.parser.isSet(o.force);
    return request;
}

int BakeCommand::run(const BakeRequest& request)
{
    const auto fail = [](const std::string& message) {
        std::fprintf(stderr, "facet bake: %s\n", message.c_str());
        return kExitFailure;
    };
    const auto start = std::chrono::steady_clock::now();
    std::string error;
    std::string warning;
    const std::optional<Environment> environment
        = Environment::fromSpec(request.environmentSpec, &error, &warning);
    if (!warning.empty())
        std::fprintf(stderr, "facet bake: %s\n", warning.c_str());
    if (!environment)
        return fail(error);

    const QString folder = QString::fromStdString(request.outputDirectory);
    const QFileInfo folderInfo(folder);
    if (folderInfo.exists() && !folderInfo.isDir())
        return fail(request.outputDirectory + ": is not a folder");
    if (!QDir().mkpath(folder))
        return fail(request.outputDirectory + ": cannot make the folder");

    // A surfaceless EGL context: no display server needed (docs/architecture.md, "OpenGL without a display").
    // The precompute and its textures go before it.
    auto context = HeadlessGLContext::create(&error);
    if (!context)
        return fail(error);
    IblPrecompute precompute(QString(), /*useDiskCache=*/false); // leaves the user's cache alone
    IblStats stats;
    const std::shared_ptr<const IblTextures> ibl
        = precompute.prepare(*environment, request.settings, &stats, &error);
    if (!ibl || !ibl->prefiltered || !ibl->irradiance)
        return fail(error.empty() ? "the IBL precompute made no textures" : error);
    std::array<std::shared_ptr<const DfgLut>, kVisibilityCount> tables;
    for (int v = 0; v < kVisibilityCount; ++v)
        if (!(tables[std::size_t(v)] = precompute.dfgTable(request.settings, Visibility(v), &stats, &error)))
            return fail(error);

    // Nothing is written over an earlier bake without --force; the check comes before any write.
    FileSet written(request.outputDirectory);
    const int levels = ibl->prefilteredMipLevels;
    const std::vector<std::string> names = bakeFileNames(levels);
    if (!request.force)
        if (const std::vector<std::string> existing = written.existing(names); !existing.empty())
            return fail(existing.front() + ": exists (use --force to replace the bake)");

    // All or nothing (core/support/FileSet.h): a bake replaced with --force is the whole new one or the
    // old one, never some files of each beside an ibl.json that describes one of them.
    if (!written.begin(&error))
        return fail(request.outputDirectory + ": " + error);
    const auto save = [&](const Image& image, const std::string& name, bool alpha) {
        if (!image.save(written.stagedPath(name), &error, alpha)) {
            error = written.named(error);
            return false;
        }
        written.written(name);
        return true;
    };
    const std::vector<std::string>& faces = bakeFaceNames();
    QJsonArray prefilteredFiles;
    QJsonArray levelRoughness;
    for (int level = 0; level < levels; ++level) {
        QJsonArray levelFiles;
        for (int face = 0; face < 6; ++face) {
            const std::string name = prefilteredName(level, faces[std::size_t(face)]);
            if (!save(levelImage(*ibl->prefiltered, face, level), name, /*alpha=*/false)) {
                return fail(error);
            }
            levelFiles.append(QString::fromStdString(name));
        }
        prefilteredFiles.append(levelFiles);
        levelRoughness.append(roughnessFromLod(level, levels));
    }
    QJsonArray irradianceFiles;
    for (int face = 0; face < 6; ++face) {
        const std::string name = irradianceName(faces[std::size_t(face)]);
        if (!save(levelImage(*ibl->irradiance, face, 0), name, /*alpha=*/false)) {
            return fail(error);
        }
        irradianceFiles.append(QString::fromStdString(name));
    }
    QJsonArray dfgTables;
    for (int v = 0; v < kVisibilityCount; ++v) {
        const DfgLut& table = *tables[std::size_t(v)];
        const std::string name = dfgName(Visibility(v));
        if (!save(levelImage(*table.texture, 0, 0), name, /*alpha=*/true)) {
            return fail(error);
        }
        dfgTables.append(
            QJsonObject {{QStringLiteral("visibility"), QString::fromLatin1(toString(Visibility(v)))},
                {QStringLiteral("file"), QString::fromStdString(name)}});
    }
    QJsonArray sh;
    for (const glm::vec3& c : ibl->irradianceSH)
        sh.append(vec3Array(c));

    const IblSettings& s = request.settings;
    QJsonObject index {
        {QStringLiteral("format"), QString::fromLatin1(kFormatName)},
        {QStringLiteral("version"), kFormatVersion},
        {QStringLiteral("source"), QString::fromStdString(request.environmentSpec)},
        {QStringLiteral("quality"), QString::fromStdString(request.quality)},
        {QStringLiteral("conventions"),
            QJsonObject {
                {QStringLiteral("frame"),
                    QStringLiteral(
                        "Directions in the environment image's frame, unrotated, at intensity 1 (Facet turns "
                        "the environment about +Y and scales it at shading time). World right-handed, +Y "
                        "up; equirect u = atan2(d.z, d.x) / (2 pi) + 0.5, v = asin(d.y) / pi + 0.5, v = 1 "
                        "the image's top row (docs/architecture.md).")},
                {QStringLiteral("faces"),
                    QJsonArray {QStringLiteral("px"), QStringLiteral("nx"), QStringLiteral("py"),
                        QStringLiteral("ny"), QStringLiteral("pz"), QStringLiteral("nz")}},
                {QStringLiteral("faceOrientation"),
                    QStringLiteral(
                        "OpenGL cube map faces +X, -X, +Y, -Y, +Z, -Z (OpenGL 4.6 core, table 8.19): a face "
                        "file's first (top) row is the face's t = 0 row and its first column s = 0, as "
                        "glTexImage2D takes them.")},
                {QStringLiteral("values"),
                    QStringLiteral(
                        "Linear scene-referred radiance, Rec.709 primaries, float RGB (the GPU's RGBA16F "
                        "values).")},
            }},
        {QStringLiteral("prefiltered"),
            QJsonObject {
                {QStringLiteral("size"), ibl->prefilteredSize},
                {QStringLiteral("levels"), levels},
                {QStringLiteral("samples"), s.prefilterSamples},
                {QStringLiteral("lodFromRoughness"),
                    QStringLiteral(
                        "lod = (levels - 1) r (2 - r), r the perceptual roughness (alpha = r^2); level 0 "
                        "is the environment itself (r = 0)")},
                {QStringLiteral("levelRoughness"), levelRoughness},
                {QStringLiteral("lobe"),
                    QStringLiteral(
                        "GGX D(h) with n = v = r (Karis 2013 split sum), weighted by n.l; read it along the "
                        "reflected direction (Facet leans it towards n for rough lobes: docs/ibl.md "
                        "\"Dominant direction\")")},
                {QStringLiteral("files"), prefilteredFiles},
            }},
        {QStringLiteral("irradiance"),
            QJsonObject {
                {QStringLiteral("size"), ibl->irradianceSize},
                {QStringLiteral("meaning"),
                    QStringLiteral(
                        "E(n) = integral of L(w) max(0, n.w) dw, NOT divided by pi: a Lambertian surface "
                        "of albedo c reflects c / pi * E(n)")},
                {QStringLiteral("files"), irradianceFiles},
                {QStringLiteral("sh9"),
                    QJsonObject {
                        {QStringLiteral("coefficients"), sh},
                        {QStringLiteral("basis"),
                            QStringLiteral(
                                "E(n) = c0 0.282095 + c1 0.488603 y + c2 0.488603 z + c3 0.488603 x + c4 "
                                "1.092548 x y + c5 1.092548 y z + c6 0.315392 (3 z^2 - 1) + c7 1.092548 x z "
                                "+ c8 0.546274 (x^2 - y^2), n = (x, y, z); the cosine lobe's A_l is "
                                "already in c_i")},
                    }},
            }},
        {QStringLiteral("dfg"),
            QJsonObject {
                {QStringLiteral("size"), tables[0]->size},
                {QStringLiteral("samples"), tables[0]->sampleCount},
                {QStringLiteral("axes"),
                    QStringLiteral(
                        "x (columns) = n.v, y (rows, the first row 0) = perceptual roughness; texel i "
                        "holds the value at i / (size - 1), so read it at (value (size - 1) + 0.5) / "
                        "size")},
                {QStringLiteral("channels"),
                    QStringLiteral(
                        "R scale, G bias (specular albedo = F0 R + G, Karis 2013), B E = R + G (the lobe's "
                        "albedo with F = 1, for multiple-scattering compensation), A W(n.v) (the share of "
                        "a Lambertian base glTF's fresnel_mix passes)")},
                {QStringLiteral("tables"), dfgTables},
            }},
        {QStringLiteral("settings"),
            QJsonObject {
                {QStringLiteral("environmentCubeSize"), ibl->environmentSize},
                {QStringLiteral("irradianceSamples"), s.irradianceSamples},
                {QStringLiteral("dfgSamples"), s.dfgSamples},
            }},
    };
    const std::string indexPath = written.path(kIndexName);
    std::string reason;
    if (!writeFileAtomically(written.stagedPath(kIndexName),
            QJsonDocument(index).toJson(QJsonDocument::Indented).toStdString(), &reason))
        return fail(indexPath + ": cannot write it: " + reason);
    written.written(kIndexName);
    if (!written.commit(&reason))
        return fail(reason);

    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "facet bake: wrote %zu files to %s: prefiltered %d x %d levels, irradiance %d and SH9, DFG %d x %d "
        "(%s, %s, %.2f s)\n",
        names.size(), request.outputDirectory.c_str(), ibl->prefilteredSize, levels, ibl->irradianceSize,
        tables[0]->size, kVisibilityCount, request.environmentSpec.c_str(), request.quality.c_str(), seconds);
    return 0;
}

} // namespace facet
