// The shader's BVH traversal (shaders/bvh.glsl) must not change what any pixel shows: the same
// scene traced through the BVH and through every node in turn gives the same image and
// classes bit for bit, in every precision; and it agrees with the CPU reference.

#include <gtest/gtest.h>

#include "compare/compare.h"
#include "cpu/cpu_renderer.h"
#include "gpu/gpu_renderer.h"
#include "scene/random_spheres.h"
#include "reference_comparison.h"
#include "validated_vulkan.h"

namespace hexray {
namespace {

class GpuBvhTest : public test::ValidatedVulkanTest, public ::testing::WithParamInterface<Precision> {};

Scene smallRandomScene(std::uint32_t spheres, std::uint64_t seed) {
    Scene scene = makeRandomSpheresScene(spheres, seed);
    scene.image.width = 96;
    scene.image.height = 54;
    return scene;
}

TEST_P(GpuBvhTest, GivesTheSameImageAsTestingEveryNode) {
    if (GetParam() == Precision::F64 && !context().selected().hasFloat64) {
        GTEST_SKIP() << context().selected().name << " has no shaderFloat64";
    }
    const Scene scene = smallRandomScene(300, 7);
    GpuRenderer renderer(context());
    const GpuRenderResult plain = renderer.render(scene, GetParam(), GpuOutput::LinearAndClasses, Acceleration::None);
    const GpuRenderResult traced = renderer.render(scene, GetParam(), GpuOutput::LinearAndClasses, Acceleration::Bvh);
    ASSERT_FALSE(plain.usedBvh);
    ASSERT_TRUE(traced.usedBvh);

    std::size_t differentPixels = 0;
    std::size_t differentClasses = 0;
    std::size_t spherePixels = 0;
    for (std::size_t i = 0; i < plain.classes.size(); ++i) {
        differentPixels += plain.image.pixels[i] != traced.image.pixels[i];
        differentClasses += plain.classes[i] != traced.classes[i];
        spherePixels += plain.classes[i].node != PixelClass::kBackground && plain.classes[i].node > 0;
    }
    EXPECT_EQ(differentPixels, 0u);
    EXPECT_EQ(differentClasses, 0u);
    EXPECT_GT(spherePixels, plain.classes.size() / 10) << "the scene must show many spheres to test anything";
}

// f32-naive is left out: it disagrees with the reference (shadow acne) with or without a BVH.
class GpuBvhAgreementTest : public GpuBvhTest {};

TEST_P(GpuBvhAgreementTest, AgreesWithTheCpuReference) {
    if (GetParam() == Precision::F64 && !context().selected().hasFloat64) {
        GTEST_SKIP() << context().selected().name << " has no shaderFloat64";
    }
    const Scene scene = smallRandomScene(2000, 11);
    GpuRenderer renderer(context());
    const GpuRenderResult gpu = renderer.render(scene, GetParam());
    ASSERT_TRUE(gpu.usedBvh) << "Auto must choose the BVH for 2000 spheres";
    const RenderComparison c = test::compareWithReference(scene, gpu);
    const Tolerance tolerance;
    EXPECT_LE(c.topology.ambiguousShare(), 0.2);
    EXPECT_EQ(c.topology.mismatches, tolerance.maxTopologyMismatches);
    EXPECT_LE(100.0 * c.encoded.shareOverOneLevel, tolerance.maxSharePercent);
    EXPECT_LE(c.encoded.rmse, tolerance.maxRmseLevels);
}

class GpuBvhChoiceTest : public test::ValidatedVulkanTest {};

TEST_F(GpuBvhChoiceTest, SmallScenesKeepTheUnrolledLoops) {
    GpuRenderer renderer(context());
    EXPECT_FALSE(renderer.render(smallRandomScene(20, 3)).usedBvh);
}

std::string precisionTestName(const ::testing::TestParamInfo<Precision>& info) {
    std::string name(precisionName(info.param));
    std::erase(name, '-');  // test names allow only letters, digits and _
    return name;
}

INSTANTIATE_TEST_SUITE_P(Precisions, GpuBvhTest,
                         ::testing::Values(Precision::F32, Precision::F64, Precision::F32Naive), precisionTestName);
INSTANTIATE_TEST_SUITE_P(Precisions, GpuBvhAgreementTest, ::testing::Values(Precision::F32, Precision::F64),
                         precisionTestName);

}  // namespace
}  // namespace hexray
