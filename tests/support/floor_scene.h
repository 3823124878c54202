#pragma once
// The random-sphere scenes' floor, lights and shaders without spheres, seen from where a test
// puts the eye (looking along +z, tilted by `pitchDegrees`): for tests that add their own spheres.

#include <cstdint>

#include <glm/vec3.hpp>

#include "scene/random_spheres.h"

namespace hexray::test {

inline Scene floorSeenFrom(const glm::dvec3& eye, double pitchDegrees, double fovDegrees, std::uint32_t width,
                           std::uint32_t height) {
    Scene scene = makeRandomSpheresScene(0, 1);
    scene.image.width = width;
    scene.image.height = height;
    scene.camera.position = eye;
    scene.camera.pitchDegrees = pitchDegrees;
    scene.camera.fovDegrees = fovDegrees;
    return scene;
}

}  // namespace hexray::test
