#include "MaterialMapRows.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <OpenImageIO/imageio.h>

#include <glm/geometric.hpp>

namespace facet::test {

bool writePng(const QString& path, int channels, const std::function<glm::dvec4(int, int)>& texel)
{
    std::vector<unsigned char> pixels(std::size_t(kMapTextureSize) * kMapTextureSize * std::size_t(channels));
    for (int y = 0; y < kMapTextureSize; ++y)
        for (int x = 0; x < kMapTextureSize; ++x) {
            const glm::dvec4 value = texel(x, y);
            for (int c = 0; c < channels; ++c)
                pixels[(std::size_t(y) * kMapTextureSize + std::size_t(x)) * std::size_t(channels)
                    + std::size_t(c)]
                    = static_cast<unsigned char>(std::lround(std::clamp(value[c], 0.0, 1.0) * 255.0));
        }
    auto output = OIIO::ImageOutput::create(path.toStdString());
    if (!output)
        return false;
    OIIO::ImageSpec spec(kMapTextureSize, kMapTextureSize, channels, OIIO::TypeDesc::UINT8);
    // The values are unassociated (as PNG stores them): without this OIIO divides colour by alpha.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    return output->open(path.toStdString(), spec) && output->write_image(OIIO::TypeDesc::UINT8, pixels.data())
        && output->close();
}

bool writeDeep(
    const QString& path, int channels, OIIO::TypeDesc type, const std::function<glm::dvec4(int, int)>& texel)
{
    std::vector<float> pixels(std::size_t(kMapTextureSize) * kMapTextureSize * std::size_t(channels));
    for (int y = 0; y < kMapTextureSize; ++y)
        for (int x = 0; x < kMapTextureSize; ++x) {
            const glm::dvec4 value = texel(x, y);
            for (int c = 0; c < channels; ++c)
                pixels[(std::size_t(y) * kMapTextureSize + std::size_t(x)) * std::size_t(channels)
                    + std::size_t(c)]
                    = float(value[c]);
        }
    auto output = OIIO::ImageOutput::create(path.toStdString());
    if (!output)
        return false;
    OIIO::ImageSpec spec(kMapTextureSize, kMapTextureSize, channels, type);
    spec.attribute("oiio:UnassociatedAlpha", 1);
    return output->open(path.toStdString(), spec) && output->write_image(OIIO::TypeDesc::FLOAT, pixels.data())
        && output->close();
}

double wave(int i, double phase)
{
    return std::cos(2.0 * std::numbers::pi * (double(i) + 0.5) / kMapTextureSize + phase);
}

QString file(const QString& folder, const char* name)
{
    return folder + QLatin1Char('/') + QLatin1String(name);
}

void useMap(Material& m, MapSlot slot, const QString& path, MapChannel channel, ColorEncoding colorSpace)
{
    MaterialMap& map = m.map(slot);
    map.path = path.toStdString();
    map.channel = channel;
    map.colorSpace = colorSpace;
}

void useNormal(Material& m, const QString& folder)
{
    useMap(m, MapSlot::Normal, file(folder, "normal.png"), MapChannel::Rgb, ColorEncoding::Linear);
}

namespace {

// The largest difference where a clamped or mirrored edge is minified: the GPU's level 1 edge
// texel averages two texels reaching inward, first order in the texture's slope (measured 0.025
// and 0.027 near the top of the sphere on llvmpipe); the mean bound stays.
constexpr double kBeyondAClampedEdge = 0.04;

// A UV transform that takes the compared pixels (u in [0.07, 0.43], v in [0.2, 0.8]) outside
// [0, 1] at both ends (u' in [-0.22, 1.22], v' in [-0.09, 1.09]), so every wrap mode shows what it
// does, with little minification: beyond a clamped edge a coarser mip level's edge texel is the
// average of a block reaching inward, which the twin (level 0) does not model.
void reachOutside(MaterialMap& map)
{
    map.uv.scale = {4.0, 2.0};
    map.uv.offset = {-0.5, -0.5};
}

void useBaseColor(Material& m, const QString& folder)
{
    useMap(m, MapSlot::BaseColor, file(folder, "basecolor.png"), MapChannel::Rgb, ColorEncoding::SRGB);
}
void useScalar(Material& m, MapSlot slot, const QString& path, MapChannel channel)
{
    useMap(m, slot, path, channel, ColorEncoding::Linear);
}

// Every core slot textured: the maps of all six at once, each from its own unit.
void useAllSix(Material& m, const QString& f)
{
    useMap(m, MapSlot::BaseColor, file(f, "packed.png"), MapChannel::Rgb, ColorEncoding::SRGB);
    useNormal(m, f);
    useScalar(m, MapSlot::Metallic, file(f, "grey.png"), MapChannel::R);
    useScalar(m, MapSlot::Roughness, file(f, "packed.png"), MapChannel::G);
    useScalar(m, MapSlot::Occlusion, file(f, "packed.png"), MapChannel::R);
    useMap(m, MapSlot::Emissive, file(f, "basecolor.png"), MapChannel::Rgb, ColorEncoding::SRGB);
    m.map(MapSlot::Emissive).factor = glm::dvec4(1.0);
}

} // namespace

const std::vector<MapRow>& materialMapRows()
{
    static const std::vector<MapRow> table = {
        {"base-color", [](Material& m, const QString& f) { useBaseColor(m, f); }},
        {"base-color-linear",
            [](Material& m, const QString& f) {
                useBaseColor(m, f);
                m.map(MapSlot::BaseColor).colorSpace = ColorEncoding::Linear;
            }},
        {"base-color-channel-g",
            [](Material& m, const QString& f) {
                useMap(m, MapSlot::BaseColor, file(f, "packed.png"), MapChannel::G, ColorEncoding::SRGB);
            }},
        {"normal", [](Material& m, const QString& f) { useNormal(m, f); }},
        {"normal-strength-0.5",
            [](Material& m, const QString& f) {
                useNormal(m, f);
                m.setFactor(MapSlot::Normal, 0.5);
            }},
        {"normal-strength-2",
            [](Material& m, const QString& f) {
                useNormal(m, f);
                m.setFactor(MapSlot::Normal, 2.0);
            }},
        {"normal-directx",
            [](Material& m, const QString& f) {
                useNormal(m, f);
                m.map(MapSlot::Normal).flipGreen = true;
            }},
        {"metallic",
            [](Material& m, const QString& f) {
                useScalar(m, MapSlot::Metallic, file(f, "grey.png"), MapChannel::R);
            }},
        {"roughness",
            [](Material& m, const QString& f) {
                useScalar(m, MapSlot::Roughness, file(f, "grey.png"), MapChannel::R);
            }},
        {"occlusion",
            [](Material& m, const QString& f) {
                useScalar(m, MapSlot::Occlusion, file(f, "grey.png"), MapChannel::R);
                m.setFactor(MapSlot::Occlusion, 0.7);
            }},
        {"roughness-channel-r",
            [](Material& m, const QString& f) {
                useScalar(m, MapSlot::Roughness, file(f, "packed.png"), MapChannel::R);
            }},
        {"roughness-channel-g",
            [](Material& m, const QString& f) {
                useScalar(m, MapSlot::Roughness, file(f, "packed.png"), MapChannel::G);
            }},
        {"roughness-channel-b",
            [](Material& m, const QString& f) {
                useScalar(m, MapSlot::Roughness, file(f, "packed.png"), MapChannel::B);
            }},
        {"roughness-channel-a",
            [](Material& m, const QString& f) {
                useScalar(m, MapSlot::Roughness, file(f, "packed.png"), MapChannel::A);
            }},
        {"metallic-channel-a",
            [](Material& m, const QString& f) {
                useScalar(m, MapSlot::Metallic, file(f, "packed.png"), MapChannel::A);
            }},
        {"metallic-invert",
            [](Material& m, const QString& f) {
                useScalar(m, MapSlot::Metallic, file(f, "packed.png"), MapChannel::B);
                m.map(MapSlot::Metallic).invert = true;
            }},
        {"roughness-invert",
            [](Material& m, const QString& f) {
                useScalar(m, MapSlot::Roughness, file(f, "packed.png"), MapChannel::A);
                m.map(MapSlot::Roughness).invert = true;
            }},
        {"occlusion-invert",
            [](Material& m, const QString& f) {
                useScalar(m, MapSlot::Occlusion, file(f, "grey.png"), MapChannel::R);
                m.map(MapSlot::Occlusion).invert = true;
            }},
        {"roughness-srgb",
            [](Material& m, const QString& f) {
                useMap(m, MapSlot::Roughness, file(f, "grey.png"), MapChannel::R, ColorEncoding::SRGB);
            }},
        {"orm-packed",
            [](Material& m, const QString& f) {
                useScalar(m, MapSlot::Occlusion, file(f, "packed.png"), MapChannel::R);
                useScalar(m, MapSlot::Roughness, file(f, "packed.png"), MapChannel::G);
                useScalar(m, MapSlot::Metallic, file(f, "packed.png"), MapChannel::B);
            }},
        // One file, but the slots cannot share a fetch (render/ShaderVariant sharedTexelFeatures):
        // another UV transform, another colour space.
        {"packed-apart-uv-and-colour-space",
            [](Material& m, const QString& f) {
                useScalar(m, MapSlot::Metallic, file(f, "packed.png"), MapChannel::B);
                useScalar(m, MapSlot::Roughness, file(f, "packed.png"), MapChannel::G);
                m.map(MapSlot::Roughness).uv.offset = {0.3, 0.1};
                useMap(m, MapSlot::Occlusion, file(f, "packed.png"), MapChannel::R, ColorEncoding::SRGB);
            }},
        // Maps whose factor hides them (not sampled, render/ShaderVariant textureMatters): the
        // GPU without the fetch must still equal the twin, which reads them.
        {"maps-hidden-by-factors",
            [](Material& m, const QString& f) {
                useScalar(m, MapSlot::Metallic, file(f, "grey.png"), MapChannel::R);
                m.setFactor(MapSlot::Metallic, 0.0);
                useScalar(m, MapSlot::Occlusion, file(f, "packed.png"), MapChannel::R);
                m.setFactor(MapSlot::Occlusion, 0.0);
                useNormal(m, f);
                m.setFactor(MapSlot::Normal, 0.0);
                useMap(m, MapSlot::Emissive, file(f, "basecolor.png"), MapChannel::Rgb, ColorEncoding::SRGB);
                m.map(MapSlot::Emissive).factor = glm::dvec4(0.0, 0.0, 0.0, 1.0);
            }},
        {"uv-scale",
            [](Material& m, const QString& f) {
                useBaseColor(m, f);
                m.map(MapSlot::BaseColor).uv.scale = {2.0, 3.0};
            }},
        {"uv-offset",
            [](Material& m, const QString& f) {
                useScalar(m, MapSlot::Roughness, file(f, "grey.png"), MapChannel::R);
                m.map(MapSlot::Roughness).uv.offset = {0.25, -0.1};
            }},
        {"uv-rotation",
            [](Material& m, const QString& f) {
                useNormal(m, f);
                m.map(MapSlot::Normal).uv.rotationDegrees = 30.0;
            }},
        // Sampler (glTF 2.0 3.8.4): each wrap mode beyond [0, 1], a mixed pair, the packed fetch
        // kept apart by samplers that differ, and nearest magnification.
        {"wrap-repeat",
            [](Material& m, const QString& f) {
                useBaseColor(m, f);
                reachOutside(m.map(MapSlot::BaseColor));
            }},
        {"wrap-clamp-to-edge",
            [](Material& m, const QString& f) {
                useBaseColor(m, f);
                reachOutside(m.map(MapSlot::BaseColor));
                m.map(MapSlot::BaseColor).sampler.wrapS = TextureWrap::ClampToEdge;
                m.map(MapSlot::BaseColor).sampler.wrapT = TextureWrap::ClampToEdge;
            },
            kBeyondAClampedEdge},
        {"wrap-mirrored-repeat",
            [](Material& m, const QString& f) {
                useScalar(m, MapSlot::Roughness, file(f, "grey.png"), MapChannel::R);
                reachOutside(m.map(MapSlot::Roughness));
                m.map(MapSlot::Roughness).sampler.wrapS = TextureWrap::MirroredRepeat;
                m.map(MapSlot::Roughness).sampler.wrapT = TextureWrap::MirroredRepeat;
            },
            kBeyondAClampedEdge},
        {"wrap-clamp-u-mirror-v",
            [](Material& m, const QString& f) {
                useNormal(m, f);
                reachOutside(m.map(MapSlot::Normal));
                m.map(MapSlot::Normal).sampler.wrapS = TextureWrap::ClampToEdge;
                m.map(MapSlot::Normal).sampler.wrapT = TextureWrap::MirroredRepeat;
            }},
        {"packed-apart-by-sampler",
            [](Material& m, const QString& f) {
                useScalar(m, MapSlot::Metallic, file(f, "packed.png"), MapChannel::B);
                useScalar(m, MapSlot::Roughness, file(f, "packed.png"), MapChannel::G);
                useScalar(m, MapSlot::Occlusion, file(f, "packed.png"), MapChannel::R);
                for (MapSlot slot : {MapSlot::Metallic, MapSlot::Roughness, MapSlot::Occlusion})
                    reachOutside(m.map(slot));
                // Each along the axis its channel varies in (G with the row, R with the column).
                m.map(MapSlot::Roughness).sampler.wrapT = TextureWrap::ClampToEdge;
                m.map(MapSlot::Occlusion).sampler.wrapS = TextureWrap::MirroredRepeat;
            },
            kBeyondAClampedEdge},
        {"mag-nearest",
            [](Material& m, const QString& f) {
                useBaseColor(m, f);
                m.map(MapSlot::BaseColor).uv.scale = {0.25, 0.25};
                m.map(MapSlot::BaseColor).sampler.magFilter = TextureFilter::Nearest;
            },
            0.06},
        // The sphere has one UV set: a map on set 1 reads set 0 (HAS_TEXCOORD_1 stays off).
        {"texcoord-1-on-a-mesh-without-it",
            [](Material& m, const QString& f) {
                useBaseColor(m, f);
                m.map(MapSlot::BaseColor).texCoord = 1;
            }},
        {"emissive",
            [](Material& m, const QString& f) {
                useMap(m, MapSlot::Emissive, file(f, "basecolor.png"), MapChannel::Rgb, ColorEncoding::SRGB);
                m.map(MapSlot::Emissive).factor = glm::dvec4(1.0, 0.5, 0.25, 1.0);
                m.emissiveStrength = 2.0;
            }},
        {"emissive-factor-only",
            [](Material& m, const QString&) {
                m.map(MapSlot::Emissive).factor = glm::dvec4(0.2, 0.4, 0.6, 1.0);
                m.emissiveStrength = 3.0;
            }},
        {"base-color-alpha",
            [](Material& m, const QString& f) {
                useMap(m, MapSlot::BaseColor, file(f, "packed.png"), MapChannel::Rgb, ColorEncoding::SRGB);
                m.map(MapSlot::BaseColor).factor.a = 0.8;
            }},
        // Each kind of file in its own format (render/TextureCache: GL_R8 and GL_RG8 swizzled,
        // GL_SRGB8 expanded from grey, GL_RGB16, 16-bit sRGB decoded to half, GL_RGBA16F).
        {"grey-8bit-base-color-srgb",
            [](Material& m, const QString& f) {
                useMap(m, MapSlot::BaseColor, file(f, "grey.png"), MapChannel::Rgb, ColorEncoding::SRGB);
            }},
        {"grey-alpha-8bit-base-color",
            [](Material& m, const QString& f) {
                useMap(m, MapSlot::BaseColor, file(f, "greyalpha.png"), MapChannel::Rgb, ColorEncoding::SRGB);
            }},
        {"grey-alpha-8bit-roughness-a",
            [](Material& m, const QString& f) {
                useScalar(m, MapSlot::Roughness, file(f, "greyalpha.png"), MapChannel::A);
                useScalar(m, MapSlot::Metallic, file(f, "greyalpha.png"), MapChannel::G);
            }},
        {"normal-16bit-png",
            [](Material& m, const QString& f) {
                useMap(m, MapSlot::Normal, file(f, "normal16.png"), MapChannel::Rgb, ColorEncoding::Linear);
            }},
        {"base-color-16bit-png-srgb",
            [](Material& m, const QString& f) {
                useMap(
                    m, MapSlot::BaseColor, file(f, "basecolor16.png"), MapChannel::Rgb, ColorEncoding::SRGB);
            }},
        {"float-exr-packed",
            [](Material& m, const QString& f) {
                useScalar(m, MapSlot::Roughness, file(f, "packed.exr"), MapChannel::G);
                useScalar(m, MapSlot::Occlusion, file(f, "packed.exr"), MapChannel::A);
                useMap(m, MapSlot::BaseColor, file(f, "packed.exr"), MapChannel::Rgb, ColorEncoding::Linear);
            }},
        {"all-five",
            [](Material& m, const QString& f) {
                useBaseColor(m, f);
                useNormal(m, f);
                useScalar(m, MapSlot::Metallic, file(f, "grey.png"), MapChannel::R);
                useScalar(m, MapSlot::Roughness, file(f, "packed.png"), MapChannel::G);
                useScalar(m, MapSlot::Occlusion, file(f, "packed.png"), MapChannel::R);
            }},
        {"all-six", useAllSix},
        // KHR_materials_clearcoat's maps (strength R and roughness G by the extension's packing).
        {"clearcoat",
            [](Material& m, const QString& f) {
                m.setClearcoat(0.8, 0.3);
                useScalar(m, MapSlot::Clearcoat, file(f, "grey.png"), MapChannel::R);
            }},
        {"clearcoat-roughness",
            [](Material& m, const QString& f) {
                m.setClearcoat(1.0, 0.9);
                useScalar(m, MapSlot::ClearcoatRoughness, file(f, "packed.png"), MapChannel::G);
            }},
        {"clearcoat-packed-strength-and-roughness",
            [](Material& m, const QString& f) {
                m.setClearcoat(1.0, 1.0);
                useScalar(m, MapSlot::Clearcoat, file(f, "packed.png"), MapChannel::R);
                useScalar(m, MapSlot::ClearcoatRoughness, file(f, "packed.png"), MapChannel::G);
            }},
        {"clearcoat-roughness-invert",
            [](Material& m, const QString& f) {
                m.setClearcoat(1.0, 1.0);
                useScalar(m, MapSlot::ClearcoatRoughness, file(f, "packed.png"), MapChannel::A);
                m.map(MapSlot::ClearcoatRoughness).invert = true;
            }},
        {"clearcoat-normal",
            [](Material& m, const QString& f) {
                m.setClearcoat(1.0, 0.2);
                useMap(m, MapSlot::ClearcoatNormal, file(f, "normal.png"), MapChannel::Rgb,
                    ColorEncoding::Linear);
            }},
        {"clearcoat-normal-directx-strength-0.5-rotated",
            [](Material& m, const QString& f) {
                m.setClearcoat(1.0, 0.2);
                useMap(m, MapSlot::ClearcoatNormal, file(f, "normal.png"), MapChannel::Rgb,
                    ColorEncoding::Linear);
                m.map(MapSlot::ClearcoatNormal).flipGreen = true;
                m.map(MapSlot::ClearcoatNormal).uv.rotationDegrees = 60.0;
                m.setFactor(MapSlot::ClearcoatNormal, 0.5);
            }},
        // The coat over a base normal map: each its own normal (the base's does not tilt the coat).
        {"clearcoat-over-base-normal",
            [](Material& m, const QString& f) {
                useNormal(m, f);
                m.setClearcoat(0.6, 0.4);
            }},
        // Coat maps while the coat is off: nothing of them is sampled, and nothing shows.
        {"clearcoat-maps-while-off",
            [](Material& m, const QString& f) {
                useScalar(m, MapSlot::Clearcoat, file(f, "grey.png"), MapChannel::R);
                useScalar(m, MapSlot::ClearcoatRoughness, file(f, "packed.png"), MapChannel::G);
                useMap(m, MapSlot::ClearcoatNormal, file(f, "normal.png"), MapChannel::Rgb,
                    ColorEncoding::Linear);
            }},
        // KHR_materials_sheen's maps: the colour (sRGB RGB), the roughness (A), both from one RGBA
        // texture (one fetch), and both while the sheen is off.
        {"sheen-color",
            [](Material& m, const QString& f) {
                m.setSheen(glm::dvec3(1.0, 0.8, 0.6), 0.5);
                useMap(
                    m, MapSlot::SheenColor, file(f, "basecolor.png"), MapChannel::Rgb, ColorEncoding::SRGB);
            }},
        {"sheen-roughness",
            [](Material& m, const QString& f) {
                m.setSheen(glm::dvec3(0.5), 0.9);
                useScalar(m, MapSlot::SheenRoughness, file(f, "packed.png"), MapChannel::A);
            }},
        {"sheen-packed-rgba",
            [](Material& m, const QString& f) {
                m.setSheen(glm::dvec3(1.0), 1.0);
                useMap(m, MapSlot::SheenColor, file(f, "packed.png"), MapChannel::Rgb, ColorEncoding::SRGB);
                useScalar(m, MapSlot::SheenRoughness, file(f, "packed.png"), MapChannel::A);
            }},
        {"sheen-maps-while-off",
            [](Material& m, const QString& f) {
                useMap(
                    m, MapSlot::SheenColor, file(f, "basecolor.png"), MapChannel::Rgb, ColorEncoding::SRGB);
                useScalar(m, MapSlot::SheenRoughness, file(f, "packed.png"), MapChannel::A);
            }},
        // KHR_materials_specular's maps: the colour (sRGB RGB, its factor above 1), the strength
        // (A), both from one RGBA texture (one fetch), and a colour map under strength 0 (not read).
        {"specular-color",
            [](Material& m, const QString& f) {
                m.setSpecular(1.0, glm::dvec3(2.0, 1.0, 0.5));
                useMap(m, MapSlot::SpecularColor, file(f, "basecolor.png"), MapChannel::Rgb,
                    ColorEncoding::SRGB);
            }},
        {"specular-strength",
            [](Material& m, const QString& f) {
                m.setSpecular(0.8, glm::dvec3(1.0));
                useScalar(m, MapSlot::Specular, file(f, "packed.png"), MapChannel::A);
            }},
        {"specular-packed-rgba",
            [](Material& m, const QString& f) {
                useMap(
                    m, MapSlot::SpecularColor, file(f, "packed.png"), MapChannel::Rgb, ColorEncoding::SRGB);
                useScalar(m, MapSlot::Specular, file(f, "packed.png"), MapChannel::A);
            }},
        {"specular-color-map-under-strength-0",
            [](Material& m, const QString& f) {
                m.setSpecular(0.0, glm::dvec3(1.0));
                useMap(m, MapSlot::SpecularColor, file(f, "basecolor.png"), MapChannel::Rgb,
                    ColorEncoding::SRGB);
            }},
        // KHR_materials_anisotropy: the factor and rotation alone, and its texture (linear RGB:
        // direction RG, strength B) turned by the rotation; the direction in world space through
        // the reference sphere's tangent frame.
        {"anisotropy-rotation", [](Material& m, const QString&) { m.setAnisotropy(0.7, 50.0); }},
        {"anisotropy-map",
            [](Material& m, const QString& f) {
                m.setAnisotropy(0.9, -25.0);
                useMap(
                    m, MapSlot::Anisotropy, file(f, "direction.png"), MapChannel::Rgb, ColorEncoding::Linear);
            }},
        // KHR_materials_iridescence: the strength (R) and thickness (G) from one texture (one
        // fetch), and a thickness map alone whose minimum lies above the maximum (it runs the other
        // way).
        {"iridescence-packed",
            [](Material& m, const QString& f) {
                m.setIridescence(1.0, 1.3, 100.0, 800.0);
                useScalar(m, MapSlot::Iridescence, file(f, "packed.png"), MapChannel::R);
                useScalar(m, MapSlot::IridescenceThickness, file(f, "packed.png"), MapChannel::G);
            }},
        {"iridescence-thickness-reversed",
            [](Material& m, const QString& f) {
                m.setIridescence(0.6, 1.8, 900.0, 300.0);
                useScalar(m, MapSlot::IridescenceThickness, file(f, "grey.png"), MapChannel::G);
            }},
        {"all-nine",
            [](Material& m, const QString& f) {
                useAllSix(m, f);
                m.setClearcoat(0.9, 0.7);
                useScalar(m, MapSlot::Clearcoat, file(f, "grey.png"), MapChannel::R);
                useScalar(m, MapSlot::ClearcoatRoughness, file(f, "packed.png"), MapChannel::B);
                useMap(m, MapSlot::ClearcoatNormal, file(f, "normal.png"), MapChannel::Rgb,
                    ColorEncoding::Linear);
                m.map(MapSlot::ClearcoatNormal).uv.scale = {2.0, 1.0};
            }},
        {"all-five-transformed",
            [](Material& m, const QString& f) {
                useBaseColor(m, f);
                useNormal(m, f);
                useScalar(m, MapSlot::Metallic, file(f, "grey.png"), MapChannel::R);
                useScalar(m, MapSlot::Roughness, file(f, "packed.png"), MapChannel::G);
                useScalar(m, MapSlot::Occlusion, file(f, "packed.png"), MapChannel::R);
                m.map(MapSlot::BaseColor).uv.scale = {2.0, 2.0};
                m.map(MapSlot::Normal).uv.rotationDegrees = -45.0;
                m.map(MapSlot::Metallic).uv.offset = {0.5, 0.5};
                m.map(MapSlot::Roughness).uv = UvTransform {{1.5, 0.5}, {0.1, 0.2}, 90.0};
                m.map(MapSlot::Occlusion).invert = true;
                m.map(MapSlot::Normal).flipGreen = true;
                m.setFactor(MapSlot::Normal, 1.5);
            }},
    };
    return table;
}

} // namespace facet::test
