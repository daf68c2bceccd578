// Picking a part of the mesh under a pixel (core/mesh/MeshPicking.h): a table of rays against small
// meshes of quads with known answers (a hit, misses, the nearest of two, back faces seen from
// behind with and without culling, hidden parts, translated / rotated / scaled / mirrored model
// matrices), and the ray through a pixel checked against the projection the renderer uses: a
// world point projected with Camera::viewMatrix/projectionMatrix to a pixel lies on the ray
// cameraRay gives for that pixel. And what the value picker reads at a hit (core/mesh/SurfaceProbe.h):
// a table of one map at a time and all together on a textured quad (the texel the point falls in,
// counted from the top as an image editor does; stored, decoded and filtered values; the map's
// UV set, transform and wrap; channel pick and inversion into the material's inputs; the normal
// map's tilt; model rotation and back faces; a released map read as absent). Needs nothing.

#include "core/mesh/MeshPicking.h"
#include "core/image/ToneMap.h"
#include "core/mesh/Mesh.h"
#include "core/mesh/MeshPrimitives.h"
#include "core/mesh/SurfaceProbe.h"
#include "core/project/Camera.h"

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
    void surfaceProbeReadsEachMap_data();
    void surfaceProbeReadsEachMap();
    void surfaceProbeFrame_data();
    void surfaceProbeFrame();
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

namespace {

// The unit quad [0, 1]^2 at z = 0 facing +Z: TEXCOORD_0 = (x, y), TEXCOORD_1 = (1 - x, y), tangent +X.
Mesh texturedQuad()
{
    Mesh mesh = meshOf({Quad {0, 1, 0, 1, 0}});
    for (Vertex& v : mesh.vertices) {
        v.uv = glm::vec2(v.position.x, v.position.y);
        v.uv1 = glm::vec2(1.0f - v.position.x, v.position.y);
        v.tangent = glm::vec4(1, 0, 0, 1);
    }
    mesh.hasUvs = mesh.hasTangents = mesh.hasTexCoord1 = true;
    return mesh;
}

// A 4x4 RGBA8 map whose texel (x, y from the top) stores ((64x + 16) / 255, (64y + 32) / 255,
// 128 / 255, 1): every texel tells where it is.
std::shared_ptr<const MapImage> locatingMap()
{
    Image pixels(4, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            pixels.at(x, y) = glm::vec4((64 * x + 16) / 255.0f, (64 * y + 32) / 255.0f, 128 / 255.0f, 1.0f);
    return std::make_shared<const MapImage>(
        MapImage::fromImage(pixels, MapLayout::Rgba, MapSampleType::UInt8));
}

glm::dvec4 storedAt(int x, int yFromTop)
{
    return glm::dvec4((64 * x + 16) / 255.0, (64 * yFromTop + 32) / 255.0, 128 / 255.0, 1.0);
}

bool near(const glm::dvec4& a, const glm::dvec4& b, double tolerance = 1e-6)
{
    return glm::length(a - b) <= tolerance;
}

SurfaceProbe probeQuadAt(const Material& material, const MaterialMapImages& images, const glm::dvec2& point)
{
    const Mesh mesh = texturedQuad();
    const std::optional<MeshHit> hit
        = pickMesh(mesh, glm::dmat4(1.0), PickRay {glm::dvec3(point, 5.0), glm::dvec3(0, 0, -1)});
    if (!hit)
        return {};
    return probeSurface(mesh, glm::dmat4(1.0), *hit, material, images);
}

enum class MapCase {
    BaseColorSrgb, // decoded per texel: linear != stored
    RoughnessGreenInverted, // channel pick and inversion feed the input
    MetallicBlueUvTransform, // the map's UV transform moves the texel
    OcclusionSet1, // TEXCOORD_1
    RoughnessWrapsBeyondOne, // UV scale 2: point 0.8 reads uv 1.6, texel of 0.6
    ReleasedMapIsAbsent, // a map without pixels (the window let it go): the factor alone
    AllTogether, // base colour, roughness and metallic at once, each its own read
};

} // namespace

Q_DECLARE_METATYPE(MapCase)

void MeshPickingTest::surfaceProbeReadsEachMap_data()
{
    QTest::addColumn<MapCase>("which");
    QTest::newRow("base colour, sRGB") << MapCase::BaseColorSrgb;
    QTest::newRow("roughness: green, inverted") << MapCase::RoughnessGreenInverted;
    QTest::newRow("metallic: blue, UV transform") << MapCase::MetallicBlueUvTransform;
    QTest::newRow("occlusion: TEXCOORD_1") << MapCase::OcclusionSet1;
    QTest::newRow("roughness: UV beyond 1 repeats") << MapCase::RoughnessWrapsBeyondOne;
    QTest::newRow("released map: factor alone") << MapCase::ReleasedMapIsAbsent;
    QTest::newRow("all together") << MapCase::AllTogether;
}

void MeshPickingTest::surfaceProbeReadsEachMap()
{
    QFETCH(MapCase, which);
    const std::shared_ptr<const MapImage> map = locatingMap();
    const MapImage released = MapImage::withoutPixels(*map);
    Material material;
    material.map(MapSlot::Roughness).factor = glm::dvec4(0.5);
    MaterialMapImages images {};
    const auto give = [&](MapSlot slot, const MapImage* image = nullptr) {
        material.map(slot).path = "locating.png";
        images[std::size_t(slot)] = image ? image : map.get();
    };
    // The centre of texel (1, 1 from the top) = (1, 2 from the bottom): uv (0.375, 0.625).
    glm::dvec2 point(0.375, 0.625);
    switch (which) {
    case MapCase::BaseColorSrgb:
        give(MapSlot::BaseColor);
        material.map(MapSlot::BaseColor).colorSpace = ColorEncoding::SRGB;
        break;
    case MapCase::RoughnessGreenInverted:
        give(MapSlot::Roughness);
        material.map(MapSlot::Roughness).channel = MapChannel::G;
        material.map(MapSlot::Roughness).invert = true;
        material.map(MapSlot::Roughness).factor = glm::dvec4(1.0);
        break;
    case MapCase::MetallicBlueUvTransform:
        give(MapSlot::Metallic);
        material.map(MapSlot::Metallic).channel = MapChannel::B;
        material.map(MapSlot::Metallic).factor = glm::dvec4(1.0);
        material.map(MapSlot::Metallic).uv.offset = glm::dvec2(0.25, 0.0); // one texel right
        break;
    case MapCase::OcclusionSet1:
        give(MapSlot::Occlusion);
        material.map(MapSlot::Occlusion).texCoord = 1; // u = 1 - x = 0.625: texel 2
        break;
    case MapCase::RoughnessWrapsBeyondOne:
        give(MapSlot::Roughness);
        material.map(MapSlot::Roughness).uv.scale = glm::dvec2(2.0, 1.0);
        point = glm::dvec2(0.6875, 0.625); // u 1.375: texel 1 again
        break;
    case MapCase::ReleasedMapIsAbsent:
        give(MapSlot::Roughness, &released);
        break;
    case MapCase::AllTogether:
        give(MapSlot::BaseColor);
        give(MapSlot::Roughness);
        give(MapSlot::Metallic);
        material.map(MapSlot::Roughness).channel = MapChannel::G;
        material.map(MapSlot::Metallic).channel = MapChannel::B;
        material.map(MapSlot::Metallic).factor = glm::dvec4(1.0);
        break;
    }
    const SurfaceProbe probe = probeQuadAt(material, images, point);
    QVERIFY(glm::length(probe.uvs[0] - point) < 1e-9);
    QVERIFY(glm::length(probe.uvs[1] - glm::dvec2(1.0 - point.x, point.y)) < 1e-9);

    const auto readOf = [&](MapSlot slot) -> const MapProbe* {
        for (const MapProbe& read : probe.maps)
            if (read.slot == slot)
                return &read;
        return nullptr;
    };
    switch (which) {
    case MapCase::BaseColorSrgb: {
        const MapProbe* read = readOf(MapSlot::BaseColor);
        QVERIFY(read);
        QCOMPARE(read->texel, glm::ivec2(1, 1));
        QCOMPARE(read->size, glm::ivec2(4, 4));
        QVERIFY(near(read->stored, storedAt(1, 1)));
        const glm::dvec4 decoded(tonemap::srgbToLinear(storedAt(1, 1).r),
            tonemap::srgbToLinear(storedAt(1, 1).g), tonemap::srgbToLinear(storedAt(1, 1).b), 1.0);
        QVERIFY(near(read->linear, decoded, 1e-6));
        QVERIFY(near(read->filtered, read->linear, 1e-9)); // a texel centre reads the texel
        const glm::dvec3 factor(material.baseColorFactor());
        QVERIFY(glm::length(probe.inputs.baseColor - factor * glm::dvec3(decoded)) < 1e-6);
        break;
    }
    case MapCase::RoughnessGreenInverted: {
        const MapProbe* read = readOf(MapSlot::Roughness);
        QVERIFY(read);
        QVERIFY(near(read->linear, read->stored)); // a data map is not decoded
        QVERIFY(std::abs(probe.inputs.perceptualRoughness - (1.0 - storedAt(1, 1).g)) < 1e-6);
        break;
    }
    case MapCase::MetallicBlueUvTransform: {
        const MapProbe* read = readOf(MapSlot::Metallic);
        QVERIFY(read);
        QVERIFY(glm::length(read->uv - glm::dvec2(0.625, 0.625)) < 1e-9);
        QCOMPARE(read->texel, glm::ivec2(2, 1));
        QVERIFY(std::abs(probe.inputs.metallic - 128 / 255.0) < 1e-6);
        break;
    }
    case MapCase::OcclusionSet1: {
        const MapProbe* read = readOf(MapSlot::Occlusion);
        QVERIFY(read);
        QCOMPARE(read->texel, glm::ivec2(2, 1));
        QVERIFY(near(read->stored, storedAt(2, 1)));
        break;
    }
    case MapCase::RoughnessWrapsBeyondOne: {
        const MapProbe* read = readOf(MapSlot::Roughness);
        QVERIFY(read);
        QVERIFY(std::abs(read->uv.x - 1.375) < 1e-9);
        QCOMPARE(read->texel, glm::ivec2(1, 1));
        break;
    }
    case MapCase::ReleasedMapIsAbsent:
        QVERIFY(probe.maps.empty());
        QCOMPARE(probe.inputs.perceptualRoughness, 0.5);
        break;
    case MapCase::AllTogether:
        QCOMPARE(int(probe.maps.size()), 3);
        QCOMPARE(probe.maps[0].slot, MapSlot::BaseColor); // MapSlot order
        for (const MapProbe& read : probe.maps) {
            QCOMPARE(read.texel, glm::ivec2(1, 1));
            QVERIFY(near(read.stored, storedAt(1, 1)));
        }
        QVERIFY(std::abs(probe.inputs.perceptualRoughness - 0.5 * storedAt(1, 1).g) < 1e-6);
        QVERIFY(std::abs(probe.inputs.metallic - 128 / 255.0) < 1e-6);
        break;
    }
}

void MeshPickingTest::surfaceProbeFrame_data()
{
    QTest::addColumn<int>("rotationDegrees"); // about +Y
    QTest::addColumn<bool>("fromBehind");
    QTest::addColumn<bool>("normalMap");
    QTest::addColumn<glm::dvec3>("expectedNormal"); // geometric, world space
    QTest::newRow("facing the ray") << 0 << false << false << glm::dvec3(0, 0, 1);
    QTest::newRow("seen from behind: turned to the viewer") << 0 << true << false << glm::dvec3(0, 0, -1);
    QTest::newRow("rotated 90 degrees") << 90 << false << false << glm::dvec3(1, 0, 0);
    QTest::newRow("normal map tilts toward +tangent") << 0 << false << true << glm::dvec3(0, 0, 1);
    QTest::newRow("normal map, rotated") << 90 << false << true << glm::dvec3(1, 0, 0);
}

void MeshPickingTest::surfaceProbeFrame()
{
    QFETCH(int, rotationDegrees);
    QFETCH(bool, fromBehind);
    QFETCH(bool, normalMap);
    QFETCH(glm::dvec3, expectedNormal);
    const Mesh mesh = texturedQuad();
    const glm::dmat4 model
        = glm::rotate(glm::dmat4(1.0), glm::radians(double(rotationDegrees)), glm::dvec3(0, 1, 0));
    const glm::dvec3 local(0.3, 0.6, 0.0);
    const glm::dvec3 world(model * glm::dvec4(local, 1.0));
    const glm::dvec3 facing(model * glm::dvec4(0, 0, fromBehind ? -1 : 1, 0));
    const PickRay ray {world + 5.0 * facing, -facing};
    const std::optional<MeshHit> hit = pickMesh(mesh, model, ray);
    QVERIFY(hit);
    Material material;
    MaterialMapImages images {};
    // A tangent-space normal tilted 45 degrees toward +X: texel (0.5 + 0.5 sin, 0.5, 0.5 + 0.5 cos).
    Image tilt(1, 1);
    tilt.at(0, 0) = glm::vec4(0.5f + 0.5f * 0.70710678f, 0.5f, 0.5f + 0.5f * 0.70710678f, 1.0f);
    const MapImage tiltMap = MapImage::fromImage(tilt, MapLayout::Rgb, MapSampleType::Half);
    if (normalMap) {
        material.map(MapSlot::Normal).path = "tilt.exr";
        images[std::size_t(MapSlot::Normal)] = &tiltMap;
    }
    const SurfaceProbe probe = probeSurface(mesh, model, *hit, material, images);
    QVERIFY(glm::length(probe.position - world) < 1e-9);
    QVERIFY2(glm::length(probe.geometricNormal - expectedNormal) < 1e-9,
        qPrintable(QStringLiteral("%1 %2 %3")
                       .arg(probe.geometricNormal.x)
                       .arg(probe.geometricNormal.y)
                       .arg(probe.geometricNormal.z)));
    if (!normalMap) {
        QVERIFY(glm::length(probe.shadingNormal - probe.geometricNormal) < 1e-9);
    } else {
        const glm::dvec3 tangent(model * glm::dvec4(1, 0, 0, 0));
        const glm::dvec3 expected = glm::normalize(expectedNormal + tangent); // 45 degrees toward it
        QVERIFY(glm::length(probe.shadingNormal - expected) < 2e-3); // half-float texel
    }
}

QTEST_APPLESS_MAIN(MeshPickingTest)
#include "MeshPickingTest.moc"
