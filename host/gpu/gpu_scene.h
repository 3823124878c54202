#pragma once
// Packs the scene model into the shader's layout (gpu_layout.h).

#include <vector>

#include "accel/bvh.h"
#include "gpu/gpu_layout.h"
#include "gpu/render_plan.h"
#include "scene/scene.h"

namespace hexray::gpu {

template <typename Real>
struct GpuScene {
    GpuFrame<Real> frame{};
    std::vector<GpuNode<Real>> nodes;
    std::vector<GpuLight<Real>> lights;
};

// The scene in the plan's placement, rounded to Real.
template <typename Real>
GpuScene<Real> packScene(const Scene& scene, const Placement& placement);

// A scene's BVH as the shader walks it (see GpuBvhNode).
template <typename Real>
struct GpuBvh {
    std::vector<GpuBvhNode<Real>> nodes;
    // Scene node indices: every plane (frame.planeCount of them, in scene order), then the
    // spheres in leaf order.
    std::vector<std::uint32_t> primitives;
    std::uint32_t depth = 0;  // nodes on the longest root-to-leaf path
};

// `bvh`'s bounds recomputed from the packed spheres, in their placement and precision.
template <typename Real>
GpuBvh<Real> packBvh(const Scene& scene, const Bvh& bvh, const GpuScene<Real>& packed);

}  // namespace hexray::gpu
