// No file is lost on a full disk (issue 12, "A saved project can be lost", "A rendered PNG can be
// lost"): every writer of Facet, tried on a small tmpfs filled to the last byte. Each row: the old
// file is byte-identical afterwards, no temporary is left behind, the message names the file and
// says "No space left on device"; then, with room again, the same write succeeds (so a row cannot
// pass because the writer always fails). Also the primitive itself, core/support/AtomicFile.h, on an
// ordinary folder: what it replaces, keeps and refuses.
//
// The volumes live in a mount namespace of this process (tests/support/FullVolume.h); where none
// can be made, the full-disk rows skip locally and fail under CI=true.

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <map>

#include <sys/stat.h>

#include "FullVolume.h"
#include "TestSupport.h"
#include "core/ibl/IblDiskCache.h"
#include "core/image/Image.h"
#include "core/material/MaterialPresets.h"
#include "core/project/Project.h"
#include "core/support/AtomicFile.h"

using namespace facet;
using facet::test::fileBytes;
using facet::test::FullVolume;

namespace {

// Every writer of core, with an "old" (variant 0) and a "new" (variant 1) content for it.
enum class Writer {
    Primitive, // writeFileAtomically itself
    ProjectSmall, // Project::save of the default project (17.7 KB since the sheen's maps)
    ProjectLarge, // Project::save, of 25 materials
    // savePreset (ui/document/UserPresets): under QFileDevice's 16 KiB buffer, the case QSaveFile
    // lost (every project is over it since the material has eleven maps)
    Preset,
    RecoveryFile, // json::writeObjectFile, as Document::writeRecoveryFile (the autosave) uses it
    IblCache, // IblDiskCache::store
    Image, // Image::save, by the file name's extension
};

constexpr qint64 kQtWriteBuffer = 16 * 1024;

bool contains(const std::string& text, const QString& part)
{
    return text.find(part.toStdString()) != std::string::npos;
}

// `extraMaterials` more materials make the file larger (each ~1.5 KiB of JSON).
Project projectVariant(int variant, int extraMaterials)
{
    Project project = Project::defaultProject();
    project.material().name = variant == 0 ? "Old" : "New";
    project.material().setFactor(MapSlot::Roughness, variant == 0 ? 0.3 : 0.7);
    for (int i = 0; i < extraMaterials; ++i) {
        project.materials.push_back(project.materials.front());
        project.materials.back().name = "Extra " + std::to_string(i);
        project.materials.back().setFactor(MapSlot::Metallic, 1.0 / (1.0 + i));
    }
    return project;
}

IblCacheEntry cacheEntry(int variant)
{
    IblCacheEntry entry;
    IblCacheLayer cube;
    cube.width = 8;
    cube.height = 8;
    cube.faces = 6;
    for (std::size_t i = 0; i < cube.valueCount(); ++i)
        cube.half.push_back(std::uint16_t(i * 37u + 5u + std::size_t(variant)));
    entry.layers.push_back(cube);
    entry.extra = {double(variant), 2.5};
    return entry;
}

facet::Image imageVariant(int variant)
{
    // The new image is bigger and noisy, so no encoder can squeeze it into a few bytes.
    const int size = variant == 0 ? 4 : 48;
    facet::Image image(size, size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const float noise = float((x * 7919 + y * 104729) % 251) / 250.0f;
            image.at(x, y) = glm::vec4(noise, 1.0f - noise, float(x) / float(size), 1.0f);
        }
    return image;
}

std::uint64_t cacheKeyOf(const QString& path)
{
    return QFileInfo(path).completeBaseName().toULongLong(nullptr, 16);
}

// Writes variant 0 or 1 of `writer`'s content to `path`. IblCache: `path` is a cache file
// (<16 hex digits>.fibl) of a cache in its folder.
bool writeWith(Writer writer, const QString& path, int variant, std::string* error)
{
    const std::string file = path.toStdString();
    switch (writer) {
    case Writer::Primitive: {
        const std::string bytes(variant == 0 ? 100 : 3000, variant == 0 ? 'o' : 'n');
        std::string reason;
        if (writeFileAtomically(file, bytes, &reason))
            return true;
        *error = file + ": " + reason;
        return false;
    }
    case Writer::ProjectSmall:
        return projectVariant(variant, 0).save(file, error);
    case Writer::ProjectLarge:
        return projectVariant(variant, variant == 0 ? 0 : 24).save(file, error);
    case Writer::Preset: {
        MaterialPreset preset;
        preset.id = "mine";
        preset.displayName = variant == 0 ? "Old look" : "New look";
        preset.material = projectVariant(variant, 0).material();
        return savePreset(preset, file, error);
    }
    case Writer::RecoveryFile: {
        QJsonObject object = projectVariant(variant, 0).toJson();
        object[QStringLiteral("recoveredFrom")] = QStringLiteral("/somewhere/p.json");
        std::string problem;
        if (json::writeObjectFile(file, object, &problem))
            return true;
        *error = file + ": " + problem;
        return false;
    }
    case Writer::IblCache:
        return IblDiskCache(QFileInfo(path).absolutePath())
            .store(cacheKeyOf(path), cacheEntry(variant), error);
    case Writer::Image:
        return imageVariant(variant).save(file, error);
    }
    return false;
}

} // namespace

Q_DECLARE_METATYPE(Writer)

class SafeWriteTest : public QObject {
    Q_OBJECT
public:
    static void initMain() { FullVolume::isolateMounts(); }

private Q_SLOTS:
    void fullDiskKeepsTheOldFile_data();
    void fullDiskKeepsTheOldFile();
    void projectRowsStraddleQtsBuffer();
    void renderToFullDisk_data();
    void renderToFullDisk();
    void imageFormatsWithoutMemoryEncoding();
    void replacingASetIsAllOrNothing_data();
    void replacingASetIsAllOrNothing();

    void primitiveWritesExactly_data();
    void primitiveWritesExactly();
    void primitiveKeepsPermissionsAndLinks();
    void primitiveRefuses_data();
    void primitiveRefuses();
};

void SafeWriteTest::fullDiskKeepsTheOldFile_data()
{
    QTest::addColumn<Writer>("writer");
    QTest::addColumn<QString>("oldName"); // written while there is room, then kept
    QTest::addColumn<QString>("newName"); // a second file, never created on the full disk

    const auto cacheName = [](std::uint64_t key) {
        return QString::fromStdString(IblDiskCache::keyHex(key)) + QStringLiteral(".fibl");
    };
    QTest::newRow("writeFileAtomically")
        << Writer::Primitive << QStringLiteral("a.bin") << QStringLiteral("b.bin");
    QTest::newRow("project < 16 KiB")
        << Writer::ProjectSmall << QStringLiteral("p.json") << QStringLiteral("q.json");
    QTest::newRow("project > 16 KiB")
        << Writer::ProjectLarge << QStringLiteral("p.json") << QStringLiteral("q.json");
    QTest::newRow("preset") << Writer::Preset << QStringLiteral("mine.json") << QStringLiteral("other.json");
    QTest::newRow("autosave recovery file")
        << Writer::RecoveryFile << QStringLiteral("session-1.facet-recovery.json")
        << QStringLiteral("session-2.facet-recovery.json");
    QTest::newRow("IBL disk cache") << Writer::IblCache << cacheName(IblDiskCache::key(1, 2))
                                    << cacheName(IblDiskCache::key(3, 4));
    // Every format Image::save encodes in memory that Facet or a user is likely to ask for.
    for (const char* extension : {"exr", "png", "hdr", "jpg", "tif", "tga", "bmp", "webp", "ppm"})
        QTest::newRow(qPrintable(QStringLiteral("Image::save .%1").arg(QLatin1String(extension))))
            << Writer::Image << QStringLiteral("out.") + QLatin1String(extension)
            << QStringLiteral("other.") + QLatin1String(extension);
}

void SafeWriteTest::fullDiskKeepsTheOldFile()
{
    QFETCH(Writer, writer);
    QFETCH(QString, oldName);
    QFETCH(QString, newName);
    FullVolume volume;
    FACET_REQUIRE_FULL_VOLUME(volume);
    const QString oldPath = volume.filePath(oldName);
    const QString newPath = volume.filePath(newName);

    std::string error;
    QVERIFY2(writeWith(writer, oldPath, 0, &error), error.c_str());
    const QByteArray old = fileBytes(oldPath);
    QVERIFY(!old.isEmpty());
    const QStringList before = volume.entries();
    QCOMPARE(before, QStringList {oldName});
    QVERIFY2(volume.fill(), qPrintable(volume.problem()));

    // Over the old file: refused, the old bytes kept, nothing else on the volume.
    error.clear();
    QVERIFY2(!writeWith(writer, oldPath, 1, &error), "the write reported success on a full disk");
    QVERIFY2(contains(error, oldPath) && contains(error, QStringLiteral("No space left on device")),
        error.c_str());
    QCOMPARE(fileBytes(oldPath), old);
    QCOMPARE(volume.entries(), before);

    // A new file: refused, and not created (not even empty).
    error.clear();
    QVERIFY2(!writeWith(writer, newPath, 1, &error), "the write reported success on a full disk");
    QVERIFY2(contains(error, newPath) && contains(error, QStringLiteral("No space left on device")),
        error.c_str());
    QCOMPARE(volume.entries(), before);

    // With room again the same write goes through and leaves no temporary.
    QVERIFY(volume.drain());
    QVERIFY2(writeWith(writer, oldPath, 1, &error), error.c_str());
    QVERIFY(fileBytes(oldPath) != old);
    QCOMPARE(volume.entries(), before);
}

void SafeWriteTest::projectRowsStraddleQtsBuffer()
{
    // The rows above must write files on both sides of the 16 KiB that decided whether QSaveFile
    // lost the file: the preset below it, the large project above it (writeFileAtomically serves
    // both). If the formats grow or shrink, adjust what they hold.
    QTemporaryDir dir;
    std::string error;
    const QString small = dir.filePath(QStringLiteral("small.json"));
    const QString large = dir.filePath(QStringLiteral("large.json"));
    QVERIFY2(writeWith(Writer::Preset, small, 1, &error), error.c_str());
    QVERIFY2(writeWith(Writer::ProjectLarge, large, 1, &error), error.c_str());
    QVERIFY2(QFileInfo(small).size() < kQtWriteBuffer, qPrintable(QString::number(QFileInfo(small).size())));
    QVERIFY2(QFileInfo(large).size() > kQtWriteBuffer, qPrintable(QString::number(QFileInfo(large).size())));
}

void SafeWriteTest::renderToFullDisk_data()
{
    QTest::addColumn<QString>("name");
    QTest::newRow("png") << QStringLiteral("out.png");
    QTest::newRow("exr") << QStringLiteral("out.exr");
}

// `facet render -o <full disk>/out.png`: exit 1, the file named, the previous picture kept.
void SafeWriteTest::renderToFullDisk()
{
    QFETCH(QString, name);
    FullVolume volume;
    FACET_REQUIRE_FULL_VOLUME(volume);
    QTemporaryDir cache;
    QProcessEnvironment environment;
    environment.insert(QStringLiteral("FACET_CACHE_DIR"), cache.path());
    const QString out = volume.filePath(name);
    const auto render = [&](const QString& roughness) {
        return facet::test::runWithoutDisplay(QStringLiteral(FACET_EXECUTABLE),
            {QStringLiteral("render"), QStringLiteral("--env"), QStringLiteral("uniform:1"),
                QStringLiteral("--roughness"), roughness, QStringLiteral("--quality"),
                QStringLiteral("draft"), QStringLiteral("--size"), QStringLiteral("24x24"),
                QStringLiteral("-o"), out},
            environment);
    };

    facet::test::ProcessResult r = render(QStringLiteral("0.3"));
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const QByteArray old = fileBytes(out);
    QVERIFY(!old.isEmpty());
    QVERIFY2(volume.fill(), qPrintable(volume.problem()));

    r = render(QStringLiteral("0.8"));
    QVERIFY2(r.exitCode == 1, qPrintable(QStringLiteral("exit %1: %2").arg(r.exitCode).arg(r.err)));
    QVERIFY2(
        r.err.contains(out) && r.err.contains(QStringLiteral("No space left on device")), qPrintable(r.err));
    QCOMPARE(fileBytes(out), old);
    QCOMPARE(volume.entries(), QStringList {name});

    QVERIFY(volume.drain());
    r = render(QStringLiteral("0.8"));
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    QVERIFY(fileBytes(out) != old);
    QCOMPARE(volume.entries(), QStringList {name});
}

void SafeWriteTest::replacingASetIsAllOrNothing_data()
{
    QTest::addColumn<QStringList>("oldArguments"); // "OUT" stands for the output
    QTest::addColumn<QStringList>("newArguments");
    QTest::addColumn<QString>("output"); // under the set's folder; "" for the folder itself
    const QString out = QStringLiteral("OUT");
    const QString project = QStringLiteral("PROJECT"); // a material with noise maps
    QTest::newRow("export --format unreal")
        << QStringList {QStringLiteral("export"), project, QStringLiteral("--format"),
               QStringLiteral("unreal"), QStringLiteral("--size"), QStringLiteral("4"), QStringLiteral("-o"),
               out}
        << QStringList {QStringLiteral("export"), project, QStringLiteral("--format"),
               QStringLiteral("unreal"), QStringLiteral("--size"), QStringLiteral("64"),
               QStringLiteral("--force"), QStringLiteral("-o"), out}
        << QString();
    QTest::newRow("export --format gltf")
        << QStringList {QStringLiteral("export"), project, QStringLiteral("--format"), QStringLiteral("gltf"),
               QStringLiteral("--size"), QStringLiteral("4"), QStringLiteral("-o"), out}
        << QStringList {QStringLiteral("export"), project, QStringLiteral("--format"), QStringLiteral("gltf"),
               QStringLiteral("--size"), QStringLiteral("64"), QStringLiteral("--force"),
               QStringLiteral("-o"), out}
        << QStringLiteral("asset.gltf");
    QTest::newRow("bake") << QStringList {QStringLiteral("bake"), QStringLiteral("uniform:1"),
        QStringLiteral("--ibl-size"), QStringLiteral("16"), QStringLiteral("--quality"),
        QStringLiteral("draft"), QStringLiteral("-o"), out}
                          << QStringList {QStringLiteral("bake"), QStringLiteral("uniform:2"),
                                 QStringLiteral("--ibl-size"), QStringLiteral("16"),
                                 QStringLiteral("--quality"), QStringLiteral("draft"),
                                 QStringLiteral("--force"), QStringLiteral("-o"), out}
                          << QString();
}

// Issue 29, "Data lost, mixed set": `export --force` and `bake --force` over an earlier set on a
// disk that fills midway exited 1 having replaced some files and not others. The new set now goes
// to a staging folder beside the old one and is swapped in whole (core/support/FileSet.h): on a disk with
// room for about half of the new set, every old file keeps its bytes and nothing else is left;
// with room, the whole new set replaces the old one.
void SafeWriteTest::replacingASetIsAllOrNothing()
{
    QFETCH(QStringList, oldArguments);
    QFETCH(QStringList, newArguments);
    QFETCH(QString, output);
    FullVolume volume(QString(), 16 * 1024 * 1024);
    FACET_REQUIRE_FULL_VOLUME(volume);
    QTemporaryDir cache;
    QProcessEnvironment environment;
    environment.insert(QStringLiteral("FACET_CACHE_DIR"), cache.path());
    // A material whose maps hold noise, so that each size gives other files.
    QTemporaryDir inputs;
    const QString project = inputs.filePath(QStringLiteral("p.json"));
    std::string error;
    QVERIFY2(imageVariant(1).save(inputs.filePath(QStringLiteral("noise.png")).toStdString(), &error),
        error.c_str());
    QVERIFY(facet::test::writeText(project,
        "{\"format\": \"facet-project\", \"version\": 1, \"materials\": [{\"name\": \"Noise\", "
        "\"baseColor\": {\"texture\": \"noise.png\"}, \"roughness\": {\"texture\": \"noise.png\", "
        "\"channel\": \"g\"}, \"normal\": {\"texture\": \"noise.png\"}}]}"));
    const auto run = [&](QStringList arguments, const QString& folder) {
        const QString target = output.isEmpty() ? folder : folder + u'/' + output;
        arguments.replaceInStrings(QRegularExpression(QStringLiteral("^OUT$")), target);
        arguments.replaceInStrings(QRegularExpression(QStringLiteral("^PROJECT$")), project);
        return facet::test::runWithoutDisplay(QStringLiteral(FACET_EXECUTABLE), arguments, environment);
    };
    const auto contents = [](const QString& folder) {
        std::map<QString, QByteArray> files;
        for (const QString& name :
            QDir(folder).entryList(QDir::Files | QDir::Hidden | QDir::Dirs | QDir::NoDotAndDotDot))
            files[name] = fileBytes(folder + u'/' + name);
        return files;
    };

    // The new set on a disk with room: its size in whole pages (tmpfs gives a file whole pages).
    QTemporaryDir reference;
    facet::test::ProcessResult r = run(newArguments, reference.path());
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const std::map<QString, QByteArray> newSet = contents(reference.path());
    QVERIFY(newSet.size() >= 3);
    qint64 newPages = 0;
    for (const auto& [name, bytes] : newSet)
        newPages += (bytes.size() + 4095) / 4096;

    const QString folder = volume.filePath(QStringLiteral("set"));
    r = run(oldArguments, folder);
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const std::map<QString, QByteArray> oldSet = contents(folder);
    QCOMPARE(oldSet.size(), newSet.size());
    int differing = 0;
    for (const auto& [name, bytes] : newSet)
        differing += oldSet.count(name) && oldSet.at(name) != bytes ? 1 : 0;
    QVERIFY2(differing >= 2, "the two sets must differ for the test to mean anything");

    // Room for about half of the new set: the first files fit, a later one does not.
    QVERIFY2(volume.fill(), qPrintable(volume.problem()));
    QVERIFY2(volume.release(newPages / 2 * 4096), qPrintable(volume.problem()));
    r = run(newArguments, folder);
    QVERIFY2(r.exitCode == 1, qPrintable(QStringLiteral("exit %1: %2").arg(r.exitCode).arg(r.err)));
    QVERIFY2(r.err.contains(QStringLiteral("No space left on device")) && r.err.contains(folder),
        qPrintable(r.err));
    QVERIFY2(!r.err.contains(QStringLiteral(".facet-new-")), qPrintable(r.err)); // names the user's files
    const std::map<QString, QByteArray> afterFailure = contents(folder);
    QCOMPARE(afterFailure.size(), oldSet.size()); // no staging folder left behind
    for (const auto& [name, bytes] : oldSet)
        QVERIFY2(afterFailure.count(name) && afterFailure.at(name) == bytes,
            qPrintable(name + QStringLiteral(" changed")));

    // With room again the whole new set replaces the old one.
    QVERIFY(volume.drain());
    r = run(newArguments, folder);
    QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    const std::map<QString, QByteArray> replaced = contents(folder);
    QCOMPARE(replaced.size(), newSet.size());
    for (const auto& [name, bytes] : newSet)
        QVERIFY2(replaced.count(name) && replaced.at(name) == bytes,
            qPrintable(name + QStringLiteral(" is not the new file")));
}

// OpenImageIO's writers that cannot encode into memory are refused (not written unchecked), with
// a message that names the file and says what to use; nothing is created.
void SafeWriteTest::imageFormatsWithoutMemoryEncoding()
{
    QTemporaryDir dir;
    for (const char* extension : {"sgi", "rla", "fits"}) {
        const QString path = dir.filePath(QStringLiteral("out.") + QLatin1String(extension));
        std::string error;
        QVERIFY(!imageVariant(1).save(path.toStdString(), &error));
        QVERIFY2(contains(error, QStringLiteral("Image::save: ") + path)
                && contains(error, QStringLiteral(".png")),
            error.c_str());
        QVERIFY(!QFileInfo::exists(path));
    }
    QCOMPARE(
        QDir(dir.path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot), QStringList {});
}

void SafeWriteTest::primitiveWritesExactly_data()
{
    QTest::addColumn<qint64>("oldSize"); // -1: no old file
    QTest::addColumn<qint64>("newSize");
    QTest::newRow("new file") << qint64(-1) << qint64(10);
    QTest::newRow("empty content") << qint64(-1) << qint64(0);
    QTest::newRow("over a larger file") << qint64(100000) << qint64(10);
    QTest::newRow("over a smaller file") << qint64(10) << qint64(100000);
    QTest::newRow("over an empty file") << qint64(0) << qint64(5);
    QTest::newRow("one byte over 16 KiB") << qint64(-1) << kQtWriteBuffer + 1;
    QTest::newRow("8 MiB") << qint64(3) << qint64(8) * 1024 * 1024;
}

void SafeWriteTest::primitiveWritesExactly()
{
    QFETCH(qint64, oldSize);
    QFETCH(qint64, newSize);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("f.bin"));
    if (oldSize >= 0) {
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        QCOMPARE(file.write(QByteArray(oldSize, 'o')), oldSize);
    }
    QByteArray bytes(newSize, '\0');
    for (qint64 i = 0; i < newSize; ++i)
        bytes[i] = char((i * 131) % 256);
    std::string reason;
    QVERIFY2(writeFileAtomically(
                 path.toStdString(), std::string_view(bytes.constData(), std::size_t(bytes.size())), &reason),
        reason.c_str());
    QCOMPARE(fileBytes(path), bytes);
    QCOMPARE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot),
        QStringList {QStringLiteral("f.bin")});
}

void SafeWriteTest::primitiveKeepsPermissionsAndLinks()
{
    QTemporaryDir dir;
    std::string reason;
    // The old file's permission bits survive the replacement (a temporary starts at 0666 & ~umask).
    const QString shared = dir.filePath(QStringLiteral("shared.json"));
    QVERIFY(writeFileAtomically(shared.toStdString(), "one", &reason));
    QVERIFY(::chmod(QFile::encodeName(shared).constData(), 0640) == 0);
    QVERIFY2(writeFileAtomically(shared.toStdString(), "two", &reason), reason.c_str());
    struct stat info { };
    QVERIFY(::stat(QFile::encodeName(shared).constData(), &info) == 0);
    QCOMPARE(int(info.st_mode & 07777), 0640);
    QCOMPARE(fileBytes(shared), QByteArray("two"));

    // Saving through a symbolic link replaces the file it points to and keeps the link.
    const QString link = dir.filePath(QStringLiteral("link.json"));
    QVERIFY(QFile::link(shared, link));
    QVERIFY2(writeFileAtomically(link.toStdString(), "three", &reason), reason.c_str());
    QVERIFY(QFileInfo(link).isSymLink());
    QCOMPARE(fileBytes(shared), QByteArray("three"));
    QCOMPARE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot),
        (QStringList {QStringLiteral("link.json"), QStringLiteral("shared.json")}));
}

void SafeWriteTest::primitiveRefuses_data()
{
    QTest::addColumn<QString>("target"); // relative to a fresh folder; see below for what is there
    QTest::addColumn<QString>("reason");
    QTest::newRow("a folder") << QStringLiteral("folder") << QStringLiteral("is a folder, not a file");
    QTest::newRow("a FIFO") << QStringLiteral("fifo") << QStringLiteral("is not a regular file");
    QTest::newRow("a missing folder")
        << QStringLiteral("no/such/f.json") << QStringLiteral("/no/such does not exist");
    QTest::newRow("no name") << QString() << QStringLiteral("no file name given");
}

void SafeWriteTest::primitiveRefuses()
{
    QFETCH(QString, target);
    QFETCH(QString, reason);
    QTemporaryDir dir;
    QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("folder")));
    QVERIFY(::mkfifo(QFile::encodeName(dir.filePath(QStringLiteral("fifo"))).constData(), 0600) == 0);
    const QStringList before
        = QDir(dir.path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot);
    const std::string path = target.isEmpty() ? std::string() : dir.filePath(target).toStdString();
    std::string why;
    QVERIFY(!writeFileAtomically(path, "content", &why));
    QVERIFY2(contains(why, reason), why.c_str());
    QCOMPARE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot), before);
    QVERIFY(QFileInfo(dir.filePath(QStringLiteral("folder"))).isDir());
    QVERIFY(QDir(dir.filePath(QStringLiteral("folder"))).isEmpty());
}

QTEST_GUILESS_MAIN(SafeWriteTest)
#include "SafeWriteTest.moc"
