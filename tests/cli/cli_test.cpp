// The real hexray executable, driven as a user would: exit codes, messages, and which files
// exist afterwards.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/cli_fixture.h"
#include "image/image_io.h"

namespace hexray {
namespace {

using test::CliTest;
using test::readFile;
using test::RunResult;
namespace fs = std::filesystem;

constexpr const char* kGoodScene = R"({
  "image": {"width": 32, "height": 24},
  "camera": {"position": [0, 60, -120], "fov": 90},
  "ambient": [0.15, 0.15, 0.15],
  "lights": [{"position": [30, 100, -70], "intensity": 10000}],
  "shaders": {"ball": {"type": "lambert", "color": [0.8, 0, 0]}},
  "nodes": [{"geometry": {"type": "sphere", "center": [-10, 60, 0], "radius": 10}, "shader": "ball"}]
})";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
}

TEST_F(CliTest, RenderWritesThePngAndSaysWhereAndHowLong) {
    const RunResult run = hexray("render " + scene("lecture-demo.json") + " -o demo.png --width 64 --height 48");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("wrote demo.png (64x48)"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("render "), std::string::npos);
    EXPECT_NE(run.out.find(" ms"), std::string::npos);
    const Rgb8Image image = readPng(dir_ / "demo.png");
    EXPECT_EQ(image.width, 64u);
    EXPECT_EQ(image.height, 48u);
}

TEST_F(CliTest, RenderDefaultsToTheSceneNameInTheCurrentDirectory) {
    const RunResult run = hexray("render " + scene("constant-debug.json") + " --backend cpu --width 40 --height 30");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("cpu reference"), std::string::npos) << run.out;
    EXPECT_TRUE(fs::exists(dir_ / "constant-debug.png"));
}

TEST_F(CliTest, RenderUnderTheValidationLayerIsClean) {
    const RunResult run =
        hexray("--validate render " + scene("spheres-and-lights.json") + " -o v.png --width 96 --height 54");
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err.find("validation"), std::string::npos) << run.err;
}

TEST_F(CliTest, ComparePrintsMetricsAndPassesOnTheDemoScene) {
    const RunResult run = hexray("compare " + scene("lecture-demo.json") + " --diff diff.png");
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    for (const char* expected :
         {"ambiguous pixels", "topology mismatches in decisions not near-tied: 0", "max abs", "mean abs", "RMSE",
          "PSNR", "pixels > 1 level", "linear [0,1]", "8-bit [levels]", "gpu f32, chosen by auto", "PASS"}) {
        EXPECT_NE(run.out.find(expected), std::string::npos) << expected << " missing from:\n" << run.out;
    }
    const Rgb8Image diff = readPng(dir_ / "diff.png");
    EXPECT_EQ(diff.width, 800u);
}

TEST_F(CliTest, CompareFailsWithExitCode1WhenTopologyDiffers) {
    // The textbook formulas in world coordinates cannot place a checker edge at 1e7.
    const RunResult run = hexray("compare " + scene("hard/checker-far-1e7.json") + " --precision f32-naive");
    EXPECT_EQ(run.exitCode, 1) << run.out << run.err;
    EXPECT_NE(run.out.find("EXCEEDED"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("FAIL"), std::string::npos);
}

// A floor lit by a light lying in it: cos theta is exactly 0 at every floor point, so every
// pixel's decision about that light is a knife edge. The checker cells 1e7 away are not: the
// textbook formulas in world coordinates (f32-naive) get many of them wrong.
constexpr const char* kLightInTheFloorScene = R"({
  "image": {"width": 64, "height": 64},
  "camera": {"position": [10000003.3, 50, -10000007.7], "pitch": -90, "fov": 60},
  "ambient": [0.1, 0.1, 0.1],
  "lights": [{"position": [10000000, 0, -10000000], "intensity": 10000}],
  "shaders": {"floor": {"type": "checker", "color1": [0.9, 0.9, 0.9], "color2": [0.1, 0.1, 0.1], "size": 1}},
  "nodes": [{"geometry": {"type": "plane", "y": 0}, "shader": "floor"}]
})";

TEST_F(CliTest, CompareFailsWhenTooManyPixelsAreAmbiguousUnlessTheLimitIsRaised) {
    writeScene("light-in-floor.json", kLightInTheFloorScene);
    RunResult run = hexray("compare light-in-floor.json --precision f32");
    EXPECT_EQ(run.exitCode, 1) << run.out << run.err;
    EXPECT_NE(run.out.find("ambiguous pixels 100.0000% <= 5.0000% EXCEEDED"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("FAIL"), std::string::npos) << run.out;

    run = hexray("compare light-in-floor.json --precision f32 --max-ambiguous 100");
    EXPECT_EQ(run.exitCode, 0) << run.out << run.err;
    EXPECT_NE(run.out.find("ambiguous pixels 100.0000% <= 100.0000% ok"), std::string::npos) << run.out;
}

TEST_F(CliTest, CompareStillChecksTheDecisionsOfAnAmbiguousPixelThatAreNotNearTied) {
    // Every pixel is ambiguous about the light, none about its checker cell: f32-naive's wrong
    // cells are topology mismatches.
    writeScene("light-in-floor.json", kLightInTheFloorScene);
    const RunResult run = hexray("compare light-in-floor.json --precision f32-naive --max-ambiguous 100");
    EXPECT_EQ(run.exitCode, 1) << run.out << run.err;
    std::smatch match;
    ASSERT_TRUE(std::regex_search(run.out, match, std::regex(R"(checker cell (\d+))"))) << run.out;
    EXPECT_GT(std::stoul(match[1]), 100u) << run.out;
    EXPECT_TRUE(std::regex_search(run.out, std::regex(R"(topology mismatches [1-9]\d* <= 0 EXCEEDED)"))) << run.out;
}

TEST_F(CliTest, CompareAllPrintsOneTableOfScenesAndPrecisions) {
    const RunResult run = hexray("compare --all " + scene("lecture-demo.json") + " " + scene("constant-debug.json"));
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    EXPECT_NE(run.out.find("| scene | precision | auto | topology mismatches | ambiguous |"), std::string::npos)
        << run.out;
    for (const char* row : {"| lecture-demo | f32-naive |", "| lecture-demo | f32 | ✓ |", "| lecture-demo | f64 |",
                            "| constant-debug | f32 | ✓ |"}) {
        EXPECT_NE(run.out.find(row), std::string::npos) << row << " missing from:\n" << run.out;
    }
}

TEST_F(CliTest, CompareDirectoryComparesEveryLoadableSceneAndFailsForTheOthers) {
    fs::create_directories(dir_ / "scenes");
    std::ofstream(dir_ / "scenes" / "a-good.json") << kGoodScene;
    std::ofstream(dir_ / "scenes" / "b-bad.json") << replaced(kGoodScene, "\"radius\": 10", "\"radius\": -3");
    std::ofstream(dir_ / "scenes" / "c-good.json") << kGoodScene;
    const RunResult run = hexray("compare scenes");
    EXPECT_EQ(run.exitCode, 2) << run.out << run.err;
    EXPECT_NE(run.out.find("| a-good | f32 | ✓ | 0 |"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("| c-good | f32 | ✓ | 0 |"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("| b-bad | – |"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("cannot load"), std::string::npos) << run.out;
    EXPECT_NE(run.err.find("b-bad.json: nodes[0].geometry.radius: must be > 0"), std::string::npos) << run.err;
    EXPECT_NE(run.out.find("FAIL"), std::string::npos) << run.out;
}

TEST_F(CliTest, RenderInDoublePrecisionSaysSo) {
    const RunResult run =
        hexray("render " + scene("lecture-demo.json") + " -o d.png --precision f64 --width 64 --height 48");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("gpu f64"), std::string::npos) << run.out;
}

// A scene whose lengths span more than float32 can hold (a ratio beyond 2^100: a 1e-30 sphere
// beside the lecture's): --precision f32 says so and renders in f64 instead, never silently wrong.
TEST_F(CliTest, RenderWarnsAndUsesF64WhenFloat32CannotHoldTheScene) {
    writeScene("wide.json", replaced(kGoodScene, R"("radius": 10}, "shader": "ball"})",
                                     R"("radius": 10}, "shader": "ball"},
                {"geometry": {"type": "sphere", "center": [5, 50, 0], "radius": 1e-30}, "shader": "ball"})"));
    const RunResult run = hexray("render wide.json -o w.png --precision f32 --backend gpu");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("hexray: warning: float32 cannot hold this scene (its lengths span 1e-30 to"),
              std::string::npos)
        << run.err;
    EXPECT_NE(run.err.find("a ratio beyond float32's 2^100); rendering in f64 instead"), std::string::npos) << run.err;
    EXPECT_NE(run.out.find("gpu f64"), std::string::npos) << run.out;
    const RunResult lecture =
        hexray("render " + scene("lecture-demo.json") + " -o l.png --precision f32 --width 64 --height 48");
    EXPECT_EQ(lecture.err.find("warning"), std::string::npos) << lecture.err;
}

TEST_F(CliTest, PrecisionWithTheCpuBackendIsRejected) {
    const RunResult run = hexray("render " + scene("lecture-demo.json") + " -o d.png --backend cpu --precision f64");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("--precision"), std::string::npos) << run.err;
    EXPECT_TRUE(createdFiles().empty());
}

#ifdef HEXRAY_WITH_EMBREE
constexpr bool kWithEmbree = true;
#else
constexpr bool kWithEmbree = false;
#endif

// The CSV's rows as field lists, keyed by nothing: the header is row 0.
std::vector<std::vector<std::string>> csvRows(const std::string& text) {
    std::vector<std::vector<std::string>> rows;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        std::vector<std::string> fields;
        std::istringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');) {
            fields.push_back(cell);
        }
        if (!line.empty() && line.back() == ',') {
            fields.emplace_back();
        }
        rows.push_back(fields);
    }
    return rows;
}

// The named column of a CSV row, found through the header.
std::string field(const std::vector<std::vector<std::string>>& rows, std::size_t row, const std::string& column) {
    const auto& header = rows.at(0);
    const auto at = std::find(header.begin(), header.end(), column);
    EXPECT_NE(at, header.end()) << column;
    return rows.at(row).at(std::size_t(at - header.begin()));
}

TEST_F(CliTest, BenchPrintsSpeedAgainstErrorAndWritesCsv) {
    const RunResult run = hexray("bench " + scene("lecture-demo.json") +
                                 " --width 48 --height 36 --rounds 2 --samples 1 --reference-samples 4 --csv b.csv");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("| scene | resolution | backend | kernel | precision | culling | spp | Mpix/s median |"),
              std::string::npos)
        << run.out;
    const auto rows = csvRows(readFile(dir_ / "b.csv"));
    // header + f32-naive, f32, f64 and f32-certified each whole and culled, the demo's hand-written
    // kernel, cpu-reference (+ Embree at its best)
    ASSERT_EQ(rows.size(), kWithEmbree ? 11u : 10u) << readFile(dir_ / "b.csv");
    for (std::size_t row = 1; row < rows.size(); ++row) {
        EXPECT_EQ(field(rows, row, "scene"), "lecture-demo");
        EXPECT_EQ(field(rows, row, "width"), "48");
        EXPECT_GT(std::stod(field(rows, row, "median_mpix_s")), 0.0);
        const std::string backend = field(rows, row, "backend");
        const std::string precision = field(rows, row, "precision_used");
        // The robust shader, the reference itself and Embree agree with the reference on every
        // unambiguous pixel: topology 0. Their colour is within a few levels of the converged image.
        if (backend == "lavapipe hand-written") {
            EXPECT_EQ(precision, "f32-naive");
            EXPECT_EQ(field(rows, row, "kernel"), "hand-written");
            EXPECT_EQ(field(rows, row, "topology_mismatches"), "");  // it writes no pixel classes
        } else if (precision != "f32-naive") {
            EXPECT_EQ(field(rows, row, "topology_mismatches"), "0") << backend << ' ' << precision;
        }
        EXPECT_EQ(field(rows, row, "vs_embree").empty(), !kWithEmbree) << backend;
        EXPECT_FALSE(field(rows, row, "vs_hand_written").empty()) << backend;
        // Only f32-certified rows send pixels to an f64 pass, and the demo has some on its checker edges.
        if (precision == "f32-certified") {
            EXPECT_GT(std::stod(field(rows, row, "f64_pass_pixel_share")), 0.0);
            EXPECT_GE(std::stod(field(rows, row, "f64_pass_vector_share")),
                      std::stod(field(rows, row, "f64_pass_pixel_share")));
        } else {
            EXPECT_EQ(field(rows, row, "f64_pass_pixel_share"), "") << backend << ' ' << precision;
        }
        // The kernels generated for the scene say how much they test per pixel; culling tests less.
        if (backend == "lavapipe" && field(rows, row, "culling_asked") == "off") {
            EXPECT_EQ(field(rows, row, "primary_tests_per_pixel"), "2") << precision;
        } else if (backend == "lavapipe") {
            EXPECT_LT(std::stod(field(rows, row, "primary_tests_per_pixel")), 2.0) << precision;
        } else {
            EXPECT_EQ(field(rows, row, "primary_tests_per_pixel"), "") << backend;
        }
    }
    EXPECT_NE(run.out.find(kWithEmbree ? "Embree: Embree 3." : "built without Embree"), std::string::npos) << run.out;
}

// f32-naive's shadow lists at 100k spheres take a pixel past lavapipe's loop limit, so its plan is
// refused: the curve leaves that row out with the reason and measures the others.
TEST_F(CliTest, BenchSphereCurveLeavesOutARowWhosePlanIsRefused) {
    const RunResult run = hexray(
        "bench --spheres 100000 --width 32 --height 18 --rounds 1 --samples 1 "
        "--backends gpu-f32,gpu-f32-naive --max-frame-seconds 1e9 --csv c.csv");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("lavapipe f32-naive at 1 spp: not measured at 100000 spheres: "), std::string::npos)
        << run.out;
    EXPECT_NE(run.out.find("65535"), std::string::npos) << run.out;
    const auto rows = csvRows(readFile(dir_ / "c.csv"));
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(field(rows, 1, "precision_used"), "f32");
}

TEST_F(CliTest, BenchSphereCurveHasARowPerBackendAndCount) {
    // --max-frame-seconds out of reach: the probe that leaves slow backends out measures time, and
    // the rows must not depend on how fast or loaded the machine is.
    const RunResult run = hexray(
        "bench --spheres 1,20 --width 64 --height 36 --rounds 1 --samples 1 --max-frame-seconds 1e9 --csv c.csv");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("| spheres | resolution | backend | kernel | precision | culling | spp | Mpix/s median |"),
              std::string::npos)
        << run.out;
    const std::string text = readFile(dir_ / "c.csv");
    const auto rows = csvRows(text);
    // lavapipe f32 and f32-naive, cpu-reference (, embree)
    const std::size_t backends = kWithEmbree ? 4 : 3;
    ASSERT_EQ(rows.size(), 1 + 2 * backends) << text;
    std::map<std::string, int> perCount;
    for (std::size_t row = 1; row < rows.size(); ++row) {
        SCOPED_TRACE(text);
        EXPECT_EQ(field(rows, row, "scene"), "random-spheres");
        EXPECT_EQ(field(rows, row, "width"), "64");
        EXPECT_EQ(field(rows, row, "height"), "36");
        ++perCount[field(rows, row, "spheres")];
        EXPECT_GT(std::stod(field(rows, row, "median_mpix_s")), 0.0);
        EXPECT_GT(std::stod(field(rows, row, "core_ns_per_pixel")), 0.0);
        EXPECT_GE(std::stoi(field(rows, row, "threads")), 1);
        const std::string backend = field(rows, row, "backend");
        // The curve's reference is the CPU reference at the same sample count: its own row is exact.
        if (backend == "cpu-reference") {
            EXPECT_EQ(field(rows, row, "precision_rmse_levels"), "0");
            EXPECT_EQ(field(rows, row, "precision_flip_mean"), "0");
        }
        const bool naive = field(rows, row, "precision_used") == "f32-naive";  // the textbook's errors are its own
        EXPECT_TRUE(!naive || backend == "lavapipe") << backend;
        EXPECT_LT(std::stod(field(rows, row, "precision_rmse_levels")), naive ? 255.0 : 1.0) << backend;
        const double flip = std::stod(field(rows, row, "precision_flip_mean"));
        EXPECT_GE(flip, 0.0) << backend;
        EXPECT_LE(flip, 1.0) << backend;
        if (!naive) {
            EXPECT_EQ(field(rows, row, "topology_mismatches"), "0") << backend;
        }
        if (kWithEmbree) {
            const double versus = std::stod(field(rows, row, "vs_embree"));
            EXPECT_GT(versus, 0.0);
            if (backend.starts_with("embree")) {
                EXPECT_EQ(versus, 1.0);  // against itself, the one Embree row
            }
        }
    }
    EXPECT_EQ(perCount, (std::map<std::string, int>{{"1", int(backends)}, {"20", int(backends)}}));
}

TEST_F(CliTest, BenchWithoutASceneBenchesTheShippedDemoScene) {
    const RunResult run = hexray("bench --rounds 1 --samples 1 --width 32 --height 24 --reference-samples 2");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("| lecture-demo | 32x24 | lavapipe hand-written |"), std::string::npos) << run.out;
}

TEST_F(CliTest, AnUnwritableOutputIsExitCode5AndLeavesNothing) {
    const RunResult run =
        hexray("render " + scene("constant-debug.json") + " -o no-such-dir/x.png --width 8 --height 8");
    EXPECT_EQ(run.exitCode, 5) << run.err;
    EXPECT_NE(run.err.find("no-such-dir/x.png: cannot create output file"), std::string::npos) << run.err;
    EXPECT_TRUE(createdFiles().empty());
}

TEST_F(CliTest, AnUnreadablePathIsBadInputNotACrash) {
    const RunResult run = hexray("compare " + std::string(300, 'a') + "/x.json");
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find("hexray: error: "), std::string::npos) << run.err;
}

TEST_F(CliTest, DevicesListsLavapipe) {
    const RunResult run = hexray("devices");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("llvmpipe"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("* "), std::string::npos) << run.out;
}

TEST_F(CliTest, UnknownDeviceIsAVulkanErrorThatListsTheDevices) {
    const RunResult run = hexray("render " + scene("lecture-demo.json") + " -o x.png --device no-such-gpu");
    EXPECT_EQ(run.exitCode, 3);
    EXPECT_NE(run.err.find("no Vulkan device matches --device no-such-gpu"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("llvmpipe"), std::string::npos) << run.err;
    EXPECT_TRUE(createdFiles().empty());
}

TEST_F(CliTest, NoVulkanDriverNamesThePackageAndTheCpuBackend) {
    const RunResult run = hexray("render " + scene("lecture-demo.json") + " -o x.png --backend gpu",
                                 "VK_ICD_FILENAMES=/nonexistent/icd.json VK_DRIVER_FILES=/nonexistent/icd.json");
    EXPECT_EQ(run.exitCode, 3);
    EXPECT_NE(run.err.find("mesa-vulkan-drivers"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("--backend cpu"), std::string::npos) << run.err;
    EXPECT_TRUE(createdFiles().empty());
}

// Each bad input: exit code 2, a message naming the file and the place, and no output file
// created or replaced.
struct BadInput {
    const char* name;
    std::string sceneText;  // empty: no scene file written (a missing file)
    const char* extraArguments;
    const char* expectedMessage;
};

void PrintTo(const BadInput& bad, std::ostream* out) {
    *out << bad.name;
}

class BadInputTest : public CliTest, public ::testing::WithParamInterface<BadInput> {};

TEST_P(BadInputTest, IsRejectedWithExitCode2AndNoOutput) {
    const BadInput& bad = GetParam();
    if (!bad.sceneText.empty()) {
        writeScene("bad.json", bad.sceneText);
    }
    std::ofstream(dir_ / "existing.png") << "keep me";
    for (const std::string target : {"new.png", "existing.png"}) {
        const RunResult run = hexray("render bad.json -o " + target + " " + bad.extraArguments);
        EXPECT_EQ(run.exitCode, 2) << run.err;
        EXPECT_NE(run.err.find(bad.expectedMessage), std::string::npos)
            << "expected \"" << bad.expectedMessage << "\" in:\n"
            << run.err;
        EXPECT_EQ(run.out, "");
    }
    EXPECT_FALSE(fs::exists(dir_ / "new.png"));
    EXPECT_EQ(readFile(dir_ / "existing.png"), "keep me");
    EXPECT_EQ(createdFiles(), std::vector<std::string>{"existing.png"});
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, BadInputTest,
    ::testing::Values(
        BadInput{"MalformedJson", replaced(kGoodScene, "\"width\": 32,", "\"width\": 32"), "",
                 "bad.json:2:32: JSON syntax error"},
        BadInput{"MissingField", replaced(kGoodScene, ", \"radius\": 10", ""), "",
                 "bad.json: nodes[0].geometry.radius: missing required field"},
        BadInput{"MistypedField", replaced(kGoodScene, "\"radius\": 10", "\"radius\": \"big\""), "",
                 "bad.json: nodes[0].geometry.radius"},
        BadInput{"UnknownShader", replaced(kGoodScene, "\"shader\": \"ball\"", "\"shader\": \"bal\""), "",
                 "bad.json: nodes[0].shader: unknown shader \"bal\""},
        BadInput{"NonFiniteNumber", replaced(kGoodScene, "\"intensity\": 10000", "\"intensity\": 1e999"), "",
                 "bad.json: lights[0].intensity"},
        BadInput{"ZeroRadius", replaced(kGoodScene, "\"radius\": 10", "\"radius\": 0"), "",
                 "bad.json: nodes[0].geometry.radius: must be > 0"},
        BadInput{"NegativeRadius", replaced(kGoodScene, "\"radius\": 10", "\"radius\": -3"), "",
                 "bad.json: nodes[0].geometry.radius: must be > 0"},
        BadInput{"PlaneBeyondTheSupportedRange",
                 replaced(kGoodScene, R"({"type": "sphere", "center": [-10, 60, 0], "radius": 10})",
                          R"({"type": "plane", "y": 1e308})"),
                 "",
                 "bad.json: nodes[0].geometry.y: must be 0 or between 1e-50 and 1e+50 in magnitude, the supported "
                 "range of lengths (got 1e+308)"},
        BadInput{"RadiusBeyondTheSupportedRange", replaced(kGoodScene, "\"radius\": 10", "\"radius\": 1e308"), "",
                 "bad.json: nodes[0].geometry.radius: must be between 1e-50 and 1e+50 in magnitude, the supported "
                 "range of lengths (got 1e+308)"},
        BadInput{"FovZero", replaced(kGoodScene, "\"fov\": 90", "\"fov\": 0"), "", "bad.json: camera.fov"},
        BadInput{"Fov180", replaced(kGoodScene, "\"fov\": 90", "\"fov\": 180"), "", "bad.json: camera.fov"},
        BadInput{"WidthZero", replaced(kGoodScene, "\"width\": 32", "\"width\": 0"), "", "bad.json: image.width"},
        BadInput{"WidthAbsurd", replaced(kGoodScene, "\"width\": 32", "\"width\": 1000000"), "",
                 "bad.json: image.width"},
        BadInput{"UnknownKey", replaced(kGoodScene, "\"fov\": 90", "\"fvo\": 90"), "",
                 "bad.json: camera.fvo: unknown key"},
        BadInput{"MissingFile", "", "", "bad.json: cannot read scene file"},
        BadInput{"WidthOverrideZero", kGoodScene, "--width 0",
                 "--width: must be an integer between 1 and 16384 (got 0)"},
        BadInput{"HeightOverrideAbsurd", kGoodScene, "--height 99999999",
                 "--height: must be an integer between 1 and 16384 (got 99999999)"},
        BadInput{"UnknownBackend", kGoodScene, "--backend quantum", "--backend"}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace hexray
