#pragma once
// Whether every component of a GLM vector or matrix is finite (neither NaN nor infinite): the
// check core makes on every number that comes from a file or a caller before using it.

#include <cmath>

#include <glm/fwd.hpp>

namespace facet {

template <glm::length_t L, typename T, glm::qualifier Q> bool isFinite(const glm::vec<L, T, Q>& v)
{
    for (glm::length_t i = 0; i < L; ++i)
        if (!std::isfinite(v[i]))
            return false;
    return true;
}

template <glm::length_t C, glm::length_t R, typename T, glm::qualifier Q>
bool isFinite(const glm::mat<C, R, T, Q>& m)
{
    for (glm::length_t c = 0; c < C; ++c)
        if (!isFinite(m[c]))
            return false;
    return true;
}

} // namespace facet
