// OpenEXR files read by core (core/image/BuiltinExrDecoder.h) against the image module's reads of the
// same files, the EXR header checks made before any decoder sees a file (core/image/ImageReader), and
// bands of rows through both decoders. Files are written with OpenImageIO directly.

#include <QFile>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "TestSupport.h"
#include "core/image/BuiltinExrDecoder.h"
#include "core/image/Image.h"
#include "core/image/ImageCodec.h"
#include "core/image/ImageReader.h"

using namespace facet;

namespace {

// An EXR of the ramp written by OpenImageIO: channels `names` of `types` (one type for all, or
// one each), `compression`, tiles of `tile` pixels (0: scanlines), the data window at `origin`.
bool writeExrWithOiio(const QString& path, const QStringList& names, const QList<int>& types,
    const QString& compression, int tile, int originX, int originY)
{
    constexpr int kWidth = 37;
    constexpr int kHeight = 21;
    std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path.toStdString());
    OIIO::ImageSpec spec(kWidth, kHeight, int(names.size()), OIIO::TypeDesc::BASETYPE(types.first()));
    spec.channelnames.clear();
    for (const QString& name : names)
        spec.channelnames.push_back(name.toStdString());
    if (types.size() > 1)
        for (int type : types)
            spec.channelformats.emplace_back(OIIO::TypeDesc::BASETYPE(type));
    spec.alpha_channel = int(names.indexOf(QStringLiteral("A")));
    spec.attribute("compression", compression.toStdString());
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (tile > 0) {
        spec.tile_width = tile;
        spec.tile_height = tile;
    }
    spec.x = originX;
    spec.y = originY;
    spec.full_x = 0;
    spec.full_y = 0;
    spec.full_width = kWidth + originX;
    spec.full_height = kHeight + originY;
    std::vector<float> values = facet::test::ramp(kWidth, kHeight, int(names.size()));
    for (std::size_t i = 0; i < values.size(); ++i)
        values[i] = values[i] * 7.3f - 1.1f; // negative and above 1, as HDR files hold
    return output && output->open(path.toStdString(), spec)
        && output->write_image(OIIO::TypeDesc::FLOAT, values.data()) && output->close();
}

} // namespace

class ExrReadingTest : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    QString path(const QString& name) const { return m_dir.filePath(name); }

private Q_SLOTS:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    // The built-in EXR decoder gives what the module gives, header and samples bit for bit, for
    // every layout it takes; the layouts it leaves to the module are left (opened by neither
    // error nor decoder), and the module reads them.
    void builtinExrDecoderMatchesTheModule_data()
    {
        QTest::addColumn<QStringList>("names");
        QTest::addColumn<QList<int>>("types");
        QTest::addColumn<QString>("compression");
        QTest::addColumn<int>("tile");
        QTest::addColumn<int>("origin");
        QTest::addColumn<bool>("builtin");
        const int half = OIIO::TypeDesc::HALF;
        const int single = OIIO::TypeDesc::FLOAT;
        const QStringList rgb = facet::test::strings({"R", "G", "B"});
        const QStringList rgba = facet::test::strings({"R", "G", "B", "A"});
        QTest::newRow("RGB half zip") << rgb << QList<int> {half} << "zip" << 0 << 0 << true;
        QTest::newRow("RGBA float none") << rgba << QList<int> {single} << "none" << 0 << 0 << true;
        QTest::newRow("RGBA half piz") << rgba << QList<int> {half} << "piz" << 0 << 0 << true;
        QTest::newRow("RGB half dwaa") << rgb << QList<int> {half} << "dwaa" << 0 << 0 << true;
        QTest::newRow("RGB half dwab") << rgb << QList<int> {half} << "dwab" << 0 << 0 << true;
        QTest::newRow("RGB half b44") << rgb << QList<int> {half} << "b44" << 0 << 0 << true;
        QTest::newRow("RGB float pxr24") << rgb << QList<int> {single} << "pxr24" << 0 << 0 << true;
        QTest::newRow("RGB half rle") << rgb << QList<int> {half} << "rle" << 0 << 0 << true;
        QTest::newRow("RGB float zips") << rgb << QList<int> {single} << "zips" << 0 << 0 << true;
        QTest::newRow("Y half") << facet::test::strings({"Y"}) << QList<int> {half} << "zip" << 0 << 0 << true;
        QTest::newRow("Y A float") << facet::test::strings({"Y", "A"}) << QList<int> {single} << "zip" << 0 << 0
                                   << true;
        QTest::newRow("R G float") << facet::test::strings({"R", "G"}) << QList<int> {single} << "zip" << 0 << 0
                                   << true;
        QTest::newRow("A only") << facet::test::strings({"A"}) << QList<int> {half} << "zip" << 0 << 0 << true;
        QTest::newRow("RGBA half tiled 16") << rgba << QList<int> {half} << "zip" << 16 << 0 << true;
        QTest::newRow("RGB float tiled 8, data window at 5,3") << rgb << QList<int> {single} << "piz" << 8 << 4
                                                               << true;
        QTest::newRow("RGB half, data window at 5,3") << rgb << QList<int> {half} << "zip" << 0 << 4 << true;
        // The module's: layers, other names, mixed and integer samples, luminance with colour.
        QTest::newRow("layer") << facet::test::strings({"diffuse.R", "diffuse.G", "diffuse.B"})
                               << QList<int> {half} << "zip" << 0 << 0 << false;
        QTest::newRow("lowercase names") << facet::test::strings({"r", "g", "b"}) << QList<int> {half} << "zip"
                                         << 0 << 0 << false;
        QTest::newRow("RGBA and Z") << facet::test::strings({"R", "G", "B", "A", "Z"}) << QList<int> {half}
                                    << "zip" << 0 << 0 << false;
        QTest::newRow("mixed half and float") << rgba << QList<int> {half, half, half, single} << "zip" << 0 << 0
                                              << false;
        QTest::newRow("32-bit integer") << rgb << QList<int> {int(OIIO::TypeDesc::UINT)} << "zip" << 0 << 0
                                        << false;
        QTest::newRow("Y with R") << facet::test::strings({"R", "Y"}) << QList<int> {half} << "zip" << 0 << 0
                                  << false;
    }
    void builtinExrDecoderMatchesTheModule()
    {
        QFETCH(QStringList, names);
        QFETCH(QList<int>, types);
        QFETCH(QString, compression);
        QFETCH(int, tile);
        QFETCH(int, origin);
        QFETCH(bool, builtin);
        const QString file = path(QStringLiteral("decode-%1.exr").arg(QString::fromLatin1(QTest::currentDataTag())
                                                                        .replace(QLatin1Char(' '), QLatin1Char('_'))
                                                                        .replace(QLatin1Char(','), QLatin1Char('_'))));
        QVERIFY(writeExrWithOiio(file, names, types, compression, tile, origin + (origin ? 1 : 0), origin ? origin - 1 : 0));
        std::string error;
        const ImageCodec* module = imageCodec(&error);
        QVERIFY2(module, error.c_str());
        ImageDecoder* theirs = module->open(file.toStdString(), nullptr, 0, &error);
        QVERIFY2(theirs, error.c_str());
        bool handled = true;
        ImageDecoder* ours = openBuiltinExr(file.toStdString(), &handled, &error);
        QCOMPARE(handled, builtin);
        if (!builtin) {
            QVERIFY(!ours);
            QVERIFY2(error.empty(), error.c_str());
            // ImageReader then opens it through the module.
            std::optional<ImageReader> reader = ImageReader::open(file.toStdString(), "test", &error);
            QVERIFY2(reader, error.c_str());
            QCOMPARE(reader->header().channelNames, module->header(theirs).channelNames);
            module->close(theirs);
            return;
        }
        QVERIFY2(ours, error.c_str());
        const ImageCodec& codec = builtinExrCodec();
        const CodecHeader& a = codec.header(ours);
        const CodecHeader& b = module->header(theirs);
        QCOMPARE(a.width, b.width);
        QCOMPARE(a.height, b.height);
        QCOMPARE(a.depth, b.depth);
        QCOMPARE(a.channels, b.channels);
        QCOMPARE(a.sample, b.sample);
        QCOMPARE(a.colorSpaceName, b.colorSpaceName);
        QCOMPARE(a.channelNames, b.channelNames);
        const std::size_t channels = std::size_t(a.channels);
        const std::size_t count = std::size_t(a.width) * std::size_t(a.height) * channels;
        // Every channel as float; the same as half; then rows 2 to 6 of the first channels into
        // RGBA pixels (the strides Image::load reads with).
        std::vector<float> mine(count, -7.0f);
        std::vector<float> module_(count, -7.0f);
        QVERIFY2(codec.read(ours, 0, a.height, a.channels, CodecSample::Float, mine.data(), 0, 0),
            codec.lastError(ours).c_str());
        QVERIFY2(module->read(theirs, 0, b.height, b.channels, CodecSample::Float, module_.data(), 0, 0),
            module->lastError(theirs).c_str());
        QVERIFY(std::memcmp(mine.data(), module_.data(), count * sizeof(float)) == 0);
        QVERIFY(std::any_of(mine.begin(), mine.end(), [](float v) { return v > 1.0f; }));
        std::vector<std::uint16_t> mineHalf(count, 1);
        std::vector<std::uint16_t> moduleHalf(count, 2);
        QVERIFY(codec.read(ours, 0, a.height, a.channels, CodecSample::Half, mineHalf.data(), 0, 0));
        QVERIFY(module->read(theirs, 0, b.height, b.channels, CodecSample::Half, moduleHalf.data(), 0, 0));
        QVERIFY(mineHalf == moduleHalf);
        const int band = std::min(a.channels, 4);
        std::vector<float> mineBand(std::size_t(a.width) * 4 * 4, -7.0f);
        std::vector<float> moduleBand(mineBand.size(), -7.0f);
        const std::ptrdiff_t xstride = 4 * sizeof(float);
        const std::ptrdiff_t ystride = xstride * a.width;
        QVERIFY2(codec.read(ours, 2, 6, band, CodecSample::Float, mineBand.data(), xstride, ystride),
            codec.lastError(ours).c_str());
        QVERIFY2(module->read(theirs, 2, 6, band, CodecSample::Float, moduleBand.data(), xstride, ystride),
            module->lastError(theirs).c_str());
        QVERIFY(std::memcmp(mineBand.data(), moduleBand.data(), mineBand.size() * sizeof(float)) == 0);
        QCOMPARE(mineBand[4 * std::size_t(a.width) + 4], mine[std::size_t(3 * a.width + 1) * channels]);
        // What the decoder refuses to do, it says.
        QVERIFY(!codec.read(ours, 0, a.height, a.channels, CodecSample::UInt8, mineHalf.data(), 0, 0));
        QVERIFY(!codec.lastError(ours).empty());
        QVERIFY(!codec.read(ours, 0, a.height + 1, a.channels, CodecSample::Float, mine.data(), 0, 0));
        codec.close(ours);
        module->close(theirs);
    }

    // An EXR header's channel list, data window and fixed-size attributes are checked before
    // OpenEXR reads them (OpenEXR reads names past a list's size, sizes its buffers from the data
    // window and reads a fixed-size type whatever size is declared; FuzzTest's mutants took
    // seconds of allocating to fail): each row breaks one thing in a sound file and the load
    // names it at once.
    void exrHeadersAreChecked_data()
    {
        QTest::addColumn<QString>("change");
        QTest::addColumn<QString>("message"); // "" loads
        QTest::newRow("sound") << "" << "";
        QTest::newRow("pixel type 7") << "type" << "broken EXR header: attribute \"channels\": channel \"B\" has pixel type 7";
        QTest::newRow("sampling 0") << "sampling" << "channel \"B\" has sampling 0x1";
        QTest::newRow("list runs past its size") << "shorter" << "a channel list entry runs past the list's";
        QTest::newRow("list ends before its size") << "early" << "the channel list does not end at its";
        QTest::newRow("data window too wide") << "wide"
                                              << "image too large: 40000x21 exceeds the limit of 32768 pixels per side";
        QTest::newRow("data window beyond the file")
            << "large" << "its header claims 16384x16384 pixels, too large for a file of";
        QTest::newRow("fixed-size attribute of another size")
            << "compression" << "broken EXR header: attribute \"compression\" (compression) is 2 bytes, not 1";
    }
    void exrHeadersAreChecked()
    {
        QFETCH(QString, change);
        QFETCH(QString, message);
        const QString file = path(QStringLiteral("chlist-%1.exr").arg(change));
        QVERIFY(writeExrWithOiio(file, facet::test::strings({"R", "G", "B"}), {OIIO::TypeDesc::HALF}, QStringLiteral("zip"), 0, 0, 0));
        QFile io(file);
        QVERIFY(io.open(QIODevice::ReadWrite));
        QByteArray bytes = io.readAll();
        const qsizetype attribute = bytes.indexOf(QByteArray("channels\0chlist\0", 16));
        QVERIFY(attribute > 0);
        const qsizetype sizeAt = attribute + 16;
        const qsizetype list = sizeAt + 4;
        QCOMPARE(bytes.mid(list, 2), QByteArray("B\0", 2)); // channels are stored by name: B, G, R
        const auto setInt32 = [&](qsizetype at, std::int32_t value) {
            for (int i = 0; i < 4; ++i)
                bytes[at + i] = char((std::uint32_t(value) >> (8 * i)) & 0xff);
        };
        if (change == QLatin1String("type"))
            setInt32(list + 2, 7);
        else if (change == QLatin1String("sampling"))
            setInt32(list + 2 + 8, 0);
        else if (change == QLatin1String("shorter"))
            setInt32(sizeAt, 40); // mid-way through the third entry
        else if (change == QLatin1String("early"))
            bytes[list] = 0; // an empty name: the list's end, 54 bytes before its size says
        const qsizetype window = bytes.indexOf(QByteArray("dataWindow\0box2i\0", 17)) + 17 + 4;
        QVERIFY(window > 21);
        if (change == QLatin1String("wide"))
            setInt32(window + 8, 39999);
        else if (change == QLatin1String("large")) {
            setInt32(window + 8, 16383);
            setInt32(window + 12, 16383);
        } else if (change == QLatin1String("compression")) {
            const qsizetype compression = bytes.indexOf(QByteArray("compression\0compression\0", 24));
            QVERIFY(compression > 0);
            setInt32(compression + 24, 2);
        }
        QVERIFY(io.seek(0));
        QCOMPARE(io.write(bytes), bytes.size());
        io.close();
        // Refused as the file opens, before a decoder reads the header (a size checked only after
        // opening would open here and be refused later by Image::load, with OpenEXR's buffers
        // already allocated).
        std::string error;
        const std::optional<ImageReader> reader = ImageReader::open(file.toStdString(), "test", &error);
        if (message.isEmpty()) {
            QVERIFY2(reader, error.c_str());
            QVERIFY2(Image::load(file.toStdString(), &error), error.c_str());
            return;
        }
        QVERIFY(!reader);
        QVERIFY2(QString::fromStdString(error).contains(message), error.c_str());
        QVERIFY2(QString::fromStdString(error).contains(file), error.c_str());
    }

    // A band of rows (what Image::loadBoxFiltered reads: thumbnails, large environments) is those
    // rows of the whole image, tiled files too (OpenImageIO 2.4's read_scanlines died of SIGFPE on
    // a tiled file: the module reads the band's rows of tiles instead).
    void bandsOfRowsAreTheImagesRows_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("tile");
        QTest::newRow("tif, tiles of 16") << "band-tiled.tif" << 16;
        QTest::newRow("tif, scanlines") << "band-lines.tif" << 0;
        QTest::newRow("exr, tiles of 16") << "band-tiled.exr" << 16;
        QTest::newRow("exr, scanlines") << "band-lines.exr" << 0;
    }
    void bandsOfRowsAreTheImagesRows()
    {
        QFETCH(QString, file);
        QFETCH(int, tile);
        constexpr int kWidth = 37;
        constexpr int kHeight = 40;
        {
            std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path(file).toStdString());
            OIIO::ImageSpec spec(kWidth, kHeight, 3, OIIO::TypeDesc::FLOAT);
            spec.tile_width = tile;
            spec.tile_height = tile;
            const std::vector<float> values = facet::test::ramp(kWidth, kHeight, 3);
            QVERIFY(output && output->open(path(file).toStdString(), spec)
                && output->write_image(OIIO::TypeDesc::FLOAT, values.data()) && output->close());
        }
        std::string error;
        std::optional<ImageReader> reader = ImageReader::open(path(file).toStdString(), "test", &error);
        QVERIFY2(reader, error.c_str());
        std::vector<float> whole(std::size_t(kWidth) * kHeight * 3);
        QVERIFY2(reader->readAll(3, CodecSample::Float, whole.data(), 0, 0, "test", &error), error.c_str());
        for (const auto& [begin, end] : {std::pair {0, 5}, std::pair {7, 23}, std::pair {16, 32}, std::pair {33, 40}}) {
            std::vector<float> band(std::size_t(kWidth) * std::size_t(end - begin) * 4, -1.0f);
            QVERIFY2(reader->read(begin, end, 3, CodecSample::Float, band.data(), 4 * sizeof(float),
                         std::ptrdiff_t(4 * sizeof(float)) * kWidth, "test", &error),
                error.c_str());
            for (int y = begin; y < end; ++y)
                for (int x = 0; x < kWidth; ++x)
                    for (int c = 0; c < 3; ++c)
                        QCOMPARE(band[(std::size_t(y - begin) * kWidth + std::size_t(x)) * 4 + std::size_t(c)],
                            whole[(std::size_t(y) * kWidth + std::size_t(x)) * 3 + std::size_t(c)]);
        }
    }
};

QTEST_GUILESS_MAIN(ExrReadingTest)
#include "ExrReadingTest.moc"
