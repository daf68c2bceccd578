// core/export/ExportTemplate: reading export templates and naming their files. The name pattern's tokens
// (and {size} as the width or WxH), file-name-safe material names, and bad templates and template
// files, each refused with the field named. tests/TextureSetExportTest.cpp checks what the
// templates write.

#include <QDir>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include "TestAssets.h"
#include "TestSupport.h"
#include "core/export/ExportTemplate.h"
#include "core/export/TextureSetExport.h"
#include "core/image/MapImage.h"

using namespace facet;

namespace {

std::optional<ExportTemplate> templateFrom(const QByteArray& json, std::string* error)
{
    return ExportTemplate::fromJson(QJsonDocument::fromJson(json).object(), error);
}

} // namespace

class ExportTemplateTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void fileNameTokens()
    {
        std::string out;
        std::string error;
        QVERIFY(expandFileName(
            "{template}/{material}-{map}@{size}", "Brass", "ORM", "1024", "unreal", &out, &error));
        QCOMPARE(out, std::string("unreal/Brass-ORM@1024"));
        QVERIFY(!expandFileName("{material}_{colour}", "a", "b", "1", "t", &out, &error));
        QCOMPARE(error,
            std::string("\"{material}_{colour}\": unknown token {colour} (known: {material}, {map}, "
                        "{size}, {template})"));
        QVERIFY(!expandFileName("{material", "a", "b", "1", "t", &out, &error));
        QVERIFY(!expandFileName("material}", "a", "b", "1", "t", &out, &error));
        QCOMPARE(fileNameSafe("Brass / worn: 2"), std::string("Brass_worn_2"));
        QCOMPARE(fileNameSafe("..hidden"), std::string("hidden"));
        QCOMPARE(fileNameSafe("///"), std::string("_"));
        QCOMPARE(fileNameSafe(""), std::string("Material"));
        // {size}: the width, or WxH.
        Material material;
        material.name = "Test Mat";
        const std::optional<ExportTemplate> t
            = templateFrom(test::exportTemplateJson(
                               R"({"map": "R", "channels": ["roughness"]})", "{template}{material}_{size}"),
                &error);
        QVERIFY2(t, error.c_str());
        TextureSetOptions options;
        options.size = 32;
        std::optional<TextureSetPlan> plan = planTextureSet(*t, material, {}, options, &error);
        QVERIFY2(plan, error.c_str());
        QCOMPARE(QString::fromStdString(plan->files[0].fileName), QStringLiteral("Test_Mat_32.png"));
        options.size = 0;
        Image wide(64, 32);
        const MapImage map = MapImage::fromImage(wide, MapLayout::Grey, MapSampleType::UInt8);
        material.map(MapSlot::Roughness).path = "wide.png";
        MaterialMapImages images {};
        images[std::size_t(MapSlot::Roughness)] = &map;
        plan = planTextureSet(*t, material, images, options, &error);
        QCOMPARE(QString::fromStdString(plan->files[0].fileName), QStringLiteral("Test_Mat_64x32.png"));
    }

    // Bad templates, each refused with the field named.
    void badTemplates_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("message");
        QTest::newRow("unknown token")
            << test::exportTemplateJson(R"({"map": "R", "channels": ["roughness"]})", "{material}_{colour}")
            << QStringLiteral(
                   "outputs[0] (the template's fileName): \"{material}_{colour}\": unknown token {colour}");
        QTest::newRow("unknown source")
            << test::exportTemplateJson(R"({"map": "R", "channels": ["metallic", "rough"]})")
            << QStringLiteral("outputs[0].channels[1]: \"rough\" is not a source (baseColor.r");
        QTest::newRow("the word constant")
            << test::exportTemplateJson(R"({"map": "R", "channels": ["constant"]})")
            << QStringLiteral("outputs[0].channels[0]: \"constant\" is not a source");
        QTest::newRow("constant out of range")
            << test::exportTemplateJson(R"({"map": "R", "channels": [1.5]})")
            << QStringLiteral("outputs[0].channels[0]: the constant 1.5 is outside [0, 1]");
        QTest::newRow("five channels") << test::exportTemplateJson(
            R"({"map": "R", "channels": ["metallic", "metallic", "metallic", "metallic", "metallic"]})")
                                       << QStringLiteral("outputs[0].channels: has 5 entries; a file has 1 "
                                                         "to 4 channels");
        QTest::newRow("no channels") << test::exportTemplateJson(R"({"map": "R"})")
                                     << QStringLiteral("outputs[0].channels: is missing");
        QTest::newRow("no map") << test::exportTemplateJson(R"({"channels": ["metallic"]})")
                                << QStringLiteral("outputs[0].map: is missing");
        QTest::newRow("misspelt key")
            << test::exportTemplateJson(R"({"map": "R", "channels": ["metallic"], "colourSpace": "srgb"})")
            << QStringLiteral("outputs[0].colourSpace: unknown key");
        QTest::newRow("bad colour space")
            << test::exportTemplateJson(R"({"map": "R", "channels": ["metallic"], "colorSpace": "acescg"})")
            << QStringLiteral("outputs[0].colorSpace: unknown name \"acescg\"");
        QTest::newRow("tga 16") << test::exportTemplateJson(
            R"({"map": "R", "channels": ["metallic"], "bitDepth": 16, "fileFormat": "tga"})")
                                << QStringLiteral(
                                       "outputs[0].bitDepth: tga files cannot hold 16-bit channels");
        QTest::newRow("exr 8") << test::exportTemplateJson(
            R"({"map": "R", "channels": ["metallic"], "fileFormat": "exr"})")
                               << QStringLiteral("outputs[0].bitDepth: exr files cannot hold 8-bit channels");
        QTest::newRow("bit depth 12")
            << test::exportTemplateJson(R"({"map": "R", "channels": ["metallic"], "bitDepth": 12})")
            << QStringLiteral("outputs[0].bitDepth: 12 is not 8, 16 or 32");
        QTest::newRow("jpeg") << test::exportTemplateJson(
            R"({"map": "R", "channels": ["metallic"], "fileFormat": "jpg"})")
                              << QStringLiteral("outputs[0].fileFormat: unknown name \"jpg\"");
        QTest::newRow("a path") << test::exportTemplateJson(
            R"({"map": "R", "channels": ["metallic"], "fileName": "../{map}"})")
                                << QStringLiteral(
                                       "outputs[0].fileName: \"../{map}\" holds a folder separator");
        QTest::newRow("no outputs") << QByteArray(
            R"({"format": "facet-export-template", "version": 1, "outputs": []})")
                                    << QStringLiteral("outputs: is missing or empty");
        QTest::newRow("not a template")
            << QByteArray(R"({"format": "facet-project", "version": 1})")
            << QStringLiteral("format: \"facet-project\" is not \"facet-export-template\"");
        QTest::newRow("newer") << QByteArray(
            R"({"format": "facet-export-template", "version": 9, "outputs": []})")
                               << QStringLiteral("written by a newer Facet (version 9)");
    }

    void badTemplates()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, message);
        std::string error;
        QVERIFY(!templateFrom(json, &error));
        QVERIFY2(QString::fromStdString(error).startsWith(message)
                || QString::fromStdString(error).contains(message),
            error.c_str());
    }

    void badTemplateFiles()
    {
        QTemporaryDir dir;
        std::string error;
        QVERIFY(!ExportTemplate::load(dir.filePath(QStringLiteral("missing.json")).toStdString(), &error));
        QCOMPARE(QString::fromStdString(error),
            dir.filePath(QStringLiteral("missing.json")) + QStringLiteral(": no such file"));
        const QString broken = dir.filePath(QStringLiteral("broken.json"));
        QVERIFY(test::writeText(broken, "{\"format\": \"facet-export-template\", "));
        QVERIFY(!ExportTemplate::load(broken.toStdString(), &error));
        QVERIFY2(QString::fromStdString(error).startsWith(broken + QStringLiteral(": ")), error.c_str());
        const QString good = dir.filePath(QStringLiteral("my-engine.json"));
        QVERIFY(test::writeText(good,
            test::exportTemplateJson(R"({"map": "R", "channels": ["roughness"]})", "{template}_{map}")));
        const std::optional<ExportTemplate> t = ExportTemplate::load(good.toStdString(), &error);
        QVERIFY2(t, error.c_str());
        QCOMPARE(t->id, std::string("my-engine"));
    }
};

QTEST_GUILESS_MAIN(ExportTemplateTest)
#include "ExportTemplateTest.moc"
