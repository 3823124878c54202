#pragma once
// Random scenes for differential fuzzing: valid by construction (the loader accepts every one),
// the same for the same seed on every platform, and biased toward what breaks renderers: counts
// of 0, every shader, cameras inside spheres, on planes and looking straight up or down, lengths
// across the whole supported range (tiny and huge radii, far offsets), spheres tangent to planes
// and to each other, lights on surfaces.

#include <cstdint>

#include "scene/scene.h"

namespace hexray::test {

struct GeneratedScene {
    Scene scene;
    // Something was placed exactly on a decision's boundary (a light or the camera on a surface,
    // a sphere tangent to a plane or another sphere, a ray grazing a plane), where many pixels
    // are honestly near-tied: the comparison's ambiguity limit does not apply.
    bool knifeEdge = false;
};

// A scene within the supported range (scene.h), 16 x 12 pixels, 1 sample per pixel.
GeneratedScene generateScene(std::uint64_t seed);

// A length just outside the supported range, for checking that the loader rejects it: the
// generator's scene for `seed` with one coordinate, radius or intensity moved out of range.
Scene generateOutOfRangeScene(std::uint64_t seed);

}  // namespace hexray::test
