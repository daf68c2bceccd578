#include "core/shading/ShadingModel.h"

#include "core/support/EnumNames.h"

namespace facet {

namespace {
constexpr std::pair<BrdfComposition, const char*> kCompositions[]
    = {{BrdfComposition::Gltf, "gltf"}, {BrdfComposition::LearnOpenGL, "learnopengl"}};
constexpr std::pair<Distribution, const char*> kDistributions[]
    = {{Distribution::GGX, "ggx"}, {Distribution::Beckmann, "beckmann"}};
constexpr std::pair<Visibility, const char*> kVisibilities[] = {
    {Visibility::SmithGGXCorrelated, "smith-ggx-correlated"},
    {Visibility::SmithGGXUncorrelated, "smith-ggx-uncorrelated"}, {Visibility::SchlickGGX, "schlick-ggx"}};
constexpr std::pair<Fresnel, const char*> kFresnels[]
    = {{Fresnel::Schlick, "schlick"}, {Fresnel::Dielectric, "dielectric"}};
constexpr std::pair<DielectricCoupling, const char*> kCouplings[]
    = {{DielectricCoupling::FresnelMix, "fresnel-mix"},
        {DielectricCoupling::EnergyPreserving, "energy-preserving"}};
} // namespace

const char* toString(BrdfComposition value)
{
    return enumName(kCompositions, value);
}
const char* toString(Distribution value)
{
    return enumName(kDistributions, value);
}
const char* toString(Visibility value)
{
    return enumName(kVisibilities, value);
}
const char* toString(Fresnel value)
{
    return enumName(kFresnels, value);
}
const char* toString(DielectricCoupling value)
{
    return enumName(kCouplings, value);
}
std::optional<BrdfComposition> brdfCompositionFromString(std::string_view name)
{
    return enumFromName(kCompositions, name);
}
std::optional<Distribution> distributionFromString(std::string_view name)
{
    return enumFromName(kDistributions, name);
}
std::optional<Visibility> visibilityFromString(std::string_view name)
{
    return enumFromName(kVisibilities, name);
}
std::optional<Fresnel> fresnelFromString(std::string_view name)
{
    return enumFromName(kFresnels, name);
}
std::optional<DielectricCoupling> dielectricCouplingFromString(std::string_view name)
{
    return enumFromName(kCouplings, name);
}

} // namespace facet
