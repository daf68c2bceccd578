#include "TestSupport.h"

#include <cstdint>
#include <cstdio>
#include <memory>
#include <vector>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>

#include <OpenImageIO/imageio.h>

namespace facet::test {

QString assetsDir()
{
    const QByteArray fromEnvironment = qgetenv("FACET_ASSETS_DIR");
    return fromEnvironment.isEmpty() ? QStringLiteral(FACET_ASSETS_DIR)
                                     : QString::fromLocal8Bit(fromEnvironment);
}

static QString existing(const QString& path)
{
    return QFileInfo::exists(path) ? path : QString();
}

QString hdriPath(const QString& name)
{
    const QString fetched = existing(assetsDir() + QStringLiteral("/hdri/") + name + QStringLiteral(".exr"));
    if (!fetched.isEmpty())
        return fetched;
    return existing(sourceDir() + QStringLiteral("/tests/data/hdri/") + name + QStringLiteral(".exr"));
}
QString modelPath(const QString& name)
{
    return existing(assetsDir() + QStringLiteral("/models/") + name + QStringLiteral(".glb"));
}
QString sourceDir()
{
    return QStringLiteral(FACET_SOURCE_DIR);
}

QString outputDir()
{
    const QByteArray fromEnvironment = qgetenv("FACET_TEST_OUTPUT_DIR");
    const QString dir = fromEnvironment.isEmpty() ? QStringLiteral(FACET_TEST_OUTPUT_DIR)
                                                  : QString::fromLocal8Bit(fromEnvironment);
    QDir().mkpath(dir);
    return dir;
}

bool runningInCi()
{
    return qgetenv("CI") == "true";
}

void forgetDisplayServer()
{
    qunsetenv("DISPLAY");
    qunsetenv("WAYLAND_DISPLAY");
}

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

bool writeConstantExr(const QString& path, float radiance, int width)
{
    if (!QDir().mkpath(QFileInfo(path).absolutePath()))
        return false;
    const int height = width / 2;
    const std::vector<float> pixels(std::size_t(width * height * 3), radiance);
    std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path.toStdString());
    const OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::FLOAT);
    return output && output->open(path.toStdString(), spec)
        && output->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) && output->close();
}

namespace {

// CRC-32 of PNG chunks (ISO 3309 / ITU-T V.42, the PNG specification's section 5.5): bitwise.
std::uint32_t pngCrc(const QByteArray& bytes)
{
    std::uint32_t crc = 0xffffffffU;
    for (char byte : bytes) {
        crc ^= std::uint8_t(byte);
        for (int bit = 0; bit < 8; ++bit)
            crc = (crc >> 1) ^ (0xedb88320U & (0U - (crc & 1U)));
    }
    return crc ^ 0xffffffffU;
}

void appendBigEndian(QByteArray& bytes, std::uint32_t value)
{
    for (int shift = 24; shift >= 0; shift -= 8)
        bytes.append(char((value >> shift) & 0xffU));
}

void appendChunk(QByteArray& png, const char* type, const QByteArray& data)
{
    appendBigEndian(png, std::uint32_t(data.size()));
    const QByteArray typed = QByteArray(type) + data;
    png.append(typed);
    appendBigEndian(png, pngCrc(typed));
}

} // namespace

bool writePngHeaderOnly(const QString& path, int width, int height)
{
    QByteArray png("\x89PNG\r\n\x1a\n", 8);
    QByteArray header;
    appendBigEndian(header, std::uint32_t(width));
    appendBigEndian(header, std::uint32_t(height));
    header.append(char(8)); // bit depth
    header.append(char(2)); // colour type: RGB
    header.append(char(0)); // compression, filter, interlace
    header.append(char(0));
    header.append(char(0));
    appendChunk(png, "IHDR", header);
    appendChunk(png, "IDAT", {});
    appendChunk(png, "IEND", {});
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(png) == png.size();
}

std::string describe(const glm::dvec3& v, int digits)
{
    char text[128];
    std::snprintf(text, sizeof text, "(%.*g, %.*g, %.*g)", digits, v.x, digits, v.y, digits, v.z);
    return text;
}

ProcessResult runWithoutDisplay(
    const QString& executable, const QStringList& arguments, const QProcessEnvironment& extra)
{
    QProcess process;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.remove(QStringLiteral("DISPLAY"));
    environment.remove(QStringLiteral("WAYLAND_DISPLAY"));
    environment.insert(extra);
    process.setProcessEnvironment(environment);
    process.start(executable, arguments);
    ProcessResult result;
    if (!process.waitForFinished(300000)) {
        result.err = QStringLiteral("did not finish");
        return result;
    }
    result.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    result.out = QString::fromUtf8(process.readAllStandardOutput());
    result.err = QString::fromUtf8(process.readAllStandardError());
    return result;
}

bool writeText(const QString& path, const QByteArray& text)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile file(path);
    return file.open(QIODevice::WriteOnly | QIODevice::Truncate) && file.write(text) == text.size();
}

QStringList strings(std::initializer_list<const char*> items)
{
    QStringList list;
    for (const char* item : items)
        list.append(QString::fromUtf8(item));
    return list;
}

GltfValidation validateGltf(const QString& path)
{
    GltfValidation result;
    const QString validator = QStringLiteral(FACET_GLTF_VALIDATOR);
    if (!QFileInfo::exists(validator + QStringLiteral("/package.json"))) {
        result.report = QStringLiteral(
            "the glTF validator is not installed in %1 (packaging/install-deps.sh installs it)")
                            .arg(validator);
        return result;
    }
    QProcess node;
    node.start(QStringLiteral("node"),
        {sourceDir() + QStringLiteral("/tests/tools/validate-gltf.cjs"), validator, path});
    if (!node.waitForFinished(120000) || node.exitStatus() != QProcess::NormalExit) {
        result.report = QStringLiteral("node did not run or finish: ") + node.errorString();
        return result;
    }
    result.report
        = QString::fromUtf8(node.readAllStandardOutput()) + QString::fromUtf8(node.readAllStandardError());
    if (node.exitCode() == 2)
        return result;
    result.ran = true;
    result.clean = node.exitCode() == 0;
    return result;
}

} // namespace facet::test
