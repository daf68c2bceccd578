// core/ibl/IblDiskCache: round trip, corrupt and truncated files, key uniqueness. Needs nothing.

#include "core/ibl/IblDiskCache.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <set>

#include <sys/stat.h>

using namespace facet;

namespace {

IblCacheEntry sampleEntry()
{
    IblCacheEntry entry;
    IblCacheLayer cube;
    cube.width = 4;
    cube.height = 4;
    cube.faces = 6;
    cube.level = 1;
    for (std::size_t i = 0; i < cube.valueCount(); ++i)
        cube.half.push_back(std::uint16_t(i * 37u + 5u));
    entry.layers.push_back(cube);
    IblCacheLayer lut;
    lut.width = 3;
    lut.height = 2;
    lut.format = IblCacheLayer::Format::Float;
    for (std::size_t i = 0; i < lut.valueCount(); ++i)
        lut.single.push_back(float(i) * 0.125f - 1.0f);
    entry.layers.push_back(lut);
    entry.extra = {3.14159, -2.5, 1e-300, 1e300};
    return entry;
}

bool sameEntry(const IblCacheEntry& a, const IblCacheEntry& b)
{
    if (a.layers.size() != b.layers.size() || a.extra != b.extra)
        return false;
    for (std::size_t i = 0; i < a.layers.size(); ++i) {
        const IblCacheLayer& x = a.layers[i];
        const IblCacheLayer& y = b.layers[i];
        if (x.width != y.width || x.height != y.height || x.faces != y.faces || x.level != y.level
            || x.format != y.format || x.half != y.half || x.single != y.single)
            return false;
    }
    return true;
}

} // namespace

class IblDiskCacheTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void roundTrip();
    void missingFileIsSilent();
    void truncatedFileIsIgnored();
    void corruptFileIsIgnored();
    void wrongKeyOrVersionIsIgnored();
    void keysAreUnique();
    void directoryFromEnvironment();
    void rejectsInconsistentEntry();
    void entryThatIsNotAFileIsIgnored_data();
    void entryThatIsNotAFileIsIgnored();
};

void IblDiskCacheTest::roundTrip()
{
    QTemporaryDir dir;
    const IblDiskCache cache(dir.path() + QStringLiteral("/nested/ibl"));
    const std::uint64_t key = IblDiskCache::key(0x1234, 0x5678);
    std::string error;
    QVERIFY2(cache.store(key, sampleEntry(), &error), error.c_str());
    QVERIFY(QFile::exists(cache.pathFor(key)));
    QVERIFY(cache.pathFor(key).endsWith(
        QString::fromStdString(IblDiskCache::keyHex(key)) + QStringLiteral(".fibl")));
    std::string warning;
    const std::optional<IblCacheEntry> loaded = cache.load(key, &warning);
    QVERIFY2(loaded, warning.c_str());
    QVERIFY(warning.empty());
    QVERIFY(sameEntry(*loaded, sampleEntry()));
    // Overwriting replaces the file atomically (writeFileAtomically) and leaves no temporary behind.
    QVERIFY2(cache.store(key, sampleEntry(), &error), error.c_str());
    QCOMPARE(QDir(cache.directory()).entryList(QDir::Files).size(), 1);
}

void IblDiskCacheTest::missingFileIsSilent()
{
    QTemporaryDir dir;
    const IblDiskCache cache(dir.path());
    std::string warning;
    QVERIFY(!cache.load(42, &warning));
    QVERIFY(warning.empty());
}

void IblDiskCacheTest::truncatedFileIsIgnored()
{
    QTemporaryDir dir;
    const IblDiskCache cache(dir.path());
    std::string error;
    QVERIFY(cache.store(7, sampleEntry(), &error));
    const qint64 size = QFileInfo(cache.pathFor(7)).size();
    for (qint64 cut : {qint64(0), qint64(5), qint64(40), size / 2, size - 1}) {
        QVERIFY(cache.store(7, sampleEntry(), &error));
        QVERIFY(QFile::resize(cache.pathFor(7), cut));
        std::string warning;
        QVERIFY(!cache.load(7, &warning));
        QVERIFY2(
            warning.rfind("IblDiskCache::load: ", 0) == 0 && warning.find("ignoring it") != std::string::npos,
            warning.c_str());
    }
}

void IblDiskCacheTest::corruptFileIsIgnored()
{
    QTemporaryDir dir;
    const IblDiskCache cache(dir.path());
    std::string error;
    QVERIFY(cache.store(9, sampleEntry(), &error));
    QFile file(cache.pathFor(9));
    QVERIFY(file.open(QIODevice::ReadWrite));
    QByteArray bytes = file.readAll();
    bytes[bytes.size() - 20] = char(bytes[bytes.size() - 20] ^ 0x40); // one flipped bit in the payload
    file.seek(0);
    file.write(bytes);
    file.close();
    std::string warning;
    QVERIFY(!cache.load(9, &warning));
    QVERIFY2(warning.find("checksum") != std::string::npos, warning.c_str());

    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write("not a cache file at all, but long enough to have a header........");
    file.close();
    QVERIFY(!cache.load(9, &warning));
    QVERIFY2(warning.find("bad magic") != std::string::npos, warning.c_str());
}

void IblDiskCacheTest::wrongKeyOrVersionIsIgnored()
{
    QTemporaryDir dir;
    const IblDiskCache cache(dir.path());
    std::string error;
    QVERIFY(cache.store(11, sampleEntry(), &error));
    // A file renamed to another key's name must not be taken for it.
    QVERIFY(QFile::copy(cache.pathFor(11), cache.pathFor(12)));
    std::string warning;
    QVERIFY(!cache.load(12, &warning));
    QVERIFY2(warning.find("holds key") != std::string::npos, warning.c_str());
    // Version field (bytes 8..11).
    QFile file(cache.pathFor(11));
    QVERIFY(file.open(QIODevice::ReadWrite));
    file.seek(8);
    file.write(QByteArray("\x63\0\0\0", 4));
    file.close();
    QVERIFY(!cache.load(11, &warning));
    QVERIFY2(warning.find("version 99") != std::string::npos, warning.c_str());
}

void IblDiskCacheTest::keysAreUnique()
{
    std::set<std::uint64_t> keys;
    int count = 0;
    for (std::uint64_t content : {0ull, 1ull, 2ull, 0xffffffffffffffffull, 0x100000000ull})
        for (std::uint64_t settings : {0ull, 1ull, 2ull, 3ull, 0x8000000000000000ull}) {
            keys.insert(IblDiskCache::key(content, settings));
            ++count;
        }
    QCOMPARE(int(keys.size()), count);
    // Not symmetric: (a, b) and (b, a) are different entries.
    QVERIFY(IblDiskCache::key(1, 2) != IblDiskCache::key(2, 1));
    QCOMPARE(IblDiskCache::keyHex(0xabcull), std::string("0000000000000abc"));
}

void IblDiskCacheTest::directoryFromEnvironment()
{
    QTemporaryDir dir;
    qputenv("FACET_CACHE_DIR", dir.path().toUtf8());
    QCOMPARE(IblDiskCache::defaultDirectory(), dir.path());
    QCOMPARE(IblDiskCache().directory(), dir.path());
    qunsetenv("FACET_CACHE_DIR");
    QVERIFY(IblDiskCache::defaultDirectory().endsWith(QStringLiteral("/ibl")));
}

void IblDiskCacheTest::rejectsInconsistentEntry()
{
    QTemporaryDir dir;
    const IblDiskCache cache(dir.path());
    IblCacheEntry entry = sampleEntry();
    entry.layers[0].half.pop_back();
    std::string error;
    QVERIFY(!cache.store(3, entry, &error));
    QVERIFY2(error.rfind("IblDiskCache::store: ", 0) == 0, error.c_str());
    QVERIFY(!QFile::exists(cache.pathFor(3)));
}

void IblDiskCacheTest::entryThatIsNotAFileIsIgnored_data()
{
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("reason");
    // A link to /dev/zero was read without end before; a FIFO blocked the open.
    QTest::newRow("a link to /dev/zero") << QStringLiteral("zero") << QStringLiteral("not a regular file");
    QTest::newRow("a FIFO") << QStringLiteral("fifo") << QStringLiteral("not a regular file");
    QTest::newRow("a link loop") << QStringLiteral("loop") << QStringLiteral("loop of symbolic links");
    QTest::newRow("a folder") << QStringLiteral("folder") << QStringLiteral("is a folder");
    QTest::newRow("a dangling link") << QStringLiteral("dangling") << QStringLiteral("does not exist");
}

void IblDiskCacheTest::entryThatIsNotAFileIsIgnored()
{
    QFETCH(QString, kind);
    QFETCH(QString, reason);
    QTemporaryDir dir;
    const IblDiskCache cache(dir.path());
    std::string error;
    QVERIFY2(cache.store(11, sampleEntry(), &error), error.c_str()); // makes the cache's folders
    const QString path = cache.pathFor(11);
    QVERIFY(QFile::remove(path));
    if (kind == QLatin1String("zero"))
        QVERIFY(QFile::link(QStringLiteral("/dev/zero"), path));
    else if (kind == QLatin1String("fifo"))
        QCOMPARE(::mkfifo(QFile::encodeName(path).constData(), 0600), 0);
    else if (kind == QLatin1String("loop"))
        QVERIFY(QFile::link(path, path));
    else if (kind == QLatin1String("folder"))
        QVERIFY(QDir().mkpath(path));
    else
        QVERIFY(QFile::link(path + QStringLiteral(".gone"), path));
    std::string warning;
    QVERIFY(!cache.load(11, &warning));
    QVERIFY2(warning.find(reason.toStdString()) != std::string::npos, warning.c_str());
    QVERIFY2(warning.find(path.toStdString()) != std::string::npos, warning.c_str());
    // Storing again replaces what is there (a link is replaced, not followed into /dev/zero).
    if (kind != QLatin1String("folder")) {
        QVERIFY2(cache.store(11, sampleEntry(), &error), error.c_str());
        QVERIFY(cache.load(11, &warning));
    }
}

QTEST_GUILESS_MAIN(IblDiskCacheTest)
#include "IblDiskCacheTest.moc"
