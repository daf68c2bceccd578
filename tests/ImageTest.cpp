// core/image/Image: loading through OpenImageIO (channel expansion, encoding, sanitising), atomic
// saving, and the box-filtered read. Fixture files are written with OpenImageIO directly
// (support/ImageFixture.h, not through Image::save) so a bug in save cannot hide one in load, and
// 8-bit files are cross-checked with QImage. Refusing bad files with a message naming them:
// ImageLoadErrorsTest.

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include <QDir>
#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <OpenImageIO/imageio.h>

#include "ImageFixture.h"
#include "TestSupport.h"
#include "core/image/Image.h"

// QCOMPARE prints values it knows; teach it glm's vectors (found by argument-dependent lookup).
namespace glm {
char* toString(const glm::vec4& v)
{
    return qstrdup(QByteArray("(" + QByteArray::number(v.x, 'g', 9) + ", " + QByteArray::number(v.y, 'g', 9)
        + ", " + QByteArray::number(v.z, 'g', 9) + ", " + QByteArray::number(v.w, 'g', 9) + ")")
                       .constData());
}
} // namespace glm

using facet::ColorEncoding;
using facet::Image;
using facet::ImageLoadStats;
using facet::test::writeFixture;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// OIIO turns byte k into k * (1/255.f), which may differ from k / 255.f in the last bit.
bool fuzzyEqual(const glm::vec4& a, const glm::vec4& b)
{
    for (int c = 0; c < 4; ++c)
        if (!(std::abs(a[c] - b[c]) <= 1e-6f))
            return false;
    return true;
}

#define COMPARE_PIXEL(actual, expected)                                                                      \
    QVERIFY2(fuzzyEqual((actual), (expected)),                                                               \
        qPrintable(QStringLiteral("%1 != %2")                                                                \
                       .arg(QLatin1String(glm::toString(actual)))                                            \
                       .arg(QLatin1String(glm::toString(expected)))))

// k / 255: a value an 8-bit file stores exactly.
float byteValue(int k)
{
    return float(k) / 255.0f;
}

QStringList entriesOf(const QString& dir)
{
    return QDir(dir).entryList(QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot);
}

} // namespace

class ImageTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void constructAndAccess();
    void sanitizeInMemory();
    void exrWithSpecialValuesIsSanitised();
    void greyPngExpandsToRgb();
    void greyAlphaPngExpandsToRgba();
    void rgbPngGetsOpaqueAlpha();
    void rgbaPngKeepsUnassociatedAlpha();
    void encodingFollowsFileAndFormat_data();
    void encodingFollowsFileAndFormat();
    void toLinearMatchesSrgbEotf();
    void exrRoundTrip();
    void exrWithoutAlphaRoundTrip();
    void pngSaveWritesValuesAsGiven();
    void saveReplacesExistingFile();
    void failedSaveLeavesNothingBehind();
    void boxFilteredReadMatchesTheWholeImage_data();
    void boxFilteredReadMatchesTheWholeImage();
};

void ImageTest::constructAndAccess()
{
    Image image(3, 2, glm::vec4(0.25f, 0.5f, 0.75f, 1.0f));
    QCOMPARE(image.width(), 3);
    QCOMPARE(image.height(), 2);
    QCOMPARE(image.pixelCount(), std::size_t(6));
    QVERIFY(!image.isEmpty());
    QCOMPARE(image.at(2, 1).y, 0.5f);
    image.at(2, 1) = glm::vec4(1.0f);
    // Row-major from the top: (2, 1) is the last pixel.
    QCOMPARE(image.data()[5].x, 1.0f);
    QVERIFY(Image().isEmpty());
}

void ImageTest::sanitizeInMemory()
{
    Image image(4, 1);
    image.at(0, 0) = {kNaN, -kInf, kInf, kNaN};
    image.at(1, 0) = {-1.0f, 2.0f, -0.5f, 1.5f};
    image.at(2, 0) = {0.0f, 1e30f, 3.0f, -kInf};
    image.at(3, 0) = {0.5f, 0.5f, 0.5f, 0.25f};
    const ImageLoadStats stats = image.sanitize();
    QCOMPARE(stats.nanCount, std::size_t(2)); // R of pixel 0, its alpha
    QCOMPARE(stats.infCount, std::size_t(3)); // G, B of pixel 0, alpha of pixel 2
    QCOMPARE(stats.negativeCount, std::size_t(2)); // R, B of pixel 1
    QCOMPARE(stats.total(), std::size_t(7));
    QCOMPARE(image.at(0, 0), glm::vec4(0.0f, 0.0f, 65504.0f, 1.0f));
    QCOMPARE(image.at(1, 0), glm::vec4(0.0f, 2.0f, 0.0f, 1.0f)); // alpha 1.5 clamped, not counted
    QCOMPARE(image.at(2, 0), glm::vec4(0.0f, 1e30f, 3.0f, 0.0f)); // large finite values stay
    QCOMPARE(image.at(3, 0), glm::vec4(0.5f, 0.5f, 0.5f, 0.25f));
    // A clean image stays as it is.
    QCOMPARE(image.sanitize().total(), std::size_t(0));
}

void ImageTest::exrWithSpecialValuesIsSanitised()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("special.exr"));
    // 3x2 RGBA float: 2 NaN (one colour, one alpha), 3 Inf (+Inf, -Inf colour, +Inf alpha),
    // 4 negative (three colour, one alpha).
    const std::vector<float> values = {
        kNaN,
        1.0f,
        2.0f,
        1.0f,
        /**/ kInf,
        -kInf,
        0.5f,
        0.5f,
        /**/ -0.25f,
        -3.0f,
        0.125f,
        kNaN,
        -1e-6f,
        0.2f,
        0.3f,
        2.0f,
        /**/ 1.0f,
        1.0f,
        1.0f,
        -0.5f,
        /**/ 4.0f,
        5.0f,
        6.0f,
        kInf,
    };
    QVERIFY(writeFixture(path, 3, 2, 4, OIIO::TypeDesc::FLOAT, values));

    std::string error;
    ImageLoadStats stats;
    const std::optional<Image> image = Image::load(path.toStdString(), &error, &stats);
    QVERIFY2(image, error.c_str());
    QCOMPARE(stats.nanCount, std::size_t(2));
    QCOMPARE(stats.infCount, std::size_t(3));
    QCOMPARE(stats.negativeCount, std::size_t(4));
    QCOMPARE(image->sourceChannels(), 4);
    QCOMPARE(image->encoding(), ColorEncoding::Linear);
    QCOMPARE(image->at(0, 0), glm::vec4(0.0f, 1.0f, 2.0f, 1.0f));
    QCOMPARE(image->at(1, 0), glm::vec4(65504.0f, 0.0f, 0.5f, 0.5f));
    QCOMPARE(image->at(2, 0), glm::vec4(0.0f, 0.0f, 0.125f, 1.0f));
    QCOMPARE(image->at(0, 1), glm::vec4(0.0f, 0.2f, 0.3f, 1.0f));
    QCOMPARE(image->at(1, 1), glm::vec4(1.0f, 1.0f, 1.0f, 0.0f));
    QCOMPARE(image->at(2, 1), glm::vec4(4.0f, 5.0f, 6.0f, 1.0f));
}

void ImageTest::greyPngExpandsToRgb()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("grey.png"));
    QVERIFY(writeFixture(path, 3, 1, 1, OIIO::TypeDesc::UINT8, {0.0f, byteValue(128), 1.0f}));
    // The fixture is what we think it is.
    QCOMPARE(QImage(path).pixelColor(1, 0).red(), 128);

    std::string error;
    const std::optional<Image> image = Image::load(path.toStdString(), &error);
    QVERIFY2(image, error.c_str());
    QCOMPARE(image->sourceChannels(), 1);
    QCOMPARE(image->encoding(), ColorEncoding::SRGB);
    QCOMPARE(image->at(0, 0), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    COMPARE_PIXEL(image->at(1, 0), glm::vec4(byteValue(128), byteValue(128), byteValue(128), 1.0f));
    QCOMPARE(image->at(2, 0), glm::vec4(1.0f));
}

void ImageTest::greyAlphaPngExpandsToRgba()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("greyalpha.png"));
    QVERIFY(writeFixture(
        path, 2, 1, 2, OIIO::TypeDesc::UINT8, {byteValue(200), byteValue(64), byteValue(10), 1.0f}));
    std::string error;
    const std::optional<Image> image = Image::load(path.toStdString(), &error);
    QVERIFY2(image, error.c_str());
    QCOMPARE(image->sourceChannels(), 2);
    QCOMPARE(image->encoding(), ColorEncoding::SRGB);
    // Grey not premultiplied by the alpha of 64/255.
    COMPARE_PIXEL(image->at(0, 0), glm::vec4(byteValue(200), byteValue(200), byteValue(200), byteValue(64)));
    COMPARE_PIXEL(image->at(1, 0), glm::vec4(byteValue(10), byteValue(10), byteValue(10), 1.0f));
}

void ImageTest::rgbPngGetsOpaqueAlpha()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("rgb.png"));
    QVERIFY(writeFixture(path, 1, 2, 3, OIIO::TypeDesc::UINT8,
        {byteValue(255), byteValue(128), byteValue(1), 0.0f, byteValue(17), byteValue(254)}));
    std::string error;
    const std::optional<Image> image = Image::load(path.toStdString(), &error);
    QVERIFY2(image, error.c_str());
    QCOMPARE(image->sourceChannels(), 3);
    QCOMPARE(image->width(), 1);
    QCOMPARE(image->height(), 2);
    COMPARE_PIXEL(image->at(0, 0), glm::vec4(1.0f, byteValue(128), byteValue(1), 1.0f));
    COMPARE_PIXEL(image->at(0, 1), glm::vec4(0.0f, byteValue(17), byteValue(254), 1.0f));
}

void ImageTest::rgbaPngKeepsUnassociatedAlpha()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("rgba.png"));
    QVERIFY(writeFixture(path, 2, 1, 4, OIIO::TypeDesc::UINT8,
        {byteValue(200), byteValue(100), byteValue(50), byteValue(128), /**/ 1.0f, 1.0f, 0.0f, 0.0f}));
    // Cross-check the bytes with another decoder: Qt's ARGB32 is unassociated.
    const QImage check = QImage(path).convertToFormat(QImage::Format_ARGB32);
    QCOMPARE(qRed(check.pixel(0, 0)), 200);
    QCOMPARE(qAlpha(check.pixel(0, 0)), 128);
    QCOMPARE(qRed(check.pixel(1, 0)), 255);

    std::string error;
    const std::optional<Image> image = Image::load(path.toStdString(), &error);
    QVERIFY2(image, error.c_str());
    QCOMPARE(image->sourceChannels(), 4);
    COMPARE_PIXEL(image->at(0, 0), glm::vec4(byteValue(200), byteValue(100), byteValue(50), byteValue(128)));
    // A transparent texel keeps its colour (premultiplying would make it black).
    QCOMPARE(image->at(1, 0), glm::vec4(1.0f, 1.0f, 0.0f, 0.0f));
}

void ImageTest::encodingFollowsFileAndFormat_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("type");
    QTest::addColumn<QString>("colorSpace");
    QTest::addColumn<bool>("srgb");
    QTest::newRow("8-bit png") << QStringLiteral("a.png") << int(OIIO::TypeDesc::UINT8) << QString() << true;
    QTest::newRow("16-bit png") << QStringLiteral("a.png") << int(OIIO::TypeDesc::UINT16) << QString()
                                << true;
    QTest::newRow("jpeg") << QStringLiteral("a.jpg") << int(OIIO::TypeDesc::UINT8) << QString() << true;
    QTest::newRow("8-bit tiff, untagged")
        << QStringLiteral("a.tif") << int(OIIO::TypeDesc::UINT8) << QString() << true;
    // PNG stores these as a gAMA chunk (1.0, 1/2.2): the file's word wins over the convention.
    QTest::newRow("8-bit png, gamma 1")
        << QStringLiteral("a.png") << int(OIIO::TypeDesc::UINT8) << QStringLiteral("Linear") << false;
    QTest::newRow("8-bit png, gamma 2.2") << QStringLiteral("a.png") << int(OIIO::TypeDesc::UINT8)
                                          << QStringLiteral("GammaCorrected2.2") << true;
    QTest::newRow("16-bit tiff, untagged")
        << QStringLiteral("a.tif") << int(OIIO::TypeDesc::UINT16) << QString() << true;
    QTest::newRow("float tiff") << QStringLiteral("a.tif") << int(OIIO::TypeDesc::FLOAT) << QString()
                                << false;
    QTest::newRow("half exr") << QStringLiteral("a.exr") << int(OIIO::TypeDesc::HALF) << QString() << false;
    QTest::newRow("radiance hdr") << QStringLiteral("a.hdr") << int(OIIO::TypeDesc::FLOAT) << QString()
                                  << false;
}

void ImageTest::encodingFollowsFileAndFormat()
{
    QFETCH(QString, name);
    QFETCH(int, type);
    QFETCH(QString, colorSpace);
    QFETCH(bool, srgb);
    QTemporaryDir dir;
    const QString path = dir.filePath(name);
    const QByteArray colorSpaceText = colorSpace.toLatin1();
    QVERIFY(writeFixture(path, 2, 2, 3, OIIO::TypeDesc(OIIO::TypeDesc::BASETYPE(type)),
        std::vector<float>(12, 0.5f), colorSpace.isEmpty() ? nullptr : colorSpaceText.constData()));
    std::string error;
    const std::optional<Image> image = Image::load(path.toStdString(), &error);
    QVERIFY2(image, error.c_str());
    QCOMPARE(image->encoding(), srgb ? ColorEncoding::SRGB : ColorEncoding::Linear);
    // Nothing is decoded on load: the file's 0.5 (within its quantisation) is still there.
    QVERIFY(std::abs(image->at(1, 1).x - 0.5f) < 0.01f);
}

void ImageTest::toLinearMatchesSrgbEotf()
{
    // Reference values of the IEC 61966-2-1 EOTF, computed in double precision.
    struct Case {
        float encoded, linear;
    };
    const Case cases[] = {
        {0.0f, 0.0f},
        {0.02f, 0.02f / 12.92f}, // linear toe
        {0.035f, 0.035f / 12.92f}, // still the toe (the power curve gives 0.2% less)
        {0.04045f, 0.0031308049535603713f}, // the joint, from the toe side
        {0.05f, 0.003935939504088967f}, // just past it: ((0.05+0.055)/1.055)^2.4
        {0.5f, 0.21404114048223255f},
        {byteValue(128), 0.21586050011389926f},
        {0.8f, 0.6038273388553378f},
        {1.0f, 1.0f},
    };
    Image image(int(std::size(cases)), 1);
    for (int i = 0; i < int(std::size(cases)); ++i)
        image.at(i, 0) = glm::vec4(cases[i].encoded, cases[i].encoded, cases[i].encoded, 0.5f);

    // A linear image is left alone.
    Image linear = image;
    linear.toLinear();
    for (int i = 0; i < int(std::size(cases)); ++i)
        QCOMPARE(linear.at(i, 0).x, cases[i].encoded);

    image.setEncoding(ColorEncoding::SRGB);
    image.toLinear();
    QCOMPARE(image.encoding(), ColorEncoding::Linear);
    for (int i = 0; i < int(std::size(cases)); ++i) {
        const glm::vec4 pixel = image.at(i, 0);
        for (int c = 0; c < 3; ++c)
            QVERIFY2(std::abs(pixel[c] - cases[i].linear) <= 2e-7f + 1e-6f * cases[i].linear,
                qPrintable(QStringLiteral("%1 -> %2, expected %3")
                               .arg(cases[i].encoded)
                               .arg(pixel[c])
                               .arg(cases[i].linear)));
        QCOMPARE(pixel.w, 0.5f); // alpha is not a colour
    }
    // Decoding twice would darken again: the second call is a no-op.
    image.toLinear();
    for (int i = 0; i < int(std::size(cases)); ++i)
        QVERIFY(std::abs(image.at(i, 0).x - cases[i].linear) <= 2e-7f + 1e-6f * cases[i].linear);
}

void ImageTest::exrRoundTrip()
{
    Image image(3, 2);
    image.at(0, 0) = {0.0f, 0.25f, 1.0f, 1.0f};
    image.at(1, 0) = {1.5f, 1000.0f, 0.001f, 0.5f};
    image.at(2, 0) = {3.14159f, 2.71828f, 60000.0f, 0.0f};
    image.at(0, 1) = {1e6f, 0.1f, 0.2f, 1.0f}; // beyond half: written as the largest half, not Inf
    image.at(1, 1) = {7.0f, 8.0f, 9.0f, 0.75f};
    image.at(2, 1) = {0.5f, 0.5f, 0.5f, 0.25f};

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("round.exr"));
    std::string error;
    QVERIFY2(image.save(path.toStdString(), &error), error.c_str());
    QCOMPARE(entriesOf(dir.path()), QStringList {QStringLiteral("round.exr")});

    ImageLoadStats stats;
    const std::optional<Image> loaded = Image::load(path.toStdString(), &error, &stats);
    QVERIFY2(loaded, error.c_str());
    QCOMPARE(stats.total(), std::size_t(0));
    QCOMPARE(loaded->width(), 3);
    QCOMPARE(loaded->height(), 2);
    QCOMPARE(loaded->sourceChannels(), 4);
    QCOMPARE(loaded->encoding(), ColorEncoding::Linear);
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 3; ++x) {
            for (int c = 0; c < 4; ++c) {
                const float expected = std::min(image.at(x, y)[c], 65504.0f);
                const float actual = loaded->at(x, y)[c];
                // Half floats keep 11 significant bits: relative error at most 2^-11.
                QVERIFY2(std::abs(actual - expected) <= expected * (1.0f / 2048.0f) + 1e-7f,
                    qPrintable(QStringLiteral("(%1,%2)[%3]: %4 != %5")
                                   .arg(x)
                                   .arg(y)
                                   .arg(c)
                                   .arg(actual)
                                   .arg(expected)));
            }
        }
    }
}

void ImageTest::exrWithoutAlphaRoundTrip()
{
    Image image(2, 1, glm::vec4(0.5f, 2.0f, 4.0f, 0.25f));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("rgb.exr"));
    std::string error;
    QVERIFY2(image.save(path.toStdString(), &error, false), error.c_str());
    const std::optional<Image> loaded = Image::load(path.toStdString(), &error);
    QVERIFY2(loaded, error.c_str());
    QCOMPARE(loaded->sourceChannels(), 3);
    QCOMPARE(loaded->at(1, 0), glm::vec4(0.5f, 2.0f, 4.0f, 1.0f)); // exact in half
}

void ImageTest::pngSaveWritesValuesAsGiven()
{
    Image image(3, 1);
    image.at(0, 0) = {byteValue(200), byteValue(100), byteValue(50), byteValue(128)};
    image.at(1, 0) = {2.0f, -1.0f, kNaN, 1.0f}; // clamped to [0,1], NaN stored as 0
    image.at(2, 0) = {1.0f, 1.0f, 1.0f, 0.0f}; // transparent but coloured
    image.setEncoding(ColorEncoding::SRGB);

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("out.png"));
    std::string error;
    QVERIFY2(image.save(path.toStdString(), &error), error.c_str());

    const QImage check = QImage(path).convertToFormat(QImage::Format_ARGB32);
    QCOMPARE(check.size(), QSize(3, 1));
    QCOMPARE(check.pixel(0, 0), qRgba(200, 100, 50, 128)); // not divided by alpha
    QCOMPARE(check.pixel(1, 0), qRgba(255, 0, 0, 255));
    QCOMPARE(check.pixel(2, 0), qRgba(255, 255, 255, 0));

    const std::optional<Image> loaded = Image::load(path.toStdString(), &error);
    QVERIFY2(loaded, error.c_str());
    QCOMPARE(loaded->encoding(), ColorEncoding::SRGB);
    COMPARE_PIXEL(loaded->at(0, 0), image.at(0, 0));

    // A format without alpha drops it and still succeeds.
    const QString jpeg = dir.filePath(QStringLiteral("out.jpg"));
    QVERIFY2(image.save(jpeg.toStdString(), &error), error.c_str());
    const std::optional<Image> loadedJpeg = Image::load(jpeg.toStdString(), &error);
    QVERIFY2(loadedJpeg, error.c_str());
    QCOMPARE(loadedJpeg->sourceChannels(), 3);
}

void ImageTest::saveReplacesExistingFile()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("over.exr"));
    std::string error;
    QVERIFY2(Image(2, 2, glm::vec4(1.0f)).save(path.toStdString(), &error), error.c_str());
    QVERIFY2(Image(4, 2, glm::vec4(0.5f)).save(path.toStdString(), &error), error.c_str());
    const std::optional<Image> loaded = Image::load(path.toStdString(), &error);
    QVERIFY2(loaded, error.c_str());
    QCOMPARE(loaded->width(), 4);
    QCOMPARE(loaded->at(3, 1).x, 0.5f);
    // No temporary left next to it.
    QCOMPARE(entriesOf(dir.path()), QStringList {QStringLiteral("over.exr")});
}

void ImageTest::failedSaveLeavesNothingBehind()
{
    QTemporaryDir dir;
    const Image image(2, 2, glm::vec4(0.5f));
    std::string error;

    // A directory that does not exist: the temporary file cannot even be created.
    const QString missingDir = dir.filePath(QStringLiteral("no/such/dir/out.exr"));
    QVERIFY(!image.save(missingDir.toStdString(), &error));
    QVERIFY2(error.rfind("Image::save: " + missingDir.toStdString() + ": ", 0) == 0, error.c_str());
    QVERIFY(entriesOf(dir.path()).isEmpty());

    // The target is a directory: the temporary file is written in full, then the rename fails;
    // the temporary must go. (Permissions cannot make this fail when the tests run as root.)
    const QString folder = dir.filePath(QStringLiteral("folder.exr"));
    QVERIFY(QDir().mkdir(folder));
    error.clear();
    QVERIFY(!image.save(folder.toStdString(), &error));
    QVERIFY2(error.rfind("Image::save: " + folder.toStdString() + ": ", 0) == 0, error.c_str());
    QCOMPARE(entriesOf(dir.path()), QStringList {QStringLiteral("folder.exr")});
    QVERIFY(entriesOf(folder).isEmpty());

    // An extension no writer knows.
    const QString unknown = dir.filePath(QStringLiteral("out.notaformat"));
    error.clear();
    QVERIFY(!image.save(unknown.toStdString(), &error));
    QVERIFY2(error.rfind("Image::save: " + unknown.toStdString() + ": ", 0) == 0, error.c_str());
    QCOMPARE(entriesOf(dir.path()), QStringList {QStringLiteral("folder.exr")});

    // Nothing to write.
    const QString empty = dir.filePath(QStringLiteral("empty.exr"));
    error.clear();
    QVERIFY(!Image().save(empty.toStdString(), &error));
    QVERIFY2(error.rfind("Image::save: " + empty.toStdString() + ": ", 0) == 0, error.c_str());
    QVERIFY(!QFile::exists(empty));
}

// Image::loadBoxFiltered (thumbnails of large HDRIs read a band at a time) gives what loading
// the whole image and filtering it gives: several bands (2048 x 1024 is two), bins wider and
// narrower than a texel, special values sanitised, an sRGB file decoded.
void ImageTest::boxFilteredReadMatchesTheWholeImage_data()
{
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("width");
    QTest::addColumn<int>("height");
    QTest::addColumn<int>("outWidth");
    QTest::addColumn<int>("outHeight");
    QTest::newRow("EXR in two bands, to 64 x 32") << "big.exr" << 2048 << 1024 << 64 << 32;
    QTest::newRow("EXR, odd sizes") << "odd.exr" << 301 << 97 << 37 << 11;
    QTest::newRow("EXR, enlarged") << "small.exr" << 16 << 8 << 64 << 32;
    QTest::newRow("sRGB PNG, decoded") << "ldr.png" << 300 << 150 << 64 << 32;
}

void ImageTest::boxFilteredReadMatchesTheWholeImage()
{
    QFETCH(QString, name);
    QFETCH(int, width);
    QFETCH(int, height);
    QFETCH(int, outWidth);
    QFETCH(int, outHeight);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(name);
    const bool png = name.endsWith(QLatin1String(".png"));
    std::vector<float> values(std::size_t(width) * std::size_t(height) * 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c) {
                const float wave = 0.5f + 0.45f * std::sin(0.05f * float(x * (c + 1)) + 0.11f * float(y));
                values[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3 + std::size_t(c)]
                    = png ? wave : wave * 4.0f;
            }
    if (!png) {
        values[3 * 5] = std::numeric_limits<float>::quiet_NaN(); // sanitised to 0
        values[3 * 7 + 1] = -2.0f;
        values[3 * (std::size_t(width) * std::size_t(height / 2) + std::size_t(width / 3))]
            = 5000.0f; // a sun
    }
    QVERIFY(writeFixture(path, width, height, 3, png ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::HALF, values));

    std::string error;
    std::optional<Image> whole = Image::load(path.toStdString(), &error);
    QVERIFY2(whole, error.c_str());
    whole->toLinear();
    const Image expected = whole->boxFiltered(outWidth, outHeight);
    int sourceWidth = 0;
    int sourceHeight = 0;
    const auto filtered = Image::loadBoxFiltered(
        path.toStdString(), true, [&](int, int) { return std::pair<int, int>(outWidth, outHeight); }, &error,
        &sourceWidth, &sourceHeight);
    QVERIFY2(filtered, error.c_str());
    QCOMPARE(sourceWidth, width);
    QCOMPARE(sourceHeight, height);
    QCOMPARE(filtered->width(), outWidth);
    QCOMPARE(filtered->height(), outHeight);
    QCOMPARE(filtered->encoding(), ColorEncoding::Linear);
    for (int y = 0; y < outHeight; ++y)
        for (int x = 0; x < outWidth; ++x)
            for (int c = 0; c < 4; ++c) {
                const float a = filtered->at(x, y)[c];
                const float b = expected.at(x, y)[c];
                QVERIFY2(std::isfinite(a) && std::abs(a - b) <= 1e-5f * std::max(1.0f, std::abs(b)),
                    qPrintable(QStringLiteral("(%1, %2)[%3]: %4, whole image %5")
                                   .arg(x)
                                   .arg(y)
                                   .arg(c)
                                   .arg(a)
                                   .arg(b)));
            }
    // A missing file is named.
    const auto missing = Image::loadBoxFiltered(
        dir.filePath(QStringLiteral("none.exr")).toStdString(), true,
        [](int w, int h) { return std::pair<int, int>(w, h); }, &error);
    QVERIFY(!missing);
    QVERIFY2(error.find("none.exr") != std::string::npos, error.c_str());
}

QTEST_GUILESS_MAIN(ImageTest)
#include "ImageTest.moc"
