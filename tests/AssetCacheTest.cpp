// core/project/AssetCache: environments and meshes loaded once for a batch of frames (a contact sheet's
// cells), again when their file changes, and errors passed through with the loader's message.

#include "core/project/AssetCache.h"
#include "core/project/Project.h"
#include "core/project/ProjectAssets.h"

#include "TestSupport.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <filesystem>

using namespace facet;

class AssetCacheTest : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    QString path(const QString& name) const { return m_dir.filePath(name); }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QVERIFY(facet::test::writeConstantExr(path(QStringLiteral("a.exr")), 0.5f));
        QVERIFY(facet::test::writeConstantExr(path(QStringLiteral("b.exr")), 2.0f));
    }

    void environmentsLoadOnce_data()
    {
        QTest::addColumn<QStringList>("specs"); // asked for in this order
        QTest::addColumn<int>("loads");
        QTest::newRow("one file, three times") << QStringList {QStringLiteral("{dir}/a.exr"), QStringLiteral("{dir}/a.exr"),
            QStringLiteral("{dir}/a.exr")} << 1;
        QTest::newRow("two files, twice each")
            << QStringList {QStringLiteral("{dir}/a.exr"), QStringLiteral("{dir}/b.exr"), QStringLiteral("{dir}/a.exr"),
                   QStringLiteral("{dir}/b.exr")}
            << 2;
        QTest::newRow("built-in and uniform") << QStringList {QStringLiteral("studio"), QStringLiteral("uniform:1"),
            QStringLiteral("studio"), QStringLiteral("uniform:1"), QStringLiteral("uniform:2")} << 3;
    }

    void environmentsLoadOnce()
    {
        QFETCH(QStringList, specs);
        QFETCH(int, loads);
        AssetCache cache;
        for (QString spec : specs) {
            spec.replace(QLatin1String("{dir}"), m_dir.path());
            std::string error;
            const auto environment = cache.environment(spec.toStdString(), &error);
            QVERIFY2(environment, error.c_str());
            QVERIFY(!environment->isEmpty());
        }
        QCOMPARE(cache.environmentLoads(), loads);
    }

    void changedFileLoadsAgain()
    {
        AssetCache cache;
        const QString file = path(QStringLiteral("changing.exr"));
        QVERIFY(facet::test::writeConstantExr(file, 1.0f));
        std::string error;
        const auto first = cache.environment(file.toStdString(), &error);
        QVERIFY2(first, error.c_str());
        QVERIFY(facet::test::writeConstantExr(file, 3.0f));
        // A later modification time, whatever the file system's resolution.
        std::filesystem::last_write_time(file.toStdString(),
            std::filesystem::last_write_time(file.toStdString()) + std::chrono::seconds(2));
        const auto second = cache.environment(file.toStdString(), &error);
        QVERIFY2(second, error.c_str());
        QCOMPARE(cache.environmentLoads(), 2);
        QVERIFY(second->contentHash() != first->contentHash());
        QCOMPARE(second->image().at(0, 0).r, 3.0f);
    }

    void errorsNameTheFile()
    {
        AssetCache cache;
        std::string error;
        QVERIFY(!cache.environment(path(QStringLiteral("missing.exr")).toStdString(), &error));
        QVERIFY2(error.find("missing.exr") != std::string::npos, error.c_str());
        error.clear();
        QVERIFY(!cache.mesh(path(QStringLiteral("missing.obj")).toStdString(), &error));
        QVERIFY2(error.find("missing.obj") != std::string::npos, error.c_str());
    }

    void projectsShareTheirAssets()
    {
        // Two cells: one environment, one mesh between them, loaded once; map-less materials.
        AssetCache cache;
        Project a = Project::defaultProject();
        a.environment.source = path(QStringLiteral("a.exr")).toStdString();
        a.environment.intensity = 2.0;
        Project b = a;
        b.environment.rotationDegrees = 90.0;
        b.environment.intensity = 1.0;
        std::string error;
        const auto first = loadProjectAssets(a, cache, &error);
        QVERIFY2(first, error.c_str());
        const auto second = loadProjectAssets(b, cache, &error);
        QVERIFY2(second, error.c_str());
        QCOMPARE(cache.environmentLoads(), 1);
        QCOMPARE(cache.meshLoads(), 1);
        QCOMPARE(first->mesh.get(), second->mesh.get());
        QCOMPARE(first->meshKey, second->meshKey);
        // Each keeps its own rotation and intensity over the shared pixels.
        QCOMPARE(&first->environment.image(), &second->environment.image());
        QCOMPARE(first->environment.intensity(), 2.0);
        QCOMPARE(second->environment.rotationDegrees(), 90.0);
    }
};

QTEST_GUILESS_MAIN(AssetCacheTest)
#include "AssetCacheTest.moc"
