// `hexray compare --report DIR`, checked in a real browser: headless chromium loads the page from
// file://, its script counts the images that loaded, and tests/cli/check_report.py compares the
// summary table with the --json document of the same run.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/cli_fixture.h"
#include "image/image_io.h"

namespace hexray {
namespace {

using test::CliTest;
using test::RunResult;
namespace fs = std::filesystem;

// A name that HTML must escape, in a scene beside the test's others.
constexpr const char* kTrickyName = "a<b>&\"q'";

class ReportTest : public CliTest {
protected:
    // Two scenes (one named kTrickyName), small, with a report and the JSON.
    RunResult compareWithReport(const std::string& more = "") const {
        fs::copy_file(test::sourcePath("scenes/constant-debug.json"), dir_ / (std::string(kTrickyName) + ".json"));
        return hexray("compare 'a<b>&\"q'\\''.json' " + scene("spheres-and-lights.json") +
                      " --width 64 --height 48 --report out --json out.json " + more);
    }

    RunResult checkInBrowser() const {
        return shell("/usr/bin/python3 '" + test::sourcePath("tests/cli/check_report.py").string() + "' out out.json");
    }

    std::vector<std::string> images() const {
        std::vector<std::string> names = entriesStartingWith(dir_ / "out" / "images", "");
        std::sort(names.begin(), names.end());
        return names;
    }
};

TEST_F(ReportTest, EveryImageLoadsAndTheSummaryEqualsTheJson) {
    const RunResult run = compareWithReport();
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    EXPECT_NE(run.out.find("wrote report out/index.html"), std::string::npos) << run.out;
    const std::vector<std::string> expected = {
        "001-a_b___q_-f32-cpu.png",           "001-a_b___q_-f32-diff.png",
        "001-a_b___q_-f32-gpu.png",           "001-a_b___q_-f32-mask.png",
        "002-spheres-and-lights-f32-cpu.png", "002-spheres-and-lights-f32-diff.png",
        "002-spheres-and-lights-f32-gpu.png", "002-spheres-and-lights-f32-mask.png"};
    EXPECT_EQ(images(), expected);
    const Rgb8Image gpu = readPng(dir_ / "out" / "images" / "002-spheres-and-lights-f32-gpu.png");
    EXPECT_EQ(gpu.width, 64u);
    EXPECT_EQ(gpu.height, 48u);
    // The --json document, written a moment earlier: only the wall time differs.
    nlohmann::json results = nlohmann::json::parse(test::readFile(dir_ / "out" / "results.json"));
    nlohmann::json document = nlohmann::json::parse(test::readFile(dir_ / "out.json"));
    EXPECT_EQ(results["report"], "out");
    results["timings_ms"].erase("wall");
    document["timings_ms"].erase("wall");
    EXPECT_EQ(results, document);
    const RunResult valid = validateJson("out/results.json");
    EXPECT_EQ(valid.exitCode, 0) << valid.out << valid.err;
    EXPECT_EQ(entriesStartingWith(dir_ / "out", ".hexray"), std::vector<std::string>{});

    const RunResult check = checkInBrowser();
    EXPECT_EQ(check.exitCode, 0) << check.out << check.err;
    EXPECT_EQ(check.out, "images loaded=8 failed=0; rows=2 agree\n") << check.err;
}

// The image check counts what is missing, so it cannot pass without looking.
TEST_F(ReportTest, AMissingImageIsCounted) {
    ASSERT_EQ(compareWithReport().exitCode, 0);
    fs::remove(dir_ / "out" / "images" / "002-spheres-and-lights-f32-mask.png");
    const RunResult check = checkInBrowser();
    EXPECT_EQ(check.exitCode, 0) << check.out << check.err;
    EXPECT_EQ(check.out, "images loaded=7 failed=1; rows=2 agree\n") << check.err;
}

// Hovering over the GPU render shows the reference in its place; a click keeps it there.
TEST_F(ReportTest, TheGpuRenderFlipsToTheReference) {
    ASSERT_EQ(compareWithReport().exitCode, 0);
    const RunResult check =
        shell("/usr/bin/python3 '" + test::sourcePath("tests/cli/check_report.py").string() + "' --flip out");
    EXPECT_EQ(check.exitCode, 0) << check.out << check.err;
    EXPECT_EQ(check.out, "flip gpu cpu gpu cpu\n") << check.err;
}

// A scene that cannot be loaded is a row too (without images), and the report is still written.
TEST_F(ReportTest, AFailedSceneIsReported) {
    writeScene("broken.json", "{\"image\" 8}");
    const RunResult run = compareWithReport("broken.json");
    EXPECT_EQ(run.exitCode, 2) << run.out << run.err;
    const std::string page = test::readFile(dir_ / "out" / "index.html");
    EXPECT_NE(page.find("data-scene=\"broken\""), std::string::npos) << page;
    const RunResult check = checkInBrowser();
    EXPECT_EQ(check.exitCode, 0) << check.out << check.err;
    EXPECT_EQ(check.out, "images loaded=8 failed=0; rows=3 agree\n") << check.err;
}

// Without a browser the check fails, saying why: CI installs chromium, so the test never skips.
TEST_F(ReportTest, AMissingBrowserFailsTheCheck) {
    ASSERT_EQ(compareWithReport().exitCode, 0);
    const RunResult check = shell("PATH=/nonexistent /usr/bin/python3 '" +
                                  test::sourcePath("tests/cli/check_report.py").string() + "' out out.json");
    EXPECT_EQ(check.exitCode, 2);
    EXPECT_NE(check.out.find("chromium not found"), std::string::npos) << check.out << check.err;
}

// Control characters in a scene's name reach neither the page nor a file name.
TEST_F(ReportTest, ControlCharactersInANameAreEscaped) {
    const std::string raw = "x\x1b]0;owned\x07";
    fs::copy_file(test::sourcePath("scenes/constant-debug.json"), dir_ / (raw + ".json"));
    const RunResult run = hexray("compare '" + raw + ".json' --width 64 --height 48 --report out");
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    const std::string page = test::readFile(dir_ / "out" / "index.html");
    EXPECT_EQ(page.find_first_of("\x1b\x07"), std::string::npos);
    EXPECT_NE(page.find("data-scene=\"x\\x1b]0;owned\\x07\""), std::string::npos) << page;
    EXPECT_TRUE(fs::exists(dir_ / "out" / "images" / "001-x__0_owned_-f32-gpu.png"));
}

// A second report replaces the first's files and removes its images that it does not have.
TEST_F(ReportTest, ALaterReportReplacesAnEarlierOne) {
    ASSERT_EQ(compareWithReport().exitCode, 0);
    std::ofstream(dir_ / "out" / "images" / "mine.png") << "not hexray's";
    const RunResult run = hexray("compare " + scene("constant-debug.json") + " --width 64 --height 48 --report out");
    ASSERT_EQ(run.exitCode, 0) << run.out << run.err;
    const std::vector<std::string> expected = {"001-constant-debug-f32-cpu.png", "001-constant-debug-f32-diff.png",
                                               "001-constant-debug-f32-gpu.png", "001-constant-debug-f32-mask.png",
                                               "mine.png"};
    EXPECT_EQ(images(), expected);
}

// The images go into DIR/images itself: a symlink there is refused, and what it names is untouched.
TEST_F(ReportTest, ASymlinkedImageDirectoryIsRefused) {
    fs::create_directories(dir_ / "out");
    fs::create_directories(dir_ / "elsewhere");
    fs::create_directory_symlink(dir_ / "elsewhere", dir_ / "out" / "images");
    const RunResult run = hexray("compare " + scene("constant-debug.json") + " --width 64 --height 48 --report out");
    EXPECT_EQ(run.exitCode, 5) << run.out << run.err;
    EXPECT_NE(run.err.find("out/images: cannot hold the report's images"), std::string::npos) << run.err;
    EXPECT_TRUE(fs::is_empty(dir_ / "elsewhere"));
    EXPECT_FALSE(fs::exists(dir_ / "out" / "index.html"));
    EXPECT_EQ(entriesStartingWith(dir_ / "out", ".hexray"), std::vector<std::string>{});
}

// The report directory is an output: one that holds an input is refused before any work.
TEST_F(ReportTest, AReportOverAnInputIsRefused) {
    fs::create_directories(dir_ / "out");
    fs::copy_file(test::sourcePath("scenes/constant-debug.json"), dir_ / "out" / "index.html");
    const RunResult run = hexray("compare out/index.html --width 64 --height 48 --report out");
    EXPECT_EQ(run.exitCode, 2) << run.out << run.err;
    EXPECT_NE(run.err.find("--report out: would write over the scene out/index.html"), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(dir_ / "out" / "images"));
}

}  // namespace
}  // namespace hexray
