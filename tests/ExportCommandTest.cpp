// `facet export` (app/ExportCommand.h) as a user runs it: a project of two textured materials and
// one of constants, written with map files of its own. The dry run lists and writes nothing; a
// built-in and a user template write the files their patterns name, one material or all;
// nothing is replaced without --force; a missing map, a bad template, a material that is not
// there, a file in place of the folder, a read-only folder and a full disk are refused with the
// file named, leaving no file of the export behind.

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <cmath>

#include <OpenImageIO/imageio.h>

#include "FullVolume.h"
#include "TestAssets.h"
#include "TestSupport.h"
#include "core/image/Image.h"
#include "core/project/Project.h"

using facet::test::FullVolume;

namespace {

facet::test::ProcessResult runExport(const QStringList& arguments)
{
    return facet::test::runWithoutDisplay(
        QStringLiteral(FACET_EXECUTABLE), QStringList {QStringLiteral("export")} + arguments);
}

QStringList unrealFiles(const char* material)
{
    QStringList files;
    for (const char* map : {"BC", "N", "ORM"})
        files.append(QStringLiteral("T_%1_%2.png").arg(QLatin1String(material), QLatin1String(map)));
    return files;
}

QStringList sorted(QStringList list)
{
    list.sort();
    return list;
}

QStringList entries(const QString& folder)
{
    return QDir(folder).entryList(QDir::Files | QDir::Hidden, QDir::Name);
}

int imageWidth(const QString& path)
{
    auto input = OIIO::ImageInput::open(path.toStdString());
    return input ? input->spec().width : -1;
}

} // namespace

class ExportCommandTest : public QObject {
    Q_OBJECT
public:
    static void initMain()
    {
        facet::test::forgetDisplayServer();
        FullVolume::isolateMounts();
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_project = facet::test::writeTexturedProject(m_dir.path());
        QVERIFY(!m_project.isEmpty());
    }

    void dryRunWritesNothing()
    {
        const QString out = m_dir.filePath(QStringLiteral("dry"));
        const facet::test::ProcessResult r = runExport({m_project, QStringLiteral("--format"),
            QStringLiteral("unity-hdrp"), QStringLiteral("--dry-run"), QStringLiteral("-o"), out});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains(QStringLiteral("Brick Wall (Unity HDRP (Lit)): 3 files"))
                && r.out.contains(
                    QStringLiteral("  Brick_Wall_MaskMap.png  32x16  RGBA 8-bit linear: R metallic, G "
                                   "occlusion, B constant 1.000, A 1 - roughness"))
                && r.out.contains(QStringLiteral("  Gold_BaseMap.png  1x1  RGBA 8-bit sRGB"))
                && r.out.contains(QStringLiteral("(no Emissive: the material does not use it)")),
            qPrintable(r.out));
        QVERIFY(!QFileInfo::exists(out));
    }

    void writesEverySet_data()
    {
        QTest::addColumn<QStringList>("extra");
        QTest::addColumn<QStringList>("files");
        QTest::addColumn<int>("brickWidth"); // of the brick's first file; -1 when not written
        QTest::newRow("all materials")
            << QStringList {}
            << sorted(unrealFiles("Brick_Wall") + unrealFiles("Steel") + unrealFiles("Gold")) << 32;
        QTest::newRow("--material by name")
            << facet::test::strings({"--material", "Steel"}) << sorted(unrealFiles("Steel")) << -1;
        QTest::newRow("--material by index")
            << facet::test::strings({"--material", "0"}) << sorted(unrealFiles("Brick_Wall")) << 32;
        QTest::newRow("--size 8") << facet::test::strings({"--material", "Brick Wall", "--size", "8"})
                                  << sorted(unrealFiles("Brick_Wall")) << 8;
        QTest::newRow("--bit-depth 16") << facet::test::strings({"--material", "Gold", "--bit-depth", "16"})
                                        << sorted(unrealFiles("Gold")) << -1;
    }

    void writesEverySet()
    {
        QFETCH(QStringList, extra);
        QFETCH(QStringList, files);
        QFETCH(int, brickWidth);
        QTemporaryDir out;
        const facet::test::ProcessResult r
            = runExport(QStringList {m_project, QStringLiteral("--format"), QStringLiteral("unreal"),
                            QStringLiteral("-o"), out.path()}
                + extra);
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.startsWith(QStringLiteral("facet export: wrote %1 files").arg(files.size())),
            qPrintable(r.out));
        QCOMPARE(entries(out.path()), files);
        if (brickWidth > 0)
            QCOMPARE(imageWidth(out.filePath(QStringLiteral("T_Brick_Wall_BC.png"))), brickWidth);
        if (extra.contains(QStringLiteral("--bit-depth"))) {
            auto input = OIIO::ImageInput::open(out.filePath(QStringLiteral("T_Gold_ORM.png")).toStdString());
            QVERIFY(input);
            QCOMPARE(input->spec().format, OIIO::TypeDesc(OIIO::TypeDesc::UINT16));
        }
    }

    void userTemplate()
    {
        const QString templatePath = m_dir.filePath(QStringLiteral("studio-engine.json"));
        QVERIFY(facet::test::writeText(templatePath,
            R"({"format": "facet-export-template", "version": 1, "name": "Studio engine",
                "fileName": "{template}_{material}_{map}_{size}",
                "outputs": [{"map": "rough", "channels": ["roughness"], "bitDepth": 32, "fileFormat": "exr"}]})"));
        QTemporaryDir out;
        const facet::test::ProcessResult r = runExport({m_project, QStringLiteral("--format"), templatePath,
            QStringLiteral("--material"), QStringLiteral("Brick Wall"), QStringLiteral("-o"), out.path()});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(
            entries(out.path()), QStringList {QStringLiteral("studio-engine_Brick_Wall_rough_32x16.exr")});
    }

    // --format gltf and glb: the asset where -o says (a folder: named after the input), on the
    // project's mesh or --mesh, validator-clean.
    void writesGltfAssets_data()
    {
        QTest::addColumn<QStringList>("extra");
        QTest::addColumn<QString>("asset"); // relative to the output folder
        QTest::addColumn<int>("files");
        QTest::newRow("gltf into a folder")
            << facet::test::strings({"--format", "gltf"}) << QStringLiteral("walls.gltf")
            << 1 + 3 + 2 + 1; // the .bin, Brick's 3 textures, Steel's 2, the asset
        QTest::newRow("glb by name, shader ball")
            << facet::test::strings({"--format", "glb", "--mesh", "shaderball", "-o", "%/ball.glb"})
            << QStringLiteral("ball.glb") << 1;
        QTest::newRow("one material, 16-bit") << facet::test::strings(
            {"--format", "gltf", "--material", "Steel", "--bit-depth", "16", "-o", "%/steel.gltf"})
                                              << QStringLiteral("steel.gltf") << 4;
    }

    void writesGltfAssets()
    {
        QFETCH(QStringList, extra);
        QFETCH(QString, asset);
        QFETCH(int, files);
        QTemporaryDir out;
        QStringList arguments = QStringList {m_project} + extra;
        if (!extra.contains(QStringLiteral("-o")))
            arguments += QStringList {QStringLiteral("-o"), out.path()};
        for (QString& argument : arguments)
            argument.replace(QLatin1Char('%'), out.path());
        const facet::test::ProcessResult r = runExport(arguments);
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.startsWith(QStringLiteral("facet export: wrote %1").arg(out.filePath(asset))),
            qPrintable(r.out + r.err));
        QCOMPARE(entries(out.path()).size(), files);
        FACET_REQUIRE_VALID_GLTF(out.filePath(asset));
    }

    // The exported asset renders as the original: the showcase still life (five materials:
    // textures embedded, BLEND glass, an emissive lamp), rendered by `facet render` before and
    // after a glb round trip. Measured at 160x120: relative RMSE 3.4e-6, worst pixel 5.5e-4 (a
    // half-float step), from the 8-bit re-encoding of the textures.
    void gltfRendersAsTheOriginal()
    {
        QTemporaryDir out;
        const QString original = out.filePath(QStringLiteral("showcase.glb"));
        QString error;
        QVERIFY2(facet::test::writeShowcaseAsset(original, &error), qPrintable(error));
        const QString exported = out.filePath(QStringLiteral("exported.glb"));
        facet::test::ProcessResult r = runExport(
            {original, QStringLiteral("--format"), QStringLiteral("glb"), QStringLiteral("-o"), exported});
        QCOMPARE(r.exitCode, 0);
        FACET_REQUIRE_VALID_GLTF(exported);
        std::vector<facet::Image> images;
        for (const QString& asset : {original, exported}) {
            const QString image = asset + QStringLiteral(".exr");
            r = facet::test::runWithoutDisplay(QStringLiteral(FACET_EXECUTABLE),
                {QStringLiteral("render"), asset, QStringLiteral("--size"), QStringLiteral("160x120"),
                    QStringLiteral("-o"), image});
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
            std::string problem;
            std::optional<facet::Image> loaded = facet::Image::load(image.toStdString(), &problem);
            QVERIFY2(loaded, problem.c_str());
            images.push_back(std::move(*loaded));
        }
        double squaredError = 0.0, squaredTruth = 0.0, worst = 0.0;
        for (std::size_t i = 0; i < images[0].pixelCount(); ++i) {
            for (int c = 0; c < 3; ++c) {
                const double a = images[0].data()[i][c];
                const double b = images[1].data()[i][c];
                squaredError += (a - b) * (a - b);
                squaredTruth += a * a;
                worst = std::max(worst, std::abs(a - b) / std::max(a, 0.05));
            }
        }
        const double relativeRmse = std::sqrt(squaredError / squaredTruth);
        qInfo("exported vs original: relative RMSE %.2e, worst pixel %.2e", relativeRmse, worst);
        QVERIFY2(relativeRmse < 1e-3 && worst < 5e-3,
            qPrintable(QStringLiteral("%1 %2").arg(relativeRmse).arg(worst)));
    }

    void replacesOnlyWithForce()
    {
        QTemporaryDir out;
        const QString steelOrm = out.filePath(QStringLiteral("T_Steel_ORM.png"));
        QVERIFY(facet::test::writeText(steelOrm, "an artist's file"));
        const QStringList arguments = {m_project, QStringLiteral("--format"), QStringLiteral("unreal"),
            QStringLiteral("-o"), out.path()};
        facet::test::ProcessResult r = runExport(arguments);
        QCOMPARE(r.exitCode, 1);
        QCOMPARE(
            r.err, QStringLiteral("facet export: %1: exists (use --force to replace it)\n").arg(steelOrm));
        QCOMPARE(
            entries(out.path()), QStringList {QStringLiteral("T_Steel_ORM.png")}); // checked before writing
        QCOMPARE(facet::test::fileBytes(steelOrm), QByteArray("an artist's file"));
        r = runExport(arguments + QStringList {QStringLiteral("--force")});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(imageWidth(steelOrm), 8);
    }

    void badInputs_data()
    {
        QTest::addColumn<QStringList>("arguments"); // "@" stands for the project, "%" for the folder
        QTest::addColumn<QString>("message");
        QTest::newRow("no such material")
            << facet::test::strings({"@", "--format", "godot", "--material", "Copper", "-o", "%"})
            << QStringLiteral(
                   "facet export: --material: 'Copper' is not a material of the input (its materials: "
                   "Brick Wall, Steel, Gold; or an index from 0 to 2)\n");
        QTest::newRow("index out of range")
            << facet::test::strings({"@", "--format", "godot", "--material", "3", "-o", "%"})
            << QStringLiteral("facet export: --material: '3' is not a material");
        QTest::newRow("missing template file")
            << facet::test::strings({"@", "--format", "%/none.json", "-o", "%"})
            << QStringLiteral("facet export: %/none.json: no such file\n");
        QTest::newRow("no such project")
            << facet::test::strings({"%/none.json", "--format", "godot", "-o", "%"})
            << QStringLiteral("facet export: ");
        QTest::newRow("32 bits in a PNG")
            << facet::test::strings({"@", "--format", "unreal", "--bit-depth", "32", "-o", "%"})
            << QStringLiteral("facet export: material 'Brick Wall': unreal's BC is png, which cannot hold "
                              "32-bit channels");
    }

    void badInputs()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, message);
        QTemporaryDir out;
        for (QString& argument : arguments) {
            argument.replace(QLatin1Char('@'), m_project);
            argument.replace(QLatin1Char('%'), out.path());
        }
        message.replace(QLatin1Char('%'), out.path());
        const facet::test::ProcessResult r = runExport(arguments);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.startsWith(message), qPrintable(r.err));
        QCOMPARE(entries(out.path()), QStringList {});
    }

    void missingMapIsNamed()
    {
        QTemporaryDir copy;
        const QString project = facet::test::writeTexturedProject(copy.path());
        QVERIFY(QFile::remove(copy.filePath(QStringLiteral("steel_rough.png"))));
        const QString out = copy.filePath(QStringLiteral("out"));
        const facet::test::ProcessResult r = runExport(
            {project, QStringLiteral("--format"), QStringLiteral("unreal"), QStringLiteral("-o"), out});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("steel_rough.png")), qPrintable(r.err));
        QVERIFY(!QFileInfo::exists(out) || entries(out).isEmpty());
    }

    void unwritableFolders()
    {
        // A file where the folder should be.
        const QString file = m_dir.filePath(QStringLiteral("not-a-folder"));
        QVERIFY(facet::test::writeText(file, "x"));
        facet::test::ProcessResult r = runExport(
            {m_project, QStringLiteral("--format"), QStringLiteral("unreal"), QStringLiteral("-o"), file});
        QCOMPARE(r.exitCode, 1);
        QCOMPARE(r.err, QStringLiteral("facet export: %1: is not a folder\n").arg(file));

        // A read-only folder (a read-only mount: root ignores permission bits).
        {
            FullVolume readOnly(QString(), 256 * 1024);
            FACET_REQUIRE_FULL_VOLUME(readOnly);
            QVERIFY2(readOnly.makeReadOnly(), qPrintable(readOnly.problem()));
            r = runExport({m_project, QStringLiteral("--format"), QStringLiteral("unreal"),
                QStringLiteral("-o"), readOnly.path()});
            QCOMPARE(r.exitCode, 1);
            // The set's staging folder is the first thing written (core/support/FileSet.h): the folder is
            // named.
            QVERIFY2(r.err.contains(
                         readOnly.path() + QStringLiteral(": cannot make a folder to write the new files in"))
                    && r.err.contains(QStringLiteral("Read-only file system")),
                qPrintable(r.err));
            QCOMPARE(readOnly.entries(), QStringList {});
        }

        // A volume that takes part of the export: the files written before the disk filled go.
        FullVolume volume(QString(), 64 * 1024);
        FACET_REQUIRE_FULL_VOLUME(volume);
        // Fill all but a few KiB (tmpfs takes 4 KiB pages): room for a file or two, not the set.
        QVERIFY(facet::test::writeText(
            volume.filePath(QStringLiteral("ballast")), QByteArray(volume.freeBytes() - 6 * 1024, 'b')));
        r = runExport({m_project, QStringLiteral("--format"), QStringLiteral("unreal"),
            QStringLiteral("--size"), QStringLiteral("64"), QStringLiteral("-o"), volume.path()});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(volume.path()) && r.err.contains(QStringLiteral("No space left on device")),
            qPrintable(r.err));
        QCOMPARE(volume.entries(), QStringList {QStringLiteral("ballast")});
    }

private:
    QTemporaryDir m_dir;
    QString m_project;
};

QTEST_GUILESS_MAIN(ExportCommandTest)
#include "ExportCommandTest.moc"
