// Culling by tile class (host/gpu/tile_classes.h) is conservative: on every shipped scene, hard
// cases included, in f32 and f64, the render by tile classes is bit for bit the render of the
// whole image with the scene's kernel: colours, pixel classes and the 8-bit output.

#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "gpu/gpu_renderer.h"
#include "gpu/tile_classes.h"
#include "scene/scene_loader.h"
#include "support/test_paths.h"
#include "validated_vulkan.h"

namespace hexray {
namespace {

class TileCullingTest : public test::ValidatedVulkanTest,
                        public ::testing::WithParamInterface<std::tuple<std::filesystem::path, Precision>> {};

TEST_P(TileCullingTest, RendersExactlyWhatTheWholeKernelRenders) {
    const auto& [path, precision] = GetParam();
    if (precision == Precision::F64 && !context().selected().hasFloat64) {
        GTEST_SKIP() << context().selected().name << " has no shaderFloat64";
    }
    const Scene scene = loadSceneFile(path);
    GpuRenderer renderer(context());
    const RenderPlan culled = renderer.plan(scene, {precision, Acceleration::Auto, Culling::On});
    const RenderPlan whole = renderer.plan(scene, {precision, Acceleration::Auto, Culling::Off});
    ASSERT_TRUE(whole.tileClasses.kernels.empty());
    const GpuRenderResult expected = renderer.render(scene, whole, GpuOutput::LinearAndClasses);
    const GpuRenderResult actual = renderer.render(scene, culled, GpuOutput::LinearAndClasses);
    EXPECT_EQ(actual.image.pixels, expected.image.pixels);
    EXPECT_EQ(actual.classes, expected.classes);
    EXPECT_EQ(renderer.render(scene, culled, GpuOutput::Encoded8).encoded.bytes,
              renderer.render(scene, whole, GpuOutput::Encoded8).encoded.bytes);
}

std::vector<std::tuple<std::filesystem::path, Precision>> cases() {
    std::vector<std::tuple<std::filesystem::path, Precision>> all;
    for (const auto& scene : test::shippedScenes()) {
        for (const Precision precision : {Precision::F32, Precision::F64}) {
            all.emplace_back(scene, precision);
        }
    }
    return all;
}

INSTANTIATE_TEST_SUITE_P(ShippedScenes, TileCullingTest, ::testing::ValuesIn(cases()), [](const auto& info) {
    return test::sceneTestName(std::get<0>(info.param)) + (std::get<1>(info.param) == Precision::F64 ? "_f64" : "_f32");
});

using TileCullingPlanTest = test::ValidatedVulkanTest;

// The lecture demo: the sky needs no node test, the ball covers a few tiles, and most of the floor
// lies where the ball's shadow cannot fall.
TEST_F(TileCullingPlanTest, TheDemoSceneLosesMostOfItsWork) {
    Scene scene = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    overrideImageSize(scene, 1920, 1080, "test");
    GpuRenderer renderer(context());
    const RenderPlan plan = renderer.plan(scene, {Precision::F32, Acceleration::Auto, Culling::On});
    ASSERT_NE(plan.tileClasses.classification, nullptr);
    const TileClassification& tiles = *plan.tileClasses.classification;
    EXPECT_GE(tiles.classes.size(), 3u);
    const TileWork& topLeft = tiles.classes[tiles.classOfTile.front()];
    EXPECT_EQ(topLeft.primary, 0u);  // sky
    const TileWork& bottomRight = tiles.classes[tiles.classOfTile.back()];
    EXPECT_EQ(bottomRight.primary, 1u);    // only the floor...
    EXPECT_EQ(bottomRight.shadow[0], 0u);  // ...and the ball's shadow is elsewhere
    const WorkPerPixel before = workPerPixel(*plan.kernel.code);
    const WorkPerPixel after = workPerPixel(*plan.kernel.code, tiles, scene.image);
    EXPECT_EQ(before.primaryTests, 2.0);
    EXPECT_EQ(before.shadowTests, 1.0);  // the floor cannot come between: the eye and the light are above it
    EXPECT_LT(after.primaryTests, 1.2);
    EXPECT_LT(after.shadowTests, 0.3);
}

TEST_F(TileCullingPlanTest, TextbookKernelsAndCustomRequestsAreNotCulled) {
    const Scene scene = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    GpuRenderer renderer(context());
    EXPECT_TRUE(
        renderer.plan(scene, {Precision::F32Naive, Acceleration::Auto, Culling::On}).tileClasses.kernels.empty());
    EXPECT_TRUE(renderer.plan(scene, {Precision::F32, Acceleration::Auto, Culling::Off}).tileClasses.kernels.empty());
}

}  // namespace
}  // namespace hexray
