// glTF material extensions as the importer reads them (core/gltf/GltfMaterials): a row per
// extension, per field and per kind of bad value (out of range, the wrong type, a texture Facet
// does not read yet): the material's value, and the warning that names the file, the material
// and the field; the mesh import of the same file says nothing of the materials.

#include "core/gltf/GltfImport.h"
#include "core/mesh/MeshImport.h"

#include "GltfWriter.h"
#include "TestSupport.h"

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

bool near(double a, double b, double tolerance = 1e-6)
{
    return std::abs(a - b) <= tolerance;
}

} // namespace

class GltfExtensionsTest : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    QString path(const QString& name) const { return m_dir.filePath(name); }

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
        row("clearcoat texture",
            R"({"KHR_materials_clearcoat": {"clearcoatFactor": 1, "clearcoatTexture": {"index": 0}}})", 1.0,
            0.0, 1.5, "KHR_materials_clearcoat.clearcoatTexture is not read yet");
        row("clearcoat normal texture",
            R"({"KHR_materials_clearcoat": {"clearcoatFactor": 1, "clearcoatNormalTexture": {"index": 0}}})",
            1.0, 0.0, 1.5, "KHR_materials_clearcoat.clearcoatNormalTexture is not read yet");
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
        QVERIFY(near(m.clearcoat.factor, clearcoat));
        QVERIFY(near(m.clearcoat.roughness, clearcoatRoughness));
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
};

QTEST_GUILESS_MAIN(GltfExtensionsTest)
#include "GltfExtensionsTest.moc"
