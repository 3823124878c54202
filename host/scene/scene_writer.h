#pragma once
// Writes the scene model as a scene file that loads back into the same scene, every number
// exactly (shortest round-trip decimal): for generated scenes, such as the differential fuzzer's.

#include <string>

#include "scene/scene.h"

namespace hexray::inline scene {

// The scene as JSON text in the format scene_loader.h reads (one node per line, so that a
// large scene stays readable and a diff of two shows the node that changed).
std::string sceneToJson(const Scene& scene);

}  // namespace hexray::scene
