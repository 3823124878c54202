// The real hexray executable, driven as a user would: exit codes, messages, and which files
// exist afterwards.

#include <sys/wait.h>

#include <csignal>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

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
    const RunResult run = hexray("--validate render " + scene("spheres-and-lights.json") + " -o v.png --width 96 --height 54");
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err.find("validation"), std::string::npos) << run.err;
}

TEST_F(CliTest, ComparePrintsMetricsAndPassesOnTheDemoScene) {
    const RunResult run = hexray("compare " + scene("lecture-demo.json") + " --diff diff.png");
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    for (const char* expected : {"ambiguous pixels", "topology mismatches on unambiguous pixels: 0", "max abs",
                                 "mean abs", "RMSE", "PSNR", "pixels > 1 level", "linear [0,1]", "8-bit [levels]",
                                 "gpu f32, chosen by auto", "PASS"}) {
        EXPECT_NE(run.out.find(expected), std::string::npos) << expected << " missing from:\n" << run.out;
    }
    const Rgb8Image diff = readPng(dir_ / "diff.png");
    EXPECT_EQ(diff.width, 800u);
}

TEST_F(CliTest, CompareFailsWithExitCode1WhenTopologyDiffers) {
    // The textbook formulas in world coordinates cannot place a checker edge at 1e7.
    const RunResult run =
        hexray("compare " + scene("hard/checker-far-1e7.json") + " --precision f32-naive");
    EXPECT_EQ(run.exitCode, 1) << run.out << run.err;
    EXPECT_NE(run.out.find("EXCEEDED"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("FAIL"), std::string::npos);
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

TEST_F(CliTest, RenderInDoublePrecisionSaysSo) {
    const RunResult run = hexray("render " + scene("lecture-demo.json") + " -o d.png --precision f64 --width 64 --height 48");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("gpu f64"), std::string::npos) << run.out;
}

TEST_F(CliTest, PrecisionWithTheCpuBackendIsRejected) {
    const RunResult run = hexray("render " + scene("lecture-demo.json") + " -o d.png --backend cpu --precision f64");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("--precision"), std::string::npos) << run.err;
    EXPECT_TRUE(createdFiles().empty());
}

TEST_F(CliTest, BenchPrintsSpeedAgainstErrorAndWritesCsv) {
    const RunResult run = hexray("bench " + scene("lecture-demo.json") +
                                 " --width 48 --height 36 --rounds 2 --samples 1 --reference-samples 4 --csv b.csv");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("| scene | resolution | backend | precision | spp | Mpix/s median |"), std::string::npos)
        << run.out;
    const std::string csv = readFile(dir_ / "b.csv");
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5) << csv;  // header + f32-naive, f32, f64, cpu-reference
    // The robust shader agrees with the reference on every unambiguous pixel: topology 0.
    EXPECT_NE(csv.find("lecture-demo,48,36,lavapipe,f32,1,"), std::string::npos) << csv;
    for (const std::string& line : {std::string("lavapipe,f32,1,"), std::string("lavapipe,f64,1,")}) {
        const auto at = csv.find(line);
        ASSERT_NE(at, std::string::npos) << csv;
        const std::string row = csv.substr(at, csv.find('\n', at) - at);
        EXPECT_EQ(row.substr(row.rfind(',') + 1), "0") << row;
    }
}

TEST_F(CliTest, AnUnwritableOutputIsExitCode5AndLeavesNothing) {
    const RunResult run = hexray("render " + scene("constant-debug.json") + " -o no-such-dir/x.png --width 8 --height 8");
    EXPECT_EQ(run.exitCode, 5) << run.err;
    EXPECT_NE(run.err.find("no-such-dir/x.png: cannot create output file"), std::string::npos) << run.err;
    EXPECT_TRUE(createdFiles().empty());
}

TEST_F(CliTest, AnUnreadablePathIsBadInputNotACrash) {
    const RunResult run = hexray("compare " + std::string(300, 'a') + "/x.json");
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find("hexray: error: "), std::string::npos) << run.err;
}

TEST_F(CliTest, AnInterruptedRenderLeavesTheOldImageAndNoTemporaryFile) {
    std::ofstream(dir_ / "big.png") << "keep me";
    // A render of several seconds, terminated after one: the partial file must go. (SIGTERM, as
    // a background job started by sh ignores SIGINT.)
    const std::string command = "cd '" + dir_.string() + "' && ('" HEXRAY_EXECUTABLE "' render " +
                                scene("lecture-demo.json") +
                                " -o big.png --width 8192 --height 8192 --spp 2 >/dev/null 2>&1 & pid=$!; sleep 1; "
                                "kill -TERM $pid; wait $pid)";
    const int status = std::system(command.c_str());
    EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 128 + SIGTERM);  // killed by the signal
    EXPECT_EQ(readFile(dir_ / "big.png"), "keep me");
    EXPECT_EQ(createdFiles(), std::vector<std::string>{"big.png"});
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
            << "expected \"" << bad.expectedMessage << "\" in:\n" << run.err;
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
        BadInput{"FovZero", replaced(kGoodScene, "\"fov\": 90", "\"fov\": 0"), "", "bad.json: camera.fov"},
        BadInput{"Fov180", replaced(kGoodScene, "\"fov\": 90", "\"fov\": 180"), "", "bad.json: camera.fov"},
        BadInput{"WidthZero", replaced(kGoodScene, "\"width\": 32", "\"width\": 0"), "", "bad.json: image.width"},
        BadInput{"WidthAbsurd", replaced(kGoodScene, "\"width\": 32", "\"width\": 1000000"), "",
                 "bad.json: image.width"},
        BadInput{"UnknownKey", replaced(kGoodScene, "\"fov\": 90", "\"fvo\": 90"), "",
                 "bad.json: camera.fvo: unknown key"},
        BadInput{"MissingFile", "", "", "bad.json: cannot read scene file"},
        BadInput{"WidthOverrideZero", kGoodScene, "--width 0", "--width: must be between 1 and 16384 (got 0)"},
        BadInput{"HeightOverrideAbsurd", kGoodScene, "--height 99999999",
                 "--height: must be between 1 and 16384 (got 99999999)"},
        BadInput{"UnknownBackend", kGoodScene, "--backend quantum", "--backend"}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace hexray
