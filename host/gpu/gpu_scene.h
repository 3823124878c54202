#pragma once
// Packs the scene model into the shader's layout (gpu_layout.h).

#include <cstddef>
#include <cstdint>
#include <span>
#include <variant>
#include <vector>

#include "layout/gpu_layout.h"
#include "gpu/render_plan.h"
#include "scene/scene.h"

namespace hexray::inline gpu {

// Each (shader, geometry kind) pair the scene's nodes use, numbered in the order of first use: the
// looks (GpuLook) a node's `look` indexes.
class LookIndex {
public:
    LookIndex() = default;
    explicit LookIndex(const Scene& scene);

    std::uint32_t of(const Node& node) const { return lookOfSlot_[slot(node.shaderIndex, isSphere(node))]; }
    std::size_t size() const { return looks_.size(); }
    // Look l's shader (an index into Scene::shaders) and whether it shows spheres.
    std::uint32_t shaderIndex(std::size_t l) const { return looks_[l].shaderIndex; }
    bool showsSpheres(std::size_t l) const { return looks_[l].sphere; }

private:
    struct Pair {
        std::uint32_t shaderIndex;
        bool sphere;
    };
    static bool isSphere(const Node& node) { return std::holds_alternative<Sphere>(node.geometry); }
    static std::size_t slot(std::uint32_t shaderIndex, bool sphere) { return 2 * std::size_t(shaderIndex) + sphere; }

    std::vector<std::uint32_t> lookOfSlot_;  // by slot(): 2 per shader
    std::vector<Pair> looks_;
};

template <typename Real>
struct GpuScene {
    GpuFrame<Real> frame{};
    std::vector<GpuNode<Real>> nodes;
    std::vector<GpuLook<Real>> looks;
    std::vector<GpuLight<Real>> lights;
    LookIndex lookIndex;  // which of `looks` each node has
};

// Whether packScene packs the nodes, or leaves them to packNodesInto.
enum class NodePacking { Now, Later };

// The scene in the plan's placement, rounded to Real.
template <typename Real>
GpuScene<Real> packScene(const Scene& scene, const Placement& placement, NodePacking nodes = NodePacking::Now);

// packScene's nodes, all of them, written to `out` (straight into a mapped buffer: a large scene's
// packed nodes are not held on the host as well).
template <typename Real>
void packNodesInto(const Scene& scene, const Placement& placement, const LookIndex& looks, std::byte* out);

// The candidate lists' sphere records (gpu_layout.h's kCandidateSphereBytes each): the packed
// sphere nodes `sphereNodes`, in that order, with their looks, to `out`.
template <typename Real>
void packCandidateSpheresInto(const Scene& scene, const Placement& placement,
                              std::span<const std::uint32_t> sphereNodes, const LookIndex& looks, std::byte* out);

}  // namespace hexray::gpu
