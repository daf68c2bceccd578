// Deterministic mutation fuzzing of the readers of what users feed Facet: projects, images (as
// environments and as material maps) and meshes (every format the seeds cover, glTF included).
// GCC has no libFuzzer, so this is the driver: each seed in tests/fuzz/corpus is mutated a fixed
// number of times (bit flips, interesting bytes, cut, duplicated, inserted and deleted runs,
// numbers made huge) with a fixed seed, so a run is reproducible; every mutant must load or fail
// with a message naming the file, never crash, hang or return something invalid. Before each run
// the input is written to test-output/fuzz-current.<ext>: after a crash that file is the input to
// keep in tests/fuzz/regressions (each of which runs first, as it is). FACET_FUZZ_RUNS changes
// the runs per seed (default 60; CI's budget), FACET_FUZZ_SEED the sequence.

#include "core/image/Image.h"
#include "core/image/MapImage.h"
#include "core/mesh/Mesh.h"
#include "core/mesh/MeshImport.h"
#include "core/project/Project.h"

#include "TestSupport.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>

using namespace facet;

namespace {

QByteArray readAll(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

bool writeAll(const QString& path, const QByteArray& bytes)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly | QIODevice::Truncate) && file.write(bytes) == bytes.size();
}

// One mutation of `bytes`, chosen and placed by `random`.
QByteArray mutate(QByteArray bytes, std::mt19937& random)
{
    const auto below = [&random](qsizetype n) { return n <= 0 ? 0 : qsizetype(random() % std::uint32_t(n)); };
    const int mutations = 1 + int(random() % 4);
    for (int m = 0; m < mutations && !bytes.isEmpty(); ++m) {
        const qsizetype at = below(bytes.size());
        switch (random() % 8) {
        case 0: // flip a bit
            bytes[at] = char(bytes[at] ^ char(1 << (random() % 8)));
            break;
        case 1: { // an interesting byte
            static const char kBytes[] = {0, char(0xff), char(0x7f), char(0x80), '9', '-', '.', 'e'};
            bytes[at] = kBytes[random() % sizeof kBytes];
            break;
        }
        case 2: // cut
            bytes.truncate(at);
            break;
        case 3: { // duplicate a run
            const QByteArray run = bytes.mid(at, 1 + below(64));
            bytes.insert(below(bytes.size()), run);
            break;
        }
        case 4: // delete a run
            bytes.remove(at, 1 + below(32));
            break;
        case 5: { // a 32-bit field made huge (a size, a count, an offset in a binary header)
            const quint32 huge = random() % 2 ? 0xffffffffu : 0x7fffffffu + quint32(random() % 1024);
            for (int i = 0; i < 4 && at + i < bytes.size(); ++i)
                bytes[at + i] = char((huge >> (8 * i)) & 0xff);
            break;
        }
        case 6: { // a number in text made huge or negative
            static const char* kNumbers[]
                = {"99999999999", "-1", "1e308", "-0", "4294967296", "nan", "1e-320"};
            const qsizetype digit = bytes.indexOf(QByteArray::number(int(random() % 10)), at);
            if (digit >= 0)
                bytes.replace(digit, 1, kNumbers[random() % (sizeof kNumbers / sizeof *kNumbers)]);
            break;
        }
        default: // random bytes
            for (int i = 0, n = 1 + int(below(8)); i < n && at + i < bytes.size(); ++i)
                bytes[at + i] = char(random());
            break;
        }
    }
    return bytes;
}

enum class Reader { Project, Image, Map, Mesh };

// Every seed is under 2 KiB and loads in milliseconds; a mutant taking this long is a defect.
constexpr qint64 kSlowMs = 3000;

// Loads `path` with `reader`: true when it loaded (valid) or failed with a message naming the file.
bool loadsOrFailCleanly(Reader reader, const std::string& path, std::string* why, bool* loaded = nullptr)
{
    bool ignored = false;
    if (!loaded)
        loaded = &ignored;
    *loaded = false;
    std::string error;
    switch (reader) {
    case Reader::Project: {
        const std::optional<Project> project = Project::load(path, &error);
        *loaded = bool(project);
        if (project && !project->validate(why))
            return false;
        break;
    }
    case Reader::Image: {
        const std::optional<Image> image = Image::load(path, &error);
        *loaded = bool(image);
        if (image && (image->width() <= 0 || image->height() <= 0)) {
            *why = "an empty image loaded";
            return false;
        }
        break;
    }
    case Reader::Map: {
        *loaded = bool(MapImage::load(path, &error));
        break;
    }
    case Reader::Mesh: {
        const std::optional<Mesh> mesh = importMesh(path, &error);
        *loaded = bool(mesh);
        if (mesh && !mesh->validate(why))
            return false;
        break;
    }
    }
    if (!error.empty() && error.find(path) == std::string::npos) {
        *why = "the message does not name the file: " + error;
        return false;
    }
    return true;
}

Reader readerFor(const QString& fileName)
{
    const QString suffix = QFileInfo(fileName).suffix().toLower();
    if (suffix == QLatin1String("json"))
        return Reader::Project;
    if (QStringList {QStringLiteral("obj"), QStringLiteral("ply"), QStringLiteral("stl"),
            QStringLiteral("gltf"), QStringLiteral("glb")}
            .contains(suffix))
        return Reader::Mesh;
    return Reader::Image;
}

} // namespace

class FuzzTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void regressionsLoadOrFailCleanly();
    void mutants_data();
    void mutants();
};

void FuzzTest::regressionsLoadOrFailCleanly()
{
    const QDir regressions(QStringLiteral(FACET_FUZZ_DIR "/regressions"));
    for (const QFileInfo& file : regressions.entryInfoList(QDir::Files)) {
        if (file.fileName() == QLatin1String("README.md"))
            continue;
        std::string why;
        const Reader reader = readerFor(file.fileName());
        QElapsedTimer clock;
        clock.start();
        QVERIFY2(
            loadsOrFailCleanly(reader, file.filePath().toStdString(), &why), qPrintable(file.fileName()));
        if (reader == Reader::Image)
            QVERIFY2(loadsOrFailCleanly(Reader::Map, file.filePath().toStdString(), &why), why.c_str());
        qInfo("%s: %lld ms", qPrintable(file.fileName()), static_cast<long long>(clock.elapsed()));
        QVERIFY2(clock.elapsed() < kSlowMs, qPrintable(file.fileName()));
    }
}

void FuzzTest::mutants_data()
{
    QTest::addColumn<QString>("seed");
    const QDir corpus(QStringLiteral(FACET_FUZZ_DIR "/corpus"));
    const QStringList seeds = corpus.entryList(QDir::Files, QDir::Name);
    QVERIFY(seeds.size() >= 10);
    for (const QString& seed : seeds)
        QTest::newRow(qPrintable(seed)) << corpus.filePath(seed);
}

void FuzzTest::mutants()
{
    QFETCH(QString, seed);
    const QByteArray original = readAll(seed);
    QVERIFY(!original.isEmpty());
    bool ok = false;
    int runs = qEnvironmentVariableIntValue("FACET_FUZZ_RUNS", &ok);
    if (!ok || runs <= 0)
        runs = 60;
    const unsigned sequence = unsigned(qEnvironmentVariableIntValue("FACET_FUZZ_SEED"));
    // The seed's name picks its sequence (FNV-1a: qHash is salted per process, which would make
    // every run different).
    std::uint32_t nameHash = 2166136261u;
    for (const char c : QFileInfo(seed).fileName().toUtf8())
        nameHash = (nameHash ^ std::uint8_t(c)) * 16777619u;
    std::mt19937 random(sequence * 7919u + nameHash);
    const QString suffix = QFileInfo(seed).suffix();
    const QString current = test::outputDir() + QStringLiteral("/fuzz-current.") + suffix;
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("mutant.") + suffix);
    const Reader reader = readerFor(seed);
    // The seed itself loads: the mutants start from a file that reaches the reader's depths.
    std::string why;
    bool seedLoads = false;
    QVERIFY2(loadsOrFailCleanly(reader, seed.toStdString(), &why, &seedLoads), why.c_str());
    QVERIFY2(seedLoads, "the seed itself does not load");
    QElapsedTimer clock;
    clock.start();
    int loaded = 0;
    qint64 slowest = 0;
    int slowestRun = -1;
    for (int run = 0; run < runs; ++run) {
        const qint64 before = clock.elapsed();
        const QByteArray bytes = mutate(original, random);
        QVERIFY(writeAll(current, bytes)); // what to keep if this run crashes
        QVERIFY(writeAll(path, bytes));
        bool didLoad = false;
        QVERIFY2(loadsOrFailCleanly(reader, path.toStdString(), &why, &didLoad),
            qPrintable(QStringLiteral("run %1: %2 (the input: %3)")
                           .arg(run)
                           .arg(QString::fromStdString(why), current)));
        if (reader == Reader::Image)
            QVERIFY2(loadsOrFailCleanly(Reader::Map, path.toStdString(), &why),
                qPrintable(QStringLiteral("run %1 as a map: %2").arg(run).arg(QString::fromStdString(why))));
        loaded += didLoad;
        // A small input that takes seconds is a hang in waiting (a size claimed and allocated, a
        // loop over a count from the file): kept beside the output, and a failure.
        if (clock.elapsed() - before > kSlowMs) {
            const QString kept = test::outputDir()
                + QStringLiteral("/fuzz-slow-%1-%2.%3")
                      .arg(QFileInfo(seed).completeBaseName())
                      .arg(run)
                      .arg(suffix);
            writeAll(kept, bytes);
            QFAIL(qPrintable(QStringLiteral("run %1 took %2 ms: kept as %3")
                                 .arg(run)
                                 .arg(clock.elapsed() - before)
                                 .arg(kept)));
        }
        if (clock.elapsed() - before > slowest) {
            slowest = clock.elapsed() - before;
            slowestRun = run;
        }
    }
    QFile::remove(current);
    qInfo("%d mutants of %s in %lld ms (%d loaded, the rest refused with a message; the slowest, run %d, "
          "%lld ms)",
        runs, qPrintable(QFileInfo(seed).fileName()), static_cast<long long>(clock.elapsed()), loaded,
        slowestRun, static_cast<long long>(slowest));
}

QTEST_GUILESS_MAIN(FuzzTest)
#include "FuzzTest.moc"
