// core/material/MaterialSwatch: the preset library's swatches, rendered on the CPU. Each built-in preset's
// swatch (written to test-output/swatches.png to look at) is a lit sphere: alpha 1 inside, 0
// outside, partial at the rim; metals take their colour from the base colour (gold redder than
// silver); a glossy material shows the studio's soft boxes as sharper highlights than a rough one
// (more contrast on the sphere); a normal map and an emissive colour change the swatch; under a
// uniform environment a white rough dielectric is flat. Prints the time per swatch.

#include <QElapsedTimer>
#include <QtTest/QTest>

#include <cmath>

#include "TestSupport.h"
#include "core/material/MaterialPresets.h"
#include "core/material/MaterialSwatch.h"

using namespace facet;

namespace {

constexpr int kSize = 40;

// Mean, standard deviation and largest value of the luminance over the fully covered pixels.
struct Stats {
    double mean, deviation, largest;
};
Stats stats(const Image& swatch)
{
    double sum = 0.0, squares = 0.0, largest = 0.0;
    int count = 0;
    for (int y = 0; y < swatch.height(); ++y)
        for (int x = 0; x < swatch.width(); ++x) {
            const glm::vec4& p = swatch.at(x, y);
            if (p.a < 1.0f)
                continue;
            const double l = 0.2126 * p.r + 0.7152 * p.g + 0.0722 * p.b;
            sum += l;
            squares += l * l;
            largest = std::max(largest, l);
            ++count;
        }
    const double mean = sum / count;
    return {mean, std::sqrt(std::max(squares / count - mean * mean, 0.0)), largest};
}

glm::dvec3 meanColour(const Image& swatch)
{
    glm::dvec3 sum(0.0);
    int count = 0;
    for (int y = 0; y < swatch.height(); ++y)
        for (int x = 0; x < swatch.width(); ++x)
            if (swatch.at(x, y).a == 1.0f) {
                sum += glm::dvec3(swatch.at(x, y));
                ++count;
            }
    return sum / double(count);
}

} // namespace

class MaterialSwatchTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void everyBuiltinPreset()
    {
        const SwatchRenderer renderer;
        const std::vector<MaterialPreset>& presets = builtinPresets();
        Image sheet(kSize * int(presets.size()), kSize, glm::vec4(0.3f, 0.3f, 0.3f, 1.0f));
        QElapsedTimer clock;
        clock.start();
        for (std::size_t i = 0; i < presets.size(); ++i) {
            const Image swatch = renderer.render(presets[i].material, {}, kSize);
            QCOMPARE(swatch.width(), kSize);
            // Coverage: the centre is covered, the corners are not, the rim is partial.
            QCOMPARE(swatch.at(kSize / 2, kSize / 2).a, 1.0f);
            QCOMPARE(swatch.at(0, 0).a, 0.0f);
            bool partial = false;
            for (int y = 0; y < kSize && !partial; ++y)
                for (int x = 0; x < kSize && !partial; ++x)
                    partial = swatch.at(x, y).a > 0.0f && swatch.at(x, y).a < 1.0f;
            QVERIFY2(partial, presets[i].id.c_str());
            for (int y = 0; y < kSize; ++y)
                for (int x = 0; x < kSize; ++x) {
                    const glm::vec4 p = swatch.at(x, y);
                    QVERIFY(std::isfinite(p.r) && p.r >= 0.0f && p.r <= 1.0f);
                    sheet.at(int(i) * kSize + x, y) = glm::mix(sheet.at(int(i) * kSize + x, y), p, p.a);
                }
        }
        const double ms = double(clock.nsecsElapsed()) / 1e6 / double(presets.size());
        qInfo("%zu swatches of %dx%d: %.1f ms each (one thread)", presets.size(), kSize, kSize, ms);
        sheet.setEncoding(ColorEncoding::SRGB);
        std::string error;
        QVERIFY2(sheet.save((test::outputDir() + QStringLiteral("/swatches.png")).toStdString(), &error),
            error.c_str());
    }

    void looksFollowTheMaterial()
    {
        const SwatchRenderer renderer;
        const glm::dvec3 gold = meanColour(renderer.render(findPreset("gold")->material, {}, kSize));
        const glm::dvec3 silver = meanColour(renderer.render(findPreset("silver")->material, {}, kSize));
        QVERIFY2(gold.r / gold.b > 1.5 * silver.r / silver.b,
            qPrintable(QStringLiteral("gold %1, silver %2").arg(gold.r / gold.b).arg(silver.r / silver.b)));

        Material glossy;
        glossy.setBaseColor(glm::dvec3(0.05));
        glossy.setFactor(MapSlot::Roughness, 0.1);
        Material rough = glossy;
        rough.setFactor(MapSlot::Roughness, 0.9);
        // The soft box reflected: a bright, small highlight on the glossy sphere, spread dim on
        // the rough one.
        const Stats glossyStats = stats(renderer.render(glossy, {}, kSize));
        const Stats roughStats = stats(renderer.render(rough, {}, kSize));
        qInfo("highlight: glossy %.3f (mean %.3f), rough %.3f (mean %.3f)", glossyStats.largest,
            glossyStats.mean, roughStats.largest, roughStats.mean);
        QVERIFY(glossyStats.largest > roughStats.largest + 0.15);

        // A smooth clear coat over the rough one: the soft box's sharp highlight again, over the
        // rough base (the coat lit by its own prefiltered light).
        Material coated = rough;
        coated.setClearcoat(1.0, 0.05);
        const Stats coatedStats = stats(renderer.render(coated, {}, kSize));
        qInfo("highlight: coated rough %.3f (mean %.3f)", coatedStats.largest, coatedStats.mean);
        QVERIFY(coatedStats.largest > roughStats.largest + 0.15);

        // A pink sheen over the dark rough base: the sphere turns pink (the sheen's lobe lit by
        // the irradiance), and brighter, since the dark base gives up little.
        Material velvet = rough;
        velvet.setSheen(glm::dvec3(1.0, 0.3, 0.6), 0.5);
        const glm::dvec3 plain = meanColour(renderer.render(rough, {}, kSize));
        const glm::dvec3 sheened = meanColour(renderer.render(velvet, {}, kSize));
        qInfo("mean colour: rough (%.3f, %.3f, %.3f), with a pink sheen (%.3f, %.3f, %.3f)", plain.r, plain.g,
            plain.b, sheened.r, sheened.g, sheened.b);
        QVERIFY(sheened.r > plain.r + 0.05 && sheened.r > sheened.g + 0.05);

        Material lamp = rough;
        lamp.map(MapSlot::Emissive).factor = glm::dvec4(1.0, 0.3, 0.0, 1.0);
        lamp.emissiveStrength = 4.0;
        QVERIFY(meanColour(renderer.render(lamp, {}, kSize)).r
            > meanColour(renderer.render(rough, {}, kSize)).r + 0.3);

        // A normal map tilting every normal: the swatch changes.
        Image tilt(4, 4, glm::vec4(0.8f, 0.5f, 0.8f, 1.0f));
        const MapImage normal = MapImage::fromImage(tilt, MapLayout::Rgb, MapSampleType::UInt8);
        Material bumped = glossy;
        bumped.map(MapSlot::Normal).path = "tilt.png";
        MaterialMapImages images {};
        images[std::size_t(MapSlot::Normal)] = &normal;
        const Image a = renderer.render(glossy, {}, kSize);
        const Image b = renderer.render(bumped, images, kSize);
        double difference = 0.0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x)
                difference += std::abs(a.at(x, y).g - b.at(x, y).g);
        QVERIFY(difference / (kSize * kSize) > 0.01);
    }

    void uniformLightIsFlat()
    {
        // A white rough dielectric in a uniform environment: the furnace, flat across the sphere
        // (up to the split sum's view dependence, small for a rough lobe).
        const SwatchRenderer renderer(Environment::uniform(glm::dvec3(0.5)), 16);
        Material white;
        white.setBaseColor(glm::dvec3(1.0));
        white.setFactor(MapSlot::Roughness, 1.0);
        const auto [mean, deviation, largest] = stats(renderer.render(white, {}, kSize));
        Q_UNUSED(largest);
        qInfo("uniform: mean %.3f, deviation %.4f", mean, deviation);
        QVERIFY(deviation < 0.03);
        QVERIFY(mean > 0.3 && mean < 0.8);
    }
};

QTEST_GUILESS_MAIN(MaterialSwatchTest)
#include "MaterialSwatchTest.moc"
