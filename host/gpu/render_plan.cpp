#include "gpu/render_plan.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include <glm/geometric.hpp>

#include "camera/camera.h"
#include "accel/candidate_lists.h"
#include "kernels/kept_kernels.h"
#include "kernels/prebuilt_kernels.h"
#include "gpu/certainty_bound.h"
#include "gpu/plan_refused.h"
#include "gpu/tile_classes.h"
#include "util/parallel_parts.h"
#include "scene/scene_contents.h"
#include "shader_interface.h"

namespace hexray::inline gpu {
namespace {

// ---------------------------------------------------------------- tunables
// The robust sphere test (the stable root pair, the normal from the chord) is needed only for rays
// from an origin close to the sphere's surface, where the near root cancels and a camera or light
// on the sphere must see its power of exactly 0 as a root at 0. The fast form serves an origin at
// distance d from the centre of a sphere of radius r when d >= kFastMinOutside * r or
// d <= kFastMaxInside * r: for a camera ray the Hearn-Baker discriminant with the plain roots and
// the normal from the hit point; for a shadow ray from a light, which decides only blocked or
// not, b^2 - power when also d <= kFastMaxShadowOutside * r (the discriminant's error grows like
// d^2 / r; at 32 r it is still a hundredth of the band compare calls ambiguous, 2^-17 of the
// distances), else the robust test. The data-driven kernel, which has no power from the host for a
// light, takes the camera's fast form from the lights too (sphereCrossesSegmentFast: the error is
// that of l, at any distance), when every sphere would take it from every light.
constexpr double kFastMinOutside = 1.25;
constexpr double kFastMaxInside = 0.5;
constexpr double kFastMaxShadowOutside = 32.0;
// The data-driven kernel takes the fast tests for the whole scene when every (origin, sphere) pair
// would; past this many pairs it is not checked, and the robust tests serve.
constexpr std::size_t kFastTestChecks = std::size_t{1} << 24;
// Culling: at most this many tile classes, each a kernel that glslang and the driver compile
// (cached on disk by both). Auto culls only renders of at least kCullingMinSamples samples: on
// lavapipe a class kernel's compile costs about as much as culling saves on 5 to 50 million samples
// (warm or cold driver cache), so a single frame of ordinary size renders faster whole.
constexpr std::size_t kMaxTileClasses = 12;
static_assert(kMaxTileClasses < kKeptPipelines, "a render holds a pipeline per tile class at once");
constexpr std::uint64_t kCullingMinSamples = std::uint64_t{32} << 20;

// The first sphere that hides `light` from every visible point (sphereHidesLight), if any.
std::optional<std::uint32_t> sphereHidingLight(const Scene& scene, const PointLight& light) {
    for (std::uint32_t i = 0; i < scene.nodes.size(); ++i) {
        const auto* sphere = std::get_if<Sphere>(&scene.nodes[i].geometry);
        if (sphere && sphereHidesLight(*sphere, scene.camera.position, light.position)) {
            return i;
        }
    }
    return std::nullopt;
}

// How a ray from `origin`, the same for every pixel (the eye, or a light), meets the sphere.
SphereTest sphereTestFor(const Sphere& sphere, const glm::dvec3& origin, Formulation formulation, double maxOutside) {
    if (formulation == Formulation::Textbook) {
        return SphereTest::Textbook;
    }
    const double distance = glm::length(sphere.center - origin);
    const double r = sphere.radius;
    const bool outside = distance >= kFastMinOutside * r && distance <= maxOutside * r;
    return outside || distance <= kFastMaxInside * r ? SphereTest::Fast : SphereTest::Robust;
}

std::vector<glm::dvec3> lightPositions(const Scene& scene) {
    std::vector<glm::dvec3> positions;
    for (const PointLight& light : scene.lights) {
        positions.push_back(light.position);
    }
    return positions;
}

// Whether every sphere takes the fast test from the eye, and from every light (a walk over the
// nodes across cores); no for more than kFastTestChecks pairs of a sphere and one of those
// origins, which would take longer to check than the robust tests cost.
struct FastTests {
    bool camera = true;
    bool shadow = true;
};

FastTests everySphereFast(const Scene& scene, Formulation formulation) {
    const std::vector<glm::dvec3> lights = lightPositions(scene);
    const auto fastFrom = [&](const Sphere& sphere, const glm::dvec3& origin) {
        return sphereTestFor(sphere, origin, formulation, std::numeric_limits<double>::infinity()) == SphereTest::Fast;
    };
    const double nodes = double(scene.nodes.size());
    const FastTests checked{nodes <= double(kFastTestChecks), nodes * double(lights.size()) <= double(kFastTestChecks)};
    if (!checked.camera && !checked.shadow) {
        return {false, false};
    }
    return reduceAcrossCores(
        scene.nodes.size(), kNodesPerPart, checked,
        [&](FastTests& part, std::size_t i) {
            if (const auto* sphere = std::get_if<Sphere>(&scene.nodes[i].geometry)) {
                part.camera = part.camera && fastFrom(*sphere, scene.camera.position);
                part.shadow = part.shadow && std::ranges::all_of(lights, [&](const glm::dvec3& light) {
                                  return fastFrom(*sphere, light);
                              });
            }
        },
        [](FastTests& total, const FastTests& part) {
            total.camera = total.camera && part.camera;
            total.shadow = total.shadow && part.shadow;
        });
}

// The shadow tests a light needs: no plane that cannot shadow it (planeMayShadow); a sphere that
// holds the eye and not the light blocks it from every visible point, and no other test is needed.
// The textbook formulation tests every node, as a course would.
std::vector<ShadowTest> shadowTestsFor(const Scene& scene, const PointLight& light, Formulation formulation) {
    std::vector<ShadowTest> tests;
    if (formulation == Formulation::Robust) {
        if (const auto hiding = sphereHidingLight(scene, light)) {
            return {ShadowTest{.node = *hiding, .hidesLight = true}};
        }
    }
    for (std::uint32_t i = 0; i < scene.nodes.size(); ++i) {
        if (const auto* plane = std::get_if<Plane>(&scene.nodes[i].geometry)) {
            if (formulation == Formulation::Textbook || planeMayShadow(*plane, scene.camera.position, light.position)) {
                tests.push_back({i, SphereTest::Robust});
            }
        } else {
            const Sphere& sphere = std::get<Sphere>(scene.nodes[i].geometry);
            tests.push_back({i, sphereTestFor(sphere, light.position, formulation, kFastMaxShadowOutside),
                             glm::length(light.position - sphere.center) > sphere.radius});
        }
    }
    return tests;
}

std::uint32_t shaderKind(const Shader& shader) {
    if (std::holds_alternative<ConstantShader>(shader))
        return gpu::SHADER_CONSTANT;
    if (std::holds_alternative<LambertShader>(shader))
        return gpu::SHADER_LAMBERT;
    return gpu::SHADER_CHECKER;
}

SceneCode sceneCodeFor(const Scene& scene, const RenderPlan& plan) {
    SceneCode code;
    code.width = plan.width;
    code.formulation = plan.formulation;
    const glm::dvec3 eye = scene.camera.position;
    for (const Node& node : scene.nodes) {
        NodeCode nodeCode;
        nodeCode.shader = shaderKind(scene.shaders[node.shaderIndex]);
        if (const auto* sphere = std::get_if<Sphere>(&node.geometry)) {
            nodeCode.geometry = gpu::GEOMETRY_SPHERE;
            nodeCode.sphereTest =
                sphereTestFor(*sphere, eye, plan.formulation, std::numeric_limits<double>::infinity());
            nodeCode.cameraOutside =
                plan.formulation == Formulation::Robust && glm::length(sphere->center - eye) > sphere->radius;
        } else {
            nodeCode.geometry = gpu::GEOMETRY_PLANE;
        }
        code.nodes.push_back(nodeCode);
    }
    for (const PointLight& light : scene.lights) {
        code.shadowTests.push_back(shadowTestsFor(scene, light, plan.formulation));
    }
    code.eyeAtOrigin = plan.placement.cameraRelative;
    return code;
}

// Candidate lists pay as soon as the data-driven kernel has spheres to skip.
bool wantsCandidates(const Scene& scene, const PlanRequest& request) {
    if (request.acceleration == Acceleration::None || countSpheres(scene) == 0) {
        return false;
    }
    return request.acceleration == Acceleration::Always || !isSmallScene(scene) || !request.generatedKernel;
}

// Whether the device holds each of the lists' texel buffers (candidate_buffers.h).
bool fitsDevice(const CandidateLists& lists, FloatWidth width, const DeviceAbilities& device) {
    const std::size_t record =
        width == FloatWidth::F64 ? gpu::kCandidateSphereBytes<double> : gpu::kCandidateSphereBytes<float>;
    const std::size_t largest =
        std::max({lists.entries.size(), lists.cellStarts.size(), lists.sphereNodes.size() * record / kTexelBytes,
                  lists.gridByteCount() / kTexelBytes});
    return largest <= device.maxTexelBufferElements;
}

// Textbook kernels are never culled: they show what a course's renderer does.
bool cullingPays(const Scene& scene, const RenderPlan& plan, Culling culling) {
    if (culling == Culling::Off || plan.formulation == Formulation::Textbook) {
        return false;
    }
    const std::uint64_t samples = std::uint64_t(scene.image.width) * scene.image.height * scene.image.samplesPerPixel;
    return culling == Culling::On || samples >= kCullingMinSamples;
}

// A kernel per tile class; none when every tile needs the whole scene's work.
TileClasses tileClassesFor(const Scene& scene, const SceneCode& code) {
    auto classification = std::make_shared<TileClassification>(classifyTiles(scene, code, kMaxTileClasses));
    TileClasses classes;
    const bool culls =
        std::any_of(classification->classes.begin(), classification->classes.end(),
                    [&](const TileWork& work) { return workPerPixel(codeForClass(code, work)) != workPerPixel(code); });
    if (!culls) {
        return classes;
    }
    for (std::size_t c = 0; c < classification->classes.size(); ++c) {
        SceneCode classCode = codeForClass(code, classification->classes[c]);
        classCode.tileList = true;
        classes.kernels.push_back(Kernel{"generated for tile class " + std::to_string(c + 1) + " of " +
                                             std::to_string(classification->classes.size()),
                                         std::make_shared<const SceneCode>(std::move(classCode)),
                                         {}});
    }
    classes.classification = std::move(classification);
    return classes;
}

// The loop passes one dispatch may make on `device`: lavapipe's limit, or none (loop_budget.h).
std::uint64_t loopPassLimitOf(const PlanRequest& request, const DeviceAbilities& device) {
    if (request.loopPassLimit != 0) {
        return request.loopPassLimit;
    }
    return device.name.find("llvmpipe") != std::string::npos ? kLavapipeLoopPasses : UINT64_MAX;
}

// The data-driven kernel's light batches within the device's loop limit (a generated kernel's
// loops are unrolled); a scene one sample and one light of which pass it is refused.
void planLoops(const Scene& scene, const PlanRequest& request, const DeviceAbilities& device, RenderPlan& plan) {
    if (plan.layout == SceneLayout::Uniform) {
        return;
    }
    plan.loopPassLimit = loopPassLimitOf(request, device);
    const LoopPasses passes = loopPasses(scene, plan.candidates.get());
    plan.tracePasses = tracePasses(passes, scene.image.samplesPerPixel);
    if (auto batches = planLightBatches(passes, scene.image.samplesPerPixel, plan.loopPassLimit)) {
        plan.lightBatches = std::move(*batches);
        return;
    }
    throw PlanRefused(Refusal::PastLoopLimit,
                      "a pixel of this scene (" + sceneContents(scene) + ") may need " +
                          std::to_string(smallestDispatchPasses(passes)) +
                          " loop passes for a single sample and light (its camera ray and its longest shadow test), "
                          "and " +
                          device.name + " ends a shader's loops after " + std::to_string(plan.loopPassLimit) +
                          " in all: it cannot render it right",
                      "use --backend cpu");
}

}  // namespace

Precision resolvePrecision(const Scene& scene, Precision requested, const DeviceAbilities& device,
                           std::vector<std::string>* warnings, bool generatedKernel) {
    if (requested == Precision::Auto) {
        return choosePrecision(scene, device.float64);
    }
    if (requested == Precision::F32Certified && device.float64) {
        auto problem = float32RangeProblem(scene);
        if (!problem) {
            problem = certificationProblem(scene, generatedKernel);
        }
        if (problem) {
            if (warnings) {
                warnings->push_back("f32-certified cannot render this scene (" + *problem + "); rendering in f64");
            }
            return Precision::F64;
        }
    }
    if (const auto problem = float32RangeProblem(scene); problem && requested == Precision::F32 && device.float64) {
        if (warnings) {
            warnings->push_back("float32 cannot hold this scene (" + *problem + "); rendering in f64 instead");
        }
        return Precision::F64;
    }
    if ((requested == Precision::F64 || requested == Precision::F32Certified) && !device.float64) {
        throw PlanRefused(Refusal::NoFloat64,
                          "--precision " + std::string(precisionName(requested)) + " needs shaderFloat64, which " +
                              device.name + " does not have",
                          "use --precision f32");
    }
    return requested;
}

bool sphereHidesLight(const Sphere& sphere, const glm::dvec3& eye, const glm::dvec3& light) {
    return glm::length(sphere.center - eye) < sphere.radius && glm::length(light - sphere.center) > sphere.radius;
}

bool planeMayShadow(const Plane& plane, const glm::dvec3& eye, const glm::dvec3& light) {
    const double eyeSide = eye.y - plane.height;
    const double lightSide = light.y - plane.height;
    return !((eyeSide > 0 && lightSide > 0) || (eyeSide < 0 && lightSide < 0));
}

bool isLightHiddenFromView(const Scene& scene, const PointLight& light) {
    return sphereHidingLight(scene, light).has_value();
}

bool isSmallScene(const Scene& scene) {
    return scene.nodes.size() <= gpu::SMALL_SCENE_CAPACITY && scene.lights.size() <= gpu::SMALL_SCENE_CAPACITY;
}

double placementScale(const Scene& scene) {
    // The power of two nearest the geometric middle of the scene's lengths: the squares of the
    // smallest and the largest then stay equally far inside the number range, and an object far out
    // of view moves the scale by the square root of its distance only (a power of two: no visible
    // pixel changes, as long as the range fits; see float32RangeProblem).
    const MagnitudeRange range = sceneMagnitudes(scene);
    return range.smallest > 0 ? std::exp2(std::round(0.5 * (std::log2(range.smallest) + std::log2(range.largest))))
                              : 1.0;
}

Placement placementFor(const Scene& scene, Formulation formulation) {
    if (formulation == Formulation::Textbook) {
        return Placement{false, glm::dvec3(0.0), 1.0};
    }
    return Placement{true, makePixelSheet(scene.camera, sheetAspect(scene)).origin, placementScale(scene)};
}

namespace {

// f32-certified's f64 pass: the scene's f64 kernel, whole (no tile classes), for a list of pixels.
std::shared_ptr<const RenderPlan> fallbackPlan(const Scene& scene, const PlanRequest& request,
                                               const DeviceAbilities& device) {
    PlanRequest f64 = request;
    f64.precision = Precision::F64;
    f64.culling = Culling::Off;
    RenderPlan plan = planRender(scene, f64, device);
    SceneCode code = *plan.kernel.code;
    code.pixelList = true;
    plan.kernel = Kernel{"generated for the scene's pixels in doubt", std::make_shared<const SceneCode>(code), {}};
    return std::make_shared<const RenderPlan>(std::move(plan));
}

}  // namespace

RenderPlan planRender(const Scene& scene, const PlanRequest& request, const DeviceAbilities& device) {
    RenderPlan plan;
    plan.precision = resolvePrecision(scene, request.precision, device, &plan.warnings, request.generatedKernel);
    plan.width = plan.precision == Precision::F64 ? FloatWidth::F64 : FloatWidth::F32;
    plan.formulation = plan.precision == Precision::F32Naive ? Formulation::Textbook : Formulation::Robust;
    plan.placement = placementFor(scene, plan.formulation);
    plan.layout = isSmallScene(scene) && request.generatedKernel ? SceneLayout::Uniform : SceneLayout::Texels;
    if (wantsCandidates(scene, request)) {
        auto lists = buildCandidateLists(scene, plan.placement, plan.width, plan.formulation);
        if (lists && fitsDevice(*lists, plan.width, device)) {
            plan.candidates = std::make_shared<const CandidateLists>(std::move(*lists));
            plan.layout = SceneLayout::TexelsCandidates;
        }
    }
    if (plan.layout == SceneLayout::Uniform) {
        SceneCode code = sceneCodeFor(scene, plan);
        code.valuesInBuffer = request.valuesInBuffer;
        code.certified = plan.precision == Precision::F32Certified;
        plan.kernel = Kernel{"generated for the scene", std::make_shared<const SceneCode>(code), {}};
        if (cullingPays(scene, plan, request.culling)) {
            plan.tileClasses = tileClassesFor(scene, code);
        }
    } else {
        const bool candidates = plan.layout == SceneLayout::TexelsCandidates;
        plan.kernel = Kernel{dataDrivenKernelName(plan.width, plan.formulation, candidates), nullptr,
                             dataDrivenKernel(plan.width, plan.formulation, candidates)};
        const FastTests fast = everySphereFast(scene, plan.formulation);
        plan.fastCameraTests = fast.camera;
        plan.fastShadowTests = fast.shadow;
    }
    planLoops(scene, request, device, plan);
    if (plan.precision == Precision::F32Certified) {
        plan.fallback = fallbackPlan(scene, request, device);
    }
    return plan;
}

}  // namespace hexray::gpu
