#pragma once
// Small previews made off the GUI thread: material swatches (core/material/MaterialSwatch: a sphere in the
// studio, the preset library's icons; remembered by the material's content), texture maps (the stored
// numbers, clamped; decoded through core/image/MapImageCache, so a map the viewport has loaded or is loading
// is not decoded again, and a map beyond the size budget gets its message) and equirectangular environments
// (box-filtered down, tone-mapped with Khronos PBR Neutral and sRGB-encoded, so an HDR shows as the viewport
// would show it at exposure 0). One worker thread: the machine's cores are shared with the renderer.
//
// request() queues a job; ready() arrives on the GUI thread with the key it was asked for.
// Destroying the loader drops queued jobs and waits for the running one. Texture thumbnails are
// remembered by file, modification time and size: asking again (another material's slots, the
// same file in another slot) answers from memory without decoding the map again, which matters
// once the window has released its decoded copy (ui/viewport/SceneController releaseMapPixels).

#include "core/image/Image.h"
#include "core/image/MapImage.h"
#include "core/material/Material.h"

#include <QHash>
#include <QImage>
#include <QObject>
#include <QSize>
#include <QString>
#include <QThreadPool>

#include <atomic>
#include <memory>
#include <mutex>

namespace facet {

class ThumbnailLoader : public QObject {
    Q_OBJECT
public:
    enum class Kind { Texture, Environment };

    explicit ThumbnailLoader(QObject* parent = nullptr);
    ~ThumbnailLoader() override;

    // `source`: a file path, or for environments anything Environment::fromSpec() accepts
    // ("studio", "sky", "uniform:1"). `size`: the thumbnail's bounding box.
    void request(const QString& key, const QString& source, Kind kind, QSize size);
    // A swatch of `material` (its maps read through core/image/MapImageCache), `size` pixels square;
    // ready() gets it under `key`. The same material at the same size is answered from memory.
    void requestSwatch(const QString& key, const Material& material, int size);
    // Jobs queued or running.
    int pending() const { return m_pending.load(); }

    // The conversions the jobs run (public for tests and for callers that already hold an image).
    static QImage environmentThumbnail(const Image& equirect, QSize size);
    // Linear radiance already at the thumbnail's size, tone-mapped and encoded for display.
    static QImage displayThumbnail(const Image& radiance);
    static QImage textureThumbnail(const MapImage& image, QSize size);

Q_SIGNALS:
    // `image` is null when the source could not be read (`error` says why, naming the file).
    // `sourceSize` is the full image's size; `milliseconds` the time the job took.
    void ready(
        const QString& key, const QImage& image, QSize sourceSize, const QString& error, double milliseconds);

private:
    struct Made {
        QImage image;
        QSize sourceSize;
    };
    // Delivers what was made for `memo` before, if anything was: true then, and ready() follows.
    bool deliverMade(const QString& key, const QString& memo);
    QHash<QString, Made> m_made; // texture thumbnails by file|time|size (GUI thread only)
    QThreadPool m_pool;
    std::shared_ptr<const class SwatchRenderer> m_swatchRenderer; // made by the first swatch job
    std::atomic<bool> m_stopping {false};
    std::atomic<int> m_pending {0};
    std::once_flag m_swatchRendererMade;
};

} // namespace facet
