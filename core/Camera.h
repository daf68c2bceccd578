#pragma once
// A pinhole camera looking from `position` at `target`. World conventions (DESIGN.md):
// right-handed, +Y up; the reference view looks toward -Z.

#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace facet {

struct Camera {
    glm::dvec3 position {0.0, 0.0, 3.0};
    glm::dvec3 target {0.0, 0.0, 0.0};
    glm::dvec3 up {0.0, 1.0, 0.0};
    double verticalFovDegrees = 45.0; // full vertical angle, in (0, 180)
    // Clip distances in world units (metres), 0 < nearPlane < farPlane. (Not `near`/`far`: some
    // platform headers define those as macros.)
    double nearPlane = 0.05;
    double farPlane = 100.0;

    // DESIGN.md's reference view, used by the headless renderer, the benchmarks and the accuracy
    // tests: a pinhole at (0, 0, 3) looking at the origin, +Y up, 45 degree vertical field of
    // view. (The unit sphere, seen under asin(1/3) = 19.5 degrees, fills about 85% of the image height.)
    static Camera referenceView() { return Camera {}; }

    // World -> view (glm::lookAt, right-handed: the camera looks down its -Z).
    glm::dmat4 viewMatrix() const;
    // View -> clip, OpenGL clip space (z in [-1, 1]); aspect = width / height.
    glm::dmat4 projectionMatrix(double aspect) const;

    // Checks the camera is usable; on failure returns false and sets *problem to
    // "<field>: <problem>" (the caller prefixes "camera.").
    bool validate(std::string* problem) const;

    bool operator==(const Camera&) const = default;
};

} // namespace facet
