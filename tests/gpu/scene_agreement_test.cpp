// Every shipped scene rendered by the GPU and by the CPU reference: the two must agree within
// the stated tolerance (the same defaults `hexray compare` uses).

#include <cstdio>

#include <gtest/gtest.h>

#include "compare/compare.h"
#include "cpu/cpu_renderer.h"
#include "gpu/gpu_renderer.h"
#include "scene/scene_loader.h"
#include "support/test_paths.h"
#include "validated_vulkan.h"

namespace hexray {
namespace {

// The tolerance stated by hexray compare's defaults: see Tolerance in compare.h.
const Tolerance kTolerance;

class SceneAgreementTest : public test::ValidatedVulkanTest,
                           public ::testing::WithParamInterface<std::filesystem::path> {};

TEST_P(SceneAgreementTest, GpuMatchesCpuReference) {
    const Scene scene = loadSceneFile(GetParam());
    GpuRenderer renderer(context());
    const Image gpu = renderer.render(scene).image;
    const Image cpu = renderOnCpu(scene);
    const ImageComparison c = compareRenders(cpu, gpu, scene.image.encoding);

    std::printf("%s %ux%u: linear max %.6f mean %.2e RMSE %.2e PSNR %.1f dB | 8-bit max %.0f mean %.4f "
                "RMSE %.4f levels, %llu px > 1 level (%.4f%%)\n",
                GetParam().filename().c_str(), scene.image.width, scene.image.height, c.linear.maxAbs,
                c.linear.meanAbs, c.linear.rmse, c.linear.psnr, c.encoded.maxAbs, c.encoded.meanAbs, c.encoded.rmse,
                static_cast<unsigned long long>(c.encoded.pixelsOverOneLevel), 100.0 * c.encoded.shareOverOneLevel);
    EXPECT_LE(100.0 * c.encoded.shareOverOneLevel, kTolerance.maxSharePercent);
    EXPECT_LE(c.encoded.rmse, kTolerance.maxRmseLevels);
}

INSTANTIATE_TEST_SUITE_P(ShippedScenes, SceneAgreementTest, ::testing::ValuesIn(test::shippedScenes()),
                         [](const auto& info) { return test::sceneTestName(info.param); });

}  // namespace
}  // namespace hexray
