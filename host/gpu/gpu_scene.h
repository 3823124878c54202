#pragma once
// Packs the scene model into the shader's layout (gpu_layout.h).

#include <vector>

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
    // Subtract the eye in double and divide every length by a power of two near the scene's
    // size before rounding to Real: far-off scenes lose no precision, and very large or very
    // small scenes neither overflow nor underflow. Both are exact for a power of two.
    CameraRelative,
    // World coordinates as given, rounded to Real: the textbook upload, for f32-naive.
    World,
};

template <typename Real>
GpuScene<Real> packScene(const Scene& scene, Placement placement);

// Whether the scene fits the uniform-buffer layout (see kSmallSceneCapacity).
bool isSmallScene(const Scene& scene);

// The pipeline's specialization for this scene (see gpu_layout.h).
ShaderSpecialization specializationFor(const Scene& scene, std::uint32_t outputMode);

// The power of two the camera-relative placement divides lengths by.
double placementScale(const Scene& scene);

}  // namespace hexray::gpu
