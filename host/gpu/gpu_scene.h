#pragma once
// Packs the scene model into the shader's layout (gpu_layout.h).

#include <cstdint>
#include <span>
#include <vector>

#include "layout/gpu_layout.h"
#include "gpu/render_plan.h"
#include "scene/scene.h"

namespace hexray::inline gpu {

template <typename Real>
struct GpuScene {
    GpuFrame<Real> frame{};
    std::vector<GpuNode<Real>> nodes;
    std::vector<GpuLight<Real>> lights;
};

// The scene in the plan's placement, rounded to Real.
template <typename Real>
GpuScene<Real> packScene(const Scene& scene, const Placement& placement);

// The candidate lists' sphere records: the packed sphere nodes `nodes`, in that order.
template <typename Real>
std::vector<GpuCandidateSphere<Real>> packCandidateSpheres(const GpuScene<Real>& packed,
                                                           std::span<const std::uint32_t> nodes);

}  // namespace hexray::gpu
