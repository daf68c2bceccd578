#include "core/shading/MaterialInputs.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "core/image/ToneMap.h"
#include "core/shading/Anisotropy.h"

namespace facet {

double pickChannel(const glm::dvec4& texel, MapChannel channel)
{
    switch (channel) {
    case MapChannel::G:
        return texel.g;
    case MapChannel::B:
        return texel.b;
    case MapChannel::A:
        return texel.a;
    case MapChannel::R:
    case MapChannel::Rgb:
        break;
    }
    return texel.r;
}

double scalarMapValue(const MaterialMap& map, const glm::dvec4& texel)
{
    const double value = pickChannel(texel, map.channel);
    return map.invert ? 1.0 - value : value;
}

std::optional<double> smallestScalarMapValue(const MaterialMap& map, const MapImage& image)
{
    const int component = map.channel == MapChannel::G ? 1
        : map.channel == MapChannel::B                 ? 2
        : map.channel == MapChannel::A                 ? 3
                                                       : 0;
    const std::optional<glm::vec2> range = image.texelRange(component);
    if (!range)
        return std::nullopt;
    // The colour decoding is monotonic (and alpha is never decoded): the ends map to the ends.
    const bool decode = map.colorSpace == ColorEncoding::SRGB && component < 3;
    const auto linear = [decode](double v) { return decode ? tonemap::srgbToLinear(v) : v; };
    return map.invert ? 1.0 - linear(range->y) : linear(range->x);
}

namespace {

// The decoded, scaled tangent-space normal before normalisation (GLSL shadingNormal's tn).
glm::dvec3 scaledTangentNormal(const glm::dvec4& normalTexel, double strength, bool flipGreen)
{
    glm::dvec3 tn = glm::dvec3(normalTexel) * 2.0 - 1.0;
    if (flipGreen)
        tn.y = -tn.y;
    tn.x *= strength;
    tn.y *= strength;
    return tn;
}

// The surface's tangent and bitangent: the interpolated tangent made unit and perpendicular to ng
// (Gram-Schmidt), b = cross(ng, t) times the handedness; false where the tangent is along ng.
bool tangentFrame(const glm::dvec3& ng, const glm::dvec4& tangent, glm::dvec3* t, glm::dvec3* b)
{
    const glm::dvec3 inPlane = glm::dvec3(tangent) - ng * glm::dot(ng, glm::dvec3(tangent));
    const double length = glm::length(inPlane);
    if (length < 1e-8)
        return false;
    *t = inPlane / length;
    *b = glm::cross(ng, *t) * (tangent.w < 0.0 ? -1.0 : 1.0);
    return true;
}

} // namespace

glm::dvec3 tangentSpaceNormal(const glm::dvec4& normalTexel, double strength, bool flipGreen)
{
    const glm::dvec3 tn = scaledTangentNormal(normalTexel, strength, flipGreen);
    const double length = glm::length(tn);
    return length > 1e-8 ? tn / length : glm::dvec3(0.0, 0.0, 1.0);
}

glm::dvec3 shadingNormal(const glm::dvec3& ng, const glm::dvec4& tangent, const glm::dvec4& normalTexel,
    double strength, bool flipGreen)
{
    glm::dvec3 t;
    glm::dvec3 b;
    if (!tangentFrame(ng, tangent, &t, &b))
        return ng;
    const glm::dvec3 tn = scaledTangentNormal(normalTexel, strength, flipGreen);
    const glm::dvec3 n = t * tn.x + b * tn.y + ng * tn.z;
    const double nLength = glm::length(n);
    return nLength > 1e-8 ? n / nLength : ng;
}

glm::dvec3 surfaceAnisotropyDirection(
    const glm::dvec3& ng, const glm::dvec4& tangent, const glm::dvec2& tangentDirection)
{
    glm::dvec3 t;
    glm::dvec3 b;
    if (!tangentFrame(ng, tangent, &t, &b))
        return glm::dvec3(0.0);
    const glm::dvec3 d = t * tangentDirection.x + b * tangentDirection.y;
    const double length = glm::length(d);
    return length > 1e-8 ? d / length : glm::dvec3(0.0);
}

glm::dvec4 texelValue(const MapImage& image, int x, int rowFromBottom, ColorEncoding colorSpace)
{
    const glm::dvec4 stored(image.texel(x, rowFromBottom));
    if (colorSpace != ColorEncoding::SRGB)
        return stored;
    glm::dvec4 linear = stored;
    if (image.sampleType() == MapSampleType::UInt8) {
        // GL_SRGB8(_ALPHA8): the 8-bit value decoded by the sampler (alpha is linear). The 256
        // decoded values are tabulated (tonemap::srgbToLinear, the same numbers): a texture-set
        // export reads millions of texels.
        static const std::array<double, 256> kDecoded = [] {
            std::array<double, 256> table {};
            for (int i = 0; i < 256; ++i)
                table[std::size_t(i)] = tonemap::srgbToLinear(double(float(i) / 255.0f));
            return table;
        }();
        for (int c = 0; c < 3; ++c)
            linear[c] = kDecoded[std::size_t(std::lround(stored[c] * 255.0))];
        return linear;
    }
    // 16-bit and half maps are decoded on upload into half floats, alpha included as a half.
    for (int c = 0; c < 3; ++c)
        linear[c] = MapImage::fromHalf(MapImage::linearHalfFromSrgb(float(stored[c])));
    linear.a = MapImage::fromHalf(MapImage::toHalf(float(stored.a)));
    return linear;
}

namespace {

// The texel index that integer texel coordinate `t` (a whole number, any magnitude) reads under
// `wrap`: OpenGL 4.6, section 8.14.2, table 8.20. In double so that a coordinate far outside the
// image (a UV scale of 10^6) wraps instead of overflowing an int.
int wrapTexel(double t, int size, TextureWrap wrap)
{
    const double n = double(size);
    switch (wrap) {
    case TextureWrap::ClampToEdge:
        return int(std::clamp(t, 0.0, n - 1.0));
    case TextureWrap::MirroredRepeat: {
        double m = std::fmod(t, 2.0 * n);
        if (m < 0.0)
            m += 2.0 * n;
        return int(m < n ? m : 2.0 * n - 1.0 - m);
    }
    case TextureWrap::Repeat:
        break;
    }
    double r = std::fmod(t, n);
    if (r < 0.0)
        r += n;
    return int(r);
}

} // namespace

glm::dvec4 sampleTexture(
    const MapImage& image, ColorEncoding colorSpace, const glm::dvec2& uv, const TextureSampler& sampler)
{
    if (image.isEmpty())
        return glm::dvec4(0.0, 0.0, 0.0, 1.0);
    const int width = image.width();
    const int height = image.height();
    const auto at = [&](double tx, double ty) {
        return texelValue(
            image, wrapTexel(tx, width, sampler.wrapS), wrapTexel(ty, height, sampler.wrapT), colorSpace);
    };
    // NEAREST: the texel the point falls in (t = 0 is the bottom row, MapImage's row 0).
    if (sampler.magFilter == TextureFilter::Nearest) {
        const glm::ivec2 texel = texelAt(image, uv, sampler);
        return texelValue(image, texel.x, texel.y, colorSpace);
    }
    // LINEAR: texel space with centres at integers.
    const double x = uv.x * width - 0.5;
    const double y = uv.y * height - 0.5;
    const double x0 = std::floor(x);
    const double y0 = std::floor(y);
    const double fx = x - x0;
    const double fy = y - y0;
    // At a texel centre the bilinear weights are (1, 0, 0, 0): the texel itself, exactly (a
    // texture-set export of a map at its own size reads only centres).
    if (fx == 0.0 && fy == 0.0)
        return at(x0, y0);
    const glm::dvec4 bottom = glm::mix(at(x0, y0), at(x0 + 1.0, y0), fx);
    const glm::dvec4 top = glm::mix(at(x0, y0 + 1.0), at(x0 + 1.0, y0 + 1.0), fx);
    return glm::mix(bottom, top, fy);
}

glm::ivec2 texelAt(const MapImage& image, const glm::dvec2& uv, const TextureSampler& sampler)
{
    if (image.isEmpty())
        return glm::ivec2(0);
    return glm::ivec2(wrapTexel(std::floor(uv.x * image.width()), image.width(), sampler.wrapS),
        wrapTexel(std::floor(uv.y * image.height()), image.height(), sampler.wrapT));
}

glm::dvec4 sampleMap(const MaterialMap& map, const MapImage& image, const TexCoords& uvs)
{
    return sampleTexture(
        image, map.colorSpace, map.uv.apply(uvs[std::size_t(std::clamp(map.texCoord, 0, 1))]), map.sampler);
}

MaterialInfo materialInputs(const Material& material, const MaterialMapImages& images, const glm::dvec2& uv,
    const glm::dvec4& vertexColor)
{
    return materialInputs(material, images, TexCoords {uv, uv}, vertexColor);
}

MaterialInfo materialInputs(const Material& material, const MaterialMapImages& images, const TexCoords& uvs,
    const glm::dvec4& vertexColor)
{
    const auto read = [&](MapSlot slot) -> std::optional<glm::dvec4> {
        const MapImage* image = images[std::size_t(slot)];
        const MaterialMap& map = material.map(slot);
        if (!image || image->isEmpty() || !map.hasTexture())
            return std::nullopt;
        return sampleMap(map, *image, uvs);
    };

    MaterialInfo m;
    m.baseColor = glm::dvec3(material.baseColorFactor());
    m.alpha = material.baseColorFactor().a;
    if (const auto base = read(MapSlot::BaseColor)) {
        const MapChannel channel = material.map(MapSlot::BaseColor).channel;
        m.baseColor
            *= channel == MapChannel::Rgb ? glm::dvec3(*base) : glm::dvec3(pickChannel(*base, channel));
        // A single-channel pick is a greyscale colour without coverage of its own.
        if (channel == MapChannel::Rgb)
            m.alpha *= base->a;
    }
    m.baseColor *= glm::dvec3(vertexColor);
    m.alpha *= vertexColor.a;
    m.emissive = material.emissive();
    if (const auto emissive = read(MapSlot::Emissive))
        m.emissive *= glm::dvec3(*emissive);
    m.metallic = material.metallic();
    if (const auto texel = read(MapSlot::Metallic))
        m.metallic *= scalarMapValue(material.map(MapSlot::Metallic), *texel);
    m.perceptualRoughness = material.roughness();
    if (const auto texel = read(MapSlot::Roughness))
        m.perceptualRoughness *= scalarMapValue(material.map(MapSlot::Roughness), *texel);
    m.occlusion = 1.0;
    if (const auto texel = read(MapSlot::Occlusion))
        // glTF occlusionTexture.strength: mix(1, ao, strength).
        m.occlusion = 1.0
            + material.occlusionStrength() * (scalarMapValue(material.map(MapSlot::Occlusion), *texel) - 1.0);
    // Reflectances and occlusion are fractions: a float map beyond [0, 1] must not make light from
    // nothing (issue 29). Emission is radiance and stays unbounded above.
    m.baseColor = glm::clamp(m.baseColor, glm::dvec3(0.0), glm::dvec3(1.0));
    m.emissive = glm::max(m.emissive, glm::dvec3(0.0));
    m.occlusion = std::clamp(m.occlusion, 0.0, 1.0);
    m.alpha = std::clamp(m.alpha, 0.0, 1.0);
    m.metallic = std::clamp(m.metallic, 0.0, 1.0);
    m.perceptualRoughness = std::clamp(m.perceptualRoughness, 0.0, 1.0);
    m.ior = material.ior;
    // KHR_materials_clearcoat: strength and roughness, each its factor times its texture's channel
    // (GLSL under MATERIAL_CLEARCOAT); without a coat neither is read.
    if (material.hasClearcoat()) {
        m.clearcoat = material.clearcoat();
        if (const auto texel = read(MapSlot::Clearcoat))
            m.clearcoat *= scalarMapValue(material.map(MapSlot::Clearcoat), *texel);
        m.clearcoatRoughness = material.clearcoatRoughness();
        if (const auto texel = read(MapSlot::ClearcoatRoughness))
            m.clearcoatRoughness *= scalarMapValue(material.map(MapSlot::ClearcoatRoughness), *texel);
        m.clearcoat = std::clamp(m.clearcoat, 0.0, 1.0);
        m.clearcoatRoughness = std::clamp(m.clearcoatRoughness, 0.0, 1.0);
    }
    // KHR_materials_sheen: colour (RGB) and roughness (A), each its factor times its texture (GLSL
    // under MATERIAL_SHEEN); without a sheen neither is read.
    if (material.hasSheen()) {
        m.sheenColor = material.sheenColor();
        if (const auto texel = read(MapSlot::SheenColor))
            m.sheenColor *= glm::dvec3(*texel);
        m.sheenRoughness = material.sheenRoughness();
        if (const auto texel = read(MapSlot::SheenRoughness))
            m.sheenRoughness *= scalarMapValue(material.map(MapSlot::SheenRoughness), *texel);
        m.sheenColor = glm::clamp(m.sheenColor, glm::dvec3(0.0), glm::dvec3(1.0));
        m.sheenRoughness = std::clamp(m.sheenRoughness, 0.0, 1.0);
    }
    // KHR_materials_specular: strength (A) and colour (RGB), each its factor times its texture (GLSL
    // under MATERIAL_SPECULAR); the default layer reads neither. The colour may exceed 1.
    if (material.hasSpecular()) {
        m.specular = material.specular();
        if (const auto texel = read(MapSlot::Specular))
            m.specular *= scalarMapValue(material.map(MapSlot::Specular), *texel);
        m.specularColor = material.specularColor();
        // Under strength 0 the tint tints nothing, and the shader samples no colour map
        // (render/ShaderVariant textureMatters): the factor alone, as there.
        if (const auto texel = material.specular() != 0.0 ? read(MapSlot::SpecularColor) : std::nullopt)
            m.specularColor *= glm::dvec3(*texel);
        m.specular = std::clamp(m.specular, 0.0, 1.0);
        m.specularColor = glm::max(m.specularColor, glm::dvec3(0.0));
    }
    // KHR_materials_anisotropy: the strength (factor x texture B) and the direction in the tangent
    // plane, the texture's RG (x 2 - 1; (1, 0) without one) turned by the rotation (GLSL under
    // MATERIAL_ANISOTROPY). A caller with a tangent frame maps it (surfaceAnisotropyDirection).
    if (material.hasAnisotropy()) {
        m.anisotropy = material.anisotropy();
        glm::dvec2 direction(1.0, 0.0);
        if (const auto texel = read(MapSlot::Anisotropy)) {
            direction = glm::dvec2(*texel) * 2.0 - 1.0;
            m.anisotropy *= texel->b;
        }
        m.anisotropy = std::clamp(m.anisotropy, 0.0, 1.0);
        m.anisotropyTangentDirection = shading::anisotropyDirection(
            direction, glm::radians(material.anisotropyRotationDegrees));
    }
    // KHR_materials_iridescence: the strength (factor x texture R), the film's index and its
    // thickness, mix(minimum, maximum, texture G) or the maximum without a texture (GLSL under
    // MATERIAL_IRIDESCENCE).
    if (material.hasIridescence()) {
        m.iridescence = material.iridescence();
        if (const auto texel = read(MapSlot::Iridescence))
            m.iridescence *= scalarMapValue(material.map(MapSlot::Iridescence), *texel);
        m.iridescence = std::clamp(m.iridescence, 0.0, 1.0);
        m.iridescenceIor = material.iridescenceIor;
        m.iridescenceThickness = material.iridescenceThicknessMaximum();
        if (const auto texel = read(MapSlot::IridescenceThickness))
            m.iridescenceThickness = glm::mix(material.iridescenceThicknessMinimum, m.iridescenceThickness,
                scalarMapValue(material.map(MapSlot::IridescenceThickness), *texel));
        m.iridescenceThickness = std::max(m.iridescenceThickness, 0.0);
    }
    return m;
}

} // namespace facet
