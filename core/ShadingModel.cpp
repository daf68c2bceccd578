#include "core/ShadingModel.h"

namespace facet {

namespace {
template <typename Enum, std::size_t N>
std::optional<Enum> lookup(const std::pair<Enum, const char*> (&table)[N], std::string_view name)
{
    for (const auto& [value, text] : table)
        if (name == text)
            return value;
    return std::nullopt;
}
template <typename Enum, std::size_t N>
const char* nameOf(const std::pair<Enum, const char*> (&table)[N], Enum value)
{
    for (const auto& [v, text] : table)
        if (v == value)
            return text;
    return "";
}

constexpr std::pair<BrdfComposition, const char*> kCompositions[] = {
    {BrdfComposition::Gltf, "gltf"}, {BrdfComposition::LearnOpenGL, "learnopengl"}};
constexpr std::pair<Distribution, const char*> kDistributions[] = {
    {Distribution::GGX, "ggx"}, {Distribution::Beckmann, "beckmann"}};
constexpr std::pair<Visibility, const char*> kVisibilities[] = {
    {Visibility::SmithGGXCorrelated, "smith-ggx-correlated"},
    {Visibility::SmithGGXUncorrelated, "smith-ggx-uncorrelated"},
    {Visibility::SchlickGGX, "schlick-ggx"}};
constexpr std::pair<Fresnel, const char*> kFresnels[] = {{Fresnel::Schlick, "schlick"},
                                                         {Fresnel::Dielectric, "dielectric"}};
constexpr std::pair<DielectricCoupling, const char*> kCouplings[] = {
    {DielectricCoupling::FresnelMix, "fresnel-mix"}, {DielectricCoupling::EnergyPreserving, "energy-preserving"}};
} // namespace

const char* toString(BrdfComposition value) { return nameOf(kCompositions, value); }
const char* toString(Distribution value) { return nameOf(kDistributions, value); }
const char* toString(Visibility value) { return nameOf(kVisibilities, value); }
const char* toString(Fresnel value) { return nameOf(kFresnels, value); }
const char* toString(DielectricCoupling value) { return nameOf(kCouplings, value); }
std::optional<BrdfComposition> brdfCompositionFromString(std::string_view name) { return lookup(kCompositions, name); }
std::optional<Distribution> distributionFromString(std::string_view name) { return lookup(kDistributions, name); }
std::optional<Visibility> visibilityFromString(std::string_view name) { return lookup(kVisibilities, name); }
std::optional<Fresnel> fresnelFromString(std::string_view name) { return lookup(kFresnels, name); }
std::optional<DielectricCoupling> dielectricCouplingFromString(std::string_view name) { return lookup(kCouplings, name); }

} // namespace facet
