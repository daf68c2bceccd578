#include "render/Turntable.h"

#include "core/image/VideoEncoder.h"

#include <QString>
#include <QTemporaryDir>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

namespace facet {

const char* toString(TurntableSubject subject)
{
    return subject == TurntableSubject::Object ? "object" : "environment";
}

std::optional<TurntableSubject> turntableSubjectFromString(std::string_view name)
{
    if (name == "object")
        return TurntableSubject::Object;
    if (name == "environment")
        return TurntableSubject::Environment;
    return std::nullopt;
}

glm::dmat4 turntableModelMatrix(double degrees)
{
    return glm::rotate(glm::dmat4(1.0), glm::radians(degrees), glm::dvec3(0.0, 1.0, 0.0));
}

void applyTurntable(RenderScene& scene, TurntableSubject subject, double degrees)
{
    if (degrees == 0.0)
        return;
    if (subject == TurntableSubject::Object) {
        scene.modelMatrix = turntableModelMatrix(degrees) * scene.modelMatrix;
        // The exact sphere hit of the reference view is of the unturned sphere (its texture
        // coordinates would not turn): the turned mesh is drawn as it is.
        scene.analyticSphere = false;
    } else {
        scene.environment.rotationDegrees += degrees;
    }
}

double turntableDegrees(int index, int frames)
{
    return frames > 0 ? 360.0 * double(index) / double(frames) : 0.0;
}

std::string turntableFramePath(const std::string& output, int index, int frames)
{
    const std::filesystem::path path(output);
    const std::string name = path.filename().string();
    const auto padded = [index](int digits) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%0*d", digits, index);
        return std::string(buffer);
    };
    if (const std::size_t first = name.find('#'); first != std::string::npos) {
        std::size_t last = first;
        while (last < name.size() && name[last] == '#')
            ++last;
        const std::string replaced = name.substr(0, first) + padded(int(last - first)) + name.substr(last);
        return (path.parent_path() / replaced).string();
    }
    int digits = 4;
    for (int largest = std::max(frames - 1, 0); largest >= 10000; largest /= 10)
        ++digits;
    const std::string stem = path.stem().string();
    const std::string extension = path.extension().string();
    return (path.parent_path() / (stem + "_" + padded(digits) + extension)).string();
}

std::optional<TurntableWrite> writeTurntable(const std::string& output, int frames, int fps, bool keepAlpha,
    const std::function<std::optional<Image>(int index, double degrees, std::string* error)>& frame,
    std::string* error, const std::function<bool()>& cancelled)
{
    using Clock = std::chrono::steady_clock;
    const auto seconds
        = [](Clock::time_point from) { return std::chrono::duration<double>(Clock::now() - from).count(); };
    const bool video = isVideoPath(output);
    QTemporaryDir folder; // a video's frames
    if (video && !folder.isValid()) {
        *error = output + ": no temporary folder for the frames: " + folder.errorString().toStdString();
        return std::nullopt;
    }
    TurntableWrite result;
    const auto start = Clock::now();
    for (int index = 0; index < frames; ++index) {
        std::string problem;
        const std::optional<Image> image = frame(index, turntableDegrees(index, frames), &problem);
        const std::string path = video
            ? folder.filePath(QStringLiteral("frame_%1.png").arg(index, 5, 10, QLatin1Char('0')))
                  .toStdString()
            : turntableFramePath(output, index, frames);
        if (!image || !image->save(path, &problem, keepAlpha && !video)) {
            *error = "frame " + std::to_string(index) + " of " + std::to_string(frames) + ": " + problem;
            return std::nullopt;
        }
        result.framesWritten = index + 1;
        // Asked after every frame (the window's progress counts them); after the last there is
        // nothing left to stop.
        if (cancelled && cancelled() && index + 1 < frames) {
            result.stopped = true;
            result.renderSeconds = seconds(start);
            return result;
        }
    }
    result.renderSeconds = seconds(start);
    const auto encoding = Clock::now();
    if (video
        && !encodeVideo(folder.filePath(QStringLiteral("frame_%05d.png")).toStdString(), fps, output, error))
        return std::nullopt;
    result.encodeSeconds = seconds(encoding);
    return result;
}

} // namespace facet
