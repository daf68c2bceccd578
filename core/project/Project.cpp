#include "core/project/Project.h"

#include "core/shading/DebugView.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <utility>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonValue>
#include <QSet>

#include "core/ibl/Environment.h"
#include "core/image/ColorManagement.h"
#include "core/json/JsonReader.h"
#include "core/json/JsonSupport.h"
#include "core/material/MaterialJson.h"
#include "core/support/EnumNames.h"
#include "core/support/Finite.h"

namespace facet {

namespace {

using namespace jsonsupport;

constexpr std::pair<ToneMapper, const char*> kToneMappers[] = {{ToneMapper::None, "none"},
    {ToneMapper::Reinhard, "reinhard"}, {ToneMapper::Exposure, "exposure"}, {ToneMapper::Aces, "aces"},
    {ToneMapper::KhronosNeutral, "khronos-neutral"}, {ToneMapper::AgX, "agx"}};
constexpr std::pair<DisplayEncoding, const char*> kDisplayEncodings[]
    = {{DisplayEncoding::SRGB, "srgb"}, {DisplayEncoding::Gamma, "gamma"}};
constexpr std::pair<BackgroundMode, const char*> kBackgroundModes[]
    = {{BackgroundMode::Environment, "environment"}, {BackgroundMode::Blurred, "blurred"},
        {BackgroundMode::Color, "color"}, {BackgroundMode::Transparent, "transparent"}};
constexpr std::pair<IblQuality, const char*> kIblQualities[]
    = {{IblQuality::Draft, "draft"}, {IblQuality::Default, "default"}, {IblQuality::High, "high"}};
constexpr std::pair<IblMethod, const char*> kIblMethods[]
    = {{IblMethod::SplitSum, "split-sum"}, {IblMethod::Fis, "fis"}, {IblMethod::Reference, "reference"}};

// ---- Value types <-> JSON ---------------------------------------------------------------

constexpr std::pair<LightType, const char*> kLightTypeNames[]
    = {{LightType::Directional, "directional"}, {LightType::Point, "point"}, {LightType::Spot, "spot"}};
QJsonObject lightToJson(const Light& light)
{
    QJsonObject o;
    o[QLatin1String("name")] = qs(light.name);
    o[QLatin1String("type")] = QLatin1String(toString(light.type));
    o[QLatin1String("enabled")] = light.enabled;
    o[QLatin1String("color")] = toArray(light.color);
    o[QLatin1String("useTemperature")] = light.useTemperature;
    o[QLatin1String("kelvin")] = light.kelvin;
    o[QLatin1String("intensity")] = light.intensity;
    o[QLatin1String("range")] = light.range;
    o[QLatin1String("innerConeAngle")] = light.innerConeAngle;
    o[QLatin1String("outerConeAngle")] = light.outerConeAngle;
    o[QLatin1String("position")] = toArray(light.position);
    o[QLatin1String("direction")] = toArray(light.direction);
    return o;
}

void readLight(Messages& messages, const QJsonObject& object, const std::string& path, Light& light)
{
    ObjectReader r(messages, object, path);
    r.string("name", light.name);
    r.enumeration("type", light.type, kLightTypeNames);
    r.boolean("enabled", light.enabled);
    r.vec3("color", light.color);
    r.boolean("useTemperature", light.useTemperature);
    r.number("kelvin", light.kelvin);
    r.number("intensity", light.intensity);
    r.number("range", light.range);
    r.number("innerConeAngle", light.innerConeAngle);
    r.number("outerConeAngle", light.outerConeAngle);
    r.vec3("position", light.position);
    r.vec3("direction", light.direction);
    r.warnAboutUnknownKeys();
}

QJsonObject environmentToJson(const EnvironmentSettings& environment, const std::string& baseDir)
{
    QJsonObject o;
    o[QLatin1String("source")] = qs(json::storedSpec(environment.source, baseDir));
    o[QLatin1String("rotationDegrees")] = environment.rotationDegrees;
    o[QLatin1String("intensity")] = environment.intensity;
    o[QLatin1String("quality")] = QLatin1String(toString(environment.quality));
    // Written only when they say something: a split-sum project stays the file an older Facet
    // wrote and reads (it would warn about unknown keys).
    if (environment.method != IblMethod::SplitSum)
        o[QLatin1String("method")] = QLatin1String(toString(environment.method));
    if (environment.samples != 0)
        o[QLatin1String("samples")] = environment.samples;
    return o;
}

void readEnvironment(Messages& messages, const QJsonObject& object, const std::string& path,
    const std::string& baseDir, EnvironmentSettings& environment)
{
    ObjectReader r(messages, object, path);
    std::string source = environment.source;
    r.string("source", source);
    environment.source = json::resolvedSpec(source, baseDir);
    r.number("rotationDegrees", environment.rotationDegrees);
    r.number("intensity", environment.intensity);
    r.enumeration("quality", environment.quality, kIblQualities);
    r.enumeration("method", environment.method, kIblMethods);
    r.integer("samples", environment.samples);
    r.warnAboutUnknownKeys();
}

QJsonObject viewToJson(const ViewSettings& view, const std::string& baseDir)
{
    QJsonObject o;
    o[QLatin1String("exposureEV")] = view.exposureEV;
    o[QLatin1String("toneMapper")] = QLatin1String(toString(view.toneMapper));
    o[QLatin1String("displayEncoding")] = QLatin1String(toString(view.displayEncoding));
    o[QLatin1String("gamma")] = view.gamma;
    o[QLatin1String("ocioDisplay")] = qs(view.ocioDisplay);
    o[QLatin1String("ocioView")] = qs(view.ocioView);
    o[QLatin1String("debugView")] = QLatin1String(toString(view.debugView));
    o[QLatin1String("mesh")] = qs(json::storedSpec(view.mesh, baseDir));
    o[QLatin1String("keepUnits")] = view.keepUnits;
    o[QLatin1String("msaaSamples")] = view.msaaSamples;
    o[QLatin1String("background")] = QLatin1String(toString(view.background));
    o[QLatin1String("backgroundColor")] = toArray(view.backgroundColor);
    o[QLatin1String("backgroundBlurRoughness")] = view.backgroundBlurRoughness;
    o[QLatin1String("texelDensityTarget")] = view.texelDensityTarget;
    return o;
}

void readView(Messages& messages, const QJsonObject& object, const std::string& path,
    const std::string& baseDir, ViewSettings& view)
{
    ObjectReader r(messages, object, path);
    r.number("exposureEV", view.exposureEV);
    r.enumeration("toneMapper", view.toneMapper, kToneMappers);
    r.enumeration("displayEncoding", view.displayEncoding, kDisplayEncodings);
    r.number("gamma", view.gamma);
    r.string("ocioDisplay", view.ocioDisplay);
    r.string("ocioView", view.ocioView);
    r.named("debugView", view.debugView, debugViewFromString, "debug view", debugViewNameList());
    std::string mesh = view.mesh;
    r.string("mesh", mesh);
    view.mesh = json::resolvedSpec(mesh, baseDir);
    r.boolean("keepUnits", view.keepUnits);
    r.integer("msaaSamples", view.msaaSamples);
    r.enumeration("background", view.background, kBackgroundModes);
    r.vec3("backgroundColor", view.backgroundColor);
    r.number("backgroundBlurRoughness", view.backgroundBlurRoughness);
    r.number("texelDensityTarget", view.texelDensityTarget);
    r.warnAboutUnknownKeys();
}

// Reads a whole project object; messages start at the JSON path.
std::optional<Project> readProject(const QJsonObject& object, const std::string& baseDir,
    std::string* problem, std::vector<std::string>& warnings)
{
    Messages messages;
    ObjectReader r(messages, object, {});

    // Format and version first: a newer file's fields may mean something else, so the version
    // message must win over any field error.
    if (!json::checkFormat(object, Project::kFormatName, Project::kFormatVersion, "a Facet project", problem))
        return std::nullopt;
    r.value("format");
    r.value("version");
    r.value("generator"); // informative only

    Project project;
    // Version 1 has one "material"; version 2 a "materials" array, the current one and the parts.
    if (const std::optional<QJsonObject> material = r.object("material"))
        readMaterial(messages, *material, "material", baseDir, project.material());
    if (const std::optional<QJsonArray> materials = r.array("materials")) {
        if (materials->isEmpty())
            messages.fail("materials", "needs at least one material");
        else if (materials->size() > Project::kMaxMaterials)
            messages.fail("materials",
                std::to_string(materials->size()) + " materials, more than the "
                    + std::to_string(Project::kMaxMaterials) + " Facet reads");
        else
            project.materials.assign(std::size_t(materials->size()), Material {});
        for (int i = 0; i < int(project.materials.size()) && !messages.failed(); ++i) {
            const std::string path = "materials[" + std::to_string(i) + "]";
            const QJsonValue value = materials->at(i);
            if (!value.isObject()) {
                messages.fail(path, std::string("expected an object, got ") + typeName(value));
                break;
            }
            readMaterial(messages, value.toObject(), path, baseDir, project.materials[std::size_t(i)]);
        }
    }
    r.integer("currentMaterial", project.currentMaterial);
    if (const std::optional<QJsonArray> parts = r.array("parts")) {
        if (parts->size() > Project::kMaxParts)
            messages.fail("parts",
                std::to_string(parts->size()) + " parts, more than the " + std::to_string(Project::kMaxParts)
                    + " Facet reads");
        for (int i = 0; i < int(parts->size()) && !messages.failed(); ++i) {
            const std::string path = "parts[" + std::to_string(i) + "]";
            const QJsonValue value = parts->at(i);
            if (!value.isObject()) {
                messages.fail(path, std::string("expected an object, got ") + typeName(value));
                break;
            }
            MeshPart part;
            ObjectReader pr(messages, value.toObject(), path);
            pr.string("name", part.name);
            pr.integer("material", part.material);
            pr.boolean("visible", part.visible);
            pr.warnAboutUnknownKeys();
            project.parts.push_back(std::move(part));
        }
    }
    if (const std::optional<QJsonObject> environment = r.object("environment"))
        readEnvironment(messages, *environment, "environment", baseDir, project.environment);
    if (const std::optional<QJsonArray> lights = r.array("lights")) {
        // Counted before any is read: a file of millions of empty lights is refused at once.
        if (lights->size() > kMaxLights)
            messages.fail("lights",
                std::to_string(lights->size()) + " lights; Facet draws at most "
                    + std::to_string(kMaxLights));
        for (int i = 0; i < int(lights->size()) && !messages.failed(); ++i) {
            const std::string path = "lights[" + std::to_string(i) + "]";
            const QJsonValue value = lights->at(i);
            if (!value.isObject()) {
                messages.fail(path, std::string("expected an object, got ") + typeName(value));
                break;
            }
            Light light;
            readLight(messages, value.toObject(), path, light);
            project.lights.push_back(std::move(light));
        }
    }
    if (const std::optional<QJsonObject> camera = r.object("camera"))
        readCamera(messages, *camera, "camera", project.camera);
    if (const std::optional<QJsonObject> view = r.object("view"))
        readView(messages, *view, "view", baseDir, project.view);
    // Version 3. Older files open with the default layout for what they hold.
    project.compare = CompareLayout::defaultFor(project);
    if (const std::optional<QJsonObject> compare = r.object("compare"))
        readCompareLayout(messages, *compare, "compare", baseDir, project.compare);
    r.warnAboutUnknownKeys();

    if (messages.failed())
        return failed(messages.error, problem);
    // A material's own problems name it as the file does: "material." in version 1 files,
    // "materials[i]." in version 2.
    std::string invalid;
    const bool single = !object.contains(QLatin1String("materials"));
    for (std::size_t i = 0; i < project.materials.size(); ++i)
        if (!project.materials[i].validate(&invalid))
            return failed(
                (single ? std::string("material.") : "materials[" + std::to_string(i) + "].") + invalid,
                problem);
    if (!project.validate(&invalid))
        return failed(invalid, problem);
    warnings = std::move(messages.warnings);
    return project;
}

} // namespace

// ---- Names ------------------------------------------------------------------------------

const char* toString(ToneMapper value)
{
    return enumName(kToneMappers, value);
}
std::optional<ToneMapper> toneMapperFromString(std::string_view name)
{
    return enumFromName(kToneMappers, name);
}
const char* toString(DisplayEncoding value)
{
    return enumName(kDisplayEncodings, value);
}
std::optional<DisplayEncoding> displayEncodingFromString(std::string_view name)
{
    return enumFromName(kDisplayEncodings, name);
}
const char* toString(BackgroundMode value)
{
    return enumName(kBackgroundModes, value);
}
std::optional<BackgroundMode> backgroundModeFromString(std::string_view name)
{
    return enumFromName(kBackgroundModes, name);
}
const char* toString(IblQuality value)
{
    return enumName(kIblQualities, value);
}
std::optional<IblQuality> iblQualityFromString(std::string_view name)
{
    return enumFromName(kIblQualities, name);
}
const char* toString(IblMethod value)
{
    return enumName(kIblMethods, value);
}
std::optional<IblMethod> iblMethodFromString(std::string_view name)
{
    return enumFromName(kIblMethods, name);
}
int defaultIblSamples(IblMethod method)
{
    switch (method) {
    case IblMethod::SplitSum:
        return 0;
    case IblMethod::Fis:
        return kDefaultFisSamples;
    case IblMethod::Reference:
        return 1024;
    }
    return 0;
}

// ---- Validation -------------------------------------------------------------------------

bool ViewSettings::validate(std::string* problem) const
{
    if (!std::isfinite(exposureEV) || exposureEV < kMinExposureEV || exposureEV > kMaxExposureEV)
        return fail("exposureEV: " + number(exposureEV) + " is outside [" + number(kMinExposureEV) + ", "
                + number(kMaxExposureEV) + "]",
            problem);
    if (!std::isfinite(gamma) || gamma < 1.0 || gamma > 3.0)
        return fail("gamma: " + number(gamma) + " is outside [1, 3]", problem);
    // An OCIO view belongs to a display: one without the other names no transform. Whether the
    // names exist depends on $OCIO's config at render time (render/ToneMapping reports it).
    if (ocioDisplay.empty() && !ocioView.empty())
        return fail("ocioDisplay: must be set when ocioView is (\"" + ocioView + "\")", problem);
    if (!ocioDisplay.empty() && ocioView.empty())
        return fail("ocioView: must be set when ocioDisplay is (\"" + ocioDisplay + "\")", problem);
    if (mesh.empty())
        return fail("mesh: must not be empty (\"sphere\" is the built-in sphere)", problem);
    if (msaaSamples != 1 && msaaSamples != 2 && msaaSamples != 4 && msaaSamples != 8 && msaaSamples != 16)
        return fail("msaaSamples: " + std::to_string(msaaSamples) + " is not one of 1, 2, 4, 8, 16", problem);
    if (!isFinite(backgroundColor) || backgroundColor.x < 0.0 || backgroundColor.y < 0.0
        || backgroundColor.z < 0.0)
        return fail("backgroundColor: must be finite and >= 0 (linear)", problem);
    if (!std::isfinite(backgroundBlurRoughness) || backgroundBlurRoughness < 0.0
        || backgroundBlurRoughness > 1.0)
        return fail(
            "backgroundBlurRoughness: " + number(backgroundBlurRoughness) + " is outside [0, 1]", problem);
    if (!std::isfinite(texelDensityTarget) || texelDensityTarget <= 0.0
        || texelDensityTarget > kMaxTexelDensity)
        return fail("texelDensityTarget: " + number(texelDensityTarget) + " is outside (0, "
                + number(kMaxTexelDensity) + "] (texels per unit)",
            problem);
    return true;
}

bool EnvironmentSettings::validate(std::string* problem) const
{
    if (source.empty())
        return fail("source: must not be empty (a path, \"studio\", \"sky\" or \"uniform:VALUE\")", problem);
    // The spec's form here, not only in the compare cells made from it: a bad environment.source
    // was reported as compare.environments.cells[0].source (issue 29).
    std::string local;
    if (!Environment::checkSpec(source, &local))
        return fail("source: " + local, problem);
    if (!std::isfinite(rotationDegrees))
        return fail("rotationDegrees: must be finite", problem);
    if (!std::isfinite(intensity) || intensity < 0.0)
        return fail("intensity: " + number(intensity) + " must be a finite number >= 0", problem);
    if (samples < 0 || samples > kMaxIblSamples)
        return fail("samples: " + std::to_string(samples) + " must be 0 (the method's default) to "
                + std::to_string(kMaxIblSamples),
            problem);
    if (samples != 0 && method == IblMethod::SplitSum)
        return fail("samples: " + std::to_string(samples)
                + " given with the split-sum method, which takes no samples (use \"fis\" or \"reference\")",
            problem);
    return true;
}

bool Project::validate(std::string* problem) const
{
    std::string local;
    if (materials.empty())
        return fail("materials: needs at least one material", problem);
    if (materials.size() > std::size_t(kMaxMaterials))
        return fail("materials: more than " + std::to_string(kMaxMaterials), problem);
    for (std::size_t i = 0; i < materials.size(); ++i)
        if (!materials[i].validate(&local))
            return fail("materials[" + std::to_string(i) + "]." + local, problem);
    if (currentMaterial < 0 || std::size_t(currentMaterial) >= materials.size())
        return fail("currentMaterial: " + std::to_string(currentMaterial) + " is not a material (there are "
                + std::to_string(materials.size()) + ")",
            problem);
    if (parts.size() > std::size_t(kMaxParts))
        return fail("parts: more than " + std::to_string(kMaxParts), problem);
    for (std::size_t i = 0; i < parts.size(); ++i)
        if (parts[i].material < 0 || std::size_t(parts[i].material) >= materials.size())
            return fail("parts[" + std::to_string(i) + "].material: " + std::to_string(parts[i].material)
                    + " is not a material (there are " + std::to_string(materials.size()) + ")",
                problem);
    if (!environment.validate(&local))
        return fail("environment." + local, problem);
    if (lights.size() > std::size_t(kMaxLights))
        return fail("lights: " + std::to_string(lights.size()) + " lights; Facet draws at most "
                + std::to_string(kMaxLights),
            problem);
    for (std::size_t i = 0; i < lights.size(); ++i)
        if (!lights[i].validate(&local))
            return fail("lights[" + std::to_string(i) + "]." + local, problem);
    if (!camera.validate(&local))
        return fail("camera." + local, problem);
    if (!view.validate(&local))
        return fail("view." + local, problem);
    if (!compare.validate(materials.size(), &local))
        return fail("compare." + local, problem);
    return true;
}

// ---- Project ----------------------------------------------------------------------------

Material& Project::material()
{
    Q_ASSERT(currentMaterial >= 0 && std::size_t(currentMaterial) < materials.size());
    return materials[std::size_t(currentMaterial)];
}

const Material& Project::material() const
{
    Q_ASSERT(currentMaterial >= 0 && std::size_t(currentMaterial) < materials.size());
    return materials[std::size_t(currentMaterial)];
}

int Project::materialOfPart(std::size_t part) const
{
    if (part < parts.size() && parts[part].material >= 0
        && std::size_t(parts[part].material) < materials.size())
        return parts[part].material;
    return 0;
}

bool Project::isPartVisible(std::size_t part) const
{
    return part >= parts.size() || parts[part].visible;
}

namespace {
constexpr int kNewProjectFisSamples = 1024;
} // namespace

Project Project::defaultProject()
{
    Project project;
    Material& material = project.material();
    material.name = "Glossy plastic";
    material.setBaseColor(glm::dvec3(0.8, 0.3, 0.2)); // a red-orange that shows diffuse and specular apart
    material.setFactor(MapSlot::Roughness, 0.35);
    material.setFactor(MapSlot::Metallic, 0.0);
    project.environment = EnvironmentSettings {};
    // Accurate by default: fis at 1024 samples, the fewest meeting the target of docs/accuracy.md
    // ("Accurate by default"), which also says why a file without a method stays a split-sum file
    // and what $FACET_NEW_PROJECT_METHOD is for (an unknown value is ignored here; the app warns).
    project.environment.method = IblMethod::Fis;
    project.environment.samples = kNewProjectFisSamples;
    if (const QByteArray chosen = qgetenv("FACET_NEW_PROJECT_METHOD"); !chosen.isEmpty())
        if (const std::optional<IblMethod> method = iblMethodFromString(chosen.toStdString())) {
            project.environment.method = *method;
            project.environment.samples = *method == IblMethod::Fis ? kNewProjectFisSamples : 0;
        }
    project.camera = Camera::referenceView();
    project.view = ViewSettings {};
    project.compare = CompareLayout::defaultFor(project);
    return project;
}

QJsonObject Project::toJson(const std::string& baseDir) const
{
    QJsonObject o;
    o[QLatin1String("format")] = QLatin1String(kFormatName);
    o[QLatin1String("version")] = kFormatVersion;
#ifdef FACET_VERSION
    o[QLatin1String("generator")] = QStringLiteral("Facet " FACET_VERSION);
#endif
    QJsonArray materialArray;
    for (const Material& m : materials)
        materialArray.append(materialToJson(m, baseDir, true));
    o[QLatin1String("materials")] = materialArray;
    o[QLatin1String("currentMaterial")] = currentMaterial;
    if (!parts.empty()) {
        QJsonArray partArray;
        for (const MeshPart& part : parts) {
            QJsonObject p;
            p[QLatin1String("name")] = qs(part.name);
            p[QLatin1String("material")] = part.material;
            p[QLatin1String("visible")] = part.visible;
            partArray.append(p);
        }
        o[QLatin1String("parts")] = partArray;
    }
    o[QLatin1String("environment")] = environmentToJson(environment, baseDir);
    QJsonArray lightArray;
    for (const Light& light : lights)
        lightArray.append(lightToJson(light));
    o[QLatin1String("lights")] = lightArray;
    o[QLatin1String("camera")] = cameraToJson(camera);
    o[QLatin1String("view")] = viewToJson(view, baseDir);
    o[QLatin1String("compare")] = compare.toJson(baseDir);
    return o;
}

std::optional<Project> Project::fromJson(
    const QJsonObject& object, const std::string& baseDir, std::string* error, std::string* warning)
{
    std::string problem;
    std::vector<std::string> warnings;
    std::optional<Project> project = readProject(object, baseDir, &problem, warnings);
    if (!project)
        return failed("Project::fromJson: " + problem, error);
    appendWarnings(warning, warnings, "Project::fromJson: ");
    return project;
}

bool Project::save(const std::string& path, std::string* error) const
{
    const std::string prefix = "Project::save: " + path + ": ";
    std::string problem;
    if (!validate(&problem))
        return fail(prefix + "not saved, the project is invalid: " + problem, error);
    const std::string baseDir = ss(QFileInfo(qs(path)).absolutePath());
    if (!json::writeObjectFile(path, toJson(baseDir), &problem))
        return fail(prefix + problem, error);
    return true;
}

std::optional<Project> Project::load(const std::string& path, std::string* error, std::string* warning)
{
    const std::string prefix = "Project::load: " + path + ": ";
    std::string problem;
    const std::optional<QJsonObject> object = json::readObjectFile(path, kMaxFileBytes, &problem);
    if (!object)
        return failed(prefix + problem, error);
    std::vector<std::string> warnings;
    std::optional<Project> project
        = readProject(*object, ss(QFileInfo(qs(path)).absolutePath()), &problem, warnings);
    if (!project)
        return failed(prefix + problem, error);
    // The OCIO names are checked as the file opens (issue 29: before, only when a PNG was drawn,
    // long after the window showed the project), against $OCIO's config or the built-in one.
    if (!project->view.ocioDisplay.empty()) {
        const std::shared_ptr<const ColorManagement> config = ColorManagement::shared(&problem);
        if (!config)
            return failed(prefix + "view.ocioDisplay: " + problem, error);
        if (!config->checkDisplayView(project->view.ocioDisplay, project->view.ocioView, &problem))
            return failed(prefix + "view." + problem, error);
    }
    appendWarnings(warning, warnings, prefix);
    return project;
}

Project withoutDisplaySettings(Project project)
{
    const ViewSettings defaults;
    project.view.exposureEV = defaults.exposureEV;
    project.view.toneMapper = defaults.toneMapper;
    project.view.displayEncoding = defaults.displayEncoding;
    project.view.gamma = defaults.gamma;
    project.view.ocioDisplay.clear();
    project.view.ocioView.clear();
    project.compare = {};
    for (Material& material : project.materials)
        material.name.clear();
    for (Light& light : project.lights)
        light.name.clear();
    return project;
}

} // namespace facet
