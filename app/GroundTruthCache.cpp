#include "GroundTruthCache.h"

#include "core/support/AtomicFile.h"

#include <cstdio>
#include <cstring>

#include <QCryptographicHash>
#include <QDataStream>
#include <QDir>
#include <QFile>
#include <QStandardPaths>

namespace facet {

namespace {

constexpr char kMagic[8] = {'F', 'A', 'C', 'E', 'T', 'G', 'T', '1'};
constexpr quint32 kFileVersion = 1;
constexpr quint32 kMaxSide = 16384; // a bigger header is a corrupt file, not a benchmark image

// %.17g: the shortest text that gives the double back exactly, so equal inputs give equal keys.
std::string number(double value)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    return buffer;
}

} // namespace

GroundTruthCache::GroundTruthCache(QString directory)
    : m_directory(directory.isEmpty() ? defaultDirectory() : std::move(directory))
{
}

QString GroundTruthCache::defaultDirectory()
{
    const QString overridden = qEnvironmentVariable("FACET_CACHE_DIR");
    if (!overridden.isEmpty())
        return overridden + QStringLiteral("/ground-truth");
    return QStandardPaths::writableLocation(QStandardPaths::CacheLocation) + QStringLiteral("/ground-truth");
}

std::string GroundTruthCache::keyText(const GroundTruthScene& scene, const GroundTruthSettings& settings)
{
    if (!scene.lights.empty())
        return {};
    char hash[24];
    std::snprintf(
        hash, sizeof hash, "%016llx", static_cast<unsigned long long>(scene.environment.contentHash()));
    const MaterialInfo& m = scene.material;
    const ShadingModel& model = scene.model;
    std::string key = "facet ground truth, integrator " + std::to_string(kIntegratorVersion) + "\n";
    key += "environment " + std::string(hash) + " rotation " + number(scene.environment.rotationDegrees())
        + " intensity " + number(scene.environment.intensity()) + "\n";
    key += "material base " + number(m.baseColor.r) + " " + number(m.baseColor.g) + " "
        + number(m.baseColor.b) + " metallic " + number(m.metallic) + " roughness "
        + number(m.perceptualRoughness) + " ior " + number(m.ior) + "\n";
    key += std::string("model ") + toString(model.composition) + " " + toString(model.distribution) + " "
        + toString(model.visibility) + " " + toString(model.fresnel) + " " + toString(model.coupling)
        + (model.multiScatter ? " multiscatter" : " singlescatter") + "\n";
    key += "settings " + std::to_string(settings.width) + "x" + std::to_string(settings.height) + " spp "
        + std::to_string(settings.samplesPerPixel) + " seed " + std::to_string(settings.seed) + " lobes "
        + std::to_string(int(settings.lobes)) + " albedo " + std::to_string(settings.albedoTableSize) + "/"
        + std::to_string(settings.albedoTableSamples) + "\n";
    // What else changes the image, written only where it differs from the default so that the
    // entries of the common case keep their keys.
    if (scene.transparentBackground)
        key += "background transparent\n";
    if (scene.unlit)
        key += "unlit\n";
    if (scene.alphaMode != AlphaMode::Opaque)
        key += std::string("alpha ") + toString(scene.alphaMode) + " cutoff " + number(scene.alphaCutoff)
            + " coverage " + number(m.alpha) + "\n";
    if (m.emissive != glm::dvec3(0.0))
        key += "emissive " + number(m.emissive.r) + " " + number(m.emissive.g) + " " + number(m.emissive.b)
            + "\n";
    return key;
}

QString GroundTruthCache::pathFor(const std::string& keyText) const
{
    const QByteArray digest
        = QCryptographicHash::hash(QByteArray::fromStdString(keyText), QCryptographicHash::Sha1).toHex();
    return m_directory + QLatin1Char('/') + QString::fromLatin1(digest) + QStringLiteral(".fgt");
}

std::optional<Image> GroundTruthCache::load(
    const GroundTruthScene& scene, const GroundTruthSettings& settings, std::string* warning) const
{
    const std::string key = keyText(scene, settings);
    if (key.empty())
        return std::nullopt;
    const QString path = pathFor(key);
    QFile file(path);
    if (!file.exists())
        return std::nullopt;
    auto fail = [&](const char* reason) -> std::optional<Image> {
        if (warning)
            *warning = "GroundTruthCache::load: " + path.toStdString() + ": " + reason + "; recomputing it";
        return std::nullopt;
    };
    if (!file.open(QIODevice::ReadOnly))
        return fail("cannot open it");
    QDataStream in(&file);
    in.setByteOrder(QDataStream::LittleEndian);
    in.setFloatingPointPrecision(QDataStream::SinglePrecision);
    char magic[sizeof kMagic];
    quint32 version = 0, width = 0, height = 0, keyLength = 0;
    if (in.readRawData(magic, sizeof magic) != int(sizeof magic)
        || std::memcmp(magic, kMagic, sizeof magic) != 0)
        return fail("not a ground-truth cache file");
    in >> version >> width >> height >> keyLength;
    if (in.status() != QDataStream::Ok || version != kFileVersion)
        return fail("unknown version");
    if (width != quint32(settings.width) || height != quint32(settings.height) || width > kMaxSide
        || height > kMaxSide || keyLength != key.size())
        return fail("header does not match the request");
    QByteArray storedKey(int(keyLength), '\0');
    if (in.readRawData(storedKey.data(), int(keyLength)) != int(keyLength) || storedKey.toStdString() != key)
        return fail("key does not match (a hash collision or a corrupt file)");
    Image image {int(width), int(height)};
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        glm::vec4& p = image.data()[i];
        in >> p.r >> p.g >> p.b >> p.a;
    }
    if (in.status() != QDataStream::Ok)
        return fail("truncated");
    if (!file.atEnd())
        return fail("longer than its header says");
    return image;
}

bool GroundTruthCache::store(const GroundTruthScene& scene, const GroundTruthSettings& settings,
    const Image& image, std::string* error) const
{
    const std::string key = keyText(scene, settings);
    if (key.empty())
        return true; // not cacheable (see keyText); nothing to do is not an error
    const QString path = pathFor(key);
    auto fail = [&](const QString& reason) {
        if (error)
            *error = "GroundTruthCache::store: " + path.toStdString() + ": " + reason.toStdString();
        return false;
    };
    if (!QDir().mkpath(m_directory))
        return fail(QStringLiteral("cannot create the directory"));
    // Encoded in memory, then one checked atomic write (core/support/AtomicFile.h): a full disk leaves
    // no truncated entry.
    QByteArray bytes;
    QDataStream out(&bytes, QIODevice::WriteOnly);
    out.setByteOrder(QDataStream::LittleEndian);
    out.setFloatingPointPrecision(QDataStream::SinglePrecision);
    out.writeRawData(kMagic, sizeof kMagic);
    out << kFileVersion << quint32(image.width()) << quint32(image.height()) << quint32(key.size());
    out.writeRawData(key.data(), int(key.size()));
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
        const glm::vec4& p = image.data()[i];
        out << p.r << p.g << p.b << p.a;
    }
    if (out.status() != QDataStream::Ok)
        return fail(QStringLiteral("encoding the entry failed"));
    std::string reason;
    if (!writeFileAtomically(
            path.toStdString(), std::string_view(bytes.constData(), std::size_t(bytes.size())), &reason))
        return fail(QStringLiteral("cannot write it: ") + QString::fromStdString(reason));
    return true;
}

} // namespace facet
