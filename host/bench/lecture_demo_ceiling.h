#pragma once
// `hexray bench`'s yardstick for the lecture demo scene: host/bench/lecture_demo_ceiling.comp, a
// hand-written kernel with the scene's values as literals, run through the renderer's public
// interface as a plan whose kernel is that program.

#include "gpu/gpu_renderer.h"
#include "gpu/render_plan.h"
#include "scene/scene.h"

namespace hexray::inline bench {

// Whether the kernel renders `scene`: the nodes, shaders, lights, background, ambient and eye
// of scenes/lecture-demo.json, one sample per pixel. Image size, camera orientation, field of
// view, sampling and output encoding may differ (the kernel takes them from the host).
bool isLectureDemoScene(const Scene& scene);

// The renderer's f32 plan for `scene` with the hand-written kernel in place of its own. Throws
// std::invalid_argument unless isLectureDemoScene(scene).
RenderPlan lectureDemoCeilingPlan(const GpuRenderer& renderer, const Scene& scene);

}  // namespace hexray::bench
