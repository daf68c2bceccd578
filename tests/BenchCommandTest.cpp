// `facet bench` as CI and scripts drive it: the executable run with no display server, its CSV
// read back (columns, one row per measurement, finite errors), its ground-truth cache, and its
// command-line errors (exit 2 with a message naming the flag).

#include <cmath>

#include <QFile>
#include <QProcessEnvironment>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include "TestSupport.h"

namespace {

using Result = facet::test::ProcessResult;

Result runFacet(const QStringList& arguments, const QString& cacheDir)
{
    // The test's own caches (never the user's) and the sample data the build was configured with.
    QProcessEnvironment extra;
    extra.insert(QStringLiteral("FACET_CACHE_DIR"), cacheDir);
    extra.insert(QStringLiteral("FACET_ASSETS_DIR"), facet::test::assetsDir());
    return facet::test::runWithoutDisplay(QStringLiteral(FACET_EXECUTABLE), arguments, extra);
}

struct Csv {
    QStringList header;
    QList<QStringList> rows;
    int column(const char* name) const { return int(header.indexOf(QString::fromLatin1(name))); }
};

Csv readCsv(const QString& path)
{
    Csv csv;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        return csv;
    const QStringList lines = QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    if (lines.isEmpty())
        return csv;
    csv.header = lines.first().split(QLatin1Char(','));
    for (qsizetype i = 1; i < lines.size(); ++i)
        csv.rows.append(lines[i].split(QLatin1Char(',')));
    return csv;
}

} // namespace

class BenchCommandTest : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    QString path(const QString& name) const { return m_dir.filePath(name); }

private Q_SLOTS:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    // --quick is the CI run: one map, two configurations, two materials at two roughness values.
    // A second run reads every ground truth from the cache and measures the same errors.
    void quickRunWritesCsv()
    {
        FACET_REQUIRE_ASSET(facet::test::hdriPath(QStringLiteral("city")), "hdri/city.exr");
        const QString csvPath = path(QStringLiteral("quick.csv"));
        const QString cache = path(QStringLiteral("cache"));
        const Result first = runFacet(
            {QStringLiteral("bench"), QStringLiteral("--quick"), QStringLiteral("--csv"), csvPath}, cache);
        QVERIFY2(first.exitCode == 0, qPrintable(first.err));
        // Time and error side by side, per configuration.
        QVERIFY2(first.out.contains(QStringLiteral("needed"))
                && first.out.contains(QStringLiteral("preset=draft"))
                && first.out.contains(QStringLiteral("preset=default")),
            qPrintable(first.out));
        QVERIFY2(
            first.out.contains(QStringLiteral("ground truth: 4 images computed")), qPrintable(first.out));

        const Csv csv = readCsv(csvPath);
        for (const char* name :
            {"group", "config", "environment", "material", "roughness", "size", "truth_spp", "cube_size",
                "prefilter_size", "prefilter_mip_levels", "prefilter_samples", "irradiance",
                "irradiance_size", "irradiance_samples", "dfg_size", "dfg_samples", "ibl_ms", "ibl_needed_ms",
                "ibl_prefilter_ms", "render_ms", "rel_rmse", "max_rel_error", "mean_rel_error", "pixels"})
            QVERIFY2(csv.column(name) >= 0, name);
        QCOMPARE(csv.rows.size(), 8); // 2 configurations x 1 map x 2 materials x 2 roughness values
        const int rmse = csv.column("rel_rmse");
        for (const QStringList& row : csv.rows) {
            QCOMPARE(row.size(), csv.header.size());
            QCOMPARE(row[csv.column("environment")], QStringLiteral("city"));
            bool ok = false;
            const double error = row[rmse].toDouble(&ok);
            // A working renderer is within tens of percent here (docs/benchmarks.md); a broken one
            // (black, NaN, wrong lookups) is at 100% or more.
            QVERIFY2(ok && std::isfinite(error) && error >= 0.0 && error < 0.5,
                qPrintable(row.join(QLatin1Char(','))));
            QVERIFY(row[csv.column("ibl_ms")].toDouble() > 0.0);
            QVERIFY(row[csv.column("pixels")].toInt() > 100);
        }
        QCOMPARE(csv.rows.first()[csv.column("config")], QStringLiteral("preset=draft"));
        QCOMPARE(csv.rows.last()[csv.column("config")], QStringLiteral("preset=default"));

        const QString againPath = path(QStringLiteral("again.csv"));
        const Result again = runFacet(
            {QStringLiteral("bench"), QStringLiteral("--quick"), QStringLiteral("--csv"), againPath}, cache);
        QVERIFY2(again.exitCode == 0, qPrintable(again.err));
        QVERIFY2(again.out.contains(QStringLiteral("0 images computed"))
                && again.out.contains(QStringLiteral("4 from the cache")),
            qPrintable(again.out));
        const Csv second = readCsv(againPath);
        QCOMPARE(second.rows.size(), csv.rows.size());
        for (qsizetype i = 0; i < csv.rows.size(); ++i) {
            // Same truth, same GPU frame: the error may differ only in its last printed digit.
            const double a = csv.rows[i][rmse].toDouble();
            const double b = second.rows[i][rmse].toDouble();
            QVERIFY2(std::abs(a - b) <= 1e-5 * std::max(a, 1e-3),
                qPrintable(QStringLiteral("%1 vs %2").arg(a).arg(b)));
        }
    }

    void helpListsTheOptions()
    {
        const Result r
            = runFacet({QStringLiteral("bench"), QStringLiteral("--help")}, path(QStringLiteral("cache")));
        QCOMPARE(r.exitCode, 0);
        for (const char* option : {"--env", "--size", "--spp", "--quick", "--csv", "--threads", "--sweep"})
            QVERIFY2(r.out.contains(QString::fromLatin1(option)), option);
    }

    void badArgumentsExitTwo_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("message");
        QTest::newRow("unknown env") << QStringList {QStringLiteral("--env"), QStringLiteral("no-such-map")}
                                     << QStringLiteral("--env: 'no-such-map' is not an installed CC0 map");
        QTest::newRow("missing file")
            << QStringList {QStringLiteral("--env"), QStringLiteral("/no/such/map.exr")}
            << QStringLiteral("--env: '/no/such/map.exr' is not a file");
        QTest::newRow("unknown builtin")
            << QStringList {QStringLiteral("--env"), QStringLiteral("builtin:moon")}
            << QStringLiteral("--env: 'builtin:moon'");
        QTest::newRow("bad uniform") << QStringList {QStringLiteral("--env"), QStringLiteral("uniform:-1")}
                                     << QStringLiteral("--env: Environment::fromSpec: uniform:-1");
        QTest::newRow("size zero") << QStringList {QStringLiteral("--size"), QStringLiteral("0")}
                                   << QStringLiteral("--size: '0' is not a whole number from 8 to 1024");
        QTest::newRow("size text") << QStringList {QStringLiteral("--size"), QStringLiteral("big")}
                                   << QStringLiteral("--size: 'big' is not a whole number");
        QTest::newRow("spp negative") << QStringList {QStringLiteral("--spp"), QStringLiteral("-4")}
                                      << QStringLiteral("--spp: '-4' is not a whole number");
        QTest::newRow("threads zero") << QStringList {QStringLiteral("--threads"), QStringLiteral("0")}
                                      << QStringLiteral("--threads: '0' is not a whole number");
        QTest::newRow("repeat") << QStringList {QStringLiteral("--repeat"), QStringLiteral("1.5")}
                                << QStringLiteral("--repeat: '1.5' is not a whole number");
        QTest::newRow("roughness") << QStringList {QStringLiteral("--roughness"), QStringLiteral("0.5,2")}
                                   << QStringLiteral("--roughness: '2' is not a number in [0, 1]");
        QTest::newRow("sweep") << QStringList {QStringLiteral("--sweep"), QStringLiteral("presets,colour")}
                               << QStringLiteral("--sweep: 'colour' is not one of presets, samples");
        QTest::newRow("csv folder")
            << QStringList {QStringLiteral("--csv"), QStringLiteral("/no/such/dir/out.csv")}
            << QStringLiteral("--csv '/no/such/dir/out.csv': the folder /no/such/dir does not exist");
        QTest::newRow("positional") << QStringList {QStringLiteral("project.json")}
                                    << QStringLiteral("unexpected argument 'project.json'");
        QTest::newRow("unknown option")
            << QStringList {QStringLiteral("--fast")} << QStringLiteral("Unknown option 'fast'");
    }

    void badArgumentsExitTwo()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, message);
        arguments.prepend(QStringLiteral("bench"));
        const Result r = runFacet(arguments, path(QStringLiteral("cache")));
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.out.isEmpty(), qPrintable(r.out)); // nothing that looks like a result
        QVERIFY2(r.err.startsWith(QStringLiteral("facet bench: ") + message), qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("Try 'facet bench --help'")), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(BenchCommandTest)
#include "BenchCommandTest.moc"
