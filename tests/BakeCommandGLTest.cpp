// `facet bake` (app/BakeCommand.h) through the executable: what it writes is what the renderer
// shades with (every prefiltered level and face, the irradiance faces, the SH9 coefficients and
// each visibility term's DFG table, texel for texel against render/IblPrecompute's textures read
// back in this process), ibl.json indexes every file with its conventions, an earlier bake is not
// replaced without --force, and a bake that cannot finish (a full disk) leaves no file of its own.

#include "core/ibl/Environment.h"
#include "render/DfgLut.h"
#include "render/GLTexture.h"
#include "render/HeadlessGLContext.h"
#include "render/IblPrecompute.h"
#include "render/IblSettings.h"
#include "render/IblTextures.h"

#include "FullVolume.h"
#include "TestSupport.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcessEnvironment>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

using namespace facet;
using facet::test::FullVolume;

namespace {

const char* const kFaces[] = {"px", "nx", "py", "ny", "pz", "nz"};

facet::test::ProcessResult bake(const QStringList& arguments)
{
    return facet::test::runWithoutDisplay(
        QStringLiteral(FACET_EXECUTABLE), QStringList {QStringLiteral("bake")} + arguments);
}

// RGBA floats of an EXR written by the bake (missing channels: alpha 1), rows top first.
std::vector<float> readExr(const QString& path, int* width, int* height, QString* problem)
{
    auto input = OIIO::ImageInput::open(path.toStdString());
    if (!input) {
        *problem = path + QStringLiteral(": cannot open it");
        return {};
    }
    const OIIO::ImageSpec& spec = input->spec();
    *width = spec.width;
    *height = spec.height;
    std::vector<float> read(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels));
    if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, read.data())) {
        *problem = path + QStringLiteral(": cannot read it");
        return {};
    }
    std::vector<float> rgba(std::size_t(spec.width) * std::size_t(spec.height) * 4, 1.0f);
    for (std::size_t p = 0; p < std::size_t(spec.width) * std::size_t(spec.height); ++p)
        for (int c = 0; c < std::min(spec.nchannels, 4); ++c)
            rgba[p * 4 + std::size_t(c)] = read[p * std::size_t(spec.nchannels) + std::size_t(c)];
    return rgba;
}

// The largest difference between the file and the texture's level (RGB, or RGBA with `alpha`).
double largestDifference(
    const QString& path, const GLTexture& texture, int face, int level, bool alpha, QString* problem)
{
    int fileWidth = 0;
    int fileHeight = 0;
    const std::vector<float> file = readExr(path, &fileWidth, &fileHeight, problem);
    if (file.empty())
        return INFINITY;
    int width = 0;
    int height = 0;
    const std::vector<float> gpu = readTextureLevel(texture, face, level, &width, &height);
    if (width != fileWidth || height != fileHeight) {
        *problem = QStringLiteral("%1: %2x%3, the texture %4x%5")
                       .arg(path)
                       .arg(fileWidth)
                       .arg(fileHeight)
                       .arg(width)
                       .arg(height);
        return INFINITY;
    }
    double largest = 0.0;
    for (std::size_t i = 0; i < gpu.size(); ++i)
        if (alpha || i % 4 != 3)
            largest = std::max(largest, double(std::abs(gpu[i] - file[i])));
    return largest;
}

std::optional<QJsonObject> readIndex(const QString& folder)
{
    QFile file(folder + QStringLiteral("/ibl.json"));
    if (!file.open(QIODevice::ReadOnly))
        return std::nullopt;
    const QJsonDocument document = QJsonDocument::fromJson(file.readAll());
    if (!document.isObject())
        return std::nullopt;
    return document.object();
}

} // namespace

class BakeCommandGLTest : public QObject {
    Q_OBJECT
public:
    static void initMain()
    {
        facet::test::forgetDisplayServer();
        FullVolume::isolateMounts();
    }

private Q_SLOTS:
    void writesWhatTheRendererShadesWith_data()
    {
        QTest::addColumn<QString>("environment");
        QTest::addColumn<QString>("quality");
        QTest::addColumn<int>("iblSize"); // 0: the preset's
        QTest::addColumn<int>("cubeSize"); // 0: the preset's (grown to iblSize)
        QTest::addColumn<int>("samples"); // 0: the preset's
        QTest::newRow("studio, draft") << QStringLiteral("studio") << QStringLiteral("draft") << 0 << 0 << 0;
        QTest::newRow("sky, default") << QStringLiteral("sky") << QStringLiteral("default") << 0 << 0 << 0;
        QTest::newRow("studio, draft, --ibl-size 32")
            << QStringLiteral("studio") << QStringLiteral("draft") << 32 << 0 << 0;
        QTest::newRow("studio, draft, --cube-size 64")
            << QStringLiteral("studio") << QStringLiteral("draft") << 0 << 64 << 0;
        QTest::newRow("studio, draft, --samples 16")
            << QStringLiteral("studio") << QStringLiteral("draft") << 0 << 0 << 16;
        QTest::newRow("studio, --ibl-size 64 --cube-size 64 --samples 32 (cmgen's work)")
            << QStringLiteral("studio") << QStringLiteral("default") << 64 << 64 << 32;
    }

    // Each option alone and bad values: exit 2 (a usage error), the option and the value named.
    void refusesBadSettings_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("message");
        QTest::newRow("--ibl-size 8") << QStringList {QStringLiteral("--ibl-size"),
            QStringLiteral("8")} << QStringLiteral("--ibl-size: '8' is not a whole number from 16 to 2048");
        QTest::newRow("--cube-size x") << QStringList {QStringLiteral("--cube-size"),
            QStringLiteral("x")} << QStringLiteral("--cube-size: 'x' is not a whole number from 16 to 2048");
        QTest::newRow("--cube-size below --ibl-size")
            << QStringList {QStringLiteral("--ibl-size"), QStringLiteral("128"),
                   QStringLiteral("--cube-size"), QStringLiteral("64")}
            << QStringLiteral("--cube-size: 64 is smaller than the prefiltered cube (128)");
        QTest::newRow("--samples 0") << QStringList {QStringLiteral("--samples"),
            QStringLiteral("0")} << QStringLiteral("--samples: '0' is not a whole number from 1 to 65536");
        QTest::newRow("--samples 1e9")
            << QStringList {QStringLiteral("--samples"), QStringLiteral("1000000000")}
            << QStringLiteral("--samples: '1000000000' is not a whole number");
    }

    void refusesBadSettings()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, message);
        QTemporaryDir out;
        const facet::test::ProcessResult r
            = bake(QStringList {QStringLiteral("studio"), QStringLiteral("-o"), out.path()} + arguments);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QCOMPARE(QDir(out.path()).entryList(QDir::Files), QStringList {});
    }

    void writesWhatTheRendererShadesWith()
    {
        QFETCH(QString, environment);
        QFETCH(QString, quality);
        QFETCH(int, iblSize);
        QFETCH(int, cubeSize);
        QFETCH(int, samples);
        QTemporaryDir out;
        QStringList arguments {
            environment, QStringLiteral("--quality"), quality, QStringLiteral("-o"), out.path()};
        if (iblSize > 0)
            arguments << QStringLiteral("--ibl-size") << QString::number(iblSize);
        if (cubeSize > 0)
            arguments << QStringLiteral("--cube-size") << QString::number(cubeSize);
        if (samples > 0)
            arguments << QStringLiteral("--samples") << QString::number(samples);
        const facet::test::ProcessResult r = bake(arguments);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.startsWith(QStringLiteral("facet bake: wrote ")), qPrintable(r.out));

        const std::optional<QJsonObject> index = readIndex(out.path());
        QVERIFY(index);
        QCOMPARE(index->value(QStringLiteral("format")).toString(), QStringLiteral("facet-ibl-bake"));
        QCOMPARE(index->value(QStringLiteral("version")).toInt(), 1);
        const QJsonObject prefiltered = index->value(QStringLiteral("prefiltered")).toObject();
        const QJsonObject irradiance = index->value(QStringLiteral("irradiance")).toObject();
        const QJsonObject dfg = index->value(QStringLiteral("dfg")).toObject();

        // The same IBL in this process, as the renderer makes it.
        std::string error;
        auto context = HeadlessGLContext::create(&error);
        QVERIFY2(context, error.c_str());
        IblSettings settings = *IblSettings::preset(quality.toStdString());
        if (iblSize > 0) {
            settings.prefilterSize = iblSize;
            settings.cubeSize = std::max(settings.cubeSize, iblSize);
        }
        if (cubeSize > 0)
            settings.cubeSize = cubeSize;
        if (samples > 0)
            settings.prefilterSamples = samples;
        IblPrecompute precompute(QString(), /*useDiskCache=*/false);
        const std::optional<Environment> env = Environment::fromSpec(environment.toStdString(), &error);
        QVERIFY2(env, error.c_str());
        const auto ibl = precompute.prepare(*env, settings, nullptr, &error);
        QVERIFY2(ibl, error.c_str());
        if (iblSize > 0)
            QCOMPARE(ibl->prefilteredSize, iblSize);
        if (cubeSize > 0)
            QCOMPARE(ibl->environmentSize, cubeSize);
        // What ran, as ibl.json says (a bake with another cube or samples differs texel for texel).
        QCOMPARE(index->value(QStringLiteral("settings"))
                     .toObject()
                     .value(QStringLiteral("environmentCubeSize"))
                     .toInt(),
            ibl->environmentSize);
        QCOMPARE(prefiltered.value(QStringLiteral("samples")).toInt(), settings.prefilterSamples);

        const int levels = ibl->prefilteredMipLevels;
        QCOMPARE(prefiltered.value(QStringLiteral("levels")).toInt(), levels);
        QCOMPARE(prefiltered.value(QStringLiteral("size")).toInt(), ibl->prefilteredSize);
        const QJsonArray files = prefiltered.value(QStringLiteral("files")).toArray();
        const QJsonArray roughness = prefiltered.value(QStringLiteral("levelRoughness")).toArray();
        QCOMPARE(files.size(), levels);
        QCOMPARE(roughness.size(), levels);
        QString problem;
        for (int level = 0; level < levels; ++level) {
            QCOMPARE(roughness[level].toDouble(), roughnessFromLod(level, levels));
            const QJsonArray faces = files[level].toArray();
            QCOMPARE(faces.size(), 6);
            for (int face = 0; face < 6; ++face) {
                const QString name = faces[face].toString();
                QCOMPARE(name,
                    QStringLiteral("prefiltered_m%1_%2.exr").arg(level).arg(QLatin1String(kFaces[face])));
                const double difference
                    = largestDifference(out.filePath(name), *ibl->prefiltered, face, level, false, &problem);
                QVERIFY2(difference == 0.0,
                    qPrintable(QStringLiteral("%1: %2 %3").arg(name).arg(difference).arg(problem)));
            }
        }
        const QJsonArray irradianceFiles = irradiance.value(QStringLiteral("files")).toArray();
        QCOMPARE(irradianceFiles.size(), 6);
        for (int face = 0; face < 6; ++face) {
            const QString name = irradianceFiles[face].toString();
            const double difference
                = largestDifference(out.filePath(name), *ibl->irradiance, face, 0, false, &problem);
            QVERIFY2(difference == 0.0,
                qPrintable(QStringLiteral("%1: %2 %3").arg(name).arg(difference).arg(problem)));
        }
        const QJsonArray sh = irradiance.value(QStringLiteral("sh9"))
                                  .toObject()
                                  .value(QStringLiteral("coefficients"))
                                  .toArray();
        QCOMPARE(sh.size(), 9);
        for (int i = 0; i < 9; ++i)
            for (int c = 0; c < 3; ++c)
                QCOMPARE(float(sh[i].toArray()[c].toDouble()), ibl->irradianceSH[std::size_t(i)][c]);

        const QJsonArray tables = dfg.value(QStringLiteral("tables")).toArray();
        QCOMPARE(tables.size(), kVisibilityCount);
        for (int v = 0; v < kVisibilityCount; ++v) {
            const QJsonObject table = tables[v].toObject();
            QCOMPARE(table.value(QStringLiteral("visibility")).toString(),
                QString::fromLatin1(toString(Visibility(v))));
            const auto lut = precompute.dfgTable(settings, Visibility(v), nullptr, &error);
            QVERIFY2(lut, error.c_str());
            QCOMPARE(dfg.value(QStringLiteral("size")).toInt(), lut->size);
            const QString name = table.value(QStringLiteral("file")).toString();
            const double difference
                = largestDifference(out.filePath(name), *lut->texture, 0, 0, true, &problem);
            QVERIFY2(difference == 0.0,
                qPrintable(QStringLiteral("%1: %2 %3").arg(name).arg(difference).arg(problem)));
        }
        // Nothing but the files the index names.
        const int expected = levels * 6 + 6 + kVisibilityCount + 1;
        QCOMPARE(QDir(out.path()).entryList(QDir::Files | QDir::Hidden).size(), expected);
    }

    // An earlier bake stays unless --force; with it, the bake is replaced.
    void replacesOnlyWithForce()
    {
        QTemporaryDir out;
        const QStringList arguments {QStringLiteral("studio"), QStringLiteral("--quality"),
            QStringLiteral("draft"), QStringLiteral("-o"), out.path()};
        facet::test::ProcessResult r = bake(arguments);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QFile index(out.filePath(QStringLiteral("ibl.json")));
        QVERIFY(index.open(QIODevice::ReadOnly));
        const QByteArray studio = index.readAll();
        index.close();

        r = bake({QStringLiteral("sky"), QStringLiteral("--quality"), QStringLiteral("draft"),
            QStringLiteral("-o"), out.path()});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("exists (use --force")) && r.err.contains(out.path()),
            qPrintable(r.err));
        QVERIFY(index.open(QIODevice::ReadOnly));
        QCOMPARE(index.readAll(), studio);
        index.close();

        r = bake({QStringLiteral("sky"), QStringLiteral("--quality"), QStringLiteral("draft"),
            QStringLiteral("--force"), QStringLiteral("-o"), out.path()});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(index.open(QIODevice::ReadOnly));
        QVERIFY(index.readAll().contains("\"source\": \"sky\""));
    }

    // Bad input and a folder that cannot take the bake: exit 1, the file named, nothing of the
    // bake left behind.
    void failsWithoutLeavingFiles()
    {
        QTemporaryDir dir;
        facet::test::ProcessResult r = bake({dir.filePath(QStringLiteral("missing.exr")),
            QStringLiteral("-o"), dir.filePath(QStringLiteral("out"))});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("missing.exr")), qPrintable(r.err));

        QFile notAFolder(dir.filePath(QStringLiteral("file")));
        QVERIFY(notAFolder.open(QIODevice::WriteOnly));
        notAFolder.close();
        r = bake({QStringLiteral("studio"), QStringLiteral("-o"), notAFolder.fileName()});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("is not a folder")), qPrintable(r.err));

        // A volume that takes part of the bake (a draft bake is about 168 KiB): the files written
        // before the disk filled go again.
        FullVolume volume(QString(), 96 * 1024);
        FACET_REQUIRE_FULL_VOLUME(volume);
        r = bake({QStringLiteral("studio"), QStringLiteral("--quality"), QStringLiteral("draft"),
            QStringLiteral("-o"), volume.path()});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(volume.path()) && r.err.contains(QStringLiteral("No space left on device")),
            qPrintable(r.err));
        QVERIFY2(
            !r.err.contains(QStringLiteral("prefiltered_m0_px.exr")), qPrintable(r.err)); // it got that far
        QCOMPARE(volume.entries(), QStringList {});
    }
};

QTEST_GUILESS_MAIN(BakeCommandGLTest)
#include "BakeCommandGLTest.moc"
