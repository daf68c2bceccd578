#pragma once
// How core's checks say why they refuse: a function `bool f(..., std::string* problem)` ends with
// `return fail("why", problem);`, which sets *problem when the caller asked for it and returns
// false.

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

namespace facet {

inline bool fail(std::string message, std::string* problem)
{
    if (problem)
        *problem = std::move(message);
    return false;
}

// "<field>: <value> is outside [lo, hi]" (numbers as %.9g) when `value` is not a finite number
// within the inclusive range; true otherwise.
inline bool checkRange(double value, double lo, double hi, const std::string& field, std::string* problem)
{
    if (std::isfinite(value) && value >= lo && value <= hi)
        return true;
    const auto number = [](double v) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.9g", v);
        return std::string(buffer);
    };
    return fail(
        field + ": " + number(value) + " is outside [" + number(lo) + ", " + number(hi) + "]", problem);
}

} // namespace facet
