// The render plan's decisions (host/gpu/render_plan.h), one place for each: the precision and what
// it implies, the layout, and per node and light which formulation a generated kernel uses.

#include <algorithm>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "accel/candidate_lists.h"
#include "kernels/kernel_generator.h"
#include "gpu/render_plan.h"
#include "scene/scene_loader.h"
#include "scene/scene_contents.h"
#include "shader_interface.h"
#include "support/test_paths.h"
#include "gpu/plan_refused.h"

namespace hexray {
namespace {

const DeviceAbilities kLavapipe{"lavapipe", true};

Scene twoSpheres(const Sphere& first, const Sphere& second, const glm::dvec3& light) {
    Scene scene;
    scene.camera.position = {0, 0, 0};
    scene.shaderNames = {"matte"};
    scene.shaders = {LambertShader{Color(0.5)}};
    scene.nodes = {Node{first, 0}, Node{second, 0}};
    scene.lights = {PointLight{light, Color(1), 1000}};
    return scene;
}

TEST(RenderPlan, PrecisionDecidesWidthFormulationAndPlacement) {
    const Scene scene = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    const RenderPlan f32 = planRender(scene, {Precision::F32}, kLavapipe);
    EXPECT_EQ(f32.width, FloatWidth::F32);
    EXPECT_EQ(f32.formulation, Formulation::Robust);
    EXPECT_TRUE(f32.placement.cameraRelative);
    EXPECT_EQ(f32.placement.origin, scene.camera.position);
    const RenderPlan f64 = planRender(scene, {Precision::F64}, kLavapipe);
    EXPECT_EQ(f64.width, FloatWidth::F64);
    const RenderPlan naive = planRender(scene, {Precision::F32Naive}, kLavapipe);
    EXPECT_EQ(naive.formulation, Formulation::Textbook);
    EXPECT_FALSE(naive.placement.cameraRelative);
    EXPECT_EQ(naive.placement.scale, 1.0);
    // Auto is decided here, never passed on.
    EXPECT_EQ(planRender(scene, {Precision::Auto}, kLavapipe).precision, Precision::F32);
    EXPECT_EQ(planRender(scene, {Precision::Auto}, kLavapipe).layout, SceneLayout::Uniform);
}

TEST(RenderPlan, F64OnADeviceWithoutItIsRefused) {
    const Scene scene = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    EXPECT_THROW(planRender(scene, {Precision::F64}, DeviceAbilities{"no-f64", false}), PlanRefused);
}

// The camera test is the robust one only for a sphere whose surface the eye is close to (here a
// ground of radius 1e6 seen from 1 above it), the fast one for an ordinary sphere; the shadow
// test from the light likewise: fast for a sphere a few radii from the light, robust for a tiny
// one 1e4 radii away.
TEST(RenderPlan, EachNodeGetsTheFormulationItsConditioningNeeds) {
    const Scene ground = twoSpheres(Sphere{{0, -1e6 - 1, 0}, 1e6}, Sphere{{0, 0, 50}, 10}, {0, 20, 50});
    const RenderPlan plan = planRender(ground, {Precision::F64}, kLavapipe);
    ASSERT_TRUE(plan.kernel.code);
    EXPECT_EQ(plan.kernel.code->nodes[0].sphereTest, SphereTest::Robust);
    EXPECT_EQ(plan.kernel.code->nodes[1].sphereTest, SphereTest::Fast);

    const Scene shadows = twoSpheres(Sphere{{0, 0, 100}, 10}, Sphere{{3e4, 0, 100}, 1}, {0, 40, 100});
    const RenderPlan shadowPlan = planRender(shadows, {Precision::F64}, kLavapipe);
    const auto& tests = shadowPlan.kernel.code->shadowTests[0];
    ASSERT_EQ(tests.size(), 2u);
    EXPECT_EQ(tests[0].sphereTest, SphereTest::Fast);    // the light is 4 radii from it
    EXPECT_EQ(tests[1].sphereTest, SphereTest::Robust);  // 3e4 radii away
    const std::string source = generateKernel(*shadowPlan.kernel.code);
    EXPECT_NE(source.find("sphereCrossesSegmentFromOutside(LIGHT0_POSITION - NODE0_GEOMETRY.xyz"), std::string::npos);
    EXPECT_NE(source.find("sphereCrossesSegment(LIGHT0_POSITION - NODE1_GEOMETRY.xyz"), std::string::npos);
}

TEST(RenderPlan, APlaneWithTheEyeAndTheLightOnOneSideCastsNoShadowTest) {
    Scene scene = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    const RenderPlan above = planRender(scene, {Precision::F32}, kLavapipe);
    ASSERT_EQ(above.kernel.code->shadowTests[0].size(), 1u);  // the ball only
    EXPECT_EQ(above.kernel.code->shadowTests[0][0].node, 1u);
    scene.lights[0].position.y = -10;  // below the floor, the eye above it
    const RenderPlan below = planRender(scene, {Precision::F32}, kLavapipe);
    EXPECT_EQ(below.kernel.code->shadowTests[0].size(), 2u);
    // The textbook formulation tests every node, as a course would.
    EXPECT_EQ(planRender(scene, {Precision::F32Naive}, kLavapipe).kernel.code->shadowTests[0].size(), 2u);
}

// Every point the eye sees inside a sphere lies in its ball: a light outside it is blocked from all
// of them, decided here rather than by a test from the light that float32 cannot resolve.
TEST(RenderPlan, ASphereHoldingTheEyeHidesALightOutsideIt) {
    const Scene room = twoSpheres(Sphere{{0, 0, 0}, 100}, Sphere{{0, 0, 50}, 10}, {0, 0, -1e9});
    const RenderPlan plan = planRender(room, {Precision::F32}, kLavapipe);
    ASSERT_EQ(plan.kernel.code->shadowTests[0].size(), 1u);  // the room only
    EXPECT_TRUE(plan.kernel.code->shadowTests[0][0].hidesLight);
    EXPECT_NE(generateKernel(*plan.kernel.code).find("bool blockedBy0 = true;"), std::string::npos);
    EXPECT_TRUE(isLightHiddenFromView(room, room.lights[0]));
    // A light inside the room, or an eye on its wall, is tested as usual; so is a textbook kernel.
    Scene lampInside = room;
    lampInside.lights[0].position = {0, 90, 0};
    EXPECT_FALSE(isLightHiddenFromView(lampInside, lampInside.lights[0]));
    EXPECT_EQ(planRender(lampInside, {Precision::F32}, kLavapipe).kernel.code->shadowTests[0].size(), 2u);
    Scene eyeOnWall = room;
    eyeOnWall.camera.position = {0, 0, -100};
    EXPECT_FALSE(isLightHiddenFromView(eyeOnWall, eyeOnWall.lights[0]));
    EXPECT_FALSE(planRender(room, {Precision::F32Naive}, kLavapipe).kernel.code->shadowTests[0][0].hidesLight);
}

TEST(RenderPlan, LargeScenesGetTheDataDrivenKernel) {
    Scene scene = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    for (int i = 0; i < 40; ++i) {
        scene.nodes.push_back(Node{Sphere{{double(i) * 30, 10, 200}, 5}, scene.nodes[1].shaderIndex});
    }
    const RenderPlan plan = planRender(scene, {Precision::F32}, kLavapipe);
    EXPECT_EQ(plan.layout, SceneLayout::TexelsCandidates);
    ASSERT_TRUE(plan.candidates);
    EXPECT_EQ(plan.candidates->sphereNodes.size(), countSpheres(scene));
    EXPECT_FALSE(plan.kernel.code);
    EXPECT_FALSE(plan.kernel.spirv.empty());
    EXPECT_EQ(plan.kernel.name, "render.comp f32 candidates");

    const RenderPlan everyNode = planRender(scene, {Precision::F32, Acceleration::None}, kLavapipe);
    EXPECT_EQ(everyNode.layout, SceneLayout::Texels);
    EXPECT_FALSE(everyNode.candidates);
    EXPECT_EQ(everyNode.kernel.name, "render.comp f32 storage");
}

// The data-driven kernel's camera and shadow tests, for the whole scene: fast when every sphere
// would get it in a generated kernel from the eye (and from every light), robust as soon as one
// would not (here one whose surface is a tenth of its radius from the eye, or from a light), and
// the textbook ones in f32-naive.
TEST(RenderPlan, TheDataDrivenKernelTakesTheFastTestsOnlyWhenEverySphereWould) {
    Scene scene = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    for (int i = 0; i < 40; ++i) {
        scene.nodes.push_back(Node{Sphere{{double(i) * 30, 10, 200}, 5}, scene.nodes[1].shaderIndex});
    }
    const RenderPlan plan = planRender(scene, {Precision::F32}, kLavapipe);
    ASSERT_FALSE(plan.kernel.code);
    EXPECT_TRUE(plan.fastCameraTests);
    EXPECT_TRUE(plan.fastShadowTests);
    const RenderPlan naive = planRender(scene, {Precision::F32Naive}, kLavapipe);
    EXPECT_FALSE(naive.fastCameraTests);
    EXPECT_FALSE(naive.fastShadowTests);

    Scene nearLight = scene;
    nearLight.nodes.push_back(Node{Sphere{scene.lights[0].position + glm::dvec3(0, 0, 11), 10}, 1});
    const RenderPlan nearLightPlan = planRender(nearLight, {Precision::F32}, kLavapipe);
    EXPECT_TRUE(nearLightPlan.fastCameraTests);
    EXPECT_FALSE(nearLightPlan.fastShadowTests);

    scene.nodes.push_back(Node{Sphere{scene.camera.position + glm::dvec3(0, 0, 11), 10}, scene.nodes[1].shaderIndex});
    EXPECT_FALSE(planRender(scene, {Precision::F32}, kLavapipe).fastCameraTests);
    EXPECT_FALSE(planRender(scene, {Precision::F64}, kLavapipe).fastCameraTests);
}

TEST(RenderPlan, ListsTheDeviceCannotHoldAreNotUsed) {
    Scene scene = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    for (int i = 0; i < 40; ++i) {
        scene.nodes.push_back(Node{Sphere{{double(i) * 30, 10, 200}, 5}, scene.nodes[1].shaderIndex});
    }
    const RenderPlan fits = planRender(scene, {Precision::F32}, kLavapipe);
    ASSERT_TRUE(fits.candidates);
    const auto largest = std::uint32_t(std::max(fits.candidates->entries.size(), fits.candidates->cellStarts.size()));
    EXPECT_EQ(planRender(scene, {Precision::F32}, DeviceAbilities{"just enough", true, largest}).layout,
              SceneLayout::TexelsCandidates);
    const RenderPlan tooSmall = planRender(scene, {Precision::F32}, DeviceAbilities{"small", true, largest - 1});
    EXPECT_EQ(tooSmall.layout, SceneLayout::Texels);
    EXPECT_FALSE(tooSmall.candidates);
}

TEST(RenderPlan, LargeScenesWithoutSpheresTestEveryNode) {
    Scene scene = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    std::erase_if(scene.nodes, [](const Node& node) { return std::holds_alternative<Sphere>(node.geometry); });
    const Node plane = scene.nodes.at(0);
    while (scene.nodes.size() <= gpu::SMALL_SCENE_CAPACITY) {
        scene.nodes.push_back(plane);
    }
    const RenderPlan plan = planRender(scene, {Precision::F32, Acceleration::Always}, kLavapipe);
    EXPECT_EQ(plan.layout, SceneLayout::Texels);
    EXPECT_FALSE(plan.candidates);
}

TEST(RenderPlan, EveryPrecisionGetsCandidateLists) {
    Scene scene = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    for (int i = 0; i < 40; ++i) {
        scene.nodes.push_back(Node{Sphere{{double(i) * 30, 10, 200}, 5}, scene.nodes[1].shaderIndex});
    }
    EXPECT_EQ(planRender(scene, {Precision::F64}, kLavapipe).kernel.name, "render.comp f64 candidates");
    EXPECT_EQ(planRender(scene, {Precision::F32Naive}, kLavapipe).kernel.name, "render.comp f32 textbook candidates");
}

// A floor under `lights` lights: every pixel below the horizon runs the light loop for each.
Scene floorUnderLights(std::size_t lights) {
    Scene scene;
    scene.camera.position = {0, 2, 0};
    scene.camera.pitchDegrees = -30;
    scene.shaderNames = {"matte"};
    scene.shaders = {LambertShader{Color(0.5)}};
    scene.nodes = {Node{Plane{0.0}, 0}};
    for (std::size_t i = 0; i < lights; ++i) {
        scene.lights.push_back(PointLight{{double(i % 100), 10.0, double(i / 100)}, Color(1), 1.0});
    }
    return scene;
}

const DeviceAbilities kLlvmpipe{"llvmpipe (LLVM 15.0.6, 256 bits)", true};

// On lavapipe, three loop passes a light (loop_budget.h): 30000 lights take two batches, 1000 one
// dispatch; a device without the limit renders any number in one.
TEST(RenderPlan, OnLavapipeAFloorUnder30000LightsRendersInTwoBatchesOfLights) {
    const RenderPlan many = planRender(floorUnderLights(30000), {}, kLlvmpipe);
    EXPECT_EQ(many.lightBatches.samplesPerDispatch, 1u);
    EXPECT_EQ(many.lightBatches.lightEnds.size(), 2u);
    EXPECT_EQ(many.lightBatches.lightEnds.back(), 30000u);
    EXPECT_FALSE(planRender(floorUnderLights(1000), {}, kLlvmpipe).lightBatches.splits());
    EXPECT_FALSE(planRender(floorUnderLights(30000), {}, DeviceAbilities{"a GPU", true}).lightBatches.splits());
}

// A generated kernel's loops are unrolled: no batches whatever the limit.
TEST(RenderPlan, AGeneratedKernelIsNeverSplit) {
    PlanRequest request;
    request.loopPassLimit = 10;
    const RenderPlan plan = planRender(floorUnderLights(3), request, kLlvmpipe);
    EXPECT_EQ(plan.layout, SceneLayout::Uniform);
    EXPECT_FALSE(plan.lightBatches.splits());
}

// One sample with one light past the limit: nothing to split, and the message says what to do.
TEST(RenderPlan, AScenePastTheLimitForOneSampleAndOneLightIsRefused) {
    PlanRequest request;
    request.loopPassLimit = 12;  // a floor: 5 passes for a sample, 3 a light; 33 planes: 37 and 35
    Scene planes = floorUnderLights(40);
    EXPECT_NO_THROW(planRender(planes, request, kLlvmpipe));
    for (int i = 1; i < 33; ++i) {
        planes.nodes.push_back(Node{Plane{-double(i)}, 0});
    }
    try {
        planRender(planes, request, kLlvmpipe);
        FAIL() << "planned";
    } catch (const PlanRefused& error) {
        EXPECT_EQ(error.refusal(), Refusal::PastLoopLimit);
        const std::string message = error.what();
        EXPECT_NE(message.find("may need 72 loop passes"), std::string::npos) << message;
        EXPECT_NE(message.find("after 12"), std::string::npos) << message;
        EXPECT_NE(message.find("use --backend cpu"), std::string::npos) << message;
    }
}

}  // namespace
}  // namespace hexray
