#pragma once
// Packs the scene model into the shader's layout (gpu_layout.h), in camera-relative float.

#include <vector>

#include "gpu/gpu_layout.h"
#include "scene/scene.h"

namespace hexray::gpu {

struct GpuScene {
    GpuFrame frame{};
    std::vector<GpuNode> nodes;
    std::vector<GpuLight> lights;
};

// Subtracts the eye position from every position in double before rounding to float, so a
// scene far from the world origin renders as precisely as one at it.
GpuScene packScene(const Scene& scene);

}  // namespace hexray::gpu
