#include "core/image/HeatMap.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace facet::heatmap {

namespace {

// viridis at 0, 1/8, ..., 1 (sRGB bytes).
constexpr std::array<std::array<int, 3>, 9> kStops {{
    {68, 1, 84},
    {71, 44, 122},
    {59, 81, 139},
    {44, 113, 142},
    {33, 144, 141},
    {39, 173, 129},
    {92, 200, 99},
    {170, 220, 50},
    {253, 231, 37},
}};

glm::vec3 stop(std::size_t i)
{
    return glm::vec3(float(kStops[i][0]), float(kStops[i][1]), float(kStops[i][2])) / 255.0f;
}

} // namespace

glm::vec3 ramp(double t)
{
    t = std::isnan(t) ? 0.0 : std::clamp(t, 0.0, 1.0);
    const double position = t * double(kStops.size() - 1);
    const std::size_t low = std::min(std::size_t(position), kStops.size() - 2);
    const float fraction = float(position - double(low));
    return stop(low) + (stop(low + 1) - stop(low)) * fraction;
}

glm::vec3 color(double value, double scale)
{
    if (!(scale > 0.0))
        return kOverScale;
    if (value > scale)
        return kOverScale;
    return ramp(value / scale);
}

} // namespace facet::heatmap
