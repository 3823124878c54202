#pragma once
// Points in Morton (Z-curve) order: points near each other in space are mostly near each other
// in the order. The candidate lists keep their spheres' records in this order, so that the records
// neighbouring pixels read lie close together in memory.

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

namespace hexray::inline accel {

// The indices of `points`, ordered along a Z-curve through their bounding box (10 bits a
// coordinate); equal codes keep their index order, so the order is deterministic.
std::vector<std::uint32_t> mortonOrder(std::span<const glm::dvec3> points);

}  // namespace hexray::accel
