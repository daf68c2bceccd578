#include "core/ibl/Environment.h"
#include "core/support/Fnv1a.h"

#include "core/ibl/EnvironmentIndex.h"
#include "core/project/AssetLibrary.h"
#include "core/support/FileCheck.h"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>
#include <numbers>
#include <string_view>
#include <vector>

#include <QDir>
#include <QFileInfo>
#include <QtDebug>
#include <QtGlobal>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

namespace facet {

namespace {

constexpr double kPi = std::numbers::pi;

double degreesToRadians(double degrees)
{
    return degrees * (kPi / 180.0);
}

// Rotation about +Y by `radians`, right-handed: +X goes toward -Z, i.e. counter-clockwise seen
// from above (from +Y looking down). R_y = [[c, 0, s], [0, 1, 0], [-s, 0, c]].
glm::dvec3 rotateAboutY(const glm::dvec3& d, double radians)
{
    const double c = std::cos(radians);
    const double s = std::sin(radians);
    return {c * d.x + s * d.z, d.y, -s * d.x + c * d.z};
}

std::uint32_t floatBits(float value)
{
    // -0 and +0 are the same radiance: hash them alike.
    if (value == 0.0f)
        value = 0.0f;
    std::uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

std::uint64_t hashPixels(const Image& image)
{
    Fnv1a64 hash;
    hash.addUint32(std::uint32_t(image.width()));
    hash.addUint32(std::uint32_t(image.height()));
    // RGB only: an environment's alpha is never used, so it must not split caches.
    const glm::vec4* pixels = image.data();
    for (std::size_t i = 0; i < image.pixelCount(); ++i)
        for (int c = 0; c < 3; ++c)
            hash.addUint32(floatBits(pixels[i][c]));
    return hash.value();
}

// The size an environment keeps of a width x height file: its own, or the largest of the same
// aspect within Environment::kMaxWidth x kMaxHeight (each side rounded down, at least 1).
std::pair<int, int> keptSize(int width, int height)
{
    if (width <= Environment::kMaxWidth && height <= Environment::kMaxHeight)
        return {width, height};
    const double scale
        = std::min(double(Environment::kMaxWidth) / width, double(Environment::kMaxHeight) / height);
    return {std::max(1, int(std::floor(width * scale))), std::max(1, int(std::floor(height * scale)))};
}

// Reads an environment file as load() keeps it: linear, sanitised, area-filtered to keptSize
// a band at a time. Errors without a function prefix ("<path>: <reason>").
std::optional<Image> decodeEnvironmentFile(const std::string& path, std::string* error, ImageLoadStats* stats)
{
    std::string imageError;
    std::optional<Image> image
        = Image::loadBoxFiltered(path, /*linear=*/true, &keptSize, &imageError, nullptr, nullptr, stats);
    if (!image && error) {
        static const std::string kImagePrefix = "Image::loadBoxFiltered: ";
        if (imageError.rfind(kImagePrefix, 0) == 0)
            imageError.erase(0, kImagePrefix.size());
        *error = imageError;
    }
    return image;
}

} // namespace

// The pixels of an environment: in memory from the start, or decoded from `path` at the first
// get() (an environment found in core/ibl/EnvironmentIndex).
class Environment::Pixels {
public:
    explicit Pixels(Image image)
        : m_image(std::move(image))
        , m_decoded(true)
    {
    }
    Pixels(std::string path, std::uint64_t contentHash, int width, int height)
        : m_path(std::move(path))
        , m_contentHash(contentHash)
        , m_width(width)
        , m_height(height)
    {
    }

    const Image& get()
    {
        std::call_once(m_once, [this] {
            if (!m_decoded.load())
                decode();
        });
        return m_image;
    }
    bool decoded() const { return m_decoded.load(); }

private:
    void decode()
    {
        std::string error;
        std::optional<Image> image = decodeEnvironmentFile(m_path, &error, nullptr);
        if (image)
            image->sanitize();
        if (!image) {
            qWarning("Environment: %s; it decoded when first loaded: lighting with black until it "
                     "is loaded again",
                qPrintable(QString::fromStdString(error)));
            m_image = Image(m_width, m_height, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
            EnvironmentIndex().forget(m_path);
        } else {
            if (image->width() != m_width || image->height() != m_height
                || hashPixels(*image) != m_contentHash) {
                qWarning("Environment: %s: changed on disk without changing its size or times; "
                         "load it again to light with the new pixels",
                    m_path.c_str());
                EnvironmentIndex().forget(m_path);
            }
            m_image = std::move(*image);
        }
        m_decoded.store(true);
    }

    std::once_flag m_once;
    Image m_image;
    std::atomic<bool> m_decoded {false};
    std::string m_path;
    std::uint64_t m_contentHash = 0;
    int m_width = 0;
    int m_height = 0;
};

namespace {

// Shortest text that reads back as the same double (std::to_chars round-trip guarantee).
std::string formatNumber(double value)
{
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::string trimmed(std::string_view text)
{
    const auto isSpace = [](char c) { return c == ' ' || c == '\t'; };
    while (!text.empty() && isSpace(text.front()))
        text.remove_prefix(1);
    while (!text.empty() && isSpace(text.back()))
        text.remove_suffix(1);
    return std::string(text);
}

// A finite, non-negative number that a float holds, and nothing else ("1e999" is out of range,
// "nan"/"inf" are not finite, "1e300" would become Inf in the image).
std::optional<double> parseRadiance(std::string_view text)
{
    const std::string token = trimmed(text);
    if (token.empty())
        return std::nullopt;
    double value = 0.0;
    const char* end = token.data() + token.size();
    const auto result = std::from_chars(token.data(), end, value);
    if (result.ec != std::errc() || result.ptr != end || !std::isfinite(value) || value < 0.0
        || value > double(std::numeric_limits<float>::max()))
        return std::nullopt;
    return value;
}

double smoothstep(double edge0, double edge1, double x)
{
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// A soft-edged box [-halfWidth, halfWidth] with edges `softness` wide (the value is 0.5 at
// +-halfWidth), so that a procedural light has no hard, aliasing edge.
double softBox(double x, double halfWidth, double softness)
{
    return 1.0 - smoothstep(halfWidth - 0.5 * softness, halfWidth + 0.5 * softness, std::abs(x));
}

glm::dvec3 mix(const glm::dvec3& a, const glm::dvec3& b, double t)
{
    return a + (b - a) * t;
}

// The procedural built-ins, as functions of a direction in the image frame. Values are linear
// radiance (Rec.709 primaries); the numbers are picked to look like a photographer's studio and
// a clear day, with an exposure that suits the default camera (mean around 1).

// A unit direction with its equirect angles, which the renderer below knows without asin/atan2.
struct Direction {
    glm::dvec3 d;
    double elevation; // asin(d.y), in [-pi/2, pi/2]
    double azimuth; // atan2(d.z, d.x), in [-pi, pi]: 0 at +X, +-pi at -X
    double cosElevation; // cos(elevation)
};

glm::dvec3 studioRadiance(const Direction& direction)
{
    const glm::dvec3& d = direction.d;
    // Room: neutral grey walls, a little brighter toward the ceiling, a warm floor that
    // bounces the soft box's light (blended over the horizon so there is no seam).
    const glm::dvec3 wall = glm::dvec3(0.40) + glm::dvec3(0.12) * std::max(d.y, 0.0);
    const glm::dvec3 floorBounce(0.55, 0.45, 0.33);
    glm::dvec3 radiance = mix(floorBounce, wall, smoothstep(-0.15, 0.05, d.y));

    // Soft box: a 1.6 x 1.0 rectangle on a ceiling at height 1 (about 77 x 53 degrees seen from
    // the centre), edges blurred over 0.08 of its plane.
    if (d.y > 0.05) {
        const double x = d.x / d.y;
        const double z = d.z / d.y;
        const double mask = softBox(x, 0.8, 0.08) * softBox(z, 0.5, 0.08);
        radiance = mix(radiance, glm::dvec3(15.0, 15.0, 15.0), mask);
    }

    // Two vertical strip lights left and right (toward -X and +X): 6 degrees wide, from 5
    // degrees below the horizon to 45 degrees above, slightly cool.
    const double verticalMask = softBox(
        direction.elevation - degreesToRadians(20.0), degreesToRadians(25.0), degreesToRadians(2.0));
    if (verticalMask > 0.0) {
        const double nearPlusX = direction.azimuth;
        const double nearMinusX = direction.azimuth > 0.0 ? direction.azimuth - kPi : direction.azimuth + kPi;
        const double stripWidth = degreesToRadians(3.0);
        const double stripSoftness = degreesToRadians(1.5);
        // Width in azimuth, measured along the horizon (cos(elevation) keeps the strip straight).
        const double strips = softBox(nearPlusX * direction.cosElevation, stripWidth, stripSoftness)
            + softBox(nearMinusX * direction.cosElevation, stripWidth, stripSoftness);
        radiance = mix(radiance, glm::dvec3(7.5, 8.0, 8.5), std::min(strips, 1.0) * verticalMask);
    }
    return radiance;
}

// Sun of the Sky built-in: 35 degrees up, toward +X+Z (behind the default camera on its
// right), so the sphere of the reference view is lit from the front right.
glm::dvec3 skySunDirection()
{
    const double elevation = degreesToRadians(35.0);
    const double azimuth = degreesToRadians(45.0);
    return {std::cos(elevation) * std::cos(azimuth), std::sin(elevation),
        std::cos(elevation) * std::sin(azimuth)};
}

glm::dvec3 skyRadiance(const Direction& direction)
{
    const glm::dvec3& d = direction.d;
    // Sky: pale blue at the horizon (about 2), deep blue at the zenith.
    const glm::dvec3 horizon(1.7, 2.0, 2.5);
    const glm::dvec3 zenith(0.3, 0.55, 1.3);
    const glm::dvec3 sky = mix(horizon, zenith, std::sqrt(std::max(d.y, 0.0)));
    // Ground: a grey-brown plane, about 0.25, joined to the sky over a degree or so.
    const glm::dvec3 ground(0.28, 0.25, 0.21);
    const double skyMask = smoothstep(-0.02, 0.01, d.y);
    glm::dvec3 radiance = mix(ground, sky, skyMask);

    // Sun: a disc of 2 degrees angular radius (4 wide, larger than the real 0.27 so that it
    // stays visible and well sampled at 512 wide) with a soft limb, radiance 400, warm, and a
    // faint aureole around it (below 3e-5 beyond 50 degrees, where it is left out).
    static const glm::dvec3 sun = skySunDirection();
    static const double cosAureoleEnd = std::cos(degreesToRadians(50.0));
    const double cosAngle = glm::dot(d, sun);
    if (cosAngle > cosAureoleEnd) {
        const double angle = std::acos(std::min(cosAngle, 1.0));
        const double disc = 1.0 - smoothstep(degreesToRadians(1.6), degreesToRadians(2.4), angle);
        const double aureole = 6.0 * std::exp(-angle / degreesToRadians(4.0));
        radiance += glm::dvec3(1.0, 0.9, 0.75) * aureole * skyMask;
        radiance = mix(radiance, glm::dvec3(400.0, 380.0, 340.0), disc);
    }
    return radiance;
}

Image renderEquirect(int width, int height, glm::dvec3 (*radianceOf)(const Direction&))
{
    // Each texel averages a 4x4 grid of directions over its footprint: a box-filtered
    // (anti-aliased) image whose lights keep their power at any resolution. The angles of the
    // grid's columns and rows are computed once (directionFromEquirectUv, unrolled).
    constexpr int kSubsamples = 4;
    struct Angle {
        double angle, cosine, sine;
    };
    const auto angle = [](double radians) { return Angle {radians, std::cos(radians), std::sin(radians)}; };
    std::vector<Angle> azimuths(std::size_t(width) * kSubsamples);
    for (std::size_t i = 0; i < azimuths.size(); ++i)
        azimuths[i] = angle(((double(i) + 0.5) / double(azimuths.size()) - 0.5) * 2.0 * kPi);
    std::vector<Angle> elevations(std::size_t(height) * kSubsamples);
    for (std::size_t j = 0; j < elevations.size(); ++j) // row 0 on top: v = 1 - (j + 0.5) / n
        elevations[j] = angle((0.5 - (double(j) + 0.5) / double(elevations.size())) * kPi);

    Image image(width, height, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            glm::dvec3 sum(0.0);
            for (int sy = 0; sy < kSubsamples; ++sy) {
                const Angle& elevation = elevations[std::size_t(y * kSubsamples + sy)];
                for (int sx = 0; sx < kSubsamples; ++sx) {
                    const Angle& azimuth = azimuths[std::size_t(x * kSubsamples + sx)];
                    const Direction direction {
                        {elevation.cosine * azimuth.cosine, elevation.sine, elevation.cosine * azimuth.sine},
                        elevation.angle, azimuth.angle, elevation.cosine};
                    sum += radianceOf(direction);
                }
            }
            const glm::dvec3 mean = sum / double(kSubsamples * kSubsamples);
            image.at(x, y) = glm::vec4(glm::vec3(mean), 1.0f);
        }
    }
    return image;
}

} // namespace

glm::dvec2 equirectUvFromDirection(const glm::dvec3& direction)
{
    const double length = glm::length(direction);
    const glm::dvec3 d = length > 0.0 ? direction / length : glm::dvec3(1.0, 0.0, 0.0);
    return {std::atan2(d.z, d.x) / (2.0 * kPi) + 0.5, std::asin(std::clamp(d.y, -1.0, 1.0)) / kPi + 0.5};
}

glm::dvec3 directionFromEquirectUv(const glm::dvec2& uv)
{
    const double azimuth = (uv.x - 0.5) * 2.0 * kPi;
    const double elevation = (uv.y - 0.5) * kPi;
    const double cosElevation = std::cos(elevation);
    return {cosElevation * std::cos(azimuth), std::sin(elevation), cosElevation * std::sin(azimuth)};
}

Environment::Environment(Image equirect, std::string name)
    : m_name(std::move(name))
{
    // The radiance of an environment is finite and non-negative whatever made the image.
    // (load() has sanitised already and reported it; this pass then changes nothing.)
    equirect.sanitize();
    m_contentHash = hashPixels(equirect);
    m_width = equirect.width();
    m_height = equirect.height();
    m_pixels = std::make_shared<Pixels>(std::move(equirect));
}

Environment::Environment(std::string path, std::uint64_t contentHash, int width, int height)
    : m_width(width)
    , m_height(height)
    , m_name(path)
    , m_contentHash(contentHash)
{
    m_pixels = std::make_shared<Pixels>(std::move(path), contentHash, width, height);
}

const Image& Environment::image() const
{
    static const Image kEmpty;
    return m_pixels ? m_pixels->get() : kEmpty;
}

bool Environment::decoded() const
{
    return m_pixels && m_pixels->decoded();
}

Environment Environment::uniform(const glm::dvec3& radiance)
{
    // A small image is enough: every texel is the same, so every filter returns the constant.
    Image image(8, 4, glm::vec4(glm::vec3(radiance), 1.0f));
    Environment environment(std::move(image),
        "uniform:" + formatNumber(radiance.x) + "," + formatNumber(radiance.y) + ","
            + formatNumber(radiance.z));
    environment.m_uniform = true;
    return environment;
}

Environment Environment::builtin(Builtin which, int width)
{
    Q_ASSERT(width >= 8);
    width = std::max(width, 8);
    width += width % 2;
    const int height = width / 2;
    switch (which) {
    case Builtin::Studio:
        return Environment(renderEquirect(width, height, &studioRadiance), builtinName(which));
    case Builtin::Sky:
        return Environment(renderEquirect(width, height, &skyRadiance), builtinName(which));
    }
    return {};
}

std::optional<Environment> Environment::load(
    const std::string& path, std::string* error, std::string* warning)
{
    if (warning)
        warning->clear();
    // A file loaded before and unchanged since: its record says all but the pixels.
    const EnvironmentIndex index;
    FileIdentity before;
    const bool identified = fileIdentity(path, &before);
    if (identified) {
        if (const std::optional<EnvironmentRecord> record = index.find(path, before)) {
            if (warning)
                *warning = record->warning;
            return Environment(path, record->contentHash, record->width, record->height);
        }
    }

    std::string imageError;
    ImageLoadStats stats;
    std::optional<Image> image = decodeEnvironmentFile(path, &imageError, &stats);
    if (!image) {
        if (error)
            *error = "Environment::load: " + imageError;
        return std::nullopt;
    }

    std::string lines;
    auto addLine = [&lines](const std::string& line) {
        if (!lines.empty())
            lines += '\n';
        lines += line;
    };
    if (stats.total() > 0)
        addLine(path + ": replaced " + std::to_string(stats.nanCount) + " NaN, "
            + std::to_string(stats.infCount) + " Inf, " + std::to_string(stats.negativeCount)
            + " negative samples");
    if (image->width() != 2 * image->height())
        addLine(path + ": " + std::to_string(image->width()) + "x" + std::to_string(image->height())
            + " is not 2:1; an equirectangular image is stretched to cover the sphere");
    if (warning)
        *warning = lines;
    Environment environment(std::move(*image), path);
    // Remembered only when the file did not change while it was read (the index also refuses a
    // file too recent to trust); a failure to remember costs the next load its decoding, no more.
    FileIdentity after;
    if (identified && fileIdentity(path, &after) && after == before)
        index.store(
            path, before, {environment.contentHash(), environment.width(), environment.height(), lines});
    return environment;
}

namespace {
const std::string kUniformPrefix = "uniform:";

// What a bare name that is no file could have meant: the built-in environments and the installed
// CC0 samples (which the command line takes by name, a project by library reference).
std::string bareNameAdvice(const std::string& name)
{
    const QString folder = QString::fromStdString(AssetLibrary::installed().folder) + QStringLiteral("/hdri");
    if (QFileInfo(folder + QLatin1Char('/') + QString::fromStdString(name) + QStringLiteral(".exr")).isFile())
        return "the built-in environments are studio and sky; the installed sample is library:installed/hdri/"
            + name + ".exr";
    QStringList samples = QDir(folder).entryList({QStringLiteral("*.exr")}, QDir::Files, QDir::Name);
    for (QString& sample : samples)
        sample.chop(4);
    if (samples.isEmpty())
        return "the built-in environments are studio and sky, and no CC0 samples are installed in "
            + folder.toStdString() + " (packaging/fetch-assets.sh installs them)";
    return "the built-in environments are studio and sky; the installed samples are "
        + samples.join(QStringLiteral(", ")).toStdString() + " (library:installed/hdri/NAME.exr)";
}
} // namespace

bool Environment::namesFile(const std::string& spec)
{
    return !spec.empty() && spec.rfind(kUniformPrefix, 0) != 0 && !builtinFromName(spec);
}

std::optional<Environment> Environment::fromSpec(
    const std::string& spec, std::string* error, std::string* warning)
{
    if (warning)
        warning->clear();
    if (spec.empty()) {
        if (error)
            *error = "Environment::fromSpec: empty environment (expected a path, a built-in name or "
                     "uniform:VALUE)";
        return std::nullopt;
    }
    if (spec.rfind(kUniformPrefix, 0) == 0) {
        const std::string_view values = std::string_view(spec).substr(kUniformPrefix.size());
        std::vector<double> numbers;
        bool valid = true;
        std::size_t start = 0;
        while (valid) {
            const std::size_t comma = values.find(',', start);
            const std::optional<double> number = parseRadiance(
                values.substr(start, comma == std::string_view::npos ? comma : comma - start));
            valid = number.has_value();
            if (valid)
                numbers.push_back(*number);
            if (comma == std::string_view::npos)
                break;
            start = comma + 1;
        }
        if (!valid || (numbers.size() != 1 && numbers.size() != 3)) {
            if (error)
                *error = "Environment::fromSpec: " + spec
                    + ": expected uniform:VALUE or uniform:R,G,B with finite non-negative numbers";
            return std::nullopt;
        }
        return uniform(
            numbers.size() == 1 ? glm::dvec3(numbers[0]) : glm::dvec3(numbers[0], numbers[1], numbers[2]));
    }
    // A built-in name wins over a file of the same name in the working directory ("./studio"
    // reaches the file) and over the installed sample of that name (library:installed/hdri/studio.exr).
    if (const std::optional<Builtin> which = builtinFromName(spec))
        return builtin(*which);
    const std::optional<std::string> file = AssetLibrary::fileForSpec(spec, "Environment::fromSpec", error);
    if (!file)
        return std::nullopt;
    std::string path = *file;
    std::optional<Environment> environment = load(path, error, warning);
    if (!environment && error && !QFileInfo::exists(QString::fromStdString(path))) {
        // Say where a missing file was meant to come from, and how to get it.
        if (const std::string advice = AssetLibrary::missingFileAdvice(path); !advice.empty())
            *error += "; " + advice;
        else if (path.find_first_of("/.") == std::string::npos)
            *error += "; " + bareNameAdvice(path);
    }
    return environment;
}

bool Environment::checkSpec(const std::string& spec, std::string* problem)
{
    if (namesFile(spec))
        return true;
    // Empty, built-in or uniform: fromSpec makes these in memory (a uniform environment is 8x4
    // texels, a built-in one is not made here), so its own message is the one to give.
    if (builtinFromName(spec))
        return true;
    std::string error;
    if (fromSpec(spec, &error))
        return true;
    const std::string prefix = "Environment::fromSpec: ";
    if (problem)
        *problem = error.rfind(prefix, 0) == 0 ? error.substr(prefix.size()) : error;
    return false;
}

std::optional<Environment::Builtin> Environment::builtinFromName(const std::string& name)
{
    for (Builtin which : {Builtin::Studio, Builtin::Sky})
        if (name == builtinName(which))
            return which;
    return std::nullopt;
}

const char* Environment::builtinName(Builtin which)
{
    switch (which) {
    case Builtin::Studio:
        return "studio";
    case Builtin::Sky:
        return "sky";
    }
    return "";
}

glm::dvec3 Environment::toImageFrame(const glm::dvec3& worldDirection) const
{
    if (m_rotationDegrees == 0.0)
        return worldDirection;
    return rotateAboutY(worldDirection, -degreesToRadians(m_rotationDegrees));
}

glm::dvec3 Environment::toWorldFrame(const glm::dvec3& imageDirection) const
{
    if (m_rotationDegrees == 0.0)
        return imageDirection;
    return rotateAboutY(imageDirection, degreesToRadians(m_rotationDegrees));
}

glm::dvec3 Environment::radiance(const glm::dvec3& direction) const
{
    if (isEmpty())
        return glm::dvec3(0.0);
    const Image& image = this->image();
    const int width = image.width();
    const int height = image.height();
    const glm::dvec2 uv = equirectUvFromDirection(toImageFrame(direction));
    // Texel centres sit at (x + 0.5) / width in u and 1 - (y + 0.5) / height in v (row 0 on
    // top); interpolate between the four around the point, the way a GL_LINEAR sampler does
    // with GL_REPEAT in u and GL_CLAMP_TO_EDGE in v.
    const double x = uv.x * width - 0.5;
    const double y = (1.0 - uv.y) * height - 0.5;
    const double x0f = std::floor(x);
    const double y0f = std::floor(y);
    const double fx = x - x0f;
    const double fy = y - y0f;
    const auto wrapX = [width](long long column) { return int(((column % width) + width) % width); };
    const auto clampY = [height](long long row) { return int(std::clamp<long long>(row, 0, height - 1)); };
    const int xa = wrapX((long long)x0f);
    const int xb = wrapX((long long)x0f + 1);
    const int ya = clampY((long long)y0f);
    const int yb = clampY((long long)y0f + 1);
    const auto texel = [&image](int column, int row) { return glm::dvec3(glm::vec3(image.at(column, row))); };
    const glm::dvec3 top = mix(texel(xa, ya), texel(xb, ya), fx);
    const glm::dvec3 bottom = mix(texel(xa, yb), texel(xb, yb), fx);
    return mix(top, bottom, fy) * m_intensity;
}

glm::dvec3 Environment::radianceNearest(const glm::dvec3& direction) const
{
    if (isEmpty())
        return glm::dvec3(0.0);
    const Image& image = this->image();
    const int width = image.width();
    const int height = image.height();
    const glm::dvec2 uv = equirectUvFromDirection(toImageFrame(direction));
    // The texel whose footprint holds the point; u = 1 wraps to column 0.
    const long long column = (long long)std::floor(uv.x * width);
    const int x = int(((column % width) + width) % width);
    const int y = int(std::clamp<long long>((long long)std::floor((1.0 - uv.y) * height), 0, height - 1));
    return glm::dvec3(glm::vec3(image.at(x, y))) * m_intensity;
}

} // namespace facet
