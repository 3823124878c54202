#pragma once
// Packs the scene model into the shader's layout (gpu_layout.h).

#include <vector>

#include "accel/bvh.h"
#include "gpu/gpu_layout.h"
#include "scene/scene.h"

namespace hexray::gpu {

template <typename Real>
struct GpuScene {
    GpuFrame<Real> frame{};
    std::vector<GpuNode<Real>> nodes;
    std::vector<GpuLight<Real>> lights;
};

enum class Placement {
    // Subtract the eye in double and divide every length by a power of two near the geometric
    // middle of the scene's lengths (placementScale) before rounding to Real: far-off scenes lose
    // no precision, and very large or very small scenes neither overflow nor underflow. Both are
    // exact for a power of two.
    CameraRelative,
    // World coordinates as given, rounded to Real: the textbook upload, for f32-naive.
    World,
};

template <typename Real>
GpuScene<Real> packScene(const Scene& scene, Placement placement);

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

// Whether the scene fits the uniform-buffer layout (see kSmallSceneCapacity).
bool isSmallScene(const Scene& scene);

// How the scene reaches the shader, each a variant of render.comp.
enum class SceneLayout {
    Uniform,     // small scenes: uniform buffers, loops the compiler unrolls
    Storage,     // storage buffers, every node for every ray
    StorageBvh,  // storage buffers and a BVH over the spheres (needs subgroup vote and ballot)
};

// Acceleration::Auto takes the BVH for scenes too large for the uniform layout when
// bvhPays(scene).
SceneLayout chooseSceneLayout(const Scene& scene, Acceleration acceleration, bool canTraverseBvh);

// The pipeline's specialization for this scene (see gpu_layout.h).
ShaderSpecialization specializationFor(const Scene& scene, std::uint32_t outputMode);

// The power of two the camera-relative placement divides lengths by.
double placementScale(const Scene& scene);

}  // namespace hexray::gpu
