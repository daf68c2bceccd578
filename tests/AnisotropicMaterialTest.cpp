// KHR_materials_anisotropy in the CPU material (core/shading/MaterialBrdf, the ground truth's
// integrand, and its inputs): the base's specular lobes take the extension's anisotropic D and V in
// the frame of the direction (a row per strength, roughness and direction, the Gram-Schmidt of a
// direction off the tangent plane included); strength 0, no direction or a direction along n give
// the isotropic BRDF exactly; the lobe is reciprocal, turns with its frame and is symmetric under
// t -> -t; the white furnace gains nothing and, without compensation, equals the lobe's own
// visible-normal albedo; the ground truth's integrator, whose BRDF strategy samples the stretched
// lobe, agrees with a plain cosine-weighted integral of the same BRDF; the reference sphere's
// tangent is the sphere mesh's; and the material's inputs read the extension's factor, rotation and
// texture (docs/shading.md, "Anisotropy").

#include <algorithm>
#include <cmath>
#include <numbers>

#include <QtTest/QTest>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "TestSupport.h"
#include "core/ibl/EnvironmentSampler.h"
#include "core/image/MapImage.h"
#include "core/mesh/MeshPrimitives.h"
#include "core/shading/Anisotropy.h"
#include "core/shading/DfgTable.h"
#include "core/shading/GroundTruth.h"
#include "core/shading/MaterialBrdf.h"
#include "core/shading/MaterialInputs.h"
#include "core/shading/ReferenceView.h"
#include "core/shading/Sampling.h"

using namespace facet;
using namespace facet::shading;

namespace {

using test::direction;

constexpr double kPiTurn = std::numbers::pi;

// A white metal (F = 1 for every v.h) of `roughness`, anisotropic along `t`.
MaterialInfo brushed(double roughness, double strength, const glm::dvec3& t)
{
    MaterialInfo m = test::whiteMaterial(1.0, roughness);
    m.anisotropy = strength;
    m.anisotropyDirection = t;
    return m;
}

// Turns w about +Z by `angle`.
glm::dvec3 turned(const glm::dvec3& w, double angle)
{
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    return {c * w.x - s * w.y, s * w.x + c * w.y, w.z};
}

// Pairs of (v, l) over the hemisphere of +Z: near normal, off the plane of t, grazing.
struct Pair {
    glm::dvec3 v, l;
};
const Pair kPairs[] = {
    {direction(0.95, 0.3), direction(0.9, 2.9)},
    {direction(0.6, 0.0), direction(0.7, kPiTurn)},
    {direction(0.5, 1.2), direction(0.4, 4.0)},
    {direction(0.2, 0.7), direction(0.8, 3.5)},
    {direction(0.1, 2.0), direction(0.15, 5.5)},
};

const glm::dvec3 kN {0.0, 0.0, 1.0};

} // namespace

class AnisotropicMaterialTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    // A white metal's specular lobe is D V exactly (F = 1, no compensation), D and V the
    // anisotropic pair in the frame of the direction made perpendicular to n.
    void evaluateTakesTheAnisotropicPair_data()
    {
        QTest::addColumn<double>("roughness");
        QTest::addColumn<double>("strength");
        QTest::addColumn<glm::dvec3>("t");
        QTest::newRow("strength 0.5, along x") << 0.4 << 0.5 << glm::dvec3(1.0, 0.0, 0.0);
        QTest::newRow("strength 1, along y") << 0.3 << 1.0 << glm::dvec3(0.0, 1.0, 0.0);
        QTest::newRow("strength 0.8, diagonal") << 0.6 << 0.8 << glm::normalize(glm::dvec3(1.0, 1.0, 0.0));
        QTest::newRow("strength 0.7, off the plane (Gram-Schmidt)") << 0.2 << 0.7 << glm::dvec3(0.6, 0.3, 0.5);
        QTest::newRow("strength 1, roughness 0 (clamped)") << 0.0 << 1.0 << glm::dvec3(1.0, 0.0, 0.0);
        QTest::newRow("strength above 1 clamped") << 0.5 << 4.0 << glm::dvec3(0.0, -1.0, 0.0);
    }
    void evaluateTakesTheAnisotropicPair()
    {
        QFETCH(double, roughness);
        QFETCH(double, strength);
        QFETCH(glm::dvec3, t);
        ShadingModel model;
        model.multiScatter = false;
        const MaterialBrdf brdf(model, m_table);
        const MaterialInfo m = brushed(roughness, strength, t);
        const glm::dvec3 tangent = glm::normalize(t - kN * glm::dot(kN, t));
        const glm::dvec3 bitangent = glm::cross(kN, tangent);
        const auto local = [&](const glm::dvec3& w) {
            return glm::dvec3(glm::dot(w, tangent), glm::dot(w, bitangent), w.z);
        };
        const AnisotropicAlpha alpha = anisotropicAlpha(roughness, strength);
        for (const Pair& pair : kPairs) {
            const glm::dvec3 h = glm::normalize(pair.v + pair.l);
            const double expected = D_GGXAnisotropic(local(h), alpha) * V_GGXAnisotropic(local(pair.v), local(pair.l), alpha);
            const BrdfLobes lobes = brdf.evaluate(m, kN, pair.v, pair.l);
            QVERIFY2(std::abs(lobes.specular.r - expected) <= 1e-9 * expected + 1e-12,
                qPrintable(QStringLiteral("%1 against D V %2").arg(lobes.specular.r).arg(expected)));
            QCOMPARE(lobes.diffuse, glm::dvec3(0.0));
        }
    }

    // No stretch, no direction, or a direction along n: the isotropic BRDF, to the last bit, for
    // a dielectric and a metal, under each visibility.
    void withoutAFrameIsIsotropic_data()
    {
        QTest::addColumn<double>("strength");
        QTest::addColumn<glm::dvec3>("t");
        QTest::addColumn<int>("visibility");
        for (Visibility visibility : {Visibility::SmithGGXCorrelated, Visibility::SchlickGGX}) {
            const char* name = visibility == Visibility::SchlickGGX ? "Schlick-GGX" : "height-correlated";
            QTest::addRow("strength 0, a direction, %s", name) << 0.0 << glm::dvec3(1.0, 0.0, 0.0) << int(visibility);
            QTest::addRow("strength 0.8, no direction, %s", name) << 0.8 << glm::dvec3(0.0) << int(visibility);
            QTest::addRow("strength 0.8, along n, %s", name) << 0.8 << glm::dvec3(0.0, 0.0, 2.0) << int(visibility);
        }
    }
    void withoutAFrameIsIsotropic()
    {
        QFETCH(double, strength);
        QFETCH(glm::dvec3, t);
        QFETCH(int, visibility);
        ShadingModel model;
        model.visibility = Visibility(visibility);
        const MaterialBrdf brdf(model, m_table);
        for (double metallic : {0.0, 1.0}) {
            MaterialInfo isotropic = test::whiteMaterial(metallic, 0.4);
            isotropic.baseColor = glm::dvec3(0.8, 0.4, 0.2);
            MaterialInfo m = isotropic;
            m.anisotropy = strength;
            m.anisotropyDirection = t;
            for (const Pair& pair : kPairs)
                QCOMPARE(brdf.evaluate(m, kN, pair.v, pair.l).total(), brdf.evaluate(isotropic, kN, pair.v, pair.l).total());
        }
    }

    // f(l, v) = f(v, l) for the lobe (compensation off: its factor reads n.v alone); turning v, l
    // and t together about n changes nothing; t and -t are one direction of stretch.
    void lobeIsReciprocalAndTurnsWithItsFrame_data()
    {
        QTest::addColumn<double>("strength");
        QTest::addColumn<double>("roughness");
        QTest::newRow("strength 0.6, roughness 0.3") << 0.6 << 0.3;
        QTest::newRow("strength 1, roughness 0.1") << 1.0 << 0.1;
        QTest::newRow("strength 0.3, roughness 0.8") << 0.3 << 0.8;
    }
    void lobeIsReciprocalAndTurnsWithItsFrame()
    {
        QFETCH(double, strength);
        QFETCH(double, roughness);
        ShadingModel model;
        model.multiScatter = false;
        const MaterialBrdf brdf(model, m_table);
        const glm::dvec3 t = glm::normalize(glm::dvec3(0.8, 0.6, 0.0));
        for (const Pair& pair : kPairs) {
            const double f = brdf.evaluate(brushed(roughness, strength, t), kN, pair.v, pair.l).specular.r;
            const double swapped = brdf.evaluate(brushed(roughness, strength, t), kN, pair.l, pair.v).specular.r;
            QVERIFY2(std::abs(f - swapped) <= 1e-9 * f, qPrintable(QStringLiteral("%1 %2").arg(f).arg(swapped)));
            const double angle = 1.1;
            const double rotated = brdf.evaluate(brushed(roughness, strength, turned(t, angle)), kN,
                                           turned(pair.v, angle), turned(pair.l, angle))
                                       .specular.r;
            QVERIFY2(std::abs(f - rotated) <= 1e-9 * f, qPrintable(QStringLiteral("%1 %2").arg(f).arg(rotated)));
            const double flipped = brdf.evaluate(brushed(roughness, strength, -t), kN, pair.v, pair.l).specular.r;
            QVERIFY2(std::abs(f - flipped) <= 1e-9 * f, qPrintable(QStringLiteral("%1 %2").arg(f).arg(flipped)));
        }
    }

    // Uniform light of radiance 1: what the material reflects towards v. A white metal and a white
    // dielectric, views along t and across it: nothing above 1.005. Without compensation the
    // metal's albedo is the lobe's own (its visible-normal estimate, AnisotropyTest), which holds
    // the integrator's mixture of strategies to the lobe's sampler. Extremes printed.
    void furnaceGainsNothing_data()
    {
        QTest::addColumn<double>("metallic");
        QTest::addColumn<bool>("multiScatter");
        QTest::newRow("white metal, compensated") << 1.0 << true;
        QTest::newRow("white metal, single scattering") << 1.0 << false;
        // fresnel_mix gains at grazing views on any white dielectric (docs/energy.md): the
        // energy-preserving coupling is the one whose furnace means something.
        QTest::newRow("white dielectric, compensated, energy-preserving") << 0.0 << true;
    }
    void furnaceGainsNothing()
    {
        QFETCH(double, metallic);
        QFETCH(bool, multiScatter);
        ShadingModel model;
        model.multiScatter = multiScatter;
        model.coupling = DielectricCoupling::EnergyPreserving;
        const MaterialBrdf brdf(model, m_table);
        double highest = 0.0;
        double lowest = 2.0;
        double worstAgainstLobe = 0.0;
        for (double roughness : {0.1, 0.5, 1.0})
            for (double strength : {0.5, 1.0})
                for (double phi : {0.0, kPiTurn / 2.0, 2.0})
                    for (double NoV : {0.1, 0.5, 1.0}) {
                        MaterialInfo m = test::whiteMaterial(metallic, roughness);
                        m.anisotropy = strength;
                        m.anisotropyDirection = direction(0.0, phi); // the view lies in the xz plane
                        const glm::dvec3 albedo = directionalAlbedo(brdf, m, NoV, 4096);
                        highest = std::max({highest, albedo.r, albedo.g, albedo.b});
                        lowest = std::min({lowest, albedo.r, albedo.g, albedo.b});
                        if (metallic == 1.0 && !multiScatter) {
                            // The view in the frame of t: turned by -phi.
                            const glm::dvec3 v(std::sqrt(1.0 - NoV * NoV), 0.0, NoV);
                            const double lobe = anisotropicDirectionalAlbedo(
                                turned(v, -phi), anisotropicAlpha(roughness, strength), 16384);
                            worstAgainstLobe = std::max(worstAgainstLobe, std::abs(albedo.r - lobe));
                        }
                    }
        qInfo("albedo in [%.4f, %.4f]; largest difference from the lobe's own albedo %.5f", lowest, highest,
            worstAgainstLobe);
        QVERIFY2(highest <= 1.005, qPrintable(QString::number(highest)));
        QVERIFY2(worstAgainstLobe <= 0.003, qPrintable(QString::number(worstAgainstLobe)));
    }

    // The compensation of the stretched lobe (shading::anisotropicCompensation) against the lobe's
    // own single-scattering albedo A (its visible-normal estimate): a white metal's compensated
    // albedo A M(1) over roughness 0.05 to 1, strength 0.1 to 1, nine view azimuths from along t
    // to across it and n.v 0.02 to 1 never exceeds 1.005 (measured 1.0013 at most); the worst
    // point and the darkest front view are printed.
    void compensationNeverGains()
    {
        ShadingModel model;
        const MaterialBrdf brdf(model, m_table);
        double highest = 0.0;
        double darkest = 2.0;
        QString at;
        for (int r = 1; r <= 20; ++r)
            for (int s = 1; s <= 10; ++s)
                for (int azimuth = 0; azimuth <= 8; ++azimuth)
                    for (double NoV : {0.02, 0.05, 0.1, 0.15, 0.2, 0.3, 0.5, 0.7, 0.9, 1.0}) {
                        const double roughness = 0.05 * r;
                        const double strength = 0.1 * s;
                        const double phi = kPiTurn / 16.0 * azimuth;
                        const glm::dvec3 v = direction(NoV, phi);
                        const double lobe
                            = anisotropicDirectionalAlbedo(v, anisotropicAlpha(roughness, strength), 2048);
                        const AnisotropicCompensation c = anisotropicCompensation(v, roughness, strength);
                        const double albedo
                            = lobe * brdf.multiScatterFactor(glm::dvec3(1.0), NoV, c.perceptualRoughness, c.weight).x;
                        if (albedo > highest) {
                            highest = albedo;
                            at = QStringLiteral("roughness %1, strength %2, azimuth %3, n.v %4")
                                     .arg(roughness)
                                     .arg(strength)
                                     .arg(phi)
                                     .arg(NoV);
                        }
                        if (NoV == 1.0)
                            darkest = std::min(darkest, albedo);
                    }
        qInfo("compensated albedo at most %.4f (%s); the darkest front view %.4f", highest, qPrintable(at), darkest);
        QVERIFY2(highest <= 1.005, qPrintable(QString::number(highest)));
    }

    // The ground truth's estimate at one point of the reference sphere under a uniform light of
    // radiance 1 (the BRDF strategy draws the stretched lobe in its frame, the environment
    // strategy the sphere of directions, weighted by the power heuristic) against a plain
    // cosine-weighted integral of the same BRDF over 2^18 Hammersley points: the integrator's
    // densities are the samplers'. A material without a direction of its own takes the sphere's
    // tangent frame (sphereTangent) and the rotation of its tangent-plane direction.
    void groundTruthIntegratesTheLobe_data()
    {
        QTest::addColumn<double>("metallic");
        QTest::addColumn<double>("roughness");
        QTest::addColumn<double>("strength");
        QTest::addColumn<double>("rotation");
        QTest::newRow("metal 0.3, strength 0.8") << 1.0 << 0.3 << 0.8 << 0.0;
        QTest::newRow("metal 0.5, strength 1, turned 60 degrees") << 1.0 << 0.5 << 1.0 << 60.0;
        QTest::newRow("dielectric 0.2, strength 0.6, turned -30 degrees") << 0.0 << 0.2 << 0.6 << -30.0;
    }
    void groundTruthIntegratesTheLobe()
    {
        QFETCH(double, metallic);
        QFETCH(double, roughness);
        QFETCH(double, strength);
        QFETCH(double, rotation);
        GroundTruthScene scene;
        scene.environment = Environment::uniform(glm::dvec3(1.0));
        scene.material = test::whiteMaterial(metallic, roughness);
        scene.material.baseColor = glm::dvec3(0.9, 0.6, 0.3);
        scene.material.anisotropy = strength;
        scene.material.anisotropyTangentDirection = anisotropyDirection(glm::dvec2(1.0, 0.0), glm::radians(rotation));
        const std::shared_ptr<const DfgTable> table = albedoTable(32, 512, scene.model.visibility);
        const MaterialBrdf brdf(scene.model, *table);
        const EnvironmentSampler sampler(scene.environment);
        const glm::dvec3 p = glm::normalize(glm::dvec3(0.3, 0.25, 0.9));
        const glm::dvec3 v = glm::normalize(referenceview::kEye - p);
        const glm::dvec3 estimate = integrateOutgoingRadiance(scene, brdf, sampler, p, v, 8192, 7, 0);

        MaterialInfo explicitFrame = scene.material;
        explicitFrame.anisotropyDirection = surfaceAnisotropyDirection(
            p, referenceview::sphereTangent(p), explicitFrame.anisotropyTangentDirection);
        QVERIFY(explicitFrame.hasAnisotropy());
        glm::dvec3 t;
        glm::dvec3 b;
        sampling::buildOrthonormalBasis(p, t, b);
        const auto count = std::uint32_t(1) << 18;
        glm::dvec3 cosine(0.0);
        for (std::uint32_t i = 0; i < count; ++i) {
            const glm::dvec3 l
                = sampling::tangentToWorld(sampling::sampleCosineHemisphere(sampling::hammersley(i, count)), t, b, p);
            cosine += brdf.evaluate(explicitFrame, p, v, l).total() * kPiTurn; // f (n.l) / (n.l / pi)
        }
        cosine /= double(count);
        const double error = glm::length(estimate - cosine) / glm::length(cosine);
        qInfo("ground truth (%.4f, %.4f, %.4f), cosine integral (%.4f, %.4f, %.4f): %.3f%% apart", estimate.r,
            estimate.g, estimate.b, cosine.r, cosine.g, cosine.b, 100.0 * error);
        QVERIFY2(error < 0.01, qPrintable(QString::number(error)));
        // The same point with the frame given: the same estimate (the default frame is that one).
        GroundTruthScene given = scene;
        given.material = explicitFrame;
        const glm::dvec3 again = integrateOutgoingRadiance(given, brdf, sampler, p, v, 8192, 7, 0);
        QVERIFY2(glm::length(again - estimate) <= 1e-9 * glm::length(estimate),
            qPrintable(QStringLiteral("%1 against %2").arg(again.r).arg(estimate.r)));
    }

    // The reference sphere's tangent is the sphere mesh's dP/du (what the GPU interpolates), unit,
    // perpendicular to the point, +X at the front, handedness +1.
    void sphereTangentIsTheMeshs()
    {
        const Mesh sphere = makeSphere();
        double worst = 0.0;
        for (const Vertex& vertex : sphere.vertices) {
            const glm::dvec3 p = glm::normalize(glm::dvec3(vertex.position));
            if (std::abs(p.y) > 0.99)
                continue; // the pole rows: no dP/du to agree on
            const glm::dvec4 t = referenceview::sphereTangent(p);
            QCOMPARE(t.w, 1.0);
            QVERIFY(std::abs(glm::dot(glm::dvec3(t), p)) < 1e-12);
            worst = std::max(worst, glm::length(glm::dvec3(t) - glm::dvec3(vertex.tangent)));
        }
        qInfo("largest difference from the mesh's tangents %.2e", worst);
        QVERIFY2(worst < 1e-5, qPrintable(QString::number(worst)));
        QCOMPARE(referenceview::sphereTangent(glm::dvec3(0.0, 0.0, 1.0)), glm::dvec4(1.0, 0.0, 0.0, 1.0));
    }

    // The tangent-plane direction through the surface's frame: x along the tangent, y along
    // cross(n, t) times the handedness; nothing where the tangent lies along the normal.
    void surfaceDirectionMapsThroughTheFrame_data()
    {
        QTest::addColumn<glm::dvec4>("tangent");
        QTest::addColumn<glm::dvec2>("planar");
        QTest::addColumn<glm::dvec3>("expected");
        QTest::newRow("along the tangent") << glm::dvec4(1, 0, 0, 1) << glm::dvec2(1, 0) << glm::dvec3(1, 0, 0);
        QTest::newRow("along the bitangent") << glm::dvec4(1, 0, 0, 1) << glm::dvec2(0, 1) << glm::dvec3(0, 1, 0);
        QTest::newRow("mirrored frame (w -1)") << glm::dvec4(1, 0, 0, -1) << glm::dvec2(0, 1) << glm::dvec3(0, -1, 0);
        QTest::newRow("tangent off the plane, long")
            << glm::dvec4(3, 0, 3, 1) << glm::dvec2(std::sqrt(0.5), std::sqrt(0.5))
            << glm::normalize(glm::dvec3(1, 1, 0));
        QTest::newRow("tangent along n: none") << glm::dvec4(0, 0, 1, 1) << glm::dvec2(1, 0) << glm::dvec3(0.0);
    }
    void surfaceDirectionMapsThroughTheFrame()
    {
        QFETCH(glm::dvec4, tangent);
        QFETCH(glm::dvec2, planar);
        QFETCH(glm::dvec3, expected);
        const glm::dvec3 d = surfaceAnisotropyDirection(kN, tangent, planar);
        QVERIFY2(glm::length(d - expected) < 1e-12,
            qPrintable(QStringLiteral("(%1, %2, %3)").arg(d.x).arg(d.y).arg(d.z)));
    }

    // The extension's inputs: strength = factor x texture B, direction = the texture's RG x 2 - 1
    // ((1, 0) without one) turned counter-clockwise by the rotation; nothing read at strength 0.
    void inputsReadTheExtension_data()
    {
        QTest::addColumn<double>("factor");
        QTest::addColumn<double>("rotation");
        QTest::addColumn<bool>("texture");
        QTest::addColumn<glm::dvec3>("texel"); // RGB of the one-texel map
        QTest::addColumn<double>("strength");
        QTest::addColumn<glm::dvec2>("planar");
        const glm::dvec3 none(0.0);
        QTest::newRow("factor alone") << 0.7 << 0.0 << false << none << 0.7 << glm::dvec2(1, 0);
        QTest::newRow("factor, turned 90 degrees") << 1.0 << 90.0 << false << none << 1.0 << glm::dvec2(0, 1);
        QTest::newRow("texture along the bitangent, B 0.5")
            << 0.8 << 0.0 << true << glm::dvec3(0.5, 1.0, 0.5) << 0.4 << glm::dvec2(0, 1);
        QTest::newRow("texture diagonal, turned -45 degrees")
            << 1.0 << -45.0 << true << glm::dvec3(1.0, 1.0, 1.0) << 1.0 << glm::dvec2(1, 0);
        QTest::newRow("texture of no direction (0.5, 0.5): the tangent")
            << 1.0 << 0.0 << true << glm::dvec3(0.5, 0.5, 1.0) << 1.0 << glm::dvec2(1, 0);
        QTest::newRow("strength 0: nothing read") << 0.0 << 30.0 << true << glm::dvec3(0.0, 1.0, 1.0) << 0.0
                                                  << glm::dvec2(1, 0);
    }
    void inputsReadTheExtension()
    {
        QFETCH(double, factor);
        QFETCH(double, rotation);
        QFETCH(bool, texture);
        QFETCH(glm::dvec3, texel);
        QFETCH(double, strength);
        QFETCH(glm::dvec2, planar);
        Material material;
        material.setAnisotropy(factor, rotation);
        MaterialMapImages images {};
        // A half-float texel holds 0.5 exactly (an 8-bit one rounds it to 128/255).
        const MapImage map = MapImage::fromImage(Image(1, 1, glm::vec4(glm::vec3(texel), 1.0f)), MapLayout::Rgb,
            MapSampleType::Half);
        if (texture) {
            material.map(MapSlot::Anisotropy).path = "/brushed.exr";
            images[std::size_t(MapSlot::Anisotropy)] = &map;
        }
        const MaterialInfo m = materialInputs(material, images, glm::dvec2(0.5));
        QVERIFY2(std::abs(m.anisotropy - strength) < 1e-6, qPrintable(QString::number(m.anisotropy)));
        QVERIFY2(glm::length(m.anisotropyTangentDirection - planar) < 1e-6,
            qPrintable(QStringLiteral("(%1, %2)").arg(m.anisotropyTangentDirection.x).arg(m.anisotropyTangentDirection.y)));
        QCOMPARE(m.anisotropyDirection, glm::dvec3(0.0)); // the caller's frame maps it
    }

private:
    DfgTable m_table = DfgTable::compute(64, 1024);
};

QTEST_APPLESS_MAIN(AnisotropicMaterialTest)
#include "AnisotropicMaterialTest.moc"
