// Framing (core/project/Camera.h framingDistance): for tall, square and wide images and several fields of
// view, a camera at that distance has the whole bounding sphere inside the four side planes of its
// frustum, with a small margin, and the sphere fills the smaller dimension of the image. The
// planes come from the projection and view matrices the renderer uses (Gribb and Hartmann, "Fast
// Extraction of Viewing Frustum Planes from the World-View-Projection Matrix", 2001), so the test
// checks what is drawn, not the formula against itself. Needs nothing.

#include "core/project/Camera.h"

#include <QtTest/QTest>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>

using namespace facet;

class CameraTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void horizontalFieldOfView();
    void framedSphereFitsTheSmallerDimension_data();
    void framedSphereFitsTheSmallerDimension();
    void wideReferenceFramingIsTheReferenceView();
};

void CameraTest::horizontalFieldOfView()
{
    Camera camera;
    camera.verticalFovDegrees = 45.0;
    QVERIFY(std::abs(camera.horizontalFovDegrees(1.0) - 45.0) < 1e-12);
    // 2 atan(2 tan(22.5 deg)) = 79.28 degrees; half the aspect, 2 atan(tan(22.5 deg) / 2) = 23.40.
    QVERIFY(std::abs(camera.horizontalFovDegrees(2.0) - 79.2785) < 1e-4);
    QVERIFY(std::abs(camera.horizontalFovDegrees(0.5) - 23.4018) < 1e-4);
}

void CameraTest::framedSphereFitsTheSmallerDimension_data()
{
    QTest::addColumn<double>("aspect"); // width / height
    QTest::addColumn<double>("verticalFov");
    QTest::addColumn<double>("radius");
    for (const double fov : {20.0, 45.0, 90.0})
        for (const double aspect : {0.3, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0})
            QTest::addRow("aspect %.2f, fov %.0f", aspect, fov) << aspect << fov << 1.0;
    QTest::newRow("tall, radius 2.5") << 0.6 << 45.0 << 2.5;
    QTest::newRow("wide, radius 0.1") << 1.8 << 45.0 << 0.1;
}

void CameraTest::framedSphereFitsTheSmallerDimension()
{
    QFETCH(double, aspect);
    QFETCH(double, verticalFov);
    QFETCH(double, radius);
    Camera camera;
    camera.verticalFovDegrees = verticalFov;
    camera.farPlane = 1000.0;
    const double distance = camera.framingDistance(radius, aspect);
    // From an oblique direction, as F keeps the view direction.
    const glm::dvec3 direction = glm::normalize(glm::dvec3(0.4, 0.5, 1.0));
    camera.target = glm::dvec3(0.0);
    camera.position = direction * distance;

    // Side planes of clip = P V x: w + x >= 0 (left), w - x >= 0 (right), likewise y (bottom, top).
    const glm::dmat4 m = camera.projectionMatrix(aspect) * camera.viewMatrix();
    const glm::dvec4 rowX(m[0][0], m[1][0], m[2][0], m[3][0]);
    const glm::dvec4 rowY(m[0][1], m[1][1], m[2][1], m[3][1]);
    const glm::dvec4 rowW(m[0][3], m[1][3], m[2][3], m[3][3]);
    // Distance from the sphere's centre (the origin) to each plane, in units of the radius.
    const auto clearance
        = [radius](const glm::dvec4& plane) { return plane.w / glm::length(glm::dvec3(plane)) / radius; };
    const double left = clearance(rowW + rowX);
    const double right = clearance(rowW - rowX);
    const double bottom = clearance(rowW + rowY);
    const double top = clearance(rowW - rowY);
    const QString report = QStringLiteral("distance %1; clearance left %2 right %3 bottom %4 top %5 (radii)")
                               .arg(distance)
                               .arg(left)
                               .arg(right)
                               .arg(bottom)
                               .arg(top);
    // Inside every side plane with a small margin: the limiting pair between 1.05 and 1.25 radii
    // from the centre (1.148 for the reference view's 45 degrees), the other pair no closer.
    const double limiting = aspect < 1.0 ? std::min(left, right) : std::min(bottom, top);
    const double other = aspect < 1.0 ? std::min(bottom, top) : std::min(left, right);
    QVERIFY2(limiting > 1.05 && limiting < 1.25, qPrintable(report));
    QVERIFY2(other >= limiting - 1e-9, qPrintable(report));
    QVERIFY2(std::abs(left - right) < 1e-9 && std::abs(bottom - top) < 1e-9, qPrintable(report)); // centred

    // It fills the smaller dimension: the silhouette's half-size over the image's half-size
    // there, tan(asin(r / d)) / tan(smaller fov / 2), is kFramingFill (85%) whatever the shape.
    const double smallerHalfFov
        = glm::radians(std::min(verticalFov, camera.horizontalFovDegrees(aspect))) / 2.0;
    const double fill = std::tan(std::asin(radius / distance)) / std::tan(smallerHalfFov);
    QVERIFY2(std::abs(fill - Camera::kFramingFill) < 1e-9,
        qPrintable(report + QStringLiteral("; fill %1").arg(fill)));
}

void CameraTest::wideReferenceFramingIsTheReferenceView()
{
    // The reference view (docs/architecture.md) frames the unit sphere exactly as framing does in a square
    // or wide image: F there gives the reference distance back.
    const Camera reference = Camera::referenceView();
    for (const double aspect : {1.0, 1.5, 16.0 / 9.0})
        QVERIFY(std::abs(reference.framingDistance(1.0, aspect) - 3.0) < 1e-12);
    // A tall image needs more: 1 / sin(atan(0.854 tan(11.70 deg))) = 5.74 at aspect 0.5.
    QVERIFY(std::abs(reference.framingDistance(1.0, 0.5) - 5.7446) < 1e-3);
    QVERIFY(std::abs(Camera::kFramingFill - (2.0 + std::sqrt(2.0)) / 4.0) < 1e-15);
}

QTEST_APPLESS_MAIN(CameraTest)
#include "CameraTest.moc"
