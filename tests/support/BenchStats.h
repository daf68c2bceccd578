#pragma once
// The summaries the benchmarks print (tests/bench): a series of measured times is reported as its
// fastest and its median, the fastest being the least disturbed by other work on the machine.

#include <algorithm>
#include <vector>

namespace facet::bench {

// The middle value (the upper one of an even count); 0 for none.
inline double median(std::vector<double> values)
{
    if (values.empty())
        return 0.0;
    const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

// The smallest value; 0 for none.
inline double fastest(const std::vector<double>& values)
{
    return values.empty() ? 0.0 : *std::min_element(values.begin(), values.end());
}

} // namespace facet::bench
