// Asset libraries and how a project stores the files it uses (docs/project-format.md, "Paths"):
// library names, references and their errors; the round trip of every spec kind; projects that
// use an installed and a user-library file moved deeper and elsewhere; version-1 paths into the
// installed samples; a library or a library file this computer lacks, with advice on getting it;
// built-in names winning over installed samples of the same name. Needs nothing but files it
// writes (its own installed-samples folder through $FACET_ASSETS_DIR, its own settings).

#include <cmath>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include "TestSupport.h"
#include "core/ibl/Environment.h"
#include "core/project/AssetLibrary.h"
#include "core/project/Project.h"
#include "core/project/ProjectAssets.h"

using namespace facet;
using facet::test::strings;
using facet::test::writeText;

namespace {

QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}

// A QStringList from literals (QT_NO_CAST_FROM_ASCII forbids the implicit conversion).


// One triangle with a normal and no UVs: the smallest mesh importMesh takes.
const QByteArray kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n";

QJsonObject readJson(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(file.readAll()).object();
}

} // namespace

class LibraryPathsTest : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_installed; // this test's installed samples ($FACET_ASSETS_DIR)
    QString m_user; // a user library folder, "My HDRIs"
    QString m_work; // projects live under here

    // {installed}, {user}, {work} and {project} (m_work/project) replaced by this test's folders.
    QString expand(QString text) const
    {
        text.replace(QLatin1String("{installed}"), m_installed);
        text.replace(QLatin1String("{user}"), m_user);
        text.replace(QLatin1String("{project}"), m_work + QStringLiteral("/project"));
        text.replace(QLatin1String("{work}"), m_work);
        return text;
    }

public:
    static void initMain() { QStandardPaths::setTestModeEnabled(true); }

private Q_SLOTS:
    void initTestCase()
    {
        QCoreApplication::setOrganizationName(QStringLiteral("FacetTests"));
        QSettings().remove(QStringLiteral("assetLibraries"));
        QVERIFY(m_dir.isValid());
        m_installed = m_dir.filePath(QStringLiteral("installed-assets"));
        m_user = m_dir.filePath(QStringLiteral("My HDRIs"));
        m_work = m_dir.filePath(QStringLiteral("work"));
        qputenv("FACET_ASSETS_DIR", m_installed.toLocal8Bit());
        QVERIFY(test::writeConstantExr(m_installed + QStringLiteral("/hdri/night.exr"), 0.25f));
        // An installed sample with a built-in's name, of a radiance the built-in never has.
        QVERIFY(test::writeConstantExr(m_installed + QStringLiteral("/hdri/studio.exr"), 5.0f));
        QVERIFY(writeText(m_installed + QStringLiteral("/models/tri.obj"), kTriangleObj));
        QVERIFY(test::writeConstantExr(m_user + QStringLiteral("/loft.exr"), 2.0f));
        QVERIFY(writeText(m_user + QStringLiteral("/chair.obj"), kTriangleObj));
        std::string error;
        const auto library = AssetLibrary::addUserLibrary(m_user.toStdString(), &error);
        QVERIFY2(library, error.c_str());
        QCOMPARE(qs(library->name), QStringLiteral("my-hdris"));
        // Adding it again keeps its library and name.
        QCOMPARE(qs(AssetLibrary::addUserLibrary(m_user.toStdString(), &error)->name), QStringLiteral("my-hdris"));
        QCOMPARE(AssetLibrary::userLibraries().size(), std::size_t(1));
        QCOMPARE(qs(AssetLibrary::installed().folder), m_installed);
    }

    void cleanupTestCase()
    {
        QSettings().remove(QStringLiteral("assetLibraries"));
        qunsetenv("FACET_ASSETS_DIR");
    }

    void libraryNames_data()
    {
        QTest::addColumn<QString>("folder");
        QTest::addColumn<QStringList>("taken");
        QTest::addColumn<QString>("name");
        QTest::newRow("words") << "/x/My HDRIs" << QStringList {} << "my-hdris";
        QTest::newRow("punctuation runs") << "/x/HDRIs (2k)__final" << QStringList {} << "hdris-2k-final";
        QTest::newRow("trailing slash") << "/x/Skies/" << QStringList {} << "skies";
        QTest::newRow("nothing usable") << "/x/___" << QStringList {} << "library";
        QTest::newRow("reserved") << "/x/installed" << QStringList {} << "installed-2";
        QTest::newRow("taken") << "/y/skies" << strings({"skies"}) << "skies-2";
        QTest::newRow("taken twice") << "/z/skies" << strings({"skies", "skies-2"}) << "skies-3";
    }
    void libraryNames()
    {
        QFETCH(QString, folder);
        QFETCH(QStringList, taken);
        QFETCH(QString, name);
        std::vector<AssetLibrary> libraries;
        for (const QString& other : taken)
            libraries.push_back({AssetLibrary::Kind::User, other.toStdString(), "/elsewhere/" + other.toStdString()});
        const std::string made = AssetLibrary::nameForFolder(folder.toStdString(), libraries);
        QCOMPARE(qs(made), name);
        QVERIFY(AssetLibrary::isValidName(made));
    }

    void referencesResolve_data()
    {
        QTest::addColumn<QString>("spec");
        QTest::addColumn<QString>("path"); // empty: an error containing `problem`
        QTest::addColumn<QString>("problem");
        QTest::newRow("installed") << "library:installed/hdri/night.exr" << "{installed}/hdri/night.exr" << "";
        QTest::newRow("user") << "library:my-hdris/loft.exr" << "{user}/loft.exr" << "";
        QTest::newRow("file need not exist") << "library:my-hdris/later.exr" << "{user}/later.exr" << "";
        QTest::newRow("cleaned") << "library:installed/hdri/./x/../night.exr" << "{installed}/hdri/night.exr" << "";
        QTest::newRow("unknown library") << "library:nobody/x.exr" << ""
                                         << "library:nobody/x.exr: no library named \"nobody\" on this machine";
        QTest::newRow("climbs out") << "library:my-hdris/../secret.exr" << "" << "no \"..\"";
        QTest::newRow("absolute inside") << "library:my-hdris//etc/x.exr" << "" << "relative";
        QTest::newRow("no path") << "library:my-hdris" << "" << "expected a file path";
        QTest::newRow("bad name") << "library:My HDRIs/loft.exr" << "" << "\"My HDRIs\" is not a library name";
        QTest::newRow("no name") << "library:/loft.exr" << "" << "\"\" is not a library name";
    }
    void referencesResolve()
    {
        QFETCH(QString, spec);
        QFETCH(QString, path);
        QFETCH(QString, problem);
        std::string why;
        const std::optional<std::string> resolved = AssetLibrary::resolveSpec(spec.toStdString(), &why);
        if (path.isEmpty()) {
            QVERIFY(!resolved);
            QVERIFY2(qs(why).contains(problem), why.c_str());
            return;
        }
        QVERIFY2(resolved, why.c_str());
        QCOMPARE(qs(*resolved), expand(path));
        // And back: the path of a library file gives a reference to the same file.
        const std::optional<std::string> back = AssetLibrary::specForPath(*resolved);
        QVERIFY(back);
        QCOMPARE(qs(AssetLibrary::resolveSpec(*back, nullptr).value_or("")), qs(*resolved));
    }

    // Every kind of spec, as the project holds it in memory and as the file stores it; loading
    // the file gives the same value back.
    void specRoundTrip_data()
    {
        QTest::addColumn<bool>("mesh"); // view.mesh, else environment.source
        QTest::addColumn<QString>("memory");
        QTest::addColumn<QString>("stored");
        QTest::newRow("built-in studio") << false << "studio" << "studio";
        QTest::newRow("built-in sky") << false << "sky" << "sky";
        QTest::newRow("uniform") << false << "uniform:1" << "uniform:1";
        QTest::newRow("uniform rgb") << false << "uniform:0.5,0.25,1" << "uniform:0.5,0.25,1";
        QTest::newRow("installed hdri") << false << "{installed}/hdri/night.exr" << "library:installed/hdri/night.exr";
        QTest::newRow("installed studio.exr") << false << "{installed}/hdri/studio.exr"
                                              << "library:installed/hdri/studio.exr";
        QTest::newRow("user library hdri") << false << "{user}/loft.exr" << "library:my-hdris/loft.exr";
        QTest::newRow("project file") << false << "{project}/env/local.exr" << "env/local.exr";
        QTest::newRow("sibling folder") << false << "{work}/shared/hall.exr" << "../shared/hall.exr";
        QTest::newRow("file called like a built-in") << false << "{project}/studio" << "./studio";
        QTest::newRow("file called like a reference") << false << "{project}/library:x/y.exr"
                                                      << "./library:x/y.exr";
        QTest::newRow("file called like uniform") << false << "{project}/uniform:2" << "./uniform:2";
        QTest::newRow("unknown library kept") << false << "library:nobody/x.exr" << "library:nobody/x.exr";
        QTest::newRow("built-in mesh") << true << "cube" << "cube";
        QTest::newRow("installed mesh") << true << "{installed}/models/tri.obj" << "library:installed/models/tri.obj";
        QTest::newRow("user library mesh") << true << "{user}/chair.obj" << "library:my-hdris/chair.obj";
        QTest::newRow("project mesh") << true << "{project}/meshes/m.obj" << "meshes/m.obj";
    }
    void specRoundTrip()
    {
        QFETCH(bool, mesh);
        QFETCH(QString, memory);
        QFETCH(QString, stored);
        Project project = Project::defaultProject();
        (mesh ? project.view.mesh : project.environment.source) = expand(memory).toStdString();
        const QString path = m_work + QStringLiteral("/project/p.json");
        QVERIFY(QDir().mkpath(QFileInfo(path).absolutePath()));
        std::string error;
        QVERIFY2(project.save(path.toStdString(), &error), error.c_str());
        const QJsonObject json = readJson(path);
        const QString written = mesh ? json[QLatin1String("view")][QLatin1String("mesh")].toString()
                                     : json[QLatin1String("environment")][QLatin1String("source")].toString();
        QCOMPARE(written, stored);
        const auto loaded = Project::load(path.toStdString(), &error);
        QVERIFY2(loaded, error.c_str());
        QCOMPARE(qs(mesh ? loaded->view.mesh : loaded->environment.source), expand(memory));
        // A recovery copy (no base folder) keeps the in-memory value as it is.
        const QJsonObject absolute = project.toJson();
        QCOMPARE(mesh ? absolute[QLatin1String("view")][QLatin1String("mesh")].toString()
                      : absolute[QLatin1String("environment")][QLatin1String("source")].toString(),
            expand(memory));
    }

    // A project using an installed sample and a user library's file, moved one folder deeper and
    // to another place, opens with the same files; its own files move with it.
    void projectMovesKeepLibraryFiles_data()
    {
        QTest::addColumn<QString>("environment");
        QTest::addColumn<QString>("mesh");
        QTest::addColumn<QString>("destination"); // the project folder's new place
        QTest::addColumn<QString>("expectedEnvironment");
        QTest::addColumn<QString>("expectedMesh");
        const QString installed = QStringLiteral("{installed}/hdri/night.exr");
        const QString user = QStringLiteral("{user}/loft.exr");
        const QString installedMesh = QStringLiteral("{installed}/models/tri.obj");
        const QString userMesh = QStringLiteral("{user}/chair.obj");
        QTest::newRow("installed, deeper") << installed << userMesh << "{work}/a/b/moved" << installed << userMesh;
        QTest::newRow("installed, elsewhere") << installed << userMesh << "{work}/../elsewhere/moved" << installed
                                             << userMesh;
        QTest::newRow("user library, deeper") << user << installedMesh << "{work}/a/b/moved" << user << installedMesh;
        QTest::newRow("user library, elsewhere") << user << installedMesh << "{work}/../elsewhere/moved" << user
                                                 << installedMesh;
        QTest::newRow("project files move along") << "{work}/original/env/local.exr" << "{work}/original/m.obj"
                                                  << "{work}/a/b/moved" << "{work}/a/b/moved/env/local.exr"
                                                  << "{work}/a/b/moved/m.obj";
    }
    void projectMovesKeepLibraryFiles()
    {
        QFETCH(QString, environment);
        QFETCH(QString, mesh);
        QFETCH(QString, destination);
        QFETCH(QString, expectedEnvironment);
        QFETCH(QString, expectedMesh);
        const QString original = m_work + QStringLiteral("/original");
        QDir(original).removeRecursively();
        QDir(expand(destination)).removeRecursively();
        QVERIFY(test::writeConstantExr(original + QStringLiteral("/env/local.exr"), 1.0f));
        QVERIFY(writeText(original + QStringLiteral("/m.obj"), kTriangleObj));
        Project project = Project::defaultProject();
        project.environment.source = expand(environment).toStdString();
        project.view.mesh = expand(mesh).toStdString();
        std::string error;
        QVERIFY2(project.save((original + QStringLiteral("/p.json")).toStdString(), &error), error.c_str());

        const QString moved = QDir::cleanPath(expand(destination));
        QVERIFY(QDir().mkpath(QFileInfo(moved).absolutePath()));
        QVERIFY(QDir().rename(original, moved));
        const auto loaded = Project::load((moved + QStringLiteral("/p.json")).toStdString(), &error);
        QVERIFY2(loaded, error.c_str());
        QCOMPARE(qs(loaded->environment.source), QDir::cleanPath(expand(expectedEnvironment)));
        QCOMPARE(qs(loaded->view.mesh), QDir::cleanPath(expand(expectedMesh)));
        QVERIFY(QFileInfo::exists(qs(loaded->environment.source)));
        QVERIFY(QFileInfo::exists(qs(loaded->view.mesh)));
        // And what the moved project names loads.
        const auto assets = loadProjectAssets(*loaded, &error);
        QVERIFY2(assets, error.c_str());
        QVERIFY(QDir(moved).removeRecursively());
    }

    // Version-1 files stored an installed sample as a path out of the project folder; once the
    // project moved, that path leads nowhere. It is read as the installed file of the same name.
    void versionOnePathsIntoSamples_data()
    {
        QTest::addColumn<QString>("stored");
        QTest::addColumn<QString>("expected");
        QTest::newRow("relative, moved deeper")
            << "../../home/olduser/.local/share/facet/assets/hdri/night.exr" << "{installed}/hdri/night.exr";
        QTest::newRow("absolute, another machine")
            << "/home/olduser/.local/share/facet/assets/hdri/night.exr" << "{installed}/hdri/night.exr";
        QTest::newRow("XDG data home") << "/data/xdg/facet/assets/hdri/night.exr" << "{installed}/hdri/night.exr";
        // Not rescued: the installed samples lack the file, or the path is not into the samples.
        QTest::newRow("sample not installed") << "/home/olduser/.local/share/facet/assets/hdri/gone.exr"
                                              << "/home/olduser/.local/share/facet/assets/hdri/gone.exr";
        QTest::newRow("not the samples") << "/home/olduser/hdri/night.exr" << "/home/olduser/hdri/night.exr";
    }
    void versionOnePathsIntoSamples()
    {
        QFETCH(QString, stored);
        QFETCH(QString, expected);
        const QString path = m_work + QStringLiteral("/v1/deeper/p.json");
        QJsonObject environment {{QStringLiteral("source"), stored}};
        QJsonObject object {{QStringLiteral("format"), QStringLiteral("facet-project")},
            {QStringLiteral("version"), 1}, {QStringLiteral("environment"), environment}};
        QVERIFY(writeText(path, QJsonDocument(object).toJson()));
        std::string error;
        const auto loaded = Project::load(path.toStdString(), &error);
        QVERIFY2(loaded, error.c_str());
        const QString expectedPath = expected.startsWith(QLatin1Char('{'))
            ? expand(expected)
            : QDir::cleanPath(QFileInfo(path).absoluteDir().absoluteFilePath(expected));
        QCOMPARE(qs(loaded->environment.source), expectedPath);
        // The next save writes the library reference.
        if (expected.startsWith(QLatin1String("{installed}"))) {
            QVERIFY2(loaded->save(path.toStdString(), &error), error.c_str());
            QCOMPARE(readJson(path)[QLatin1String("environment")][QLatin1String("source")].toString(),
                QStringLiteral("library:installed/hdri/night.exr"));
        }
    }

    // A file that cannot be found says, when it belongs to a library, which one and how to get it.
    void missingFilesSayHowToGetThem_data()
    {
        QTest::addColumn<bool>("mesh");
        QTest::addColumn<QString>("spec");
        QTest::addColumn<QStringList>("mentions");
        QTest::addColumn<QStringList>("absent");
        QTest::newRow("installed reference")
            << false << "library:installed/hdri/gone.exr"
            << strings({"gone.exr", "installed CC0 samples", "packaging/fetch-assets.sh"}) << QStringList {};
        QTest::newRow("installed path") << false << "{installed}/hdri/gone.exr"
                                        << strings({"gone.exr", "library:installed/hdri/gone.exr",
                                               "packaging/fetch-assets.sh", "FACET_ASSETS_DIR"})
                                        << QStringList {};
        QTest::newRow("unknown library") << false << "library:nobody/x.exr"
                                         << strings({"no library named \"nobody\"", "Add Folder", "relink"})
                                         << strings({"fetch-assets"});
        QTest::newRow("user library lacks it") << false << "library:my-hdris/gone.exr"
                                               << strings({"\"my-hdris\"", "has no gone.exr"})
                                               << strings({"fetch-assets"});
        QTest::newRow("installed sample by bare name") << false << "night"
                                                       << strings({"library:installed/hdri/night.exr"})
                                                       << QStringList {};
        QTest::newRow("plain file") << false << "/nowhere/x.exr" << strings({"/nowhere/x.exr", "no such file"})
                                    << strings({"fetch-assets", "library"});
        QTest::newRow("installed mesh") << true << "library:installed/models/gone.glb"
                                        << strings({"gone.glb", "packaging/fetch-assets.sh"}) << QStringList {};
        QTest::newRow("mesh of an unknown library")
            << true << "library:nobody/m.obj" << strings({"no library named \"nobody\"", "Add Folder"})
            << QStringList {};
        QTest::newRow("plain mesh") << true << "/nowhere/m.obj" << strings({"/nowhere/m.obj"})
                                    << strings({"fetch-assets", "library"});
    }
    void missingFilesSayHowToGetThem()
    {
        QFETCH(bool, mesh);
        QFETCH(QString, spec);
        QFETCH(QStringList, mentions);
        QFETCH(QStringList, absent);
        std::string error;
        const bool loaded = mesh ? bool(loadViewMesh(expand(spec).toStdString(), &error))
                                 : bool(Environment::fromSpec(expand(spec).toStdString(), &error));
        QVERIFY(!loaded);
        for (const QString& part : mentions)
            QVERIFY2(qs(error).contains(part), qPrintable(part + QStringLiteral(" not in: ") + qs(error)));
        for (const QString& part : absent)
            QVERIFY2(!qs(error).contains(part), qPrintable(part + QStringLiteral(" in: ") + qs(error)));
    }

    // What each spec loads: `studio` and `sky` are the built-in procedural environments even when
    // installed samples of those names exist; references load the library's file.
    void specsLoadTheirSource_data()
    {
        QTest::addColumn<QString>("spec");
        QTest::addColumn<double>("radiance"); // < 0: not a constant (the built-in)
        QTest::newRow("built-in studio wins") << "studio" << -1.0;
        QTest::newRow("installed studio.exr") << "library:installed/hdri/studio.exr" << 5.0;
        QTest::newRow("installed night.exr") << "library:installed/hdri/night.exr" << 0.25;
        QTest::newRow("user library") << "library:my-hdris/loft.exr" << 2.0;
        QTest::newRow("absolute path") << "{user}/loft.exr" << 2.0;
        QTest::newRow("uniform") << "uniform:3" << 3.0;
    }
    void specsLoadTheirSource()
    {
        QFETCH(QString, spec);
        QFETCH(double, radiance);
        std::string error;
        const auto environment = Environment::fromSpec(expand(spec).toStdString(), &error);
        QVERIFY2(environment, error.c_str());
        const glm::dvec3 up = environment->radiance(glm::dvec3(0.0, 1.0, 0.0));
        const glm::dvec3 side = environment->radiance(glm::dvec3(1.0, 0.0, 0.0));
        if (radiance < 0.0) {
            QCOMPARE(qs(environment->name()), spec);
            QVERIFY2(up != side, test::describe(up).c_str()); // procedural, not a constant
            QVERIFY(std::abs(up.x - 5.0) > 0.5);
        } else {
            QVERIFY2(std::abs(up.x - radiance) < 1e-6 && std::abs(side.y - radiance) < 1e-6,
                test::describe(up).c_str());
        }
        const auto mesh = loadViewMesh("library:installed/models/tri.obj", &error);
        QVERIFY2(mesh, error.c_str());
    }
};

QTEST_GUILESS_MAIN(LibraryPathsTest)
#include "LibraryPathsTest.moc"
