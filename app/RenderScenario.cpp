#include "RenderScenario.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>

#include "core/json/JsonStructure.h"
#include "core/json/JsonSupport.h"
#include "core/project/AssetProject.h"
#include "core/project/ProjectAssets.h"

namespace facet {

namespace {

// The harness's config reader's defaults (src/config-reader.ts): what a scenario leaves out.
constexpr int kDefaultDimension = 768;
constexpr double kDefaultPhi = 90.0;
constexpr double kDefaultRadius = 1.0;
constexpr double kDefaultFov = 45.0;
constexpr int kMaxDimension = 8192; // the image is twice this: within facet render's 16384
// three.js's ACESFilmicToneMapping multiplies by exposure / 0.6 before Hill's fit.
const double kAcesExposureEV = std::log2(1.0 / 0.6);

// One field at a time, each message naming its path ("scenario.orbit.phi: ...").
class Reader {
public:
    explicit Reader(QString* error)
        : m_error(error)
    {
    }
    bool failed() const { return m_failed; }
    void fail(const QString& path, const QString& problem)
    {
        if (!m_failed)
            *m_error = path + QStringLiteral(": ") + problem;
        m_failed = true;
    }

    // The object under `key`: an empty one when missing (every field then takes its default).
    QJsonObject object(const QJsonObject& parent, const QString& key, const QString& path)
    {
        const QJsonValue v = parent.value(key);
        if (v.isUndefined())
            return {};
        if (!v.isObject())
            fail(path, QStringLiteral("expected an object, got %1").arg(typeName(v)));
        return v.toObject();
    }
    double number(const QJsonObject& parent, const QString& key, const QString& path, double fallback)
    {
        const QJsonValue v = parent.value(key);
        if (v.isUndefined())
            return fallback;
        if (!v.isDouble() || !std::isfinite(v.toDouble())) {
            fail(path, QStringLiteral("expected a number, got %1").arg(typeName(v)));
            return fallback;
        }
        return v.toDouble();
    }
    QString string(
        const QJsonObject& parent, const QString& key, const QString& path, const QString& fallback)
    {
        const QJsonValue v = parent.value(key);
        if (v.isUndefined()) {
            if (fallback.isNull())
                fail(path, QStringLiteral("missing"));
            return fallback;
        }
        if (!v.isString() || v.toString().isEmpty()) {
            fail(path,
                v.isString() ? QStringLiteral("empty")
                             : QStringLiteral("expected a string, got %1").arg(typeName(v)));
            return fallback;
        }
        return v.toString();
    }
    bool boolean(const QJsonObject& parent, const QString& key, const QString& path, bool fallback)
    {
        const QJsonValue v = parent.value(key);
        if (v.isUndefined())
            return fallback;
        if (!v.isBool()) {
            fail(path, QStringLiteral("expected true or false, got %1").arg(typeName(v)));
            return fallback;
        }
        return v.toBool();
    }

private:
    static QString typeName(const QJsonValue& v) { return QString::fromLatin1(jsonsupport::typeName(v)); }

    QString* m_error;
    bool m_failed = false;
};

// An absolute path for a path relative to the working folder.
std::string absolute(const QString& path)
{
    return QDir::cleanPath(QFileInfo(path).absoluteFilePath()).toStdString();
}

} // namespace

std::optional<RenderScenario> readRenderScenario(const QString& json, QString* error)
{
    const QByteArray bytes = json.toUtf8();
    if (const auto problem
        = jsonStructureProblem(std::string_view(bytes.constData(), std::size_t(bytes.size())))) {
        *error = QStringLiteral("--scenario: %1").arg(QString::fromStdString(*problem));
        return std::nullopt;
    }
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(bytes, &parseError);
    if (parseError.error != QJsonParseError::NoError || !document.isObject()) {
        *error = parseError.error != QJsonParseError::NoError
            ? QStringLiteral("--scenario: not JSON (%1 at character %2)")
                  .arg(parseError.errorString())
                  .arg(parseError.offset)
            : QStringLiteral("--scenario: expected a JSON object {\"scenario\": {...}, \"outputFile\": ...}");
        return std::nullopt;
    }
    const QJsonObject root = document.object();
    Reader r(error);
    if (!root.value(QStringLiteral("scenario")).isObject()) {
        r.fail(QStringLiteral("scenario"),
            root.contains(QStringLiteral("scenario")) ? QStringLiteral("expected an object")
                                                      : QStringLiteral("missing"));
        return std::nullopt;
    }
    const QJsonObject s = root.value(QStringLiteral("scenario")).toObject();
    RenderScenario scenario;
    scenario.name
        = r.string(s, QStringLiteral("name"), QStringLiteral("scenario.name"), QStringLiteral("scenario"))
              .toStdString();
    const QString model = r.string(s, QStringLiteral("model"), QStringLiteral("scenario.model"), QString());
    const QString lighting
        = r.string(s, QStringLiteral("lighting"), QStringLiteral("scenario.lighting"), QString());
    const QString output
        = r.string(root, QStringLiteral("outputFile"), QStringLiteral("outputFile"), QString());
    const QJsonObject dimensions
        = r.object(s, QStringLiteral("dimensions"), QStringLiteral("scenario.dimensions"));
    const QJsonObject target = r.object(s, QStringLiteral("target"), QStringLiteral("scenario.target"));
    const QJsonObject orbit = r.object(s, QStringLiteral("orbit"), QStringLiteral("scenario.orbit"));
    const double width = r.number(
        dimensions, QStringLiteral("width"), QStringLiteral("scenario.dimensions.width"), kDefaultDimension);
    const double height = r.number(dimensions, QStringLiteral("height"),
        QStringLiteral("scenario.dimensions.height"), kDefaultDimension);
    const glm::dvec3 center(r.number(target, QStringLiteral("x"), QStringLiteral("scenario.target.x"), 0.0),
        r.number(target, QStringLiteral("y"), QStringLiteral("scenario.target.y"), 0.0),
        r.number(target, QStringLiteral("z"), QStringLiteral("scenario.target.z"), 0.0));
    const double theta
        = r.number(orbit, QStringLiteral("theta"), QStringLiteral("scenario.orbit.theta"), 0.0);
    const double phi
        = r.number(orbit, QStringLiteral("phi"), QStringLiteral("scenario.orbit.phi"), kDefaultPhi);
    const double radius
        = r.number(orbit, QStringLiteral("radius"), QStringLiteral("scenario.orbit.radius"), kDefaultRadius);
    const double fov
        = r.number(s, QStringLiteral("verticalFoV"), QStringLiteral("scenario.verticalFoV"), kDefaultFov);
    const bool skybox
        = r.boolean(s, QStringLiteral("renderSkybox"), QStringLiteral("scenario.renderSkybox"), false);
    if (r.failed())
        return std::nullopt;

    // Ranges.
    for (const auto& [value, path] : {std::pair {width, QStringLiteral("scenario.dimensions.width")},
             std::pair {height, QStringLiteral("scenario.dimensions.height")}})
        if (value != std::floor(value) || value < 1 || value > kMaxDimension)
            r.fail(
                path, QStringLiteral("%1 is not a whole number from 1 to %2").arg(value).arg(kMaxDimension));
    if (radius < 0.0)
        r.fail(QStringLiteral("scenario.orbit.radius"), QStringLiteral("%1 is negative").arg(radius));
    if (!(fov > 0.0 && fov < 180.0))
        r.fail(QStringLiteral("scenario.verticalFoV"), QStringLiteral("%1 is outside (0, 180)").arg(fov));
    if (!QFileInfo(model).isFile())
        r.fail(QStringLiteral("scenario.model"), QStringLiteral("%1: no such file").arg(model));
    if (!QFileInfo(lighting).isFile())
        r.fail(QStringLiteral("scenario.lighting"), QStringLiteral("%1: no such file").arg(lighting));
    const QString suffix = QFileInfo(output).suffix().toLower();
    if (suffix != QStringLiteral("png") && suffix != QStringLiteral("exr"))
        r.fail(QStringLiteral("outputFile"),
            QStringLiteral("'%1' is not a .png (display-referred) or .exr (linear radiance) file")
                .arg(output));
    if (r.failed())
        return std::nullopt;

    // The model: a glTF asset with its materials and parts, or any mesh file Facet reads with the
    // default material; in its own units either way.
    const std::string modelPath = absolute(model);
    std::string loadError;
    std::optional<Project> project;
    if (isAssetFileName(modelPath)) {
        project = projectFromAsset(modelPath, &loadError);
    } else {
        project = Project::defaultProject();
        project->view.mesh = modelPath;
    }
    if (!project) {
        r.fail(QStringLiteral("scenario.model"), QString::fromStdString(loadError));
        return std::nullopt;
    }
    project->view.keepUnits = true;
    // The clip planes from the model's extent, as the harness's Cycles renderer sets them: near a
    // thousandth of the larger of the orbit and the model's radius, far beyond the model's far side.
    const std::optional<Mesh> mesh = loadViewMesh(project->view.mesh, &loadError, nullptr, true);
    if (!mesh) {
        r.fail(QStringLiteral("scenario.model"), QString::fromStdString(loadError));
        return std::nullopt;
    }
    const glm::dvec3 meshCenter(mesh->boundingSphereCenter());
    const double meshRadius = std::max(double(mesh->boundingSphereRadius()), 1e-5);

    // The camera on the orbit (docs/fidelity.md): model-viewer's spherical coordinates.
    const double t = theta * std::numbers::pi / 180.0;
    const double p = phi * std::numbers::pi / 180.0;
    const glm::dvec3 direction(std::sin(p) * std::sin(t), std::cos(p), std::sin(p) * std::cos(t));
    Camera& camera = project->camera;
    camera.position = center + radius * direction;
    camera.target = radius > 0.0 ? center : center - direction;
    // Straight above or below, +Y is along the view: the image's up is then away from theta's side.
    camera.up = std::abs(std::sin(p)) > 1e-6
        ? glm::dvec3(0.0, 1.0, 0.0)
        : glm::dvec3(-std::sin(t), 0.0, -std::cos(t)) * (std::cos(p) > 0 ? 1.0 : -1.0);
    camera.verticalFovDegrees = fov;
    const double extent = std::max(radius, meshRadius);
    camera.nearPlane = 2.0 * extent / 1000.0;
    camera.farPlane
        = std::max(2.0 * (glm::length(camera.position - meshCenter) + meshRadius), 10.0 * camera.nearPlane);

    project->environment.source = absolute(lighting);
    project->environment.rotationDegrees = 0.0;
    project->environment.intensity = 1.0;
    ViewSettings& view = project->view;
    view.background = skybox ? BackgroundMode::Environment : BackgroundMode::Transparent;
    view.toneMapper = ToneMapper::Aces;
    view.exposureEV = kAcesExposureEV;
    view.displayEncoding = DisplayEncoding::SRGB;
    view.ocioDisplay.clear();
    view.ocioView.clear();

    std::string invalid;
    if (!project->validate(&invalid)) {
        *error = QStringLiteral("--scenario: %1").arg(QString::fromStdString(invalid));
        return std::nullopt;
    }
    scenario.project = std::move(*project);
    scenario.outputPath = output.toStdString();
    scenario.width = 2 * int(width);
    scenario.height = 2 * int(height);
    return scenario;
}

} // namespace facet
