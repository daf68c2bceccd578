// The project file on disk: built-in specs and paths as stored, paths on another volume, moving a
// project folder, missing and unreadable files, and saves that fail leaving the old file intact.
// (Split from ProjectTest, which holds the format itself.)

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonObject>
#include <QStorageInfo>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include "core/project/Project.h"

using namespace facet;

namespace {
QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}
bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

QByteArray readAll(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

bool writeAll(const QString& path, const QByteArray& data)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(data) == data.size();
}
} // namespace

class ProjectFilesTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void specsKeepBuiltinNames()
    {
        QCOMPARE(json::storedSpec("studio", "/a/b"), std::string("studio"));
        QCOMPARE(json::storedSpec("uniform:0.5,0.5,0.5", "/a/b"), std::string("uniform:0.5,0.5,0.5"));
        QCOMPARE(json::resolvedSpec("uniform:1", "/a/b"), std::string("uniform:1"));
        QCOMPARE(json::resolvedSpec("sky", "/a/b"), std::string("sky"));
        // A file whose relative path would read as a built-in name keeps a "./".
        QCOMPARE(json::storedSpec("/a/b/studio", "/a/b"), std::string("./studio"));
        QCOMPARE(json::resolvedSpec("./studio", "/a/b"), std::string("/a/b/studio"));
        QCOMPARE(json::resolvedSpec("room.exr", "/a/b"), std::string("/a/b/room.exr"));
        QCOMPARE(json::storedPath("/a/b/c/d.png", "/a/b"), std::string("c/d.png"));
        QCOMPARE(json::storedPath("/a/x.png", "/a/b"), std::string("../x.png"));
        QCOMPARE(json::storedPath("/a/x.png", ""), std::string("/a/x.png"));
        QCOMPARE(json::storedPath("", "/a/b"), std::string());
        QCOMPARE(json::resolvedPath("../x.png", "/a/b"), std::string("/a/x.png"));
        QCOMPARE(json::resolvedPath("/abs/x.png", "/a/b"), std::string("/abs/x.png"));
    }

    void pathsOnAnotherVolumeStayAbsolute()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        // /proc is its own file system on Linux; if it shares the temporary folder's volume here,
        // there is no second volume to test with.
        const QStorageInfo proc(QStringLiteral("/proc/self"));
        const QStorageInfo temp(dir.path());
        if (!proc.isValid() || !temp.isValid() || proc.rootPath() == temp.rootPath())
            QSKIP("no second volume to test with");
        QCOMPARE(json::storedPath("/proc/self/status", dir.path().toStdString()),
            std::string("/proc/self/status"));
        QCOMPARE(json::resolvedPath("/proc/self/status", dir.path().toStdString()),
            std::string("/proc/self/status"));
    }

    void movingTheProjectFolderKeepsTexturesFound()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString before = QDir(dir.path()).filePath(QStringLiteral("before"));
        const QString after = QDir(dir.path()).filePath(QStringLiteral("elsewhere/after"));
        Project p = Project::defaultProject();
        p.material().map(MapSlot::BaseColor).path
            = QDir(before).filePath(QStringLiteral("tex/albedo.png")).toStdString();
        p.material().map(MapSlot::Normal).path
            = QDir(before).filePath(QStringLiteral("tex/normal.png")).toStdString();
        p.environment.source = QDir(before).filePath(QStringLiteral("env.exr")).toStdString();
        QVERIFY(writeAll(QDir(before).filePath(QStringLiteral("tex/albedo.png")), "png"));
        QVERIFY(writeAll(QDir(before).filePath(QStringLiteral("tex/normal.png")), "png"));
        QVERIFY(writeAll(QDir(before).filePath(QStringLiteral("env.exr")), "exr"));
        std::string error;
        QVERIFY2(
            p.save(QDir(before).filePath(QStringLiteral("p.json")).toStdString(), &error), error.c_str());

        QVERIFY(QDir().mkpath(QFileInfo(after).absolutePath()));
        QVERIFY(QDir().rename(before, after));
        const std::optional<Project> loaded
            = Project::load(QDir(after).filePath(QStringLiteral("p.json")).toStdString(), &error);
        QVERIFY2(loaded, error.c_str());
        for (MapSlot slot : {MapSlot::BaseColor, MapSlot::Normal}) {
            const QString texture = qs(loaded->material().map(slot).path);
            QVERIFY2(texture.startsWith(after) && QFileInfo::exists(texture), qPrintable(texture));
        }
        QVERIFY(QFileInfo::exists(qs(loaded->environment.source)));
        QVERIFY(loaded->material().map(MapSlot::Metallic).path.empty());
    }

    void missingAndUnreadableFiles()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        std::string error;
        const QString missing = QDir(dir.path()).filePath(QStringLiteral("missing.json"));
        QVERIFY(!Project::load(missing.toStdString(), &error));
        QVERIFY2(
            contains(error, "Project::load: " + missing.toStdString() + ": no such file"), error.c_str());

        QVERIFY(!Project::load(dir.path().toStdString(), &error));
        QVERIFY2(contains(error, "is a folder"), error.c_str());

        QVERIFY(!Project::load({}, &error));
        QVERIFY2(contains(error, "Project::load"), error.c_str());

        const QString locked = QDir(dir.path()).filePath(QStringLiteral("locked.json"));
        QVERIFY(writeAll(locked, R"({"format": "facet-project", "version": 1})"));
        QVERIFY(QFile::setPermissions(locked, QFileDevice::WriteOwner));
        QFile probe(locked);
        if (probe.open(QIODevice::ReadOnly))
            QSKIP("running with permission to read any file (root): cannot test an unreadable file");
        QVERIFY(!Project::load(locked.toStdString(), &error));
        QVERIFY2(contains(error, "locked.json: cannot read it"), error.c_str());
    }

    // A file is read up to its limit and refused one byte over it, whatever its size; the reader
    // grows its buffer as bytes arrive (it allocated the whole limit for every file before).
    void sizeLimitIsExact_data()
    {
        constexpr qint64 kLimit = qint64(2) << 20;
        QTest::addColumn<qint64>("limit");
        QTest::addColumn<qint64>("size");
        QTest::addColumn<QString>("expected"); // "" when the object reads
        const QString tooLarge = QStringLiteral("the file is larger than 2 MiB, too large to be a Facet file");
        QTest::newRow("a few bytes") << kLimit << qint64(16) << QString();
        QTest::newRow("64 KiB (one read step)") << kLimit << qint64(64 * 1024) << QString();
        QTest::newRow("64 KiB + 1") << kLimit << qint64(64 * 1024 + 1) << QString();
        QTest::newRow("at the limit") << kLimit << kLimit << QString();
        QTest::newRow("one byte over") << kLimit << kLimit + 1 << tooLarge;
        QTest::newRow("ten times the limit") << kLimit << 10 * kLimit << tooLarge;
        QTest::newRow("only white space") << kLimit << qint64(1000) << QStringLiteral("the file is empty");
        QTest::newRow("a project at Project::kMaxFileBytes")
            << Project::kMaxFileBytes << Project::kMaxFileBytes << QString();
        QTest::newRow("a project one byte over")
            << Project::kMaxFileBytes << Project::kMaxFileBytes + 1
            << QStringLiteral("the file is larger than 16 MiB, too large to be a Facet file");
    }
    void sizeLimitIsExact()
    {
        QFETCH(qint64, limit);
        QFETCH(qint64, size);
        QFETCH(QString, expected);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = QDir(dir.path()).filePath(QStringLiteral("sized.json"));
        // An object padded with spaces to `size` bytes (all spaces for the empty row).
        QByteArray content = expected.endsWith(QStringLiteral("empty")) ? QByteArray() : QByteArray("{\"a\": 1}");
        QVERIFY(content.size() <= size);
        content.append(QByteArray(size - content.size(), ' '));
        QVERIFY(writeAll(path, content));
        QCOMPARE(QFileInfo(path).size(), size);

        std::string problem;
        const std::optional<QJsonObject> object = json::readObjectFile(path.toStdString(), limit, &problem);
        if (expected.isEmpty()) {
            QVERIFY2(object, problem.c_str());
            QCOMPARE(object->value(QStringLiteral("a")).toInt(), 1);
        } else {
            QVERIFY(!object);
            QCOMPARE(qs(problem), expected);
        }
    }

    void failedSaveLeavesTheOriginalUntouched()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString folder = QDir(dir.path()).filePath(QStringLiteral("work"));
        QVERIFY(QDir().mkpath(folder));
        const QString path = QDir(folder).filePath(QStringLiteral("keep.json"));
        std::string error;
        QVERIFY2(Project::defaultProject().save(path.toStdString(), &error), error.c_str());
        const QByteArray original = readAll(path);
        QVERIFY(!original.isEmpty());

        // An invalid project is refused before anything is written.
        Project invalid = Project::defaultProject();
        invalid.lights.push_back(Light {});
        invalid.lights.back().intensity = -5.0;
        QVERIFY(!invalid.save(path.toStdString(), &error));
        QVERIFY2(
            contains(error, "Project::save: " + path.toStdString()) && contains(error, "lights[0].intensity"),
            error.c_str());
        QCOMPARE(readAll(path), original);

        // A folder that does not exist.
        const QString nowhere = QDir(dir.path()).filePath(QStringLiteral("no/such/folder/p.json"));
        QVERIFY(!Project::defaultProject().save(nowhere.toStdString(), &error));
        QVERIFY2(
            contains(error, "Project::save: " + nowhere.toStdString()) && contains(error, "does not exist"),
            error.c_str());
        QVERIFY(!QFileInfo::exists(nowhere));

        // A folder path given as the file.
        QVERIFY(!Project::defaultProject().save(folder.toStdString(), &error));
        QVERIFY(QFileInfo(folder).isDir());

        // A read-only folder: the save fails and the old file survives, with no temporary left.
        Project changed = Project::defaultProject();
        changed.material().name = "Changed";
        QVERIFY(QFile::setPermissions(folder, QFileDevice::ReadOwner | QFileDevice::ExeOwner));
        QFile probe(QDir(folder).filePath(QStringLiteral("probe")));
        const bool folderStillWritable = probe.open(QIODevice::WriteOnly);
        if (folderStillWritable) {
            probe.close();
            probe.remove();
        }
        bool saved = false;
        if (!folderStillWritable)
            saved = changed.save(path.toStdString(), &error);
        QVERIFY(QFile::setPermissions(
            folder, QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner));
        if (folderStillWritable)
            QSKIP("running with permission to write anywhere (root): cannot test a read-only folder");
        QVERIFY(!saved);
        QVERIFY2(
            contains(error, "Project::save: " + path.toStdString() + ": cannot write it"), error.c_str());
        QCOMPARE(readAll(path), original);
        QCOMPARE(
            QDir(folder).entryList(QDir::Files | QDir::Hidden), QStringList {QStringLiteral("keep.json")});
    }
};

QTEST_GUILESS_MAIN(ProjectFilesTest)
#include "ProjectFilesTest.moc"
