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

// Whether packScene packs the nodes, or leaves them to packNodesInto.
enum class NodePacking { Now, Later };

// The scene in the plan's placement, rounded to Real.
template <typename Real>
GpuScene<Real> packScene(const Scene& scene, const Placement& placement, NodePacking nodes = NodePacking::Now);

// packScene's nodes, all of them, written to `out` (straight into a mapped buffer: a large scene's
// packed nodes are not held on the host as well).
template <typename Real>
void packNodesInto(const Scene& scene, const Placement& placement, std::byte* out);

// The candidate lists' sphere records: the packed sphere nodes `sphereNodes`, in that order, to `out`.
template <typename Real>
void packCandidateSpheresInto(const Scene& scene, const Placement& placement,
                              std::span<const std::uint32_t> sphereNodes, std::byte* out);

}  // namespace hexray::gpu
