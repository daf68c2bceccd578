#include "core/shading/DebugView.h"

#include <array>

namespace facet {

namespace {

// One row per DebugView, in enum order: the name files and the command line use, the label the
// window shows, and an older name still accepted.
struct DebugViewName {
    const char* name;
    const char* label;
    const char* alias;
};
constexpr std::array<DebugViewName, kDebugViewCount> kDebugViewNames = {{
    {"none", "Off (shaded image)", nullptr},
    {"base-color", "Base colour", nullptr},
    {"shading-normal", "Shading normal", nullptr},
    {"geometric-normal", "Geometric normal", nullptr},
    {"metallic", "Metallic", nullptr},
    {"roughness", "Roughness", nullptr},
    {"occlusion", "Ambient occlusion", nullptr},
    {"distribution", "Distribution D", "d"},
    {"visibility", "Visibility V", "v"},
    {"fresnel", "Fresnel F", "f"},
    {"irradiance", "Irradiance E/\u03c0", nullptr},
    {"ibl-diffuse", "IBL diffuse", nullptr},
    {"prefiltered-radiance", "Prefiltered radiance", nullptr},
    {"brdf-lut", "BRDF lookup table (DFG)", nullptr},
    {"ibl-specular", "IBL specular", nullptr},
    {"ibl-total", "IBL diffuse + specular", nullptr},
    {"direct-light", "Direct light (lights only)", nullptr},
    {"white-furnace", "White furnace", nullptr},
    {"uv", "Texture coordinates (UV)", nullptr},
    {"tangent", "Tangent", nullptr},
    {"emissive", "Emissive", nullptr},
    {"alpha", "Alpha (coverage)", nullptr},
    {"non-finite", "Invalid values (NaN, Inf, negative)", nullptr},
    {"uv-checker", "UV checker", nullptr},
    {"texel-density", "Texel density", nullptr},
    {"clearcoat", "Clearcoat strength", nullptr},
    {"clearcoat-roughness", "Clearcoat roughness", nullptr},
    {"clearcoat-normal", "Clearcoat normal", nullptr},
    {"sheen-color", "Sheen colour", nullptr},
    {"sheen-roughness", "Sheen roughness", nullptr},
    {"specular", "Specular strength", nullptr},
    {"specular-color", "Specular colour", nullptr},
    {"anisotropy", "Anisotropy strength", nullptr},
    {"anisotropy-direction", "Anisotropy direction", nullptr},
    {"iridescence", "Iridescence strength", nullptr},
    {"iridescence-thickness", "Iridescence thickness (white: 1000 nm)", nullptr},
    {"iridescence-fresnel", "Iridescence Fresnel (film at n.v)", nullptr},
}};

} // namespace

const char* toString(DebugView view)
{
    const int index = int(view);
    return index >= 0 && index < kDebugViewCount ? kDebugViewNames[std::size_t(index)].name : "none";
}

const char* debugViewLabel(DebugView view)
{
    const int index = int(view);
    return index >= 0 && index < kDebugViewCount ? kDebugViewNames[std::size_t(index)].label : "";
}

std::optional<DebugView> debugViewFromString(const std::string& name)
{
    for (int i = 0; i < kDebugViewCount; ++i) {
        const DebugViewName& row = kDebugViewNames[std::size_t(i)];
        if (name == row.name || (row.alias && name == row.alias))
            return DebugView(i);
    }
    return std::nullopt;
}

bool debugViewShowsIntegratedLight(DebugView view)
{
    switch (view) {
    case DebugView::None:
    case DebugView::IblDiffuse:
    case DebugView::IblSpecular:
    case DebugView::IblTotal:
    case DebugView::WhiteFurnace:
    case DebugView::NonFinite:
        return true;
    default:
        return false;
    }
}

std::string debugViewNameList()
{
    std::string list;
    for (const DebugViewName& row : kDebugViewNames) {
        list += (list.empty() ? "" : ", ") + std::string(row.name);
        if (row.alias)
            list += std::string(" (or ") + row.alias + ")";
    }
    return list;
}

} // namespace facet
