#pragma once
// Texture Maps > a slot's Inspect Map… (docs/app.md "Texture Maps"): the map's file decoded and
// shown channel by channel, as Substance 3D Painter's channel view and Marmoset's texture
// inspector do: for each stored channel a grey thumbnail, what it feeds in the current material
// ("G: roughness (this slot)", "B: metallic", "A: not read"), a histogram of its values as stored
// and their smallest, largest and mean value (core/image/MapStatistics.h).

#include "core/image/MapImage.h"
#include "core/material/Material.h"

#include <QDialog>

#include <memory>

class QLabel;

namespace facet {

class MapInspectorDialog : public QDialog {
    Q_OBJECT
public:
    // `image`: the decoded map of `material`'s slot `slot` (its file's path is the slot's).
    MapInspectorDialog(const Material& material, MapSlot slot, std::shared_ptr<const MapImage> image,
        QWidget* parent = nullptr);

    // What each stored channel's row says ("G: roughness (this slot)"), in channel order (tests).
    QStringList channelCaptions() const;
    // "min 0.020 · max 0.980 · mean 0.512", in channel order.
    QStringList channelSummaries() const;
    // A histogram drawn as the dialog shows it (tests read its bars).
    static QImage histogramImage(const std::array<std::uint64_t, 256>& histogram, QSize size);
    // Stored channel `channel` as a grey thumbnail at most `side` pixels wide or tall.
    static QImage channelThumbnail(const MapImage& image, int channel, int side);

private:
    QStringList m_captions;
    QStringList m_summaries;
};

} // namespace facet
