// Embree's renders (the bench's yardstick) agree with the CPU reference as closely as the f32
// shader must, in both ways of tracing: the bench's ratios mean something only if Embree draws
// the same image.

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "compare/compare.h"
#include "cpu/cpu_renderer.h"
#include "embree/embree_renderer.h"
#include "scene/random_spheres.h"
#include "scene/scene_loader.h"
#include "support/test_paths.h"

namespace hexray {
namespace {

void expectAgreesWithTheReference(const Scene& scene, EmbreeTracing tracing) {
    SCOPED_TRACE(tracingName(tracing));
    const CpuRender reference = renderOnCpu(scene, 2);
    const EmbreeRender embree = EmbreeRenderer(2).render(scene, tracing);
    ASSERT_EQ(embree.image.width, scene.image.width);
    ASSERT_EQ(embree.image.height, scene.image.height);

    const RenderComparison comparison = compareRenders(reference.image, reference.classes, reference.ambiguity,
                                                       embree.image, embree.classes, scene.image.encoding);
    std::printf("  %llu ambiguous pixels, %llu topology mismatches, RMSE %.3f levels, max %.0f, %.3f%% > 1 level\n",
                static_cast<unsigned long long>(comparison.topology.ambiguous),
                static_cast<unsigned long long>(comparison.topology.mismatches), comparison.encoded.rmse,
                comparison.encoded.maxAbs, 100.0 * comparison.encoded.shareOverOneLevel);
    const Verdict verdict = judge(comparison, Tolerance{});
    EXPECT_TRUE(verdict.topologyOk) << comparison.topology.mismatches << " topology mismatches";
    EXPECT_TRUE(verdict.shareOk) << comparison.encoded.shareOverOneLevel;
    EXPECT_TRUE(verdict.rmseOk) << comparison.encoded.rmse;

    // Not a vacuous agreement: the image shows spheres, the floor, lit and shadowed pixels.
    const auto count = [&](auto predicate) {
        return std::count_if(embree.classes.begin(), embree.classes.end(), predicate);
    };
    EXPECT_GT(count([](const PixelClass& c) { return c.node != PixelClass::kBackground && c.node > 0; }), 0);
    EXPECT_GT(count([](const PixelClass& c) { return c.node != PixelClass::kBackground && (c.flags >> 1) != 0; }), 0);
}

// Packets trace the same rays as single rays, through other Embree kernels whose float t may
// differ in its last bits: every pixel shows what it shows with single rays (no ambiguity
// allowed), in a colour at most one 8-bit level apart.
void expectPacketsDrawWhatSingleRaysDraw(const Scene& scene) {
    const EmbreeRenderer renderer(2);
    const EmbreeRender single = renderer.render(scene, EmbreeTracing::SingleRays);
    const EmbreeRender packets = renderer.render(scene, EmbreeTracing::Packets);
    const RenderComparison comparison = compareRenders(single.image, single.classes, Ambiguities{}, packets.image,
                                                       packets.classes, scene.image.encoding);
    EXPECT_EQ(comparison.topology.pixels, std::uint64_t{scene.image.width} * scene.image.height);
    EXPECT_EQ(comparison.topology.mismatches, 0u);
    EXPECT_LE(comparison.encoded.maxAbs, 1.0);
    std::printf("  packets against single rays: 0 topology mismatches, largest difference %.2g linear, %.0f levels\n",
                comparison.linear.maxAbs, comparison.encoded.maxAbs);
}

void expectAgreesInBothWays(const Scene& scene) {
    expectAgreesWithTheReference(scene, EmbreeTracing::SingleRays);
    expectAgreesWithTheReference(scene, EmbreeTracing::Packets);
    expectPacketsDrawWhatSingleRaysDraw(scene);
}

TEST(EmbreeRenderer, LectureDemoMatchesTheCpuReference) {
    Scene scene = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    overrideImageSize(scene, 160, 120, "test");
    expectAgreesInBothWays(scene);
}

TEST(EmbreeRenderer, SpheresAndLightsWithAntiAliasingMatchesTheCpuReference) {
    Scene scene = loadSceneFile(test::sourcePath("scenes/spheres-and-lights.json"));
    overrideImageSize(scene, 120, 90, "test");
    scene.image.samplesPerPixel = 4;
    expectAgreesInBothWays(scene);
}

TEST(EmbreeRenderer, RandomSpheresMatchTheCpuReference) {
    for (std::uint32_t count : {1u, 300u}) {
        SCOPED_TRACE(count);
        Scene scene = makeRandomSpheresScene(count, 1);
        overrideImageSize(scene, 192, 108, "test");
        expectAgreesInBothWays(scene);
    }
}

// Images whose sides are not multiples of the packet's 4 x 2 pixels leave lanes of the last
// tiles empty; each pixel is still drawn once, the one the single rays draw.
TEST(EmbreeRenderer, PacketsCoverImagesOfAnySize) {
    for (const auto& [width, height] : {std::pair{97u, 61u}, std::pair{1u, 1u}, std::pair{3u, 5u}}) {
        SCOPED_TRACE(testing::Message() << width << " x " << height);
        Scene scene = makeRandomSpheresScene(200, 2);
        overrideImageSize(scene, width, height, "test");
        expectPacketsDrawWhatSingleRaysDraw(scene);
    }
}

TEST(EmbreeRenderer, NamesItsWaysOfTracing) {
    EXPECT_EQ(tracingName(EmbreeTracing::SingleRays), "single rays");
    EXPECT_EQ(tracingName(EmbreeTracing::Packets), "8-ray packets");
}

TEST(EmbreeRenderer, ReportsItsVersionAndTimes) {
    const EmbreeRenderer renderer(2);
    EXPECT_EQ(renderer.version().rfind("Embree 3.", 0), 0u) << renderer.version();
    Scene scene = makeRandomSpheresScene(10, 1);
    overrideImageSize(scene, 16, 9, "test");
    for (const EmbreeTracing tracing : {EmbreeTracing::SingleRays, EmbreeTracing::Packets}) {
        EXPECT_GT(renderer.render(scene, tracing).renderMilliseconds, 0.0);
    }
}

}  // namespace
}  // namespace hexray
