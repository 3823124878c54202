// `hexray render` of several scenes in one process: an image each, named after its scene,
// collisions refused before any work, a failed scene (or a directory that cannot be searched)
// reported while the others render.

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/cli_fixture.h"
#include "kernels/kept_kernels.h"
#include "image/image_io.h"

namespace hexray {
namespace {

using test::CliTest;
using test::readFile;
using test::RunResult;
namespace fs = std::filesystem;

constexpr const char* kSize = " --width 40 --height 30";

std::vector<std::uint8_t> pixelsOf(const fs::path& png) {
    return readPng(png).bytes;
}

TEST_F(CliTest, RenderOfSeveralScenesWritesEachToItsOwnImageInOneProcess) {
    fs::create_directories(dir_ / "out");
    const RunResult run = hexray("render " + scene("lecture-demo.json") + " " + scene("constant-debug.json") + " " +
                                 scene("spheres-and-lights.json") + " -o out" + kSize);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("rendered 3 of 3 scenes"), std::string::npos) << run.out;
    for (const char* name : {"lecture-demo", "constant-debug", "spheres-and-lights"}) {
        ASSERT_TRUE(fs::exists(dir_ / "out" / (std::string(name) + ".png"))) << name;
        // Each exactly what a render of that scene alone writes.
        const RunResult alone = hexray("render " + scene(std::string(name) + ".json") + " -o alone.png" + kSize);
        ASSERT_EQ(alone.exitCode, 0) << alone.err;
        EXPECT_EQ(pixelsOf(dir_ / "out" / (std::string(name) + ".png")), pixelsOf(dir_ / "alone.png")) << name;
    }
}

// A small scene whose structure is `structure`'s binary digits (1: a sphere, 0: a plane), so that
// each number gets its own generated kernel.
std::string sceneOfStructure(unsigned structure) {
    std::string nodes;
    for (unsigned digit = 0, rest = structure; rest > 0; ++digit, rest >>= 1) {
        nodes += nodes.empty() ? "" : ",";
        nodes += rest & 1 ? "{\"geometry\": {\"type\": \"sphere\", \"center\": [" + std::to_string(-3.0 + 1.5 * digit) +
                                ", 0.5, " + std::to_string(4 + digit) + "], \"radius\": 0.7}, \"shader\": \"matte\"}"
                          : "{\"geometry\": {\"type\": \"plane\", \"y\": " + std::to_string(-1.0 - digit) +
                                "}, \"shader\": \"squares\"}";
    }
    return R"({"image": {"width": 24, "height": 16}, "camera": {"position": [0, 2, -6]}, "ambient": [0.1, 0.1, 0.1],
               "lights": [{"position": [3, 8, -2], "intensity": 60}],
               "shaders": {"matte": {"type": "lambert", "color": [0.7, 0.4, 0.2]},
                           "squares": {"type": "checker", "color1": [0.9, 0.9, 0.9], "color2": [0.1, 0.1, 0.1],
                                       "size": 1}},
               "nodes": [)" +
           nodes + "]}";
}

TEST_F(CliTest, ABatchOfMoreScenesThanTheRendererKeepsKernelsForGivesEachTheImageItGetsAlone) {
    // More distinct kernels than are kept, and the first scene again at the end, after its kernel
    // and pipeline were dropped.
    const unsigned scenes = unsigned(std::max(kKeptPipelines, kKeptGeneratedKernels)) + 4;
    fs::create_directories(dir_ / "scenes");
    fs::create_directories(dir_ / "out");
    for (unsigned i = 0; i <= scenes; ++i) {
        writeScene("scenes/s" + std::to_string(100 + i) + ".json", sceneOfStructure(i < scenes ? i + 1 : 1));
    }
    const RunResult run = hexray("render scenes --backend gpu -o out/");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    for (unsigned i = 0; i <= scenes; ++i) {
        const std::string name = "s" + std::to_string(100 + i);
        const RunResult alone = hexray("render scenes/" + name + ".json --backend gpu -o alone.png");
        ASSERT_EQ(alone.exitCode, 0) << alone.err;
        EXPECT_EQ(pixelsOf(dir_ / "out" / (name + ".png")), pixelsOf(dir_ / "alone.png")) << name;
    }
    const std::string last = "s" + std::to_string(100 + scenes) + ".png";
    EXPECT_EQ(pixelsOf(dir_ / "out" / "s100.png"), pixelsOf(dir_ / "out" / last));
}

TEST_F(CliTest, RenderOfADirectoryRendersEverySceneInItIntoTheCurrentDirectory) {
    fs::create_directories(dir_ / "scenes" / "more");
    fs::copy_file(test::sourcePath("scenes/lecture-demo.json"), dir_ / "scenes" / "a.json");
    fs::copy_file(test::sourcePath("scenes/constant-debug.json"), dir_ / "scenes" / "more" / "b.json");
    const RunResult run = hexray("render scenes --backend cpu" + std::string(kSize));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_TRUE(fs::exists(dir_ / "a.png"));
    EXPECT_TRUE(fs::exists(dir_ / "b.png"));
}

TEST_F(CliTest, RenderRefusesScenesWhoseImagesWouldHaveTheSameNameBeforeAnyWork) {
    fs::create_directories(dir_ / "x");
    fs::create_directories(dir_ / "y");
    fs::copy_file(test::sourcePath("scenes/lecture-demo.json"), dir_ / "x" / "scene.json");
    fs::copy_file(test::sourcePath("scenes/constant-debug.json"), dir_ / "y" / "scene.json");
    const RunResult run = hexray("render " + scene("lecture-demo.json") + " x/scene.json y/scene.json" + kSize);
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find("scenes x/scene.json and y/scene.json would both be written to scene.png"),
              std::string::npos)
        << run.err;
    EXPECT_EQ(createdFiles(), std::vector<std::string>({"x", "y"}));  // not even the first scene's image
}

TEST_F(CliTest, RenderOfSeveralScenesNeedsAnExistingDirectoryForMinusO) {
    const std::string scenes = "render " + scene("lecture-demo.json") + " " + scene("constant-debug.json");
    RunResult run = hexray(scenes + " -o both.png" + kSize);
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find("-o both.png: 2 scenes are rendered into a directory, and this is not one"),
              std::string::npos)
        << run.err;
    run = hexray(scenes + " -o missing/" + kSize);
    EXPECT_EQ(run.exitCode, 5) << run.err;
    EXPECT_NE(run.err.find("-o missing/: no such directory"), std::string::npos) << run.err;
    run = hexray(scenes + " -o -" + kSize);
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_EQ(createdFiles(), std::vector<std::string>{});
}

TEST_F(CliTest, RenderOfSeveralScenesRefusesAnImageThatWouldReplaceOneOfTheScenesBeforeAnyWork) {
    // b.png is a hard link to a.json: the image of scene b would destroy scene a.
    fs::copy_file(test::sourcePath("scenes/lecture-demo.json"), dir_ / "a.json");
    fs::copy_file(test::sourcePath("scenes/constant-debug.json"), dir_ / "b.json");
    fs::create_hard_link(dir_ / "a.json", dir_ / "b.png");
    const std::string original = readFile(dir_ / "a.json");
    const RunResult run = hexray("render a.json b.json -o ." + std::string(kSize));
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find("./b.png: the same file as the scene a.json"), std::string::npos) << run.err;
    EXPECT_EQ(readFile(dir_ / "a.json"), original);
    EXPECT_FALSE(fs::exists(dir_ / "a.png"));
}

TEST_F(CliTest, AFailedSceneIsReportedTheOthersStillRenderAndTheExitCodeIsTheFirstFailures) {
    writeScene("bad.json", "{\"image\": {\"width\": 8}}");
    const RunResult run = hexray("render " + scene("lecture-demo.json") + " bad.json missing.json " +
                                 scene("constant-debug.json") + kSize);
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find("bad.json: image.height: missing required field"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("missing.json: cannot read scene file"), std::string::npos) << run.err;
    EXPECT_NE(run.out.find("rendered 2 of 4 scenes; failed: bad.json, missing.json"), std::string::npos) << run.out;
    EXPECT_EQ(createdFiles(), std::vector<std::string>({"constant-debug.png", "lecture-demo.png"}));
}

// scenes/a.json, scenes/B.JSON, and scenes/locked/c.json in a directory hexray may not read.
class SceneDirectoryTest : public CliTest {
protected:
    void SetUp() override {
        CliTest::SetUp();
        fs::create_directories(dir_ / "scenes" / "locked");
        fs::copy_file(test::sourcePath("scenes/lecture-demo.json"), dir_ / "scenes" / "a.json");
        fs::copy_file(test::sourcePath("scenes/constant-debug.json"), dir_ / "scenes" / "B.JSON");
        fs::copy_file(test::sourcePath("scenes/constant-debug.json"), dir_ / "scenes" / "locked" / "c.json");
        fs::permissions(dir_ / "scenes" / "locked", fs::perms::none);
    }
    void TearDown() override {
        fs::permissions(dir_ / "scenes" / "locked", fs::perms::owner_all);
        CliTest::TearDown();
    }

    // Runs hexray without root's power to read any directory.
    RunResult hexrayUnprivileged(const std::string& arguments) const {
        return hexray(arguments, ::geteuid() == 0 ? "setpriv --bounding-set=-dac_override,-dac_read_search" : "");
    }
};

TEST_F(SceneDirectoryTest, RenderReportsADirectoryItCannotReadAsAFailedSceneAndRendersTheRest) {
    const RunResult run = hexrayUnprivileged("render scenes --backend cpu" + std::string(kSize));
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find("scenes/locked: cannot read the directory: Permission denied"), std::string::npos)
        << run.err;
    EXPECT_NE(run.out.find("rendered 2 of 3 scenes; failed: scenes/locked"), std::string::npos) << run.out;
    EXPECT_EQ(createdFiles(), std::vector<std::string>({"B.png", "a.png", "scenes"}));
}

TEST_F(SceneDirectoryTest, CompareReportsADirectoryItCannotReadAsAFailedRow) {
    const RunResult run = hexrayUnprivileged("compare scenes" + std::string(kSize));
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find("scenes/locked: cannot read the directory: Permission denied"), std::string::npos)
        << run.err;
    for (const char* row : {"| a ", "| B ", "| locked "}) {
        EXPECT_NE(run.out.find(row), std::string::npos) << row << "\n" << run.out;
    }
    EXPECT_NE(run.out.find("FAIL"), std::string::npos) << run.out;
}

TEST_F(CliTest, WithoutAUsableGpuEveryScenesFallsBackToTheCpuAfterOneNote) {
    const RunResult run = hexray("render " + scene("lecture-demo.json") + " " + scene("constant-debug.json") + kSize,
                                 "HEXRAY_INJECT_VULKAN_FAULT=no-compute-queue");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::string note = "rendering on the CPU reference instead";
    ASSERT_NE(run.err.find(note), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find(note, run.err.find(note) + 1), std::string::npos) << "one note:\n" << run.err;
    EXPECT_NE(run.out.find("wrote lecture-demo.png (40x30) — cpu reference"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("wrote constant-debug.png (40x30) — cpu reference"), std::string::npos) << run.out;
}

TEST_F(CliTest, WithBackendGpuAndNoUsableGpuEverySceneFailsWithTheVulkanExitCode) {
    const RunResult run =
        hexray("render " + scene("lecture-demo.json") + " " + scene("constant-debug.json") + " --backend gpu" + kSize,
               "HEXRAY_INJECT_VULKAN_FAULT=no-compute-queue");
    EXPECT_EQ(run.exitCode, 3) << run.err;
    EXPECT_NE(run.out.find("rendered 0 of 2 scenes"), std::string::npos) << run.out;
    EXPECT_EQ(createdFiles(), std::vector<std::string>{});
}

}  // namespace
}  // namespace hexray
