#pragma once
// A bounding-volume hierarchy over a scene's spheres, built on the host. Planes are unbounded
// and stay out of it: whoever uses it tests them in a plain loop.
//
// The nodes are a flat array in depth-first order, so that the shader can later walk the same
// array from a storage buffer: an interior node's first child is the next node, its second
// child is at `firstOrSecondChild`. Bounds are double here (the CPU reference's precision); a
// float copy for the GPU must round them outward.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "accel/acceleration.h"
#include "scene/scene.h"
#include "scene/scene_contents.h"  // countSpheres

namespace hexray::inline accel {

struct BvhNode {
    glm::dvec3 boundsMin{0.0};  // the box around everything below this node
    glm::dvec3 boundsMax{0.0};
    // Leaf (count > 0): its spheres are sphereNodes[firstOrSecondChild .. + count).
    // Interior (count == 0): the index of the second child; the first is the next node.
    std::uint32_t firstOrSecondChild = 0;
    std::uint32_t count = 0;

    bool isLeaf() const { return count > 0; }
};

struct Bvh {
    std::vector<BvhNode> nodes;              // nodes[0] is the root; empty when there are no spheres
    std::vector<std::uint32_t> sphereNodes;  // indices into Scene::nodes, in leaf order
    // The planes, in scene order: with them listed, a ray's cost no longer includes a scan of
    // every node.
    std::vector<std::uint32_t> planeNodes;
};

inline constexpr std::uint32_t kMaxBvhLeafSpheres = 4;

// Binned SAH over sphere centres, leaves of at most kMaxBvhLeafSpheres spheres, built by
// `threadCount` threads (0: one per core). Deterministic: the same scene gives the same tree,
// on any number of threads.
Bvh buildBvh(const Scene& scene, unsigned threadCount = 0);

// Above this many spheres the CPU reference traverses a BVH instead of testing every sphere.
inline constexpr std::size_t kBvhMinSpheres = 16;
// Whether a BVH makes the CPU reference faster for this scene (more than kBvhMinSpheres spheres).
bool bvhPays(const Scene& scene);

}  // namespace hexray::accel
