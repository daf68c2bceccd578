// IblSettings: the cache key follows every field (a field left out of hash() would let one
// setting's disk entries answer for another's).

#include <QtTest/QTest>

#include "render/IblSettings.h"

using namespace facet;

class IblSettingsTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
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
};

QTEST_GUILESS_MAIN(IblSettingsTest)
#include "IblSettingsTest.moc"
