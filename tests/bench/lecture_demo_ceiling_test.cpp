// The lecture demo's hand-written kernel (`hexray bench`'s yardstick): which scenes it takes,
// and that it renders the same image as the renderer up to its textbook arithmetic.

#include <stdexcept>

#include <gtest/gtest.h>

#include "compare/compare.h"
#include "gpu/gpu_renderer.h"
#include "bench/lecture_demo_ceiling.h"
#include "scene/scene_loader.h"
#include "support/test_paths.h"
#include "gpu/validated_vulkan.h"

namespace hexray {
namespace {

Scene demoScene() {
    return loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
}

TEST(LectureDemoScene, AcceptsTheDemoWithAnyImageAndCameraOrientation) {
    Scene scene = demoScene();
    EXPECT_TRUE(isLectureDemoScene(scene));
    scene.image.width = 1920;
    scene.image.height = 1080;
    scene.camera.yawDegrees = 30;
    scene.camera.fovDegrees = 60;
    EXPECT_TRUE(isLectureDemoScene(scene));
}

TEST(LectureDemoScene, RejectsAnyChangeTheKernelHardWires) {
    const Scene demo = demoScene();
    const auto rejects = [&](auto change) {
        Scene scene = demo;
        change(scene);
        return !isLectureDemoScene(scene);
    };
    EXPECT_TRUE(rejects([](Scene& s) { s.image.samplesPerPixel = 4; }));
    EXPECT_TRUE(rejects([](Scene& s) { s.camera.position.x = 1; }));
    EXPECT_TRUE(rejects([](Scene& s) { s.ambient = Color(0.2); }));
    EXPECT_TRUE(rejects([](Scene& s) { s.lights[0].intensity = 9000; }));
    EXPECT_TRUE(rejects([](Scene& s) { s.lights.push_back(s.lights[0]); }));
    EXPECT_TRUE(rejects([](Scene& s) { std::get<Sphere>(s.nodes[1].geometry).radius = 11; }));
    EXPECT_TRUE(rejects([](Scene& s) { std::get<Plane>(s.nodes[0].geometry).height = 1; }));
    EXPECT_TRUE(rejects([](Scene& s) { std::get<CheckerShader>(s.shaders[s.nodes[0].shaderIndex]).size = 10; }));
    EXPECT_TRUE(rejects([](Scene& s) { std::swap(s.nodes[0], s.nodes[1]); }));
    EXPECT_TRUE(rejects([](Scene& s) { s.shaders[s.nodes[1].shaderIndex] = ConstantShader{Color(0.8, 0, 0)}; }));
}

using LectureDemoCeilingTest = test::ValidatedVulkanTest;

TEST_F(LectureDemoCeilingTest, RendersTheDemoAsTheRendererDoes) {
    Scene scene = demoScene();
    scene.image.width = 400;
    scene.image.height = 300;
    GpuRenderer renderer(context());
    const GpuRenderResult ceiling =
        renderer.render(scene, lectureDemoCeilingPlan(renderer, scene), GpuOutput::Encoded8);
    const GpuRenderResult rendered = renderer.render(scene, Precision::F32, GpuOutput::Encoded8);
    ASSERT_EQ(ceiling.encoded.bytes.size(), rendered.encoded.bytes.size());
    const ErrorMetrics error = compareEncoded(rendered.encoded, ceiling.encoded);
    // The textbook arithmetic moves a few pixels at checker edges near the horizon and at the
    // shadow's edge; everything else agrees to a level.
    EXPECT_LT(error.shareOverOneLevel, 0.005);
    EXPECT_LT(error.rmse, 5.0);
}

TEST_F(LectureDemoCeilingTest, RefusesAnyOtherScene) {
    Scene scene = demoScene();
    std::get<Sphere>(scene.nodes[1].geometry).radius = 11;
    GpuRenderer renderer(context());
    EXPECT_THROW(lectureDemoCeilingPlan(renderer, scene), std::invalid_argument);
}

}  // namespace
}  // namespace hexray
