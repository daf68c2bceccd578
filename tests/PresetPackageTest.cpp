// core/material/PresetPackage: a material preset with its textures as one folder, carried between two
// preset libraries: exported from one (a packed file read by three slots copied once, an image
// embedded in a .glb written out), installed into another under a unique id, and exported again
// from there: the material's parameters equal and every texture's bytes the original's. Refused
// with the file named: a missing texture, a package that reaches outside itself, one with a
// texture gone, an existing package without `replace`, a full disk (nothing left behind).

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <filesystem>

#include "FullVolume.h"
#include "TestAssets.h"
#include "TestSupport.h"
#include "core/gltf/GltfImport.h"
#include "core/material/PresetPackage.h"
#include "core/project/Project.h"

using namespace facet;
using facet::test::FullVolume;

namespace {

// Every field but the texture paths.
Material withoutPaths(Material material)
{
    for (const MapSlot slot : kAllMapSlots)
        material.map(slot).path = material.map(slot).path.empty() ? "" : "texture";
    return material;
}

QByteArray bytesOf(const std::string& path)
{
    if (const std::optional<GltfImageReference> reference = parseGltfImageReference(path)) {
        std::string mime, error;
        const std::optional<std::vector<unsigned char>> bytes = readGltfImage(*reference, &mime, &error);
        return bytes ? QByteArray(reinterpret_cast<const char*>(bytes->data()), qsizetype(bytes->size()))
                     : QByteArray();
    }
    return test::fileBytes(QString::fromStdString(path));
}

} // namespace

class PresetPackageTest : public QObject {
    Q_OBJECT
public:
    static void initMain() { FullVolume::isolateMounts(); }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_sources.isValid());
        const QString project = test::writeTexturedProject(m_sources.path());
        QVERIFY(!project.isEmpty());
        std::string error;
        const std::optional<Project> loaded = Project::load(project.toStdString(), &error);
        QVERIFY2(loaded, error.c_str());
        m_preset.id = "brick-wall";
        m_preset.displayName = "Brick Wall";
        m_preset.material = loaded->materials[0]; // base colour, normal, one ORM file for three slots
        m_preset.material.ior = 1.52;
        m_preset.material.map(MapSlot::Normal).flipGreen = true;
        m_preset.material.map(MapSlot::BaseColor).uv.scale = glm::dvec2(2.0, 2.0);
        // The emissive map: an image embedded in a .glb.
        QString problem;
        const QString glb = m_sources.filePath(QStringLiteral("showcase.glb"));
        QVERIFY2(test::writeShowcaseAsset(glb, &problem), qPrintable(problem));
        m_preset.material.map(MapSlot::Emissive).path = gltfImageReference(glb.toStdString(), 0);
        m_preset.material.map(MapSlot::Emissive).factor = glm::dvec4(1.0);
    }

    void betweenTwoLibraries()
    {
        QTemporaryDir libraryA, outbox, libraryB, outbox2, libraryC;
        std::string error;
        // Library A holds the package; it goes out, into B, out of B again, into C.
        const std::optional<std::string> inA
            = exportPresetPackage(m_preset, libraryA.path().toStdString(), false, &error);
        QVERIFY2(inA, error.c_str());
        QCOMPARE(QString::fromStdString(*inA), libraryA.filePath(QStringLiteral("brick-wall.facetpreset")));
        // Four texture files (the ORM file once), and the index.
        QCOMPARE(QDir(QString::fromStdString(*inA)).entryList(QDir::Files, QDir::Name),
            test::strings({"baseColor-brick_base.png", "emissive-showcase-image0.png",
                "metallic-brick_orm.png", "normal-brick_normal.png", "preset.json"}));
        // Paths in the index are relative: the folder moves as a whole.
        QFile index(QString::fromStdString(*inA) + QStringLiteral("/preset.json"));
        QVERIFY(index.open(QIODevice::ReadOnly));
        QVERIFY(!index.readAll().contains(libraryA.path().toUtf8()));

        const std::optional<std::string> inB
            = installPresetPackage(*inA, libraryB.path().toStdString(), &error);
        QVERIFY2(inB, error.c_str());
        const std::optional<MaterialPreset> fromB = loadPresetPackage(*inB, &error);
        QVERIFY2(fromB, error.c_str());
        const std::optional<std::string> outOfB
            = exportPresetPackage(*fromB, outbox2.path().toStdString(), false, &error);
        QVERIFY2(outOfB, error.c_str());
        const std::optional<std::string> inC
            = installPresetPackage(*outOfB, libraryC.path().toStdString(), &error);
        QVERIFY2(inC, error.c_str());
        const std::optional<MaterialPreset> fromC = loadPresetPackage(*inC, &error);
        QVERIFY2(fromC, error.c_str());

        for (const MaterialPreset* preset : {&*fromB, &*fromC}) {
            QCOMPARE(preset->displayName, m_preset.displayName);
            QVERIFY(withoutPaths(preset->material) == withoutPaths(m_preset.material));
            for (const MapSlot slot : kAllMapSlots) {
                const std::string& original = m_preset.material.map(slot).path;
                if (original.empty())
                    continue;
                const std::string& copy = preset->material.map(slot).path;
                QVERIFY2(QString::fromStdString(copy).startsWith(
                             QString::fromStdString(preset == &*fromB ? *inB : *inC)),
                    copy.c_str());
                QCOMPARE(bytesOf(copy), bytesOf(original));
            }
            // Slots that read one file still read one file.
            QCOMPARE(
                preset->material.map(MapSlot::Roughness).path, preset->material.map(MapSlot::Occlusion).path);
        }
        // Out of B and out of C again: the same file names, no prefix piled on a prefix (issue 30:
        // "baseColor-baseColor-brick_base.png").
        QTemporaryDir outbox3;
        const std::optional<std::string> outOfC
            = exportPresetPackage(*fromC, outbox3.path().toStdString(), false, &error);
        QVERIFY2(outOfC, error.c_str());
        for (const std::string* package : {&*outOfB, &*outOfC})
            QCOMPARE(QDir(QString::fromStdString(*package)).entryList(QDir::Files, QDir::Name),
                test::strings({"baseColor-brick_base.png", "emissive-showcase-image0.png",
                    "metallic-brick_orm.png", "normal-brick_normal.png", "preset.json"}));
        // Installing again gets a new id, not a replacement.
        const std::optional<std::string> again
            = installPresetPackage(*inA, libraryB.path().toStdString(), &error);
        QVERIFY2(again, error.c_str());
        QCOMPARE(
            QString::fromStdString(*again), libraryB.filePath(QStringLiteral("brick-wall-2.facetpreset")));
        const std::optional<MaterialPreset> second = loadPresetPackage(*again, &error);
        QCOMPARE(second->id, std::string("brick-wall-2"));
    }

    void refusals()
    {
        QTemporaryDir dir;
        std::string error;
        // A texture that is not there: nothing written.
        MaterialPreset lost = m_preset;
        lost.material.map(MapSlot::Roughness).path = dir.filePath(QStringLiteral("gone.png")).toStdString();
        QVERIFY(!exportPresetPackage(lost, dir.path().toStdString(), false, &error));
        QVERIFY2(QString::fromStdString(error).contains(QStringLiteral("roughness: "))
                && QString::fromStdString(error).contains(QStringLiteral("gone.png")),
            error.c_str());
        QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("brick-wall.facetpreset"))));

        // An existing package is kept without `replace`.
        QVERIFY(exportPresetPackage(m_preset, dir.path().toStdString(), false, &error));
        QVERIFY(!exportPresetPackage(m_preset, dir.path().toStdString(), false, &error));
        QVERIFY2(QString::fromStdString(error).endsWith(QStringLiteral("brick-wall.facetpreset: exists")),
            error.c_str());
        QVERIFY2(exportPresetPackage(m_preset, dir.path().toStdString(), true, &error), error.c_str());

        // A package whose index reaches outside it, or lost a texture.
        const QString package = dir.filePath(QStringLiteral("brick-wall.facetpreset"));
        QFile file(package + QStringLiteral("/preset.json"));
        QVERIFY(file.open(QIODevice::ReadOnly));
        QJsonObject json = QJsonDocument::fromJson(file.readAll()).object();
        file.close();
        QJsonObject material = json.value(QStringLiteral("material")).toObject();
        QJsonObject base = material.value(QStringLiteral("baseColor")).toObject();
        base.insert(QStringLiteral("texture"), QStringLiteral("../outside.png"));
        material.insert(QStringLiteral("baseColor"), base);
        json.insert(QStringLiteral("material"), material);
        QVERIFY(test::writeText(dir.filePath(QStringLiteral("outside.png")), "x"));
        QVERIFY(test::writeText(package + QStringLiteral("/preset.json"), QJsonDocument(json).toJson()));
        QVERIFY(!loadPresetPackage(package.toStdString(), &error));
        QVERIFY2(QString::fromStdString(error).contains(QStringLiteral("outside.png is outside the package")),
            error.c_str());
        QVERIFY(exportPresetPackage(m_preset, dir.path().toStdString(), true, &error));
        QVERIFY(QFile::remove(package + QStringLiteral("/normal-brick_normal.png")));
        QVERIFY(!loadPresetPackage(package.toStdString(), &error));
        QVERIFY2(QString::fromStdString(error).contains(QStringLiteral("normal-brick_normal.png is missing")),
            error.c_str());
        QVERIFY(!loadPresetPackage(dir.path().toStdString(), &error));
        QVERIFY2(QString::fromStdString(error).contains(QStringLiteral("has no preset.json")), error.c_str());
    }

    void fullDiskLeavesNothing()
    {
        FullVolume volume(QString(), 64 * 1024);
        FACET_REQUIRE_FULL_VOLUME(volume);
        QVERIFY(volume.fill());
        std::string error;
        QVERIFY(!exportPresetPackage(m_preset, volume.path().toStdString(), false, &error));
        QVERIFY2(
            QString::fromStdString(error).contains(QStringLiteral("No space left on device")), error.c_str());
        QCOMPARE(volume.entries(), QStringList {});
    }

private:
    QTemporaryDir m_sources;
    MaterialPreset m_preset;
};

QTEST_GUILESS_MAIN(PresetPackageTest)
#include "PresetPackageTest.moc"
