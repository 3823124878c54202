// Inputs kept from fuzzing (tests/fuzz/regressions/), run in the normal build: each must load
// into a scene that keeps the renderers' invariants, or be rejected with a SceneError that
// names the place, the same judgement the fuzzer applies. Plus checks that the judge can fail.

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fuzz/scene_invariants.h"
#include "scene/scene_loader.h"

using namespace hexray;
namespace fs = std::filesystem;

namespace {

std::vector<fs::path> regressionInputs() {
    std::vector<fs::path> inputs;
    for (const auto& entry : fs::directory_iterator(fs::path(HEXRAY_SOURCE_DIR) / "tests/fuzz/regressions")) {
        if (entry.is_regular_file() && entry.path().extension() == ".json")
            inputs.push_back(entry.path());
    }
    std::sort(inputs.begin(), inputs.end());
    return inputs;
}

std::string contents(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class FuzzRegression : public ::testing::TestWithParam<fs::path> {};

// Each input's verdict is pinned in NAME.expected beside it: "accepted", or the exact message
// of the rejection, so a loader that starts accepting an input or names another place fails.
TEST_P(FuzzRegression, AcceptedWithInvariantsOrRejectedAtAPlace) {
    const std::string source = GetParam().filename().string();
    fs::path expectedPath = GetParam();
    expectedPath.replace_extension(".expected");
    std::string expected = contents(expectedPath);
    ASSERT_FALSE(expected.empty()) << expectedPath << " is missing";
    expected.erase(expected.find_last_not_of('\n') + 1);
    try {
        const Scene scene = parseScene(contents(GetParam()), source);
        const auto violation = test::sceneInvariantViolation(scene);
        EXPECT_FALSE(violation) << *violation;
        EXPECT_EQ(expected, "accepted");
    } catch (const SceneError& error) {
        EXPECT_TRUE(test::rejectionNamesPlace(error.what(), source)) << error.what();
        EXPECT_EQ(error.what(), expected);
    }  // any other exception fails the test
}

INSTANTIATE_TEST_SUITE_P(Inputs, FuzzRegression, ::testing::ValuesIn(regressionInputs()),
                         [](const ::testing::TestParamInfo<fs::path>& info) {
                             std::string name = info.param.stem().string();
                             std::replace_if(
                                 name.begin(), name.end(),
                                 [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
                             return name;
                         });

TEST(FuzzRegressionInputs, ThereAreSome) {
    EXPECT_GE(regressionInputs().size(), 5u);
}

// ---------------------------------------------------------------- the judge itself

Scene validScene() {
    Scene scene;
    scene.shaderNames = {"a", "b"};
    scene.shaders = {LambertShader{}, CheckerShader{}};
    scene.lights = {PointLight{}};
    scene.nodes = {Node{Plane{}, 0}, Node{Sphere{}, 1}};
    return scene;
}

TEST(SceneInvariants, HoldForAValidScene) {
    const auto violation = test::sceneInvariantViolation(validScene());
    EXPECT_FALSE(violation) << *violation;
}

TEST(SceneInvariants, CatchEachKindOfBreak) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const auto broken = [&](auto&& breakIt) {
        Scene scene = validScene();
        breakIt(scene);
        return test::sceneInvariantViolation(scene).has_value();
    };
    EXPECT_TRUE(broken([](Scene& s) { s.image.width = 0; }));
    EXPECT_TRUE(broken([](Scene& s) { s.image.height = kMaxImageDimension + 1; }));
    EXPECT_TRUE(broken([](Scene& s) { s.image.samplesPerPixel = 0; }));
    EXPECT_TRUE(broken([](Scene& s) { s.image = {16384, 16384, Sampling::Center, Encoding::Srgb, 17}; }));
    EXPECT_TRUE(broken([](Scene& s) { s.image.sampling = Sampling(7); }));
    EXPECT_TRUE(broken([&](Scene& s) { s.camera.position.y = nan; }));
    EXPECT_TRUE(broken([&](Scene& s) { s.camera.rollDegrees = inf; }));
    EXPECT_TRUE(broken([](Scene& s) { s.camera.fovDegrees = 180.0; }));
    EXPECT_TRUE(broken([&](Scene& s) { s.camera.fovDegrees = nan; }));
    EXPECT_TRUE(broken([](Scene& s) { s.camera.aspect = 0.0; }));
    EXPECT_TRUE(broken([](Scene& s) { s.ambient.g = -0.5; }));
    EXPECT_TRUE(broken([&](Scene& s) { s.background.b = inf; }));
    EXPECT_TRUE(broken([](Scene& s) { s.lights[0].intensity = -1.0; }));
    EXPECT_TRUE(broken([&](Scene& s) { s.lights[0].color.r = nan; }));
    EXPECT_TRUE(broken([](Scene& s) { s.shaderNames.pop_back(); }));
    EXPECT_TRUE(broken([](Scene& s) { s.shaderNames[1] = "a"; }));
    EXPECT_TRUE(broken([](Scene& s) { std::get<CheckerShader>(s.shaders[1]).size = 0.0; }));
    EXPECT_TRUE(broken([&](Scene& s) { std::get<CheckerShader>(s.shaders[1]).color2.g = nan; }));
    EXPECT_TRUE(broken([](Scene& s) { std::get<LambertShader>(s.shaders[0]).color.r = -1.0; }));
    EXPECT_TRUE(broken([&](Scene& s) { s.nodes[0].geometry = Plane{inf}; }));
    EXPECT_TRUE(broken([](Scene& s) { s.nodes[1].geometry = Sphere{{0, 0, 0}, -0.0}; }));
    EXPECT_TRUE(broken([&](Scene& s) { s.nodes[1].geometry = Sphere{{0, nan, 0}, 1.0}; }));
    EXPECT_TRUE(broken([](Scene& s) { s.nodes[0].shaderIndex = 2; }));
}

TEST(SceneInvariants, RejectionMessagesMustNameThePlace) {
    EXPECT_TRUE(test::rejectionNamesPlace("x.json: nodes[0].geometry.radius: must be > 0 (got -3)", "x.json"));
    EXPECT_TRUE(test::rejectionNamesPlace("x.json: (root): expected an object (got null)", "x.json"));
    EXPECT_TRUE(test::rejectionNamesPlace("x.json: [\"a b\"]: unknown key (allowed: image)", "x.json"));
    EXPECT_TRUE(test::rejectionNamesPlace("x.json:2:32: JSON syntax error: unexpected '}'", "x.json"));
    EXPECT_FALSE(test::rejectionNamesPlace("y.json: image: missing required field", "x.json"));
    EXPECT_FALSE(test::rejectionNamesPlace("x.json: must be > 0", "x.json"));
    EXPECT_FALSE(test::rejectionNamesPlace("x.json: image: ", "x.json"));
    EXPECT_FALSE(test::rejectionNamesPlace("x.json:2: JSON syntax error: unexpected '}'", "x.json"));
    EXPECT_FALSE(test::rejectionNamesPlace("x.json:2:32: syntax error", "x.json"));
}

}  // namespace
