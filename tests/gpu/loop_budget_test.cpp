// The loop passes the data-driven kernel makes (gpu/loop_budget.h), and the light batches that keep
// each dispatch within a limit: as few as greedy batches in order make, each within the limit, and
// together every sample of every light exactly once, in the single pass's order.

#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "gpu/loop_budget.h"

namespace hexray {
namespace {

Scene floorUnder(std::size_t lights) {
    Scene scene;
    scene.shaders = {LambertShader{Color(0.5)}};
    scene.nodes = {Node{Plane{0.0}, 0}};
    scene.lights.assign(lights, PointLight{{0.0, 10.0, 0.0}, Color(1), 1.0});
    return scene;
}

// A made-up bound: `sample` a sample, and the lights' own.
LoopPasses passesOf(std::uint64_t sample, std::vector<std::uint64_t> lights) {
    return LoopPasses{sample, std::move(lights), 0};
}

// Every (sample, light) that `work` renders, in its order.
std::vector<std::pair<std::uint32_t, std::uint32_t>> order(const std::vector<PixelWork>& work) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> visits;
    for (const PixelWork& part : work) {
        for (std::uint32_t sample = part.firstSample; sample < part.endSample; ++sample) {
            for (std::uint32_t light = part.firstLight; light < part.endLight; ++light) {
                visits.emplace_back(sample, light);
            }
        }
    }
    return visits;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> singlePassOrder(std::uint32_t samples, std::uint32_t lights) {
    return order({PixelWork{0, samples, 0, lights}});
}

// A floor alone: the camera ray's loop over its one node (2 passes) and the light loop's last;
// each light its pass and its shadow test's loop over the node (2).
TEST(LoopBudget, AFloorTakesThreePassesASampleAndThreeALight) {
    const LoopPasses passes = loopPasses(floorUnder(2), nullptr);
    EXPECT_EQ(passes.sample, 3u);
    EXPECT_EQ(passes.lights, (std::vector<std::uint64_t>{3, 3}));
    EXPECT_EQ(dispatchPasses(passes, 1, 0, 2), 3u + 6u + 2u);  // and the sample loop's two
    EXPECT_EQ(dispatchPasses(passes, 4, 0, 2), 4u * 9u + 5u);
    EXPECT_EQ(tracePasses(passes, 4), 4u * 9u + 5u + 4u * 2u);  // and each sample's loop over the nodes
    EXPECT_EQ(smallestDispatchPasses(passes), 3u + 2u + 3u);
}

TEST(LoopBudget, WithinTheLimitOneDispatchRendersEverything) {
    const LoopPasses passes = passesOf(3, {3, 3, 3});
    const std::optional<LightBatches> batches = planLightBatches(passes, 4, dispatchPasses(passes, 4, 0, 3));
    ASSERT_TRUE(batches);
    EXPECT_FALSE(batches->splits());
    EXPECT_EQ(order(batches->work(4, 3)), singlePassOrder(4, 3));
}

TEST(LoopBudget, WholeSamplesAsManyAsFitADispatch) {
    const LoopPasses passes = passesOf(3, {3, 3, 3});  // a sample 12 passes, n samples 13 n + 1
    const std::optional<LightBatches> batches = planLightBatches(passes, 7, 3 * 13 + 1 + 12);
    ASSERT_TRUE(batches);
    EXPECT_EQ(batches->samplesPerDispatch, 3u);
    EXPECT_EQ(batches->lightEnds, (std::vector<std::uint32_t>{3}));
    const std::vector<PixelWork> work = batches->work(7, 3);
    ASSERT_EQ(work.size(), 3u);
    EXPECT_EQ(work.back().firstSample, 6u);
    EXPECT_EQ(work.back().endSample, 7u);
    EXPECT_EQ(order(work), singlePassOrder(7, 3));
}

TEST(LoopBudget, OneSampleInGreedyBatchesOfLightsEachWithinTheLimit) {
    const std::vector<std::uint64_t> lights = {4, 9, 2, 2, 7, 1, 1, 1, 8, 3};
    const LoopPasses passes = passesOf(5, lights);  // a sample alone: 5 and the sample loop's 2
    const std::uint64_t limit = 7 + 12;             // lights of 12 passes at most a batch
    const std::optional<LightBatches> batches = planLightBatches(passes, 2, limit);
    ASSERT_TRUE(batches);
    EXPECT_EQ(batches->samplesPerDispatch, 1u);
    EXPECT_EQ(batches->lightEnds, (std::vector<std::uint32_t>{1, 3, 8, 10}));
    const std::vector<PixelWork> work = batches->work(2, 10);
    EXPECT_EQ(work.size(), 8u);
    for (const PixelWork& part : work) {
        EXPECT_LE(dispatchPasses(passes, 1, part.firstLight, part.endLight), limit);
        if (part.endLight < lights.size()) {  // the next light would not have fitted
            EXPECT_GT(dispatchPasses(passes, 1, part.firstLight, part.endLight + 1), limit);
        }
    }
    EXPECT_EQ(order(work), singlePassOrder(2, 10));
}

TEST(LoopBudget, NothingWhenOneSampleWithOneLightPassesTheLimit) {
    const LoopPasses passes = passesOf(5, {4, 13, 2});
    EXPECT_FALSE(planLightBatches(passes, 1, 7 + 12));
    EXPECT_TRUE(planLightBatches(passes, 1, 7 + 13));
    EXPECT_FALSE(planLightBatches(passesOf(30, {}), 1, 20));
}

}  // namespace
}  // namespace hexray
