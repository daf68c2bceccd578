// core/image/Image refusing bad files with a message that names them, on one line: a missing
// file, text named .png, truncated files of every format (cut in the pixels and in the header; bytes
// after a whole file's end are no reason to refuse it), an EXR of 32-bit integers, a folder, a
// header claiming an absurd size or more pixels than the file can hold, and what is not a regular
// file; texture maps (core/image/MapImage) through the same reader. Fixture files are written with
// OpenImageIO directly (support/ImageFixture.h). Loading good files and saving: ImageTest.

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <sys/stat.h>

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <OpenImageIO/imageio.h>

#include "ImageFixture.h"
#include "TestSupport.h"
#include "core/image/Image.h"
#include "core/image/MapImage.h"

using facet::Image;
using facet::MapImage;
using facet::test::writeFixture;

namespace {

bool writeBytes(const QString& path, const QByteArray& bytes)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

QByteArray readBytes(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

// Rewrites ImageWidth (256) and ImageLength (257) in the first IFD of a little-endian TIFF: the
// header then claims a size the file does not hold (the pixel data stays 4x4).
bool patchTiffSize(QByteArray& tiff, int width, int height)
{
    const auto u16 = [&tiff](qsizetype at) { return quint16(quint8(tiff[at]) | quint8(tiff[at + 1]) << 8); };
    const auto u32 = [&](qsizetype at) { return quint32(u16(at)) | quint32(u16(at + 2)) << 16; };
    const auto put = [&tiff](qsizetype at, quint32 value, int bytes) {
        for (int i = 0; i < bytes; ++i)
            tiff[at + i] = char((value >> (8 * i)) & 0xff);
    };
    if (tiff.size() < 8 || !tiff.startsWith("II*"))
        return false;
    const qsizetype ifd = qsizetype(u32(4));
    const int entries = u16(ifd);
    int patched = 0;
    for (int i = 0; i < entries; ++i) {
        const qsizetype entry = ifd + 2 + 12 * i;
        const quint16 tag = u16(entry);
        const quint16 type = u16(entry + 2);
        if (tag != 256 && tag != 257)
            continue;
        const quint32 value = quint32(tag == 256 ? width : height);
        if (type == 3 && value <= 0xffff) // SHORT
            put(entry + 8, value, 2);
        else if (type == 4) // LONG
            put(entry + 8, value, 4);
        else
            return false;
        ++patched;
    }
    return patched == 2;
}

// What a failed load must say: the function, the path, then a reason, on one line.
void checkLoadError(const std::optional<Image>& image, const std::string& error, const QString& path)
{
    QVERIFY(!image);
    const std::string prefix = "Image::load: " + path.toStdString() + ": ";
    QVERIFY2(error.rfind(prefix, 0) == 0, error.c_str());
    QVERIFY2(error.size() > prefix.size() + 3, error.c_str());
    QVERIFY2(error.find('\n') == std::string::npos, error.c_str());
}

} // namespace

class ImageLoadErrorsTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void missingFileIsAnError();
    void textFileNamedPngIsAnError();
    void truncatedFilesAreErrors_data();
    void truncatedFilesAreErrors();
    void integerExrIsRefused();
    void directoryIsAnError();
    void absurdHeaderSizeIsRefusedBeforeReading();
    void headerClaimingMoreThanTheFileHoldsIsRefused();
    void notAFileIsRefused_data();
    void notAFileIsRefused();
};

void ImageLoadErrorsTest::missingFileIsAnError()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("missing.exr"));
    std::string error;
    const std::optional<Image> image = Image::load(path.toStdString(), &error);
    checkLoadError(image, error, path);
}

void ImageLoadErrorsTest::textFileNamedPngIsAnError()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("notes.png"));
    QVERIFY(writeBytes(path, "This is not an image, just some text.\n"));
    std::string error;
    const std::optional<Image> image = Image::load(path.toStdString(), &error);
    checkLoadError(image, error, path);
}

void ImageLoadErrorsTest::truncatedFilesAreErrors_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("fileType"); // OIIO::TypeDesc::BASETYPE
    QTest::newRow("EXR") << QStringLiteral("cut.exr") << int(OIIO::TypeDesc::HALF);
    QTest::newRow("PNG") << QStringLiteral("cut.png") << int(OIIO::TypeDesc::UINT8);
    // Issue 29: these loaded half grey or half black without a word.
    QTest::newRow("JPEG") << QStringLiteral("cut.jpg") << int(OIIO::TypeDesc::UINT8);
    QTest::newRow("TIFF, strips") << QStringLiteral("cut.tif") << int(OIIO::TypeDesc::UINT8);
    QTest::newRow("TIFF, strips, 16-bit") << QStringLiteral("cut16.tif") << int(OIIO::TypeDesc::UINT16);
    QTest::newRow("TIFF, zip") << QStringLiteral("cut-zip.tif") << int(OIIO::TypeDesc::UINT8);
    QTest::newRow("TIFF, tiles") << QStringLiteral("cut-tiled.tif") << int(OIIO::TypeDesc::UINT8);
}

void ImageLoadErrorsTest::truncatedFilesAreErrors()
{
    QFETCH(QString, name);
    QFETCH(int, fileType);
    QTemporaryDir dir;
    // Noise does not compress: cutting the file in half loses pixel data, not only padding.
    std::vector<float> noise(64 * 64 * 3);
    unsigned state = 12345u;
    for (float& value : noise) {
        state = state * 1664525u + 1013904223u;
        value = float(state >> 8) / float(1u << 24);
    }
    const QString whole = dir.filePath(QStringLiteral("whole-") + name);
    QVERIFY(writeFixture(whole, 64, 64, 3, OIIO::TypeDesc(OIIO::TypeDesc::BASETYPE(fileType)), noise));
    std::string error;
    QVERIFY2(Image::load(whole.toStdString(), &error), error.c_str());
    QVERIFY2(MapImage::load(whole.toStdString(), &error), error.c_str());

    const QByteArray bytes = readBytes(whole);
    const QString path = dir.filePath(name);
    QVERIFY(writeBytes(path, bytes.left(bytes.size() / 2)));
    checkLoadError(Image::load(path.toStdString(), &error), error, path);
    // Texture maps go through the same reader.
    QVERIFY(!MapImage::load(path.toStdString(), &error));
    QVERIFY2(QString::fromStdString(error).contains(path), error.c_str());

    // Cut inside the header as well.
    QVERIFY(writeBytes(path, bytes.left(40)));
    checkLoadError(Image::load(path.toStdString(), &error), error, path);

    // Bytes after the end of a whole file (a camera's appended data) are no reason to refuse it.
    QVERIFY(writeBytes(path, bytes + QByteArray(300, 'x')));
    QVERIFY2(Image::load(path.toStdString(), &error), error.c_str());
}

// Issue 29: an EXR of 32-bit unsigned integer channels (an ID pass) loaded as black (its values
// normalised by 2^32); it is refused, saying what it is.
void ImageLoadErrorsTest::integerExrIsRefused()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("ids.exr"));
    QVERIFY(writeFixture(path, 8, 8, 3, OIIO::TypeDesc::UINT32, std::vector<float>(8 * 8 * 3, 7.0f)));
    std::string error;
    checkLoadError(Image::load(path.toStdString(), &error), error, path);
    QVERIFY2(error.find("32-bit unsigned integers") != std::string::npos, error.c_str());
    QVERIFY(!MapImage::load(path.toStdString(), &error));
    QVERIFY2(error.find("32-bit unsigned integers") != std::string::npos, error.c_str());
}

void ImageLoadErrorsTest::directoryIsAnError()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("folder.exr"));
    QVERIFY(QDir().mkdir(path));
    std::string error;
    checkLoadError(Image::load(path.toStdString(), &error), error, path);
}

void ImageLoadErrorsTest::absurdHeaderSizeIsRefusedBeforeReading()
{
    QTemporaryDir dir;
    const QString tiny = dir.filePath(QStringLiteral("tiny.tif"));
    QVERIFY(writeFixture(tiny, 4, 4, 3, OIIO::TypeDesc::UINT8, std::vector<float>(48, 0.5f)));
    const QByteArray original = readBytes(tiny);

    struct Case {
        int width, height;
        const char* size;
    };
    // One side over kMaxDimension; then both sides allowed but the area over kMaxPixels
    // (20000 x 20000 RGBA32F would be 6.4 GB).
    const Case cases[] = {{60000, 16, "60000x16"}, {16, 40000, "16x40000"}, {20000, 20000, "20000x20000"}};
    static_assert(20000 <= Image::kMaxDimension && std::size_t(20000) * 20000 > Image::kMaxPixels);
    for (const Case& c : cases) {
        QByteArray bytes = original;
        QVERIFY(patchTiffSize(bytes, c.width, c.height));
        const QString path = dir.filePath(QStringLiteral("huge-%1.tif").arg(QLatin1String(c.size)));
        QVERIFY(writeBytes(path, bytes));
        std::string error;
        const std::optional<Image> image = Image::load(path.toStdString(), &error);
        checkLoadError(image, error, path);
        // Our refusal, naming the claimed size, not an allocation or a decoder failure.
        QVERIFY2(error.find("too large") != std::string::npos, error.c_str());
        QVERIFY2(error.find(c.size) != std::string::npos, error.c_str());
    }
}

// A 68-byte PNG (valid chunks and CRCs) whose header claims 32768 x 8192: exactly the pixel
// limit, so only the file's size tells it cannot be real. It cost 4 GiB and 18-55 s to fail.
void ImageLoadErrorsTest::headerClaimingMoreThanTheFileHoldsIsRefused()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("claims-32768x8192.png"));
    QVERIFY(writeBytes(path,
        QByteArray::fromHex(
            "89504e470d0a1a0a0000000d49484452000080000000200008020000000cb5e7460000000b4944415478"
            "9c6360c00700001e0001f6fde9960000000049454e44ae426082")));
    static_assert(std::size_t(32768) * 8192 <= Image::kMaxPixels);
    QElapsedTimer clock;
    clock.start();
    std::string error;
    const std::optional<Image> image = Image::load(path.toStdString(), &error);
    checkLoadError(image, error, path);
    QVERIFY2(error.find("claims 32768x8192 pixels, too large for a file of 68 bytes") != std::string::npos,
        error.c_str());
    QVERIFY2(clock.elapsed() < facet::test::wallClockBoundMs(2000),
        qPrintable(QStringLiteral("%1 ms").arg(clock.elapsed())));
    // The same refusal for a material map and a box-filtered (thumbnail) read.
    const std::optional<Image> thumbnail = Image::loadBoxFiltered(
        path.toStdString(), true,
        [](int, int) {
            return std::pair {64, 32};
        },
        &error);
    QVERIFY(!thumbnail);
    QVERIFY2(error.find("too large for a file of 68 bytes") != std::string::npos, error.c_str());
}

void ImageLoadErrorsTest::notAFileIsRefused_data()
{
    QTest::addColumn<QString>("kind");
    QTest::addColumn<QString>("reason");
    QTest::newRow("a FIFO") << QStringLiteral("fifo") << QStringLiteral("is not a regular file");
    QTest::newRow("/dev/zero") << QStringLiteral("zero") << QStringLiteral("is not a regular file");
    QTest::newRow("/dev/urandom") << QStringLiteral("urandom") << QStringLiteral("is not a regular file");
    QTest::newRow("a link loop") << QStringLiteral("loop") << QStringLiteral("is a loop of symbolic links");
    QTest::newRow("a NUL in the path") << QStringLiteral("nul") << QStringLiteral("holds a NUL character");
}

void ImageLoadErrorsTest::notAFileIsRefused()
{
    QFETCH(QString, kind);
    QFETCH(QString, reason);
    QTemporaryDir dir;
    std::string path = dir.filePath(QStringLiteral("image.exr")).toStdString();
    if (kind == QLatin1String("fifo"))
        QCOMPARE(::mkfifo(path.c_str(), 0600), 0);
    else if (kind == QLatin1String("zero") || kind == QLatin1String("urandom"))
        path = "/dev/" + kind.toStdString();
    else if (kind == QLatin1String("loop"))
        QVERIFY(QFile::link(QString::fromStdString(path), QString::fromStdString(path)));
    else
        path = dir.filePath(QStringLiteral("a.png")).toStdString() + std::string(1, '\0') + ".exr";
    std::string error;
    QVERIFY(!Image::load(path, &error));
    QVERIFY2(error.find(reason.toStdString()) != std::string::npos, error.c_str());
}

QTEST_GUILESS_MAIN(ImageLoadErrorsTest)
#include "ImageLoadErrorsTest.moc"
