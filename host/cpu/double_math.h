#pragma once
// Small double-precision helpers the CPU reference's files share.

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/vec3.hpp>

namespace hexray::inline cpu {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The largest |component|: the scale a vector's rounding errors are counted against.
inline double largestAbsComponent(const glm::dvec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

}  // namespace hexray::cpu
