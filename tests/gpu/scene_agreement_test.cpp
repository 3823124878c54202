// Every shipped scene (hard cases included) rendered by the GPU, in f32, f64 and f32-certified, against
// the CPU reference: every decision the reference did not find near-tied must match, the colours
// may differ only by rounding, and no colour is NaN, infinite or negative (compare's defaults).

#include <cstdio>
#include <map>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "compare/compare.h"
#include "cpu/cpu_renderer.h"
#include "gpu/gpu_renderer.h"
#include "scene/scene_loader.h"
#include "support/test_paths.h"
#include "reference_comparison.h"
#include "validated_vulkan.h"

namespace hexray {
namespace {

const Tolerance kTolerance;  // hexray compare's defaults, see compare.h

// Scenes built on knife edges, where more pixels than compare's limit allows are near-tied by
// design, and how many (percent, in f32 and f64); the analytic hard-case suite
// (hard_case_test.cpp) is their real check. Every other scene must stay within compare's limit,
// so that this test cannot pass vacuously.
struct Allowance {
    double f32;
    double f64;
};
const std::map<std::string, Allowance> kKnifeEdges = {
    {"hard_grazing_plane_slopes", {100, 100}},   // rays parallel to the plane, or nearly
    {"hard_grazing_sphere_silhouette", {7, 5}},  // rays within float32 rounding of the silhouette
    {"hard_huge_sphere_ground", {50, 5}},        // float32's horizon of a radius-1e6 ground
    {"hard_light_on_plane", {28, 28}},           // cos theta exactly 0 on the whole floor
    {"hard_light_on_top_of_sphere", {88, 88}},   // shadow segments ending exactly on the sphere
    {"hard_overflow_huge_scale", {7, 7}},        // rows exactly on checker edges
    {"hard_scene_offset_1e5", {7, 7}},           // rows exactly on checker edges
    {"hard_scene_offset_1e6", {7, 7}},           // rows exactly on checker edges
    {"hard_scene_offset_1e7", {7, 7}},           // rows exactly on checker edges
    {"hard_underflow_tiny_scale", {7, 7}},       // rows exactly on checker edges
    {"hard_terminator_grazing_light", {66, 5}},  // the light grazes every lit point
    {"hard_tiny_sphere_far_1e5", {95, 5}},       // beyond float32 (auto takes f64): its normals too
    {"hard_tiny_sphere_far_1e7", {100, 5}},      // beyond float32 (auto takes f64)
};

double allowedAmbiguousPercent(const std::string& scene, Precision precision) {
    const auto knifeEdge = kKnifeEdges.find(scene);
    if (knifeEdge == kKnifeEdges.end()) {
        return kTolerance.maxAmbiguousPercent;
    }
    // f32-certified decides as f64 does (decision_roundoff.h), so its near-ties are f64's.
    return precision == Precision::F32 ? knifeEdge->second.f32 : knifeEdge->second.f64;
}

class SceneAgreementTest : public test::ValidatedVulkanTest,
                           public ::testing::WithParamInterface<std::tuple<std::filesystem::path, Precision>> {};

TEST_P(SceneAgreementTest, GpuMatchesCpuReferenceOutsideNearTiedDecisions) {
    const auto& [path, precision] = GetParam();
    if (precision != Precision::F32 && !context().selected().hasFloat64) {
        GTEST_SKIP() << context().selected().name << " has no shaderFloat64";
    }
    const Scene scene = loadSceneFile(path);
    GpuRenderer renderer(context());
    const RenderComparison c = test::compareWithReference(scene, renderer.render(scene, precision));

    std::printf(
        "%s %s: ambiguous %.3f%%, topology mismatches %llu (node %llu, checker %llu, lights %llu); "
        "compared colours: 8-bit max %.0f RMSE %.4f levels, %.4f%% > 1 level; linear max %.2e\n",
        test::sceneTestName(path).c_str(), std::string(precisionName(precision)).c_str(),
        100.0 * c.topology.ambiguousShare(), static_cast<unsigned long long>(c.topology.mismatches),
        static_cast<unsigned long long>(c.topology.nodeMismatches),
        static_cast<unsigned long long>(c.topology.checkerMismatches),
        static_cast<unsigned long long>(c.topology.lightMismatches), c.encoded.maxAbs, c.encoded.rmse,
        100.0 * c.encoded.shareOverOneLevel, c.linear.maxAbs);
    EXPECT_LE(100.0 * c.topology.ambiguousShare(), allowedAmbiguousPercent(test::sceneTestName(path), precision));
    EXPECT_EQ(c.invalidColours, 0u);
    EXPECT_EQ(c.topology.mismatches, kTolerance.maxTopologyMismatches);
    EXPECT_LE(100.0 * c.encoded.shareOverOneLevel, kTolerance.maxSharePercent);
    EXPECT_LE(c.encoded.rmse, kTolerance.maxRmseLevels);
}

INSTANTIATE_TEST_SUITE_P(ShippedScenes, SceneAgreementTest,
                         ::testing::Combine(::testing::ValuesIn(test::shippedScenes()),
                                            ::testing::Values(Precision::F32, Precision::F64, Precision::F32Certified)),
                         [](const auto& info) {
                             return test::sceneTestName(std::get<0>(info.param)) + "_" +
                                    test::precisionTestName(std::get<1>(info.param));
                         });

}  // namespace
}  // namespace hexray
