#pragma once
// The flags of `facet render` and `facet sheet` that say on the command line what a project says
// in its JSON (issue 29: camera, field of view, exposure, tone mapper, environment rotation and
// intensity and the background existed only inside project files):
//
//   --camera-position x,y,z --camera-target x,y,z --fov DEG --exposure EV --tone-mapper NAME
//   --env-rotation DEG --env-intensity EV --background env|blurred|transparent|color:R,G,B
//   --keep-units
//   --set PATH=VALUE (repeatable) --save-project FILE
//
// --set reaches every field: PATH is a JSON pointer into the project file's JSON (RFC 6901:
// "/view/exposureEV", "/materials/0/roughness/factor", "/camera/position/1"), VALUE is JSON
// (1.5, true, [0, 1, 3], "aces") or a bare word taken as a string (aces). The edited project is
// read back by the same rules as a project file, so an out-of-range value is refused naming its
// path, as a project file's would be. --save-project writes the project the input and flags
// describe (docs/project-format.md), so a command line can become a project file.
//
// Order: the input, then the command's own flags (--env, --material, ...), then the flags here,
// --set last: the most general edit has the last word.

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QString>

#include <string>

#include "core/project/Project.h"

namespace facet {

class SceneFlags {
public:
    void addTo(QCommandLineParser& parser) const;
    // Applies the flags that are set to `project` (paths resolve against `baseDir`, the folder of
    // the project file, or the working folder). False with *error naming the flag or the --set
    // path, e.g. "--fov: 190 is outside (0, 180)", "--set /view/exposureEV: ... is outside
    // [-20, 20]"; a project that fails validation is refused too.
    bool apply(
        const QCommandLineParser& parser, Project& project, const std::string& baseDir, QString* error) const;
    // The --save-project file, or "" when not given.
    QString saveProjectPath(const QCommandLineParser& parser) const;

    // One --set edit on a project's JSON (exposed for tests): false with *error naming the path.
    static bool setJsonPointer(QJsonObject& root, const QString& assignment, QString* error);

private:
    QCommandLineOption m_cameraPosition {QStringLiteral("camera-position"),
        QStringLiteral("Camera position x,y,z in world units."), QStringLiteral("x,y,z")};
    QCommandLineOption m_cameraTarget {QStringLiteral("camera-target"),
        QStringLiteral("The point the camera looks at, x,y,z."), QStringLiteral("x,y,z")};
    QCommandLineOption m_fov {QStringLiteral("fov"),
        QStringLiteral("Vertical field of view in degrees, in (0, 180)."), QStringLiteral("deg")};
    QCommandLineOption m_exposure {QStringLiteral("exposure"),
        QStringLiteral("Exposure in stops (EV), in [-20, 20]: PNG output only; EXR is radiance."),
        QStringLiteral("EV")};
    QCommandLineOption m_toneMapper {QStringLiteral("tone-mapper"),
        QStringLiteral("Tone mapper for PNG output: none, reinhard, exposure, aces, khronos-neutral, agx."),
        QStringLiteral("name")};
    QCommandLineOption m_envRotation {QStringLiteral("env-rotation"),
        QStringLiteral("Environment rotation about +Y in degrees."), QStringLiteral("deg")};
    QCommandLineOption m_envIntensity {QStringLiteral("env-intensity"),
        QStringLiteral("Environment intensity in stops (EV): its radiance times 2^EV."),
        QStringLiteral("EV")};
    QCommandLineOption m_background {QStringLiteral("background"),
        QStringLiteral("What pixels that miss the mesh show: env, blurred, color:R,G,B (linear) or "
                       "transparent (alpha 0 there: PNG straight alpha, EXR premultiplied)."),
        QStringLiteral("mode")};
    QCommandLineOption m_keepUnits {QStringLiteral("keep-units"),
        QStringLiteral("Keep the mesh in its own units and origin (a camera in asset space) instead of "
                       "fitting it to the unit sphere.")};
    QCommandLineOption m_set {QStringLiteral("set"),
        QStringLiteral("Set any project field: PATH=VALUE, PATH a JSON pointer into the project "
                       "(/view/exposureEV), VALUE JSON (1.5, true, [0,1,3], \"aces\") or a bare word. "
                       "Repeatable; applied last."),
        QStringLiteral("path=value")};
    QCommandLineOption m_saveProject {QStringLiteral("save-project"),
        QStringLiteral("Also write the project the input and flags describe to FILE (JSON)."),
        QStringLiteral("file")};
};

} // namespace facet
