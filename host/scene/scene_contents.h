#pragma once
// What a scene holds, in words, for messages: "1000000 spheres, 1 plane and 2 lights".

#include <cstddef>
#include <string>
#include <variant>

#include "scene/scene.h"

namespace hexray {

inline std::string sceneContents(const Scene& scene) {
    std::size_t spheres = 0;
    for (const Node& node : scene.nodes) {
        spheres += std::holds_alternative<Sphere>(node.geometry);
    }
    const auto counted = [](std::size_t count, const char* one, const char* many) {
        return std::to_string(count) + " " + (count == 1 ? one : many);
    };
    return counted(spheres, "sphere", "spheres") + ", " + counted(scene.nodes.size() - spheres, "plane", "planes") +
           " and " + counted(scene.lights.size(), "light", "lights");
}

}  // namespace hexray
