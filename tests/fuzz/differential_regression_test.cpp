// The scenes the differential fuzzer found failing, kept with their fixes
// (tests/fuzz/regressions/differential-*.json): each must now pass the fuzzer's own check in
// every precision, at 1 and 4 samples, with the data-driven and the generated kernel. And the
// check itself must fail a GPU render spoilt in each way it exists to catch.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fuzz/differential_check.h"
#include "gpu/gpu_renderer.h"
#include "scene/scene_loader.h"
#include "support/test_paths.h"
#include "gpu/validated_vulkan.h"

namespace hexray {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> differentialRegressions() {
    std::vector<fs::path> scenes;
    for (const auto& entry : fs::directory_iterator(test::sourcePath("tests/fuzz/regressions"))) {
        const std::string name = entry.path().filename().string();
        if (name.starts_with("differential-") && entry.path().extension() == ".json")
            scenes.push_back(entry.path());
    }
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

std::string described(const std::vector<test::Finding>& findings) {
    std::string text;
    for (const test::Finding& finding : findings)
        text += "\n  " + test::describe(finding);
    return text;
}

class DifferentialRegression : public test::ValidatedVulkanTest, public ::testing::WithParamInterface<fs::path> {};

TEST_P(DifferentialRegression, PassesTheDifferentialCheck) {
    const Scene scene = loadSceneFile(GetParam());
    GpuRenderer renderer(context());
    const auto findings = test::checkRenders(renderer, scene, {});
    EXPECT_TRUE(findings.empty()) << GetParam().filename() << described(findings);
}

INSTANTIATE_TEST_SUITE_P(Scenes, DifferentialRegression, ::testing::ValuesIn(differentialRegressions()),
                         [](const ::testing::TestParamInfo<fs::path>& info) {
                             std::string name = info.param.stem().string();
                             std::replace_if(
                                 name.begin(), name.end(),
                                 [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
                             return name;
                         });

// ---------------------------------------------------------------- the check can fail

class DifferentialCheck : public test::ValidatedVulkanTest {
protected:
    // A shipped scene at the fuzzer's size, with the GPU's render spoilt by `spoil`. (Not the lecture
    // demo: its round numbers put whole rows of small images' pixel centres exactly on checker edges.)
    std::vector<test::Finding> findingsWith(const std::function<void(GpuRenderResult&)>& spoil) {
        const Scene scene = loadSceneFile(test::sourcePath("scenes/spheres-and-lights.json"));
        GpuRenderer renderer(context());
        test::DifferentialOptions options;
        options.precisions = {Precision::F32, Precision::F64};  // f64 holds the ambiguity limit
        options.samplesPerPixel = {1};
        options.generatedKernels = false;
        return test::checkRenders(renderer, scene, options, [&](const Scene& s, const RenderPlan& plan) {
            GpuRenderResult result = renderer.render(s, plan, GpuOutput::LinearAndClasses);
            spoil(result);
            return result;
        });
    }

    static bool has(const std::vector<test::Finding>& findings, const std::string& kind) {
        return std::ranges::any_of(findings, [&](const test::Finding& f) { return f.kind == kind; });
    }
};

TEST_F(DifferentialCheck, PassesTheRenderAsItIs) {
    const auto findings = findingsWith([](GpuRenderResult&) {});
    EXPECT_TRUE(findings.empty()) << described(findings);
}

TEST_F(DifferentialCheck, CatchesOneNaNPixel) {
    const auto findings = findingsWith([](GpuRenderResult& r) {
        r.image.pixels[r.image.pixels.size() / 2].g = std::numeric_limits<float>::quiet_NaN();
    });
    EXPECT_TRUE(has(findings, "invalid colour")) << described(findings);
}

TEST_F(DifferentialCheck, CatchesAnotherNodeShown) {
    const auto findings = findingsWith([](GpuRenderResult& r) {
        for (PixelClass& c : r.classes)
            c.node = c.node == 0 ? 1 : 0;
    });
    EXPECT_TRUE(has(findings, "topology")) << described(findings);
}

TEST_F(DifferentialCheck, CatchesALightLostEverywhere) {
    const auto findings = findingsWith([](GpuRenderResult& r) {
        for (PixelClass& c : r.classes)
            c.flags &= ~PixelClass::litBit(0);
    });
    EXPECT_TRUE(has(findings, "topology")) << described(findings);
}

TEST_F(DifferentialCheck, CatchesHalvedColours) {
    const auto findings = findingsWith([](GpuRenderResult& r) {
        for (auto& pixel : r.image.pixels)
            pixel *= 0.5f;
    });
    EXPECT_TRUE(has(findings, "colour")) << described(findings);
}

}  // namespace
}  // namespace hexray
