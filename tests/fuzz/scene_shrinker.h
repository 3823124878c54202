#pragma once
// Makes a failing scene small and round enough to read, keeping the failure: a regression scene
// a person can reason about.

#include <cstddef>
#include <functional>

#include "scene/scene.h"

namespace hexray::test {

// A smaller, rounder scene for which `fails` still holds (`scene` must fail). Greedy, repeated
// until no step helps or `maxTries` candidates have been tried: drop nodes, lights and unused
// shaders; straighten the camera (no yaw, pitch or roll, a 90-degree field, the image's aspect);
// default the image's sampling and encoding; then each number in turn becomes 0, or is rounded
// to 1, 2 or 3 significant digits. Every candidate is a scene the loader accepts.
Scene shrinkScene(const Scene& scene, const std::function<bool(const Scene&)>& fails, std::size_t maxTries = 1500);

}  // namespace hexray::test
