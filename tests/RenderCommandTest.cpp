// `facet render` as scripts drive it: the executable run with no display server, its errors and
// exit codes, and the ways of naming what it renders (environments, library files, debug views,
// the default project's method), each read back from its output. What the images must show (the
// furnaces, core's integrator, the maps, glTF assets): RenderCommandImageTest.

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>
#include <QProcessEnvironment>
#include <QSettings>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <glm/geometric.hpp>

#include "GltfWriter.h"
#include "RunFacet.h"
#include "TestSupport.h"
#include "core/image/Image.h"
#include "core/shading/ReferenceView.h"

#include <optional>
#include <vector>

#include <sys/stat.h>

using namespace facet;
using facet::test::runFacet;
using facet::test::strings;
using facet::test::writeText;

namespace {

using Result = facet::test::ProcessResult;

// A QStringList from literals (QT_NO_CAST_FROM_ASCII forbids the implicit conversion).

// A project file holding only an environment source, a mesh and a debug view.
QByteArray projectJson(const QString& source, const QString& mesh = QStringLiteral("sphere"),
    const QString& debugView = QStringLiteral("none"))
{
    return QStringLiteral(
        "{\"format\": \"facet-project\", \"version\": 1, \"environment\": {\"source\": \"%1\"}, "
        "\"view\": {\"mesh\": \"%2\", \"debugView\": \"%3\"}}")
        .arg(source, mesh, debugView)
        .toUtf8();
}

} // namespace

class RenderCommandTest : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    QString path(const QString& name) const { return m_dir.filePath(name); }

    // The child's asset libraries: this test's installed samples and user settings only.
    QProcessEnvironment libraryEnvironment() const
    {
        QProcessEnvironment extra;
        extra.insert(QStringLiteral("FACET_ASSETS_DIR"), path(QStringLiteral("assets")));
        extra.insert(QStringLiteral("XDG_CONFIG_HOME"), path(QStringLiteral("config")));
        extra.insert(QStringLiteral("FACET_CACHE_DIR"), path(QStringLiteral("library-ibl-cache")));
        return extra;
    }
    // {dir} in an argument is this test's folder.
    QStringList expand(QStringList arguments) const
    {
        for (QString& argument : arguments)
            argument.replace(QLatin1String("{dir}"), m_dir.path());
        return arguments;
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        // Installed samples: a night and a "studio" of a radiance the built-in studio never has.
        QVERIFY(facet::test::writeConstantExr(path(QStringLiteral("assets/hdri/night.exr")), 0.25f));
        QVERIFY(facet::test::writeConstantExr(path(QStringLiteral("assets/hdri/studio.exr")), 5.0f));
        // A user library "my-hdris", as the window's Add Folder registers it (QSettings of facet).
        QVERIFY(facet::test::writeConstantExr(path(QStringLiteral("My HDRIs/loft.exr")), 2.0f));
        QSettings settings(path(QStringLiteral("config/Facet/facet.conf")), QSettings::IniFormat);
        settings.beginWriteArray(QStringLiteral("assetLibraries"), 1);
        settings.setArrayIndex(0);
        settings.setValue(QStringLiteral("name"), QStringLiteral("my-hdris"));
        settings.setValue(QStringLiteral("folder"), path(QStringLiteral("My HDRIs")));
        settings.endArray();
        settings.sync();
        QCOMPARE(settings.status(), QSettings::NoError);
        // Projects naming library files, in folders of different depths.
        QVERIFY(writeText(path(QStringLiteral("projects/installed.json")),
            projectJson(QStringLiteral("library:installed/hdri/night.exr"))));
        QVERIFY(writeText(path(QStringLiteral("projects/a/b/c/user.json")),
            projectJson(QStringLiteral("library:my-hdris/loft.exr"))));
        QVERIFY(writeText(path(QStringLiteral("projects/gone.json")),
            projectJson(QStringLiteral("library:installed/hdri/gone.exr"))));
        QVERIFY(writeText(path(QStringLiteral("projects/unknown-library.json")),
            projectJson(QStringLiteral("library:nobody/x.exr"))));
        QVERIFY(writeText(path(QStringLiteral("projects/gone-mesh.json")),
            projectJson(QStringLiteral("uniform:1"), QStringLiteral("library:installed/models/gone.glb"))));
        QVERIFY(writeText(path(QStringLiteral("projects/bad-view.json")),
            projectJson(QStringLiteral("uniform:1"), QStringLiteral("sphere"), QStringLiteral("bogus"))));
        QVERIFY(writeText(path(QStringLiteral("projects/old-view.json")),
            projectJson(QStringLiteral("uniform:1"), QStringLiteral("sphere"), QStringLiteral("d"))));
        QVERIFY(writeText(path(QStringLiteral("projects/new-view.json")),
            projectJson(
                QStringLiteral("uniform:1"), QStringLiteral("sphere"), QStringLiteral("distribution"))));
    }

    // Every way of naming an environment renders that environment: the background of the ground
    // truth's corner pixels is its radiance. `studio` stays the built-in procedural one.
    void environmentSpecsRender_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<double>("radiance"); // < 0: the built-in studio (not a constant)
        const QString loft = path(QStringLiteral("My HDRIs/loft.exr"));
        QTest::newRow("installed reference")
            << strings({"--env", "library:installed/hdri/night.exr"}) << 0.25;
        QTest::newRow("user library reference") << strings({"--env", "library:my-hdris/loft.exr"}) << 2.0;
        QTest::newRow("absolute path") << QStringList {QStringLiteral("--env"), loft} << 2.0;
        QTest::newRow("relative path")
            << QStringList {QStringLiteral("--env"), QDir::current().relativeFilePath(loft)} << 2.0;
        QTest::newRow("uniform") << strings({"--env", "uniform:0.5"}) << 0.5;
        QTest::newRow("installed sample by name") << strings({"--env", "night"}) << 0.25;
        QTest::newRow("studio is built-in") << strings({"--env", "studio"}) << -1.0;
        QTest::newRow("project, installed") << strings({"{dir}/projects/installed.json"}) << 0.25;
        QTest::newRow("project deeper, user library") << strings({"{dir}/projects/a/b/c/user.json"}) << 2.0;
    }
    void environmentSpecsRender()
    {
        QFETCH(QStringList, arguments);
        QFETCH(double, radiance);
        const QString out = path(QStringLiteral("spec.exr"));
        QFile::remove(out);
        const Result r = runFacet(QStringList {QStringLiteral("render")} + expand(arguments)
                + QStringList {QStringLiteral("--spp"), QStringLiteral("1"), QStringLiteral("--size"),
                    QStringLiteral("8x8"), QStringLiteral("-o"), out},
            libraryEnvironment());
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        std::string error;
        const auto image = Image::load(out.toStdString(), &error);
        QVERIFY2(image, error.c_str());
        QVERIFY(!referenceview::intersectSphere(referenceview::rayDirection(0, 0, 8, 8)));
        const float corner = image->at(0, 0).g;
        if (radiance < 0.0)
            QVERIFY2(std::abs(corner - 5.0f) > 0.5f && image->at(0, 0) != image->at(0, 7),
                qPrintable(QString::number(corner)));
        else
            QVERIFY2(std::abs(corner - float(radiance)) < 1e-3f, qPrintable(QString::number(corner)));
    }

    // A library file missing on this machine: the message names it and says how to get it.
    void missingLibraryFilesAreNamed_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QStringList>("mentions");
        QTest::newRow("project, installed sample") << strings({"{dir}/projects/gone.json", "--spp", "1"})
                                                   << strings({"gone.exr", "packaging/fetch-assets.sh"});
        QTest::newRow("project, gpu path")
            << strings({"{dir}/projects/gone.json"}) << strings({"gone.exr", "packaging/fetch-assets.sh"});
        QTest::newRow("project, unknown library") << strings({"{dir}/projects/unknown-library.json"})
                                                  << strings({"x.exr", "\"nobody\"", "Add Folder"});
        QTest::newRow("project, installed mesh") << strings({"{dir}/projects/gone-mesh.json"})
                                                 << strings({"gone.glb", "packaging/fetch-assets.sh"});
        QTest::newRow("--env reference")
            << strings({"--env", "library:installed/hdri/gone.exr", "--spp", "1"})
            << strings({"gone.exr", "packaging/fetch-assets.sh"});
        QTest::newRow("--env bare name, no such sample")
            << strings({"--env", "gone", "--spp", "1"})
            << strings({"gone: no such file", "studio and sky", "installed samples are night, studio"});
    }
    void missingLibraryFilesAreNamed()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QStringList, mentions);
        const QString out = path(QStringLiteral("never.exr"));
        const Result r = runFacet(QStringList {QStringLiteral("render")} + expand(arguments)
                + QStringList {QStringLiteral("--size"), QStringLiteral("8x8"), QStringLiteral("-o"), out},
            libraryEnvironment());
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.startsWith(QStringLiteral("facet render: ")));
        for (const QString& part : mentions)
            QVERIFY2(r.err.contains(part), qPrintable(part + QStringLiteral(" not in: ") + r.err));
        QVERIFY(!QFile::exists(out));
    }

    // Descriptive debug view names and the old one-letter ones render the same view, and not the
    // shaded image (an unknown name used to fall back to it silently).
    void debugViewNamesAndAliases_data()
    {
        QTest::addColumn<QStringList>("name");
        QTest::addColumn<QStringList>("alias");
        QTest::newRow("distribution") << strings({"--view", "distribution"}) << strings({"--view", "d"});
        QTest::newRow("visibility") << strings({"--view", "visibility"}) << strings({"--view", "v"});
        QTest::newRow("fresnel") << strings({"--view", "fresnel"}) << strings({"--view", "f"});
        QTest::newRow("project's old name")
            << strings({"{dir}/projects/new-view.json"}) << strings({"{dir}/projects/old-view.json"});
    }
    void debugViewNamesAndAliases()
    {
        QFETCH(QStringList, name);
        QFETCH(QStringList, alias);
        const QStringList common {QStringLiteral("--env"), QStringLiteral("uniform:1"),
            QStringLiteral("--quality"), QStringLiteral("draft"), QStringLiteral("--size"),
            QStringLiteral("16x16"), QStringLiteral("--reference-view")};
        std::optional<Image> images[3];
        // The same request with the shaded image (the last --view wins).
        const QStringList variants[3]
            = {name, alias, name + QStringList {QStringLiteral("--view"), QStringLiteral("none")}};
        for (int i = 0; i < 3; ++i) {
            const QString out = path(QStringLiteral("view-%1.exr").arg(i));
            const Result r = runFacet(QStringList {QStringLiteral("render")} + expand(variants[i]) + common
                    + QStringList {QStringLiteral("-o"), out},
                libraryEnvironment());
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
            std::string error;
            images[i] = Image::load(out.toStdString(), &error);
            QVERIFY2(images[i], error.c_str());
        }
        int differsFromShaded = 0;
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                QVERIFY2(images[1]->at(x, y) == images[0]->at(x, y),
                    qPrintable(QStringLiteral("(%1,%2)").arg(x).arg(y)));
                differsFromShaded += images[0]->at(x, y) != images[2]->at(x, y);
            }
        QVERIFY2(differsFromShaded > 20, qPrintable(QString::number(differsFromShaded)));
    }

    // Accurate by default (issue 29): with no lighting flag, the default project renders by fis at
    // 1024 samples (the suite's other tests set $FACET_NEW_PROJECT_METHOD=split-sum); a
    // project file that names no method keeps the split sum.
    void defaultProjectRendersByFis()
    {
        const QByteArray saved = qgetenv("FACET_NEW_PROJECT_METHOD");
        qunsetenv("FACET_NEW_PROJECT_METHOD");
        const QString out = path(QStringLiteral("default-method.png"));
        const Result r = runFacet({QStringLiteral("render"), QStringLiteral("--reference-view"),
            QStringLiteral("--size"), QStringLiteral("24x24"), QStringLiteral("--quality"),
            QStringLiteral("draft"), QStringLiteral("--stats"), QStringLiteral("-o"), out});
        const QString project = path(QStringLiteral("no-method.json"));
        QFile file(project);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(
            R"({"format": "facet-project", "version": 3, "materials": [{}], "environment": {"source": "studio"}})");
        file.close();
        const Result fromFile = runFacet({QStringLiteral("render"), project, QStringLiteral("--size"),
            QStringLiteral("24x24"), QStringLiteral("--quality"), QStringLiteral("draft"),
            QStringLiteral("--stats"), QStringLiteral("-o"), out});
        // --ibl names the method with its own default count: the default project's 1024 is fis's.
        const Result splitSum = runFacet({QStringLiteral("render"), QStringLiteral("--ibl"),
            QStringLiteral("split-sum"), QStringLiteral("--size"), QStringLiteral("24x24"),
            QStringLiteral("--stats"), QStringLiteral("-o"), out});
        const Result fis = runFacet({QStringLiteral("render"), QStringLiteral("--ibl"), QStringLiteral("fis"),
            QStringLiteral("--size"), QStringLiteral("24x24"), QStringLiteral("--stats"),
            QStringLiteral("-o"), out});
        qputenv("FACET_NEW_PROJECT_METHOD", saved);
        QVERIFY2(splitSum.exitCode == 0 && splitSum.out.contains(QStringLiteral("ibl_method: split-sum\n")),
            qPrintable(splitSum.err + splitSum.out));
        QVERIFY2(fis.exitCode == 0 && fis.out.contains(QStringLiteral("ibl_samples: 256\n")),
            qPrintable(fis.err + fis.out));
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("ibl_method: fis\n"))
                && r.out.contains(QStringLiteral("ibl_samples: 1024\n")),
            qPrintable(r.out));
        QVERIFY2(fromFile.exitCode == 0, qPrintable(fromFile.err));
        QVERIFY2(fromFile.out.contains(QStringLiteral("ibl_method: split-sum\n")), qPrintable(fromFile.out));
    }

    void badInputGivesClearErrors_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QString>("message");
        const QString out = QStringLiteral("never-written.exr");
        QTest::newRow("no output") << QStringList {QStringLiteral("render")} << 2
                                   << QStringLiteral("-o OUT.exr");
        QTest::newRow("bad extension")
            << QStringList {QStringLiteral("render"), QStringLiteral("-o"), QStringLiteral("x.jpg")} << 2
            << QStringLiteral("must be .exr");
        QTest::newRow("roughness range") << QStringList {QStringLiteral("render"),
            QStringLiteral("--roughness"), QStringLiteral("1.5"), QStringLiteral("-o"), out}
                                         << 2 << QStringLiteral("--roughness: 1.5 is outside [0, 1]");
        QTest::newRow("metallic nan") << QStringList {QStringLiteral("render"), QStringLiteral("--metallic"),
            QStringLiteral("nan"), QStringLiteral("-o"), out}
                                      << 2 << QStringLiteral("--metallic: 'nan' is not a number");
        QTest::newRow("base colour") << QStringList {QStringLiteral("render"), QStringLiteral("--base-color"),
            QStringLiteral("1,1"), QStringLiteral("-o"), out}
                                     << 2 << QStringLiteral("--base-color: '1,1' is not r,g,b");
        QTest::newRow("size") << QStringList {QStringLiteral("render"), QStringLiteral("--size"),
            QStringLiteral("0x10"), QStringLiteral("-o"), out}
                              << 2 << QStringLiteral("--size: '0x10'");
        QTest::newRow("spp") << QStringList {QStringLiteral("render"), QStringLiteral("--spp"),
            QStringLiteral("-3"), QStringLiteral("-o"), out}
                             << 2 << QStringLiteral("--spp: '-3'");
        QTest::newRow("brdf") << QStringList {QStringLiteral("render"), QStringLiteral("--brdf"),
            QStringLiteral("phong"), QStringLiteral("-o"), out}
                              << 2 << QStringLiteral("--brdf: 'phong' is not gltf or learnopengl");
        QTest::newRow("multiscatter") << QStringList {QStringLiteral("render"),
            QStringLiteral("--multiscatter"), QStringLiteral("maybe"), QStringLiteral("-o"), out}
                                      << 2 << QStringLiteral("--multiscatter: 'maybe' is not on or off");
        QTest::newRow("preset") << QStringList {QStringLiteral("render"), QStringLiteral("--material"),
            QStringLiteral("unobtainium"), QStringLiteral("-o"), out}
                                << 2 << QStringLiteral("no preset 'unobtainium'");
        QTest::newRow("quality") << QStringList {QStringLiteral("render"), QStringLiteral("--quality"),
            QStringLiteral("ultra"), QStringLiteral("-o"), out}
                                 << 2 << QStringLiteral("--quality: 'ultra'");
        QTest::newRow("missing project") << QStringList {QStringLiteral("render"),
            QStringLiteral("no-such.json"), QStringLiteral("-o"), out}
                                         << 1 << QStringLiteral("no-such.json");
        QTest::newRow("missing environment") << QStringList {QStringLiteral("render"),
            QStringLiteral("--env"), QStringLiteral("/no/such/env.exr"), QStringLiteral("--spp"),
            QStringLiteral("4"), QStringLiteral("-o"), out}
                                             << 1 << QStringLiteral("/no/such/env.exr");
        QTest::newRow("uniform garbage") << QStringList {QStringLiteral("render"), QStringLiteral("--env"),
            QStringLiteral("uniform:-1"), QStringLiteral("--spp"), QStringLiteral("4"), QStringLiteral("-o"),
            out} << 2 << QStringLiteral("environment.source: uniform:-1"); // a bad flag value: a usage error
        QTest::newRow("unknown debug view")
            << QStringList {QStringLiteral("render"), QStringLiteral("--view"), QStringLiteral("bogus"),
                   QStringLiteral("-o"), out}
            << 2
            << QStringLiteral("--view: unknown debug view 'bogus' (expected one of: "
                              "none, base-color, ");
        QTest::newRow("project's unknown debug view")
            << QStringList {QStringLiteral("render"), path(QStringLiteral("projects/bad-view.json")),
                   QStringLiteral("-o"), out}
            << 1
            << QStringLiteral(
                   "bad-view.json: view.debugView: unknown debug view \"bogus\" (expected one of: none, ");
        QTest::newRow("ibl method") << QStringList {QStringLiteral("render"), QStringLiteral("--ibl"),
            QStringLiteral("path-tracing"), QStringLiteral("-o"),
            out} << 2 << QStringLiteral("--ibl: 'path-tracing' is not split-sum, fis or reference");
        QTest::newRow("ibl samples zero")
            << QStringList {QStringLiteral("render"), QStringLiteral("--ibl"), QStringLiteral("reference"),
                   QStringLiteral("--ibl-samples"), QStringLiteral("0"), QStringLiteral("-o"), out}
            << 2 << QStringLiteral("--ibl-samples: '0' is not a whole number from 1 to 65536");
        QTest::newRow("ibl samples with the split sum")
            << QStringList {QStringLiteral("render"), QStringLiteral("--ibl"), QStringLiteral("split-sum"),
                   QStringLiteral("--ibl-samples"), QStringLiteral("64"), QStringLiteral("-o"), out}
            << 2 << QStringLiteral("--ibl-samples: 64 given with --ibl split-sum");
        QTest::newRow("ibl with spp") << QStringList {QStringLiteral("render"), QStringLiteral("--ibl"),
            QStringLiteral("reference"), QStringLiteral("--spp"), QStringLiteral("16"), QStringLiteral("-o"),
            out} << 2 << QStringLiteral("give one or the other");
        QTest::newRow("ground truth mesh") << QStringList {QStringLiteral("render"), QStringLiteral("--mesh"),
            QStringLiteral("cube"), QStringLiteral("--spp"), QStringLiteral("4"), QStringLiteral("-o"), out}
                                           << 2 << QStringLiteral("reference sphere only");
    }
    void badInputGivesClearErrors()
    {
        QFETCH(QStringList, arguments);
        QFETCH(int, exitCode);
        QFETCH(QString, message);
        // Run inside the temporary directory so that nothing could be written anywhere else.
        QStringList args = arguments;
        for (QString& a : args)
            if (a == QStringLiteral("never-written.exr"))
                a = path(a);
        const Result r = runFacet(args);
        QCOMPARE(r.exitCode, exitCode);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY(r.err.startsWith(QStringLiteral("facet render: ")));
        QVERIFY(r.out.isEmpty());
        QVERIFY(!QFile::exists(path(QStringLiteral("never-written.exr"))));
    }

    void unwritableOutputFails()
    {
        const Result r = runFacet(
            {QStringLiteral("render"), QStringLiteral("--spp"), QStringLiteral("1"), QStringLiteral("--size"),
                QStringLiteral("8x8"), QStringLiteral("-o"), QStringLiteral("/no/such/dir/out.exr")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("/no/such/dir/out.exr")), qPrintable(r.err));
    }

    // Broken assets: a message naming the file and the problem, the right exit code, no crash.
    void badGltfAssetsGiveClearErrors_data()
    {
        QTest::addColumn<QString>("defect");
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QString>("message");
        QTest::newRow("missing image")
            << QStringLiteral("missing-image") << 1 << QStringLiteral("nope.png: no such file");
        QTest::newRow("image that is not an image")
            << QStringLiteral("not-an-image") << 1 << QStringLiteral("fake.png");
        QTest::newRow("wrong accessor")
            << QStringLiteral("accessor") << 1 << QStringLiteral("reach past the end");
        QTest::newRow("texture index out of range") << QStringLiteral(
            "texture-index") << 0 << QStringLiteral("names texture 9, which does not exist");
        QTest::newRow(".glb cut in half") << QStringLiteral("cut") << 1 << QStringLiteral("cut short");
        QTest::newRow("not glTF at all")
            << QStringLiteral("garbage") << 1 << QStringLiteral("not a readable glTF file");
    }
    void badGltfAssetsGiveClearErrors()
    {
        using facet::test::GltfWriter;
        QFETCH(QString, defect);
        QFETCH(int, exitCode);
        QFETCH(QString, message);
        QDir(m_dir.path()).mkpath(defect);
        const QString folder = path(defect);
        GltfWriter w;
        QJsonObject values;
        if (defect == QLatin1String("missing-image"))
            values[QLatin1String("baseColorTexture")] = QJsonObject {
                {QStringLiteral("index"), w.addTexture(w.addImageUri(QStringLiteral("nope.png")))}};
        else if (defect == QLatin1String("not-an-image")) {
            QFile fake(folder + QStringLiteral("/fake.png"));
            QVERIFY(fake.open(QIODevice::WriteOnly) && fake.write("this is text, not a PNG\n") > 0);
            values[QLatin1String("baseColorTexture")] = QJsonObject {
                {QStringLiteral("index"), w.addTexture(w.addImageUri(QStringLiteral("fake.png")))}};
        } else if (defect == QLatin1String("texture-index"))
            values[QLatin1String("baseColorTexture")] = QJsonObject {{QStringLiteral("index"), 9}};
        QJsonObject material;
        material[QLatin1String("pbrMetallicRoughness")] = values;
        w.addNode(w.addQuad(w.addMaterial(material)));
        if (defect == QLatin1String("accessor")) {
            QJsonArray accessors = w.json()[QLatin1String("accessors")].toArray();
            QJsonObject a = accessors[0].toObject();
            a[QLatin1String("count")] = 100000;
            accessors[0] = a;
            w.json()[QLatin1String("accessors")] = accessors;
        }
        const QString asset = folder + QStringLiteral("/asset.glb");
        QVERIFY(w.write(asset, GltfWriter::BufferStorage::Glb));
        if (defect == QLatin1String("cut") || defect == QLatin1String("garbage")) {
            QFile file(asset);
            QVERIFY(file.open(QIODevice::ReadWrite));
            if (defect == QLatin1String("cut"))
                QVERIFY(file.resize(file.size() / 2));
            else
                QVERIFY(file.resize(0) && file.write("this is not a model") > 0);
        }
        const QString out = folder + QStringLiteral("/out.exr");
        const Result r = runFacet({QStringLiteral("render"), asset, QStringLiteral("--reference-view"),
            QStringLiteral("--quality"), QStringLiteral("draft"), QStringLiteral("--size"),
            QStringLiteral("16x16"), QStringLiteral("-o"), out});
        QVERIFY2(
            r.exitCode == exitCode, qPrintable(QStringLiteral("exit %1: %2").arg(r.exitCode).arg(r.err)));
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY2(r.err.contains(asset) || r.err.contains(folder), qPrintable(r.err)); // names the file
        QCOMPARE(QFile::exists(out), exitCode == 0);
    }

    // Issue 29's crash and hang through the command line: a glTF nested 20 000 levels deep (as
    // the asset, as --mesh, as a project's mesh, as a project's texture reference into it), and
    // $OCIO naming a FIFO, a folder or a device. Each is refused with the file named, exit 1, no
    // output (before: a stack overflow, and a render that never returned).
    void hostileInputsAreRefused_data()
    {
        QTest::addColumn<QString>("input");
        QTest::addColumn<QString>("message");
        const QString deep = QStringLiteral("nest deeper than 256 levels");
        QTest::newRow("deep glTF as the asset") << QStringLiteral("asset") << deep;
        QTest::newRow("deep glTF as --mesh") << QStringLiteral("--mesh") << deep;
        QTest::newRow("deep glTF as a project's mesh") << QStringLiteral("project-mesh") << deep;
        QTest::newRow("deep glTF as a project's texture") << QStringLiteral("project-map") << deep;
        QTest::newRow("$OCIO a FIFO") << QStringLiteral("ocio-fifo") << QStringLiteral("not a regular file");
        QTest::newRow("$OCIO a folder") << QStringLiteral("ocio-folder") << QStringLiteral("folder");
        QTest::newRow("$OCIO a device")
            << QStringLiteral("ocio-device") << QStringLiteral("not a regular file");
    }
    void hostileInputsAreRefused()
    {
        using facet::test::GltfWriter;
        QFETCH(QString, input);
        QFETCH(QString, message);
        const QString folder = path(QStringLiteral("hostile-") + input);
        QVERIFY(QDir().mkpath(folder));
        // A textured quad whose "extras" nest 20 000 arrays deep (a 40 KB file).
        GltfWriter w;
        QJsonObject values;
        values[QLatin1String("baseColorTexture")] = QJsonObject {{QStringLiteral("index"),
            w.addTexture(w.addImageEmbedded(
                facet::test::encodePng(2, 2, 3, std::vector<glm::vec4>(4, glm::vec4(0.5f))),
                QStringLiteral("image/png")))}};
        QJsonObject material;
        material[QLatin1String("pbrMetallicRoughness")] = values;
        w.addNode(w.addQuad(w.addMaterial(material)));
        w.json()[QLatin1String("extras")] = QStringLiteral("DEEP");
        const QString asset = folder + QStringLiteral("/deep.gltf");
        QVERIFY(w.write(asset, GltfWriter::BufferStorage::DataUri));
        QFile file(asset);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QByteArray text = file.readAll();
        file.close();
        text.replace("\"DEEP\"", QByteArray(20000, '[') + QByteArray(20000, ']'));
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate) && file.write(text) == text.size());
        file.close();

        const QString out = folder + QStringLiteral("/out.png");
        QStringList arguments {QStringLiteral("render")};
        QProcessEnvironment environment;
        QString named = asset;
        if (input == QLatin1String("asset")) {
            arguments << asset;
        } else if (input == QLatin1String("--mesh")) {
            arguments << QStringLiteral("--mesh") << asset;
        } else if (input.startsWith(QLatin1String("project-"))) {
            const QString project = folder + QStringLiteral("/p.json");
            const QByteArray json = input == QLatin1String("project-mesh")
                ? projectJson(QStringLiteral("uniform:1"), asset)
                : QStringLiteral("{\"format\": \"facet-project\", \"version\": 1, \"environment\": "
                                 "{\"source\": \"uniform:1\"}, \"materials\": [{\"name\": \"m\", "
                                 "\"baseColor\": {\"texture\": \"%1#images/0\"}}]}")
                      .arg(asset)
                      .toUtf8();
            QVERIFY(writeText(project, json));
            arguments << project;
        } else {
            named = folder + QStringLiteral("/config.ocio");
            if (input == QLatin1String("ocio-fifo"))
                QVERIFY(::mkfifo(QFile::encodeName(named).constData(), 0600) == 0);
            else if (input == QLatin1String("ocio-folder"))
                QVERIFY(QDir().mkpath(named));
            else
                named = QStringLiteral("/dev/zero");
            environment.insert(QStringLiteral("OCIO"), named);
            // The config is read when a project's view asks for an OCIO display.
            const QString project = folder + QStringLiteral("/p.json");
            QVERIFY(writeText(project,
                "{\"format\": \"facet-project\", \"version\": 1, \"view\": {\"ocioDisplay\": \"sRGB - "
                "Display\", "
                "\"ocioView\": \"ACES 1.0 - SDR Video\"}}"));
            arguments << project;
        }
        arguments << QStringLiteral("--env") << QStringLiteral("uniform:1") << QStringLiteral("--size")
                  << QStringLiteral("16x16") << QStringLiteral("--quality") << QStringLiteral("draft")
                  << QStringLiteral("-o") << out;
        const Result r = runFacet(arguments, environment);
        QVERIFY2(r.exitCode == 1, qPrintable(QStringLiteral("exit %1: %2").arg(r.exitCode).arg(r.err)));
        QVERIFY2(r.err.contains(message) && r.err.contains(named), qPrintable(r.err));
        QVERIFY(!QFile::exists(out));
    }
};

QTEST_GUILESS_MAIN(RenderCommandTest)
#include "RenderCommandTest.moc"
