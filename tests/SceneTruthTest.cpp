// core/truth/RayScene and core/truth/SceneTruth: the ground truth of staged scenes held to closed
// forms, each a table of rows.
// - The convex-object truth as its special case: the reference sphere alone renders as
//   core/shading/GroundTruth renders it (a row per material kind, under the built-in sky).
// - A Lambert floor alone under a uniform environment L has radiance albedo x L at every pixel
//   (its points see the upper hemisphere whole).
// - A black sphere resting on the floor (y = -1) under the uniform environment: a floor point at
//   distance d from the sphere's centre sees it as a cap of half-angle asin(1/d) centred at
//   elevation asin(1/d), whose projected solid angle is pi sin^2(a) cos(b) = pi / d^3, so its
//   radiance is albedo L (1 - 1/d^3): the contact darkening, exactly.
// - The shadow of a sphere and of a box mesh (Embree's triangles) under one directional light,
//   pixel by pixel: albedo / pi x E cos(theta) where the ray to the light is free, 0 where the
//   object blocks it (decided analytically for each pixel's floor point).
// - Rays: intersect and occluded agree with the analytic sphere and with a box's slab test.

#include <QtTest/QTest>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "core/ibl/Environment.h"
#include "core/image/ImageMetrics.h"
#include "core/mesh/MeshPrimitives.h"
#include "core/shading/GroundTruth.h"
#include "core/shading/ReferenceView.h"
#include "core/truth/RayScene.h"
#include "core/truth/SceneTruth.h"

#include "TestSupport.h"

using namespace facet;

namespace {

constexpr int kSize = 48;
constexpr double kFloorHeight = -1.0;

// A material that reflects nothing at all: black, and no specular layer (KHR_materials_specular 0).
MaterialInfo blackMaterial()
{
    MaterialInfo m;
    m.baseColor = glm::dvec3(0.0);
    m.specular = 0.0;
    return m;
}

// A Lambert surface: a dielectric without its specular layer.
MaterialInfo lambert(double albedo)
{
    MaterialInfo m;
    m.baseColor = glm::dvec3(albedo);
    m.specular = 0.0;
    return m;
}

// Where the reference view's ray through pixel (x, y) meets the floor (kFloorSize wide, centred
// under the origin); nullopt where it passes beside or above it.
constexpr double kFloorSize = 200.0;
std::optional<glm::dvec3> floorPoint(int x, int y)
{
    const glm::dvec3 d = referenceview::rayDirection(x, y, kSize, kSize);
    if (d.y >= 0.0)
        return std::nullopt;
    const double t = (kFloorHeight - referenceview::kEye.y) / d.y;
    const glm::dvec3 p = referenceview::kEye + t * d;
    // A margin from the edge: the floor's far points are seen at grazing angles.
    if (std::abs(p.x) > 0.45 * kFloorSize || std::abs(p.z) > 0.45 * kFloorSize)
        return std::nullopt;
    return p;
}

bool hitsUnitSphere(const glm::dvec3& origin, const glm::dvec3& direction)
{
    const double b = glm::dot(origin, direction);
    const double c = glm::dot(origin, origin) - 1.0;
    const double discriminant = b * b - c;
    return discriminant >= 0.0 && -b + std::sqrt(discriminant) > 0.0;
}

// The slab test of the ray against the box [lo, hi].
bool hitsBox(
    const glm::dvec3& origin, const glm::dvec3& direction, const glm::dvec3& lo, const glm::dvec3& hi)
{
    double near = 0.0;
    double far = 1e30;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(direction[i]) < 1e-15) {
            if (origin[i] < lo[i] || origin[i] > hi[i])
                return false;
            continue;
        }
        double t0 = (lo[i] - origin[i]) / direction[i];
        double t1 = (hi[i] - origin[i]) / direction[i];
        if (t0 > t1)
            std::swap(t0, t1);
        near = std::max(near, t0);
        far = std::min(far, t1);
    }
    return near <= far;
}

SceneTruthSettings settings(int samples)
{
    SceneTruthSettings s;
    s.width = kSize;
    s.height = kSize;
    s.samplesPerPixel = samples;
    return s;
}

} // namespace

class SceneTruthTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void raysMeetTheSphereAndTheBox();
    void convexSphereIsTheSphereTruth_data();
    void convexSphereIsTheSphereTruth();
    void floorAloneReflectsAlbedoTimesL_data();
    void floorAloneReflectsAlbedoTimesL();
    void contactDarkeningIsExact();
    void shadowsUnderOneLight_data();
    void shadowsUnderOneLight();
};

void SceneTruthTest::raysMeetTheSphereAndTheBox()
{
    RayScene scene;
    const int sphere = scene.addUnitSphere();
    // makeCube spans -1 to 1: scaled by 0.5 about (3, 0, 0), a box from x = 2.5 to 3.5.
    const int boxSurface = scene.addMesh(
        makeCube(), glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(3.0, 0.0, 0.0)), glm::dvec3(0.5)));
    std::string error;
    QVERIFY2(scene.commit(&error), error.c_str());
    QCOMPARE(scene.surfaceCount(), 2);

    // Along +X from the far left: the sphere first, at x = -1, its outward normal facing the ray.
    std::optional<RayHit> hit = scene.intersect(glm::dvec3(-5.0, 0.0, 0.0), glm::dvec3(1.0, 0.0, 0.0));
    QVERIFY(hit);
    QCOMPARE(hit->surface, sphere);
    QVERIFY(std::abs(hit->distance - 4.0) < 1e-12);
    QVERIFY(glm::length(hit->geometricNormal - glm::dvec3(-1.0, 0.0, 0.0)) < 1e-12);
    QVERIFY(!hit->backFace);
    // From inside the sphere: its far side, from behind.
    hit = scene.intersect(glm::dvec3(0.0), glm::dvec3(1.0, 0.0, 0.0));
    QVERIFY(hit && hit->surface == sphere && hit->backFace);
    QVERIFY(glm::length(hit->geometricNormal - glm::dvec3(-1.0, 0.0, 0.0)) < 1e-12);
    // Past the sphere: the box's face at x = 2.5 (Embree, single precision).
    hit = scene.intersect(glm::dvec3(1.5, 0.1, 0.2), glm::dvec3(1.0, 0.0, 0.0));
    QVERIFY(hit);
    QCOMPARE(hit->surface, boxSurface);
    QVERIFY(std::abs(hit->distance - 1.0) < 1e-5);
    QVERIFY(glm::length(hit->geometricNormal - glm::dvec3(-1.0, 0.0, 0.0)) < 1e-5);
    // Shadow rays: the range counts.
    QVERIFY(scene.occluded(glm::dvec3(1.5, 0.1, 0.2), glm::dvec3(1.0, 0.0, 0.0)));
    QVERIFY(!scene.occluded(glm::dvec3(1.5, 0.1, 0.2), glm::dvec3(1.0, 0.0, 0.0), 0.0, 0.9));
    QVERIFY(!scene.occluded(glm::dvec3(1.5, 0.1, 0.2), glm::dvec3(0.0, 1.0, 0.0)));
    QVERIFY(!scene.intersect(glm::dvec3(0.0, 5.0, 0.0), glm::dvec3(0.0, 1.0, 0.0)));
}

// The truth of one convex object is this integrator's special case.
void SceneTruthTest::convexSphereIsTheSphereTruth_data()
{
    QTest::addColumn<double>("metallic");
    QTest::addColumn<double>("roughness");
    QTest::addColumn<double>("clearcoat");
    QTest::newRow("dielectric 0.5") << 0.0 << 0.5 << 0.0;
    QTest::newRow("metal 0.3") << 1.0 << 0.3 << 0.0;
    QTest::newRow("coated dielectric 0.7") << 0.0 << 0.7 << 1.0;
}

void SceneTruthTest::convexSphereIsTheSphereTruth()
{
    QFETCH(double, metallic);
    QFETCH(double, roughness);
    QFETCH(double, clearcoat);
    MaterialInfo material;
    material.baseColor = glm::dvec3(0.8, 0.5, 0.3);
    material.metallic = metallic;
    material.perceptualRoughness = roughness;
    material.clearcoat = clearcoat;
    material.clearcoatRoughness = 0.2;
    const Environment environment = Environment::builtin(Environment::Builtin::Sky, 128);

    GroundTruthScene sphereScene;
    sphereScene.material = material;
    sphereScene.environment = environment;
    GroundTruthSettings sphereSettings;
    sphereSettings.width = kSize;
    sphereSettings.height = kSize;
    sphereSettings.samplesPerPixel = 512;
    const Image expected = renderGroundTruth(sphereScene, sphereSettings);

    SceneTruthScene scene;
    scene.geometry.addUnitSphere();
    std::string error;
    QVERIFY2(scene.geometry.commit(&error), error.c_str());
    scene.surfaces = {{material, ShadingModel {}}};
    scene.environment = environment;
    const Image image = renderSceneTruth(scene, settings(512));

    const double relative = relativeRmse(image, expected);
    // Both converge to one integral, with the same stratified points at the first surface: 0.38%
    // to 0.57% apart at 512 samples.
    qInfo("relative RMSE against the sphere truth: %.4f", relative);
    QVERIFY2(relative < 0.01, qPrintable(QStringLiteral("relative RMSE %1").arg(relative)));
}

void SceneTruthTest::floorAloneReflectsAlbedoTimesL_data()
{
    QTest::addColumn<double>("albedo");
    QTest::addColumn<double>("radiance");
    QTest::newRow("albedo 0.5, L 1") << 0.5 << 1.0;
    QTest::newRow("albedo 0.9, L 3") << 0.9 << 3.0;
    QTest::newRow("albedo 0, L 2") << 0.0 << 2.0;
}

void SceneTruthTest::floorAloneReflectsAlbedoTimesL()
{
    QFETCH(double, albedo);
    QFETCH(double, radiance);
    SceneTruthScene scene;
    scene.geometry.addFloor(kFloorHeight, kFloorSize, glm::dvec2(0.0));
    std::string error;
    QVERIFY2(scene.geometry.commit(&error), error.c_str());
    scene.surfaces = {{lambert(albedo), ShadingModel {}}};
    scene.environment = Environment::uniform(glm::dvec3(radiance));
    const Image image = renderSceneTruth(scene, settings(64));
    int floorPixels = 0;
    double worst = 0.0;
    double sum = 0.0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            if (!floorPoint(x, y))
                continue;
            ++floorPixels;
            const double got = image.at(x, y).y;
            sum += got;
            worst = std::max(worst, std::abs(got - albedo * radiance));
        }
    QVERIFY(floorPixels > kSize * kSize / 3);
    const double mean = sum / floorPixels;
    const double expected = albedo * radiance;
    qInfo("floor alone: mean %.5f, expected %.5f, worst pixel off by %.5f", mean, expected, worst);
    // Unbiased: the mean over the floor's pixels (measured within 0.01%); each pixel within its
    // noise (64 samples: the worst of about 1100 pixels 2.2% off).
    QVERIFY2(std::abs(mean - expected) <= 0.002 * std::max(expected, 0.05),
        qPrintable(QStringLiteral("mean %1").arg(mean)));
    QVERIFY2(worst <= 0.03 * std::max(expected, 0.05), qPrintable(QStringLiteral("worst %1").arg(worst)));
}

void SceneTruthTest::contactDarkeningIsExact()
{
    const double albedo = 0.8;
    SceneTruthScene scene;
    scene.geometry.addUnitSphere();
    scene.geometry.addFloor(kFloorHeight, kFloorSize, glm::dvec2(0.0));
    std::string error;
    QVERIFY2(scene.geometry.commit(&error), error.c_str());
    scene.surfaces = {{blackMaterial(), ShadingModel {}}, {lambert(albedo), ShadingModel {}}};
    scene.environment = Environment::uniform(glm::dvec3(1.0));
    SceneTruthStats stats;
    const Image image = renderSceneTruth(scene, settings(1024), &stats);
    qInfo("%d x %d at 1024 spp: %.2f s, %.1f million rays per second", kSize, kSize, stats.seconds,
        double(stats.rays) / stats.seconds * 1e-6);
    const glm::dvec3 centre(0.0);
    double squared = 0.0;
    double reference = 0.0;
    double nearest = 1e9;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const glm::dvec3 d = referenceview::rayDirection(x, y, kSize, kSize);
            const std::optional<glm::dvec3> p = floorPoint(x, y);
            if (!p || hitsUnitSphere(referenceview::kEye, d))
                continue;
            const double distance = glm::length(*p - centre);
            nearest = std::min(nearest, distance);
            const double expected = albedo * (1.0 - 1.0 / (distance * distance * distance));
            const double got = image.at(x, y).y;
            squared += (got - expected) * (got - expected);
            reference += expected * expected;
        }
    QVERIFY(nearest < 1.5); // the darkening near the contact is in the picture
    const double relative = std::sqrt(squared / reference);
    // Measured 0.25% at 1024 samples.
    qInfo("contact darkening: relative RMSE %.4f against albedo L (1 - 1/d^3)", relative);
    QVERIFY2(relative < 0.01, qPrintable(QStringLiteral("relative RMSE %1").arg(relative)));
}

void SceneTruthTest::shadowsUnderOneLight_data()
{
    QTest::addColumn<bool>("box"); // a box mesh (Embree) rather than the analytic sphere
    // The direction the light travels.
    QTest::addColumn<double>("x");
    QTest::addColumn<double>("y");
    QTest::addColumn<double>("z");
    QTest::newRow("sphere, light from above") << false << 0.0 << -1.0 << 0.0;
    QTest::newRow("sphere, light low from the left") << false << 1.0 << -0.6 << -0.3;
    QTest::newRow("box, light from above right") << true << -0.5 << -1.0 << -0.4;
}

void SceneTruthTest::shadowsUnderOneLight()
{
    QFETCH(bool, box);
    QFETCH(double, x);
    QFETCH(double, y);
    QFETCH(double, z);
    const glm::dvec3 travel(x, y, z);
    const double albedo = 0.7;
    const double lux = 3.0;
    const glm::dvec3 lo(-0.6, kFloorHeight, -0.6);
    const glm::dvec3 hi(0.6, kFloorHeight + 1.2, 0.6);
    SceneTruthScene scene;
    if (box)
        scene.geometry.addMesh(
            makeCube(), glm::scale(glm::translate(glm::dmat4(1.0), 0.5 * (lo + hi)), 0.5 * (hi - lo)));
    else
        scene.geometry.addUnitSphere();
    scene.geometry.addFloor(kFloorHeight, kFloorSize, glm::dvec2(0.0));
    std::string error;
    QVERIFY2(scene.geometry.commit(&error), error.c_str());
    scene.surfaces = {{blackMaterial(), ShadingModel {}}, {lambert(albedo), ShadingModel {}}};
    scene.environment = Environment::uniform(glm::dvec3(0.0));
    Light light;
    light.type = LightType::Directional;
    light.intensity = lux;
    light.direction = travel;
    scene.lights = {light};
    // The light and a black object: no noise at all, one sample is the answer.
    const Image image = renderSceneTruth(scene, settings(1));
    const glm::dvec3 toLight = -glm::normalize(travel);
    int shadowed = 0;
    int lit = 0;
    for (int py = 0; py < kSize; ++py)
        for (int px = 0; px < kSize; ++px) {
            const glm::dvec3 d = referenceview::rayDirection(px, py, kSize, kSize);
            const std::optional<glm::dvec3> p = floorPoint(px, py);
            if (!p
                || (box ? hitsBox(referenceview::kEye, d, lo, hi) : hitsUnitSphere(referenceview::kEye, d)))
                continue;
            // A point whose ray to the light grazes the object (a box grown or shrunk by 1e-3, or
            // the sphere's shadow boundary) is left out: single and double precision may differ there.
            const glm::dvec3 margin(1e-3);
            const bool blocked = box ? hitsBox(*p, toLight, lo, hi) : hitsUnitSphere(*p, toLight);
            const bool grazes = box ? hitsBox(*p, toLight, lo - margin, hi + margin)
                    != hitsBox(*p, toLight, lo + margin, hi - margin)
                                    : std::abs(glm::length(glm::cross(*p, toLight)) - 1.0) < 1e-3;
            if (grazes)
                continue;
            const double expected = blocked ? 0.0 : albedo / std::numbers::pi * lux * toLight.y;
            const double got = image.at(px, py).y;
            (blocked ? shadowed : lit) += 1;
            QVERIFY2(std::abs(got - expected) < 1e-4,
                qPrintable(QStringLiteral("pixel %1,%2: %3, expected %4 (%5)")
                               .arg(px)
                               .arg(py)
                               .arg(got)
                               .arg(expected)
                               .arg(QLatin1String(blocked ? "in shadow" : "lit"))));
        }
    QVERIFY(shadowed > 20);
    QVERIFY(lit > 200);
}

QTEST_GUILESS_MAIN(SceneTruthTest)
#include "SceneTruthTest.moc"
