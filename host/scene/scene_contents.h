#pragma once
// What a scene holds: its spheres counted, and in words, for messages: "1000000 spheres, 1 plane
// and 2 lights".

#include <algorithm>
#include <cstddef>
#include <string>
#include <variant>

#include "scene/scene.h"

namespace hexray::inline scene {

inline std::size_t countSpheres(const Scene& scene) {
    return static_cast<std::size_t>(std::count_if(scene.nodes.begin(), scene.nodes.end(), [](const Node& node) {
        return std::holds_alternative<Sphere>(node.geometry);
    }));
}

inline std::string sceneContents(const Scene& scene) {
    const std::size_t spheres = countSpheres(scene);
    const auto counted = [](std::size_t count, const char* one, const char* many) {
        return std::to_string(count) + " " + (count == 1 ? one : many);
    };
    return counted(spheres, "sphere", "spheres") + ", " + counted(scene.nodes.size() - spheres, "plane", "planes") +
           " and " + counted(scene.lights.size(), "light", "lights");
}

}  // namespace hexray::scene
