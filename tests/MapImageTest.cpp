// core/image/MapImage and core/image/MapImageCache: material maps read in the file's own bit depth and
// channels (a row per file kind: 8-bit grey, grey + alpha, RGB, RGBA, 16-bit, half and float EXR,
// two named channels, float TIFF), rows stored bottom to top, float samples sanitised; the size
// budget refused from the header before decoding (a crafted 16384² PNG of 57 bytes), configurable
// by environment; each file decoded once however many ask, at once or one after another, and again
// when it changes on disk. Fixtures are written with OpenImageIO directly.

#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <thread>
#include <vector>

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <OpenImageIO/imageio.h>

#include "TestSupport.h"
#include "core/image/MapImage.h"
#include "core/image/MapImageCache.h"
#include "core/image/MapStatistics.h"

using namespace facet;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// Writes `values` (interleaved, top row first as files store them) exactly as a `fileType` file;
// `names` renames the channels (EXR).
bool writeFixture(const QString& path, int width, int height, int channels, OIIO::TypeDesc fileType,
    const std::vector<float>& values, const std::vector<std::string>& names = {})
{
    std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path.toStdString());
    if (!output)
        return false;
    OIIO::ImageSpec spec(width, height, channels, fileType);
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (!names.empty())
        spec.channelnames = names;
    if (path.endsWith(QLatin1String(".tif")))
        spec.attribute("compression", "none");
    return output->open(path.toStdString(), spec) && output->write_image(OIIO::TypeDesc::FLOAT, values.data())
        && output->close();
}

// Distinct values per texel and channel, in [0, 1] (and beyond for float files: `scale`).
std::vector<float> pattern(int width, int height, int channels, float scale, int levels)
{
    std::vector<float> values(std::size_t(width * height * channels));
    for (std::size_t i = 0; i < values.size(); ++i)
        values[i] = scale * float((i * 37 + 11) % std::size_t(levels)) / float(levels - 1);
    return values;
}

struct FileRow {
    const char* name;
    const char* extension;
    int channels;
    OIIO::TypeDesc fileType;
    std::vector<std::string> channelNames;
    MapSampleType type;
    MapLayout layout;
    ColorEncoding encoding;
    float scale;    // values written in [0, scale]
    int levels;     // distinct values the file can hold exactly (255, 65535) or that we write
    double epsilon; // how exactly a sample reads back
};

} // namespace

class MapImageTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    // Inspect Map's numbers (core/image/MapStatistics.h): per stored channel the histogram, the range
    // and the mean of the values as stored, for each layout and sample type.
    void statisticsOfEachChannel_data()
    {
        QTest::addColumn<int>("layout");
        QTest::addColumn<int>("type");
        QTest::newRow("RGB, 8-bit") << int(MapLayout::Rgb) << int(MapSampleType::UInt8);
        QTest::newRow("grey, 16-bit") << int(MapLayout::Grey) << int(MapSampleType::UInt16);
        QTest::newRow("RGBA, half: values above 1 in the last bin")
            << int(MapLayout::Rgba) << int(MapSampleType::Half);
        QTest::newRow("red + green, 8-bit") << int(MapLayout::RedGreen) << int(MapSampleType::UInt8);
    }
    void statisticsOfEachChannel()
    {
        QFETCH(int, layout);
        QFETCH(int, type);
        // 16 x 4 texels: channel c of column x holds x / 16 + c / 8 (the half map's last channel
        // reaches 1.31).
        Image source(16, 4);
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 16; ++x)
                source.at(x, y) = glm::vec4(float(x) / 16.0f) + glm::vec4(0.0f, 0.125f, 0.25f, 0.375f);
        const MapImage map = MapImage::fromImage(source, MapLayout(layout), MapSampleType(type));
        const MapStatistics statistics = mapStatistics(map);
        QCOMPARE(int(statistics.channels.size()), map.channels());
        for (int c = 0; c < map.channels(); ++c) {
            const MapChannelStatistics& channel = statistics.channels[std::size_t(c)];
            std::uint64_t total = 0;
            for (std::uint64_t count : channel.histogram)
                total += count;
            QCOMPARE(total, std::uint64_t(64));
            // Exactly the stored values: their range, mean and bins.
            float lo = 1e9f, hi = -1e9f;
            double sum = 0.0;
            std::array<std::uint64_t, MapChannelStatistics::kBins> bins {};
            for (int y = 0; y < 4; ++y)
                for (int x = 0; x < 16; ++x) {
                    const float v = map.sample(x, y, c);
                    lo = std::min(lo, v);
                    hi = std::max(hi, v);
                    sum += v;
                    ++bins[std::size_t(std::clamp(int(std::floor(v * 256.0f)), 0, 255))];
                }
            QCOMPARE(channel.minimum, lo);
            QCOMPARE(channel.maximum, hi);
            QVERIFY(std::abs(channel.mean - sum / 64.0) < 1e-9);
            QVERIFY(channel.histogram == bins);
            QVERIFY(channel.maximum > channel.minimum + 0.6f); // the gradient, not a constant
        }
        if (MapLayout(layout) == MapLayout::Rgba) // 15/16 + 0.375 = 1.31: counted in the last bin
            QVERIFY(statistics.channels[3].histogram[255] > 0 && statistics.channels[3].maximum > 1.3f);
        // A stand-in without pixels has none.
        QVERIFY(mapStatistics(MapImage::withoutPixels(map)).channels.empty());
    }

    // Which slots read which stored channel of a file (an ORM texture in three slots, a base
    // colour reading RGB, a grey map read by "g").
    void slotsReadingEachChannel()
    {
        Material material;
        for (MapSlot slot : {MapSlot::Occlusion, MapSlot::Roughness, MapSlot::Metallic})
            material.map(slot).path = "/maps/orm.png";
        material.map(MapSlot::Occlusion).channel = MapChannel::R;
        material.map(MapSlot::Roughness).channel = MapChannel::G;
        material.map(MapSlot::Metallic).channel = MapChannel::B;
        material.map(MapSlot::BaseColor).path = "/maps/orm.png"; // rgb
        using Slots = std::vector<MapSlot>;
        QCOMPARE(slotsReadingChannel(material, "/maps/orm.png", MapLayout::Rgb, 0),
            (Slots {MapSlot::BaseColor, MapSlot::Occlusion}));
        QCOMPARE(slotsReadingChannel(material, "/maps/orm.png", MapLayout::Rgb, 1),
            (Slots {MapSlot::BaseColor, MapSlot::Roughness}));
        QCOMPARE(slotsReadingChannel(material, "/maps/orm.png", MapLayout::Rgb, 2),
            (Slots {MapSlot::BaseColor, MapSlot::Metallic}));
        QCOMPARE(slotsReadingChannel(material, "/maps/orm.png", MapLayout::Rgba, 3), Slots {});
        QCOMPARE(slotsReadingChannel(material, "/maps/other.png", MapLayout::Rgb, 0), Slots {});
        // A grey file: every colour channel is its one channel.
        QCOMPARE(slotsReadingChannel(material, "/maps/orm.png", MapLayout::Grey, 0),
            (Slots {MapSlot::BaseColor, MapSlot::Metallic, MapSlot::Roughness, MapSlot::Occlusion}));
        QCOMPARE(storedChannelOf(MapChannel::A, MapLayout::Rgb), -1);
        QCOMPARE(storedChannelOf(MapChannel::A, MapLayout::GreyAlpha), 1);
        QCOMPARE(storedChannelOf(MapChannel::B, MapLayout::RedGreen), -1);
    }

    void initTestCase() { QVERIFY(m_folder.isValid()); }
    void cleanup()
    {
        qunsetenv("FACET_MAX_MAP_SIZE");
        qunsetenv("FACET_MAX_MAP_MPIXELS");
    }

    void loadsInOwnDepthAndChannels_data();
    void loadsInOwnDepthAndChannels();
    void floatSamplesAreSanitised();
    void fromImageQuantises();
    void crafted16kHeaderIsRefusedBeforeDecoding();
    void budgetComesFromTheEnvironment_data();
    void budgetComesFromTheEnvironment();
    void cacheDecodesEachFileOnce();
    void cacheSharesOneDecodeBetweenThreads();
    void cacheDecodesAgainWhenTheFileChanges();
    void cacheReportsFailures();

private:
    QString path(const QString& name) const { return m_folder.filePath(name); }
    QTemporaryDir m_folder;
};

namespace {
const std::vector<FileRow>& fileRows()
{
    using T = OIIO::TypeDesc;
    static const std::vector<FileRow> rows = {
        {"png 8-bit grey", "png", 1, T::UINT8, {}, MapSampleType::UInt8, MapLayout::Grey, ColorEncoding::SRGB, 1.0f, 256, 1e-7},
        {"png 8-bit grey+alpha", "png", 2, T::UINT8, {}, MapSampleType::UInt8, MapLayout::GreyAlpha, ColorEncoding::SRGB, 1.0f, 256, 1e-7},
        {"png 8-bit RGB", "png", 3, T::UINT8, {}, MapSampleType::UInt8, MapLayout::Rgb, ColorEncoding::SRGB, 1.0f, 256, 1e-7},
        {"png 8-bit RGBA", "png", 4, T::UINT8, {}, MapSampleType::UInt8, MapLayout::Rgba, ColorEncoding::SRGB, 1.0f, 256, 1e-7},
        {"png 16-bit RGB", "png", 3, T::UINT16, {}, MapSampleType::UInt16, MapLayout::Rgb, ColorEncoding::SRGB, 1.0f, 65536, 1e-9},
        {"png 16-bit grey", "png", 1, T::UINT16, {}, MapSampleType::UInt16, MapLayout::Grey, ColorEncoding::SRGB, 1.0f, 65536, 1e-9},
        {"exr half RGBA", "exr", 4, T::HALF, {}, MapSampleType::Half, MapLayout::Rgba, ColorEncoding::Linear, 1.0f, 1024, 5e-4},
        {"exr float RGB beyond 1", "exr", 3, T::FLOAT, {}, MapSampleType::Half, MapLayout::Rgb, ColorEncoding::Linear, 40.0f, 1024, 5e-4},
        {"exr float R,G", "exr", 2, T::FLOAT, {"R", "G"}, MapSampleType::Half, MapLayout::RedGreen, ColorEncoding::Linear, 1.0f, 1024, 5e-4},
        {"exr half Y", "exr", 1, T::HALF, {"Y"}, MapSampleType::Half, MapLayout::Grey, ColorEncoding::Linear, 1.0f, 1024, 5e-4},
        {"tif float RGB", "tif", 3, T::FLOAT, {}, MapSampleType::Half, MapLayout::Rgb, ColorEncoding::Linear, 1.0f, 1000, 5e-4},
        {"tif 8-bit 5 channels", "tif", 5, T::UINT8, {}, MapSampleType::UInt8, MapLayout::Rgba, ColorEncoding::SRGB, 1.0f, 256, 1e-7},
    };
    return rows;
}
} // namespace

void MapImageTest::loadsInOwnDepthAndChannels_data()
{
    QTest::addColumn<int>("row");
    for (std::size_t i = 0; i < fileRows().size(); ++i)
        QTest::newRow(fileRows()[i].name) << int(i);
}

void MapImageTest::loadsInOwnDepthAndChannels()
{
    QFETCH(int, row);
    const FileRow& r = fileRows()[std::size_t(row)];
    constexpr int kWidth = 7; // odd: rows are not 4-byte aligned
    constexpr int kHeight = 5;
    const QString file = path(QStringLiteral("row%1.%2").arg(row).arg(QLatin1String(r.extension)));
    const std::vector<float> values = pattern(kWidth, kHeight, r.channels, r.scale, r.levels);
    QVERIFY(writeFixture(file, kWidth, kHeight, r.channels, r.fileType, values, r.channelNames));

    std::string error;
    const std::optional<MapImage> map = MapImage::load(file.toStdString(), &error);
    QVERIFY2(map, error.c_str());
    QCOMPARE(map->width(), kWidth);
    QCOMPARE(map->height(), kHeight);
    QCOMPARE(map->sampleType(), r.type);
    QCOMPARE(map->layout(), r.layout);
    QCOMPARE(map->sourceChannels(), r.channels);
    QCOMPARE(map->encoding(), r.encoding);
    // In the file's own size: no float RGBA expansion.
    QCOMPARE(map->byteSize(),
        std::size_t(kWidth * kHeight) * std::size_t(channelCount(r.layout)) * std::size_t(bytesPerSample(r.type)));

    // Row 0 is the file's bottom row; each stored channel is the file's, and texel() expands as
    // the GPU's swizzle does.
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const int row0 = kHeight - 1 - y;
            const float* written = &values[std::size_t((y * kWidth + x) * r.channels)];
            for (int c = 0; c < map->channels(); ++c)
                QVERIFY2(std::abs(map->sample(x, row0, c) - written[c]) <= r.epsilon * std::max(1.0f, written[c]),
                    qPrintable(QStringLiteral("(%1, %2) channel %3: %4, written %5")
                                   .arg(x)
                                   .arg(y)
                                   .arg(c)
                                   .arg(map->sample(x, row0, c))
                                   .arg(written[c])));
            const glm::vec4 texel = map->texel(x, row0);
            const float* s = written;
            glm::vec4 expected;
            switch (r.layout) {
            case MapLayout::Grey:
                expected = {s[0], s[0], s[0], 1.0f};
                break;
            case MapLayout::GreyAlpha:
                expected = {s[0], s[0], s[0], s[1]};
                break;
            case MapLayout::RedGreen:
                expected = {s[0], s[1], 0.0f, 1.0f};
                break;
            case MapLayout::Rgb:
                expected = {s[0], s[1], s[2], 1.0f};
                break;
            case MapLayout::Rgba:
                expected = {s[0], s[1], s[2], s[3]};
                break;
            }
            for (int c = 0; c < 4; ++c)
                QVERIFY2(std::abs(texel[c] - expected[c]) <= r.epsilon * std::max(1.0f, expected[c]),
                    qPrintable(QStringLiteral("texel (%1, %2)[%3]: %4, expected %5")
                                   .arg(x)
                                   .arg(y)
                                   .arg(c)
                                   .arg(texel[c])
                                   .arg(expected[c])));
        }

    // Each texel component's range (what the renderer reads a roughness map's smallest value
    // from) is the smallest and largest of texel() over the map, kept by a stand-in, and unknown
    // once a sample is written otherwise.
    for (int c = 0; c < 4; ++c) {
        glm::vec2 expected(std::numeric_limits<float>::max(), std::numeric_limits<float>::lowest());
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                expected.x = std::min(expected.x, map->texel(x, y)[c]);
                expected.y = std::max(expected.y, map->texel(x, y)[c]);
            }
        const std::optional<glm::vec2> range = map->texelRange(c);
        QVERIFY(range);
        QCOMPARE(range->x, expected.x);
        QCOMPARE(range->y, expected.y);
        QCOMPARE(MapImage::withoutPixels(*map).texelRange(c), range);
    }
    MapImage written = *map;
    written.setSample(0, 0, 0, 0.5f);
    QVERIFY(!written.texelRange(0));
}

void MapImageTest::floatSamplesAreSanitised()
{
    // NaN, Inf and negative colour as environments get them (NaN -> 0, +Inf -> the largest half,
    // -Inf and negative -> 0, counted); finite values beyond half's range clamp to 65504 (not Inf,
    // not counted); alpha NaN -> 1, alpha out of [0, 1] clamped.
    const QString file = path(QStringLiteral("special.exr"));
    const std::vector<float> values = {kNaN, kInf, -kInf, 0.5f, -2.0f, 1e6f, 0.25f, kNaN, 0.1f, 0.2f, 0.3f, 7.0f};
    QVERIFY(writeFixture(file, 3, 1, 4, OIIO::TypeDesc::FLOAT, values));
    std::string error;
    ImageLoadStats stats;
    const std::optional<MapImage> map = MapImage::load(file.toStdString(), &error, &stats);
    QVERIFY2(map, error.c_str());
    QCOMPARE(map->sampleType(), MapSampleType::Half);
    const glm::vec4 expected[3] = {{0.0f, 65504.0f, 0.0f, 0.5f}, {0.0f, 65504.0f, 0.25f, 1.0f}, {0.1f, 0.2f, 0.3f, 1.0f}};
    for (int x = 0; x < 3; ++x)
        for (int c = 0; c < 4; ++c)
            QVERIFY2(std::abs(map->texel(x, 0)[c] - expected[x][c]) <= 1e-3f * std::max(1.0f, expected[x][c]),
                qPrintable(QStringLiteral("texel %1 channel %2: %3").arg(x).arg(c).arg(map->texel(x, 0)[c])));
    QCOMPARE(stats.nanCount, std::size_t(2)); // red of texel 0, alpha of texel 1
    QCOMPARE(stats.infCount, std::size_t(2)); // +Inf, -Inf
    QCOMPARE(stats.negativeCount, std::size_t(1)); // -2
}

void MapImageTest::fromImageQuantises()
{
    Image image(2, 2, glm::vec4(0.0f));
    image.at(0, 0) = glm::vec4(0.5f, 1.5f, -1.0f, 0.25f); // the top-left texel
    image.at(1, 1) = glm::vec4(1.0f / 3.0f, 0.0f, 0.0f, 1.0f); // the bottom-right one
    const MapImage bytes = MapImage::fromImage(image, MapLayout::GreyAlpha, MapSampleType::UInt8);
    QCOMPARE(bytes.channels(), 2);
    QCOMPARE(bytes.byteSize(), std::size_t(8));
    // Row 0 is the bottom: the top-left texel is (0, 1).
    QCOMPARE(bytes.sample(0, 1, 0), 128.0f / 255.0f); // red, rounded
    QCOMPARE(bytes.sample(0, 1, 1), 64.0f / 255.0f); // alpha 0.25 -> 63.75 -> 64
    QCOMPARE(bytes.texel(0, 1), glm::vec4(128.0f / 255.0f, 128.0f / 255.0f, 128.0f / 255.0f, 64.0f / 255.0f));
    QCOMPARE(bytes.sample(1, 0, 0), 85.0f / 255.0f);
    const MapImage halves = MapImage::fromImage(image, MapLayout::Rgba, MapSampleType::Half);
    QCOMPARE(halves.sample(0, 1, 1), 1.5f); // half keeps values beyond 1
    const MapImage words = MapImage::fromImage(image, MapLayout::Rgb, MapSampleType::UInt16);
    QCOMPARE(words.sample(0, 1, 1), 1.0f); // clamped
    QCOMPARE(words.sample(0, 1, 2), 0.0f);
    QCOMPARE(words.texel(0, 1).a, 1.0f);
}

void MapImageTest::crafted16kHeaderIsRefusedBeforeDecoding()
{
    const QString file = path(QStringLiteral("huge.png"));
    QVERIFY(facet::test::writePngHeaderOnly(file, 16384, 16384));
    QVERIFY(QFileInfo(file).size() < 100);
    std::string error;
    QElapsedTimer clock;
    clock.start();
    const std::optional<MapImage> map = MapImage::load(file.toStdString(), &error);
    QVERIFY(!map);
    // Refused from the header: no 768 MiB allocated, nothing decoded (the file has no pixels, so a
    // loader that tried would fail with a decoding error instead).
    QCOMPARE(QString::fromStdString(error),
        QStringLiteral("MapImage::load: %1: 16384x16384 is larger than the map size limit of 8192 pixels per "
                       "side (FACET_MAX_MAP_SIZE)")
            .arg(file));
    QVERIFY(clock.elapsed() < facet::test::wallClockBoundMs(2000));
    // Within the budget the same file is read, and fails as a file without pixels does: the
    // refusal above came from the budget.
    QVERIFY(facet::test::writePngHeaderOnly(file, 64, 64));
    QVERIFY(!MapImage::load(file.toStdString(), &error));
    QVERIFY2(error.find("larger than") == std::string::npos, error.c_str());
}

void MapImageTest::budgetComesFromTheEnvironment_data()
{
    QTest::addColumn<QByteArray>("side");
    QTest::addColumn<QByteArray>("mpixels");
    QTest::addColumn<int>("width");
    QTest::addColumn<int>("height");
    QTest::addColumn<QString>("problem"); // empty: fits
    QTest::addColumn<QString>("warning");
    QTest::newRow("defaults, 8192 fits") << QByteArray() << QByteArray() << 8192 << 8192 << QString() << QString();
    QTest::newRow("defaults, 8193 wide") << QByteArray() << QByteArray() << 8193 << 16 << QStringLiteral("8193x16 is larger than the map size limit of 8192 pixels per side (FACET_MAX_MAP_SIZE)") << QString();
    QTest::newRow("side 64") << QByteArray("64") << QByteArray() << 65 << 64 << QStringLiteral("65x64 is larger than the map size limit of 64 pixels per side (FACET_MAX_MAP_SIZE)") << QString();
    QTest::newRow("side 16384") << QByteArray("16384") << QByteArray("1024") << 16384 << 16384 << QString() << QString();
    QTest::newRow("side 40000, at most 16384") << QByteArray("40000") << QByteArray("4096") << 16385 << 16 << QStringLiteral("16385x16 is larger than the map size limit of 16384 pixels per side (FACET_MAX_MAP_SIZE)") << QString();
    QTest::newRow("mpixels 1") << QByteArray() << QByteArray("1") << 1025 << 1024 << QStringLiteral("1025x1024 is larger than the map size limit of 1 Mpixel (FACET_MAX_MAP_MPIXELS)") << QString();
    QTest::newRow("mpixels 1, exactly") << QByteArray() << QByteArray("1") << 1024 << 1024 << QString() << QString();
    QTest::newRow("bad side") << QByteArray("big") << QByteArray() << 8193 << 16 << QStringLiteral("8193x16 is larger than the map size limit of 8192 pixels per side (FACET_MAX_MAP_SIZE)") << QStringLiteral("FACET_MAX_MAP_SIZE is not a positive whole number: using 8192");
    QTest::newRow("bad mpixels") << QByteArray() << QByteArray("-3") << 16 << 16 << QString() << QStringLiteral("FACET_MAX_MAP_MPIXELS is not a positive whole number: using 64");
}

void MapImageTest::budgetComesFromTheEnvironment()
{
    QFETCH(QByteArray, side);
    QFETCH(QByteArray, mpixels);
    QFETCH(int, width);
    QFETCH(int, height);
    QFETCH(QString, problem);
    QFETCH(QString, warning);
    if (!side.isEmpty())
        qputenv("FACET_MAX_MAP_SIZE", side);
    if (!mpixels.isEmpty())
        qputenv("FACET_MAX_MAP_MPIXELS", mpixels);
    std::string note;
    const MapBudget budget = MapBudget::fromEnvironment(&note);
    QCOMPARE(QString::fromStdString(budget.check(width, height)), problem);
    QCOMPARE(QString::fromStdString(note), warning);
    // The loader applies it: a file of that size is refused from its header.
    if (!problem.isEmpty()) {
        const QString file = path(QStringLiteral("budget.png"));
        QVERIFY(facet::test::writePngHeaderOnly(file, width, height));
        std::string error;
        QVERIFY(!MapImage::load(file.toStdString(), &error));
        QCOMPARE(QString::fromStdString(error), QStringLiteral("MapImage::load: %1: %2").arg(file, problem));
    }
}

void MapImageTest::cacheDecodesEachFileOnce()
{
    const QString file = path(QStringLiteral("once.png"));
    QVERIFY(writeFixture(file, 8, 4, 3, OIIO::TypeDesc::UINT8, pattern(8, 4, 3, 1.0f, 256)));
    MapImageCache cache;
    std::string error;
    std::shared_ptr<const MapImage> first = cache.load(file.toStdString(), &error);
    QVERIFY2(first, error.c_str());
    std::shared_ptr<const MapImage> second = cache.load(file.toStdString(), &error);
    QCOMPARE(second.get(), first.get()); // the same decode
    QCOMPARE(cache.decodeCount(file.toStdString()), std::uint64_t(1));
    // Nobody holds it any more: the memory went, and the next reader decodes again.
    const std::weak_ptr<const MapImage> weak = first;
    first.reset();
    second.reset();
    QVERIFY(weak.expired());
    QVERIFY(cache.load(file.toStdString(), &error));
    QCOMPARE(cache.decodeCount(file.toStdString()), std::uint64_t(2));
    QCOMPARE(cache.decodeCount(), std::uint64_t(2));
}

void MapImageTest::cacheSharesOneDecodeBetweenThreads()
{
    // A large enough file that the threads meet while it decodes; each keeps its image until all
    // are done, so that a second decode could only come from not waiting for the first.
    const QString file = path(QStringLiteral("shared.png"));
    QVERIFY(writeFixture(file, 1024, 1024, 3, OIIO::TypeDesc::UINT8, pattern(1024, 1024, 3, 1.0f, 256)));
    MapImageCache cache;
    std::vector<std::shared_ptr<const MapImage>> results(6);
    std::vector<std::thread> threads;
    std::atomic<int> ready {0};
    for (std::size_t i = 0; i < results.size(); ++i)
        threads.emplace_back([&, i] {
            ++ready;
            while (ready.load() < int(results.size())) {
            }
            std::string problem;
            results[i] = cache.load(file.toStdString(), &problem);
        });
    for (std::thread& thread : threads)
        thread.join();
    for (const auto& result : results) {
        QVERIFY(result);
        QCOMPARE(result.get(), results[0].get());
    }
    QCOMPARE(cache.decodeCount(file.toStdString()), std::uint64_t(1));
}

void MapImageTest::cacheDecodesAgainWhenTheFileChanges()
{
    const QString file = path(QStringLiteral("changes.png"));
    QVERIFY(writeFixture(file, 4, 4, 1, OIIO::TypeDesc::UINT8, std::vector<float>(16, 0.0f)));
    MapImageCache cache;
    std::string error;
    const auto before = cache.load(file.toStdString(), &error);
    QVERIFY2(before, error.c_str());
    QCOMPARE(before->sample(0, 0, 0), 0.0f);
    QVERIFY(writeFixture(file, 4, 4, 1, OIIO::TypeDesc::UINT8, std::vector<float>(16, 1.0f)));
    // The same size on disk: the modification time tells (set apart explicitly, as file systems
    // with a coarse clock would not).
    std::filesystem::last_write_time(file.toStdString(),
        std::filesystem::last_write_time(file.toStdString()) + std::chrono::seconds(2));
    const auto after = cache.load(file.toStdString(), &error);
    QVERIFY2(after, error.c_str());
    QVERIFY(after.get() != before.get());
    QCOMPARE(after->sample(0, 0, 0), 1.0f);
    QCOMPARE(cache.decodeCount(file.toStdString()), std::uint64_t(2));
}

void MapImageTest::cacheReportsFailures()
{
    MapImageCache cache;
    const QString missing = path(QStringLiteral("missing.png"));
    std::string error;
    QVERIFY(!cache.load(missing.toStdString(), &error));
    QCOMPARE(QString::fromStdString(error), QStringLiteral("MapImage::load: %1: no such file").arg(missing));
    const QString huge = path(QStringLiteral("huge-cached.png"));
    QVERIFY(facet::test::writePngHeaderOnly(huge, 9000, 16));
    QVERIFY(!cache.load(huge.toStdString(), &error));
    QVERIFY2(error.find("larger than the map size limit") != std::string::npos, error.c_str());
    // A failure is not remembered as an image: the file fixed, it loads.
    QVERIFY(writeFixture(missing, 2, 2, 3, OIIO::TypeDesc::UINT8, pattern(2, 2, 3, 1.0f, 256)));
    QVERIFY(cache.load(missing.toStdString(), &error));
}

QTEST_GUILESS_MAIN(MapImageTest)
#include "MapImageTest.moc"
