#include "core/material/MaterialProperties.h"

#include <array>
#include <numbers>

#include <QtGlobal>

#include "core/shading/ThinFilm.h"
#include "core/support/Failure.h"

namespace facet {

namespace {

using P = MaterialProperty;
using V = PropertyValue;

// The ranges are the material's constants; MaterialPropertiesTest checks that validate() accepts
// each end and refuses the next number beyond it.
constexpr std::array<MaterialPropertyInfo, kMaterialPropertyCount> kProperties = {{
    {P::BaseColor, "baseColor", "baseColor.factor", "Base colour (linear)", V::Color, 0.0, 1.0,
        MapSlot::BaseColor, "base-color", {}, {"baseColor", "rgb"}},
    {P::Alpha, "alpha", "baseColor.factor.a", "Base colour alpha", V::Scalar, 0.0, 1.0, MapSlot::BaseColor,
        nullptr, {}, {"baseColor", "a"}},
    {P::Metallic, "metallic", "metallic.factor", "Metallic", V::Scalar, 0.0, 1.0, MapSlot::Metallic,
        "metallic", {}, {"metallic"}},
    {P::Roughness, "roughness", "roughness.factor", "Perceptual roughness", V::Scalar, 0.0, 1.0,
        MapSlot::Roughness, "roughness", {}, {"roughness"}},
    {P::Occlusion, "occlusion", "occlusion.factor", "Occlusion strength", V::Scalar, 0.0, 1.0,
        MapSlot::Occlusion, nullptr, {}, {"occlusion"}},
    {P::Normal, "normal", "normal.factor", "Normal map strength", V::Scalar, 0.0,
        Material::kMaxNormalStrength, MapSlot::Normal, nullptr, {}, {"normal", "xyz"}, 2.0},
    {P::Emissive, "emissive", "emissive.factor", "Emissive colour (linear)", V::Color, 0.0, 1.0,
        MapSlot::Emissive, nullptr, {}, {"emissive", "rgb"}},
    {P::EmissiveStrength, "emissiveStrength", "emissiveStrength", "Emissive strength", V::Scalar, 0.0,
        Material::kMaxEmissiveStrength, std::nullopt, nullptr,
        {"KHR_materials_emissive_strength", "emissiveStrength", 1.0}, {}},
    {P::Ior, "ior", "ior", "Index of refraction", V::Scalar, Material::kMinIor, Material::kMaxIor,
        std::nullopt, nullptr, {"KHR_materials_ior", "ior", Material::kDefaultIor}, {}, 3.0},
    {P::AlphaCutoff, "alphaCutoff", "alphaCutoff", "Alpha cutoff", V::Scalar, 0.0, 1.0, std::nullopt, nullptr,
        {}, {}},
    {P::Clearcoat, "clearcoat", "clearcoat.factor", "Clearcoat strength", V::Scalar, 0.0, 1.0,
        MapSlot::Clearcoat, "clearcoat", {"KHR_materials_clearcoat", "clearcoatFactor", 0.0}, {"clearcoat"}},
    {P::ClearcoatRoughness, "clearcoatRoughness", "clearcoatRoughness.factor",
        "Clearcoat roughness (perceptual)", V::Scalar, 0.0, 1.0, MapSlot::ClearcoatRoughness,
        "clearcoat-roughness", {"KHR_materials_clearcoat", "clearcoatRoughnessFactor", 0.0},
        {"clearcoatRoughness"}},
    {P::ClearcoatNormal, "clearcoatNormal", "clearcoatNormal.factor", "Clearcoat normal map strength",
        V::Scalar, 0.0, Material::kMaxNormalStrength, MapSlot::ClearcoatNormal, nullptr, {},
        {"clearcoatNormal", "xyz"}, 2.0},
    {P::SheenColor, "sheenColor", "sheenColor.factor", "Sheen colour (linear)", V::Color, 0.0, 1.0,
        MapSlot::SheenColor, "sheen-color", {"KHR_materials_sheen", "sheenColorFactor", 0.0},
        {"sheenColor", "rgb"}},
    {P::SheenRoughness, "sheenRoughness", "sheenRoughness.factor", "Sheen roughness (perceptual)", V::Scalar,
        0.0, 1.0, MapSlot::SheenRoughness, "sheen-roughness",
        {"KHR_materials_sheen", "sheenRoughnessFactor", 0.0}, {"sheenRoughness"}},
    {P::Specular, "specular", "specular.factor", "Specular strength (dielectric)", V::Scalar, 0.0, 1.0,
        MapSlot::Specular, "specular", {"KHR_materials_specular", "specularFactor", 1.0}, {"specular"}},
    // A colour above 1 raises F0 beyond the IOR's (the product clamped to 1): the extension allows
    // it, so the range goes on to Material::kMaxSpecularColor (the dock's colour button shows [0, 1]).
    {P::SpecularColor, "specularColor", "specularColor.factor", "Specular colour (linear F0 tint)", V::Color,
        0.0, Material::kMaxSpecularColor, MapSlot::SpecularColor, "specular-color",
        {"KHR_materials_specular", "specularColorFactor", 1.0}, {"specularColor", "rgb"}},
    {P::Anisotropy, "anisotropy", "anisotropy.factor", "Anisotropy strength", V::Scalar, 0.0, 1.0,
        MapSlot::Anisotropy, "anisotropy", {"KHR_materials_anisotropy", "anisotropyStrength", 0.0},
        {"anisotropy"}},
    {P::AnisotropyRotation, "anisotropyRotation", "anisotropyRotationDegrees",
        "Anisotropy rotation (degrees, counter-clockwise from the tangent)", V::Scalar,
        -Material::kMaxAnisotropyRotationDegrees, Material::kMaxAnisotropyRotationDegrees, std::nullopt,
        "anisotropy-rotation",
        {"KHR_materials_anisotropy", "anisotropyRotation", 0.0, std::numbers::pi / 180.0, true},
        {"anisotropyDirection", "xy", MapSlot::Anisotropy}},
    {P::Iridescence, "iridescence", "iridescence.factor", "Iridescence (thin film) strength", V::Scalar, 0.0,
        1.0, MapSlot::Iridescence, "iridescence", {"KHR_materials_iridescence", "iridescenceFactor", 0.0},
        {"iridescence"}},
    {P::IridescenceIor, "iridescenceIor", "iridescenceIor", "Iridescence film's index of refraction",
        V::Scalar, Material::kMinIor, Material::kMaxIor, std::nullopt, "iridescence-ior",
        {"KHR_materials_iridescence", "iridescenceIor", shading::kDefaultIridescenceIor}, {}, 3.0},
    // The thickness without a texture, and where a thickness texture reads 1 (the extension's
    // maximum); sliders stop at 1200 nm, past the last visible interference colours.
    {P::IridescenceThickness, "iridescenceThickness", "iridescenceThickness.factor",
        "Iridescence film thickness (nm; a thickness texture's 1)", V::Scalar, 0.0,
        Material::kMaxIridescenceThickness, MapSlot::IridescenceThickness, "iridescence-thickness",
        {"KHR_materials_iridescence", "iridescenceThicknessMaximum",
            shading::kDefaultIridescenceThicknessMaximum},
        {"iridescenceThickness"}, 1200.0},
    {P::IridescenceThicknessMinimum, "iridescenceThicknessMinimum", "iridescenceThicknessMinimum",
        "Iridescence film thickness where a thickness texture reads 0 (nm)", V::Scalar, 0.0,
        Material::kMaxIridescenceThickness, std::nullopt, "iridescence-thickness-minimum",
        {"KHR_materials_iridescence", "iridescenceThicknessMinimum",
            shading::kDefaultIridescenceThicknessMinimum},
        {}, 1200.0},
}};

constexpr bool inEnumOrder()
{
    for (std::size_t i = 0; i < kProperties.size(); ++i)
        if (int(kProperties[i].property) != int(i))
            return false;
    return true;
}
static_assert(inEnumOrder(), "kProperties must list the properties in the order of the enum");

} // namespace

std::span<const MaterialPropertyInfo> materialProperties()
{
    return kProperties;
}

std::optional<MaterialProperty> factorPropertyOf(MapSlot slot)
{
    const PropertyValue value = isColorSlot(slot) ? PropertyValue::Color : PropertyValue::Scalar;
    for (const MaterialPropertyInfo& info : kProperties)
        if (info.slot == slot && info.value == value)
            return info.property;
    return std::nullopt;
}

const MaterialPropertyInfo& infoOf(MaterialProperty property)
{
    return kProperties[std::size_t(property)];
}

std::optional<MaterialProperty> materialPropertyFromString(std::string_view name)
{
    for (const MaterialPropertyInfo& info : kProperties)
        if (name == info.name)
            return info.property;
    return std::nullopt;
}

double scalarOf(const Material& material, MaterialProperty property)
{
    switch (property) {
    case P::Alpha:
        return material.map(MapSlot::BaseColor).factor.a;
    case P::EmissiveStrength:
        return material.emissiveStrength;
    case P::Ior:
        return material.ior;
    case P::AlphaCutoff:
        return material.alphaCutoff;
    case P::AnisotropyRotation:
        return material.anisotropyRotationDegrees;
    case P::IridescenceIor:
        return material.iridescenceIor;
    case P::IridescenceThicknessMinimum:
        return material.iridescenceThicknessMinimum;
    case P::BaseColor:
    case P::Emissive:
    case P::SheenColor:
    case P::SpecularColor:
        break;
    default:
        return material.map(*infoOf(property).slot).factor.x;
    }
    Q_ASSERT_X(false, "scalarOf", "a colour property");
    return 0.0;
}

void setScalar(Material& material, MaterialProperty property, double value)
{
    switch (property) {
    case P::Alpha:
        material.map(MapSlot::BaseColor).factor.a = value;
        return;
    case P::EmissiveStrength:
        material.emissiveStrength = value;
        return;
    case P::Ior:
        material.ior = value;
        return;
    case P::AlphaCutoff:
        material.alphaCutoff = value;
        return;
    case P::AnisotropyRotation:
        material.anisotropyRotationDegrees = value;
        return;
    case P::IridescenceIor:
        material.iridescenceIor = value;
        return;
    case P::IridescenceThicknessMinimum:
        material.iridescenceThicknessMinimum = value;
        return;
    case P::BaseColor:
    case P::Emissive:
    case P::SheenColor:
    case P::SpecularColor:
        break;
    default:
        material.setFactor(*infoOf(property).slot, value);
        return;
    }
    Q_ASSERT_X(false, "setScalar", "a colour property");
}

glm::dvec3 colorOf(const Material& material, MaterialProperty property)
{
    const MaterialPropertyInfo& info = infoOf(property);
    Q_ASSERT(info.value == PropertyValue::Color && info.slot);
    return glm::dvec3(material.map(*info.slot).factor);
}

void setColor(Material& material, MaterialProperty property, const glm::dvec3& rgb)
{
    const MaterialPropertyInfo& info = infoOf(property);
    Q_ASSERT(info.value == PropertyValue::Color && info.slot);
    glm::dvec4& factor = material.map(*info.slot).factor;
    factor = glm::dvec4(rgb, factor.w);
}

bool checkProperty(const Material& material, MaterialProperty property, std::string* problem)
{
    const MaterialPropertyInfo& info = infoOf(property);
    if (info.value == PropertyValue::Scalar)
        return checkRange(scalarOf(material, property), info.minimum, info.maximum, info.field, problem);
    static const char* const kComponents[] = {"r", "g", "b"};
    const glm::dvec3 rgb = colorOf(material, property);
    for (int i = 0; i < 3; ++i)
        if (!checkRange(
                rgb[i], info.minimum, info.maximum, std::string(info.field) + "." + kComponents[i], problem))
            return false;
    return true;
}

} // namespace facet
