// Embree's renders (the bench's yardstick) agree with the CPU reference as closely as the f32
// shader must: the bench's ratios mean something only if Embree draws the same image.

#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "compare/compare.h"
#include "cpu/cpu_renderer.h"
#include "embree/embree_renderer.h"
#include "scene/random_spheres.h"
#include "scene/scene_loader.h"
#include "support/test_paths.h"

namespace hexray {
namespace {

void expectAgreesWithTheReference(const Scene& scene) {
    const CpuRender reference = renderOnCpu(scene, 2);
    const EmbreeRender embree = EmbreeRenderer(2).render(scene);
    ASSERT_EQ(embree.image.width, scene.image.width);
    ASSERT_EQ(embree.image.height, scene.image.height);

    const PixelMask ambiguous = marginsBelow(reference.margins, kAmbiguityMargin);
    const RenderComparison comparison = compareRenders(reference.image, reference.classes, ambiguous, embree.image,
                                                       embree.classes, scene.image.encoding);
    std::printf("  %llu ambiguous pixels, %llu topology mismatches, RMSE %.3f levels, max %.0f, %.3f%% > 1 level\n",
                static_cast<unsigned long long>(comparison.topology.ambiguous),
                static_cast<unsigned long long>(comparison.topology.mismatches), comparison.encoded.rmse,
                comparison.encoded.maxAbs, 100.0 * comparison.encoded.shareOverOneLevel);
    const Verdict verdict = judge(comparison, Tolerance{});
    EXPECT_TRUE(verdict.topologyOk) << comparison.topology.mismatches << " topology mismatches";
    EXPECT_TRUE(verdict.shareOk) << comparison.encoded.shareOverOneLevel;
    EXPECT_TRUE(verdict.rmseOk) << comparison.encoded.rmse;

    // Not a vacuous agreement: the image shows spheres, the floor, lit and shadowed pixels.
    const auto count = [&](auto predicate) { return std::count_if(embree.classes.begin(), embree.classes.end(), predicate); };
    EXPECT_GT(count([](const PixelClass& c) { return c.node != PixelClass::kBackground && c.node > 0; }), 0);
    EXPECT_GT(count([](const PixelClass& c) { return c.node != PixelClass::kBackground && (c.flags >> 1) != 0; }), 0);
}

TEST(EmbreeRenderer, LectureDemoMatchesTheCpuReference) {
    Scene scene = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    overrideImageSize(scene, 160, 120, "test");
    expectAgreesWithTheReference(scene);
}

TEST(EmbreeRenderer, SpheresAndLightsWithAntiAliasingMatchesTheCpuReference) {
    Scene scene = loadSceneFile(test::sourcePath("scenes/spheres-and-lights.json"));
    overrideImageSize(scene, 120, 90, "test");
    scene.image.samplesPerPixel = 4;
    expectAgreesWithTheReference(scene);
}

TEST(EmbreeRenderer, RandomSpheresMatchTheCpuReference) {
    for (std::uint32_t count : {1u, 300u}) {
        SCOPED_TRACE(count);
        Scene scene = makeRandomSpheresScene(count, 1);
        overrideImageSize(scene, 192, 108, "test");
        expectAgreesWithTheReference(scene);
    }
}

TEST(EmbreeRenderer, ReportsItsVersionAndTimes) {
    const EmbreeRenderer renderer(2);
    EXPECT_EQ(renderer.version().rfind("Embree 3.", 0), 0u) << renderer.version();
    Scene scene = makeRandomSpheresScene(10, 1);
    overrideImageSize(scene, 16, 9, "test");
    const EmbreeRender render = renderer.render(scene);
    EXPECT_GT(render.renderMilliseconds, 0.0);
}

}  // namespace
}  // namespace hexray
