#pragma once
// Whether a renderer uses its acceleration structure: the CPU reference's BVH (bvh.h), the GPU's
// candidate lists (candidate_lists.h).

namespace hexray::inline accel {

// How a renderer finds what a ray meets. Each renderer's Auto decides when its acceleration
// structure pays; the others exist for tests and benchmarks, not for users.
enum class Acceleration {
    Auto,
    None,    // every node for every ray
    Always,  // the renderer's structure whenever it can use one: the CPU reference's BVH over the
             // spheres, the GPU's candidate lists (candidate_lists.h)
};

}  // namespace hexray::accel
