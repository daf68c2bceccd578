// IblSettings: the cache key follows every field (a field left out of hash() would let one
// setting's disk entries answer for another's); the DFG tables shipped as data are the integral
// of the settings whose key finds them.

#include <QtTest/QTest>

#include <glm/gtc/packing.hpp>

#include "core/project/Project.h"
#include "core/shading/DfgTable.h"
#include "render/IblSettings.h"
#include "render/ShippedDfgTables.h"

#include <cstdlib>

using namespace facet;

class IblSettingsTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    // A project's quality and its name give the same settings; the three differ; a wrong name is none.
    void presetsByQualityAndName_data()
    {
        QTest::addColumn<int>("quality");
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("cubeSize");
        QTest::newRow("draft") << int(IblQuality::Draft) << "draft" << 128;
        QTest::newRow("default") << int(IblQuality::Default) << "default" << IblSettings {}.cubeSize;
        QTest::newRow("high") << int(IblQuality::High) << "high" << 512;
    }
    void presetsByQualityAndName()
    {
        QFETCH(int, quality);
        QFETCH(QString, name);
        QFETCH(int, cubeSize);
        const IblSettings byQuality = IblSettings::preset(IblQuality(quality));
        const std::optional<IblSettings> byName = IblSettings::preset(name.toStdString());
        QVERIFY(byName);
        QCOMPARE(byQuality.hash(), byName->hash());
        QCOMPARE(byQuality.cubeSize, cubeSize);
        QVERIFY(IblSettings::presetNames().size() == 3);
        QVERIFY(!IblSettings::preset(std::string("ultra")));
    }

    void hashFollowsEveryField()
    {
        const IblSettings base;
        QCOMPARE(base.hash(), IblSettings().hash());
        auto differs = [&](auto change) {
            IblSettings other = base;
            change(other);
            return other.hash() != base.hash();
        };
        QVERIFY(differs([](IblSettings& s) { s.cubeSize = 512; }));
        QVERIFY(differs([](IblSettings& s) { s.prefilterSize = 64; }));
        QVERIFY(differs([](IblSettings& s) { s.prefilterMipLevels = 5; }));
        QVERIFY(differs([](IblSettings& s) { s.prefilterSamples = 64; }));
        QVERIFY(differs([](IblSettings& s) { s.irradianceSize = 16; }));
        QVERIFY(differs([](IblSettings& s) { s.irradianceSamples = 1536; }));
        QVERIFY(differs([](IblSettings& s) { s.dfgSize = 64; }));
        QVERIFY(differs([](IblSettings& s) { s.dfgSamples = 512; }));
        QVERIFY(differs([](IblSettings& s) { s.irradiance = IblSettings::Irradiance::SH; }));
    }

    // Each visibility term's table for the default preset is shipped, found by its key, and holds
    // DfgTable::compute's values for those settings in binary16, texel for texel (a table written
    // before a change to the integral, for other settings, another V or transposed fails here;
    // write_dfg_tables writes the file again).
    void shippedDfgTables_data()
    {
        QTest::addColumn<int>("visibility");
        for (Visibility visibility : kAllVisibilities)
            QTest::addRow("%s", toString(visibility)) << int(visibility);
    }
    void shippedDfgTables()
    {
        QFETCH(int, visibility);
        const Visibility v = Visibility(visibility);
        const IblSettings settings = *IblSettings::preset("default");
        const ShippedDfgTable* shipped = findShippedDfgTable(settings.dfgHash(v));
        QVERIFY2(shipped, "no table shipped for the default preset: run write_dfg_tables (render/ShippedDfgTables.h)");
        QVERIFY(shipped->visibility == v);
        QCOMPARE(shipped->size, settings.dfgSize);
        QCOMPARE(shipped->samples, settings.dfgSamples);
        const std::vector<float> values = DfgTable::compute(settings.dfgSize, settings.dfgSamples, v).toRgbaFloats();
        int exact = 0;
        for (std::size_t i = 0; i < values.size(); ++i) {
            const int expected = glm::packHalf1x16(values[i]);
            const int held = shipped->texels[i];
            // One binary16 step for float rounding differences between compilers' flags.
            QVERIFY2(std::abs(held - expected) <= 1,
                qPrintable(QStringLiteral("value %1 (texel %2, %3, channel %4): 0x%5, the integral gives 0x%6")
                        .arg(i)
                        .arg(i / 4 % std::size_t(shipped->size))
                        .arg(i / 4 / std::size_t(shipped->size))
                        .arg(i % 4)
                        .arg(held, 4, 16, QLatin1Char('0'))
                        .arg(expected, 4, 16, QLatin1Char('0'))));
            exact += held == expected;
        }
        QVERIFY(exact > int(values.size()) * 99 / 100);
        // Other settings' tables are not shipped: they are made (and cached) as before.
        for (const char* other : {"draft", "high"})
            QVERIFY(!findShippedDfgTable(IblSettings::preset(other)->dfgHash(v)));
    }
};

QTEST_GUILESS_MAIN(IblSettingsTest)
#include "IblSettingsTest.moc"
