// Picking a part of the mesh under a pixel (core/MeshPicking.h): a table of rays against small
// meshes of quads with known answers (a hit, misses, the nearest of two, back faces seen from
// behind with and without culling, hidden parts, translated / rotated / scaled / mirrored model
// matrices), and the ray through a pixel checked against the projection the renderer uses: a
// world point projected with Camera::viewMatrix/projectionMatrix to a pixel lies on the ray
// cameraRay gives for that pixel. Needs nothing.

#include "core/MeshPicking.h"
#include "core/Camera.h"
#include "core/Mesh.h"
#include "core/MeshPrimitives.h"

#include <QtTest/QTest>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <optional>
#include <vector>

using namespace facet;

namespace {

// A quad in the plane z = `z` covering [x0, x1] x [y0, y1], wound counter-clockwise seen from +Z
// (its front faces +Z), as one sub-mesh.
struct Quad {
    float x0, x1, y0, y1, z;
};

Mesh meshOf(const std::vector<Quad>& quads)
{
    Mesh mesh;
    mesh.name = "quads";
    for (const Quad& q : quads) {
        SubMesh sub;
        sub.name = "part " + std::to_string(mesh.subMeshes.size());
        sub.firstIndex = uint32_t(mesh.indices.size());
        sub.indexCount = 6;
        const uint32_t base = uint32_t(mesh.vertices.size());
        for (const glm::vec2 corner :
            {glm::vec2(q.x0, q.y0), glm::vec2(q.x1, q.y0), glm::vec2(q.x1, q.y1), glm::vec2(q.x0, q.y1)}) {
            Vertex v;
            v.position = glm::vec3(corner, q.z);
            v.normal = glm::vec3(0, 0, 1);
            mesh.vertices.push_back(v);
        }
        for (const uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u})
            mesh.indices.push_back(base + i);
        mesh.subMeshes.push_back(sub);
    }
    mesh.updateBounds();
    return mesh;
}

enum class Scene {
    SideBySide, // part 0: x in [-1, 0]; part 1: x in [0, 1]; both at z = 0
    Stacked, // part 0 at z = 0, part 1 at z = 1, both [-1, 1]^2
    StackedReversed, // part 0 at z = 1, part 1 at z = 0 (the order in the file must not matter)
    Single, // one quad [-1, 1]^2 at z = 0
};

Mesh sceneMesh(Scene scene)
{
    switch (scene) {
    case Scene::SideBySide:
        return meshOf({{-1, 0, -1, 1, 0}, {0, 1, -1, 1, 0}});
    case Scene::Stacked:
        return meshOf({{-1, 1, -1, 1, 0}, {-1, 1, -1, 1, 1}});
    case Scene::StackedReversed:
        return meshOf({{-1, 1, -1, 1, 1}, {-1, 1, -1, 1, 0}});
    case Scene::Single:
        return meshOf({{-1, 1, -1, 1, 0}});
    }
    return {};
}

enum class Model { Identity, Translated, TurnedAboutY, Scaled, Mirrored };

glm::dmat4 modelMatrix(Model model)
{
    switch (model) {
    case Model::Identity:
        return glm::dmat4(1.0);
    case Model::Translated:
        return glm::translate(glm::dmat4(1.0), glm::dvec3(2.0, 0.0, 0.0));
    case Model::TurnedAboutY: // the turntable: +90 degrees about +Y takes +Z to +X
        return glm::rotate(glm::dmat4(1.0), glm::radians(90.0), glm::dvec3(0.0, 1.0, 0.0));
    case Model::Scaled:
        return glm::scale(glm::dmat4(1.0), glm::dvec3(2.0));
    case Model::Mirrored:
        return glm::scale(glm::dmat4(1.0), glm::dvec3(-1.0, 1.0, 1.0));
    }
    return glm::dmat4(1.0);
}

} // namespace

Q_DECLARE_METATYPE(Scene)
Q_DECLARE_METATYPE(Model)
Q_DECLARE_METATYPE(glm::dvec3)

class MeshPickingTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void picksTheNearestVisiblePart_data();
    void picksTheNearestVisiblePart();
    void meshWithoutSubMeshesIsOnePart();
    void unusableInputsMiss();
    void sphereIsHitAtItsSurface();
    void rayThroughAPixelMeetsWhatProjectsThere_data();
    void rayThroughAPixelMeetsWhatProjectsThere();
    void centreAndCornerRays();
};

void MeshPickingTest::picksTheNearestVisiblePart_data()
{
    QTest::addColumn<Scene>("scene");
    QTest::addColumn<Model>("model");
    QTest::addColumn<glm::dvec3>("origin");
    QTest::addColumn<glm::dvec3>("direction");
    QTest::addColumn<QVector<bool>>("hidden"); // per part
    QTest::addColumn<QVector<bool>>("culled"); // per part: the material is single-sided
    QTest::addColumn<int>("expectedPart"); // -1: a miss
    QTest::addColumn<double>("expectedDistance");
    QTest::addColumn<bool>("expectedFront");

    const glm::dvec3 down(0, 0, -1); // from +Z toward the quads' fronts
    const glm::dvec3 up(0, 0, 1);
    const QVector<bool> none;
    // Hits and misses.
    QTest::newRow("hit: left part") << Scene::SideBySide << Model::Identity << glm::dvec3(-0.5, 0.2, 3)
                                    << down << none << none << 0 << 3.0 << true;
    QTest::newRow("hit: right part") << Scene::SideBySide << Model::Identity << glm::dvec3(0.5, -0.7, 3)
                                     << down << none << none << 1 << 3.0 << true;
    QTest::newRow("hit: slanted ray") << Scene::SideBySide << Model::Identity << glm::dvec3(-1.0, 0, 2)
                                      << glm::dvec3(0.75, 0, -1) << none << none << 1 << 2.0 << true;
    QTest::newRow("miss: beside the mesh") << Scene::SideBySide << Model::Identity << glm::dvec3(1.5, 0, 3)
                                           << down << none << none << -1 << 0.0 << true;
    QTest::newRow("miss: pointing away") << Scene::SideBySide << Model::Identity << glm::dvec3(0.5, 0, 3)
                                         << up << none << none << -1 << 0.0 << true;
    QTest::newRow("miss: parallel to the plane") << Scene::Single << Model::Identity << glm::dvec3(-3, 0, 0)
                                                 << glm::dvec3(1, 0, 0) << none << none << -1 << 0.0 << true;
    // Nearest of two, whichever comes first in the mesh.
    QTest::newRow("nearest of two: from the front")
        << Scene::Stacked << Model::Identity << glm::dvec3(0, 0, 3) << down << none << none << 1 << 2.0
        << true;
    QTest::newRow("nearest of two: listed the other way")
        << Scene::StackedReversed << Model::Identity << glm::dvec3(0, 0, 3) << down << none << none << 0
        << 2.0 << true;
    QTest::newRow("nearest of two: from behind") << Scene::Stacked << Model::Identity << glm::dvec3(0, 0, -3)
                                                 << up << none << none << 0 << 3.0 << false;
    // Back faces: hit while the material is double-sided, passed through when it culls them.
    QTest::newRow("back face, double-sided: hit") << Scene::Single << Model::Identity << glm::dvec3(0, 0, -3)
                                                  << up << none << none << 0 << 3.0 << false;
    QTest::newRow("back face, culled: miss") << Scene::Single << Model::Identity << glm::dvec3(0, 0, -3) << up
                                             << none << QVector<bool> {true} << -1 << 0.0 << false;
    QTest::newRow("front face of a culling part: hit")
        << Scene::Single << Model::Identity << glm::dvec3(0, 0, 3) << down << none << QVector<bool> {true}
        << 0 << 3.0 << true;
    QTest::newRow("back face culled: the part behind it")
        << Scene::Stacked << Model::Identity << glm::dvec3(0, 0, -3) << up << none
        << QVector<bool> {true, false} << 1 << 4.0 << false;
    // Hidden parts are not hit: the ray goes on to the next one, or misses.
    QTest::newRow("hidden part: the one behind")
        << Scene::Stacked << Model::Identity << glm::dvec3(0, 0, 3) << down << QVector<bool> {false, true}
        << none << 0 << 3.0 << true;
    QTest::newRow("hidden part: nothing behind")
        << Scene::SideBySide << Model::Identity << glm::dvec3(0.5, 0, 3) << down
        << QVector<bool> {false, true} << none << -1 << 0.0 << true;
    QTest::newRow("hidden part: the other still hit")
        << Scene::SideBySide << Model::Identity << glm::dvec3(-0.5, 0, 3) << down
        << QVector<bool> {false, true} << none << 0 << 3.0 << true;
    // The model matrix: the mesh is where it is drawn.
    QTest::newRow("translated: hit where it moved")
        << Scene::SideBySide << Model::Translated << glm::dvec3(2.5, 0, 3) << down << none << none << 1 << 3.0
        << true;
    QTest::newRow("translated: miss where it was")
        << Scene::SideBySide << Model::Translated << glm::dvec3(0.5, 0, 3) << down << none << none << -1
        << 0.0 << true;
    // +90 degrees about Y: the quads stand in the YZ plane facing +X, part 0 (x < 0) at z > 0.
    QTest::newRow("turned about Y: seen from +X")
        << Scene::SideBySide << Model::TurnedAboutY << glm::dvec3(3, 0, 0.5) << glm::dvec3(-1, 0, 0) << none
        << none << 0 << 3.0 << true;
    QTest::newRow("turned about Y: edge-on from +Z")
        << Scene::SideBySide << Model::TurnedAboutY << glm::dvec3(0.3, 0, 3) << down << none << none << -1
        << 0.0 << true;
    QTest::newRow("scaled 2: hit beyond the unscaled quad")
        << Scene::SideBySide << Model::Scaled << glm::dvec3(1.5, 0, 5) << down << none << none << 1 << 5.0
        << true;
    // A mirror reverses the winding as drawn (the renderer culls by screen winding, GL_CCW).
    QTest::newRow("mirrored: parts swap sides")
        << Scene::SideBySide << Model::Mirrored << glm::dvec3(0.5, 0, 3) << down << none << none << 0 << 3.0
        << false;
    QTest::newRow("mirrored: culled from the front")
        << Scene::SideBySide << Model::Mirrored << glm::dvec3(0.5, 0, 3) << down << none
        << QVector<bool> {true, true} << -1 << 0.0 << false;
}

void MeshPickingTest::picksTheNearestVisiblePart()
{
    QFETCH(Scene, scene);
    QFETCH(Model, model);
    QFETCH(glm::dvec3, origin);
    QFETCH(glm::dvec3, direction);
    QFETCH(QVector<bool>, hidden);
    QFETCH(QVector<bool>, culled);
    QFETCH(int, expectedPart);
    QFETCH(double, expectedDistance);
    QFETCH(bool, expectedFront);

    const Mesh mesh = sceneMesh(scene);
    std::vector<PickPart> parts(mesh.subMeshes.size());
    for (qsizetype i = 0; i < hidden.size(); ++i)
        parts[std::size_t(i)].visible = !hidden[i];
    for (qsizetype i = 0; i < culled.size(); ++i)
        parts[std::size_t(i)].cullsBackFaces = culled[i];
    const glm::dmat4 matrix = modelMatrix(model);
    const std::optional<MeshHit> hit = pickMesh(mesh, matrix, PickRay {origin, direction}, parts);
    if (expectedPart < 0) {
        QVERIFY2(!hit,
            hit ? qPrintable(QStringLiteral("hit part %1 at %2").arg(hit->subMesh).arg(hit->distance)) : "");
        return;
    }
    QVERIFY(hit);
    QCOMPARE(int(hit->subMesh), expectedPart);
    QVERIFY2(std::abs(hit->distance - expectedDistance) < 1e-9, qPrintable(QString::number(hit->distance)));
    QCOMPARE(hit->frontFace, expectedFront);
    // The reported point is on the ray, and on the hit triangle as drawn.
    const glm::dvec3 onRay = origin + hit->distance * direction;
    QVERIFY(glm::length(hit->position - onRay) < 1e-9);
    const uint32_t* corner = &mesh.indices[hit->triangle * 3];
    const glm::dvec3 p0 = glm::dvec3(matrix * glm::dvec4(glm::dvec3(mesh.vertices[corner[0]].position), 1.0));
    const glm::dvec3 p1 = glm::dvec3(matrix * glm::dvec4(glm::dvec3(mesh.vertices[corner[1]].position), 1.0));
    const glm::dvec3 p2 = glm::dvec3(matrix * glm::dvec4(glm::dvec3(mesh.vertices[corner[2]].position), 1.0));
    const glm::dvec2 b = hit->barycentric;
    const glm::dvec3 interpolated = (1.0 - b.x - b.y) * p0 + b.x * p1 + b.y * p2;
    QVERIFY2(glm::length(interpolated - hit->position) < 1e-9, "barycentric coordinates off the hit");
}

void MeshPickingTest::meshWithoutSubMeshesIsOnePart()
{
    Mesh mesh = sceneMesh(Scene::Stacked);
    mesh.subMeshes.clear();
    const auto hit = pickMesh(mesh, glm::dmat4(1.0), PickRay {{0.3, -0.2, 3}, {0, 0, -1}});
    QVERIFY(hit);
    QCOMPARE(hit->subMesh, std::size_t(0));
    QVERIFY(std::abs(hit->distance - 2.0) < 1e-9); // still the nearest triangle: the one at z = 1
    QCOMPARE(hit->triangle, std::size_t(2));
    // An entry saying part 0 is hidden hides the whole mesh.
    QVERIFY(!pickMesh(mesh, glm::dmat4(1.0), PickRay {{0, 0, 3}, {0, 0, -1}}, {PickPart {false, false}}));
}

void MeshPickingTest::unusableInputsMiss()
{
    const Mesh mesh = sceneMesh(Scene::Single);
    const PickRay good {{0, 0, 3}, {0, 0, -1}};
    QVERIFY(pickMesh(mesh, glm::dmat4(1.0), good));
    QVERIFY(!pickMesh(Mesh {}, glm::dmat4(1.0), good)); // empty mesh
    QVERIFY(!pickMesh(mesh, glm::dmat4(1.0), PickRay {{0, 0, 3}, {0, 0, 0}})); // zero direction
    QVERIFY(!pickMesh(mesh, glm::dmat4(0.0), good)); // singular model
    glm::dmat4 nan(1.0);
    nan[3][0] = std::nan("");
    QVERIFY(!pickMesh(mesh, nan, good));
    QVERIFY(!pickMesh(mesh, glm::dmat4(1.0), PickRay {{0, 0, std::nan("")}, {0, 0, -1}}));
    // An index out of range is skipped, not read.
    Mesh broken = mesh;
    broken.indices[0] = 1000;
    QVERIFY(!pickMesh(broken, glm::dmat4(1.0), PickRay {{0.5, -0.5, 3}, {0, 0, -1}})); // in triangle 0
    const auto other
        = pickMesh(broken, glm::dmat4(1.0), PickRay {{-0.5, 0.5, 3}, {0, 0, -1}}); // in triangle 1
    QVERIFY(other);
    QCOMPARE(other->triangle, std::size_t(1));
}

void MeshPickingTest::sphereIsHitAtItsSurface()
{
    std::optional<Mesh> sphere = makePrimitive("sphere");
    QVERIFY(sphere);
    sphere->normalizeToUnitSphere();
    // From the reference camera straight at the centre: the surface at distance 2 (the polygonal
    // sphere's faces lie inside the unit sphere by at most its chord sagitta).
    const auto hit = pickMesh(*sphere, glm::dmat4(1.0), PickRay {{0, 0, 3}, {0, 0, -1}});
    QVERIFY(hit);
    QVERIFY2(hit->distance >= 2.0 - 1e-6 && hit->distance < 2.02, qPrintable(QString::number(hit->distance)));
    QVERIFY(hit->frontFace);
}

void MeshPickingTest::rayThroughAPixelMeetsWhatProjectsThere_data()
{
    QTest::addColumn<glm::dvec3>("position");
    QTest::addColumn<double>("fov");
    QTest::addColumn<double>("width");
    QTest::addColumn<double>("height");
    QTest::addColumn<glm::dvec3>("point");
    QTest::newRow("reference view, square")
        << glm::dvec3(0, 0, 3) << 45.0 << 64.0 << 64.0 << glm::dvec3(0.3, -0.4, 0.5);
    QTest::newRow("reference view, wide")
        << glm::dvec3(0, 0, 3) << 45.0 << 1200.0 << 759.0 << glm::dvec3(-0.9, 0.2, 0);
    QTest::newRow("tall, off-axis camera")
        << glm::dvec3(2, 1.5, 2) << 30.0 << 300.0 << 900.0 << glm::dvec3(0.1, 0.6, -0.2);
    QTest::newRow("wide field of view")
        << glm::dvec3(-1, 0.5, 2.5) << 90.0 << 640.0 << 480.0 << glm::dvec3(-0.7, -0.3, 0.4);
}

void MeshPickingTest::rayThroughAPixelMeetsWhatProjectsThere()
{
    QFETCH(glm::dvec3, position);
    QFETCH(double, fov);
    QFETCH(double, width);
    QFETCH(double, height);
    QFETCH(glm::dvec3, point);
    Camera camera;
    camera.position = position;
    camera.verticalFovDegrees = fov;
    // The pixel the renderer draws `point` at: clip space, then the viewport transform (y down).
    const glm::dvec4 clip
        = camera.projectionMatrix(width / height) * camera.viewMatrix() * glm::dvec4(point, 1.0);
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    const glm::dvec2 pixel((ndc.x + 1.0) * 0.5 * width, (1.0 - ndc.y) * 0.5 * height);
    const PickRay ray = cameraRay(camera, width, height, pixel);
    QVERIFY(std::abs(glm::length(ray.direction) - 1.0) < 1e-12);
    QVERIFY(glm::length(ray.origin - position) < 1e-12);
    // The point lies on the ray: its distance from the line is ~0, and it is in front.
    const glm::dvec3 toPoint = point - ray.origin;
    const double along = glm::dot(toPoint, ray.direction);
    const double off = glm::length(toPoint - along * ray.direction);
    QVERIFY(along > 0.0);
    QVERIFY2(off < 1e-9, qPrintable(QString::number(off)));
}

void MeshPickingTest::centreAndCornerRays()
{
    const Camera camera = Camera::referenceView();
    const PickRay centre = cameraRay(camera, 64, 64, {32, 32});
    QVERIFY(glm::length(centre.direction - glm::dvec3(0, 0, -1)) < 1e-12);
    // The top-left corner of the image: up and to the left by tan(22.5 degrees) per unit ahead.
    const PickRay corner = cameraRay(camera, 64, 64, {0, 0});
    const double t = std::tan(glm::radians(22.5));
    QVERIFY(glm::length(corner.direction - glm::normalize(glm::dvec3(-t, t, -1))) < 1e-12);
}

QTEST_APPLESS_MAIN(MeshPickingTest)
#include "MeshPickingTest.moc"
