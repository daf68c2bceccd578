#include "ImageFixture.h"

#include <QtGlobal>

#include <OpenImageIO/imageio.h>

#include <cstddef>
#include <memory>

namespace facet::test {

bool writeFixture(const QString& path, int width, int height, int channels, OIIO::TypeDesc fileType,
    const std::vector<float>& values, const char* colorSpace)
{
    Q_ASSERT(values.size() == std::size_t(width * height * channels));
    std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path.toStdString());
    if (!output)
        return false;
    OIIO::ImageSpec spec(width, height, channels, fileType);
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (colorSpace)
        spec.attribute("oiio:ColorSpace", colorSpace);
    if (path.endsWith(QLatin1String(".tif")))
        spec.attribute("compression", path.contains(QLatin1String("zip")) ? "zip" : "none");
    if (path.contains(QLatin1String("tiled")))
        spec.tile_width = spec.tile_height = 16;
    return output->open(path.toStdString(), spec) && output->write_image(OIIO::TypeDesc::FLOAT, values.data())
        && output->close();
}

} // namespace facet::test
