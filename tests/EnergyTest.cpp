// Energy: white-furnace responses of the material BRDF (core/shading/MaterialBrdf.h). A white metal
// reflects at most what it receives, and all of it with multiple-scattering compensation; the
// glTF fresnel_mix gains energy at grazing angles for a white dielectric (measured here and in
// docs/energy.md), and the energy-preserving coupling does not.

#include <cmath>

#include <QtTest/QTest>

#include "TestSupport.h"
#include "core/material/Material.h"
#include "core/shading/Brdf.h"
#include "core/shading/DfgTable.h"
#include "core/shading/MaterialBrdf.h"

using namespace facet;

namespace {

const double kNoV[] = {1e-3, 0.01, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9, 1.0};
// Where compensation can be exact: from the table's second n.v texel (1/63) up. Below it, for the
// smoothest lobes the albedo changes within a span of n.v ~ alpha (0.002) that no table of this
// size resolves; the error there is measured and reported instead (docs/energy.md).
const double kNoVResolved[] = {0.02, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9, 1.0};
const double kRoughness[] = {0.0, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
// Samples per albedo estimate (each from two strategies): deterministic Hammersley points; the
// estimates converge to ~1e-4 here, far below the bounds checked.
constexpr int kSamples = 4096;

using test::whiteMaterial;

} // namespace

class EnergyTest : public QObject {
    Q_OBJECT

    DfgTable m_table = DfgTable::compute(64, 1024);

private Q_SLOTS:
    void whiteMetalNeverGainsEnergy()
    {
        ShadingModel model;
        model.multiScatter = false;
        const MaterialBrdf brdf(model, m_table);
        double lowest = 1.0;
        for (double r : kRoughness)
            for (double NoV : kNoV) {
                const double albedo = directionalAlbedo(brdf, whiteMaterial(1.0, r), NoV, kSamples).x;
                QVERIFY2(albedo <= 1.0 + 1e-3, qPrintable(QStringLiteral("r %1 n.v %2: %3").arg(r).arg(NoV).arg(albedo)));
                lowest = std::min(lowest, albedo);
            }
        // ... and single scattering does lose energy: the reason compensation exists.
        qInfo("white metal, single scattering: lowest albedo %.4f", lowest);
        QVERIFY(lowest < 0.7);
    }

    void multiScatterCompensationRestoresEnergy()
    {
        ShadingModel model; // multiScatter on by default
        const MaterialBrdf brdf(model, m_table);
        double worst = 0.0;
        for (double r : kRoughness)
            for (double NoV : kNoVResolved) {
                const double albedo = directionalAlbedo(brdf, whiteMaterial(1.0, r), NoV, kSamples).x;
                worst = std::max(worst, std::abs(albedo - 1.0));
                QVERIFY2(std::abs(albedo - 1.0) < 0.01, qPrintable(QStringLiteral("r %1 n.v %2: %3").arg(r).arg(NoV).arg(albedo)));
            }
        double grazing = 0.0;
        for (double r : kRoughness)
            for (double NoV : {1e-3, 0.01})
                grazing = std::max(
                    grazing, std::abs(directionalAlbedo(brdf, whiteMaterial(1.0, r), NoV, kSamples).x - 1.0));
        qInfo("white metal with compensation: max |albedo - 1| = %.2e for n.v >= 0.02, %.2e below", worst, grazing);
        // Below the table's resolution it must still not gain energy.
        for (double r : kRoughness)
            QVERIFY(directionalAlbedo(brdf, whiteMaterial(1.0, r), 1e-3, kSamples).x <= 1.0 + 1e-3);
    }

    // The glTF 2.0 fresnel_mix of a white dielectric: diffuse (1 - F(v.h)) + specular F(v.h).
    // At grazing view F(v.h) is large for the specular lobe's main directions but the diffuse
    // lobe is weighted by (1 - F(v.h)) over all directions, so the sum exceeds 1.
    void gltfFresnelMixGainsEnergyAtGrazingAngles()
    {
        for (bool multiScatter : {false, true}) {
            ShadingModel model;
            model.multiScatter = multiScatter;
            const MaterialBrdf brdf(model, m_table);
            double highest = 0.0;
            double highestNoV = 0.0;
            double highestRoughness = 0.0;
            for (double r : kRoughness)
                for (double NoV : kNoV) {
                    const double albedo = directionalAlbedo(brdf, whiteMaterial(0.0, r), NoV, kSamples).x;
                    if (albedo > highest) {
                        highest = albedo;
                        highestNoV = NoV;
                        highestRoughness = r;
                    }
                }
            qInfo("glTF fresnel_mix, white dielectric, multi-scatter %s: max albedo %.3f at n.v %.3f, roughness %.2f",
                  multiScatter ? "on" : "off", highest, highestNoV, highestRoughness);
            QVERIFY(highest > 1.3);
            // Head-on it is close to 1 (1 - F0 + F0).
            const double headOn = directionalAlbedo(brdf, whiteMaterial(0.0, 0.5), 1.0, kSamples).x;
            QVERIFY(std::abs(headOn - 1.0) < 0.05);
        }
    }

    void energyPreservingCouplingStaysAtOrBelowOne()
    {
        for (auto composition : {BrdfComposition::Gltf, BrdfComposition::LearnOpenGL}) {
            for (bool multiScatter : {false, true}) {
                ShadingModel model = composition == BrdfComposition::Gltf ? ShadingModel{} : ShadingModel::learnOpenGL();
                model.coupling = DielectricCoupling::EnergyPreserving;
                model.multiScatter = multiScatter;
                const DfgTable table = DfgTable::compute(64, 1024, model.visibility);
                const MaterialBrdf brdf(model, table);
                double highest = 0.0;
                double lowest = 2.0;
                for (double r : kRoughness)
                    for (double NoV : kNoV) {
                        const double albedo = directionalAlbedo(brdf, whiteMaterial(0.0, r), NoV, kSamples).x;
                        highest = std::max(highest, albedo);
                        if (NoV >= 0.02)
                            lowest = std::min(lowest, albedo);
                    }
                qInfo("energy-preserving %s, multi-scatter %s: white dielectric albedo max %.4f, min %.4f for n.v >= 0.02",
                      toString(composition), multiScatter ? "on" : "off", highest, lowest);
                // Bound: 1 plus the table's interpolation error (the coupling is exact for the table).
                QVERIFY2(highest <= 1.005, qPrintable(QString::number(highest)));
                if (composition == BrdfComposition::Gltf && multiScatter) {
                    // With compensation the white furnace is white: nothing lost, nothing gained.
                    QVERIFY2(lowest > 0.99, qPrintable(QString::number(lowest)));
                }
            }
        }
    }

    // The LearnOpenGL composition, kS = F(v.h), kD = 1 - F: measured (it gains energy too).
    void learnOpenGLCompositionIsMeasured()
    {
        ShadingModel model = ShadingModel::learnOpenGL();
        model.multiScatter = false;
        const DfgTable table = DfgTable::compute(64, 1024, model.visibility);
        const MaterialBrdf brdf(model, table);
        double highest = 0.0;
        for (double r : kRoughness)
            for (double NoV : kNoV)
                highest = std::max(highest, directionalAlbedo(brdf, whiteMaterial(0.0, r), NoV, kSamples).x);
        qInfo("LearnOpenGL composition, white dielectric: max albedo %.3f", highest);
        QVERIFY(highest > 1.0);
        // Its metal, with the IBL remapping, still loses energy without compensation.
        QVERIFY(directionalAlbedo(brdf, whiteMaterial(1.0, 1.0), 0.5, kSamples).x < 0.95);
    }

    // KHR_materials_clearcoat: f = (1 - w) f_base + w D V with w = clearcoat F(n.v), so the coated
    // albedo is (1 - w) E_base + w E_coat, E_coat the coat lobe's albedo with F = 1 (the table's
    // scale + bias). A row per base, coat strength and coat roughness; each n.v checks that
    // identity (the coat's weight, normalisation and the base's 1 - w) and that nothing is
    // gained. The loss is the coat's own single scattering, w (1 - E_coat): measured and printed
    // (docs/shading.md, "Clearcoat").
    void clearcoatNeverGainsEnergy_data()
    {
        QTest::addColumn<double>("metallic");
        QTest::addColumn<int>("coupling");
        QTest::addColumn<double>("clearcoat");
        QTest::addColumn<double>("coatRoughness");
        for (double coatRoughness : {0.0, 0.05, 0.3, 0.6, 1.0})
            for (double clearcoat : {0.25, 1.0}) {
                QTest::addRow("white metal, coat %g, coat roughness %g", clearcoat, coatRoughness)
                    << 1.0 << int(DielectricCoupling::FresnelMix) << clearcoat << coatRoughness;
                QTest::addRow("white energy-preserving dielectric, coat %g, coat roughness %g", clearcoat,
                    coatRoughness)
                    << 0.0 << int(DielectricCoupling::EnergyPreserving) << clearcoat << coatRoughness;
            }
    }
    void clearcoatNeverGainsEnergy()
    {
        QFETCH(double, metallic);
        QFETCH(int, coupling);
        QFETCH(double, clearcoat);
        QFETCH(double, coatRoughness);
        ShadingModel model;
        model.coupling = DielectricCoupling(coupling);
        const MaterialBrdf brdf(model, m_table);
        double highest = 0.0;
        double largestLoss = 0.0;
        for (double r : {0.1, 0.5, 1.0})
            for (double NoV : kNoVResolved) {
                MaterialInfo base = whiteMaterial(metallic, r);
                MaterialInfo coated = base;
                coated.clearcoat = clearcoat;
                coated.clearcoatRoughness = coatRoughness;
                const double baseAlbedo = directionalAlbedo(brdf, base, NoV, kSamples).x;
                const double albedo = directionalAlbedo(brdf, coated, NoV, kSamples).x;
                const double w = clearcoatWeight(coated, NoV);
                const double coatAlbedo
                    = m_table.sample(NoV, std::max(coatRoughness, Material::kMinPerceptualRoughness))
                          .albedo();
                const double expected = (1.0 - w) * baseAlbedo + w * coatAlbedo;
                // Below n.v 0.05 a near-mirror coat's albedo changes faster than the table's
                // texels follow (the expected value's error, not the BRDF's: 3e-3 at 0.02).
                QVERIFY2(NoV < 0.05 || std::abs(albedo - expected) < 3e-3,
                    qPrintable(QStringLiteral("r %1 n.v %2: %3, expected (1 - w) E_base + w E_coat = %4")
                                   .arg(r)
                                   .arg(NoV)
                                   .arg(albedo)
                                   .arg(expected)));
                highest = std::max(highest, albedo);
                largestLoss = std::max(largestLoss, baseAlbedo - albedo);
            }
        qInfo("albedo at most %.4f; the coat loses at most %.4f of the base's", highest, largestLoss);
        QVERIFY2(highest <= 1.005, qPrintable(QString::number(highest)));
    }

    // A black dielectric reflects only its specular layer: F0 at normal incidence for a mirror.
    void blackDielectricReflectsF0HeadOn()
    {
        ShadingModel model;
        model.multiScatter = false;
        const MaterialBrdf brdf(model, m_table);
        MaterialInfo black = whiteMaterial(0.0, 0.0);
        black.baseColor = glm::dvec3(0.0);
        const double albedo = directionalAlbedo(brdf, black, 1.0, kSamples).x;
        QVERIFY2(std::abs(albedo - 0.04) < 2e-3, qPrintable(QString::number(albedo)));
    }
};

QTEST_APPLESS_MAIN(EnergyTest)
#include "EnergyTest.moc"
