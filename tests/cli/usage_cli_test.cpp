// A command line that explains itself: --version, an unknown command named, global options after
// the command, help that says true things and points nowhere the user cannot follow, and
// progress on a terminal only.

#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/cli_fixture.h"

namespace hexray {
namespace {

using test::CliTest;
using test::RunResult;

TEST_F(CliTest, VersionNamesHexrayItsRevisionTheLoaderAndTheDeviceWithItsDriver) {
    const RunResult run = hexray("--version");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_TRUE(std::regex_search(run.out, std::regex("^hexray \\d+\\.\\d+\\.\\d+ \\(git ([0-9a-f]{12}|unknown)")))
        << run.out;
    EXPECT_TRUE(std::regex_search(run.out, std::regex("\nVulkan loader 1\\.\\d+\\.\\d+\n"))) << run.out;
    EXPECT_NE(run.out.find("\ndevice: llvmpipe"), std::string::npos) << run.out;  // the tests run on lavapipe
    EXPECT_NE(run.out.find(", driver llvmpipe Mesa"), std::string::npos) << run.out;
}

TEST_F(CliTest, VersionWithoutVulkanSaysSoAndSucceeds) {
    const RunResult run = hexray("--version", "VK_DRIVER_FILES=/nonexistent.json VK_ICD_FILENAMES=/nonexistent.json");
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("hexray "), std::string::npos);
    EXPECT_NE(run.out.find("device: none: Vulkan is unavailable (no Vulkan driver found)"), std::string::npos)
        << run.out;
}

TEST_F(CliTest, AnUnknownCommandIsNamedWithTheKnownOnes) {
    for (const char* line : {"frobnicate", "--validate frobnicate scene.json"}) {
        const RunResult run = hexray(line);
        EXPECT_EQ(run.exitCode, 2) << line;
        EXPECT_NE(
            run.err.find(
                "hexray: error: unknown command 'frobnicate' (the commands are render, watch, merge, compare, diff, "
                "bench, pixel, devices"),
            std::string::npos)
            << run.err;
    }
    const RunResult none = hexray("--validate");
    EXPECT_EQ(none.exitCode, 2);
    EXPECT_NE(none.err.find(
                  "hexray: error: a command is required: render, watch, merge, compare, diff, bench, pixel, devices"),
              std::string::npos)
        << none.err;
    const RunResult noScene = hexray("render");
    EXPECT_EQ(noScene.exitCode, 2);
    EXPECT_NE(noScene.err.find("hexray: error: render needs its scenes argument"), std::string::npos) << noScene.err;
}

TEST_F(CliTest, GlobalOptionsAreAcceptedAfterTheCommand) {
    const std::string render = "render " + scene("lecture-demo.json") + " --width 24 --height 16 -o v.png";
    EXPECT_EQ(hexray(render + " --validate").exitCode, 0);
    // It reaches the command: without the layer to load, --validate after the command fails as
    // before it, and the render without it does not.
    const std::string noLayers = "VK_LAYER_PATH=/nonexistent";
    for (const std::string& line : {render + " --validate", "--validate " + render}) {
        const RunResult run = hexray(line, noLayers);
        EXPECT_EQ(run.exitCode, 3) << line;
        EXPECT_NE(run.err.find("validation was requested but VK_LAYER_KHRONOS_validation is not installed"),
                  std::string::npos)
            << run.err;
    }
    EXPECT_EQ(hexray(render, noLayers).exitCode, 0);
    const RunResult version = hexray("devices --version");
    EXPECT_EQ(version.exitCode, 0) << version.err;
    EXPECT_NE(version.out.find("Vulkan loader"), std::string::npos) << version.out;
}

TEST_F(CliTest, HelpSaysTheTruthAndPointsToNoFileTheUserLacks) {
    std::string help;
    for (const char* command : {"", "render", "merge", "compare", "bench", "pixel", "devices"}) {
        const RunResult run = hexray(std::string(command) + " --help");
        EXPECT_EQ(run.exitCode, 0) << command;
        help += run.out;
    }
    EXPECT_EQ(help.find("README"), std::string::npos) << help;
    EXPECT_EQ(help.find("default 1)"), std::string::npos) << help;
    EXPECT_NE(help.find("default: the scene's image.spp"), std::string::npos) << help;
    EXPECT_NE(help.find(".exr (linear float RGB"), std::string::npos) << help;
    EXPECT_NE(help.find("--strip"), std::string::npos) << help;
}

// Progress lines go to a terminal, and only there: `script` gives the command a pseudo-terminal.
class ProgressCliTest : public CliTest {
protected:
    RunResult onTerminal(const std::string& arguments) const {
        return shell("script -qec \"\\\"$HEXRAY\\\" " + arguments + "\" /dev/null");
    }
};

TEST_F(ProgressCliTest, RenderShowsRowsDoneAndTimeLeftOnATerminalOnBothBackends) {
    const std::string cpu =
        "render " + scene("lecture-demo.json") + " --backend cpu --width 200 --height 1500 -o c.png";
    RunResult run = onTerminal(cpu);
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    EXPECT_TRUE(std::regex_search(run.out, std::regex("rendering [^:]*lecture-demo.json: \\d+% \\(\\d+ of 1500 "
                                                      "rows\\), \\d+\\.\\d s left")))
        << run.out;
    // The GPU's bands of 256 MiB of pixels: 1024 rows each at this width.
    run = onTerminal("render " + scene("lecture-demo.json") + " --backend gpu --width 16384 --height 2100 -o g.png");
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    EXPECT_TRUE(
        std::regex_search(run.out, std::regex("rendering [^:]*: \\d+% \\(\\d+ of 2100 rows\\), \\d+\\.\\d s left")))
        << run.out;
}

TEST_F(ProgressCliTest, CompareAndALargeSceneLoadShowProgressOnATerminal) {
    RunResult run = onTerminal("compare " + scene("lecture-demo.json"));
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    EXPECT_TRUE(
        std::regex_search(run.out, std::regex("comparing [^:]*: \\d+% \\(\\d+ of 600 rows\\), \\d+\\.\\d s left")))
        << run.out;
    // Some 3 MB of spheres: progress every MiB parsed.
    {
        std::ofstream big(dir_ / "big.json");
        big << R"({"image": {"width": 8, "height": 8}, "camera": {"position": [0, 0, -10]},)"
            << R"("shaders": {"s": {"type": "constant", "color": [1, 1, 1]}}, "nodes": [)";
        for (int i = 0; i < 40000; ++i) {
            big << (i ? "," : "") << R"({"geometry": {"type": "sphere", "center": [)" << i
                << R"(, 0.5, 100], "radius": 0.25}, "shader": "s"})";
        }
        big << "]}";
    }
    run = onTerminal("render big.json --backend cpu -o big.png");
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    EXPECT_TRUE(std::regex_search(run.out, std::regex("loading big.json: \\d+% \\(\\d\\.\\d of \\d\\.\\d MB\\)")))
        << run.out;
}

TEST_F(ProgressCliTest, BenchShowsMeasurementsDoneAndTimeLeftOnATerminal) {
    const RunResult run = onTerminal("bench " + scene("lecture-demo.json") +
                                     " --width 64 --height 48 --rounds 2 --samples 1 --reference-samples 1");
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    EXPECT_TRUE(
        std::regex_search(run.out, std::regex("bench: \\d+% \\(\\d+ of \\d+ measurements\\), \\d+\\.\\d s left")))
        << run.out;
    EXPECT_EQ(run.out.find("bench: round 1 of 2"), std::string::npos) << run.out;
}

TEST_F(ProgressCliTest, NothingIsShownWhenStandardErrorIsNotATerminal) {
    const RunResult run =
        hexray("render " + scene("lecture-demo.json") + " --backend cpu --width 200 --height 1500 -o c.png");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err, "");
    const RunResult compare = hexray("compare " + scene("lecture-demo.json"));
    ASSERT_EQ(compare.exitCode, 0) << compare.err;
    EXPECT_EQ(compare.err, "");
}

}  // namespace
}  // namespace hexray
