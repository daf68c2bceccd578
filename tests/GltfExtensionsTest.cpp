// glTF material extensions as the importer reads them (core/gltf/GltfMaterials): a row per
// extension, per field and per kind of bad value (out of range, the wrong type, a texture that is
// not there): the material's value, and the warning that names the file, the material
// and the field; the mesh import of the same file says nothing of the materials.

#include "core/gltf/GltfImport.h"
#include "core/mesh/MeshImport.h"

#include "GltfWriter.h"
#include "TestSupport.h"

#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <cmath>

using namespace facet;
using facet::test::GltfWriter;
using Storage = GltfWriter::BufferStorage;

namespace {

bool contains(const std::string& text, const char* part)
{
    return text.find(part) != std::string::npos;
}

bool near(double a, double b, double tolerance = 1e-6)
{
    return std::abs(a - b) <= tolerance;
}

} // namespace

class GltfExtensionsTest : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    QString path(const QString& name) const { return m_dir.filePath(name); }
    // Textures 0 and 1 of `w`: files a.png and b.png, 4 x 4 RGBA with alpha 128 (a lobe's packing
    // reads the colour from RGB and a number from A).
    bool addTwoRgbaTextures(GltfWriter& w)
    {
        for (const char* name : {"a.png", "b.png"}) {
            QImage image(4, 4, QImage::Format_RGBA8888);
            image.fill(QColor(200, 100, 50, 128));
            if (!image.save(path(QLatin1String(name))))
                return false;
            w.addTexture(w.addImageUri(QLatin1String(name)));
        }
        return true;
    }
    // `w` (which may hold textures already) with a quad of one material, `name`, whose one
    // extension is `extension` with the JSON `object` (KHR_texture_transform also listed as used
    // when the object holds one), written to `file` and imported.
    std::optional<GltfAsset> importWithExtension(GltfWriter& w, const char* name, const char* extension,
        const QByteArray& object, const QString& file, std::string* error, std::string* warnings) const
    {
        QJsonObject material;
        material[QLatin1String("name")] = QLatin1String(name);
        material[QLatin1String("extensions")]
            = QJsonObject {{QLatin1String(extension), QJsonDocument::fromJson(object).object()}};
        w.addNode(w.addQuad(w.addMaterial(material)));
        QJsonArray used {QLatin1String(extension)};
        if (object.contains("KHR_texture_transform"))
            used.append(QLatin1String("KHR_texture_transform"));
        w.json()[QLatin1String("extensionsUsed")] = used;
        if (!w.write(path(file), Storage::DataUri)) {
            *error = "could not write " + file.toStdString();
            return std::nullopt;
        }
        return importGltf(path(file).toStdString(), error, warnings);
    }

private Q_SLOTS:
    // The extensions of the material model, a row per field and per kind of bad value: what is read,
    // and the warning that names the material and the field.
    void materialExtensions_data()
    {
        QTest::addColumn<QByteArray>("extensions"); // the material's "extensions" object
        QTest::addColumn<double>("clearcoat");
        QTest::addColumn<double>("clearcoatRoughness");
        QTest::addColumn<double>("ior");
        QTest::addColumn<QString>("warning"); // a part of the import's warning, or empty for none
        const auto row = [](const char* name, const char* json, double clearcoat, double clearcoatRoughness,
                             double ior, const char* warning) {
            QTest::newRow(name) << QByteArray(json) << clearcoat << clearcoatRoughness << ior
                                << QString::fromUtf8(warning);
        };
        row("clearcoat",
            R"({"KHR_materials_clearcoat": {"clearcoatFactor": 0.8, "clearcoatRoughnessFactor": 0.2}})", 0.8,
            0.2, 1.5, "");
        row("clearcoat, no factor (the extension's default 0)", R"({"KHR_materials_clearcoat": {}})", 0.0,
            0.0, 1.5, "");
        row("clearcoat, roughness only", R"({"KHR_materials_clearcoat": {"clearcoatRoughnessFactor": 0.4}})",
            0.0, 0.4, 1.5, "");
        row("clearcoat above 1", R"({"KHR_materials_clearcoat": {"clearcoatFactor": 1.5}})", 1.0, 0.0, 1.5,
            "extensions.gltf: material 'M' KHR_materials_clearcoat.clearcoatFactor 1.5 is outside Facet's "
            "[0, "
            "1]: 1 used");
        row("clearcoat roughness negative",
            R"({"KHR_materials_clearcoat": {"clearcoatFactor": 1, "clearcoatRoughnessFactor": -2}})", 1.0,
            0.0, 1.5,
            "KHR_materials_clearcoat.clearcoatRoughnessFactor -2 is outside Facet's [0, 1]: 0 used");
        row("clearcoat factor a string", R"({"KHR_materials_clearcoat": {"clearcoatFactor": "shiny"}})", 0.0,
            0.0, 1.5, "KHR_materials_clearcoat.clearcoatFactor is not a number: 0 used");
        row("clearcoat texture that does not exist",
            R"({"KHR_materials_clearcoat": {"clearcoatFactor": 1, "clearcoatTexture": {"index": 7}}})", 1.0,
            0.0, 1.5, "KHR_materials_clearcoat.clearcoatTexture names texture 7, which does not exist");
        row("clearcoat normal texture not a textureInfo",
            R"({"KHR_materials_clearcoat": {"clearcoatFactor": 1, "clearcoatNormalTexture": 3}})", 1.0, 0.0,
            1.5, "KHR_materials_clearcoat.clearcoatNormalTexture is not a textureInfo with an integer index");
        row("clearcoat roughness texture index a string",
            R"({"KHR_materials_clearcoat": {"clearcoatFactor": 1, "clearcoatRoughnessTexture": {"index": "a"}}})",
            1.0, 0.0, 1.5,
            "KHR_materials_clearcoat.clearcoatRoughnessTexture is not a textureInfo with an integer index");
        row("ior a string", R"({"KHR_materials_ior": {"ior": "glass"}})", 0.0, 0.0, 1.5,
            "KHR_materials_ior.ior is not a number: 1.5 used");
        row("ior and clearcoat",
            R"({"KHR_materials_ior": {"ior": 1.33}, "KHR_materials_clearcoat": {"clearcoatFactor": 0.5}})",
            0.5, 0.0, 1.33, "");
    }

    void materialExtensions()
    {
        QFETCH(QByteArray, extensions);
        QFETCH(double, clearcoat);
        QFETCH(double, clearcoatRoughness);
        QFETCH(double, ior);
        QFETCH(QString, warning);
        GltfWriter w;
        QJsonObject material;
        material[QLatin1String("name")] = QLatin1String("M");
        material[QLatin1String("extensions")] = QJsonDocument::fromJson(extensions).object();
        QVERIFY(!material[QLatin1String("extensions")].toObject().isEmpty());
        w.addNode(w.addQuad(w.addMaterial(material)));
        QJsonArray used;
        for (const QString& name : material[QLatin1String("extensions")].toObject().keys())
            used.append(name);
        w.json()[QLatin1String("extensionsUsed")] = used;
        const QString file = path(QStringLiteral("extensions.gltf"));
        QVERIFY(w.write(file, Storage::DataUri));
        std::string error, warnings;
        const auto asset = importGltf(file.toStdString(), &error, &warnings);
        QVERIFY2(asset, error.c_str());
        const Material& m = asset->materials.at(0);
        std::string problem;
        QVERIFY2(m.validate(&problem), problem.c_str());
        QVERIFY(near(m.clearcoat(), clearcoat));
        QVERIFY(near(m.clearcoatRoughness(), clearcoatRoughness));
        for (MapSlot slot : {MapSlot::Clearcoat, MapSlot::ClearcoatRoughness, MapSlot::ClearcoatNormal})
            QVERIFY2(!m.map(slot).hasTexture(), toString(slot)); // a bad textureInfo leaves the factor alone
        QVERIFY(near(m.ior, ior));
        if (warning.isEmpty())
            QVERIFY2(warnings.empty(), warnings.c_str());
        else
            QVERIFY2(QString::fromStdString(warnings).contains(warning), warnings.c_str());
        // The mesh import of the same file says nothing of the materials (the window and `render`
        // read both: the notes were said twice).
        std::string meshWarnings;
        QVERIFY2(importMesh(file.toStdString(), &error, &meshWarnings), error.c_str());
        QVERIFY2(meshWarnings.empty(), meshWarnings.c_str());
    }

    // KHR_materials_clearcoat's three textures, each alone and all together (one packed texture
    // for the strength and roughness, as the extension intends): which slot reads which file, in
    // which channel (R strength, G roughness), colour space (data), UV set, transform and, for the
    // normal, its scale.
    void clearcoatTextures_data()
    {
        QTest::addColumn<QByteArray>("clearcoat"); // the extension's object
        QTest::addColumn<QString>("strengthFile"); // the slot's file name, or empty for none
        QTest::addColumn<QString>("roughnessFile");
        QTest::addColumn<QString>("normalFile");
        QTest::addColumn<double>("normalScale");
        QTest::addColumn<int>("texCoord"); // of every textured slot
        QTest::addColumn<double>("uvScale"); // KHR_texture_transform's scale, 1 for none
        const QString none;
        // A stray "scale" on a textureInfo that has none is not the coat's strength.
        QTest::newRow("strength alone (a stray scale ignored)")
            << QByteArray(R"({"clearcoatFactor": 1, "clearcoatTexture": {"index": 0, "scale": 0.25}})")
            << QStringLiteral("a.png") << none << none << 1.0 << 0 << 1.0;
        QTest::newRow("roughness alone, UV set 1")
            << QByteArray(R"({"clearcoatFactor": 1, "clearcoatRoughnessFactor": 1,
                 "clearcoatRoughnessTexture": {"index": 1, "texCoord": 1}})")
            << none << QStringLiteral("b.png") << none << 1.0 << 1 << 1.0;
        QTest::newRow("normal alone, scale 0.5, transformed")
            << QByteArray(R"({"clearcoatFactor": 1, "clearcoatNormalTexture": {"index": 2, "scale": 0.5,
                 "extensions": {"KHR_texture_transform": {"scale": [4, 4]}}}})")
            << none << none << QStringLiteral("c.png") << 0.5 << 0 << 4.0;
        QTest::newRow("all three, strength and roughness packed in one")
            << QByteArray(R"({"clearcoatFactor": 1, "clearcoatRoughnessFactor": 1,
                 "clearcoatTexture": {"index": 0}, "clearcoatRoughnessTexture": {"index": 0},
                 "clearcoatNormalTexture": {"index": 2}})")
            << QStringLiteral("a.png") << QStringLiteral("a.png") << QStringLiteral("c.png") << 1.0 << 0
            << 1.0;
    }

    void clearcoatTextures()
    {
        QFETCH(QByteArray, clearcoat);
        QFETCH(QString, strengthFile);
        QFETCH(QString, roughnessFile);
        QFETCH(QString, normalFile);
        QFETCH(double, normalScale);
        QFETCH(int, texCoord);
        QFETCH(double, uvScale);
        GltfWriter w;
        for (const char* name : {"a.png", "b.png", "c.png"}) {
            QImage image(4, 4, QImage::Format_RGB888);
            image.fill(Qt::gray);
            QVERIFY(image.save(path(QLatin1String(name))));
            w.addTexture(w.addImageUri(QLatin1String(name)));
        }
        QVERIFY(!QJsonDocument::fromJson(clearcoat).object().isEmpty());
        std::string error, warnings;
        const auto asset = importWithExtension(w, "Coated", "KHR_materials_clearcoat", clearcoat,
            QStringLiteral("coat.gltf"), &error, &warnings);
        QVERIFY2(asset, error.c_str());
        // The quad has one UV set: a map on the second is read on the first, and that is said.
        if (texCoord == 1)
            QVERIFY2(contains(warnings, "clearcoatRoughness reads TEXCOORD_1, which no primitive has"),
                warnings.c_str());
        else
            QVERIFY2(warnings.empty(), warnings.c_str());
        const Material& m = asset->materials.at(0);
        std::string problem;
        QVERIFY2(m.validate(&problem), problem.c_str());
        const struct {
            MapSlot slot;
            QString file;
            MapChannel channel;
        } expected[] = {{MapSlot::Clearcoat, strengthFile, MapChannel::R},
            {MapSlot::ClearcoatRoughness, roughnessFile, MapChannel::G},
            {MapSlot::ClearcoatNormal, normalFile, MapChannel::Rgb}};
        for (const auto& e : expected) {
            const MaterialMap& map = m.map(e.slot);
            QCOMPARE(QString::fromStdString(map.path), e.file.isEmpty() ? QString() : path(e.file));
            QCOMPARE(map.channel, e.channel);
            QCOMPARE(map.colorSpace, ColorEncoding::Linear);
            if (e.file.isEmpty())
                continue;
            QCOMPARE(map.texCoord, texCoord);
            QVERIFY(near(map.uv.scale.x, uvScale));
        }
        QVERIFY(near(m.map(MapSlot::ClearcoatNormal).factor.x, normalScale));
        QCOMPARE(m.clearcoat(), 1.0);
    }

    // KHR_materials_sheen's factors: the extension's defaults (black, 0: no sheen), values clamped
    // with a note naming the field, fields of the wrong type refused with a note, nothing crashes.
    void sheenFactors_data()
    {
        QTest::addColumn<QByteArray>("sheen"); // the extension's object
        QTest::addColumn<double>("red"); // the colour's components read back
        QTest::addColumn<double>("green");
        QTest::addColumn<double>("blue");
        QTest::addColumn<double>("roughness");
        QTest::addColumn<QString>("warning"); // part of the notes, or empty for none
        const auto row = [](const char* name, const char* json, glm::dvec3 color, double roughness,
                             const char* warning) {
            QTest::newRow(name) << QByteArray(json) << color.r << color.g << color.b << roughness
                                << QString::fromLatin1(warning);
        };
        row("colour and roughness", R"({"sheenColorFactor": [0.9, 0.5, 0.1], "sheenRoughnessFactor": 0.6})",
            {0.9, 0.5, 0.1}, 0.6, "");
        row("empty (the extension's defaults: no sheen)", "{}", glm::dvec3(0.0), 0.0, "");
        row("roughness only", R"({"sheenRoughnessFactor": 0.3})", glm::dvec3(0.0), 0.3, "");
        row("colour above 1", R"({"sheenColorFactor": [2, 0.5, 0.5]})", {1.0, 0.5, 0.5}, 0.0,
            "KHR_materials_sheen.sheenColorFactor 2 is outside Facet's [0, 1]: 1 used");
        row("colour of two numbers", R"({"sheenColorFactor": [1, 1]})", glm::dvec3(0.0), 0.0,
            "KHR_materials_sheen.sheenColorFactor is not an array of three numbers: black used");
        row("colour a string", R"({"sheenColorFactor": "velvet"})", glm::dvec3(0.0), 0.0,
            "KHR_materials_sheen.sheenColorFactor is not an array of three numbers");
        row("roughness a string", R"({"sheenColorFactor": [1, 1, 1], "sheenRoughnessFactor": "soft"})",
            glm::dvec3(1.0), 0.0, "KHR_materials_sheen.sheenRoughnessFactor is not a number: 0 used");
        row("roughness negative", R"({"sheenColorFactor": [1, 1, 1], "sheenRoughnessFactor": -1})",
            glm::dvec3(1.0), 0.0,
            "KHR_materials_sheen.sheenRoughnessFactor -1 is outside Facet's [0, 1]: 0 used");
        row("colour texture that does not exist",
            R"({"sheenColorFactor": [1, 1, 1], "sheenColorTexture": {"index": 9}})", glm::dvec3(1.0), 0.0,
            "KHR_materials_sheen.sheenColorTexture names texture 9, which does not exist");
        row("roughness texture not a textureInfo",
            R"({"sheenColorFactor": [1, 1, 1], "sheenRoughnessTexture": 2})", glm::dvec3(1.0), 0.0,
            "KHR_materials_sheen.sheenRoughnessTexture is not a textureInfo with an integer index");
    }
    void sheenFactors()
    {
        QFETCH(QByteArray, sheen);
        QFETCH(double, red);
        QFETCH(double, green);
        QFETCH(double, blue);
        QFETCH(double, roughness);
        QFETCH(QString, warning);
        GltfWriter w;
        std::string error, warnings;
        const auto asset = importWithExtension(
            w, "M", "KHR_materials_sheen", sheen, QStringLiteral("sheen.gltf"), &error, &warnings);
        QVERIFY2(asset, error.c_str());
        const Material& m = asset->materials.at(0);
        std::string problem;
        QVERIFY2(m.validate(&problem), problem.c_str());
        QVERIFY(near(m.sheenColor().r, red));
        QVERIFY(near(m.sheenColor().g, green));
        QVERIFY(near(m.sheenColor().b, blue));
        QVERIFY(near(m.sheenRoughness(), roughness));
        QCOMPARE(m.hasSheen(), red + green + blue > 0.0);
        for (MapSlot slot : {MapSlot::SheenColor, MapSlot::SheenRoughness})
            QVERIFY2(!m.map(slot).hasTexture(), toString(slot));
        if (warning.isEmpty())
            QVERIFY2(warnings.empty(), warnings.c_str());
        else
            QVERIFY2(QString::fromStdString(warnings).contains(warning), warnings.c_str());
    }

    // KHR_materials_sheen's two textures, each alone and as one RGBA texture (the extension's
    // packing: colour RGB in sRGB, roughness in A, linear).
    void sheenTextures_data()
    {
        QTest::addColumn<QByteArray>("sheen");
        QTest::addColumn<QString>("colorFile");
        QTest::addColumn<QString>("roughnessFile");
        const QString none;
        QTest::newRow("colour alone") << QByteArray(R"({"sheenColorFactor": [1, 1, 1],
                 "sheenColorTexture": {"index": 0}})")
                                      << QStringLiteral("a.png") << none;
        QTest::newRow("roughness alone")
            << QByteArray(R"({"sheenColorFactor": [1, 1, 1], "sheenRoughnessFactor": 1,
                 "sheenRoughnessTexture": {"index": 1}})")
            << none << QStringLiteral("b.png");
        QTest::newRow("one RGBA texture for both") << QByteArray(R"({"sheenColorFactor": [1, 1, 1],
                 "sheenRoughnessFactor": 1, "sheenColorTexture": {"index": 0},
                 "sheenRoughnessTexture": {"index": 0}})")
                                                   << QStringLiteral("a.png") << QStringLiteral("a.png");
    }
    void sheenTextures()
    {
        QFETCH(QByteArray, sheen);
        QFETCH(QString, colorFile);
        QFETCH(QString, roughnessFile);
        GltfWriter w;
        QVERIFY(addTwoRgbaTextures(w));
        std::string error, warnings;
        const auto asset = importWithExtension(
            w, "Velvet", "KHR_materials_sheen", sheen, QStringLiteral("velvet.gltf"), &error, &warnings);
        QVERIFY2(asset, error.c_str());
        QVERIFY2(warnings.empty(), warnings.c_str());
        const Material& m = asset->materials.at(0);
        std::string problem;
        QVERIFY2(m.validate(&problem), problem.c_str());
        const MaterialMap& color = m.map(MapSlot::SheenColor);
        const MaterialMap& roughness = m.map(MapSlot::SheenRoughness);
        QCOMPARE(QString::fromStdString(color.path), colorFile.isEmpty() ? QString() : path(colorFile));
        QCOMPARE(QString::fromStdString(roughness.path),
            roughnessFile.isEmpty() ? QString() : path(roughnessFile));
        QCOMPARE(color.channel, MapChannel::Rgb);
        QCOMPARE(color.colorSpace, ColorEncoding::SRGB);
        QCOMPARE(roughness.channel, MapChannel::A);
        QCOMPARE(roughness.colorSpace, ColorEncoding::Linear);
        QVERIFY(m.hasSheen());
    }

    // KHR_materials_specular's factors: the extension's defaults (1, white: the core's layer, no
    // shader cost), a colour above 1 kept (the extension allows it) up to Facet's 100, values
    // beyond clamped and fields of the wrong type refused, each with a note naming the field.
    void specularFactors_data()
    {
        QTest::addColumn<QByteArray>("specular"); // the extension's object
        QTest::addColumn<double>("strength");
        QTest::addColumn<glm::dvec3>("color");
        QTest::addColumn<QString>("warning"); // part of the notes, or empty for none
        const auto row = [](const char* name, const char* json, double strength, glm::dvec3 color,
                             const char* warning) {
            QTest::newRow(name) << QByteArray(json) << strength << color << QString::fromLatin1(warning);
        };
        row("strength and colour", R"({"specularFactor": 0.4, "specularColorFactor": [1, 0.5, 0.25]})", 0.4,
            {1.0, 0.5, 0.25}, "");
        row("empty (the extension's defaults)", "{}", 1.0, glm::dvec3(1.0), "");
        row("strength 0 (a purely diffuse dielectric)", R"({"specularFactor": 0})", 0.0, glm::dvec3(1.0), "");
        row("colour above 1 (allowed)", R"({"specularColorFactor": [25, 2, 1]})", 1.0, {25.0, 2.0, 1.0}, "");
        row("colour above Facet's 100", R"({"specularColorFactor": [1000, 1, 1]})", 1.0, {100.0, 1.0, 1.0},
            "KHR_materials_specular.specularColorFactor 1000 is outside Facet's [0, 100]: 100 used");
        row("colour negative", R"({"specularColorFactor": [-1, 1, 1]})", 1.0, {0.0, 1.0, 1.0},
            "KHR_materials_specular.specularColorFactor -1 is outside Facet's [0, 100]: 0 used");
        row("colour of two numbers", R"({"specularColorFactor": [1, 1]})", 1.0, glm::dvec3(1.0),
            "KHR_materials_specular.specularColorFactor is not an array of three numbers: white used");
        row("strength a string", R"({"specularFactor": "shiny"})", 1.0, glm::dvec3(1.0),
            "KHR_materials_specular.specularFactor is not a number: 1 used");
        row("strength above 1", R"({"specularFactor": 3})", 1.0, glm::dvec3(1.0),
            "KHR_materials_specular.specularFactor 3 is outside Facet's [0, 1]: 1 used");
        row("texture that does not exist", R"({"specularTexture": {"index": 9}})", 1.0, glm::dvec3(1.0),
            "KHR_materials_specular.specularTexture names texture 9, which does not exist");
        row("colour texture not a textureInfo", R"({"specularColorTexture": 2})", 1.0, glm::dvec3(1.0),
            "KHR_materials_specular.specularColorTexture is not a textureInfo with an integer index");
    }
    void specularFactors()
    {
        QFETCH(QByteArray, specular);
        QFETCH(double, strength);
        QFETCH(glm::dvec3, color);
        QFETCH(QString, warning);
        GltfWriter w;
        std::string error, warnings;
        const auto asset = importWithExtension(
            w, "M", "KHR_materials_specular", specular, QStringLiteral("specular.gltf"), &error, &warnings);
        QVERIFY2(asset, error.c_str());
        const Material& m = asset->materials.at(0);
        std::string problem;
        QVERIFY2(m.validate(&problem), problem.c_str());
        QVERIFY(near(m.specular(), strength));
        for (int c = 0; c < 3; ++c)
            QVERIFY2(near(m.specularColor()[c], color[c]), qPrintable(QString::number(m.specularColor()[c])));
        QCOMPARE(m.hasSpecular(), strength != 1.0 || color != glm::dvec3(1.0));
        for (MapSlot slot : {MapSlot::Specular, MapSlot::SpecularColor})
            QVERIFY2(!m.map(slot).hasTexture(), toString(slot));
        if (warning.isEmpty())
            QVERIFY2(warnings.empty(), warnings.c_str());
        else
            QVERIFY2(QString::fromStdString(warnings).contains(warning), warnings.c_str());
    }

    // KHR_materials_specular's two textures, each alone and as one RGBA texture (the extension's
    // packing: colour RGB in sRGB, strength in A, linear). A texture with the default factors still
    // turns the layer on: it modulates them.
    void specularTextures_data()
    {
        QTest::addColumn<QByteArray>("specular");
        QTest::addColumn<QString>("strengthFile");
        QTest::addColumn<QString>("colorFile");
        const QString none;
        QTest::newRow("strength alone")
            << QByteArray(R"({"specularTexture": {"index": 0}})") << QStringLiteral("a.png") << none;
        QTest::newRow("colour alone")
            << QByteArray(R"({"specularColorTexture": {"index": 1}})") << none << QStringLiteral("b.png");
        QTest::newRow("one RGBA texture for both")
            << QByteArray(R"({"specularFactor": 0.5, "specularTexture": {"index": 0},
                 "specularColorTexture": {"index": 0}})")
            << QStringLiteral("a.png") << QStringLiteral("a.png");
    }
    void specularTextures()
    {
        QFETCH(QByteArray, specular);
        QFETCH(QString, strengthFile);
        QFETCH(QString, colorFile);
        GltfWriter w;
        QVERIFY(addTwoRgbaTextures(w));
        std::string error, warnings;
        const auto asset = importWithExtension(
            w, "Lens", "KHR_materials_specular", specular, QStringLiteral("lens.gltf"), &error, &warnings);
        QVERIFY2(asset, error.c_str());
        QVERIFY2(warnings.empty(), warnings.c_str());
        const Material& m = asset->materials.at(0);
        std::string problem;
        QVERIFY2(m.validate(&problem), problem.c_str());
        const MaterialMap& strength = m.map(MapSlot::Specular);
        const MaterialMap& color = m.map(MapSlot::SpecularColor);
        QCOMPARE(
            QString::fromStdString(strength.path), strengthFile.isEmpty() ? QString() : path(strengthFile));
        QCOMPARE(QString::fromStdString(color.path), colorFile.isEmpty() ? QString() : path(colorFile));
        QCOMPARE(strength.channel, MapChannel::A);
        QCOMPARE(strength.colorSpace, ColorEncoding::Linear);
        QCOMPARE(color.channel, MapChannel::Rgb);
        QCOMPARE(color.colorSpace, ColorEncoding::SRGB);
        QVERIFY(m.hasSpecular());
    }

    // KHR_materials_anisotropy: strength (default 0: isotropic) and rotation, radians in the file
    // and degrees in Facet, wrapped to [-180, 180] (a whole turn is the same direction); the
    // texture linear RGB (direction RG, strength B); values beyond the ranges clamped and fields of
    // the wrong type refused, each with a note naming the field.
    void anisotropy_data()
    {
        QTest::addColumn<QByteArray>("anisotropy"); // the extension's object
        QTest::addColumn<double>("strength");
        QTest::addColumn<double>("degrees");
        QTest::addColumn<QString>("file"); // the texture's, or empty
        QTest::addColumn<QString>("warning"); // part of the notes, or empty for none
        const auto row = [](const char* name, const char* json, double strength, double degrees,
                             const char* file, const char* warning) {
            QTest::newRow(name) << QByteArray(json) << strength << degrees << QString::fromLatin1(file)
                                << QString::fromLatin1(warning);
        };
        row("strength and a quarter turn", R"({"anisotropyStrength": 0.6, "anisotropyRotation": 1.5707963267948966})",
            0.6, 90.0, "", "");
        row("empty (the extension's defaults)", "{}", 0.0, 0.0, "", "");
        row("a turn and a half radian", R"({"anisotropyStrength": 1, "anisotropyRotation": 6.783185307179586})", 1.0,
            0.5 * 180.0 / 3.141592653589793, "", "");
        row("minus four radians", R"({"anisotropyStrength": 1, "anisotropyRotation": -4})", 1.0,
            360.0 - 4.0 * 180.0 / 3.141592653589793, "", "");
        row("a texture", R"({"anisotropyStrength": 0.8, "anisotropyTexture": {"index": 0}})", 0.8, 0.0, "a.png", "");
        row("strength a string", R"({"anisotropyStrength": "brushed"})", 0.0, 0.0, "",
            "KHR_materials_anisotropy.anisotropyStrength is not a number: 0 used");
        row("strength above 1", R"({"anisotropyStrength": 3})", 1.0, 0.0, "",
            "KHR_materials_anisotropy.anisotropyStrength 3 is outside Facet's [0, 1]: 1 used");
        row("rotation a string", R"({"anisotropyStrength": 1, "anisotropyRotation": "left"})", 1.0, 0.0, "",
            "KHR_materials_anisotropy.anisotropyRotation is not a number: 0 used");
        row("texture that does not exist", R"({"anisotropyStrength": 1, "anisotropyTexture": {"index": 9}})", 1.0,
            0.0, "", "KHR_materials_anisotropy.anisotropyTexture names texture 9, which does not exist");
    }
    void anisotropy()
    {
        QFETCH(QByteArray, anisotropy);
        QFETCH(double, strength);
        QFETCH(double, degrees);
        QFETCH(QString, file);
        QFETCH(QString, warning);
        GltfWriter w;
        QVERIFY(addTwoRgbaTextures(w));
        std::string error, warnings;
        const auto asset = importWithExtension(
            w, "Brushed", "KHR_materials_anisotropy", anisotropy, QStringLiteral("brushed.gltf"), &error, &warnings);
        QVERIFY2(asset, error.c_str());
        const Material& m = asset->materials.at(0);
        std::string problem;
        QVERIFY2(m.validate(&problem), problem.c_str());
        QVERIFY2(near(m.anisotropy(), strength), qPrintable(QString::number(m.anisotropy())));
        QVERIFY2(near(m.anisotropyRotationDegrees, degrees, 1e-9),
            qPrintable(QString::number(m.anisotropyRotationDegrees, 'g', 17)));
        const MaterialMap& map = m.map(MapSlot::Anisotropy);
        QCOMPARE(QString::fromStdString(map.path), file.isEmpty() ? QString() : path(file));
        QCOMPARE(map.channel, MapChannel::Rgb);
        QCOMPARE(map.colorSpace, ColorEncoding::Linear);
        if (warning.isEmpty())
            QVERIFY2(warnings.empty(), warnings.c_str());
        else
            QVERIFY2(QString::fromStdString(warnings).contains(warning), warnings.c_str());
    }

    // KHR_materials_iridescence: factor (default 0: no film), index (1.3) and thickness range
    // (100 to 400 nm; the minimum may exceed the maximum); the strength its texture's R, the
    // thickness its own texture's G, both linear; values beyond the ranges clamped and fields of the
    // wrong type refused, each with a note naming the field.
    void iridescence_data()
    {
        QTest::addColumn<QByteArray>("iridescence"); // the extension's object
        QTest::addColumn<double>("factor");
        QTest::addColumn<double>("ior");
        QTest::addColumn<double>("minimum");
        QTest::addColumn<double>("maximum");
        QTest::addColumn<QString>("strengthFile"); // the textures', or empty
        QTest::addColumn<QString>("thicknessFile");
        QTest::addColumn<QString>("warning"); // part of the notes, or empty for none
        const auto row = [](const char* name, const char* json, double factor, double ior, double minimum,
                             double maximum, const char* strengthFile, const char* thicknessFile,
                             const char* warning) {
            QTest::newRow(name) << QByteArray(json) << factor << ior << minimum << maximum
                                << QString::fromLatin1(strengthFile) << QString::fromLatin1(thicknessFile)
                                << QString::fromLatin1(warning);
        };
        row("every field", R"({"iridescenceFactor": 0.7, "iridescenceIor": 1.8, "iridescenceThicknessMinimum": 200,
            "iridescenceThicknessMaximum": 650})",
            0.7, 1.8, 200.0, 650.0, "", "", "");
        row("empty (the extension's defaults)", "{}", 0.0, 1.3, 100.0, 400.0, "", "", "");
        row("minimum above the maximum", R"({"iridescenceFactor": 1, "iridescenceThicknessMinimum": 900,
            "iridescenceThicknessMaximum": 300})",
            1.0, 1.3, 900.0, 300.0, "", "", "");
        row("one texture for both", R"({"iridescenceFactor": 1, "iridescenceTexture": {"index": 0},
            "iridescenceThicknessTexture": {"index": 0}})",
            1.0, 1.3, 100.0, 400.0, "a.png", "a.png", "");
        row("a thickness texture alone", R"({"iridescenceFactor": 0.5, "iridescenceThicknessTexture": {"index": 1}})",
            0.5, 1.3, 100.0, 400.0, "", "b.png", "");
        row("factor a string", R"({"iridescenceFactor": "oily"})", 0.0, 1.3, 100.0, 400.0, "", "",
            "KHR_materials_iridescence.iridescenceFactor is not a number: 0 used");
        row("factor above 1", R"({"iridescenceFactor": 2})", 1.0, 1.3, 100.0, 400.0, "", "",
            "KHR_materials_iridescence.iridescenceFactor 2 is outside Facet's [0, 1]: 1 used");
        row("index below 1", R"({"iridescenceFactor": 1, "iridescenceIor": 0.5})", 1.0, 1.0, 100.0, 400.0, "", "",
            "KHR_materials_iridescence.iridescenceIor 0.5 is outside Facet's [1, 5]: 1 used");
        row("negative thickness", R"({"iridescenceFactor": 1, "iridescenceThicknessMaximum": -5})", 1.0, 1.3, 100.0,
            0.0, "", "", "KHR_materials_iridescence.iridescenceThicknessMaximum -5 is outside Facet's");
        row("thickness texture that does not exist",
            R"({"iridescenceFactor": 1, "iridescenceThicknessTexture": {"index": 9}})", 1.0, 1.3, 100.0, 400.0, "",
            "", "KHR_materials_iridescence.iridescenceThicknessTexture names texture 9, which does not exist");
    }
    void iridescence()
    {
        QFETCH(QByteArray, iridescence);
        QFETCH(double, factor);
        QFETCH(double, ior);
        QFETCH(double, minimum);
        QFETCH(double, maximum);
        QFETCH(QString, strengthFile);
        QFETCH(QString, thicknessFile);
        QFETCH(QString, warning);
        GltfWriter w;
        QVERIFY(addTwoRgbaTextures(w));
        std::string error, warnings;
        const auto asset = importWithExtension(
            w, "Film", "KHR_materials_iridescence", iridescence, QStringLiteral("film.gltf"), &error, &warnings);
        QVERIFY2(asset, error.c_str());
        const Material& m = asset->materials.at(0);
        std::string problem;
        QVERIFY2(m.validate(&problem), problem.c_str());
        QVERIFY2(near(m.iridescence(), factor), qPrintable(QString::number(m.iridescence())));
        QVERIFY2(near(m.iridescenceIor, ior), qPrintable(QString::number(m.iridescenceIor)));
        QVERIFY2(near(m.iridescenceThicknessMinimum, minimum), qPrintable(QString::number(m.iridescenceThicknessMinimum)));
        QVERIFY2(near(m.iridescenceThicknessMaximum(), maximum),
            qPrintable(QString::number(m.iridescenceThicknessMaximum())));
        const MaterialMap& strength = m.map(MapSlot::Iridescence);
        const MaterialMap& thickness = m.map(MapSlot::IridescenceThickness);
        QCOMPARE(QString::fromStdString(strength.path), strengthFile.isEmpty() ? QString() : path(strengthFile));
        QCOMPARE(QString::fromStdString(thickness.path), thicknessFile.isEmpty() ? QString() : path(thicknessFile));
        QCOMPARE(strength.channel, MapChannel::R);
        QCOMPARE(thickness.channel, MapChannel::G);
        QCOMPARE(strength.colorSpace, ColorEncoding::Linear);
        QCOMPARE(thickness.colorSpace, ColorEncoding::Linear);
        if (warning.isEmpty())
            QVERIFY2(warnings.empty(), warnings.c_str());
        else
            QVERIFY2(QString::fromStdString(warnings).contains(warning), warnings.c_str());
    }
};

QTEST_GUILESS_MAIN(GltfExtensionsTest)
#include "GltfExtensionsTest.moc"
