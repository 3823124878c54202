// The differential fuzzer's host parts: the generator's scenes are reproducible, valid, written
// and read back exactly, and reach the edges they are meant to; scenes moved out of range are
// rejected; the shrinker keeps a failure while making the scene small and round.

#include <cmath>
#include <cstdint>
#include <cstdio>

#include <glm/geometric.hpp>
#include <string>

#include <gtest/gtest.h>

#include "fuzz/differential_check.h"
#include "fuzz/scene_generator.h"
#include "fuzz/scene_shrinker.h"
#include "scene/scene_loader.h"
#include "scene/scene_writer.h"
#include "support/test_paths.h"

namespace hexray {
namespace {

constexpr std::uint64_t kSeeds = 3000;

TEST(SceneWriter, ShippedSceneLoadsBackTheSame) {
    const Scene scene = loadSceneFile(test::sourcePath("scenes/course-2024-lecture4.json"));
    const std::string text = sceneToJson(scene);
    EXPECT_EQ(sceneToJson(parseScene(text, "written.json")), text);
    EXPECT_NE(text.find("\"type\":\"checker\""), std::string::npos);
}

TEST(SceneGenerator, SameSeedSameSceneOtherSeedAnother) {
    EXPECT_EQ(sceneToJson(test::generateScene(42)), sceneToJson(test::generateScene(42)));
    EXPECT_NE(sceneToJson(test::generateScene(42)), sceneToJson(test::generateScene(43)));
}

TEST(SceneGenerator, EverySceneLoadsBackExactly) {
    for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
        const auto finding = test::checkLoad(test::generateScene(seed), false);
        ASSERT_FALSE(finding) << "seed " << seed << ": " << test::describe(*finding);
    }
}

TEST(SceneGenerator, OutOfRangeScenesAreRejectedNamingTheRange) {
    for (std::uint64_t seed = 0; seed < kSeeds; seed += 7) {
        const auto finding = test::checkLoad(test::generateOutOfRangeScene(seed), true);
        ASSERT_FALSE(finding) << "seed " << seed << ": " << test::describe(*finding);
    }
}

bool holdsCamera(const Scene& scene) {
    for (const Node& node : scene.nodes) {
        const auto* sphere = std::get_if<Sphere>(&node.geometry);
        if (sphere && glm::length(scene.camera.position - sphere->center) < sphere->radius)
            return true;
    }
    return false;
}

// The edges the generator is for are reached, each in a fair share of the scenes.
TEST(SceneGenerator, ReachesTheEdges) {
    std::uint64_t noNodes = 0, noLights = 0, manyNodes = 0, cameraInside = 0, straightDown = 0, tiny = 0, huge = 0;
    for (std::uint64_t seed = 0; seed < kSeeds; ++seed) {
        const Scene scene = test::generateScene(seed);
        noNodes += scene.nodes.empty();
        noLights += scene.lights.empty();
        manyNodes += scene.nodes.size() > 32;
        cameraInside += holdsCamera(scene);
        straightDown += scene.camera.pitchDegrees == -90.0;
        double smallest = INFINITY, largest = 0;
        for (const Node& node : scene.nodes) {
            if (const auto* sphere = std::get_if<Sphere>(&node.geometry)) {
                smallest = std::min(smallest, sphere->radius);
                largest = std::max(largest, sphere->radius);
            }
        }
        tiny += smallest < 1e-40;
        huge += largest > 1e40;
    }
    for (const std::uint64_t count : {noNodes, noLights, manyNodes, cameraInside, straightDown, tiny, huge}) {
        EXPECT_GT(count, kSeeds / 100);
    }
    std::printf(
        "of %llu scenes: no nodes %llu, no lights %llu, > 32 nodes %llu, camera in a sphere %llu, looking "
        "straight down %llu, a radius < 1e-40 %llu, > 1e40 %llu\n",
        static_cast<unsigned long long>(kSeeds), static_cast<unsigned long long>(noNodes),
        static_cast<unsigned long long>(noLights), static_cast<unsigned long long>(manyNodes),
        static_cast<unsigned long long>(cameraInside), static_cast<unsigned long long>(straightDown),
        static_cast<unsigned long long>(tiny), static_cast<unsigned long long>(huge));
}

bool hasLargeSphere(const Scene& scene) {
    for (const Node& node : scene.nodes) {
        const auto* sphere = std::get_if<Sphere>(&node.geometry);
        if (sphere && sphere->radius > 10.0)
            return true;
    }
    return false;
}

int significantDigits(double value) {
    for (int digits = 1; digits <= 17; ++digits) {
        char text[64];
        std::snprintf(text, sizeof text, "%.*e", digits - 1, value);
        if (std::strtod(text, nullptr) == value)
            return digits;
    }
    return 17;
}

TEST(SceneShrinker, KeepsTheFailureAndLeavesOneRoundNode) {
    std::uint64_t seed = 0;
    Scene scene;
    do {
        scene = test::generateScene(seed++);
    } while (!(hasLargeSphere(scene) && scene.nodes.size() > 3 && !scene.lights.empty()));

    const Scene shrunk = test::shrinkScene(scene, hasLargeSphere);
    EXPECT_TRUE(hasLargeSphere(shrunk));
    ASSERT_EQ(shrunk.nodes.size(), 1u);
    EXPECT_TRUE(shrunk.lights.empty());
    EXPECT_EQ(shrunk.shaders.size(), 1u);
    EXPECT_EQ(shrunk.camera.yawDegrees, 0.0);
    EXPECT_EQ(shrunk.camera.rollDegrees, 0.0);
    const Sphere& sphere = std::get<Sphere>(shrunk.nodes[0].geometry);
    EXPECT_LE(significantDigits(sphere.radius), 1) << sphere.radius;
    EXPECT_EQ(sphere.center, glm::dvec3(0.0));
}

}  // namespace
}  // namespace hexray
