// |v| without overflow or underflow for any finite v. World coordinates reach 1e100
// (docs/scene-format.md), so a face's Newell normal (a sum of products of coordinate
// differences) reaches ~1e200, and glm::length would square it to infinity (1e400), leaving a
// unit normal of zero: the largest component is factored out first.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace aabench {

inline double stable_length(const glm::dvec3& v) {
    const double m = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    if (!(m > 0.0) || !std::isfinite(m)) return m;
    return m * glm::length(v / m);
}

}  // namespace aabench
