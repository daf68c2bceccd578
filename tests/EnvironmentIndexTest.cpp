// Environment::load remembers a file by its identity (core/ibl/EnvironmentIndex.h) and does not decode
// it again while it is unchanged (issue 12, "Large HDRIs": a warm cache never decodes the image);
// any change to the file, or a record that is not a good one, is a miss; a file too recent to
// trust is not remembered; a record that turns out wrong is forgotten with a warning. Files larger
// than Environment::kMaxWidth x kMaxHeight are kept area-filtered.

#include <cmath>
#include <cstdio>
#include <utility>

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include "core/ibl/Environment.h"
#include "core/ibl/EnvironmentIndex.h"
#include "core/image/Image.h"

using namespace facet;

namespace {

// A width x height image whose texels differ (a gradient with a bright spot), one NaN so that
// loading warns.
Image testImage(int width, int height, float scale = 1.0f)
{
    Image image(width, height, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.at(x, y) = glm::vec4(scale * float(x + 1) / float(width),
                scale * float(y + 1) / float(height), scale * float((x * 7 + y * 13) % 17), 1.0f);
    image.at(1, 1) = glm::vec4(std::nanf(""), 2.0f, 3.0f, 1.0f);
    return image;
}

bool writeImage(const QString& path, const Image& image)
{
    std::string error;
    const bool written = image.save(path.toStdString(), &error, false);
    if (!written)
        qWarning("%s", error.c_str());
    return written;
}

// Sets the modification time `seconds` into the past (the status-change time becomes now).
bool age(const QString& path, int seconds = 3600)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadWrite))
        return false;
    return file.setFileTime(
        QDateTime::currentDateTimeUtc().addSecs(-seconds), QFileDevice::FileModificationTime);
}

bool samePixels(const Image& a, const Image& b)
{
    if (a.width() != b.width() || a.height() != b.height())
        return false;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            if (a.at(x, y) != b.at(x, y))
                return false;
    return true;
}

} // namespace

class EnvironmentIndexTest : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    QString m_cache;

    QString path(const QString& name) const { return m_dir.filePath(name); }
    // Writes an aged test image and loads it once, so that the index holds it.
    bool indexed(const QString& file, Environment* first)
    {
        if (!writeImage(file, testImage(32, 16)) || !age(file))
            return false;
        std::string error;
        std::optional<Environment> environment = Environment::load(file.toStdString(), &error);
        if (!environment) {
            qWarning("%s", error.c_str());
            return false;
        }
        *first = *environment;
        return environment->decoded() && QFile::exists(EnvironmentIndex().recordPath(file.toStdString()));
    }

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_cache = m_dir.filePath(QStringLiteral("cache"));
        qputenv("FACET_CACHE_DIR", m_cache.toUtf8());
    }
    void cleanupTestCase() { qunsetenv("FACET_CACHE_DIR"); }

    void secondLoadDecodesNothing()
    {
        const QString file = path(QStringLiteral("second.exr"));
        Environment first;
        QVERIFY(indexed(file, &first));
        std::string firstWarning;
        QVERIFY(Environment::load(file.toStdString(), nullptr, &firstWarning)); // (deferred: the warning)
        QVERIFY2(firstWarning.find("replaced 1 NaN") != std::string::npos, firstWarning.c_str());

        std::string error;
        std::string warning;
        std::optional<Environment> second = Environment::load(file.toStdString(), &error, &warning);
        QVERIFY2(second, error.c_str());
        QVERIFY2(!second->decoded(), "an unchanged, indexed file was decoded again");
        QCOMPARE(second->contentHash(), first.contentHash());
        QCOMPARE(second->width(), 32);
        QCOMPARE(second->height(), 16);
        QCOMPARE(second->name(), file.toStdString());
        QCOMPARE(warning, firstWarning);
        QVERIFY(!second->isEmpty());

        // A copy shares the pixels: one decodes, both have them.
        const Environment copy = *second;
        QVERIFY(samePixels(copy.image(), first.image()));
        QVERIFY(second->decoded());
        QVERIFY(samePixels(second->image(), first.image()));
        QCOMPARE(second->radiance(glm::dvec3(0.3, 0.4, 0.5)), first.radiance(glm::dvec3(0.3, 0.4, 0.5)));
    }

    // Every change to the file, and every record that is not a good one, is a miss: the file is
    // decoded again (and, for a changed file, the hash follows the new pixels).
    void changesAreMisses_data()
    {
        QTest::addColumn<QString>("change");
        QTest::addColumn<bool>("newPixels");
        QTest::newRow("rewritten, same size") << "rewrite" << true;
        QTest::newRow("rewritten, then its time set back") << "rewrite-keep-time" << true;
        QTest::newRow("another file renamed over it, time kept") << "rename-over" << true;
        QTest::newRow("touched") << "touch" << false;
        QTest::newRow("resized") << "resize" << true;
        QTest::newRow("record of an older version") << "record-version" << false;
        QTest::newRow("record of another path") << "record-path" << false;
        QTest::newRow("record of another size") << "record-size" << false;
        QTest::newRow("record garbage") << "record-garbage" << false;
        QTest::newRow("record empty") << "record-empty" << false;
        QTest::newRow("record a link to /dev/zero") << "record-device" << false;
        QTest::newRow("record a folder") << "record-folder" << false;
    }
    void changesAreMisses()
    {
        QFETCH(QString, change);
        QFETCH(bool, newPixels);
        const QString file = path(QStringLiteral("change-%1.exr").arg(QString::number(qHash(change), 16)));
        Environment first;
        QVERIFY(indexed(file, &first));
        const QString record = EnvironmentIndex().recordPath(file.toStdString());
        const QDateTime oldTime = QFileInfo(file).lastModified();

        auto editRecord = [&](const char* field, const QJsonValue& value) {
            QFile in(record);
            QVERIFY(in.open(QIODevice::ReadOnly));
            QJsonObject object = QJsonDocument::fromJson(in.readAll()).object();
            in.close();
            QVERIFY(object.contains(QLatin1String(field)));
            object.insert(QLatin1String(field), value);
            QFile out(record);
            QVERIFY(out.open(QIODevice::WriteOnly | QIODevice::Truncate));
            out.write(QJsonDocument(object).toJson());
        };
        if (change == QLatin1String("rewrite")) {
            QVERIFY(writeImage(file, testImage(32, 16, 2.0f)));
            QVERIFY(age(file));
        } else if (change == QLatin1String("rewrite-keep-time")) {
            QVERIFY(writeImage(file, testImage(32, 16, 2.0f)));
            QFile f(file);
            QVERIFY(f.open(QIODevice::ReadWrite));
            QVERIFY(f.setFileTime(oldTime, QFileDevice::FileModificationTime));
        } else if (change == QLatin1String("rename-over")) {
            const QString other = path(QStringLiteral("other.exr"));
            QVERIFY(writeImage(other, testImage(32, 16, 3.0f)));
            QFile f(other);
            QVERIFY(f.open(QIODevice::ReadWrite));
            QVERIFY(f.setFileTime(oldTime, QFileDevice::FileModificationTime));
            f.close();
            QVERIFY(std::rename(other.toLocal8Bit().constData(), file.toLocal8Bit().constData()) == 0);
        } else if (change == QLatin1String("touch")) {
            QVERIFY(age(file, 60));
        } else if (change == QLatin1String("resize")) {
            QVERIFY(writeImage(file, testImage(64, 32)));
            QVERIFY(age(file));
        } else if (change == QLatin1String("record-version")) {
            editRecord("version", EnvironmentIndex::kVersion + 1);
        } else if (change == QLatin1String("record-path")) {
            editRecord("path", QStringLiteral("/elsewhere/x.exr"));
        } else if (change == QLatin1String("record-size")) {
            editRecord("size", QStringLiteral("12"));
        } else if (change == QLatin1String("record-garbage")) {
            QFile out(record);
            QVERIFY(out.open(QIODevice::WriteOnly | QIODevice::Truncate));
            out.write("{\"format\": \"facet-environment-index\", \"version\": 1, \"pa");
        } else if (change == QLatin1String("record-empty")) {
            QFile out(record);
            QVERIFY(out.open(QIODevice::WriteOnly | QIODevice::Truncate));
        } else if (change == QLatin1String("record-device")) {
            QVERIFY(QFile::remove(record));
            QVERIFY(QFile::link(QStringLiteral("/dev/zero"), record));
        } else if (change == QLatin1String("record-folder")) {
            QVERIFY(QFile::remove(record));
            QVERIFY(QDir().mkpath(record));
        }

        std::string error;
        std::optional<Environment> again = Environment::load(file.toStdString(), &error);
        QVERIFY2(again, error.c_str());
        QVERIFY2(again->decoded(), "the file was taken from a record that does not fit it");
        QCOMPARE(again->contentHash() != first.contentHash(), newPixels);
        if (change == QLatin1String("record-folder"))
            QVERIFY(QDir(record).removeRecursively());
    }

    // A file modified within the last kSettleSeconds could change again within its clock tick
    // without changing its times: it is not remembered.
    void recentFilesAreNotIndexed()
    {
        const QString file = path(QStringLiteral("recent.exr"));
        QVERIFY(writeImage(file, testImage(32, 16)));
        for (int i = 0; i < 2; ++i) {
            std::optional<Environment> environment = Environment::load(file.toStdString(), nullptr);
            QVERIFY(environment);
            QVERIFY(environment->decoded());
        }
        QVERIFY(!QFile::exists(EnvironmentIndex().recordPath(file.toStdString())));
        FileIdentity identity;
        QVERIFY(fileIdentity(file.toStdString(), &identity));
        std::string reason;
        QVERIFY(!EnvironmentIndex().store(file.toStdString(), identity, {1, 32, 16, {}}, &reason));
        QVERIFY2(reason.find("less than 2 s ago") != std::string::npos, reason.c_str());
    }

    // The same file by another spelling of its path (relative, with "./" or "..") is one record.
    void pathsAreAbsolute()
    {
        const QString file = path(QStringLiteral("spelt.exr"));
        Environment first;
        QVERIFY(indexed(file, &first));
        QVERIFY(QDir(m_dir.path()).mkpath(QStringLiteral("sub")));
        const QString other = m_dir.path() + QStringLiteral("/./sub/../spelt.exr");
        QCOMPARE(EnvironmentIndex().recordPath(other.toStdString()),
            EnvironmentIndex().recordPath(file.toStdString()));
        std::optional<Environment> again = Environment::load(other.toStdString(), nullptr);
        QVERIFY(again);
        QVERIFY(!again->decoded());
        QCOMPARE(again->contentHash(), first.contentHash());
    }

    // A record whose file decodes to other pixels (its hash edited here; in use, a file changed
    // within its clock tick) is forgotten, with a warning naming the file, at the first image().
    void wrongRecordIsForgotten()
    {
        const QString file = path(QStringLiteral("wrong.exr"));
        Environment first;
        QVERIFY(indexed(file, &first));
        const QString record = EnvironmentIndex().recordPath(file.toStdString());
        QFile in(record);
        QVERIFY(in.open(QIODevice::ReadOnly));
        QJsonObject object = QJsonDocument::fromJson(in.readAll()).object();
        in.close();
        object.insert(QStringLiteral("contentHash"), QStringLiteral("12345"));
        QFile out(record);
        QVERIFY(out.open(QIODevice::WriteOnly | QIODevice::Truncate));
        out.write(QJsonDocument(object).toJson());
        out.close();

        std::optional<Environment> deferred = Environment::load(file.toStdString(), nullptr);
        QVERIFY(deferred);
        QVERIFY(!deferred->decoded());
        QCOMPARE(deferred->contentHash(), std::uint64_t(12345));
        QTest::ignoreMessage(QtWarningMsg,
            QRegularExpression(
                QStringLiteral("wrong\\.exr: changed on disk without changing its size or times")));
        QVERIFY(samePixels(deferred->image(), first.image())); // the file's pixels
        QVERIFY(!QFile::exists(record));
        std::optional<Environment> again = Environment::load(file.toStdString(), nullptr);
        QVERIFY(again && again->decoded());
        QCOMPARE(again->contentHash(), first.contentHash());
    }

    // A file gone between the load and the first image(): black pixels of the recorded size, a
    // warning naming it, the record forgotten; the next load says the file is missing.
    void fileGoneBeforeDecoding()
    {
        const QString file = path(QStringLiteral("gone.exr"));
        Environment first;
        QVERIFY(indexed(file, &first));
        std::optional<Environment> deferred = Environment::load(file.toStdString(), nullptr);
        QVERIFY(deferred && !deferred->decoded());
        QVERIFY(QFile::remove(file));
        QTest::ignoreMessage(
            QtWarningMsg, QRegularExpression(QStringLiteral("gone\\.exr: .*lighting with black")));
        const Image& image = deferred->image();
        QCOMPARE(image.width(), 32);
        QCOMPARE(image.height(), 16);
        QCOMPARE(image.at(5, 5), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
        QVERIFY(!QFile::exists(EnvironmentIndex().recordPath(file.toStdString())));
        std::string error;
        QVERIFY(!Environment::load(file.toStdString(), &error));
        QVERIFY2(error.find("gone.exr") != std::string::npos, error.c_str());
    }

    // Larger than kMaxWidth x kMaxHeight: kept area-filtered to the largest size of its aspect
    // that fits, each kept texel the mean of the file's texels under it, read a band at a time.
    void largeFilesAreKeptFiltered_data()
    {
        QTest::addColumn<int>("width");
        QTest::addColumn<int>("height");
        QTest::addColumn<int>("keptWidth");
        QTest::addColumn<int>("keptHeight");
        QTest::newRow("fits") << 4096 << 8 << 4096 << 8;
        QTest::newRow("twice as wide") << 8192 << 6 << 4096 << 3;
        QTest::newRow("a little wider") << 4200 << 10 << 4096 << 9;
        QTest::newRow("too tall") << 40 << 4096 << 20 << 2048;
    }
    void largeFilesAreKeptFiltered()
    {
        QFETCH(int, width);
        QFETCH(int, height);
        QFETCH(int, keptWidth);
        QFETCH(int, keptHeight);
        const QString file = path(QStringLiteral("large-%1x%2.exr").arg(width).arg(height));
        Image source = testImage(width, height);
        source.at(1, 1) = glm::vec4(1.0f); // (no NaN: the means below are of the file's values)
        QVERIFY(writeImage(file, source));
        std::string error;
        std::optional<Environment> environment = Environment::load(file.toStdString(), &error);
        QVERIFY2(environment, error.c_str());
        QCOMPARE(environment->width(), keptWidth);
        QCOMPARE(environment->height(), keptHeight);
        const Image& kept = environment->image();
        QCOMPARE(kept.width(), keptWidth);
        // The file stores half floats: the expected means are of what it holds.
        std::optional<Image> stored = Image::load(file.toStdString(), &error);
        QVERIFY2(stored, error.c_str());
        const Image expected = stored->boxFiltered(keptWidth, keptHeight);
        for (int y = 0; y < keptHeight; ++y)
            for (int x = 0; x < keptWidth; ++x)
                QCOMPARE(kept.at(x, y), expected.at(x, y));
        if (width == 2 * keptWidth && height == 2 * keptHeight) {
            const glm::vec4 block
                = (stored->at(6, 2) + stored->at(7, 2) + stored->at(6, 3) + stored->at(7, 3)) / 4.0f;
            QVERIFY(glm::all(glm::lessThan(glm::abs(kept.at(3, 1) - block), glm::vec4(1e-6f))));
        }
    }
};

QTEST_GUILESS_MAIN(EnvironmentIndexTest)
#include "EnvironmentIndexTest.moc"
