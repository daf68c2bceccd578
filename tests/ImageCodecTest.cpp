// The image codec module (core/ImageCodec.h): OpenImageIO loaded only by processes that read or
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

#include <cstdint>
#include <vector>

#include "TestSupport.h"
#include "core/Image.h"
#include "core/ImageCodec.h"
#include "core/ImageReader.h"
#include "core/ImageWriter.h"
#include "core/MapImage.h"

using namespace facet;

Q_DECLARE_METATYPE(facet::CodecSample)
Q_DECLARE_METATYPE(facet::ColorEncoding)

namespace {

// A width x height image of `channels` channels whose sample (x, y, c) is (x + 3y + 7c) / 64.
std::vector<float> ramp(int width, int height, int channels)
{
    std::vector<float> values(std::size_t(width) * std::size_t(height) * std::size_t(channels));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < channels; ++c)
                values[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(channels)
                    + std::size_t(c)]
                    = float(x + 3 * y + 7 * c) / 64.0f;
    return values;
}

bool writeWithOiio(const QString& path, int width, int height, int channels, OIIO::TypeDesc type,
    const std::vector<std::string>& names = {})
{
    std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path.toStdString());
    OIIO::ImageSpec spec(width, height, channels, type);
    spec.attribute("oiio:UnassociatedAlpha", 1); // the ramp's alpha is not premultiplied into it
    if (!names.empty())
        spec.channelnames = names;
    const std::vector<float> values = ramp(width, height, channels);
    return output && output->open(path.toStdString(), spec)
        && output->write_image(OIIO::TypeDesc::FLOAT, values.data()) && output->close();
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
        QVERIFY2(probe.save(path(QStringLiteral("probe.exr")).toStdString(), &error), error.c_str());
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
        const std::vector<float> expected = ramp(kWidth, kHeight, channels);
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
        const std::vector<float> values = ramp(kWidth, kHeight, channels);
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
        const std::vector<float> values = ramp(2, 2, 3);
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
        QTest::newRow("render to a PNG") << facet::test::strings(
            {"render", "--env", "uniform:1", "--size", "16x16", "-o", "{dir}/out.png"})
                                         << 0 << true;
    }
    void commandsLoadItOnlyForImages()
    {
        QFETCH(QStringList, arguments);
        QFETCH(int, exitCode);
        QFETCH(bool, loads);
        for (QString& argument : arguments)
            argument.replace(QLatin1String("{dir}"), m_dir.path());
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
        QProcessEnvironment extra;
        extra.insert(QStringLiteral("FACET_IMAGEIO_MODULE"), module);
        extra.insert(QStringLiteral("FACET_CACHE_DIR"), path(QStringLiteral("cache")));
        const facet::test::ProcessResult result
            = runFacet(facet::test::strings(
                           {"render", "--env", "uniform:1", "--size", "16x16", "-o", "out-unusable.png"}),
                extra);
        QCOMPARE(result.exitCode, 1);
        QVERIFY2(
            result.err.contains(QStringLiteral("image input/output module ") + module + QStringLiteral(": ")),
            qPrintable(result.err));
        QVERIFY2(result.err.contains(why), qPrintable(result.err));
        QVERIFY2(result.err.contains(QLatin1String("out-unusable.png")), qPrintable(result.err));
    }
};

QTEST_GUILESS_MAIN(ImageCodecTest)
#include "ImageCodecTest.moc"
