#pragma once
// The document: materials on a mesh, under an environment and punctual lights, seen by a camera
// through a display transform, with the layout of the Compare modes; and its file format,
// "facet-project" version 3 (JSON, docs/project-format.md). Plain values (Tiled's libtiled
// model); the undoable editing lives in ui/.
//
// Files: paths (textures, environment image, mesh) are absolute in memory and stored relative to
// the project file's folder when on the same volume, so a project folder can be moved or shared;
// an environment or mesh inside an asset library is stored by the library's name instead
// ("library:installed/hdri/night.exr", core/project/AssetLibrary.h, json::storedSpec).
// Loading never crashes and never throws: every problem comes back as one message naming the
// function, the file and the JSON path, e.g.
//   "Project::load: /x/y.json: lights[1].intensity: expected a number, got a string".
// Out-of-range values are errors, not clamped: a project that loads is exactly what was saved, and
// a hand-edited typo is reported instead of silently becoming something else. Unknown keys are
// ignored with a warning (a newer Facet of the same format version may add optional fields).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <QJsonObject>

#include <glm/vec3.hpp>

#include "core/material/Material.h"
#include "core/project/Camera.h"
#include "core/project/CompareLayout.h"
#include "core/project/Light.h"
#include "core/shading/DebugView.h"

namespace facet {

enum class ToneMapper { None, Reinhard, Exposure, Aces, KhronosNeutral, AgX };
const char* toString(ToneMapper value); // "none", "reinhard", "exposure", "aces", "khronos-neutral", "agx"
std::optional<ToneMapper> toneMapperFromString(std::string_view name);

// How display-referred values are encoded for the screen (when no OCIO display is chosen).
enum class DisplayEncoding { SRGB, Gamma };
const char* toString(DisplayEncoding value); // "srgb" (the piecewise IEC 61966-2-1 curve), "gamma"
std::optional<DisplayEncoding> displayEncodingFromString(std::string_view name);

// What pixels that miss the mesh show.
// Transparent: the background is radiance 0 with alpha 0, so an image written with alpha has
// the object's coverage there (PNG straight alpha, EXR premultiplied); the viewport shows black.
enum class BackgroundMode { Environment, Blurred, Color, Transparent };
const char* toString(BackgroundMode value); // "environment", "blurred", "color", "transparent"
std::optional<BackgroundMode> backgroundModeFromString(std::string_view name);

// The IBL precompute quality preset (sizes and sample counts are render/'s, chosen on the
// time/error curve of `facet bench`).
enum class IblQuality { Draft, Default, High };
const char* toString(IblQuality value); // "draft", "default", "high"
std::optional<IblQuality> iblQualityFromString(std::string_view name);

// How the surface integrates the environment's light (docs/rendering.md, "IBL methods"):
// SplitSum: prefiltered radiance x DFG table, one lookup (the real-time default).
// Fis: filtered importance sampling of the pixel's own lobe: N visible-normal GGX samples per
//   pixel, each read from the environment's mip level of its footprint, with the BRDF evaluated
//   per sample; diffuse from the irradiance map. Deterministic (no noise), biased by the filter.
// Reference: Monte Carlo with multiple importance sampling of the BRDF and the environment, the
//   integral core/shading/GroundTruth computes; converges as frames accumulate.
enum class IblMethod { SplitSum, Fis, Reference };
const char* toString(IblMethod value); // "split-sum", "fis", "reference"
std::optional<IblMethod> iblMethodFromString(std::string_view name);
// Samples per pixel an IblMethod may be asked for (--ibl-samples, environment.samples).
inline constexpr int kMaxIblSamples = 65536;
// Fis's samples per pixel unless told: the fewest of `facet bench --sweep fis` (4 ... 256, five
// CC0 maps) meeting issue 10's targets, median <= 3% and worst <= 10% (256: 1.53% / 6.44%; 128
// misses with 11.4% on studio; docs/benchmarks.md, "IBL methods").
inline constexpr int kDefaultFisSamples = 256;
// The samples a method takes when none are given: Fis kDefaultFisSamples, Reference 1024 (its
// accuracy target's count, docs/accuracy.md), the split sum none.
int defaultIblSamples(IblMethod method);

struct ViewSettings {
    // 2^20 either way covers a candle-lit room to the midday sun with room to spare.
    static constexpr double kMinExposureEV = -20.0;
    static constexpr double kMaxExposureEV = 20.0;

    double exposureEV = 0.0; // scene radiance is multiplied by 2^exposureEV before tone mapping
    ToneMapper toneMapper = ToneMapper::KhronosNeutral;
    DisplayEncoding displayEncoding = DisplayEncoding::SRGB;
    double gamma = 2.2; // the display gamma when displayEncoding is Gamma; [1, 3]
    // An OCIO display/view pair (from $OCIO's config); both empty: Facet's own transform above.
    std::string ocioDisplay;
    std::string ocioView;
    DebugView debugView = DebugView::None; // core/shading/DebugView.h (None: the shaded image)
    // "sphere" (a built-in mesh name: lower-case letters, digits, '-') or a mesh file path.
    std::string mesh = "sphere";
    // False: the mesh is centred and scaled to the unit bounding sphere, which every built-in
    // camera frames (docs/meshes.md). True: the asset's own units and origin, for a camera given
    // in asset space (a glTF scene's, the render-fidelity harness's).
    bool keepUnits = false;
    int msaaSamples = 4; // 1 (off), 2, 4, 8 or 16
    BackgroundMode background = BackgroundMode::Environment;
    glm::dvec3 backgroundColor {0.18}; // linear Rec.709, >= 0, for BackgroundMode::Color
    double backgroundBlurRoughness = 0.5; // perceptual roughness of the blurred background, [0, 1]
    // The texel-density view's target (core/shading/DebugView.h TexelDensity): texels of the material's
    // map per unit of the mesh's source file (a metre for glTF), in (0, kMaxTexelDensity]. 512
    // texels a metre: a common target for third-person game assets (1024 for first-person).
    static constexpr double kMaxTexelDensity = 1.0e6;
    double texelDensityTarget = 512.0;

    // On failure: "<field>: <problem>" (the caller prefixes "view.").
    bool validate(std::string* problem) const;
    bool operator==(const ViewSettings&) const = default;
};

struct EnvironmentSettings {
    // What Environment::fromSpec() accepts: an image path, a built-in name ("studio", "sky"), a
    // library reference ("library:NAME/PATH", kept only when this computer lacks the library) or
    // "uniform:VALUE" / "uniform:R,G,B". Files store it with json::storedSpec.
    std::string source = "studio";
    double rotationDegrees = 0.0; // about +Y (docs/architecture.md)
    double intensity = 1.0; // linear radiance multiplier, >= 0 (the UI shows log2 as EV)
    IblQuality quality = IblQuality::Default;
    IblMethod method = IblMethod::SplitSum;
    // Samples per pixel for Reference, 1..kMaxIblSamples; 0: the method's default. The
    // split sum takes none (validate() refuses a count with it).
    int samples = 0;

    // On failure: "<field>: <problem>" (the caller prefixes "environment.").
    bool validate(std::string* problem) const;
    bool operator==(const EnvironmentSettings&) const = default;
};

// One part of the view's mesh (a sub-mesh, core/mesh/Mesh.h SubMesh, in the mesh's order): which of
// the project's materials it shows and whether it is drawn. A mesh part without an entry uses
// material 0 and is visible (a primitive or a single-part mesh needs no entries at all).
struct MeshPart {
    std::string name; // the sub-mesh's name when the entry was made (shown in the UI; informative)
    int material = 0; // index into Project::materials
    bool visible = true;
    bool operator==(const MeshPart&) const = default;
};

struct Project {
    static constexpr const char* kFormatName = "facet-project";
    // The version this Facet writes and the newest it reads. Bump it when a field changes meaning
    // or a required field appears; adding an optional field with a default does not need a bump
    // (older Facets ignore it with a warning). docs/project-format.md, "Versioning".
    // Version 2: several materials ("materials", "currentMaterial") and mesh parts ("parts");
    // version 1 files (one "material") still open.
    // Version 3: the compare layout ("compare", core/project/CompareLayout.h), whose A/B snapshot is a
    // material an older Facet would drop unseen on its next save; version 1 and 2 files open
    // with CompareLayout::defaultFor.
    // Version 4: the layered lobes (each material's "clearcoat"), which a version 3 Facet would
    // drop with a warning and then save the material without; version 1 to 3 files read with
    // the lobes off.
    // Version 5: the coat's textures: "clearcoat", "clearcoatRoughness" and "clearcoatNormal" are
    // maps like the core six (a version 4 Facet would read the coat's map as its {"factor",
    // "roughness"} and drop its texture); version 4's {"factor", "roughness"} still reads.
    // Version 6: KHR_materials_sheen, maps "sheenColor" and "sheenRoughness" (a version 5 Facet
    // would drop them with a warning and save the material without its sheen).
    // Version 7: KHR_materials_specular, maps "specular" and "specularColor" (a version 6 Facet
    // would drop them with a warning and save the material with the default layer).
    // Version 8: KHR_materials_anisotropy, the map "anisotropy" and the material's
    // "anisotropyRotationDegrees" (a version 7 Facet would drop both with a warning and save the
    // material isotropic).
    // Version 9: KHR_materials_iridescence, the maps "iridescence" and "iridescenceThickness" and
    // the material's "iridescenceIor" and "iridescenceThicknessMinimum" (a version 8 Facet would
    // drop them with a warning and save the material without its film).
    static constexpr int kFormatVersion = 9;
    // More is refused when loading: far beyond any asset an artist previews, and each material
    // costs a shader variant and its textures.
    static constexpr int kMaxMaterials = 4096;
    static constexpr int kMaxParts = 65536;
    // Larger files are refused before parsing: a project is a few kilobytes.
    static constexpr qint64 kMaxFileBytes = 16 * 1024 * 1024;

    // The materials (at least one); the docks edit materials[currentMaterial] (material()).
    std::vector<Material> materials {Material {}};
    int currentMaterial = 0;
    // Per sub-mesh of the view's mesh, in order; see MeshPart.
    std::vector<MeshPart> parts;
    EnvironmentSettings environment;
    std::vector<Light> lights;
    Camera camera; // the reference view by default
    ViewSettings view;
    // What the Compare modes show (mode, environment grid, A/B, wedge); CompareLayout::defaultFor
    // when a file has none.
    CompareLayout compare;

    // The material the docks edit. Q_ASSERTs that currentMaterial is in range (validate() checks it).
    Material& material();
    const Material& material() const;
    // The material of sub-mesh `part` (MeshPart rule: material 0 without an entry; an index out of
    // range also falls back to 0), and whether it is drawn.
    int materialOfPart(std::size_t part) const;
    bool isPartVisible(std::size_t part) const;

    // File > New: a glossy red-orange plastic on the sphere in the studio environment, reference
    // camera, no punctual lights (the studio's soft boxes light it, and the no-light shader
    // variant is the cheapest).
    static Project defaultProject();

    // On failure: "<json path>: <problem>", e.g. "lights[0].intensity: -1 must be ...".
    bool validate(std::string* problem) const;

    // JSON without a file. baseDir: the folder paths are made relative to (toJson) or resolved
    // against (fromJson); empty leaves paths as they are. fromJson's messages start with
    // "Project::fromJson: "; `warning` (optional) receives ignored-key notes, one per line.
    QJsonObject toJson(const std::string& baseDir = {}) const;
    static std::optional<Project> fromJson(const QJsonObject& object, const std::string& baseDir,
        std::string* error, std::string* warning = nullptr);

    // Writes through writeFileAtomically (core/support/AtomicFile.h: a checked temporary file, then an
    // atomic rename): on any failure, a full disk included, the file at `path` is untouched.
    // Refuses an invalid project (validate()).
    bool save(const std::string& path, std::string* error) const;
    static std::optional<Project> load(
        const std::string& path, std::string* error, std::string* warning = nullptr);

    bool operator==(const Project&) const = default;
};

// What a converging render of `project` sums: the project with what only changes how the sum is
// shown or named at defaults (the display transform: exposure, tone mapper, encoding, gamma, OCIO
// display and view; the compare layout; the names of materials and lights). Two projects equal
// by this need no new samples, only a new display of the ones summed (the window's refinement,
// the error view's reference).
Project withoutDisplaySettings(Project project);

// Material <-> the JSON object of project files and material presets (docs/project-format.md,
// "material"). includeTexturePaths false leaves texture paths out (presets by default).
QJsonObject materialToJson(
    const Material& material, const std::string& baseDir, bool includeTexturePaths = true);
// Reads and validates a material object. Messages start at the JSON path (`jsonPath`, e.g.
// "material"): "material.roughness.factor: expected a number, got a string"; the caller adds its
// "Function: file: " prefix. Warnings (ignored keys) are appended to *warning, one per line.
std::optional<Material> materialFromJson(const QJsonObject& object, const std::string& baseDir,
    const std::string& jsonPath, std::string* error, std::string* warning = nullptr);

// Building blocks shared by project and preset files.
namespace json {
// A path as a file stores it: relative to baseDir (with '/' separators) when both are on the same
// volume, else absolute. Empty stays empty; an empty baseDir changes nothing.
std::string storedPath(const std::string& path, const std::string& baseDir);
// The inverse: a relative path is resolved against baseDir and cleaned.
std::string resolvedPath(const std::string& path, const std::string& baseDir);
// A "spec" (environment source, mesh) is a built-in name (lower-case letters, digits and '-', or
// "uniform:...") kept as is, a library reference ("library:NAME/PATH", core/project/AssetLibrary.h), or
// a path. storedSpec writes a file inside a library's folder as its library reference (when
// baseDir is not empty), other files as storedPath does, and a relative path that would read as a
// name or a reference as "./path". resolvedSpec turns a reference into this machine's path (one
// to a library this machine lacks stays a reference) and a path as resolvedPath does; a
// version-1 path into the installed samples that leads nowhere is redirected to the installed
// library when it has that file (docs/project-format.md, "Paths").
std::string storedSpec(const std::string& spec, const std::string& baseDir);
std::string resolvedSpec(const std::string& spec, const std::string& baseDir);
bool isBuiltinSpec(const std::string& spec);
// Checks the "format" and "version" keys of a file's top-level object: format must equal
// `formatName` and version be an integer in [1, newestVersion]. `what` names the kind of file in
// messages ("a Facet project"). A newer version gives "written by a newer Facet (version 3);
// this Facet reads up to version 1".
bool checkFormat(const QJsonObject& object, const char* formatName, int newestVersion, const char* what,
    std::string* problem);
// Reads a file holding one JSON object. On failure returns nullopt and sets *problem (no prefix)
// to e.g. "no such file", "the file is empty", "line 3, column 7: unterminated string".
std::optional<QJsonObject> readObjectFile(const std::string& path, qint64 maxBytes, std::string* problem);
// Writes `object` (indented) through writeFileAtomically (core/support/AtomicFile.h). On failure the old
// file is untouched and *problem says why, e.g. "cannot write it: No space left on device".
bool writeObjectFile(const std::string& path, const QJsonObject& object, std::string* problem);
} // namespace json

} // namespace facet
