// The split sum's sharp lobes (IblSampling::sharpLobeSamples, environment_lighting.glsl): below
// the prefiltered map's level 1 each pixel integrates its own lobe by a few filtered importance
// samples of the environment cube instead of reading the resampled level 0. Held, in docs/architecture.md's
// reference view through `facet render --reference-view`'s FrameRenderer path, to:
// - the CPU ground truth, per CC0 map and material at roughness 0.05 (the lookup alone: 7.75%
//   mean relative RMSE over the five maps in `facet bench`) and in the blend region (0.08);
// - no case worse than the lookup alone, and a clear gain where the lookup's resampling shows;
// - nothing changed at or above level 1 (roughness 0.25: the same image to the bit);
// - a white furnace at 1 within 0.5% (issue 10's bound for every method).

#include "core/image/ImageMetrics.h"
#include "core/image/MapImage.h"
#include "core/project/Project.h"
#include "render/Renderer.h"
#include "render/ShaderVariant.h"

#include "IblMethodCase.h"
#include "ReferenceViewRenderer.h"
#include "TestSupport.h"

#include <QtTest/QTest>

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

using namespace facet;

namespace {

constexpr int kSize = 32;
constexpr int kTruthSamples = 1024;

struct Row {
    const char* name;
    const char* environment; // a CC0 map name (packaging/fetch-assets.sh)
    bool metal;
    double roughness;
    double bound; // relative RMSE against the truth with the sharp lobes
    double gain; // with / without must be at most this (1: no worse)
};

// Bounds: 1.3x the error measured on llvmpipe at 32^2 (printed by each row: 0.59-12.2%; the lookup
// alone 0.70-21.3%), room for another driver's arithmetic and the truth's own noise. Gains: the
// measured ratio (0.27-0.84) plus 0.1, at most 0.95. Measured with the visible normals sampled by
// spherical caps (issue 29's pinch): against Heitz's sampling six rows gained and five lost, the
// mean over the rows the same (3.76% against 3.78%).
const Row kRows[] = {
    {"studio metal 0.05", "studio", true, 0.05, 0.0211, 0.37},
    {"studio dielectric 0.05", "studio", false, 0.05, 0.0274, 0.92},
    {"city metal 0.05", "city", true, 0.05, 0.0317, 0.82},
    {"city dielectric 0.05", "city", false, 0.05, 0.0103, 0.91},
    {"sunset metal 0.05", "sunset", true, 0.05, 0.0218, 0.53},
    {"sunset dielectric 0.05", "sunset", false, 0.05, 0.0077, 0.94},
    {"night metal 0.05", "night", true, 0.05, 0.1178, 0.83},
    {"night dielectric 0.05", "night", false, 0.05, 0.0363, 0.71},
    {"forest metal 0.05", "forest", true, 0.05, 0.1586, 0.67},
    {"forest dielectric 0.05", "forest", false, 0.05, 0.0837, 0.86},
    {"studio metal 0.08 (blend)", "studio", true, 0.08, 0.0417, 0.69},
    {"sunset metal 0.08 (blend)", "sunset", true, 0.08, 0.0290, 0.85},
};

test::IblMethodCase caseOf(const Row& row)
{
    test::IblMethodCase c;
    c.name = row.name;
    c.baseColor = row.metal ? glm::dvec3(1.0, 0.766, 0.336) : glm::dvec3(0.8, 0.1, 0.1);
    c.metallic = row.metal ? 1.0 : 0.0;
    c.roughness = row.roughness;
    c.rotationDegrees = 0.0;
    return c;
}

} // namespace

class SharpLobeGLTest : public QObject {
    Q_OBJECT
public:
    static void initMain() { facet::test::forgetDisplayServer(); }

private Q_SLOTS:
    void initTestCase()
    {
        std::string error;
        QVERIFY2(m_gpu.initialize(&error), error.c_str());
    }

    void againstTheTruth_data()
    {
        QTest::addColumn<int>("row");
        for (int i = 0; i < int(std::size(kRows)); ++i)
            QTest::newRow(kRows[i].name) << i;
    }

    void againstTheTruth()
    {
        QFETCH(int, row);
        const Row& r = kRows[row];
        const QString path = test::hdriPath(QString::fromLatin1(r.environment));
        FACET_REQUIRE_ASSET(path, r.environment);
        test::IblMethodCase c = caseOf(r);
        const std::string source = path.toStdString();
        c.environment = source.c_str();
        const Project project = test::iblMethodCaseProject(c, IblMethod::SplitSum, 0);
        std::string error;
        const auto truth = test::groundTruthImage(project, kSize, kTruthSamples, 1, &error);
        QVERIFY2(truth, error.c_str());
        m_gpu.setSharpLobeSamples(kSplitSumSharpLobeSamples);
        const auto sharp = m_gpu.render(project, "default", kSize, &error);
        QVERIFY2(sharp, error.c_str());
        m_gpu.setSharpLobeSamples(0);
        const auto lookup = m_gpu.render(project, "default", kSize, &error);
        m_gpu.setSharpLobeSamples(kSplitSumSharpLobeSamples);
        QVERIFY2(lookup, error.c_str());
        const double withSharp = relativeRmse(*sharp, *truth);
        const double without = relativeRmse(*lookup, *truth);
        std::printf("  %-28s sharp lobes %6.2f%%, lookup alone %6.2f%%\n", r.name, 100.0 * withSharp,
            100.0 * without);
        QVERIFY2(withSharp <= r.bound,
            qPrintable(QStringLiteral("%1: %2 > bound %3")
                           .arg(QString::fromLatin1(r.name))
                           .arg(withSharp)
                           .arg(r.bound)));
        QVERIFY2(withSharp <= r.gain * without,
            qPrintable(QStringLiteral("%1: %2 against %3 without")
                           .arg(QString::fromLatin1(r.name))
                           .arg(withSharp)
                           .arg(without)));
    }

    // At level 1 and above the lookup is untouched: the same image to the bit.
    void levelOneAndAboveUnchanged()
    {
        const QString path = test::hdriPath(QStringLiteral("forest"));
        FACET_REQUIRE_ASSET(path, "forest");
        const std::string source = path.toStdString();
        for (const double roughness : {0.25, 0.6}) {
            test::IblMethodCase c = caseOf(Row {"", "forest", true, roughness, 0.0, 1.0});
            c.environment = source.c_str();
            const Project project = test::iblMethodCaseProject(c, IblMethod::SplitSum, 0);
            std::string error;
            const auto sharp = m_gpu.render(project, "default", kSize, &error);
            QVERIFY2(sharp, error.c_str());
            m_gpu.setSharpLobeSamples(0);
            const auto lookup = m_gpu.render(project, "default", kSize, &error);
            m_gpu.setSharpLobeSamples(kSplitSumSharpLobeSamples);
            QVERIFY2(lookup, error.c_str());
            QCOMPARE(errorStats(*sharp, *lookup, sphereMask(kSize, kSize)).maxRelativeError, 0.0);
        }
    }

    // A white, compensated metal in a uniform environment of radiance 1 reflects 1.
    void whiteFurnace_data()
    {
        QTest::addColumn<double>("roughness");
        QTest::newRow("r 0.02") << 0.02;
        QTest::newRow("r 0.05") << 0.05;
        QTest::newRow("r 0.08") << 0.08;
    }

    void whiteFurnace()
    {
        QFETCH(double, roughness);
        test::IblMethodCase c;
        c.baseColor = glm::dvec3(1.0);
        c.metallic = 1.0;
        c.roughness = roughness;
        c.environment = "uniform:1";
        const Project project = test::iblMethodCaseProject(c, IblMethod::SplitSum, 0);
        std::string error;
        const auto image = m_gpu.render(project, "default", kSize, &error);
        QVERIFY2(image, error.c_str());
        const Image white(kSize, kSize, glm::vec4(1.0f));
        const double rmse = relativeRmse(*image, white);
        std::printf("  furnace r %.2f: %.3f%%\n", roughness, 100.0 * rmse);
        QVERIFY2(rmse <= 0.005, qPrintable(QString::number(rmse)));
    }

    // The variant (SPLIT_SUM_SHARP_LOBES) is compiled only for materials whose roughness reaches
    // below level 1 (0.106 at six levels): the factor alone, or the factor times the roughness
    // map's smallest value (its channel, colour space and inversion); a map whose range is unknown
    // counts as reaching 0. Not for the sampled methods, a one-level map or no environment cube.
    void variantOnlyWhereALobeIsSharp_data()
    {
        QTest::addColumn<double>("factor");
        QTest::addColumn<int>("map"); // 0: none; 1: values 0.2-0.9 in G; 2: 0.02-0.9 in G; 3: unknown range
        QTest::addColumn<bool>("invert");
        QTest::addColumn<int>("levels");
        QTest::addColumn<int>("method");
        QTest::addColumn<bool>("sharp");
        const int split = int(IblMethod::SplitSum);
        QTest::newRow("factor 0.05") << 0.05 << 0 << false << 6 << split << true;
        QTest::newRow("factor 0.1") << 0.1 << 0 << false << 6 << split << true;
        QTest::newRow("factor 0.11") << 0.11 << 0 << false << 6 << split << false;
        QTest::newRow("factor 0.35") << 0.35 << 0 << false << 6 << split << false;
        QTest::newRow("factor 0 (clamped to the minimum)") << 0.0 << 0 << false << 6 << split << true;
        QTest::newRow("map 0.2-0.9") << 1.0 << 1 << false << 6 << split << false;
        QTest::newRow("map 0.02-0.9") << 1.0 << 2 << false << 6 << split << true;
        QTest::newRow("map 0.2-0.9, factor 0.6 (0.12)") << 0.6 << 1 << false << 6 << split << false;
        QTest::newRow("map 0.2-0.9, factor 0.5 (0.1)") << 0.5 << 1 << false << 6 << split << true;
        QTest::newRow("map 0.2-0.9 inverted (0.1-0.8)") << 1.0 << 1 << true << 6 << split << true;
        QTest::newRow("map 0.02-0.9 inverted (0.1-0.98), factor 0.9")
            << 0.9 << 2 << true << 6 << split << true;
        QTest::newRow("map of unknown range") << 1.0 << 3 << false << 6 << split << true;
        QTest::newRow("one level") << 0.05 << 0 << false << 1 << split << false;
        QTest::newRow("fis") << 0.05 << 0 << false << 6 << int(IblMethod::Fis) << false;
        QTest::newRow("reference") << 0.05 << 0 << false << 6 << int(IblMethod::Reference) << false;
    }

    void variantOnlyWhereALobeIsSharp()
    {
        QFETCH(double, factor);
        QFETCH(int, map);
        QFETCH(bool, invert);
        QFETCH(int, levels);
        QFETCH(int, method);
        QFETCH(bool, sharp);
        RenderScene scene;
        scene.sampling.method = IblMethod(method);
        scene.environment.environmentCubemap = 1; // a name: no GL is touched
        scene.environment.prefilteredLevels = levels;
        RenderMaterial& material = scene.materials[0];
        material.material.setFactor(MapSlot::Roughness, factor);
        MaterialMap& roughness = material.material.map(MapSlot::Roughness);
        roughness.channel = MapChannel::G;
        roughness.colorSpace = ColorEncoding::Linear;
        roughness.invert = invert;
        if (map > 0) {
            Image pixels(4, 4, glm::vec4(0.5f, 0.2f, 0.5f, 1.0f));
            pixels.at(1, 1).g = 0.9f;
            pixels.at(2, 2).g = map == 2 ? 0.02f : 0.2f;
            auto image = std::make_shared<MapImage>(
                MapImage::fromImage(pixels, MapLayout::Rgb, MapSampleType::UInt16));
            if (map == 3)
                image->setSample(0, 0, 1, 0.5f); // written after: the range is no longer known
            material.maps[std::size_t(MapSlot::Roughness)].image = image;
            material.maps[std::size_t(MapSlot::Roughness)].path = "roughness.png";
        }
        const SurfaceVariantKey key = Renderer::variantKeyFor(scene, 0);
        QCOMPARE(hasFeature(key.features, SurfaceFeature::SplitSumSharpLobes), sharp);
    }

private:
    facet::test::ReferenceViewRenderer m_gpu;
};

QTEST_GUILESS_MAIN(SharpLobeGLTest)
#include "SharpLobeGLTest.moc"
