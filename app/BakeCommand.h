#pragma once
// `facet bake`: an environment's image-based lighting written as files, for engines that take
// their own IBL (issue 11):
//
//   facet bake ENV.(exr|hdr)|NAME [--quality PRESET] [--ibl-size N] [--force] -o OUT_DIR
//
// What the renderer itself shades with (render/IblPrecompute, the same passes and settings, read
// back from the GPU): every level of the prefiltered specular cubemap, the irradiance cubemap and
// its 9 SH coefficients, and the split-sum DFG table of each visibility term, as linear float
// EXR files (one file a cube face), and `ibl.json`, the index with the conventions an engine
// needs: axes and face order, the level-to-roughness map, what each channel holds. Every file is
// written atomically (core/support/AtomicFile); files already in OUT_DIR are not replaced without
// --force, and a failed bake removes the files it had written, so a folder holds a whole bake or
// what it held before. docs/app.md, "Baking IBL".

#include <optional>
#include <string>
#include <vector>

#include <QString>
#include <QStringList>

#include "render/IblSettings.h"

namespace facet {

struct BakeRequest {
    std::string environmentSpec; // as Environment::fromSpec takes it (installed CC0 names expanded)
    std::string quality = "default";
    IblSettings settings; // the preset, with --ibl-size applied
    std::string outputDirectory;
    bool force = false;
};

class BakeCommand {
public:
    static constexpr int kExitFailure = 1;
    static constexpr int kExitUsage = 2;
    static constexpr int kMinIblSize = 16;
    static constexpr int kMaxIblSize = 2048;
    static constexpr const char* kIndexName = "ibl.json";
    static constexpr const char* kFormatName = "facet-ibl-bake";
    static constexpr int kFormatVersion = 1;

    // `arguments` are what follows "bake". nullopt with *exitCode 0 (--help, text in *error) or 2
    // (a bad flag or value, named in *error).
    static std::optional<BakeRequest> parse(const QStringList& arguments, QString* error, int* exitCode);
    static QString helpText();
    // Bakes and writes; messages to stderr, a summary to stdout. 1 when the environment cannot be
    // read, the GL fails, a file exists (without --force) or cannot be written (named).
    static int run(const BakeRequest& request);
};

// The cube faces' names in OpenGL order (+X, -X, +Y, -Y, +Z, -Z), as the file names use them.
const std::vector<std::string>& bakeFaceNames();
// The files a bake with `prefilteredLevels` levels writes, the index last.
std::vector<std::string> bakeFileNames(int prefilteredLevels);

} // namespace facet
