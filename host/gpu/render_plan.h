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

#include "accel/bvh.h"  // Acceleration
#include "gpu/precision.h"
#include "scene/scene.h"

namespace hexray {

struct CandidateLists;  // gpu/candidate_lists.h

// The shader's arithmetic for positions and distances (colours are always float).
enum class FloatWidth { F32, F64 };

// Textbook: the formulas as a course writes them (f32-naive). Robust: cancellation-free
// intersections, hit points on the surface, error-bound shadow offsets; a generated kernel
// still uses the cheaper fast form for the nodes whose conditioning allows it (NodeCode).
enum class Formulation { Textbook, Robust };

// Where world coordinates go before they are rounded to the shader's floats.
struct Placement {
    // Camera-relative: subtract the eye in double and divide every length by `scale`, a power of
    // two near the geometric middle of the scene's lengths (placementScale), so both steps are
    // exact: far-off scenes lose no precision, and very large or very small ones neither overflow
    // nor underflow. Otherwise world coordinates as given.
    bool cameraRelative = true;
    glm::dvec3 origin{0.0};  // the world point placed at 0: the eye, or 0
    double scale = 1.0;
    glm::dvec3 position(const glm::dvec3& world) const { return (world - origin) / scale; }
    double length(double world) const { return world / scale; }
};

// How the scene's data reaches the kernel.
enum class SceneLayout {
    Uniform,     // small scenes: uniform buffers, read at constant indices by a generated kernel
    Storage,            // storage buffers, every node for every ray (the data-driven kernel)
    StorageCandidates,  // storage buffers, and per direction the spheres a ray can meet (candidate_lists.h)
};

// How a camera ray meets one sphere (generated kernels).
enum class SphereTest {
    Robust,    // Hearn-Baker discriminant and the stable root pair; normal from the chord
    Fast,      // b^2 - power with the host's power of the eye; normal from o + t d
    Textbook,  // b^2 - 4ac, as f32-naive does everywhere
};

// What a generated kernel does for one node.
struct NodeCode {
    std::uint32_t geometry = 0;  // gpu::GEOMETRY_*
    std::uint32_t shader = 0;    // gpu::SHADER_*
    SphereTest sphereTest = SphereTest::Robust;  // spheres only
    // Spheres: the eye is outside, so a point the camera sees on it faces away from the sphere
    // and the sphere cannot shadow it (convexity); its shadow rays skip it.
    bool cameraOutside = false;
    // Whether camera rays test it: false in a tile class none of whose rays can hit it
    // (tile_classes.h); its values may still serve shadow tests.
    bool cameraTested = true;
};

// One shadow test a light needs (generated kernels): whether `node` lies strictly between a lit
// point and the light. Robust kernels test spheres from the light, which is the same origin for
// every pixel, so the test's conditioning is known here (and the host computes the light's power
// with respect to the sphere in double); planes by the sides of the segment's ends.
struct ShadowTest {
    std::uint32_t node = 0;
    SphereTest sphereTest = SphereTest::Robust;  // spheres only
    bool lightOutside = true;                    // spheres: the light lies outside the sphere
    // Spheres: it holds the eye and not the light (sphereHidesLight), so it blocks the light from
    // every visible point: decided without arithmetic, and the light's only test.
    bool hidesLight = false;
    // False in a tile class no point of which it can shadow (tile_classes.h): the kernel leaves the
    // test out, while its values stay among the specialization constants, the same for every class.
    bool tested = true;
};

// A kernel written for one scene's structure (host/gpu/kernel_generator.h): the node tests
// unrolled in order, only the shaders, lights and shadow tests the scene uses. The scene's values
// reach it as specialization constants (host/gpu/scene_constants.h), which lavapipe compiles in as
// literals: scenes of the same structure share the SPIR-V, and the driver builds a pipeline per
// scene.
struct SceneCode {
    std::vector<NodeCode> nodes;
    // Per light, the nodes that may shadow it: a plane with the eye and the light strictly on one
    // side cannot come between a visible point and the light.
    std::vector<std::vector<ShadowTest>> shadowTests;
    FloatWidth width = FloatWidth::F32;
    Formulation formulation = Formulation::Robust;
    bool eyeAtOrigin = true;  // camera-relative placement: camera rays start at exactly 0
    bool tileList = false;    // a tile class's kernel: it renders the tiles listed for it
};

// The program a plan runs: GLSL written for the scene (compiled at run time and cached), or
// SPIR-V built with hexray (the data-driven kernels, or a caller's own, such as the bench's
// yardstick). The SPIR-V must outlive the plan.
struct Kernel {
    std::string name;                       // for messages and the pipeline cache
    std::shared_ptr<const SceneCode> code;  // a generated kernel: what to generate
    std::span<const std::uint32_t> spirv;   // else: the program itself
};

struct DeviceAbilities {
    std::string name;            // for messages
    bool float64 = false;        // shaderFloat64
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
};

struct TileClassification;

// A render by tile classes: which class each tile is in, and each class's kernel.
struct TileClasses {
    std::shared_ptr<const TileClassification> classification;
    std::vector<Kernel> kernels;  // one per class
};

struct RenderPlan {
    Precision precision = Precision::F32;  // what the user calls it (f32, f64, f32-naive; never Auto)
    FloatWidth width = FloatWidth::F32;
    Formulation formulation = Formulation::Robust;
    Placement placement;
    SceneLayout layout = SceneLayout::Uniform;
    std::shared_ptr<const CandidateLists> candidates;  // StorageCandidates only: the lists the kernel reads
    Kernel kernel;                                     // for the whole image (and for a traced pixel)
    TileClasses tileClasses;                           // when culling: the kernels that render the image instead
    std::vector<std::string> warnings;  // what `render` tells the user: a precision overruled
};

// Decides everything about how the GPU renders `scene`. Throws VulkanError (NoFloat64) for
// Precision::F64 on a device without float64.
RenderPlan planRender(const Scene& scene, const PlanRequest& request, const DeviceAbilities& device);

// The precision planRender chooses (never Auto); throws like it. f32 asked for a scene whose
// lengths float32 cannot hold (float32RangeProblem) becomes f64, with a warning in `warnings`.
Precision resolvePrecision(const Scene& scene, Precision requested, const DeviceAbilities& device,
                           std::vector<std::string>* warnings = nullptr);

// The placement a precision uses for a scene: camera-relative and rescaled, or world
// coordinates as given (f32-naive).
Placement placementFor(const Scene& scene, Formulation formulation);

// The power of two the camera-relative placement divides lengths by.
double placementScale(const Scene& scene);

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

}  // namespace hexray
