#pragma once
// How core's checks say why they refuse: a function `bool f(..., std::string* problem)` ends with
// `return fail("why", problem);`, which sets *problem when the caller asked for it and returns
// false.

#include <string>
#include <utility>

namespace facet {

inline bool fail(std::string message, std::string* problem)
{
    if (problem)
        *problem = std::move(message);
    return false;
}

} // namespace facet
