// KHR_materials_specular in the CPU material BRDF (core/shading/MaterialBrdf, the ground truth's
// integrand): the dielectric layer's F0 and F90 as the extension defines them (a row per IOR,
// strength and tint, the clamps included); its Fresnel at normal and grazing incidence, Schlick's
// and the exact dielectric's; the base's share 1 - max_value(F) of the glTF fresnel_mix; strength
// 0 leaves Lambert alone; metals ignore the layer; and a white furnace per layer and coupling that
// gains nothing (docs/shading.md, "Specular"). The split sum's twin of the layer is held to the
// same integrals by SplitSumTest.

#include <algorithm>
#include <cmath>

#include <QtTest/QTest>

#include <glm/geometric.hpp>

#include "TestSupport.h"
#include "core/shading/Brdf.h"
#include "core/shading/DfgTable.h"
#include "core/shading/MaterialBrdf.h"

using namespace facet;
using namespace facet::shading;

namespace {

using test::direction;

MaterialInfo layered(double specular, const glm::dvec3& specularColor, double metallic = 0.0)
{
    MaterialInfo m = test::whiteMaterial(metallic, 0.5);
    m.baseColor = glm::dvec3(0.8, 0.3, 0.1);
    m.specular = specular;
    m.specularColor = specularColor;
    return m;
}

// Pairs of (n.v, n.l, azimuth of l) that cover normal incidence, a mirror pair and grazing views.
struct Geometry {
    double NoV, NoL, phi;
};
const Geometry kGeometry[] = {{1.0, 1.0, 0.0}, {0.7, 0.7, 3.14159}, {0.9, 0.3, 1.0}, {0.1, 0.8, 2.5},
    {0.05, 0.05, 3.1}, {0.5, 0.95, 0.4}};

} // namespace

class SpecularLayerTest : public QObject {
    Q_OBJECT

    DfgTable m_table = DfgTable::compute(64, 1024);

private Q_SLOTS:
    // f0 = min(F0(n) specularColor, 1) specular, f90 = specular ("Implementation"; the clamp comes
    // before the strength), out-of-range inputs clamped as the shader clamps them.
    void reflectanceFollowsTheExtension_data()
    {
        QTest::addColumn<double>("ior");
        QTest::addColumn<double>("specular");
        QTest::addColumn<glm::dvec3>("specularColor");
        QTest::addColumn<glm::dvec3>("f0");
        QTest::addColumn<double>("f90");
        const glm::dvec3 white(1.0);
        QTest::newRow("default: F0(1.5), F90 1") << 1.5 << 1.0 << white << glm::dvec3(0.04) << 1.0;
        QTest::newRow("IOR 2: F0 1/9") << 2.0 << 1.0 << white << glm::dvec3(1.0 / 9.0) << 1.0;
        QTest::newRow("strength 0.5 scales both") << 1.5 << 0.5 << white << glm::dvec3(0.02) << 0.5;
        QTest::newRow("strength 0: no reflection") << 1.5 << 0.0 << white << glm::dvec3(0.0) << 0.0;
        QTest::newRow("tint per channel")
            << 1.5 << 1.0 << glm::dvec3(2.0, 1.0, 0.5) << glm::dvec3(0.08, 0.04, 0.02) << 1.0;
        QTest::newRow("tint 25: F0 clamped to 1") << 1.5 << 1.0 << glm::dvec3(25.0) << glm::dvec3(1.0) << 1.0;
        QTest::newRow("tint 100 clamped, then strength 0.3")
            << 1.5 << 0.3 << glm::dvec3(100.0, 10.0, 0.0) << glm::dvec3(0.3, 0.12, 0.0) << 0.3;
        QTest::newRow("IOR 1: nothing to tint") << 1.0 << 1.0 << glm::dvec3(50.0) << glm::dvec3(0.0) << 1.0;
        QTest::newRow("strength above 1 clamped") << 1.5 << 1.5 << white << glm::dvec3(0.04) << 1.0;
        QTest::newRow("negative tint clamped to 0")
            << 1.5 << 1.0 << glm::dvec3(-1.0, 1.0, 1.0) << glm::dvec3(0.0, 0.04, 0.04) << 1.0;
    }
    void reflectanceFollowsTheExtension()
    {
        QFETCH(double, ior);
        QFETCH(double, specular);
        QFETCH(glm::dvec3, specularColor);
        QFETCH(glm::dvec3, f0);
        QFETCH(double, f90);
        MaterialInfo m;
        m.ior = ior;
        m.specular = specular;
        m.specularColor = specularColor;
        const DielectricReflectance layer = dielectricReflectance(m);
        for (int c = 0; c < 3; ++c)
            QVERIFY2(std::abs(layer.f0[c] - f0[c]) < 1e-12, qPrintable(QString::number(layer.f0[c])));
        QCOMPARE(layer.f90, f90);
        QCOMPARE(layer.maxF0(), std::max({f0.r, f0.g, f0.b}));
    }

    // The layer's Fresnel: Schlick from f0 at normal incidence to f90 at grazing; the exact
    // dielectric curve unchanged by the default layer, scaled by the strength, shifted by a tint.
    void fresnelEndsAtF0AndF90_data()
    {
        QTest::addColumn<int>("fresnel");
        QTest::addColumn<double>("specular");
        QTest::addColumn<glm::dvec3>("specularColor");
        for (Fresnel fresnel : {Fresnel::Schlick, Fresnel::Dielectric})
            for (const auto& [specular, color] : {std::pair {1.0, glm::dvec3(1.0)}, {0.5, glm::dvec3(1.0)},
                     {1.0, glm::dvec3(3.0, 1.0, 0.25)}, {0.25, glm::dvec3(25.0)}, {0.0, glm::dvec3(1.0)}})
                QTest::addRow("%s, specular %g, tint (%g, %g, %g)",
                    fresnel == Fresnel::Schlick ? "Schlick" : "exact dielectric", specular, color.r, color.g,
                    color.b)
                    << int(fresnel) << specular << color;
    }
    void fresnelEndsAtF0AndF90()
    {
        QFETCH(int, fresnel);
        QFETCH(double, specular);
        QFETCH(glm::dvec3, specularColor);
        ShadingModel model;
        model.fresnel = Fresnel(fresnel);
        const MaterialBrdf brdf(model, m_table);
        const MaterialInfo m = layered(specular, specularColor);
        const DielectricReflectance layer = dielectricReflectance(m);
        const glm::dvec3 normal = brdf.dielectricFresnel(m, layer, 1.0);
        const glm::dvec3 grazing = brdf.dielectricFresnel(m, layer, 0.0);
        for (int c = 0; c < 3; ++c) {
            // The exact curve's normal incidence is F0(n) itself, so both models start at f0.
            QVERIFY2(std::abs(normal[c] - layer.f0[c]) < 1e-12, qPrintable(QString::number(normal[c])));
            QVERIFY2(std::abs(grazing[c] - layer.f90) < 1e-12, qPrintable(QString::number(grazing[c])));
        }
        if (Fresnel(fresnel) == Fresnel::Dielectric && specularColor == glm::dvec3(1.0))
            for (double VoH : {0.05, 0.3, 0.6, 0.9})
                QVERIFY(
                    std::abs(brdf.dielectricFresnel(m, layer, VoH).g - specular * F_Dielectric(VoH, m.ior))
                    < 1e-12);
        for (double VoH : {0.0, 0.2, 0.5, 0.8, 1.0}) {
            const glm::dvec3 F = brdf.dielectricFresnel(m, layer, VoH);
            QVERIFY(F.r >= 0.0 && F.g >= 0.0 && F.b >= 0.0 && F.r <= 1.0 && F.g <= 1.0 && F.b <= 1.0);
        }
    }

    // glTF's fresnel_mix with the extension: the specular lobe D V F M(f0) per channel, the
    // base c / pi (1 - max_value(F(v.h))) (one number for every channel), each times 1 - m.
    void fresnelMixKeepsOneMinusMaxF_data()
    {
        QTest::addColumn<double>("specular");
        QTest::addColumn<glm::dvec3>("specularColor");
        QTest::addColumn<double>("metallic");
        QTest::newRow("tint (4, 2, 0.8)") << 1.0 << glm::dvec3(4.0, 2.0, 0.8) << 0.0;
        QTest::newRow("strength 0.4, tint (0.2, 1, 3)") << 0.4 << glm::dvec3(0.2, 1.0, 3.0) << 0.0;
        QTest::newRow("tint 25 (F0 1)") << 1.0 << glm::dvec3(25.0) << 0.0;
        QTest::newRow("half metal, tint (2, 1, 1)") << 1.0 << glm::dvec3(2.0, 1.0, 1.0) << 0.5;
    }
    void fresnelMixKeepsOneMinusMaxF()
    {
        QFETCH(double, specular);
        QFETCH(glm::dvec3, specularColor);
        QFETCH(double, metallic);
        ShadingModel model;
        model.multiScatter = false; // so the specular lobe is D V F alone
        const MaterialBrdf brdf(model, m_table);
        const MaterialInfo m = layered(specular, specularColor, metallic);
        const DielectricReflectance layer = dielectricReflectance(m);
        const glm::dvec3 n(0.0, 0.0, 1.0);
        for (const Geometry& g : kGeometry) {
            const glm::dvec3 v = direction(g.NoV, 0.0);
            const glm::dvec3 l = direction(g.NoL, g.phi);
            const glm::dvec3 h = glm::normalize(v + l);
            const double VoH = std::clamp(glm::dot(v, h), 0.0, 1.0);
            const double alpha = 0.25;
            const double microfacet = D_GGX(h.z, alpha) * V_SmithGGXCorrelated(g.NoV, g.NoL, alpha);
            const glm::dvec3 F = F_Schlick(layer.f0, layer.f90, VoH);
            const glm::dvec3 metal = F_Schlick(m.baseColor, 1.0, VoH);
            const glm::dvec3 diffuse
                = m.baseColor / kPi * (1.0 - std::max({F.r, F.g, F.b})) * (1.0 - metallic);
            const glm::dvec3 spec = microfacet * ((1.0 - metallic) * F + metallic * metal);
            const BrdfLobes lobes = brdf.evaluate(m, n, v, l);
            for (int c = 0; c < 3; ++c) {
                QVERIFY2(std::abs(lobes.diffuse[c] - diffuse[c]) <= 1e-12 * std::max(1.0, diffuse[c]),
                    qPrintable(QStringLiteral("diffuse %1 != %2").arg(lobes.diffuse[c]).arg(diffuse[c])));
                QVERIFY2(std::abs(lobes.specular[c] - spec[c]) <= 1e-9 * std::max(1.0, spec[c]),
                    qPrintable(QStringLiteral("specular %1 != %2").arg(lobes.specular[c]).arg(spec[c])));
            }
        }
    }

    // Strength 0: a purely diffuse dielectric, Lambert's c / pi in every composition and coupling
    // (no Fresnel takes anything from the base: F = 0 everywhere).
    void strengthZeroIsLambert_data()
    {
        QTest::addColumn<int>("composition");
        QTest::addColumn<int>("coupling");
        for (BrdfComposition composition : {BrdfComposition::Gltf, BrdfComposition::LearnOpenGL})
            for (DielectricCoupling coupling :
                {DielectricCoupling::FresnelMix, DielectricCoupling::EnergyPreserving})
                QTest::addRow("%s, %s", composition == BrdfComposition::Gltf ? "glTF" : "LearnOpenGL",
                    coupling == DielectricCoupling::FresnelMix ? "fresnel_mix" : "energy-preserving")
                    << int(composition) << int(coupling);
    }
    void strengthZeroIsLambert()
    {
        QFETCH(int, composition);
        QFETCH(int, coupling);
        ShadingModel model;
        model.composition = BrdfComposition(composition);
        model.coupling = DielectricCoupling(coupling);
        const MaterialBrdf brdf(model, m_table);
        const MaterialInfo m = layered(0.0, glm::dvec3(3.0, 1.0, 0.5));
        const glm::dvec3 n(0.0, 0.0, 1.0);
        for (const Geometry& g : kGeometry) {
            const BrdfLobes lobes = brdf.evaluate(m, n, direction(g.NoV, 0.0), direction(g.NoL, g.phi));
            QCOMPARE(lobes.specular, glm::dvec3(0.0));
            for (int c = 0; c < 3; ++c)
                QVERIFY2(std::abs(lobes.diffuse[c] - m.baseColor[c] / kPi) < 1e-12,
                    qPrintable(QString::number(lobes.diffuse[c] * kPi)));
        }
    }

    // A metal's F0 is its base colour: the layer changes nothing of a metallic-1 material.
    void metalsIgnoreTheLayer_data()
    {
        QTest::addColumn<int>("composition");
        QTest::newRow("glTF") << int(BrdfComposition::Gltf);
        QTest::newRow("LearnOpenGL") << int(BrdfComposition::LearnOpenGL);
    }
    void metalsIgnoreTheLayer()
    {
        QFETCH(int, composition);
        ShadingModel model;
        model.composition = BrdfComposition(composition);
        const MaterialBrdf brdf(model, m_table);
        const MaterialInfo plain = layered(1.0, glm::dvec3(1.0), 1.0);
        const glm::dvec3 n(0.0, 0.0, 1.0);
        for (const auto& [specular, color] :
            {std::pair {0.0, glm::dvec3(1.0)}, {0.5, glm::dvec3(3.0, 0.1, 1.0)}})
            for (const Geometry& g : kGeometry) {
                const glm::dvec3 v = direction(g.NoV, 0.0);
                const glm::dvec3 l = direction(g.NoL, g.phi);
                const BrdfLobes expected = brdf.evaluate(plain, n, v, l);
                const BrdfLobes actual = brdf.evaluate(layered(specular, color, 1.0), n, v, l);
                QCOMPARE(actual.total(), expected.total());
            }
    }

    // A white dielectric under uniform light of radiance 1, over n.v: strength 0 reflects
    // exactly Lambert's 1; the energy-preserving coupling gives every grey layer an albedo of 1
    // and a tinted one at most 1 per channel (its base sees the largest channel); F0 = 1 is a
    // white mirror whose compensated lobe reflects 1. Nothing above 1.005 anywhere; the extremes
    // are printed.
    void furnaceGainsNothing_data()
    {
        QTest::addColumn<int>("coupling");
        QTest::addColumn<double>("specular");
        QTest::addColumn<glm::dvec3>("specularColor");
        QTest::addColumn<bool>("unity"); // the albedo is 1, not only at most 1
        const auto add = [](DielectricCoupling coupling, double specular, glm::dvec3 color, bool unity) {
            QTest::addRow("%s, specular %g, tint (%g, %g, %g)",
                coupling == DielectricCoupling::FresnelMix ? "fresnel_mix" : "energy-preserving", specular,
                color.r, color.g, color.b)
                << int(coupling) << specular << color << unity;
        };
        add(DielectricCoupling::FresnelMix, 0.0, glm::dvec3(1.0), true);
        add(DielectricCoupling::FresnelMix, 1.0, glm::dvec3(25.0), true);
        add(DielectricCoupling::EnergyPreserving, 0.0, glm::dvec3(1.0), true);
        add(DielectricCoupling::EnergyPreserving, 0.5, glm::dvec3(1.0), true);
        add(DielectricCoupling::EnergyPreserving, 1.0, glm::dvec3(5.0), true);
        add(DielectricCoupling::EnergyPreserving, 1.0, glm::dvec3(25.0), true);
        add(DielectricCoupling::EnergyPreserving, 0.8, glm::dvec3(4.0, 2.0, 0.5), false);
    }
    void furnaceGainsNothing()
    {
        QFETCH(int, coupling);
        QFETCH(double, specular);
        QFETCH(glm::dvec3, specularColor);
        QFETCH(bool, unity);
        ShadingModel model;
        model.coupling = DielectricCoupling(coupling);
        const MaterialBrdf brdf(model, m_table);
        double highest = 0.0;
        double lowest = 2.0;
        for (double roughness : {0.1, 0.5, 1.0})
            for (double NoV : {0.1, 0.3, 0.6, 1.0}) {
                MaterialInfo m = test::whiteMaterial(0.0, roughness);
                m.specular = specular;
                m.specularColor = specularColor;
                const glm::dvec3 albedo = directionalAlbedo(brdf, m, NoV, 4096);
                highest = std::max({highest, albedo.r, albedo.g, albedo.b});
                lowest = std::min({lowest, albedo.r, albedo.g, albedo.b});
            }
        qInfo("albedo in [%.4f, %.4f]", lowest, highest);
        QVERIFY2(highest <= 1.005, qPrintable(QString::number(highest)));
        // The table's interpolation and the 4096-point integral (SplitSumTest: ~1e-3).
        if (unity)
            QVERIFY2(lowest >= 0.99, qPrintable(QString::number(lowest)));
    }
};

QTEST_APPLESS_MAIN(SpecularLayerTest)
#include "SpecularLayerTest.moc"
