// Scenes whose pixels need more loop passes than lavapipe runs in one invocation (65535: Mesa's
// gallivm then silently ends every loop) render in light batches (gpu/loop_budget.h), each
// dispatch within the limit, what a pixel has so far carried from one to the next: the image
// agrees with the CPU reference past the limit, and forced batches give the single pass's image,
// classes and AOVs bit for bit.

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "compare/compare.h"
#include "gpu/gpu_renderer.h"
#include "gpu/loop_budget.h"
#include "layout/gpu_layout.h"
#include "scene/random_spheres.h"
#include "support/floor_scene.h"
#include "reference_comparison.h"
#include "validated_vulkan.h"
#include "support/random_uniform.h"

namespace hexray {
namespace {

using LightBatchesTest = test::PrecisionVulkanTest;

using test::uniform;

// The floor seen from above, filling the frame, under `lights` lights spread over it whose terms
// sum to a mid grey: a share of them dropped shows in every pixel.
Scene floorUnderLights(std::uint32_t lights, std::uint32_t width, std::uint32_t height) {
    Scene scene = test::floorSeenFrom({0.0, 3.0, 0.0}, -60.0, 70.0, width, height);
    scene.lights.clear();
    std::mt19937_64 engine(41);
    constexpr double kSide = 40.0;
    // Over a wide square at height h, lights of total intensity P spread over area A give about
    // 2 pi P / A of irradiance.
    const double intensity = 0.5 * kSide * kSide / (2.0 * M_PI * double(lights));
    for (std::uint32_t i = 0; i < lights; ++i) {
        const glm::dvec3 position(uniform(engine, -0.5, 0.5) * kSide, uniform(engine, 8.0, 12.0),
                                  uniform(engine, -0.25, 0.75) * kSide);
        scene.lights.push_back(PointLight{position, Color(1.0), intensity});
    }
    return scene;
}

void expectAgreementWithTheReference(const Scene& scene, const GpuRenderResult& gpu) {
    const RenderComparison c = test::compareWithReference(scene, gpu);
    const Tolerance tolerance;
    EXPECT_EQ(c.invalidColours, 0u);
    EXPECT_EQ(c.topology.mismatches, 0u);
    EXPECT_LE(100.0 * c.topology.ambiguousShare(), tolerance.maxAmbiguousPercent);
    EXPECT_LE(100.0 * c.encoded.shareOverOneLevel, tolerance.maxSharePercent);
    EXPECT_LE(c.encoded.rmse, tolerance.maxRmseLevels);
}

// Past lavapipe's limit for real, at a few pixels: a floor under 25000 lights (three passes a
// light: its own, and its shadow test's over the one node and the pass that ends it).
TEST_P(LightBatchesTest, AFloorUnder25000LightsAgreesWithTheReference) {
    GpuRenderer renderer(context());
    const Scene scene = floorUnderLights(25000, 16, 12);
    const RenderPlan plan = renderer.plan(scene, {GetParam()});
    if (onLavapipe()) {
        EXPECT_EQ(plan.lightBatches.lightEnds.size(), 2u);
    }
    expectAgreementWithTheReference(scene, renderer.render(scene, plan, GpuOutput::LinearAndClasses));
}

// Past the limit for four samples, not for one: two samples a dispatch.
TEST_P(LightBatchesTest, AFloorUnder10000LightsAtFourSamplesAPixelAgreesWithTheReference) {
    GpuRenderer renderer(context());
    Scene scene = floorUnderLights(10000, 16, 12);
    scene.image.samplesPerPixel = 4;
    const RenderPlan plan = renderer.plan(scene, {GetParam()});
    if (onLavapipe()) {
        EXPECT_EQ(plan.lightBatches.samplesPerDispatch, 2u);
        EXPECT_EQ(plan.lightBatches.lightEnds.size(), 1u);
    }
    expectAgreementWithTheReference(scene, renderer.render(scene, plan, GpuOutput::LinearAndClasses));
}

// `spheres` random spheres on the checkered floor under `lights` lights hanging over them, whose
// terms sum to about one bright light's.
Scene lightsOverSpheres(std::uint32_t spheres, std::uint32_t lights, std::uint32_t width, std::uint32_t height) {
    Scene scene = makeRandomSpheresScene(spheres, 5);
    scene.image.width = width;
    scene.image.height = height;
    std::mt19937_64 engine(41);
    const double side = 4.0 * std::sqrt(double(spheres)) + 10.0;
    scene.lights.clear();
    for (std::uint32_t i = 0; i < lights; ++i) {
        const glm::dvec3 position(uniform(engine, -0.5, 0.5) * side, uniform(engine, 3.0, 20.0),
                                  uniform(engine, 0.0, 1.0) * side);
        scene.lights.push_back(PointLight{position, Color(1.0), 0.4 * side * side / double(lights)});
    }
    return scene;
}

// Every output of two renders, bit for bit.
void expectIdentical(const GpuRenderResult& expected, const GpuRenderResult& actual) {
    ASSERT_EQ(expected.image.pixels.size(), actual.image.pixels.size());
    ASSERT_EQ(expected.depth.size(), actual.depth.size());
    const auto bits = [](const glm::vec3& c) { return std::bit_cast<glm::uvec3>(c); };
    std::size_t pixels = 0;
    std::size_t classes = 0;
    std::size_t aovs = 0;
    for (std::size_t i = 0; i < expected.image.pixels.size(); ++i) {
        pixels += bits(expected.image.pixels[i]) != bits(actual.image.pixels[i]);
        classes += expected.classes[i] != actual.classes[i];
        const bool sameDepth =
            std::bit_cast<std::uint32_t>(expected.depth[i]) == std::bit_cast<std::uint32_t>(actual.depth[i]);
        aovs += !sameDepth || bits(expected.normals[i]) != bits(actual.normals[i]);
    }
    EXPECT_EQ(pixels, 0u);
    EXPECT_EQ(classes, 0u);
    EXPECT_EQ(aovs, 0u);
}

// Past the limit through the candidate lists (each light's shadow test the planes' loop and the
// longest of its lists), and testing every node: the same image bit for bit, as within the limit
// (gpu_candidates_test.cpp), each split by its own bound.
TEST_P(LightBatchesTest, SpheresUnder12000LightsThroughTheirListsGiveWhatEveryNodeGives) {
    GpuRenderer renderer(context());
    const Scene scene = lightsOverSpheres(24, 12000, 16, 12);
    const RenderPlan listed = renderer.plan(scene, {GetParam(), Acceleration::Always});
    const RenderPlan every = renderer.plan(scene, {GetParam(), Acceleration::None});
    ASSERT_TRUE(listed.candidates);
    if (onLavapipe()) {
        ASSERT_TRUE(listed.lightBatches.splits());
        ASSERT_GT(every.lightBatches.lightEnds.size(), listed.lightBatches.lightEnds.size());
    }
    expectIdentical(renderer.render(scene, every, GpuOutput::LinearClassesAndAov),
                    renderer.render(scene, listed, GpuOutput::LinearClassesAndAov));
}

// A scene well within the limit, rendered whole and in forced batches: whole samples two at a
// time, then one sample at a time in batches of a few lights each; by a renderer of one band and
// by one of bands of 8 rows, whose carry starts afresh in each band.
void expectBatchesGiveTheSinglePass(GpuRenderer& renderer, GpuRenderer& banded, const Scene& scene,
                                    PlanRequest request) {
    const RenderPlan single = renderer.plan(scene, request);
    ASSERT_FALSE(single.lightBatches.splits());
    const LoopPasses passes = loopPasses(scene, single.candidates.get());
    const auto lights = std::uint32_t(scene.lights.size());
    const std::uint64_t heaviest = std::ranges::max(passes.lights);
    const GpuRenderResult whole = renderer.render(scene, single, GpuOutput::LinearClassesAndAov);
    const Rgb8Image wholeEncoded = renderer.render(scene, single, GpuOutput::Encoded8).encoded;
    const std::uint64_t twoSamples = dispatchPasses(passes, 2, 0, lights);
    for (const std::uint64_t limit : {twoSamples, smallestDispatchPasses(passes) + 4 * heaviest}) {
        request.loopPassLimit = limit;
        const RenderPlan batched = renderer.plan(scene, request);
        ASSERT_TRUE(batched.lightBatches.splits());
        SCOPED_TRACE(std::to_string(batched.lightBatches.samplesPerDispatch) + " samples a dispatch, " +
                     std::to_string(batched.lightBatches.lightEnds.size()) + " batches of lights");
        for (const PixelWork& part : batched.lightBatches.work(scene.image.samplesPerPixel, lights)) {
            ASSERT_LE(dispatchPasses(passes, part.endSample - part.firstSample, part.firstLight, part.endLight), limit);
        }
        for (GpuRenderer* r : {&renderer, &banded}) {
            expectIdentical(whole, r->render(scene, batched, GpuOutput::LinearClassesAndAov));
            EXPECT_EQ(wholeEncoded.bytes, r->render(scene, batched, GpuOutput::Encoded8).encoded.bytes);
        }
    }
}

class LightBatchesExactTest : public LightBatchesTest {};

TEST_P(LightBatchesExactTest, ForcedBatchesGiveTheSinglePassBitForBit) {
    Scene scene = lightsOverSpheres(24, 120, 40, 24);
    scene.image.samplesPerPixel = 3;
    GpuRenderer renderer(context());
    // Rows of the pixel buffer and the carry.
    GpuRenderer banded(context(), 8 * scene.image.width * (sizeof(gpu::GpuPixel) + sizeof(gpu::GpuPixelCarry)));
    {
        SCOPED_TRACE("through the candidate lists");
        expectBatchesGiveTheSinglePass(renderer, banded, scene, {GetParam(), Acceleration::Auto});
    }
    {
        SCOPED_TRACE("testing every node");
        expectBatchesGiveTheSinglePass(renderer, banded, scene, {GetParam(), Acceleration::None});
    }
}

std::string precisionTestName(const ::testing::TestParamInfo<Precision>& info) {
    std::string name(precisionName(info.param));
    std::erase(name, '-');  // test names allow only letters, digits and _
    return name;
}

// f32-naive is left out of the agreement: it disagrees with the reference (shadow acne) anyway.
INSTANTIATE_TEST_SUITE_P(Precisions, LightBatchesTest, ::testing::Values(Precision::F32, Precision::F64),
                         precisionTestName);
INSTANTIATE_TEST_SUITE_P(Precisions, LightBatchesExactTest,
                         ::testing::Values(Precision::F32, Precision::F64, Precision::F32Naive), precisionTestName);

}  // namespace
}  // namespace hexray
