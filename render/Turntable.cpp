#include "render/Turntable.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
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

} // namespace facet
