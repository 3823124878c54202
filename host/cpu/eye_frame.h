#pragma once
// The frame the CPU reference traces in: the scene moved so that the eye sits at the origin, each
// position's difference from the eye taken once, in double. Traced in world coordinates, a hit
// eye + t d keeps t d only to the rounding of the eye's coordinates, which far from the origin can
// exceed the whole scene (a sphere of radius 1e11 seen from 1e36 collapses onto the eye); the
// decision margins already measure every error against distances from the eye (cpu_margins.h).

#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace hexray::inline cpu {

struct EyeFrameScene {
    Scene scene;     // the camera at the origin
    glm::dvec3 eye;  // the world position of the frame's origin: plane checker cells are world (x, z)
};

EyeFrameScene inEyeFrame(const Scene& world);

}  // namespace hexray::cpu
