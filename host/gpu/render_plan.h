#pragma once
// How the GPU renders one scene, decided in one place (planRender) and passed on as data to
// everything that renders: GpuRenderer, the bench, `hexray pixel` and the AOV pass. The float
// width, the formulation and the placement are separate decisions (pbrt-v4 keeps its rendering
// coordinate system apart from its float type for the same reason).

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "accel/acceleration.h"
#include "gpu/loop_budget.h"
#include "kernels/kernel.h"
#include "precision/arithmetic.h"
#include "precision/precision.h"
#include "scene/scene.h"

namespace hexray::inline accel {
struct CandidateLists;  // accel/candidate_lists.h
}  // namespace hexray::accel

namespace hexray::inline gpu {

// How the scene's data reaches the kernel.
enum class SceneLayout {
    Uniform,           // small scenes: uniform buffers, read at constant indices by a generated kernel
    Texels,            // texel buffers, every node for every ray (the data-driven kernel)
    TexelsCandidates,  // texel buffers, and per direction the spheres a ray can meet (candidate_lists.h)
};

struct DeviceAbilities {
    std::string name;                                   // for messages
    bool float64 = false;                               // shaderFloat64
    std::uint32_t maxTexelBufferElements = UINT32_MAX;  // candidate lists: their largest texel buffer
};

// Whether a generated kernel's tiles are classified by the work their rays can need, each class
// rendered by a kernel with just that work (tile_classes.h). Auto: when the render is large enough
// to repay the extra kernels' compile (render_plan.cpp).
enum class Culling { Auto, On, Off };

// What the caller asks for; planRender decides the rest.
struct PlanRequest {
    Precision precision = Precision::Auto;
    // Candidate lists or not, for scenes too large for a generated kernel.
    Acceleration acceleration = Acceleration::Auto;
    Culling culling = Culling::Auto;
    // False: the data-driven kernel even for a small scene. It is the same program for every scene,
    // so a test of many scenes (the differential fuzzer) compiles it once rather than per scene.
    bool generatedKernel = true;
    // The most loop passes one dispatch of the data-driven kernel may make in an invocation
    // (loop_budget.h). 0: the device's, kLavapipeLoopPasses on lavapipe and no limit elsewhere. A
    // smaller one splits renders into light batches on any device (tests force them so).
    std::uint64_t loopPassLimit = 0;
    // A generated kernel reads the scene's values from a buffer rather than having them compiled in
    // (SceneCode::valuesInBuffer): its pipeline serves every scene of the same structure.
    bool valuesInBuffer = false;
};

struct TileClassification;

// A render by tile classes: which class each tile is in, and each class's kernel.
struct TileClasses {
    std::shared_ptr<const TileClassification> classification;
    std::vector<Kernel> kernels;  // one per class
};

struct RenderPlan {
    Precision precision = Precision::F32;  // what the user calls it (f32, f64, f32-naive, f32-certified; never Auto)
    FloatWidth width = FloatWidth::F32;
    Formulation formulation = Formulation::Robust;
    Placement placement;
    SceneLayout layout = SceneLayout::Uniform;
    std::shared_ptr<const CandidateLists> candidates;  // TexelsCandidates only: the lists the kernel reads
    Kernel kernel;                                     // for the whole image (and for a traced pixel)
    // The data-driven kernel: every sphere takes the fast camera test (as a generated kernel decides
    // sphere by sphere), passed to it as FAST_CAMERA_TESTS_ID; and the fast test from every light
    // (FAST_SHADOW_TESTS_ID).
    bool fastCameraTests = false;
    bool fastShadowTests = false;
    TileClasses tileClasses;  // when culling: the kernels that render the image instead
    // The data-driven kernel: how a pixel's samples and lights are split between dispatches, each
    // within `loopPassLimit` (loop_budget.h), and what tracing a pixel needs in one.
    LightBatches lightBatches;
    std::uint64_t loopPassLimit = UINT64_MAX;
    std::uint64_t tracePasses = 0;
    std::vector<std::string> warnings;  // what `render` tells the user: a precision overruled
    // f32-certified: the f64 plan that renders again, from a list, the pixels the kernel flags in doubt.
    std::shared_ptr<const RenderPlan> fallback;
};

// Decides everything about how the GPU renders `scene`. Throws PlanRefused: NoFloat64 for
// Precision::F64 on a device without float64, PastLoopLimit for a scene a pixel of which needs more
// loop passes for one sample and one light than the device runs (loop_budget.h).
RenderPlan planRender(const Scene& scene, const PlanRequest& request, const DeviceAbilities& device);

// The precision planRender chooses (never Auto); throws like it. f32 asked for a scene whose
// lengths float32 cannot hold (float32RangeProblem) becomes f64, with a warning in `warnings`.
// f32-certified for a scene it cannot certify (certificationProblem; `generatedKernel` false: the
// data-driven kernel) becomes f64, with a warning too.
Precision resolvePrecision(const Scene& scene, Precision requested, const DeviceAbilities& device,
                           std::vector<std::string>* warnings = nullptr, bool generatedKernel = true);

// The placement a precision uses for a scene: camera-relative and rescaled, or world
// coordinates as given (f32-naive).
Placement placementFor(const Scene& scene, Formulation formulation);

// The power of two the camera-relative placement divides lengths by.
double placementScale(const Scene& scene);

// Whether `plane` may shadow a point the camera sees from `light`. A plane blocks a segment only
// when its ends lie strictly on opposite sides, and every point the camera sees lies on the eye's
// side of a plane or on it (a camera ray stops at the plane): so not when the eye and the light lie
// strictly on one side.
bool planeMayShadow(const Plane& plane, const glm::dvec3& eye, const glm::dvec3& light);

// Whether `sphere` holds the eye strictly inside and `light` strictly outside. Every point the
// camera sees then lies in the closed ball, so the sphere blocks the light from each of them that
// faces it (the others are unlit anyway): the light needs no shadow test, which from the light
// could not resolve a sphere many radii away, or a grazing segment, in float32.
bool sphereHidesLight(const Sphere& sphere, const glm::dvec3& eye, const glm::dvec3& light);

// Whether some sphere of the scene hides `light` from every visible point (sphereHidesLight).
bool isLightHiddenFromView(const Scene& scene, const PointLight& light);

// Whether the scene fits the uniform-buffer layout (SMALL_SCENE_CAPACITY nodes and lights),
// and so gets a generated kernel.
bool isSmallScene(const Scene& scene);

}  // namespace hexray::gpu
