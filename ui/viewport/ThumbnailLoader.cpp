#include "ui/viewport/ThumbnailLoader.h"

#include "core/material/MaterialSwatch.h"

#include "core/gltf/GltfImport.h"
#include "core/ibl/Environment.h"
#include "core/image/MapImageCache.h"
#include "core/image/ToneMap.h"
#include "core/project/AssetLibrary.h"
#include "core/project/Project.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonDocument>

#include <algorithm>
#include <cmath>

namespace facet {

namespace {

constexpr int kRemembered = 256;

QSize fitted(QSize source, QSize box)
{
    return source.scaled(box, Qt::KeepAspectRatio).expandedTo(QSize(1, 1));
}

int toByte(double v)
{
    return int(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

} // namespace

ThumbnailLoader::ThumbnailLoader(QObject* parent)
    : QObject(parent)
{
    m_pool.setMaxThreadCount(1);
}

ThumbnailLoader::~ThumbnailLoader()
{
    m_stopping = true;
    m_pool.clear();
    m_pool.waitForDone();
}

bool ThumbnailLoader::deliverMade(const QString& key, const QString& memo)
{
    const auto found = m_made.constFind(memo);
    if (found == m_made.constEnd())
        return false;
    // Queued like a worker's result: the caller sees ready() after request() returns, either way.
    const Made made = *found;
    QMetaObject::invokeMethod(
        this,
        [this, key, made] {
            --m_pending;
            Q_EMIT ready(key, made.image, made.sourceSize, QString(), 0.0);
        },
        Qt::QueuedConnection);
    return true;
}

void ThumbnailLoader::request(const QString& key, const QString& source, Kind kind, QSize size)
{
    ++m_pending;
    QString memo;
    if (kind == Kind::Texture) {
        const QFileInfo file(QString::fromStdString(fileOfImagePath(source.toStdString())));
        memo = source + u'|' + QString::number(file.lastModified().toMSecsSinceEpoch()) + u'|'
            + QString::number(size.width()) + u'x' + QString::number(size.height());
        if (deliverMade(key, memo))
            return;
    }
    m_pool.start([this, key, source, kind, size, memo] {
        QElapsedTimer clock;
        clock.start();
        QImage thumbnail;
        QSize sourceSize;
        std::string error;
        if (!m_stopping) {
            if (kind == Kind::Environment) {
                const std::string spec = source.toStdString();
                std::optional<Environment> environment;
                if (const auto builtin = Environment::builtinFromName(spec))
                    environment = Environment::builtin(*builtin, 256); // procedural: make it small
                else if (!Environment::namesFile(spec))
                    environment = Environment::fromSpec(spec, &error);
                if (environment) {
                    sourceSize = QSize(environment->image().width(), environment->image().height());
                    thumbnail = environmentThumbnail(environment->image(), size);
                } else if (Environment::namesFile(spec)) {
                    // A file: read a band at a time into the thumbnail's box filter, never whole
                    // (an 8K HDRI is 512 MiB as floats; 18 library thumbnails held 67 MB at once).
                    int width = 0;
                    int height = 0;
                    const auto sizeFor = [size](int w, int h) {
                        const QSize fit = fitted(QSize(w, h), size);
                        return std::pair<int, int>(fit.width(), fit.height());
                    };
                    const std::optional<std::string> file
                        = AssetLibrary::fileForSpec(spec, "Environment::fromSpec", &error);
                    if (file)
                        if (const auto filtered
                            = Image::loadBoxFiltered(*file, true, sizeFor, &error, &width, &height)) {
                            sourceSize = QSize(width, height);
                            thumbnail = displayThumbnail(*filtered);
                        }
                }
            } else if (const std::shared_ptr<const MapImage> image
                = MapImageCache::shared().load(source.toStdString(), &error)) {
                sourceSize = QSize(image->width(), image->height());
                thumbnail = textureThumbnail(*image, size);
            }
        }
        const double ms = double(clock.nsecsElapsed()) / 1e6;
        const QString message = QString::fromStdString(error);
        QMetaObject::invokeMethod(
            this,
            [this, key, thumbnail, sourceSize, message, ms, memo] {
                --m_pending;
                if (!memo.isEmpty() && !thumbnail.isNull()) {
                    if (m_made.size() >= kRemembered)
                        m_made.clear(); // 64 x 64 each: a few MiB at most
                    m_made.insert(memo, Made {thumbnail, sourceSize});
                }
                Q_EMIT ready(key, thumbnail, sourceSize, message, ms);
            },
            Qt::QueuedConnection);
    });
}

void ThumbnailLoader::requestSwatch(const QString& key, const Material& material, int size)
{
    ++m_pending;
    const QString memo = QStringLiteral("swatch|%1|").arg(size)
        + QString::fromUtf8(
            QJsonDocument(materialToJson(material, std::string())).toJson(QJsonDocument::Compact));
    if (deliverMade(key, memo))
        return;
    m_pool.start([this, key, material, size, memo] {
        QElapsedTimer clock;
        clock.start();
        QImage swatch;
        std::string error;
        if (!m_stopping) {
            std::call_once(
                m_swatchRendererMade, [this] { m_swatchRenderer = std::make_shared<SwatchRenderer>(); });
            // The material's maps, decoded once for the whole process (a packaged preset's files).
            std::vector<std::shared_ptr<const MapImage>> keep;
            MaterialMapImages images {};
            for (const MapSlot slot : kAllMapSlots) {
                if (!material.map(slot).hasTexture())
                    continue;
                std::string problem;
                if (std::shared_ptr<const MapImage> image
                    = MapImageCache::shared().load(material.map(slot).path, &problem)) {
                    images[std::size_t(slot)] = image.get();
                    keep.push_back(std::move(image));
                } else if (error.empty()) {
                    error = problem; // the swatch is drawn without that map
                }
            }
            const Image rendered = m_swatchRenderer->render(material, images, size);
            swatch = QImage(size, size, QImage::Format_RGBA8888);
            for (int y = 0; y < size; ++y)
                for (int x = 0; x < size; ++x) {
                    const glm::vec4& p = rendered.at(x, y);
                    swatch.setPixel(x, y, qRgba(toByte(p.r), toByte(p.g), toByte(p.b), toByte(p.a)));
                }
        }
        const double ms = double(clock.nsecsElapsed()) / 1e6;
        const QString message = QString::fromStdString(error);
        QMetaObject::invokeMethod(
            this,
            [this, key, swatch, message, ms, memo, size] {
                --m_pending;
                if (!swatch.isNull()) {
                    if (m_made.size() >= kRemembered)
                        m_made.clear();
                    m_made.insert(memo, Made {swatch, QSize(size, size)});
                }
                Q_EMIT ready(key, swatch, QSize(size, size), message, ms);
            },
            Qt::QueuedConnection);
    });
}

QImage ThumbnailLoader::environmentThumbnail(const Image& equirect, QSize size)
{
    if (equirect.isEmpty())
        return {};
    const QSize target = fitted(QSize(equirect.width(), equirect.height()), size);
    return displayThumbnail(equirect.boxFiltered(target.width(), target.height()));
}

QImage ThumbnailLoader::displayThumbnail(const Image& radiance)
{
    const QSize target(radiance.width(), radiance.height());
    QImage image(target, QImage::Format_RGB32);
    for (int y = 0; y < target.height(); ++y) {
        auto* line = reinterpret_cast<QRgb*>(image.scanLine(y));
        for (int x = 0; x < target.width(); ++x) {
            const glm::vec4& p = radiance.at(x, y);
            const glm::dvec3 display = tonemap::displayTransform(
                glm::dvec3(p.r, p.g, p.b), 0.0, ToneMapper::KhronosNeutral, DisplayEncoding::SRGB, 2.2);
            line[x] = qRgb(toByte(display.r), toByte(display.g), toByte(display.b));
        }
    }
    return image;
}

QImage ThumbnailLoader::textureThumbnail(const MapImage& source, QSize size)
{
    if (source.isEmpty())
        return {};
    const QSize target = fitted(QSize(source.width(), source.height()), size);
    QImage image(target, QImage::Format_RGB32);
    for (int y = 0; y < target.height(); ++y) {
        // A box filter over the texels under the pixel; MapImage's row 0 is the bottom.
        const int y0 = y * source.height() / target.height();
        const int y1 = std::max(y0 + 1, (y + 1) * source.height() / target.height());
        auto* line = reinterpret_cast<QRgb*>(image.scanLine(y));
        for (int x = 0; x < target.width(); ++x) {
            const int x0 = x * source.width() / target.width();
            const int x1 = std::max(x0 + 1, (x + 1) * source.width() / target.width());
            glm::dvec4 sum(0.0);
            for (int sy = y0; sy < y1; ++sy)
                for (int sx = x0; sx < x1; ++sx)
                    sum += glm::dvec4(source.texel(sx, source.height() - 1 - sy));
            // The stored numbers as they are: sRGB colour maps look as painted, data maps (normal,
            // roughness) show their values, as image viewers show them.
            const glm::dvec4 p = sum / double((x1 - x0) * (y1 - y0));
            line[x] = qRgb(toByte(p.r), toByte(p.g), toByte(p.b));
        }
    }
    return image;
}

} // namespace facet
