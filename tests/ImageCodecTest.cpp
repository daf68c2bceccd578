// The image codec module (core/image/ImageCodec.h): OpenImageIO loaded only by processes that read or
// write an image, what its header and reads give for each format and sample type, what a missing
// or foreign module tells the user. Files are written with OpenImageIO directly, so that a
// mistake in the module's encoder cannot hide one in its decoder.

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcessEnvironment>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

#include "TestSupport.h"
#include "core/image/BuiltinImageEncoders.h"
#include "core/image/Image.h"
#include "core/image/ImageCodec.h"
#include "core/image/ImageReader.h"
#include "core/image/ImageWriter.h"
#include "core/image/MapImage.h"

using namespace facet;

Q_DECLARE_METATYPE(facet::CodecSample)
Q_DECLARE_METATYPE(facet::ColorEncoding)

namespace {

bool writeWithOiio(const QString& path, int width, int height, int channels, OIIO::TypeDesc type,
    const std::vector<std::string>& names = {})
{
    std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path.toStdString());
    OIIO::ImageSpec spec(width, height, channels, type);
    spec.attribute("oiio:UnassociatedAlpha", 1); // the ramp's alpha is not premultiplied into it
    if (!names.empty())
        spec.channelnames = names;
    const std::vector<float> values = facet::test::ramp(width, height, channels);
    return output && output->open(path.toStdString(), spec)
        && output->write_image(OIIO::TypeDesc::FLOAT, values.data()) && output->close();
}

// A PNG's gAMA, sRGB, cHRM and tEXt chunks, each as "type:hex of its data", sorted (writers order
// texts as they like).
QStringList pngColourChunks(const std::vector<unsigned char>& png)
{
    QStringList chunks;
    for (std::size_t at = 8; at + 12 <= png.size();) {
        const std::size_t length = (std::size_t(png[at]) << 24) | (std::size_t(png[at + 1]) << 16)
            | (std::size_t(png[at + 2]) << 8) | std::size_t(png[at + 3]);
        const QByteArray type(reinterpret_cast<const char*>(&png[at + 4]), 4);
        if (at + 12 + length > png.size())
            break;
        if (type == "gAMA" || type == "sRGB" || type == "cHRM" || type == "tEXt")
            chunks.append(QString::fromLatin1(type) + QLatin1Char(':')
                + QString::fromLatin1(
                    QByteArray(reinterpret_cast<const char*>(&png[at + 8]), qsizetype(length)).toHex()));
        at += 12 + length;
    }
    chunks.sort();
    return chunks;
}

facet::test::ProcessResult runFacet(const QStringList& arguments, const QProcessEnvironment& extra)
{
    return facet::test::runWithoutDisplay(QStringLiteral(FACET_EXECUTABLE), arguments, extra);
}

} // namespace

class ImageCodecTest : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    QString path(const QString& name) const { return m_dir.filePath(name); }

private Q_SLOTS:
    // First, before anything of this process reads an image.
    void loadedByTheFirstImageOnly()
    {
        QVERIFY(!imageCodecLoaded());
        Image probe(4, 2, glm::vec4(0.5f));
        QVERIFY(!imageCodecLoaded()); // making an image in memory needs no codec
        std::string error;
        // EXR and PNG are encoded by core (core/image/BuiltinImageEncoders.h): still no module.
        QVERIFY2(probe.save(path(QStringLiteral("probe.exr")).toStdString(), &error), error.c_str());
        QVERIFY2(probe.save(path(QStringLiteral("probe.png")).toStdString(), &error), error.c_str());
        QVERIFY(!imageCodecLoaded());
        // EXR is decoded by core too (core/image/BuiltinExrDecoder.h).
        const std::optional<Image> read = Image::load(path(QStringLiteral("probe.exr")).toStdString(), &error);
        QVERIFY2(read, error.c_str());
        QCOMPARE(read->at(3, 1), glm::vec4(0.5f));
        QVERIFY(!imageCodecLoaded());
        QVERIFY2(probe.save(path(QStringLiteral("probe.tif")).toStdString(), &error), error.c_str());
        QVERIFY(imageCodecLoaded());
        QVERIFY(imageCodec(nullptr) != nullptr);
        QCOMPARE(imageCodec(nullptr)->interfaceVersion, kImageCodecInterfaceVersion);
    }

    // The build tree has an installation's layout: <bin|tests|bench>/../lib/facet/.
    void moduleLiesBesideTheExecutables()
    {
        const QString module = QString::fromStdString(imageCodecModulePath());
        QCOMPARE(QFileInfo(module).canonicalFilePath(),
            QFileInfo(
                QCoreApplication::applicationDirPath() + QStringLiteral("/../lib/facet/libfacet_imageio.so"))
                .canonicalFilePath());
        QVERIFY2(QFileInfo::exists(module), qPrintable(module));
    }

    // What the header says and what the reads give, per format and sample type.
    void headerAndPixels_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("channels");
        QTest::addColumn<int>("oiioType"); // OIIO::TypeDesc::BASETYPE
        QTest::addColumn<CodecSample>("sample");
        QTest::addColumn<bool>("twoColour");
        QTest::addColumn<ColorEncoding>("encoding");
        QTest::addColumn<double>("tolerance"); // of a read as float against the ramp
        QTest::newRow("png 8-bit RGBA") << "a.png" << 4 << int(OIIO::TypeDesc::UINT8) << CodecSample::UInt8
                                        << false << ColorEncoding::SRGB << 0.5 / 255.0;
        QTest::newRow("png 16-bit grey") << "b.png" << 1 << int(OIIO::TypeDesc::UINT16) << CodecSample::UInt16
                                         << false << ColorEncoding::SRGB << 0.5 / 65535.0;
        QTest::newRow("png 8-bit grey+alpha")
            << "c.png" << 2 << int(OIIO::TypeDesc::UINT8) << CodecSample::UInt8 << false
            << ColorEncoding::SRGB << 0.5 / 255.0;
        QTest::newRow("exr half RGB") << "d.exr" << 3 << int(OIIO::TypeDesc::HALF) << CodecSample::Half
                                      << false << ColorEncoding::Linear << 1e-3;
        QTest::newRow("exr float R,G") << "e.exr" << 2 << int(OIIO::TypeDesc::FLOAT) << CodecSample::Float
                                       << true << ColorEncoding::Linear << 0.0;
        QTest::newRow("tif 16-bit RGB") << "f.tif" << 3 << int(OIIO::TypeDesc::UINT16) << CodecSample::UInt16
                                        << false << ColorEncoding::SRGB << 0.5 / 65535.0;
        QTest::newRow("hdr float RGB") << "g.hdr" << 3 << int(OIIO::TypeDesc::FLOAT) << CodecSample::Float
                                       << false << ColorEncoding::Linear << 0.01;
    }
    void headerAndPixels()
    {
        QFETCH(QString, file);
        QFETCH(int, channels);
        QFETCH(int, oiioType);
        QFETCH(CodecSample, sample);
        QFETCH(bool, twoColour);
        QFETCH(ColorEncoding, encoding);
        QFETCH(double, tolerance);
        constexpr int kWidth = 9;
        constexpr int kHeight = 5;
        const std::vector<std::string> names
            = twoColour ? std::vector<std::string> {"R", "G"} : std::vector<std::string> {};
        QVERIFY(writeWithOiio(path(file), kWidth, kHeight, channels,
            OIIO::TypeDesc(OIIO::TypeDesc::BASETYPE(oiioType)), names));

        std::string error;
        std::optional<ImageReader> reader = ImageReader::open(path(file).toStdString(), "test", &error);
        QVERIFY2(reader, error.c_str());
        const CodecHeader& header = reader->header();
        QCOMPARE(header.width, kWidth);
        QCOMPARE(header.height, kHeight);
        QCOMPARE(header.depth, 1);
        QCOMPARE(header.channels, channels);
        QCOMPARE(header.sample, sample);
        QCOMPARE(reader->twoColourChannels(), twoColour);
        QCOMPARE(reader->encoding(), encoding);

        // The whole image, then rows 1-3 alone into a strided buffer: the same values.
        const std::vector<float> expected = facet::test::ramp(kWidth, kHeight, channels);
        std::vector<float> whole(expected.size(), -1.0f);
        QVERIFY2(
            reader->readAll(channels, CodecSample::Float, whole.data(), 0, 0, "test", &error), error.c_str());
        for (std::size_t i = 0; i < whole.size(); ++i)
            QVERIFY2(std::abs(whole[i] - expected[i]) <= tolerance + 1e-6 * expected[i],
                qPrintable(
                    QStringLiteral("sample %1: %2, expected %3").arg(i).arg(whole[i]).arg(expected[i])));
        const std::ptrdiff_t xstride = std::ptrdiff_t(sizeof(float)) * 4; // RGBA slots, `channels` used
        std::vector<float> rows(std::size_t(kWidth) * 3 * 4, -1.0f);
        QVERIFY2(reader->read(1, 4, channels, CodecSample::Float, rows.data(), xstride, xstride * kWidth,
                     "test", &error),
            error.c_str());
        for (int y = 1; y < 4; ++y)
            for (int x = 0; x < kWidth; ++x)
                for (int c = 0; c < 4; ++c) {
                    const float got
                        = rows[(std::size_t(y - 1) * kWidth + std::size_t(x)) * 4 + std::size_t(c)];
                    if (c >= channels) {
                        QCOMPARE(got, -1.0f); // the stride's unused slots untouched
                        continue;
                    }
                    const float want
                        = expected[(std::size_t(y) * kWidth + std::size_t(x)) * std::size_t(channels)
                            + std::size_t(c)];
                    QVERIFY(std::abs(got - want) <= tolerance + 1e-6 * want);
                }

        // Integer files as their own samples (MapImage's path): exact steps.
        if (sample == CodecSample::UInt8 || sample == CodecSample::UInt16) {
            std::optional<ImageReader> again = ImageReader::open(path(file).toStdString(), "test", &error);
            QVERIFY(again);
            const double scale = sample == CodecSample::UInt8 ? 255.0 : 65535.0;
            if (sample == CodecSample::UInt8) {
                std::vector<std::uint8_t> bytes(expected.size());
                QVERIFY(again->readAll(channels, sample, bytes.data(), 0, 0, "test", &error));
                for (std::size_t i = 0; i < bytes.size(); ++i)
                    QCOMPARE(int(bytes[i]), int(std::lround(std::min(expected[i], 1.0f) * scale)));
            } else {
                std::vector<std::uint16_t> words(expected.size());
                QVERIFY(again->readAll(channels, sample, words.data(), 0, 0, "test", &error));
                for (std::size_t i = 0; i < words.size(); ++i)
                    QCOMPARE(int(words[i]), int(std::lround(std::min(expected[i], 1.0f) * scale)));
            }
        }
    }

    // writeImageFile through the module, read back with OpenImageIO directly.
    void encodedFilesHoldWhatWasAsked_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("channels");
        QTest::addColumn<int>("format"); // FileSampleFormat
        QTest::addColumn<int>("oiioType");
        QTest::addColumn<QString>("colorSpace");
        QTest::addColumn<double>("tolerance");
        QTest::newRow("png 8-bit RGB sRGB") << "w1.png" << 3 << int(FileSampleFormat::UInt8)
                                            << int(OIIO::TypeDesc::UINT8) << "sRGB" << 0.5 / 255.0;
        QTest::newRow("png 16-bit RGBA") << "w2.png" << 4 << int(FileSampleFormat::UInt16)
                                         << int(OIIO::TypeDesc::UINT16) << "sRGB" << 0.5 / 65535.0;
        QTest::newRow("exr half grey")
            << "w3.exr" << 1 << int(FileSampleFormat::Half) << int(OIIO::TypeDesc::HALF) << "Linear" << 1e-3;
        QTest::newRow("exr float RGBA")
            << "w4.exr" << 4 << int(FileSampleFormat::Float) << int(OIIO::TypeDesc::FLOAT) << "Linear" << 0.0;
        // (TGA holds no colour-space tag.)
        QTest::newRow("tga 8-bit RGBA") << "w5.tga" << 4 << int(FileSampleFormat::UInt8)
                                        << int(OIIO::TypeDesc::UINT8) << "" << 0.5 / 255.0;
    }
    void encodedFilesHoldWhatWasAsked()
    {
        QFETCH(QString, file);
        QFETCH(int, channels);
        QFETCH(int, format);
        QFETCH(int, oiioType);
        QFETCH(QString, colorSpace);
        QFETCH(double, tolerance);
        constexpr int kWidth = 7;
        constexpr int kHeight = 6;
        ImageFileSpec spec;
        spec.width = kWidth;
        spec.height = kHeight;
        spec.channels = channels;
        spec.sampleFormat = FileSampleFormat(format);
        spec.encoding = colorSpace == QLatin1String("sRGB") ? ColorEncoding::SRGB : ColorEncoding::Linear;
        const std::vector<float> values = facet::test::ramp(kWidth, kHeight, channels);
        std::string error;
        QVERIFY2(
            writeImageFile(path(file).toStdString(), spec, values.data(), "test", &error), error.c_str());

        OIIO::ImageSpec config;
        config.attribute("oiio:UnassociatedAlpha", 1);
        std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::open(path(file).toStdString(), &config);
        QVERIFY(input);
        const OIIO::ImageSpec& read = input->spec();
        QCOMPARE(read.width, kWidth);
        QCOMPARE(read.height, kHeight);
        QCOMPARE(read.nchannels, channels);
        QCOMPARE(int(read.format.basetype), oiioType);
        QCOMPARE(QString::fromStdString(read.get_string_attribute("oiio:ColorSpace")), colorSpace);
        std::vector<float> back(values.size());
        QVERIFY(input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, back.data()));
        for (std::size_t i = 0; i < back.size(); ++i)
            QVERIFY2(std::abs(back[i] - std::min(values[i], 1.0f)) <= tolerance + 1e-6,
                qPrintable(QStringLiteral("sample %1: %2, wrote %3").arg(i).arg(back[i]).arg(values[i])));
    }

    // EXR and PNG are encoded by core itself (core/image/BuiltinImageEncoders.h), without the module:
    // read back with OpenImageIO directly, each file holds what the module's encoder wrote for the
    // same samples: size, channel names, sample type, colour-space tag, text attributes, and every
    // sample bit for bit (the 8- and 16-bit rows include the values halfway between two steps).
    void builtinEncodersMatchTheModule_data()
    {
        QTest::addColumn<QString>("extension");
        QTest::addColumn<int>("channels");
        QTest::addColumn<int>("sample"); // CodecSample
        QTest::addColumn<QString>("colorSpace");
        QTest::addColumn<bool>("attributes");
        for (int channels = 1; channels <= 4; ++channels) {
            for (const char* tag : {"sRGB", "Linear", ""}) {
                QTest::addRow("png 8-bit, %d channels, tag '%s'", channels, tag)
                    << "png" << channels << int(CodecSample::UInt8) << tag << false;
                QTest::addRow("png 16-bit, %d channels, tag '%s'", channels, tag)
                    << "png" << channels << int(CodecSample::UInt16) << tag << false;
            }
            QTest::addRow("exr half, %d channels", channels)
                << "exr" << channels << int(CodecSample::Half) << "Linear" << false;
            QTest::addRow("exr float, %d channels", channels)
                << "exr" << channels << int(CodecSample::Float) << "Linear" << false;
        }
        QTest::newRow("png with text attributes") << "png" << 3 << int(CodecSample::UInt8) << "sRGB" << true;
        QTest::newRow("exr with string attributes")
            << "exr" << 4 << int(CodecSample::Half) << "Linear" << true;
    }
    void builtinEncodersMatchTheModule()
    {
        QFETCH(QString, extension);
        QFETCH(int, channels);
        QFETCH(int, sample);
        QFETCH(QString, colorSpace);
        QFETCH(bool, attributes);
        constexpr int kWidth = 37;
        constexpr int kHeight = 9;
        CodecEncodeSpec spec;
        spec.width = kWidth;
        spec.height = kHeight;
        spec.channels = channels;
        spec.sample = CodecSample(sample);
        spec.alphaChannel = channels == 2 || channels == 4 ? channels - 1 : -1;
        spec.colorSpaceName = colorSpace.toStdString();
        if (attributes)
            spec.attributes = {{"facet:rows", "3"}, {"facet:rowLabels", "gold|silver|copper"}};
        const bool integer = spec.sample == CodecSample::UInt8 || spec.sample == CodecSample::UInt16;
        const float steps = spec.sample == CodecSample::UInt16 ? 65535.0f : 255.0f;
        std::vector<float> values(std::size_t(kWidth * kHeight * channels));
        for (std::size_t i = 0; i < values.size(); ++i) {
            if (integer) // every step, and halfway between neighbours
                values[i] = std::min(1.0f, float(i % 512) * 0.5f / steps + (i % 7 == 0 ? 0.5f : 0.0f));
            else // half's range and its negatives, as core clamps them
                values[i] = float((int(i) % 91) - 45) * (i % 5 == 0 ? 1456.0f : 0.0371f);
        }
        const std::string name = "match." + extension.toStdString();
        std::vector<unsigned char> builtin;
        std::vector<unsigned char> module;
        bool refused = false;
        std::string error;
        const std::optional<CodecWriterInfo> writer = builtinImageWriterFor(name);
        QVERIFY(writer && writer->builtin);
        QVERIFY2(encodeBuiltinImage(*writer, spec, values.data(), &builtin, &refused, &error), error.c_str());
        const ImageCodec* codec = imageCodec(&error);
        QVERIFY2(codec, error.c_str());
        QVERIFY2(codec->encode(name, spec, values.data(), &module, &refused, &error), error.c_str());

        struct Read {
            OIIO::ImageSpec spec;
            std::vector<float> pixels;
        };
        const auto read
            = [&](const std::vector<unsigned char>& bytes, const QString& file) -> std::optional<Read> {
            QFile out(path(file));
            if (!out.open(QIODevice::WriteOnly)
                || out.write(reinterpret_cast<const char*>(bytes.data()), qint64(bytes.size()))
                    != qint64(bytes.size()))
                return std::nullopt;
            out.close();
            OIIO::ImageSpec config;
            config.attribute("oiio:UnassociatedAlpha", 1);
            std::unique_ptr<OIIO::ImageInput> input
                = OIIO::ImageInput::open(path(file).toStdString(), &config);
            if (!input)
                return std::nullopt;
            Read result {input->spec(), std::vector<float>(values.size())};
            if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, result.pixels.data()))
                return std::nullopt;
            return result;
        };
        const std::optional<Read> ours = read(builtin, QStringLiteral("builtin.") + extension);
        const std::optional<Read> theirs = read(module, QStringLiteral("module.") + extension);
        QVERIFY(ours && theirs);
        QCOMPARE(ours->spec.width, theirs->spec.width);
        QCOMPARE(ours->spec.height, theirs->spec.height);
        QCOMPARE(ours->spec.nchannels, theirs->spec.nchannels);
        QCOMPARE(int(ours->spec.format.basetype), int(theirs->spec.format.basetype));
        QCOMPARE(ours->spec.channelnames, theirs->spec.channelnames);
        QCOMPARE(ours->spec.alpha_channel, theirs->spec.alpha_channel);
        QCOMPARE(ours->spec.get_string_attribute("oiio:ColorSpace"),
            theirs->spec.get_string_attribute("oiio:ColorSpace"));
        for (const auto& [key, value] : spec.attributes) {
            QCOMPARE(ours->spec.get_string_attribute(key), value);
            QCOMPARE(theirs->spec.get_string_attribute(key), value);
        }
        if (extension == QLatin1String("png")) // what other readers go by: the colour chunks and texts
            QCOMPARE(pngColourChunks(builtin), pngColourChunks(module));
        for (std::size_t i = 0; i < values.size(); ++i)
            QVERIFY2(std::memcmp(&ours->pixels[i], &theirs->pixels[i], sizeof(float)) == 0,
                qPrintable(QStringLiteral("sample %1 (wrote %2): ours %3, the module's %4")
                               .arg(i)
                               .arg(double(values[i]), 0, 'g', 9)
                               .arg(double(ours->pixels[i]), 0, 'g', 9)
                               .arg(double(theirs->pixels[i]), 0, 'g', 9)));
    }

    // What the writers refuse, named.
    void refusedWritesAreNamed_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("format");
        QTest::addColumn<QString>("message");
        QTest::newRow("tga cannot hold 16 bits")
            << "r1.tga" << int(FileSampleFormat::UInt16) << "r1.tga: targa files cannot hold 16-bit samples";
        QTest::newRow("no writer for the extension")
            << "r2.nosuchformat" << int(FileSampleFormat::UInt8) << "r2.nosuchformat: ";
        QTest::newRow("sgi is not encoded in memory")
            << "r3.sgi" << int(FileSampleFormat::UInt8) << "cannot write sgi files safely";
        QTest::newRow("png cannot hold half floats (core's encoder)")
            << "r4.png" << int(FileSampleFormat::Half) << "r4.png: png files cannot hold half float samples";
        QTest::newRow("exr cannot hold 8 bits (core's encoder)")
            << "r5.exr" << int(FileSampleFormat::UInt8) << "r5.exr: openexr files cannot hold 8-bit samples";
    }
    void refusedWritesAreNamed()
    {
        QFETCH(QString, file);
        QFETCH(int, format);
        QFETCH(QString, message);
        ImageFileSpec spec;
        spec.width = 2;
        spec.height = 2;
        spec.channels = 3;
        spec.sampleFormat = FileSampleFormat(format);
        const std::vector<float> values = facet::test::ramp(2, 2, 3);
        std::string error;
        QVERIFY(!writeImageFile(path(file).toStdString(), spec, values.data(), "test", &error));
        QVERIFY2(QString::fromStdString(error).contains(message), error.c_str());
        QVERIFY(QString::fromStdString(error).startsWith(QStringLiteral("test: ")));
        QVERIFY(!QFileInfo::exists(path(file)));
    }

    // Which commands load OpenImageIO: those that read or write an image, and no other
    // (LD_DEBUG=libs lists every library the dynamic loader opens).
    void commandsLoadItOnlyForImages_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<bool>("loads");
        QTest::newRow("--version") << facet::test::strings({"--version"}) << 0 << false;
        QTest::newRow("--help") << facet::test::strings({"--help"}) << 0 << false;
        QTest::newRow("render --help") << facet::test::strings({"render", "--help"}) << 0 << false;
        QTest::newRow("render, a bad value")
            << facet::test::strings({"render", "--size", "0x0", "-o", "x.png"}) << 2 << false;
        // EXR and PNG are encoded by core: a render that reads no image never loads it.
        QTest::newRow("render to a PNG") << facet::test::strings(
            {"render", "--env", "uniform:1", "--size", "16x16", "-o", "{dir}/out.png"})
                                         << 0 << false;
        QTest::newRow("render to an EXR") << facet::test::strings(
            {"render", "--env", "uniform:1", "--size", "16x16", "-o", "{dir}/out.exr"})
                                          << 0 << false;
        // EXR is decoded by core too (core/image/BuiltinExrDecoder.h); Radiance HDR is the module's.
        QTest::newRow("render lit by an EXR, to a PNG") << facet::test::strings(
            {"render", "--env", "{dir}/lit.exr", "--size", "16x16", "-o", "{dir}/out-lit.png"})
                                                        << 0 << false;
        QTest::newRow("render lit by an HDR, to a PNG") << facet::test::strings(
            {"render", "--env", "{dir}/lit.hdr", "--size", "16x16", "-o", "{dir}/out-lit-hdr.png"})
                                                        << 0 << true;
    }
    void commandsLoadItOnlyForImages()
    {
        QFETCH(QStringList, arguments);
        QFETCH(int, exitCode);
        QFETCH(bool, loads);
        for (QString& argument : arguments)
            argument.replace(QLatin1String("{dir}"), m_dir.path());
        for (const QString& lit : {QStringLiteral("lit.exr"), QStringLiteral("lit.hdr")})
            if (arguments.contains(path(lit)) && !QFileInfo::exists(path(lit)))
                QVERIFY(writeWithOiio(path(lit), 16, 8, 3,
                    lit.endsWith(QLatin1String(".exr")) ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT));
        QProcessEnvironment extra;
        extra.insert(QStringLiteral("LD_DEBUG"), QStringLiteral("libs"));
        extra.insert(QStringLiteral("FACET_CACHE_DIR"), path(QStringLiteral("cache")));
        const facet::test::ProcessResult result = runFacet(arguments, extra);
        QCOMPARE(result.exitCode, exitCode);
        QVERIFY2(result.err.contains(QLatin1String("libQt6Core")), "LD_DEBUG listed no libraries");
        QCOMPARE(result.err.contains(QLatin1String("libOpenImageIO")), loads);
        QCOMPARE(result.err.contains(QLatin1String("libfacet_imageio")), loads);
    }

    // A module that cannot be used: every image read or write says which file and why; nothing
    // crashes.
    void unusableModuleIsNamed_data()
    {
        QTest::addColumn<QString>("module");
        QTest::addColumn<QString>("why");
        QTest::newRow("missing") << "{dir}/nowhere/libfacet_imageio.so"
                                 << "cannot open shared object file: No such file or directory";
        QTest::newRow("not a Facet module") << "{libz}"
                                            << "has no facetImageCodec (not a Facet image module)";
        QTest::newRow("not a library") << "{dir}/text.so"
                                       << "invalid ELF header";
    }
    void unusableModuleIsNamed()
    {
        QFETCH(QString, module);
        QFETCH(QString, why);
        QVERIFY(facet::test::writeText(path(QStringLiteral("text.so")),
            QByteArray("This is a text file named like a shared library, long enough for an ELF header.\n")));
        module.replace(QLatin1String("{dir}"), m_dir.path());
        if (module == QLatin1String("{libz}")) {
            // Any shared library without the entry point: the C library's zlib, which OpenImageIO needs too.
            const QStringList candidates {QStringLiteral("/lib/x86_64-linux-gnu/libz.so.1"),
                QStringLiteral("/usr/lib/x86_64-linux-gnu/libz.so.1"), QStringLiteral("/lib64/libz.so.1")};
            module.clear();
            for (const QString& candidate : candidates)
                if (QFileInfo::exists(candidate))
                    module = candidate;
            if (module.isEmpty())
                QSKIP("no libz.so.1 in the usual places");
        }
        // A Radiance HDR: EXR files do not need the module.
        if (!QFileInfo::exists(path(QStringLiteral("lit.hdr"))))
            QVERIFY(writeWithOiio(path(QStringLiteral("lit.hdr")), 16, 8, 3, OIIO::TypeDesc::FLOAT));
        QProcessEnvironment extra;
        extra.insert(QStringLiteral("FACET_IMAGEIO_MODULE"), module);
        extra.insert(QStringLiteral("FACET_CACHE_DIR"), path(QStringLiteral("cache")));
        const facet::test::ProcessResult result
            = runFacet(QStringList {QStringLiteral("render"), QStringLiteral("--env"),
                           path(QStringLiteral("lit.hdr")), QStringLiteral("--size"), QStringLiteral("16x16"),
                           QStringLiteral("-o"), path(QStringLiteral("out-unusable.png"))},
                extra);
        QCOMPARE(result.exitCode, 1);
        QVERIFY2(
            result.err.contains(QStringLiteral("image input/output module ") + module + QStringLiteral(": ")),
            qPrintable(result.err));
        QVERIFY2(result.err.contains(why), qPrintable(result.err));
        QVERIFY2(result.err.contains(QLatin1String("lit.hdr")), qPrintable(result.err));
        QVERIFY(!QFileInfo::exists(path(QStringLiteral("out-unusable.png"))));
    }
};

QTEST_GUILESS_MAIN(ImageCodecTest)
#include "ImageCodecTest.moc"
