#include "TextureSetTestMaterial.h"

#include "core/image/ToneMap.h"
#include "core/support/FileSet.h"

#include <QtGlobal>

#include <OpenImageIO/imageio.h>

#include <glm/geometric.hpp>

#include <cstddef>

namespace facet::test {

MapImage uniformMap(int width, int height, const int* values, int channels)
{
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 4; ++c)
                image.at(x, y)[c] = c < channels ? float(values[c]) / 255.0f : 1.0f;
    return MapImage::fromImage(image, channels == 4 ? MapLayout::Rgba : MapLayout::Rgb, MapSampleType::UInt8);
}

TestMaterial::TestMaterial(bool factors)
    : withFactors(factors)
{
    material.name = "Test Mat";
    material.map(MapSlot::BaseColor).path = "base.png";
    material.map(MapSlot::Normal).path = "normal.png";
    for (const MapSlot slot : {MapSlot::Occlusion, MapSlot::Roughness, MapSlot::Metallic})
        material.map(slot).path = "orm.png";
    material.map(MapSlot::Occlusion).channel = MapChannel::R;
    material.map(MapSlot::Roughness).channel = MapChannel::G;
    material.map(MapSlot::Metallic).channel = MapChannel::B;
    material.map(MapSlot::Emissive).path = "emissive.png";
    material.map(MapSlot::Emissive).colorSpace = ColorEncoding::SRGB;
    material.setBaseColor(glm::dvec3(1.0), 1.0);
    material.setFactor(MapSlot::Metallic, 1.0);
    material.setFactor(MapSlot::Roughness, 1.0);
    material.setFactor(MapSlot::Occlusion, 1.0);
    material.setFactor(MapSlot::Normal, 1.0);
    material.map(MapSlot::Emissive).factor = glm::dvec4(1.0);
    material.emissiveStrength = 7.0; // a parameter, never in the texture
    if (factors) {
        material.setBaseColor(glm::dvec3(0.5, 0.25, 1.0), 0.5);
        material.setFactor(MapSlot::Metallic, 0.5);
        material.setFactor(MapSlot::Roughness, 0.75);
        material.setFactor(MapSlot::Occlusion, 0.5); // strength
        material.setFactor(MapSlot::Normal, 2.0); // strength
        material.map(MapSlot::Normal).flipGreen = true;
        material.map(MapSlot::Emissive).factor = glm::dvec4(0.5, 1.0, 0.25, 1.0);
    }
}

MaterialMapImages TestMaterial::images() const
{
    MaterialMapImages result {};
    result[std::size_t(MapSlot::BaseColor)] = &base;
    result[std::size_t(MapSlot::Normal)] = &normal;
    result[std::size_t(MapSlot::Occlusion)] = &packed;
    result[std::size_t(MapSlot::Roughness)] = &packed;
    result[std::size_t(MapSlot::Metallic)] = &packed;
    result[std::size_t(MapSlot::Emissive)] = &emissive;
    return result;
}

double TestMaterial::expected(const QString& source) const
{
    if (source.startsWith(QStringLiteral("1-")))
        return 1.0 - expected(source.mid(2));
    if (source.startsWith(QStringLiteral("const:")))
        return source.mid(6).toDouble();
    const glm::dvec4 baseFactor = material.baseColorFactor();
    const auto srgb = [](int v) { return tonemap::srgbToLinear(v / 255.0); };
    if (source == QStringLiteral("baseColor.r"))
        return baseFactor.r * srgb(kBase[0]);
    if (source == QStringLiteral("baseColor.g"))
        return baseFactor.g * srgb(kBase[1]);
    if (source == QStringLiteral("baseColor.b"))
        return baseFactor.b * srgb(kBase[2]);
    if (source == QStringLiteral("baseColor.a"))
        return baseFactor.a * kBase[3] / 255.0;
    if (source.startsWith(QStringLiteral("normal."))) {
        glm::dvec3 n = glm::dvec3(kNormal[0], kNormal[1], kNormal[2]) / 255.0 * 2.0 - 1.0;
        if (withFactors) {
            n.y = -n.y; // DirectX map read as OpenGL
            n.x *= 2.0;
            n.y *= 2.0;
        }
        n = glm::normalize(n);
        const int axis = source.endsWith(QLatin1Char('x')) ? 0
            : source.endsWith(QLatin1Char('y'))            ? 1
                                                           : 2;
        return n[axis] * 0.5 + 0.5;
    }
    if (source == QStringLiteral("occlusion"))
        return 1.0 + material.occlusionStrength() * (kPacked[0] / 255.0 - 1.0);
    if (source == QStringLiteral("roughness"))
        return material.roughness() * kPacked[1] / 255.0;
    if (source == QStringLiteral("metallic"))
        return material.metallic() * kPacked[2] / 255.0;
    const glm::dvec4 emissiveFactor = material.map(MapSlot::Emissive).factor;
    if (source == QStringLiteral("emissive.r"))
        return emissiveFactor.r * srgb(kEmissive[0]);
    if (source == QStringLiteral("emissive.g"))
        return emissiveFactor.g * srgb(kEmissive[1]);
    if (source == QStringLiteral("emissive.b"))
        return emissiveFactor.b * srgb(kEmissive[2]);
    qFatal("unknown source %s", qPrintable(source));
}

std::optional<ReadBack> readBack(const QString& path)
{
    // Alpha as stored: OIIO would otherwise premultiply the colour by it.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto input = OIIO::ImageInput::open(path.toStdString(), &config);
    if (!input)
        return std::nullopt;
    const OIIO::ImageSpec& spec = input->spec();
    ReadBack r;
    r.width = spec.width;
    r.height = spec.height;
    r.channels = spec.nchannels;
    r.format = spec.format;
    r.colorSpace = spec.get_string_attribute("oiio:ColorSpace");
    r.values.resize(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels));
    if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, r.values.data()))
        return std::nullopt;
    return r;
}

bool writeSet(const TextureSetPlan& plan, const TestMaterial& test, const QString& folder, std::string* error)
{
    FileSet files(folder.toStdString());
    return files.begin(error) && writeTextureSet(plan, test.material, test.images(), files, error)
        && files.commit(error);
}

} // namespace facet::test
