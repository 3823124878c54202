#pragma once
// Families of generated hard rays for the accuracy oracle (oracle.h). Each ray is a scene whose
// one pixel (a 1x1 image, sampled at its centre) looks along the ray: the camera stands at the
// ray's origin and is turned toward its direction, so both renderers trace it as a pixel. The
// direction each renderer really follows differs from the aimed one by its rounding; the oracle
// judges the one it reports.

#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace hexray::oracle {

struct HardRay {
    std::string family;
    std::string name;  // what is special about this one
    Scene scene;
};

// Every family, in a fixed order: tiny spheres far away, a huge sphere as the ground, rays
// tangent to a sphere, origins on a sphere, origins near a sphere, the lecture's scene far from
// the origin, rays grazing a plane, origins on and near a plane, checker edges far away, shadow
// edges, and the lecture's scene scaled by 1e30 and 1e-30.
std::vector<HardRay> hardRays();

// A 1x1 scene with the camera at `origin` turned toward `direction` (yaw and pitch only).
Scene aimedScene(Scene scene, const glm::dvec3& origin, const glm::dvec3& direction);

}  // namespace hexray::oracle
