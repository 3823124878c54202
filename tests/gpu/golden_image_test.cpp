// The GPU's 8-bit output for the demo scenes against stored goldens. lavapipe is deterministic,
// so on it any difference at all is a regression (or an intended change: regenerate with
// HEXRAY_UPDATE_GOLDEN=1 and look at the new images before committing them).

#include <cstdlib>

#include <gtest/gtest.h>

#include "compare/compare.h"
#include "gpu/gpu_renderer.h"
#include "image/image_io.h"
#include "scene/scene_loader.h"
#include "support/test_paths.h"
#include "validated_vulkan.h"

namespace hexray {
namespace {

class GoldenImageTest : public test::ValidatedVulkanTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(GoldenImageTest, GpuOutputMatchesGolden) {
    if (!onLavapipe()) {
        GTEST_SKIP() << "goldens are lavapipe's output; this device is " << context().selected().name;
    }
    const Scene scene = loadSceneFile(test::sourcePath("scenes/" + GetParam() + ".json"));
    GpuRenderer renderer(context());
    const Rgb8Image rendered = encodeImage(renderer.render(scene).image, scene.image.encoding);
    const auto golden = test::sourcePath("tests/golden/" + GetParam() + ".png");

    if (std::getenv("HEXRAY_UPDATE_GOLDEN")) {
        writePng(golden, rendered);
        GTEST_SKIP() << "wrote " << golden;
    }
    const Rgb8Image expected = readPng(golden);
    ASSERT_EQ(expected.width, rendered.width);
    ASSERT_EQ(expected.height, rendered.height);
    const ErrorMetrics difference = compareEncoded(expected, rendered);
    EXPECT_EQ(difference.maxAbs, 0.0) << difference.pixelsOverOneLevel << " pixels differ by more than one level";
}

INSTANTIATE_TEST_SUITE_P(DemoScenes, GoldenImageTest,
                         ::testing::Values("lecture-demo", "course-2024-lecture4", "spheres-and-lights"),
                         [](const auto& info) {
                             std::string name = info.param;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

}  // namespace
}  // namespace hexray
