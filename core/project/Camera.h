#pragma once
// A pinhole camera looking from `position` at `target`. World conventions (docs/architecture.md):
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

    // docs/architecture.md's reference view, used by the headless renderer, the benchmarks and the accuracy
    // tests: a pinhole at (0, 0, 3) looking at the origin, +Y up, 45 degree vertical field of
    // view. (The unit sphere, seen under asin(1/3) = 19.5 degrees, fills about 85% of the image height.)
    static Camera referenceView() { return Camera {}; }

    // How much of the smaller image dimension a framed sphere's silhouette spans (its half-size
    // over the image's half-size there): the reference view's, tan(asin(1/3)) / tan(22.5 deg) =
    // (2 + sqrt 2) / 4 = 0.854, so the unit sphere fills 85% and stops 7% short of each edge.
    static constexpr double kFramingFill = 0.8535533905932737;

    // The full horizontal field of view of an image `aspect` = width / height wide:
    // 2 atan(aspect tan(verticalFov / 2)).
    double horizontalFovDegrees(double aspect) const;
    // How far from its centre a sphere of `radius` must be seen for its silhouette to span
    // kFramingFill of the smaller image dimension (the width of a tall image, the height of a wide
    // one), so it is whole with a small margin in any viewport shape: a sphere seen from d subtends
    // asin(r / d), which must equal atan(kFramingFill tan(smaller fov / 2)). With a 45 degree
    // field of view and aspect >= 1 this is the reference view's distance, 3, for the unit sphere.
    double framingDistance(double radius, double aspect) const;

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
