#include "ui/dialogs/MapInspectorDialog.h"

#include "core/image/MapStatistics.h"
#include "ui/docks/MapSlotWidget.h"

#include <QDialogButtonBox>
#include <QFileInfo>
#include <QGridLayout>
#include <QLabel>
#include <QPainter>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace facet {

namespace {

constexpr int kThumbnailSide = 128;
constexpr QSize kHistogramSize(256, 96);

const char* channelLetter(MapLayout layout, int channel)
{
    switch (layout) {
    case MapLayout::Grey:
        return "Grey";
    case MapLayout::GreyAlpha:
        return channel == 0 ? "Grey" : "A";
    case MapLayout::RedGreen:
        return channel == 0 ? "R" : "G";
    case MapLayout::Rgb:
    case MapLayout::Rgba:
        return channel == 0 ? "R" : channel == 1 ? "G" : channel == 2 ? "B" : "A";
    }
    return "?";
}

const char* sampleTypeName(MapSampleType type)
{
    return type == MapSampleType::UInt8 ? "8-bit" : type == MapSampleType::UInt16 ? "16-bit" : "half float";
}

} // namespace

QImage MapInspectorDialog::histogramImage(const std::array<std::uint64_t, 256>& histogram, QSize size)
{
    QImage image(size, QImage::Format_RGB32);
    image.fill(QColor(32, 32, 32));
    // Heights on a square-root scale: a few dark texels still show beside a large flat area.
    const std::uint64_t largest = *std::max_element(histogram.begin(), histogram.end());
    if (largest == 0)
        return image;
    QPainter painter(&image);
    painter.setPen(QColor(220, 220, 220));
    for (int x = 0; x < size.width(); ++x) {
        const std::size_t bin = std::size_t(x * 256 / size.width());
        const double fraction = std::sqrt(double(histogram[bin]) / double(largest));
        const int height = int(std::lround(fraction * double(size.height())));
        if (height > 0)
            painter.drawLine(x, size.height() - 1, x, size.height() - height);
    }
    return image;
}

QImage MapInspectorDialog::channelThumbnail(const MapImage& image, int channel, int side)
{
    const double scale = std::min(1.0, double(side) / double(std::max(image.width(), image.height())));
    const int width = std::max(1, int(std::lround(image.width() * scale)));
    const int height = std::max(1, int(std::lround(image.height() * scale)));
    QImage thumbnail(width, height, QImage::Format_Grayscale8);
    for (int y = 0; y < height; ++y) {
        uchar* row = thumbnail.scanLine(y);
        // MapImage rows go bottom to top; the thumbnail's top row is the file's.
        const int sourceRow = image.height() - 1 - std::min(image.height() - 1, int(double(y) / scale));
        for (int x = 0; x < width; ++x) {
            const int sourceX = std::min(image.width() - 1, int(double(x) / scale));
            const float value = std::clamp(image.sample(sourceX, sourceRow, channel), 0.0f, 1.0f);
            row[x] = uchar(std::lround(value * 255.0f));
        }
    }
    return thumbnail;
}

MapInspectorDialog::MapInspectorDialog(
    const Material& material, MapSlot slot, std::shared_ptr<const MapImage> image, QWidget* parent)
    : QDialog(parent)
{
    const MaterialMap& map = material.map(slot);
    const QString file = QFileInfo(QString::fromStdString(map.path)).fileName();
    setWindowTitle(tr("Inspect %1").arg(file));
    auto* layout = new QVBoxLayout(this);
    auto* heading = new QLabel(tr("<b>%1</b>: %2 × %3, %4, %5, %6")
                                   .arg(file.toHtmlEscaped())
                                   .arg(image->width())
                                   .arg(image->height())
                                   .arg(QString::fromLatin1(toString(image->layout())))
                                   .arg(QString::fromLatin1(sampleTypeName(image->sampleType())))
                                   .arg(map.colorSpace == ColorEncoding::SRGB ? tr("read as sRGB colour")
                                                                              : tr("read as linear data")),
        this);
    heading->setObjectName(QStringLiteral("mapInspectorHeading"));
    layout->addWidget(heading);
    auto* grid = new QGridLayout;
    const MapStatistics statistics = mapStatistics(*image);
    for (int c = 0; c < int(statistics.channels.size()); ++c) {
        const MapChannelStatistics& channel = statistics.channels[std::size_t(c)];
        QStringList feeds;
        for (MapSlot reader : slotsReadingChannel(material, map.path, image->layout(), c))
            feeds.append(reader == slot ? tr("%1 (this slot)").arg(MapSlotWidget::title(reader).toLower())
                                        : MapSlotWidget::title(reader).toLower());
        const QString caption = tr("%1: %2").arg(QString::fromLatin1(channelLetter(image->layout(), c)),
            feeds.isEmpty() ? tr("not read") : feeds.join(QStringLiteral(", ")));
        const QString summary = tr("min %1 · max %2 · mean %3")
                                    .arg(double(channel.minimum), 0, 'f', 3)
                                    .arg(double(channel.maximum), 0, 'f', 3)
                                    .arg(channel.mean, 0, 'f', 3);
        m_captions.append(caption);
        m_summaries.append(summary);
        auto* thumbnail = new QLabel(this);
        thumbnail->setPixmap(QPixmap::fromImage(channelThumbnail(*image, c, kThumbnailSide)));
        auto* histogram = new QLabel(this);
        histogram->setPixmap(QPixmap::fromImage(histogramImage(channel.histogram, kHistogramSize)));
        histogram->setToolTip(
            tr("Values as stored, 0 to 1 left to right; bar heights on a square-root scale"));
        auto* text = new QLabel(caption + QLatin1Char('\n') + summary, this);
        text->setObjectName(QStringLiteral("mapInspectorChannel%1").arg(c));
        grid->addWidget(thumbnail, c, 0);
        grid->addWidget(histogram, c, 1);
        grid->addWidget(text, c, 2);
    }
    layout->addLayout(grid);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
}

QStringList MapInspectorDialog::channelCaptions() const
{
    return m_captions;
}

QStringList MapInspectorDialog::channelSummaries() const
{
    return m_summaries;
}

} // namespace facet
