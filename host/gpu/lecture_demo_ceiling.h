#pragma once
// The scene shaders/lecture_demo_ceiling.comp hard-wires: lavapipe's throughput ceiling for
// it is `hexray bench`'s yardstick (GpuRenderer::renderLectureDemoCeiling).

#include "scene/scene.h"

namespace hexray {

// Whether the kernel renders `scene`: the nodes, shaders, lights, background, ambient and eye
// of scenes/lecture-demo.json, one sample per pixel. Image size, camera orientation, field of
// view, sampling and output encoding may differ (the kernel takes them from the host).
bool isLectureDemoScene(const Scene& scene);

}  // namespace hexray
