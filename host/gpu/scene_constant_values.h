#pragma once
// The values of a generated kernel's specialization constants (kernels/scene_constants.h) from the
// scene as packed for the device.

#include <cstddef>
#include <vector>

#include "gpu/gpu_scene.h"
#include "kernels/scene_constants.h"

namespace hexray::inline gpu {

// The constants' values as the driver takes them: each component a Real (the scene's packed
// width) or a float, in order, no padding.
template <typename Real>
std::vector<std::byte> sceneConstantValues(const std::vector<SceneConstant>& constants,
                                           const gpu::GpuScene<Real>& scene);

}  // namespace hexray::gpu
