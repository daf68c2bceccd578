#include "SceneFlags.h"

#include "CommandInputs.h"

#include <cmath>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QStringList>

namespace facet {

namespace {

constexpr double kMaxEnvironmentEV = 20.0;

bool parseVector(const QString& flag, const QString& text, glm::dvec3* out, QString* error)
{
    const QStringList parts = text.split(QLatin1Char(','));
    if (parts.size() != 3) {
        *error = QStringLiteral("--%1: '%2' is not x,y,z").arg(flag, text);
        return false;
    }
    for (int i = 0; i < 3; ++i) {
        bool ok = false;
        const double value = parts[i].trimmed().toDouble(&ok);
        // The range of the 32-bit floats the renderer uses, as a project file's numbers.
        if (!ok || !std::isfinite(value) || std::abs(value) > 3.4e38) {
            *error = QStringLiteral("--%1: '%2' is not x,y,z with finite numbers").arg(flag, text);
            return false;
        }
        (*out)[i] = value;
    }
    return true;
}

// RFC 6901: "~1" is '/', "~0" is '~'.
QString unescapePointerToken(QString token)
{
    return token.replace(QStringLiteral("~1"), QStringLiteral("/"))
        .replace(QStringLiteral("~0"), QStringLiteral("~"));
}

// Sets the value at tokens[at...] below `node`; `walked` is the pointer so far, for messages.
bool setAt(QJsonValue& node, const QStringList& tokens, int at, const QJsonValue& value,
    const QString& walked, QString* error)
{
    if (at == tokens.size()) {
        node = value;
        return true;
    }
    const QString token = tokens[at];
    const QString here = walked + u'/' + tokens[at];
    if (node.isObject()) {
        QJsonObject object = node.toObject();
        const bool last = at + 1 == tokens.size();
        if (!object.contains(token) && !last) {
            *error = QStringLiteral("%1 does not exist").arg(here);
            return false;
        }
        QJsonValue child = object.value(token);
        if (!setAt(child, tokens, at + 1, value, here, error))
            return false;
        object.insert(token, child);
        node = object;
        return true;
    }
    if (node.isArray()) {
        QJsonArray array = node.toArray();
        bool ok = false;
        const int index = token == QStringLiteral("-") ? int(array.size()) : token.toInt(&ok);
        if ((token != QStringLiteral("-") && !ok) || index < 0 || index > array.size()
            || (index == array.size() && at + 1 != tokens.size())) {
            *error
                = QStringLiteral("%1: not an index of the array's %2 elements").arg(here).arg(array.size());
            return false;
        }
        QJsonValue child = index < array.size() ? array.at(index) : QJsonValue();
        if (!setAt(child, tokens, at + 1, value, here, error))
            return false;
        if (index < array.size())
            array.replace(index, child);
        else
            array.append(child);
        node = array;
        return true;
    }
    *error
        = QStringLiteral("%1 is not an object or array").arg(walked.isEmpty() ? QStringLiteral("/") : walked);
    return false;
}

} // namespace

void SceneFlags::addTo(QCommandLineParser& parser) const
{
    for (const QCommandLineOption* option :
        {&m_cameraPosition, &m_cameraTarget, &m_fov, &m_exposure, &m_toneMapper, &m_envRotation,
            &m_envIntensity, &m_background, &m_keepUnits, &m_set, &m_saveProject})
        parser.addOption(*option);
}

QString SceneFlags::saveProjectPath(const QCommandLineParser& parser) const
{
    return parser.isSet(m_saveProject) ? parser.value(m_saveProject) : QString();
}

bool SceneFlags::setJsonPointer(QJsonObject& root, const QString& assignment, QString* error)
{
    const qsizetype equals = assignment.indexOf(u'=');
    const QString pointer = equals < 0 ? assignment : assignment.left(equals);
    if (equals < 0 || !pointer.startsWith(u'/') || pointer.size() < 2) {
        *error = QStringLiteral(
            "--set: '%1' is not PATH=VALUE with PATH a JSON pointer such as /view/exposureEV")
                     .arg(assignment);
        return false;
    }
    const QString text = assignment.mid(equals + 1);
    // JSON when it parses as JSON (a number, true, an array, a quoted string), else a bare word.
    QJsonParseError parseError;
    const QJsonDocument document
        = QJsonDocument::fromJson(QByteArray("[") + text.toUtf8() + "]", &parseError);
    const QJsonValue value = parseError.error == QJsonParseError::NoError && document.array().size() == 1
        ? document.array().at(0)
        : QJsonValue(text);
    QStringList tokens = pointer.mid(1).split(u'/');
    for (QString& token : tokens)
        token = unescapePointerToken(token);
    QJsonValue node(root);
    QString problem;
    if (!setAt(node, tokens, 0, value, QString(), &problem)) {
        *error = QStringLiteral("--set %1: %2").arg(pointer, problem);
        return false;
    }
    root = node.toObject();
    return true;
}

bool SceneFlags::apply(
    const QCommandLineParser& parser, Project& project, const std::string& baseDir, QString* error) const
{
    double number = 0.0;
    if (parser.isSet(m_cameraPosition)
        && !parseVector(QStringLiteral("camera-position"), parser.value(m_cameraPosition),
            &project.camera.position, error))
        return false;
    if (parser.isSet(m_cameraTarget)
        && !parseVector(
            QStringLiteral("camera-target"), parser.value(m_cameraTarget), &project.camera.target, error))
        return false;
    if (parser.isSet(m_fov)) {
        if (!parseNumber(
                QStringLiteral("fov"), parser.value(m_fov), 0.0, 180.0, &number, error, /*open=*/true))
            return false;
        project.camera.verticalFovDegrees = number;
    }
    if (parser.isSet(m_exposure)) {
        if (!parseNumber(QStringLiteral("exposure"), parser.value(m_exposure), ViewSettings::kMinExposureEV,
                ViewSettings::kMaxExposureEV, &number, error))
            return false;
        project.view.exposureEV = number;
    }
    if (parser.isSet(m_toneMapper)) {
        const QString name = parser.value(m_toneMapper);
        const std::optional<ToneMapper> mapper = toneMapperFromString(name.toStdString());
        if (!mapper) {
            *error = QStringLiteral(
                "--tone-mapper: '%1' is not none, reinhard, exposure, aces, khronos-neutral or agx")
                         .arg(name);
            return false;
        }
        project.view.toneMapper = *mapper;
    }
    if (parser.isSet(m_envRotation)) {
        if (!parseNumber(
                QStringLiteral("env-rotation"), parser.value(m_envRotation), -1e6, 1e6, &number, error))
            return false;
        project.environment.rotationDegrees = number;
    }
    if (parser.isSet(m_envIntensity)) {
        if (!parseNumber(QStringLiteral("env-intensity"), parser.value(m_envIntensity), -kMaxEnvironmentEV,
                kMaxEnvironmentEV, &number, error))
            return false;
        project.environment.intensity = std::exp2(number);
    }
    if (parser.isSet(m_keepUnits))
        project.view.keepUnits = true;
    if (parser.isSet(m_background)) {
        const QString mode = parser.value(m_background);
        if (mode == QStringLiteral("env")) {
            project.view.background = BackgroundMode::Environment;
        } else if (mode == QStringLiteral("blurred")) {
            project.view.background = BackgroundMode::Blurred;
        } else if (mode == QStringLiteral("transparent")) {
            project.view.background = BackgroundMode::Transparent;
        } else if (mode.startsWith(QStringLiteral("color:"))) {
            glm::dvec3 color;
            if (!parseVector(QStringLiteral("background"), mode.mid(6), &color, error))
                return false;
            if (color.x < 0.0 || color.y < 0.0 || color.z < 0.0) {
                *error = QStringLiteral("--background: '%1': a colour is linear and >= 0").arg(mode);
                return false;
            }
            project.view.background = BackgroundMode::Color;
            project.view.backgroundColor = color;
        } else {
            *error = QStringLiteral("--background: '%1' is not env, blurred, transparent or color:R,G,B")
                         .arg(mode);
            return false;
        }
    }
    std::string problem;
    if (!project.validate(&problem)) {
        *error = QString::fromStdString(problem);
        return false;
    }
    const QStringList assignments = parser.values(m_set);
    if (assignments.isEmpty())
        return true;
    QJsonObject json = project.toJson(baseDir);
    for (const QString& assignment : assignments)
        if (!setJsonPointer(json, assignment, error))
            return false;
    // Read back by the rules of a project file: a value out of range is refused naming its path,
    // and a key the format does not have (a misspelt field) is an error here, not a note.
    std::string warning;
    std::optional<Project> edited = Project::fromJson(json, baseDir, &problem, &warning);
    const QString setList = assignments.join(QStringLiteral("', '"));
    if (!edited) {
        QString text = QString::fromStdString(problem);
        text.remove(QStringLiteral("Project::fromJson: "));
        *error = QStringLiteral("--set '%1': %2").arg(setList, text);
        return false;
    }
    if (!warning.empty()) {
        // A project file's unknown key is a note ("..., ignored"); a --set one is a typo to refuse.
        QString text = QString::fromStdString(warning).trimmed();
        text.remove(QStringLiteral("Project::fromJson: "));
        text.replace(
            QStringLiteral("unknown key, ignored"), QStringLiteral("not a field of the project format"));
        *error = QStringLiteral("--set '%1': %2").arg(setList, text);
        return false;
    }
    project = std::move(*edited);
    return true;
}

} // namespace facet
