#pragma once
// A deterministic scene of many spheres, for benchmarks and tests of the BVH and candidate lists.

#include <cstdint>

#include "scene/scene.h"

namespace hexray::inline scene {

// `count` spheres of radii 0.5 to 2.5 scattered (overlaps allowed) over a square of a checkered
// floor plane y = 0, whose side grows as sqrt(count) so the density stays the same; nodes[0] is
// the floor, the spheres follow. Two lights, a camera above and behind the square looking down
// at it, a 320 x 180 image. The same count and seed give the same scene on every platform
// (std::mt19937_64 with its own mapping to [0, 1); <random>'s distributions are not portable).
Scene makeRandomSpheresScene(std::uint32_t count, std::uint64_t seed);

}  // namespace hexray::scene
