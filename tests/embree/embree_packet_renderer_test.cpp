// The bench's Embree yardstick at its best (EmbreePacketRenderer: the widest packets, shading in
// float) draws the CPU reference's image: every pixel that is not near-tied shows the same node,
// checker cell and lights, in colours within the f32 shader's tolerance. Every packet width is
// checked, whatever the CPU: Embree emulates a packet wider than the CPU's.

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "compare/compare.h"
#include "cpu/cpu_renderer.h"
#include "embree/embree_packet_renderer.h"
#include "scene/random_spheres.h"
#include "scene/scene_loader.h"
#include "support/test_paths.h"

namespace hexray {
namespace {

// Two planes (a checkered floor, a Lambert ceiling above the lights), spheres in Lambert, checker
// and Constant, three coloured lights casting shadows onto the floor and onto each other.
constexpr const char* kMixedScene = R"({
  "image": {"width": 90, "height": 60},
  "camera": {"position": [-30, 40, -90], "yaw": -15, "pitch": -14, "fov": 70},
  "background": [0.1, 0.1, 0.15],
  "ambient": [0.05, 0.05, 0.06],
  "lights": [
    {"position": [-40, 90, -30], "color": [1.0, 0.9, 0.8], "intensity": 9000},
    {"position": [50, 30, -40], "color": [0.4, 0.6, 1.0], "intensity": 4000},
    {"position": [0, 12, 20], "color": [1.0, 0.4, 0.2], "intensity": 1200}
  ],
  "shaders": {
    "floor": {"type": "checker", "color1": [0.85, 0.85, 0.8], "color2": [0.3, 0.3, 0.3], "size": 12},
    "ceiling": {"type": "lambert", "color": [0.5, 0.5, 0.5]},
    "red": {"type": "lambert", "color": [0.8, 0.1, 0.08]},
    "globe": {"type": "checker", "color1": [0.9, 0.9, 0.95], "color2": [0.15, 0.2, 0.5], "size": 30},
    "lamp": {"type": "constant", "color": [1.0, 0.95, 0.6]}
  },
  "nodes": [
    {"geometry": {"type": "plane", "y": 0}, "shader": "floor"},
    {"geometry": {"type": "plane", "y": 120}, "shader": "ceiling"},
    {"geometry": {"type": "sphere", "center": [-15, 12, 0], "radius": 12}, "shader": "red"},
    {"geometry": {"type": "sphere", "center": [20, 18, 15], "radius": 18}, "shader": "globe"},
    {"geometry": {"type": "sphere", "center": [5, 4, -25], "radius": 4}, "shader": "lamp"},
    {"geometry": {"type": "sphere", "center": [-40, 6, -20], "radius": 6}, "shader": "globe"}
  ]
})";

// The render agrees with the reference outside near-ties, and is no vacuous agreement: it shows
// both planes' nodes, checker cells of both colours, and pixels lit by each light and shadowed.
void expectMatchesTheReference(const Scene& scene, std::uint32_t packetWidth) {
    SCOPED_TRACE(testing::Message() << packetWidth << "-ray packets");
    const CpuRender reference = renderOnCpu(scene, 2);
    const EmbreePacketRenderer renderer(2, packetWidth);
    ASSERT_EQ(renderer.packetWidth(), packetWidth);
    const EmbreeRender embree = renderer.render(scene);
    ASSERT_EQ(embree.image.width, scene.image.width);
    ASSERT_EQ(embree.image.height, scene.image.height);
    const RenderComparison comparison = compareRenders(reference.image, reference.classes, reference.ambiguity,
                                                       embree.image, embree.classes, scene.image.encoding);
    std::printf("  %u-ray packets: %llu ambiguous px, %llu topology mismatches, RMSE %.3f levels, max %.0f\n",
                packetWidth, static_cast<unsigned long long>(comparison.topology.ambiguous),
                static_cast<unsigned long long>(comparison.topology.mismatches), comparison.encoded.rmse,
                comparison.encoded.maxAbs);
    EXPECT_EQ(comparison.topology.mismatches, 0u);
    const Verdict verdict = judge(comparison, Tolerance{});
    EXPECT_TRUE(verdict.shareOk) << comparison.encoded.shareOverOneLevel;
    EXPECT_TRUE(verdict.rmseOk) << comparison.encoded.rmse;
}

TEST(EmbreePacketRenderer, MixedSceneMatchesTheCpuReferenceAtEveryPacketWidth) {
    Scene scene = parseScene(kMixedScene, "test");
    for (const std::uint32_t width : {4u, 8u, 16u}) {
        expectMatchesTheReference(scene, width);
    }
    const EmbreeRender render = EmbreePacketRenderer(2).render(scene);
    const auto count = [&](auto predicate) {
        return std::count_if(render.classes.begin(), render.classes.end(), predicate);
    };
    for (std::uint32_t node = 0; node < scene.nodes.size(); ++node) {
        EXPECT_GT(count([&](const PixelClass& c) { return c.node == node; }), 0) << "node " << node;
    }
    const auto hasFlag = [](std::uint32_t flag) {
        return [flag](const PixelClass& c) { return (c.flags & flag) != 0; };
    };
    EXPECT_GT(count(hasFlag(PixelClass::kOddCheckerBit)), 0);
    for (std::uint32_t light = 0; light < scene.lights.size(); ++light) {
        EXPECT_GT(count(hasFlag(PixelClass::litBit(light))), 0) << "light " << light;
    }
    // Shadows: floor pixels the first light does not reach although they face it.
    EXPECT_GT(count([](const PixelClass& c) { return c.node == 0 && (c.flags & PixelClass::litBit(0)) == 0; }), 0);
}

TEST(EmbreePacketRenderer, SamplesPerPixelAndOddImageSizesMatchTheCpuReference) {
    Scene scene = parseScene(kMixedScene, "test");
    overrideImageSize(scene, 37, 23, "test");
    scene.image.samplesPerPixel = 4;
    for (const std::uint32_t width : {4u, 8u, 16u}) {
        expectMatchesTheReference(scene, width);
    }
}

TEST(EmbreePacketRenderer, LectureDemoAndRandomSpheresMatchTheCpuReference) {
    Scene demo = loadSceneFile(test::sourcePath("scenes/lecture-demo.json"));
    overrideImageSize(demo, 160, 120, "test");
    expectMatchesTheReference(demo, 8);
    Scene spheres = makeRandomSpheresScene(300, 1);
    overrideImageSize(spheres, 192, 108, "test");
    expectMatchesTheReference(spheres, 8);
}

TEST(EmbreePacketRenderer, PicksTheWidestPacketTheCpuAndEmbreeRun) {
    const EmbreePacketRenderer renderer(1);
    const std::uint32_t width = renderer.packetWidth();
    EXPECT_TRUE(width == 4 || width == 8 || width == 16) << width;
    if (__builtin_cpu_supports("avx2") && !__builtin_cpu_supports("avx512f")) {
        EXPECT_EQ(width, 8u);  // Debian's Embree has AVX2 kernels
    }
    EXPECT_THROW(EmbreePacketRenderer(1, 5), std::invalid_argument);
}

}  // namespace
}  // namespace hexray
