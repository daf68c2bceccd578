// The map size budget through `facet render` (core/image/MapImage.h MapBudget): a project whose map is
// larger than the budget (a crafted 16384² PNG of 57 bytes: its pixels do not exist, so only a
// loader that checks the header before decoding can name the real problem) exits 1 naming the
// file and the limit, before any GL work; FACET_MAX_MAP_SIZE and FACET_MAX_MAP_MPIXELS move the
// limit both ways, and a bad value is named and ignored. A row per case.

#include <QDir>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <OpenImageIO/imageio.h>

#include <vector>

#include "TestSupport.h"
#include "core/project/Project.h"

using namespace facet;

class MapBudgetTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase();
    void renderRefusesAMapBeyondTheBudget_data();
    void renderRefusesAMapBeyondTheBudget();

private:
    QTemporaryDir m_dir;
};

void MapBudgetTest::initTestCase()
{
    QVERIFY(m_dir.isValid());
    QVERIFY(facet::test::writePngHeaderOnly(m_dir.filePath(QStringLiteral("huge.png")), 16384, 16384));
    // A real 32 x 32 map.
    std::vector<unsigned char> pixels(32 * 32 * 3, 180);
    const std::string small = m_dir.filePath(QStringLiteral("small.png")).toStdString();
    auto output = OIIO::ImageOutput::create(small);
    OIIO::ImageSpec spec(32, 32, 3, OIIO::TypeDesc::UINT8);
    QVERIFY(output && output->open(small, spec) && output->write_image(OIIO::TypeDesc::UINT8, pixels.data())
            && output->close());
}

void MapBudgetTest::renderRefusesAMapBeyondTheBudget_data()
{
    QTest::addColumn<QString>("map");
    QTest::addColumn<QString>("slot");
    QTest::addColumn<QByteArray>("side");
    QTest::addColumn<QByteArray>("mpixels");
    QTest::addColumn<int>("exitCode");
    QTest::addColumn<QString>("message"); // in stderr
    QTest::newRow("16k base colour, default budget")
        << "huge.png" << "baseColor" << QByteArray() << QByteArray() << 1
        << "facet render: loadProjectAssets: baseColor map: MapImage::load: %1: 16384x16384 is larger than the map "
           "size limit of 8192 pixels per side (FACET_MAX_MAP_SIZE)";
    QTest::newRow("16k normal map") << "huge.png" << "normal" << QByteArray() << QByteArray() << 1
                                    << "normal map: MapImage::load: %1: 16384x16384 is larger than the map size limit";
    QTest::newRow("16k allowed by the side, not by the pixels")
        << "huge.png" << "roughness" << QByteArray("16384") << QByteArray() << 1
        << "roughness map: MapImage::load: %1: 16384x16384 is larger than the map size limit of 64 Mpixel "
           "(FACET_MAX_MAP_MPIXELS)";
    QTest::newRow("32 px over a budget of 16") << "small.png" << "baseColor" << QByteArray("16") << QByteArray() << 1
                                               << "MapImage::load: %1: 32x32 is larger than the map size limit of 16 "
                                                  "pixels per side (FACET_MAX_MAP_SIZE)";
    QTest::newRow("32 px within a budget of 32") << "small.png" << "baseColor" << QByteArray("32") << QByteArray("1")
                                                 << 0 << "";
    QTest::newRow("bad setting named, default used")
        << "small.png" << "baseColor" << QByteArray("huge") << QByteArray() << 0
        << "facet render: FACET_MAX_MAP_SIZE is not a positive whole number: using 8192";
}

void MapBudgetTest::renderRefusesAMapBeyondTheBudget()
{
    QFETCH(QString, map);
    QFETCH(QString, slot);
    QFETCH(QByteArray, side);
    QFETCH(QByteArray, mpixels);
    QFETCH(int, exitCode);
    QFETCH(QString, message);
    const QString mapPath = m_dir.filePath(map);
    Project project = Project::defaultProject();
    project.environment.source = "uniform:1";
    const std::optional<MapSlot> mapSlot = mapSlotFromString(slot.toStdString());
    QVERIFY(mapSlot);
    project.material().map(*mapSlot).path = mapPath.toStdString();
    std::string error;
    const QString projectPath = m_dir.filePath(QStringLiteral("p.json"));
    QVERIFY2(project.save(projectPath.toStdString(), &error), error.c_str());
    const QString out = m_dir.filePath(QStringLiteral("out.png"));
    QFile::remove(out);
    QProcessEnvironment environment;
    environment.insert(QStringLiteral("FACET_CACHE_DIR"), m_dir.filePath(QStringLiteral("cache")));
    if (!side.isEmpty())
        environment.insert(QStringLiteral("FACET_MAX_MAP_SIZE"), QString::fromLatin1(side));
    if (!mpixels.isEmpty())
        environment.insert(QStringLiteral("FACET_MAX_MAP_MPIXELS"), QString::fromLatin1(mpixels));
    const facet::test::ProcessResult result = facet::test::runWithoutDisplay(QStringLiteral(FACET_EXECUTABLE),
        {QStringLiteral("render"), projectPath, QStringLiteral("--size"), QStringLiteral("16x16"),
         QStringLiteral("-o"), out},
        environment);
    QVERIFY2(result.exitCode == exitCode, qPrintable(QStringLiteral("exit %1: %2").arg(result.exitCode).arg(result.err)));
    if (!message.isEmpty())
        QVERIFY2(result.err.contains(message.arg(mapPath)), qPrintable(result.err));
    QCOMPARE(QFileInfo::exists(out), exitCode == 0);
}

QTEST_GUILESS_MAIN(MapBudgetTest)
#include "MapBudgetTest.moc"
