#include "render/TextureFiltering.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace facet {

float TextureFiltering::setting(const GLInfo& info)
{
    float level = info.softwareRasterizer ? kSoftwareDefault : kHardwareDefault;
    if (const char* text = std::getenv("FACET_ANISOTROPY"); text && *text) {
        char* end = nullptr;
        const double value = std::strtod(text, &end);
        if (*end == '\0' && value >= 1.0 && value <= 16.0)
            level = float(value);
    }
    return std::clamp(level, 1.0f, std::max(info.maxAnisotropy, 1.0f));
}

float TextureFiltering::anisotropyFor(const GLInfo& info, bool interactive)
{
    const float level = setting(info);
    return info.softwareRasterizer && interactive ? std::min(level, kSoftwareInteractive) : level;
}

bool TextureFiltering::trilinear(const GLInfo& info)
{
    if (const char* text = std::getenv("FACET_TEXTURE_MIPS"); text && *text) {
        if (std::strcmp(text, "trilinear") == 0)
            return true;
        if (std::strcmp(text, "nearest") == 0)
            return false;
    }
    return !info.softwareRasterizer;
}

} // namespace facet
