// A generated kernel reading the scene's values from a buffer (PlanRequest::valuesInBuffer, what
// `hexray watch` renders an edit with at once) gives the same 8-bit image, byte for byte, as the
// kernel with the values compiled in (what `render` and watch's tier-up use) and as the data-driven
// kernel; and it renders a scene with other values through the pipeline it already has.

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gpu/gpu_renderer.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "support/test_paths.h"
#include "validated_vulkan.h"

namespace hexray {
namespace {

class ValuesInBufferTest : public test::PrecisionVulkanTest {};

// The demo scene small, as watch sees it: as shipped, with a value edited, with a sphere added.
std::vector<Scene> watchedScenes() {
    Scene demo = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    demo.image.width = 160;
    demo.image.height = 120;
    Scene valueEdited = demo;
    std::get<Sphere>(valueEdited.nodes[1].geometry).radius = 13.5;
    valueEdited.lights[0].intensity = 8000;
    Scene sphereAdded = valueEdited;
    sphereAdded.nodes.push_back(Node{Sphere{{20, 15, 10}, 6}, 1});
    return {demo, valueEdited, sphereAdded};
}

std::vector<std::uint8_t> pixels(GpuRenderer& renderer, const Scene& scene, const PlanRequest& request) {
    return renderer.render(scene, renderer.plan(scene, request), GpuOutput::Encoded8).encoded.bytes;
}

TEST_P(ValuesInBufferTest, TheSameImageAsTheSpecialisedAndTheDataDrivenKernels) {
    GpuRenderer renderer(context());
    for (const Scene& scene : watchedScenes()) {
        const std::vector<std::uint8_t> buffered =
            pixels(renderer, scene, {.precision = GetParam(), .valuesInBuffer = true});
        ASSERT_EQ(buffered.size(), std::size_t(3) * 160 * 120);
        EXPECT_EQ(buffered, pixels(renderer, scene, {.precision = GetParam()})) << scene.nodes.size() << " nodes";
        EXPECT_EQ(buffered, pixels(renderer, scene, {.precision = GetParam(), .generatedKernel = false}))
            << scene.nodes.size() << " nodes";
    }
}

TEST_P(ValuesInBufferTest, AValueEditNeedsNoNewPipeline) {
    GpuRenderer renderer(context());
    const std::vector<Scene> scenes = watchedScenes();
    const PlanRequest request{.precision = GetParam(), .valuesInBuffer = true};
    const std::vector<std::uint8_t> before = pixels(renderer, scenes[0], request);
    const std::uint64_t pipelines = renderer.pipelinesCreated();
    const std::vector<std::uint8_t> after = pixels(renderer, scenes[1], request);
    EXPECT_EQ(renderer.pipelinesCreated(), pipelines);
    EXPECT_NE(before, after);  // the values reached the kernel all the same
    pixels(renderer, scenes[2], request);
    EXPECT_EQ(renderer.pipelinesCreated(), pipelines + 1);  // a sphere added is another structure
}

INSTANTIATE_TEST_SUITE_P(Precisions, ValuesInBufferTest,
                         ::testing::Values(Precision::F32, Precision::F64, Precision::F32Naive), [](const auto& info) {
                             return std::string(precisionName(info.param)) == "f32-naive"
                                        ? std::string("F32Naive")
                                        : std::string(precisionName(info.param));
                         });

}  // namespace
}  // namespace hexray
