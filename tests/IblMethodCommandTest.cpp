// `facet render --ibl fis|reference` as scripts drive it: the executable run with no display
// server, its --stats and output read back. The methods' accuracy against the ground truth is
// FisGLTest's and ReferenceGLTest's; the command line's bad values are RenderCommandTest's.

#include <QDir>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <cmath>

#include "TestSupport.h"
#include "core/image/Image.h"

using namespace facet;

namespace {

using Result = facet::test::ProcessResult;

Result runFacet(const QStringList& arguments)
{
    return facet::test::runWithoutDisplay(QStringLiteral(FACET_EXECUTABLE), arguments);
}

} // namespace

class IblMethodCommandTest : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    QString path(const QString& name) const { return QDir(m_dir.path()).filePath(name); }

private Q_SLOTS:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    // --ibl reference (the GPU integrator) and --ibl fis (filtered importance sampling): both draw
    // their samples in draws of at most 64; --stats says what ran. 100 samples are two draws (64 +
    // 36): for reference both half-buffers then hold samples and the noise estimate exists; fis is
    // deterministic and prints none. Their accuracy against the ground truth is ReferenceGLTest's
    // and FisGLTest's.
    void sampledMethodRenders_data()
    {
        QTest::addColumn<QString>("method");
        QTest::addColumn<QStringList>("lines");
        QTest::addColumn<QStringList>("absent");
        QTest::newRow("reference") << QStringLiteral("reference")
                                   << QStringList {QStringLiteral("ibl_method: reference\n"),
                                          QStringLiteral("ibl_samples: 100\n"), QStringLiteral("draws: 2\n"),
                                          QStringLiteral("noise: ")}
                                   << QStringList {};
        QTest::newRow("fis") << QStringLiteral("fis")
                             << QStringList {QStringLiteral("ibl_method: fis\n"),
                                    QStringLiteral("ibl_samples: 100\n"), QStringLiteral("draws: 2\n")}
                             << QStringList {QStringLiteral("noise: ")};
    }
    void sampledMethodRenders()
    {
        QFETCH(QString, method);
        QFETCH(QStringList, lines);
        QFETCH(QStringList, absent);
        const QString out = path(method + QStringLiteral(".exr"));
        const Result r = runFacet({QStringLiteral("render"), QStringLiteral("--env"), QStringLiteral("sky"),
            QStringLiteral("--ibl"), method, QStringLiteral("--ibl-samples"), QStringLiteral("100"),
            QStringLiteral("--reference-view"), QStringLiteral("--quality"), QStringLiteral("draft"),
            QStringLiteral("--size"), QStringLiteral("16x16"), QStringLiteral("--stats"),
            QStringLiteral("-o"), out});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        for (const QString& line : lines)
            QVERIFY2(r.out.contains(line), qPrintable(r.out));
        for (const QString& line : absent)
            QVERIFY2(!r.out.contains(line), qPrintable(r.out));
        std::string error;
        const auto image = Image::load(out.toStdString(), &error);
        QVERIFY2(image, error.c_str());
        const glm::vec4 centre = image->at(8, 8);
        QVERIFY2(centre.r > 0.0f && std::isfinite(centre.r), qPrintable(QString::number(double(centre.r))));
        // The split sum stays the default and prints no sample count.
        const Result splitSum
            = runFacet({QStringLiteral("render"), QStringLiteral("--size"), QStringLiteral("8x8"),
                QStringLiteral("--stats"), QStringLiteral("-o"), path(QStringLiteral("ss.exr"))});
        QVERIFY2(splitSum.exitCode == 0, qPrintable(splitSum.err));
        QVERIFY(splitSum.out.contains(QLatin1String("ibl_method: split-sum\n")));
        QVERIFY(!splitSum.out.contains(QLatin1String("ibl_samples:")));
    }

    // Debug views with the sampled methods: one that shows the integrated light takes every
    // sample; one the samples cannot change (base colour) is drawn once, not 100 times.
    void sampledMethodDebugViews_data()
    {
        QTest::addColumn<QString>("method");
        QTest::addColumn<QString>("view");
        QTest::addColumn<QString>("stats");
        for (const QString& method : {QStringLiteral("reference"), QStringLiteral("fis")}) {
            const QByteArray m = method.toUtf8();
            QTest::newRow(m + " ibl-specular")
                << method << QStringLiteral("ibl-specular") << QStringLiteral("ibl_samples: 100\ndraws: 2\n");
            QTest::newRow(m + " white-furnace") << method << QStringLiteral("white-furnace")
                                                << QStringLiteral("ibl_samples: 100\ndraws: 2\n");
            QTest::newRow(m + " base-color")
                << method << QStringLiteral("base-color") << QStringLiteral("ibl_samples: 1\ndraws: 1\n");
            QTest::newRow(m + " roughness")
                << method << QStringLiteral("roughness") << QStringLiteral("ibl_samples: 1\ndraws: 1\n");
        }
    }
    void sampledMethodDebugViews()
    {
        QFETCH(QString, method);
        QFETCH(QString, view);
        QFETCH(QString, stats);
        const Result r = runFacet(
            {QStringLiteral("render"), QStringLiteral("--ibl"), method, QStringLiteral("--ibl-samples"),
                QStringLiteral("100"), QStringLiteral("--view"), view, QStringLiteral("--quality"),
                QStringLiteral("draft"), QStringLiteral("--size"), QStringLiteral("8x8"),
                QStringLiteral("--stats"), QStringLiteral("-o"), path(QStringLiteral("view.exr"))});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(stats), qPrintable(r.out));
    }
};

QTEST_GUILESS_MAIN(IblMethodCommandTest)
#include "IblMethodCommandTest.moc"
