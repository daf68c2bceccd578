#include "core/project/WedgeAxis.h"

#include <array>
#include <charconv>
#include <cmath>

#include <QFileInfo>
#include <QtGlobal>

#include "core/ibl/Environment.h"
#include "core/material/MaterialProperties.h"
#include "core/project/Project.h"
#include "core/support/Failure.h"

namespace facet {

namespace {

// A material's axes take their name, field, range and setter from the property registry
// (core/material/MaterialProperties.h); the view's range is ViewSettings' constants. A test checks
// that validate() accepts each end and refuses the next number beyond it.
WedgeParameterInfo materialAxis(WedgeParameter parameter, MaterialProperty property)
{
    const MaterialPropertyInfo& info = infoOf(property);
    return {parameter, info.name, info.field, info.minimum, info.maximum, property};
}

const std::array<WedgeParameterInfo, 19>& parameterTable()
{
    static const std::array<WedgeParameterInfo, 19> table = {{
        materialAxis(WedgeParameter::Metallic, MaterialProperty::Metallic),
        materialAxis(WedgeParameter::Roughness, MaterialProperty::Roughness),
        materialAxis(WedgeParameter::Occlusion, MaterialProperty::Occlusion),
        materialAxis(WedgeParameter::Normal, MaterialProperty::Normal),
        materialAxis(WedgeParameter::Ior, MaterialProperty::Ior),
        materialAxis(WedgeParameter::EmissiveStrength, MaterialProperty::EmissiveStrength),
        materialAxis(WedgeParameter::AlphaCutoff, MaterialProperty::AlphaCutoff),
        materialAxis(WedgeParameter::Alpha, MaterialProperty::Alpha),
        materialAxis(WedgeParameter::Clearcoat, MaterialProperty::Clearcoat),
        materialAxis(WedgeParameter::ClearcoatRoughness, MaterialProperty::ClearcoatRoughness),
        materialAxis(WedgeParameter::SheenRoughness, MaterialProperty::SheenRoughness),
        materialAxis(WedgeParameter::Specular, MaterialProperty::Specular),
        materialAxis(WedgeParameter::Anisotropy, MaterialProperty::Anisotropy),
        materialAxis(WedgeParameter::AnisotropyRotation, MaterialProperty::AnisotropyRotation),
        materialAxis(WedgeParameter::Iridescence, MaterialProperty::Iridescence),
        materialAxis(WedgeParameter::IridescenceIor, MaterialProperty::IridescenceIor),
        materialAxis(WedgeParameter::IridescenceThickness, MaterialProperty::IridescenceThickness),
        {WedgeParameter::Environment, "env", "environment.source", 0.0, 0.0, std::nullopt},
        {WedgeParameter::Exposure, "exposure", "view.exposureEV", ViewSettings::kMinExposureEV,
            ViewSettings::kMaxExposureEV, std::nullopt},
    }};
    return table;
}

// Shortest text that reads back as the same double ("0.25", "1e-05").
std::string shortest(double value)
{
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::string_view trimmed(std::string_view text)
{
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t'))
        text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t'))
        text.remove_suffix(1);
    return text;
}

// The whole of `text` as a number (an optional leading '+', as in "+1" EV), or nullopt.
std::optional<double> parseNumber(std::string_view text)
{
    if (text.size() > 1 && text.front() == '+' && text[1] != '-' && text[1] != '+')
        text.remove_prefix(1);
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size())
        return std::nullopt;
    return value;
}

void applyToMaterial(WedgeParameter parameter, double value, Material& material)
{
    const std::optional<MaterialProperty> property = infoOf(parameter).property;
    Q_ASSERT(property);
    if (property)
        setScalar(material, *property, value);
}

// Whether one value is acceptable, by the validators' own rule and message: a default material
// (or view) with the value set must validate.
bool checkValue(WedgeParameter parameter, double value, std::string* problem)
{
    if (parameter == WedgeParameter::Exposure) {
        ViewSettings probe;
        probe.exposureEV = value;
        return probe.validate(problem);
    }
    Material probe;
    applyToMaterial(parameter, value, probe);
    return probe.validate(problem);
}

// A short name for an environment spec: built-in and uniform specs as they are, a file (path or
// library reference) by its base name.
std::string environmentLabel(const std::string& spec)
{
    if (!Environment::namesFile(spec))
        return spec;
    const QString base = QFileInfo(QString::fromStdString(spec)).completeBaseName();
    return base.isEmpty() ? spec : base.toStdString();
}

} // namespace

std::span<const WedgeParameterInfo> wedgeParameters()
{
    return parameterTable();
}

const WedgeParameterInfo& infoOf(WedgeParameter parameter)
{
    for (const WedgeParameterInfo& info : parameterTable())
        if (info.parameter == parameter)
            return info;
    Q_ASSERT(false);
    return parameterTable().front();
}

const char* toString(WedgeParameter parameter)
{
    return infoOf(parameter).name;
}

std::optional<WedgeParameter> wedgeParameterFromString(std::string_view name)
{
    for (const WedgeParameterInfo& info : parameterTable())
        if (name == info.name)
            return info.parameter;
    return std::nullopt;
}

std::string wedgeParameterNameList()
{
    std::string list;
    for (const WedgeParameterInfo& info : parameterTable())
        list += (list.empty() ? "" : ", ") + std::string(info.name);
    return list;
}

WedgeAxis WedgeAxis::defaultRows()
{
    return WedgeAxis {WedgeParameter::Roughness, {0.0, 0.25, 0.5, 0.75, 1.0}, {}};
}

WedgeAxis WedgeAxis::defaultColumns()
{
    return WedgeAxis {WedgeParameter::Metallic, {0.0, 1.0}, {}};
}

std::optional<WedgeAxis> WedgeAxis::parse(std::string_view text, std::string* error)
{
    const std::string prefix = "WedgeAxis::parse: \"" + std::string(text) + "\": ";
    const auto failed = [&](const std::string& problem) {
        if (error)
            *error = prefix + problem;
        return std::nullopt;
    };
    const std::size_t equals = text.find('=');
    if (equals == std::string_view::npos)
        return failed("expected PARAMETER=V1,V2,... (e.g. roughness=0,0.5,1)");
    const std::string name(trimmed(text.substr(0, equals)));
    const std::optional<WedgeParameter> parameter = wedgeParameterFromString(name);
    if (!parameter)
        return failed("unknown parameter \"" + name + "\" (known: " + wedgeParameterNameList() + ")");

    // Split at commas; empty items are reported by their position.
    std::vector<std::string_view> items;
    const std::string_view list = text.substr(equals + 1);
    if (trimmed(list).empty())
        return failed(name + ": no values (expected " + name + "=V1,V2,...)");
    for (std::size_t start = 0;;) {
        const std::size_t comma = list.find(',', start);
        items.push_back(trimmed(list.substr(start, comma == std::string_view::npos ? comma : comma - start)));
        if (comma == std::string_view::npos)
            break;
        start = comma + 1;
    }

    WedgeAxis axis;
    axis.parameter = *parameter;
    std::string problem;
    for (std::size_t i = 0; i < items.size(); ++i) {
        // Values are counted from 1, as a person counts them on a command line.
        const std::string position = "value " + std::to_string(axis.size() + 1);
        if (items[i].empty())
            return failed(name + ": " + position + " is empty");
        if (axis.isEnvironment()) {
            std::string spec(items[i]);
            // "uniform:R,G,B" was cut at its commas: give it back the two numbers after it.
            if (spec.rfind("uniform:", 0) == 0 && i + 2 < items.size() && parseNumber(items[i + 1])
                && parseNumber(items[i + 2])) {
                // (Appended piece by piece: "," + std::string trips GCC 12's -Wrestrict at -O3.)
                for (std::size_t k = 1; k <= 2; ++k)
                    spec.append(1, ',').append(items[i + k]);
                i += 2;
            }
            // A bare number is a stray piece of a uniform:R,G,B (or a typo), not an environment.
            if (parseNumber(spec))
                return failed(name + ": " + position + ", \"" + spec
                    + "\", is a number, not an environment (uniform:R,G,B takes three numbers; a file of "
                      "that name is ./"
                    + spec + ")");
            if (!Environment::checkSpec(spec, &problem))
                return failed(name + ": " + position + ": " + problem);
            axis.environments.push_back(std::move(spec));
        } else {
            const std::optional<double> value = parseNumber(items[i]);
            if (!value)
                return failed(
                    name + ": " + position + ", \"" + std::string(items[i]) + "\", is not a number");
            if (!checkValue(axis.parameter, *value, &problem))
                return failed(name + ": " + position + ": " + problem);
            axis.values.push_back(*value);
        }
    }
    if (axis.size() > std::size_t(kMaxValues))
        return failed(name + ": " + std::to_string(axis.size()) + " values, more than the "
            + std::to_string(kMaxValues) + " an axis holds");
    Q_ASSERT(axis.validate(nullptr));
    return axis;
}

std::string WedgeAxis::toString() const
{
    std::string text = std::string(facet::toString(parameter)) + "=";
    for (std::size_t i = 0; i < size(); ++i)
        text += (i == 0 ? "" : ",") + (isEnvironment() ? environments[i] : shortest(values[i]));
    return text;
}

bool WedgeAxis::validate(std::string* problem) const
{
    // The file holds both kinds of value under "values"; messages name that key.
    const std::string name = facet::toString(parameter);
    if (isEnvironment() && !values.empty())
        return fail("values: the env axis holds environment specs, not numbers", problem);
    if (!isEnvironment() && !environments.empty())
        return fail("values: the " + name + " axis holds numbers, not environment specs", problem);
    if (size() == 0)
        return fail("values: needs at least one value", problem);
    if (size() > std::size_t(kMaxValues))
        return fail("values: " + std::to_string(size()) + " values, more than the "
                + std::to_string(kMaxValues) + " an axis holds",
            problem);
    std::string local;
    for (std::size_t i = 0; i < size(); ++i)
        if (isEnvironment() ? !Environment::checkSpec(environments[i], &local)
                            : !checkValue(parameter, values[i], &local))
            return fail("values[" + std::to_string(i) + "]: " + local, problem);
    return true;
}

void WedgeAxis::apply(std::size_t index, Project& project) const
{
    Q_ASSERT(index < size());
    switch (parameter) {
    case WedgeParameter::Environment:
        project.environment.source = environments[index];
        return;
    case WedgeParameter::Exposure:
        project.view.exposureEV = values[index];
        return;
    default:
        applyToMaterial(parameter, values[index], project.material());
        return;
    }
}

std::string WedgeAxis::label(std::size_t index) const
{
    Q_ASSERT(index < size());
    const std::string name = facet::toString(parameter);
    if (isEnvironment())
        return name + " " + environmentLabel(environments[index]);
    if (parameter == WedgeParameter::Exposure)
        return name + " " + (values[index] > 0.0 ? "+" : "") + shortest(values[index]) + " EV";
    return name + " " + shortest(values[index]);
}

std::string WedgeAxis::noEffectReason(const Project& project) const
{
    const Material& m = project.material();
    switch (parameter) {
    case WedgeParameter::AlphaCutoff:
        if (m.alphaMode != AlphaMode::Mask)
            return "alphaCutoff is used only with alphaMode \"mask\" (the material's is \""
                + std::string(facet::toString(m.alphaMode)) + "\")";
        break;
    case WedgeParameter::Alpha:
        if (m.alphaMode == AlphaMode::Opaque)
            return "alpha is ignored with alphaMode \"opaque\"";
        break;
    case WedgeParameter::EmissiveStrength:
        if (m.map(MapSlot::Emissive).factor.x == 0.0 && m.map(MapSlot::Emissive).factor.y == 0.0
            && m.map(MapSlot::Emissive).factor.z == 0.0)
            return "emissiveStrength multiplies the emissive colour, which is black";
        break;
    case WedgeParameter::Normal:
        if (!m.map(MapSlot::Normal).hasTexture())
            return "normal strength scales a normal map, and the material has none";
        break;
    case WedgeParameter::Occlusion:
        if (!m.map(MapSlot::Occlusion).hasTexture())
            return "occlusion strength mixes in an occlusion map, and the material has none";
        break;
    case WedgeParameter::Ior:
        if (m.metallic() == 1.0 && !m.map(MapSlot::Metallic).hasTexture())
            return "ior sets the dielectric's reflectance, and the material is a metal (metallic 1)";
        break;
    case WedgeParameter::Specular:
        if (m.metallic() == 1.0 && !m.map(MapSlot::Metallic).hasTexture())
            return "specular scales the dielectric's reflection, and the material is a metal (metallic 1)";
        break;
    case WedgeParameter::ClearcoatRoughness:
        if (!m.hasClearcoat())
            return "clearcoatRoughness shapes the clear coat, and the material has none (clearcoat 0)";
        break;
    case WedgeParameter::SheenRoughness:
        if (!m.hasSheen())
            return "sheenRoughness shapes the sheen, and the material has none (sheenColor black)";
        break;
    case WedgeParameter::AnisotropyRotation:
        if (!m.hasAnisotropy())
            return "anisotropyRotation turns the anisotropy, and the material has none (anisotropy 0)";
        break;
    case WedgeParameter::IridescenceIor:
    case WedgeParameter::IridescenceThickness:
        if (!m.hasIridescence())
            return std::string(facet::toString(parameter))
                + " shapes the iridescent film, and the material has none (iridescence 0)";
        break;
    default:
        break;
    }
    return {};
}

} // namespace facet
