// core/export/TextureSetExport with user templates and options, on the test material of
// support/TextureSetTestMaterial.h (its maps hold a distinct value per channel), each file read
// back with OpenImageIO: bit depths and formats as declared (PNG 16, TIFF 16/32, EXR half/float,
// TGA 8), colour-space tags; sizes (the largest map's, --size with its aspect, a filtered
// downsample, a material of constants as 1x1); texel placement (no row flip, UV transforms baked);
// plan-time refusals; the dry run's description. The built-in templates' layouts, round trips and
// optional outputs: tests/TextureSetExportTest.cpp.

#include <cmath>
#include <optional>
#include <string>

#include <QDir>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <OpenImageIO/imageio.h>

#include "TestAssets.h"
#include "TestSupport.h"
#include "TextureSetTestMaterial.h"
#include "core/export/ExportTemplate.h"
#include "core/export/TextureSetExport.h"
#include "core/image/MapImage.h"
#include "core/image/ToneMap.h"

using namespace facet;
using facet::test::ReadBack;
using facet::test::readBack;
using facet::test::TestMaterial;
using facet::test::writeSet;

namespace {

std::optional<ExportTemplate> templateFrom(const QByteArray& json, std::string* error)
{
    const QJsonDocument document = QJsonDocument::fromJson(json);
    return ExportTemplate::fromJson(document.object(), error);
}

} // namespace

class TextureSetFormatsTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    // A material of constants: 1x1 files holding its factors (or --size's size).
    void constantsOnly()
    {
        TestMaterial test(false);
        Material constant;
        constant.name = "Gold";
        constant.setBaseColor(glm::dvec3(1.0, 0.766, 0.336));
        constant.setFactor(MapSlot::Metallic, 1.0);
        constant.setFactor(MapSlot::Roughness, 0.3);
        test.material = constant;
        const std::optional<ExportTemplate> t = ExportTemplate::builtin("gltf-textures");
        std::string error;
        for (const int size : {0, 8}) {
            TextureSetOptions options;
            options.size = size;
            const std::optional<TextureSetPlan> plan = planTextureSet(*t, constant, {}, options, &error);
            QVERIFY2(plan, error.c_str());
            QTemporaryDir dir;
            QVERIFY2(writeSet(*plan, test, dir.path(), &error), error.c_str());
            const std::optional<ReadBack> orm
                = readBack(dir.filePath(QStringLiteral("Gold_occlusionRoughnessMetallic.png")));
            QVERIFY(orm);
            QCOMPARE(orm->width, size == 0 ? 1 : 8);
            QCOMPARE(orm->height, size == 0 ? 1 : 8);
            QCOMPARE(orm->values[0], 1.0f); // no occlusion map: 1
            QVERIFY(std::abs(orm->values[1] - 0.3) <= 0.5 / 255.0 + 1e-6);
            QCOMPARE(orm->values[2], 1.0f);
            const std::optional<ReadBack> base = readBack(dir.filePath(QStringLiteral("Gold_baseColor.png")));
            QCOMPARE(qRound(base->values[1] * 255.0f), qRound(tonemap::linearToSrgb(0.766) * 255.0));
            QCOMPARE(base->values[3], 1.0f);
            const std::optional<ReadBack> normal = readBack(dir.filePath(QStringLiteral("Gold_normal.png")));
            QCOMPARE(qRound(normal->values[0] * 255.0f), 128); // (0, 0, 1) stored as (0.5, 0.5, 1)
            QCOMPARE(qRound(normal->values[1] * 255.0f), 128);
            QCOMPARE(normal->values[2], 1.0f);
        }
    }

    // Texels land where the material has them: the file's top row is v = 1 (no flip), a UV
    // transform is baked in (scale 2 repeats the map twice), a smaller map is magnified.
    void texelPlacement()
    {
        // A 4x2 base colour map, one texel per (x, row) with its own red value; row 0 of the
        // Image is its top row, v = 1.
        Image image(4, 2);
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 4; ++x)
                image.at(x, y) = glm::vec4(float(y * 4 + x) * 30.0f / 255.0f, 0.0f, 0.0f, 1.0f);
        TestMaterial test(false);
        test.base = MapImage::fromImage(image, MapLayout::Rgba, MapSampleType::UInt8);
        test.material.map(MapSlot::BaseColor).colorSpace = ColorEncoding::Linear;
        test.material.map(MapSlot::Emissive).path.clear();
        for (const MapSlot slot :
            {MapSlot::Normal, MapSlot::Occlusion, MapSlot::Roughness, MapSlot::Metallic})
            test.material.map(slot).path.clear();
        const QByteArray json = test::exportTemplateJson(
            R"({"map": "R", "channels": ["baseColor.r"], "colorSpace": "linear"})");
        std::string error;
        const std::optional<ExportTemplate> t = templateFrom(json, &error);
        QVERIFY2(t, error.c_str());

        const auto exported = [&](const TestMaterial& m, ReadBack* out) {
            std::optional<TextureSetPlan> plan = planTextureSet(*t, m.material, m.images(), {}, &error);
            QTemporaryDir dir;
            if (!plan || !writeSet(*plan, m, dir.path(), &error))
                return false;
            *out = *readBack(dir.filePath(QStringLiteral("Test_Mat_R.png")));
            return true;
        };
        ReadBack file;
        QVERIFY2(exported(test, &file), error.c_str());
        QCOMPARE(file.width, 4);
        QCOMPARE(file.height, 2);
        for (int i = 0; i < 8; ++i)
            QCOMPARE(qRound(file.values[std::size_t(i)] * 255.0f), i * 30);

        test.material.map(MapSlot::BaseColor).uv.scale = glm::dvec2(2.0, 1.0);
        QVERIFY2(exported(test, &file), error.c_str());
        // u' = 2u: the file's texel x reads the map at column 2x + 0.5 -> between two texels.
        for (int x = 0; x < 4; ++x) {
            const double mapX = std::fmod(2.0 * (x + 0.5) - 0.5, 4.0);
            const int x0 = int(std::floor(mapX));
            const double f = mapX - x0;
            const double expected = ((1.0 - f) * (x0 % 4) + f * ((x0 + 1) % 4)) * 30.0;
            QCOMPARE(qRound(file.values[std::size_t(x)] * 255.0f), qRound(expected));
        }
    }

    // The set's size is the largest map's; --size keeps the aspect; a downsample is filtered.
    void sizes()
    {
        // A 64x32 checker of 0 and 1 in the roughness map (linear), the other maps 4x4.
        Image checker(64, 32);
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 64; ++x)
                checker.at(x, y) = glm::vec4(glm::vec3(float((x + y) % 2)), 1.0f);
        TestMaterial test(false);
        test.packed = MapImage::fromImage(checker, MapLayout::Rgb, MapSampleType::UInt8);
        const std::optional<ExportTemplate> t = ExportTemplate::builtin("unreal");
        std::string error;
        std::optional<TextureSetPlan> plan = planTextureSet(*t, test.material, test.images(), {}, &error);
        QVERIFY2(plan, error.c_str());
        for (const PlannedTexture& file : plan->files) {
            QCOMPARE(file.width, 64);
            QCOMPARE(file.height, 32);
        }
        TextureSetOptions options;
        options.size = 16;
        plan = planTextureSet(*t, test.material, test.images(), options, &error);
        QCOMPARE(plan->files[0].width, 16);
        QCOMPARE(plan->files[0].height, 8);
        QCOMPARE(QString::fromStdString(plan->files[0].fileName), QStringLiteral("T_Test_Mat_BC.png"));
        QTemporaryDir dir;
        QVERIFY2(writeSet(*plan, test, dir.path(), &error), error.c_str());
        const std::optional<ReadBack> orm = readBack(dir.filePath(QStringLiteral("T_Test_Mat_ORM.png")));
        QVERIFY(orm);
        QCOMPARE(orm->width, 16);
        QCOMPARE(orm->height, 8);
        // A point-sampled 4:1 reduction of a one-texel checker is all 0 or all 1; a filter gives
        // the checker's mean, 0.5, everywhere.
        for (int p = 0; p < 16 * 8; ++p) {
            const float roughness = orm->values[std::size_t(p * 3 + 1)];
            if (std::abs(roughness - 0.5f) > 0.02f)
                QFAIL(qPrintable(QStringLiteral("texel %1: roughness %2, the checker's mean is 0.5")
                                     .arg(p)
                                     .arg(roughness)));
        }
    }

    // User templates: each bit depth and format as declared, colour tags, tokens.
    void userTemplateFormats_data()
    {
        QTest::addColumn<QByteArray>("output");
        QTest::addColumn<QString>("fileName");
        QTest::addColumn<int>("type"); // OIIO::TypeDesc::BASETYPE
        QTest::addColumn<QString>("colorSpace");
        QTest::addColumn<int>("channels");
        QTest::newRow("png 16 linear grey")
            << QByteArray(R"({"map": "R", "channels": ["roughness"], "bitDepth": 16})")
            << QStringLiteral("Test_Mat_R.png") << int(OIIO::TypeDesc::UINT16) << QStringLiteral("Linear")
            << 1;
        QTest::newRow("png 8 sRGB grey+alpha")
            << QByteArray(
                   R"({"map": "BA", "channels": ["baseColor.g", "baseColor.a"], "colorSpace": "srgb"})")
            << QStringLiteral("Test_Mat_BA.png") << int(OIIO::TypeDesc::UINT8) << QStringLiteral("sRGB") << 2;
        QTest::newRow("tiff 16") << QByteArray(
            R"({"map": "M", "channels": ["metallic", "roughness"], "bitDepth": 16, "fileFormat": "tiff"})")
                                 << QStringLiteral("Test_Mat_M.tif") << int(OIIO::TypeDesc::UINT16)
                                 << QStringLiteral("Linear") << 2;
        QTest::newRow("tiff 32 float")
            << QByteArray(R"({"map": "M", "channels": ["metallic"], "bitDepth": 32, "fileFormat": "tiff"})")
            << QStringLiteral("Test_Mat_M.tif") << int(OIIO::TypeDesc::FLOAT) << QStringLiteral("Linear")
            << 1;
        QTest::newRow("exr half") << QByteArray(
            R"({"map": "E", "channels": ["emissive.r", "emissive.g", "emissive.b"], "bitDepth": 16, "fileFormat": "exr"})")
                                  << QStringLiteral("Test_Mat_E.exr") << int(OIIO::TypeDesc::HALF)
                                  << QStringLiteral("Linear") << 3;
        QTest::newRow("exr float") << QByteArray(
            R"({"map": "N", "channels": ["normal.x", "normal.y", "normal.z", 0.25], "bitDepth": 32, "fileFormat": "exr"})")
                                   << QStringLiteral("Test_Mat_N.exr") << int(OIIO::TypeDesc::FLOAT)
                                   << QStringLiteral("Linear") << 4;
        QTest::newRow("tga 8 sRGB") << QByteArray(
            R"({"map": "C", "channels": ["baseColor.r", "baseColor.g", "baseColor.b"], "colorSpace": "srgb", "fileFormat": "tga"})")
                                    << QStringLiteral("Test_Mat_C.tga") << int(OIIO::TypeDesc::UINT8)
                                    << QStringLiteral("sRGB") << 3;
    }

    void userTemplateFormats()
    {
        QFETCH(QByteArray, output);
        QFETCH(QString, fileName);
        QFETCH(int, type);
        QFETCH(QString, colorSpace);
        QFETCH(int, channels);
        std::string error;
        const std::optional<ExportTemplate> t = templateFrom(test::exportTemplateJson(output), &error);
        QVERIFY2(t, error.c_str());
        const TestMaterial test(true);
        const std::optional<TextureSetPlan> plan
            = planTextureSet(*t, test.material, test.images(), {}, &error);
        QVERIFY2(plan, error.c_str());
        QTemporaryDir dir;
        QVERIFY2(writeSet(*plan, test, dir.path(), &error), error.c_str());
        const std::optional<ReadBack> file = readBack(dir.filePath(fileName));
        QVERIFY2(file, qPrintable(QDir(dir.path()).entryList().join(QStringLiteral(", "))));
        QCOMPARE(int(file->format.basetype), type);
        QCOMPARE(file->channels, channels);
        // TIFF and TGA have no colour-space tag OpenImageIO writes and reads back.
        if (fileName.endsWith(QStringLiteral(".tga")) || fileName.endsWith(QStringLiteral(".tif")))
            QVERIFY2(file->colorSpace.empty() || QString::fromStdString(file->colorSpace) == colorSpace,
                file->colorSpace.c_str());
        else
            QCOMPARE(QString::fromStdString(file->colorSpace), colorSpace);
        // The first channel's value, to the file's precision.
        const ExportChannel& first = t->outputs[0].channels[0];
        const ExportTexel texel = exportTexel(test.material, test.images(), glm::dvec2(0.5));
        double expected = channelValue(first, texel);
        if (colorSpace == QStringLiteral("sRGB"))
            expected = tonemap::linearToSrgb(expected);
        const double step = type == int(OIIO::TypeDesc::UINT8) ? 0.5 / 255.0
            : type == int(OIIO::TypeDesc::UINT16)              ? 0.5 / 65535.0
            : type == int(OIIO::TypeDesc::HALF)                ? 1e-3
                                                               : 1e-6;
        QVERIFY2(std::abs(file->values[0] - expected) <= step + 1e-7,
            qPrintable(QStringLiteral("%1, expected %2").arg(file->values[0]).arg(expected)));
    }

    // Plan-time refusals: a bit depth the format cannot hold, two files of one name.
    void badPlans()
    {
        const TestMaterial test(false);
        std::string error;
        TextureSetOptions options;
        options.bitDepth = 32;
        QVERIFY(!planTextureSet(
            *ExportTemplate::builtin("unreal"), test.material, test.images(), options, &error));
        QCOMPARE(error,
            std::string("unreal's BC is png, which cannot hold 32-bit channels (png: 8, 16; tga: 8; "
                        "tiff: 8, 16, 32; exr: 16, 32)"));
        options.bitDepth = 16;
        const std::optional<TextureSetPlan> plan = planTextureSet(
            *ExportTemplate::builtin("unreal"), test.material, test.images(), options, &error);
        QVERIFY2(plan, error.c_str());
        QCOMPARE(plan->files[0].output.bitDepth, 16);
        const std::optional<ExportTemplate> twice = templateFrom(
            test::exportTemplateJson(
                R"({"map": "R", "channels": ["roughness"]}, {"map": "R", "channels": ["metallic"]})"),
            &error);
        QVERIFY2(twice, error.c_str());
        QVERIFY(!planTextureSet(*twice, test.material, test.images(), {}, &error));
        QVERIFY2(QString::fromStdString(error).contains(QStringLiteral("names two files Test_Mat_R.png")),
            error.c_str());
    }

    void dryRunDescription()
    {
        const TestMaterial test(false);
        std::string error;
        const std::optional<TextureSetPlan> plan = planTextureSet(
            *ExportTemplate::builtin("unity-hdrp"), test.material, test.images(), {}, &error);
        QCOMPARE(describe(plan->files[2]),
            std::string("Test_Mat_MaskMap.png  4x4  RGBA 8-bit linear: R metallic, G occlusion, B constant "
                        "1.000, A 1 - "
                        "roughness"));
    }
};

QTEST_GUILESS_MAIN(TextureSetFormatsTest)
#include "TextureSetFormatsTest.moc"
