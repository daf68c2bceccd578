// The IBL precompute's DFG LUT and caches on the GPU (render/IblPrecompute): each visibility
// variant's table against its CPU twin (core/shading/DfgTable), the tables shipped with Facet
// against the pass, the DFG keys and disk entries per variant, the memory cache (rotation and
// intensity no inputs), the disk cache read back bit for bit, and a corrupt entry recomputed. Needs
// a GL context (EGL, no display server). The environment's textures against their CPU twins:
// IblGLTest.

#include <epoxy/gl.h> // before any header that could pull in <GL/gl.h>

#include "core/ibl/Environment.h"
#include "core/ibl/IblDiskCache.h"
#include "core/shading/DfgTable.h"
#include "render/HeadlessGLContext.h"
#include "render/IblPrecompute.h"

#include "IblGLTestSupport.h"
#include "TestSupport.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

using namespace facet;
using facet::test::Level;
using facet::test::readLevel;
using facet::test::smallSettings;

class IblCacheGLTest : public QObject, protected facet::test::IblGLFixture {
    Q_OBJECT
public:
    static void initMain() { facet::test::forgetDisplayServer(); }

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();

    void dfgMatchesCpuTable_data();
    void dfgMatchesCpuTable();
    void shippedDfgTablesMatchThePass_data();
    void shippedDfgTablesMatchThePass();
    void dfgCacheKeyHoldsVisibility();
    void dfgDiskCachePerVisibility();
    void memoryCacheAndRotationIntensity();
    void diskCacheReproducesTexels();
    void corruptDiskCacheIsRecomputed();
};

void IblCacheGLTest::initTestCase()
{
    initIblFixture();
}

void IblCacheGLTest::cleanupTestCase()
{
    cleanupIblFixture();
}

void IblCacheGLTest::dfgMatchesCpuTable_data()
{
    QTest::addColumn<int>("visibility");
    for (Visibility visibility : kAllVisibilities)
        QTest::addRow("%s", toString(visibility)) << int(visibility);
}

void IblCacheGLTest::dfgMatchesCpuTable()
{
    // Each variant's GPU table against the CPU table of the SAME variant: a pass that ignored its
    // visibility (e.g. always DFG_VISIBILITY 0) fails the two other rows by up to 0.25.
    QFETCH(int, visibility);
    const Visibility variant = Visibility(visibility);
    const IblSettings settings = smallSettings();
    std::string error;
    IblStats stats;
    const auto lut = m_ibl->dfgTable(settings, variant, &stats, &error);
    QVERIFY2(lut, error.c_str());
    // QVERIFY2, not QCOMPARE: QTest would delete[] the static name facet::toString returns.
    QVERIFY2(lut->visibility == variant, toString(lut->visibility));
    QCOMPARE(lut->size, settings.dfgSize);
    QCOMPARE(lut->sampleCount, settings.dfgSamples);
    const DfgTable table = DfgTable::compute(settings.dfgSize, settings.dfgSamples, variant);
    const Level level = readLevel(lut->texture, 0, 0);
    QCOMPARE(level.width, settings.dfgSize);
    double worst = 0.0;
    double otherVariants = 0.0; // how far the other variants' CPU tables are: what the test can see
    for (int y = 0; y < level.height; ++y)
        for (int x = 0; x < level.width; ++x) {
            const DfgValue& cpu = table.texel(x, y);
            const glm::dvec3 gpu = level.at(x, y);
            worst = std::max({worst, std::abs(gpu.x - cpu.scale), std::abs(gpu.y - cpu.bias),
                std::abs(gpu.z - cpu.albedo())});
            for (Visibility other : kAllVisibilities)
                if (other != variant)
                    otherVariants = std::max(otherVariants,
                        std::abs(gpu.z
                            - integrateDfg(DfgTable::texelPosition(x, level.width),
                                DfgTable::texelPosition(y, level.height), settings.dfgSamples, other)
                                  .albedo()));
        }
    qInfo("DFG %s GPU vs CPU (%d^2, %d samples): max abs error %.3g (another V's table: %.3g)",
        toString(variant), settings.dfgSize, settings.dfgSamples, worst, otherVariants);
    // Same Hammersley points and formulas: what remains is float vs double arithmetic (~1e-6)
    // and half-float storage of values in [0, 1] (2^-11 = 4.9e-4 at 1).
    QVERIFY2(worst < 1e-3, std::to_string(worst).c_str());
    QVERIFY(otherVariants > 0.05); // the variants differ far beyond the bound: the row can fail
}

void IblCacheGLTest::shippedDfgTablesMatchThePass_data()
{
    dfgMatchesCpuTable_data();
}

void IblCacheGLTest::shippedDfgTablesMatchThePass()
{
    // The default preset's tables come from the data shipped with Facet (render/ShippedDfgTables.h):
    // no pass, nothing on disk; uploaded, they read back as the pass's own table of the same
    // settings and V, in the same orientation (a transposed or flipped upload would fail).
    QFETCH(int, visibility);
    const Visibility variant = Visibility(visibility);
    const IblSettings settings = *IblSettings::preset("default");
    QTemporaryDir cache;
    QVERIFY(cache.isValid());
    std::string error;
    IblPrecompute shipping(cache.path(), true);
    IblStats stats;
    const auto shipped = shipping.dfgTable(settings, variant, &stats, &error);
    QVERIFY2(shipped, error.c_str());
    QCOMPARE(stats.dfgShipped, 1);
    QCOMPARE(stats.passesRun, 0);
    QCOMPARE(stats.cacheHitsDisk, 0);
    QVERIFY(QDir(cache.path()).entryList(QDir::Files | QDir::NoDotAndDotDot).isEmpty());
    QVERIFY(shipped->visibility == variant);
    IblPrecompute computing(QString(), false);
    computing.setUseShippedDfgTables(false);
    stats = IblStats {};
    const auto computed = computing.dfgTable(settings, variant, &stats, &error);
    QVERIFY2(computed, error.c_str());
    QCOMPARE(stats.passesRun, 1);
    QCOMPARE(stats.dfgShipped, 0);
    const Level a = readLevel(shipped->texture, 0, 0);
    const Level b = readLevel(computed->texture, 0, 0);
    QCOMPARE(a.width, settings.dfgSize);
    QCOMPARE(b.width, settings.dfgSize);
    double worst = 0.0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const glm::dvec3 d = glm::abs(a.at(x, y) - b.at(x, y));
            worst = std::max({worst, d.x, d.y, d.z});
        }
    qInfo("DFG %s shipped vs the pass: max abs difference %.3g", toString(variant), worst);
    QVERIFY2(worst < 1e-3, std::to_string(worst).c_str()); // float vs double and binary16, as dfgMatchesCpuTable
}

void IblCacheGLTest::dfgCacheKeyHoldsVisibility()
{
    // The key of a DFG LUT holds its visibility term: three variants, three keys, three tables in
    // memory, each made once.
    const IblSettings settings = smallSettings();
    const std::uint64_t keys[] = {settings.dfgHash(Visibility::SmithGGXCorrelated),
        settings.dfgHash(Visibility::SmithGGXUncorrelated), settings.dfgHash(Visibility::SchlickGGX)};
    QVERIFY(keys[0] != keys[1] && keys[0] != keys[2] && keys[1] != keys[2]);
    QCOMPARE(settings.dfgHash(Visibility::SchlickGGX), keys[2]); // stable
    IblSettings moreSamples = settings;
    moreSamples.dfgSamples *= 2;
    QVERIFY(moreSamples.dfgHash(Visibility::SchlickGGX) != keys[2]);
    IblSettings otherPrefilter = settings; // not a DFG input: the same table
    otherPrefilter.prefilterSamples *= 2;
    QCOMPARE(otherPrefilter.dfgHash(Visibility::SchlickGGX), keys[2]);

    IblPrecompute ibl(QString(), false);
    std::string error;
    std::shared_ptr<const DfgLut> made[kVisibilityCount];
    for (Visibility visibility : kAllVisibilities) {
        IblStats stats;
        made[int(visibility)] = ibl.dfgTable(settings, visibility, &stats, &error);
        QVERIFY2(made[int(visibility)], error.c_str());
        QCOMPARE(stats.passesRun, 1); // not the table of a variant asked before
        QVERIFY2(
            made[int(visibility)]->visibility == visibility, toString(made[int(visibility)]->visibility));
    }
    QVERIFY(
        made[0]->id() != made[1]->id() && made[0]->id() != made[2]->id() && made[1]->id() != made[2]->id());
    for (Visibility visibility : kAllVisibilities) {
        IblStats stats;
        const auto again = ibl.dfgTable(settings, visibility, &stats, &error);
        QCOMPARE(again.get(), made[int(visibility)].get()); // memory hit, its own variant
        QCOMPARE(stats.passesRun, 0);
    }
    // The environment's textures do not depend on the variant, and the tables not on the
    // environment: prepare() runs no DFG pass.
    IblStats stats;
    QVERIFY2(ibl.prepare(Environment::uniform(glm::dvec3(1.0)), settings, &stats, &error), error.c_str());
    QCOMPARE(stats.passesRun, 3);
    QCOMPARE(stats.msDfg, 0.0);
}

void IblCacheGLTest::dfgDiskCachePerVisibility()
{
    // On disk: one file per variant, read back bit for bit by a fresh precompute, and an entry
    // written under version 2's key (which had no visibility: always the correlated table) is
    // never served for any variant.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const IblSettings settings = smallSettings();
    std::string error;
    std::vector<std::vector<float>> written;
    {
        IblPrecompute writer(dir.path());
        for (Visibility visibility : kAllVisibilities) {
            IblStats stats;
            const auto lut = writer.dfgTable(settings, visibility, &stats, &error);
            QVERIFY2(lut, error.c_str());
            QCOMPARE(stats.passesRun, 1);
            QCOMPARE(stats.cacheHitsDisk, 0);
            written.push_back(readLevel(lut->texture, 0, 0).rgba);
            QVERIFY(QFile::exists(
                IblDiskCache(dir.path()).pathFor(IblDiskCache::key(0, settings.dfgHash(visibility)))));
        }
    }
    QCOMPARE(QDir(dir.path()).entryList({QStringLiteral("*.fibl")}).size(), kVisibilityCount);
    QVERIFY(written[0] != written[1] && written[0] != written[2] && written[1] != written[2]);
    {
        IblPrecompute reader(dir.path());
        for (Visibility visibility : kAllVisibilities) {
            IblStats stats;
            const auto lut = reader.dfgTable(settings, visibility, &stats, &error);
            QVERIFY2(lut, error.c_str());
            QCOMPARE(stats.passesRun, 0);
            QCOMPARE(stats.cacheHitsDisk, 1);
            QVERIFY2(lut->visibility == visibility, toString(lut->visibility));
            QVERIFY(readLevel(lut->texture, 0, 0).rgba == written[std::size_t(visibility)]);
        }
    }

    // Version 2's key: FNV-1a 64 over int32 (2, "DFG", dfgSize, dfgSamples), no visibility. Put a
    // valid entry of the correlated table there (what version 2 wrote) in an empty folder.
    auto fnv = [](std::uint64_t h, std::int32_t value) {
        for (int i = 0; i < 4; ++i) {
            h ^= (std::uint32_t(value) >> (8 * i)) & 0xffu;
            h *= 0x100000001b3ULL;
        }
        return h;
    };
    std::uint64_t oldHash = fnv(0xcbf29ce484222325ULL, 2);
    for (std::int32_t v : {0x44464700, settings.dfgSize, settings.dfgSamples})
        oldHash = fnv(oldHash, v);
    QTemporaryDir oldDir;
    QVERIFY(oldDir.isValid());
    const IblDiskCache oldCache(oldDir.path());
    IblCacheEntry stale;
    IblCacheLayer layer;
    layer.width = layer.height = settings.dfgSize;
    layer.format = IblCacheLayer::Format::Float;
    layer.single = written[std::size_t(Visibility::SmithGGXCorrelated)];
    stale.layers.push_back(layer);
    QVERIFY2(oldCache.store(IblDiskCache::key(0, oldHash), stale, &error), error.c_str());
    IblPrecompute upgraded(oldDir.path());
    for (Visibility visibility : kAllVisibilities) {
        QVERIFY(IblDiskCache::key(0, settings.dfgHash(visibility)) != IblDiskCache::key(0, oldHash));
        IblStats stats;
        QVERIFY2(upgraded.dfgTable(settings, visibility, &stats, &error), error.c_str());
        QCOMPARE(stats.cacheHitsDisk, 0);
        QCOMPARE(stats.passesRun, 1);
    }
}

void IblCacheGLTest::memoryCacheAndRotationIntensity()
{
    IblPrecompute ibl(QString(), false);
    Environment env = Environment::builtin(Environment::Builtin::Sky, 64);
    std::string error;
    IblStats stats;
    const auto first = ibl.prepare(env, smallSettings(), &stats, &error);
    QVERIFY2(first, error.c_str());
    QCOMPARE(stats.passesRun, 3);
    QCOMPARE(stats.cacheHitsMemory, 0);

    const auto second = ibl.prepare(env, smallSettings(), &stats, &error);
    QCOMPARE(second.get(), first.get());
    QCOMPARE(stats.passesRun, 0);
    QCOMPARE(stats.cacheHitsMemory, 1);

    // Rotation and intensity are applied at shading time: not inputs of the precompute.
    env.setRotationDegrees(73.0);
    env.setIntensity(4.0);
    const auto rotated = ibl.prepare(env, smallSettings(), &stats, &error);
    QCOMPARE(rotated.get(), first.get());
    QCOMPARE(stats.passesRun, 0);

    // Other settings with the same DFG parameters: the DFG LUT is reused, the rest reruns.
    const auto lut = ibl.dfgTable(smallSettings(), Visibility::SmithGGXCorrelated, &stats, &error);
    QVERIFY2(lut, error.c_str());
    IblSettings other = smallSettings();
    other.prefilterSamples = 32;
    const auto third = ibl.prepare(env, other, &stats, &error);
    QVERIFY2(third, error.c_str());
    QCOMPARE(stats.passesRun, 3);
    QCOMPARE(ibl.dfgTable(other, Visibility::SmithGGXCorrelated, &stats, &error).get(), lut.get());
    QCOMPARE(stats.passesRun, 3); // added to, and nothing added
    QVERIFY(third.get() != first.get());
}

void IblCacheGLTest::diskCacheReproducesTexels()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    qputenv("FACET_CACHE_DIR", dir.path().toUtf8());
    const Environment env = Environment::builtin(Environment::Builtin::Studio, 64);
    std::string error;
    IblStats stats;
    std::shared_ptr<const IblTextures> computed;
    std::shared_ptr<const DfgLut> lut;
    std::vector<std::vector<float>> before;
    {
        IblPrecompute writer; // default directory: $FACET_CACHE_DIR
        QCOMPARE(writer.cacheDirectory(), dir.path());
        computed = writer.prepare(env, smallSettings(), &stats, &error);
        QVERIFY2(computed, error.c_str());
        lut = writer.dfgTable(smallSettings(), Visibility::SmithGGXCorrelated, &stats, &error);
        QVERIFY2(lut, error.c_str());
        QCOMPARE(stats.passesRun, 4);
        QCOMPARE(stats.cacheHitsDisk, 0);
        for (int face = 0; face < 6; ++face) {
            before.push_back(readLevel(computed->environment, face, 0).rgba);
            for (int level = 0; level < computed->prefilteredMipLevels; ++level)
                before.push_back(readLevel(computed->prefiltered, face, level).rgba);
            before.push_back(readLevel(computed->irradiance, face, 0).rgba);
        }
        before.push_back(readLevel(lut->texture, 0, 0).rgba);
    }
    QCOMPARE(QDir(dir.path()).entryList({QStringLiteral("*.fibl")}).size(), 2); // environment + DFG

    IblPrecompute reader;
    const auto loaded = reader.prepare(env, smallSettings(), &stats, &error);
    QVERIFY2(loaded, error.c_str());
    const auto loadedLut = reader.dfgTable(smallSettings(), Visibility::SmithGGXCorrelated, &stats, &error);
    QVERIFY2(loadedLut, error.c_str());
    QCOMPARE(stats.passesRun, 0);
    QCOMPARE(stats.cacheHitsDisk, 2);
    QVERIFY(!reader.compiledPasses()); // a disk-cache hit compiles no shader
    std::size_t i = 0;
    for (int face = 0; face < 6; ++face) {
        QVERIFY(readLevel(loaded->environment, face, 0).rgba == before[i++]);
        for (int level = 0; level < loaded->prefilteredMipLevels; ++level)
            QVERIFY(readLevel(loaded->prefiltered, face, level).rgba == before[i++]);
        QVERIFY(readLevel(loaded->irradiance, face, 0).rgba == before[i++]);
    }
    QVERIFY(readLevel(loadedLut->texture, 0, 0).rgba == before[i++]);
    QVERIFY(loaded->irradianceSH == computed->irradianceSH);
    qputenv("FACET_CACHE_DIR", m_cacheDir.path().toUtf8());
}

void IblCacheGLTest::corruptDiskCacheIsRecomputed()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const Environment env = Environment::builtin(Environment::Builtin::Sky, 64);
    std::string error;
    IblStats stats;
    {
        IblPrecompute writer(dir.path());
        QVERIFY2(writer.prepare(env, smallSettings(), &stats, &error), error.c_str());
    }
    const QString path
        = IblDiskCache(dir.path())
              .pathFor(IblDiskCache::key(env.contentHash(), smallSettings().sanitized().hash()));
    QVERIFY(QFile::exists(path));
    QVERIFY(QFile::resize(path, QFileInfo(path).size() / 2)); // truncated
    IblPrecompute reader(dir.path());
    QTest::ignoreMessage(QtWarningMsg, QRegularExpression(QStringLiteral("IblDiskCache::load: .*truncated")));
    const auto result = reader.prepare(env, smallSettings(), &stats, &error);
    QVERIFY2(result, error.c_str());
    QCOMPARE(stats.passesRun, 3); // the environment's passes rerun
    QCOMPARE(stats.cacheHitsDisk, 0);
    QVERIFY(reader.lastWarning().find("truncated") != std::string::npos);
    // ... and the file was rewritten whole.
    IblPrecompute again(dir.path());
    QVERIFY(again.prepare(env, smallSettings(), &stats, &error));
    QCOMPARE(stats.passesRun, 0);
}

QTEST_GUILESS_MAIN(IblCacheGLTest)
#include "IblCacheGLTest.moc"
