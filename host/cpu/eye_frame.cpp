#include "cpu/eye_frame.h"

#include <variant>

namespace hexray::inline cpu {

EyeFrameScene inEyeFrame(const Scene& world) {
    EyeFrameScene frame{world, world.camera.position};
    const glm::dvec3 eye = frame.eye;
    frame.scene.camera.position = glm::dvec3(0.0);
    for (PointLight& light : frame.scene.lights) {
        light.position -= eye;
    }
    for (Node& node : frame.scene.nodes) {
        if (auto* sphere = std::get_if<Sphere>(&node.geometry)) {
            sphere->center -= eye;
        } else {
            std::get<Plane>(node.geometry).height -= eye.y;
        }
    }
    return frame;
}

}  // namespace hexray::cpu
