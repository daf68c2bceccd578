#include "core/project/Camera.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "core/support/Failure.h"
#include "core/support/Finite.h"

namespace facet {

glm::dmat4 Camera::viewMatrix() const
{
    return glm::lookAtRH(position, target, up);
}

glm::dmat4 Camera::projectionMatrix(double aspect) const
{
    return glm::perspectiveRH_NO(glm::radians(verticalFovDegrees), aspect, nearPlane, farPlane);
}

double Camera::horizontalFovDegrees(double aspect) const
{
    return glm::degrees(2.0 * std::atan(aspect * std::tan(glm::radians(verticalFovDegrees) / 2.0)));
}

double Camera::framingDistance(double radius, double aspect) const
{
    const double smallerHalfFov
        = glm::radians(std::min(verticalFovDegrees, horizontalFovDegrees(aspect))) / 2.0;
    return radius / std::sin(std::atan(kFramingFill * std::tan(smallerHalfFov)));
}

bool Camera::validate(std::string* problem) const
{
    if (!isFinite(position))
        return fail("position: must be finite", problem);
    if (!isFinite(target))
        return fail("target: must be finite", problem);
    if (!isFinite(up))
        return fail("up: must be finite", problem);
    const glm::dvec3 forward = target - position;
    if (glm::length(forward) <= 1e-9)
        return fail("target: must differ from position", problem);
    // lookAt needs an up vector that is not parallel to the viewing direction.
    if (glm::length(glm::cross(glm::normalize(forward), up)) <= 1e-9)
        return fail("up: must be non-zero and not parallel to the viewing direction", problem);
    if (!std::isfinite(verticalFovDegrees) || verticalFovDegrees <= 0.0 || verticalFovDegrees >= 180.0)
        return fail("verticalFovDegrees: must be in (0, 180)", problem);
    if (!std::isfinite(nearPlane) || nearPlane <= 0.0)
        return fail("nearPlane: must be > 0", problem);
    if (!std::isfinite(farPlane) || farPlane <= nearPlane)
        return fail("farPlane: must be greater than nearPlane", problem);
    return true;
}

} // namespace facet
