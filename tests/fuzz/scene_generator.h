#pragma once
// Random scenes for differential fuzzing: valid by construction (the loader accepts every one),
// the same for the same seed on every platform, and biased toward what breaks renderers: counts
// of 0, every shader, cameras inside spheres, on planes and looking straight up or down, lengths
// across the whole supported range (tiny and huge radii, far offsets), and in two scenes of five
// things placed exactly on boundaries: spheres tangent to planes and to each other, lights and the
// camera on surfaces.

#include <cstdint>

#include "scene/scene.h"

namespace hexray::test {

// A scene within the supported range (scene.h), 32 x 24 pixels, 1 sample per pixel. What it places
// exactly on a boundary, near_tie_reasons.h finds again in the scene itself.
Scene generateScene(std::uint64_t seed);

// A length just outside the supported range, for checking that the loader rejects it: the
// generator's scene for `seed` with one coordinate, radius or intensity moved out of range.
Scene generateOutOfRangeScene(std::uint64_t seed);

}  // namespace hexray::test
