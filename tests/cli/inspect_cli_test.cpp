// The inspection features through the real executable: `hexray pixel`, `render --aov`,
// `compare --mask` and `compare --aov`.

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "cli/cli_fixture.h"
#include "image/exr_io.h"
#include "image/image_io.h"
#include "support/lecture_demo.h"

namespace hexray {
namespace {

namespace fs = std::filesystem;
namespace demo = test::lecture_demo;

class InspectCliTest : public test::CliTest {
protected:
    static std::string demoScene() { return scene("lecture-demo.json"); }
};

// The line of the table that starts with `label`.
std::string line(const std::string& text, const std::string& label) {
    std::istringstream in(text);
    for (std::string row; std::getline(in, row);) {
        if (row.rfind(label, 0) == 0) {
            return row;
        }
    }
    return "";
}

TEST_F(InspectCliTest, PixelExplainsALitFloorPixelIdenticallyOnBothBackends) {
    const test::RunResult run = hexray("pixel " + demoScene() + " " + std::to_string(demo::kFloorX) + " " +
                                       std::to_string(demo::kFloorY) + " --precision f32");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    // The hit row shows node 0 at the analytic distance in both columns.
    const double t = *demo::planeT(demo::direction(demo::kFloorX, demo::kFloorY, 800, 600));
    const std::string hit = line(run.out, "hit");
    const std::regex pattern(R"(node (\d+), t = ([0-9.e+-]+)\s+node (\d+), t = ([0-9.e+-]+))");
    std::smatch match;
    ASSERT_TRUE(std::regex_search(hit, match, pattern)) << run.out;
    EXPECT_EQ(match[1], "0");
    EXPECT_EQ(match[3], "0");
    EXPECT_NEAR(std::stod(match[2]), t, 1e-5 * t);
    EXPECT_NEAR(std::stod(match[4]), t, 1e-9 * t);
    EXPECT_NE(line(run.out, "light 0").find("lit"), std::string::npos);
    EXPECT_EQ(line(run.out, "light 0").find("shadowed"), std::string::npos);
    EXPECT_NE(run.out.find("printed here in world units"), std::string::npos);
    EXPECT_NE(run.out.find("gpu and cpu agree"), std::string::npos) << run.out;
    EXPECT_EQ(run.out.find("differs"), std::string::npos) << run.out;
}

TEST_F(InspectCliTest, PixelInTheSphereShadowSaysShadowedOnBothBackends) {
    const test::RunResult run =
        hexray("pixel " + demoScene() + " " + std::to_string(demo::kShadowX) + " " + std::to_string(demo::kShadowY));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::string light = line(run.out, "light 0");
    const auto first = light.find("shadowed");
    ASSERT_NE(first, std::string::npos) << run.out;
    EXPECT_NE(light.find("shadowed", first + 1), std::string::npos) << run.out;  // both columns
    EXPECT_NE(run.out.find("gpu and cpu agree"), std::string::npos) << run.out;
}

TEST_F(InspectCliTest, PixelWithOneBackendPrintsOneColumn) {
    const test::RunResult run = hexray("pixel " + demoScene() + " 0 0 --backend cpu");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(line(run.out, "hit").find("background"), std::string::npos);
    EXPECT_EQ(run.out.find("gpu (shader trace)"), std::string::npos);
}

TEST_F(InspectCliTest, PixelOutsideTheImageIsBadInput) {
    test::RunResult run = hexray("pixel " + demoScene() + " 800 10");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("X = 800 is outside the image: the width is 800, so X must be in 0..799"), std::string::npos)
        << run.err;
    run = hexray("pixel " + demoScene() + " 10 -1");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("Y = -1 is outside the image"), std::string::npos) << run.err;
    run = hexray("pixel " + demoScene() + " 10 10 --sample 1");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("--sample = 1"), std::string::npos) << run.err;
}

TEST_F(InspectCliTest, PixelRejectsAPrecisionForTheCpuBackendAlone) {
    const test::RunResult run = hexray("pixel " + demoScene() + " 10 10 --backend cpu --precision f64");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("--precision: applies to the GPU backend only"), std::string::npos) << run.err;
}

// A second render into the same AOV directory replaces the first's set whole: the three-light
// scene's light-1 and light-2 do not linger beside the one-light demo's files.
TEST_F(InspectCliTest, RenderAovReplacesAnEarlierSetInTheSameDirectory) {
    ASSERT_EQ(
        hexray("render " + scene("spheres-and-lights.json") + " -o a.png --width 64 --height 36 --aov aov").exitCode,
        0);
    ASSERT_TRUE(fs::exists(dir_ / "aov" / "light-2.exr"));
    const test::RunResult run = hexray("render " + demoScene() + " -o b.png --width 64 --height 48 --aov aov");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("wrote 8 AOV files"), std::string::npos) << run.out;
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(dir_ / "aov")) {
        const std::string name = entry.path().filename().string();
        EXPECT_TRUE(name.rfind("light-1", 0) != 0 && name.rfind("light-2", 0) != 0 && name[0] != '.') << name;
        ++files;
    }
    EXPECT_EQ(files, 8u);
    EXPECT_EQ(readExr(dir_ / "aov" / "depth.exr").width, 64u);
}

// Depth, object id, normal and light mask at the hand-computed pixels, on each backend; and
// the two backends' files against each other.
TEST_F(InspectCliTest, RenderAovFilesHoldTheAnalyticValuesOnBothBackends) {
    // f64 so that the backends' depths agree to float rounding even near the horizon, where
    // f32's direction rounding is amplified (pixel_trace_test checks the f32 AOVs).
    ASSERT_EQ(hexray("render " + demoScene() + " -o gpu.png --precision f64 --aov gpu-aov").exitCode, 0);
    const test::RunResult cpuRun = hexray("render " + demoScene() + " -o cpu.png --backend cpu --aov cpu-aov");
    ASSERT_EQ(cpuRun.exitCode, 0) << cpuRun.err;
    EXPECT_NE(cpuRun.out.find("wrote 8 AOV files"), std::string::npos) << cpuRun.out;
    const auto at = [](std::uint32_t x, std::uint32_t y) { return std::size_t(y) * 800 + x; };
    const std::size_t floor = at(demo::kFloorX, demo::kFloorY);
    const std::size_t sphere = at(demo::kSphereX, demo::kSphereY);
    const std::size_t shadow = at(demo::kShadowX, demo::kShadowY);
    const double floorT = *demo::planeT(demo::direction(demo::kFloorX, demo::kFloorY, 800, 600));
    const double sphereT = *demo::sphereT(demo::direction(demo::kSphereX, demo::kSphereY, 800, 600));
    std::map<std::string, ExrImage> images[2];
    for (int backend = 0; backend < 2; ++backend) {
        const fs::path aov = dir_ / (backend == 0 ? "gpu-aov" : "cpu-aov");
        SCOPED_TRACE(aov.string());
        for (const char* name : {"depth", "normal", "object-id", "light-0"}) {
            images[backend][name] = readExr(aov / (std::string(name) + ".exr"));
            EXPECT_EQ(readPng(aov / (std::string(name) + ".png")).width, 800u);
        }
        const auto& depth = images[backend]["depth"].channels.at("Y");
        const auto& id = images[backend]["object-id"].channels.at("Y");
        const auto& lit = images[backend]["light-0"].channels.at("Y");
        EXPECT_NEAR(depth[floor], floorT, 1e-5 * floorT);
        EXPECT_NEAR(depth[sphere], sphereT, 1e-5 * sphereT);
        EXPECT_TRUE(std::isinf(depth[0]));
        EXPECT_EQ(id[floor], 0.0f);
        EXPECT_EQ(id[sphere], 1.0f);
        EXPECT_EQ(id[0], -1.0f);
        EXPECT_EQ(images[backend]["normal"].channels.at("G")[floor], 1.0f);
        EXPECT_EQ(lit[floor], 1.0f);
        EXPECT_EQ(lit[shadow], 0.0f);
        EXPECT_EQ(lit[0], 0.0f);
    }
    const auto& gpuId = images[0]["object-id"].channels.at("Y");
    const auto& cpuId = images[1]["object-id"].channels.at("Y");
    const auto& gpuDepth = images[0]["depth"].channels.at("Y");
    const auto& cpuDepth = images[1]["depth"].channels.at("Y");
    std::size_t differentIds = 0;
    for (std::size_t i = 0; i < gpuId.size(); ++i) {
        if (gpuId[i] != cpuId[i]) {
            ++differentIds;
        } else if (std::isfinite(cpuDepth[i])) {
            ASSERT_NEAR(gpuDepth[i], cpuDepth[i], 1e-6 * cpuDepth[i]) << "pixel " << i;
        } else {
            ASSERT_TRUE(std::isinf(gpuDepth[i])) << "pixel " << i;
        }
    }
    EXPECT_LE(differentIds, 20u);  // at most a few silhouette pixels within rounding
}

TEST_F(InspectCliTest, CompareMaskMarksTheReportedMismatchesAndExcusedPixels) {
    // f32-naive disagrees with the reference on a few dozen pixels of this scene.
    const test::RunResult run = hexray("compare " + demoScene() + " --precision f32-naive --mask mask.png --aov aov");
    ASSERT_EQ(run.exitCode, 1) << run.out << run.err;
    const auto count = [&](const char* pattern) {
        std::smatch match;
        EXPECT_TRUE(std::regex_search(run.out, match, std::regex(pattern))) << pattern << " in " << run.out;
        return match.empty() ? std::size_t{0} : std::size_t(std::stoul(match[1]));
    };
    const std::size_t ambiguous = count(R"(ambiguous pixels[^:]*: (\d+))");
    const std::size_t excused = count(R"(excused pixels[^:]*: (\d+))");
    const std::size_t mismatches = count(R"(topology mismatches in decisions not near-tied: (\d+))");
    ASSERT_GT(mismatches, 0u);
    ASSERT_GT(excused, 0u);
    const Rgb8Image mask = readPng(dir_ / "mask.png");
    const auto margins = readExr(dir_ / "aov" / "cpu" / "margin.exr").channels.at("Y");
    ASSERT_EQ(margins.size() * 3, mask.bytes.size());
    std::size_t red = 0, blue = 0, navy = 0, other = 0, nearTied = 0, blueOrNavyNotNearTied = 0;
    for (std::size_t i = 0; i < margins.size(); ++i) {
        const int r = mask.bytes[3 * i], g = mask.bytes[3 * i + 1], b = mask.bytes[3 * i + 2];
        const bool isRed = r == 255 && g == 0 && b == 0, isBlue = r == 0 && g == 64 && b == 255;
        const bool isNavy = r == 0 && g == 0 && b == 112, isYellow = r == 255 && g == 255 && b == 0;
        red += isRed;
        blue += isBlue;
        navy += isNavy;
        other += !(r == 0 && g == 0 && b == 0) && !isRed && !isBlue && !isNavy && !isYellow;
        nearTied += margins[i] < 1.0f;  // margin.exr: in units of each decision's bound
        blueOrNavyNotNearTied += (isBlue || isNavy) && !(margins[i] < 1.0f);
    }
    EXPECT_EQ(red, mismatches);
    EXPECT_EQ(blue, excused);
    EXPECT_EQ(other, 0u);
    EXPECT_EQ(nearTied, ambiguous);  // the margin AOV marks the ambiguous pixels
    EXPECT_EQ(blueOrNavyNotNearTied, 0u);
    EXPECT_GT(navy, 0u);
    EXPECT_TRUE(fs::exists(dir_ / "aov" / "gpu" / "depth.exr"));
}

TEST_F(InspectCliTest, CompareMaskHasNoRedWhenTheRendersAgree) {
    const test::RunResult run = hexray("compare " + demoScene() + " --precision f32 --mask mask.png");
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    const Rgb8Image mask = readPng(dir_ / "mask.png");
    std::size_t blue = 0;
    for (std::size_t i = 0; i < mask.bytes.size(); i += 3) {
        ASSERT_FALSE(mask.bytes[i] == 255 && mask.bytes[i + 1] == 0) << "pixel " << i / 3 << " is red";
        blue += mask.bytes[i + 2] != 0;
    }
    EXPECT_GT(blue, 0u);  // the far checker cells and the shadow's edge have near-tied pixels
}

// A scene large enough for the data-driven kernel: the GPU trace follows its candidate lists and
// the CPU reference its BVH; the table lists only the nodes some backend hits and counts the rest.
TEST_F(InspectCliTest, PixelListsOnlyTheNodesHitInAManySphereScene) {
    // A 21 x 15 wall of spheres (radius 0.9, 2 apart) at z = 50 behind a floor at y = -5; the
    // centre pixel's ray passes within 0.5 of the sphere at (0, 14, 50): node 1 + 10 * 15 + 7.
    std::string nodes = R"({"geometry": {"type": "plane", "y": -5}, "shader": "s"})";
    for (int i = 0; i <= 20; ++i) {
        for (int j = 0; j < 15; ++j) {
            nodes += R"(, {"geometry": {"type": "sphere", "center": [)" + std::to_string(2 * i - 20) + ", " +
                     std::to_string(2 * j) + R"(, 50], "radius": 0.9}, "shader": "s"})";
        }
    }
    writeScene("wall.json", R"({"image": {"width": 128, "height": 96},
        "camera": {"position": [0, 14, -50], "yaw": 0, "pitch": 0, "roll": 0, "fov": 60},
        "lights": [{"position": [0, 40, -40], "color": [1, 1, 1], "intensity": 5000}],
        "shaders": {"s": {"type": "lambert", "color": [0.5, 0.5, 0.5]}},
        "nodes": [)" + nodes + "]}");
    const test::RunResult run = hexray("pixel wall.json 64 48");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(line(run.out, "hit").find("node 158, t = "), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("  314 other nodes: miss"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("gpu and cpu agree"), std::string::npos) << run.out;
}

}  // namespace
}  // namespace hexray
