// `render --json` and `pixel --json` through the real executable: the documents validate against
// docs/schemas/hexray-results.schema.json, their values are the run's, a failed run still writes
// its document, and the document's path is checked like every other output's.

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

namespace fs = std::filesystem;
using nlohmann::json;

// Without a Vulkan driver: --backend auto renders on the CPU reference.
constexpr const char* kNoDriver = "VK_ICD_FILENAMES=/nonexistent/icd.json VK_DRIVER_FILES=/nonexistent/icd.json";

// The lecture demo at 64x48: its floor, lit, at (32, 40).
constexpr const char* kSmall = " --width 64 --height 48";
constexpr std::uint32_t kFloorX = 32;
constexpr std::uint32_t kFloorY = 40;

class JsonCliTest : public test::CliTest {
protected:
    std::string demoScene() const { return shippedScene("lecture-demo.json"); }

    // A shipped scene's path, quoted for the shell (built by appending: GCC 12 warns, wrongly, about
    // the fixture's "'" + path + "'" when it is inlined here).
    static std::string shippedScene(const std::string& name) {
        std::string quoted(1, '\'');
        quoted.append(test::sourcePath("scenes/" + name).string()).push_back('\'');
        return quoted;
    }

    json readJson(const std::string& name) const { return json::parse(test::readFile(dir_ / name)); }

    // A document that came on standard output, kept as a file for the validator.
    json keep(const std::string& text, const std::string& name) const {
        std::ofstream(dir_ / name) << text;
        return json::parse(text);
    }

    void expectValid(const std::string& name) const {
        const test::RunResult valid = validateJson(name);
        EXPECT_EQ(valid.exitCode, 0) << valid.out << valid.err;
        EXPECT_EQ(valid.out, "");
    }

    // The 8-bit colour of pixel (x, y) of a PNG in the test's directory.
    json pngPixel(const std::string& name, std::uint32_t x, std::uint32_t y) const {
        const Rgb8Image image = readPng(dir_ / name);
        const std::size_t at = 3 * (std::size_t(y) * image.width + x);
        return json::array({image.bytes.at(at), image.bytes.at(at + 1), image.bytes.at(at + 2)});
    }
};

TEST_F(JsonCliTest, RenderOnTheCpuRecordsTheSceneAndValidates) {
    const test::RunResult run =
        hexray("render " + demoScene() + kSmall + " --spp 2 --backend cpu -o out.png --json out.json");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    expectValid("out.json");
    const json document = readJson("out.json");
    EXPECT_EQ(document["schema"], "hexray-render/1");
    EXPECT_EQ(document["exit"]["code"], run.exitCode);
    EXPECT_EQ(document["exit"]["name"], "success");
    EXPECT_EQ(document["requested"]["backend"], "cpu");
    EXPECT_TRUE(document["device"].is_null());  // Vulkan was never started
    EXPECT_TRUE(document["timings_ms"]["startup"].is_null());
    EXPECT_EQ(document["scenes_rendered"], 1);
    EXPECT_EQ(document["scenes_failed"], 0);
    ASSERT_EQ(document["scenes"].size(), 1u);
    const json& scene = document["scenes"][0];
    EXPECT_EQ(scene["output"], "out.png");
    EXPECT_EQ(scene["width"], 64);
    EXPECT_EQ(scene["height"], 48);
    EXPECT_EQ(scene["spp"], 2);
    EXPECT_EQ(scene["backend"], "cpu");
    EXPECT_TRUE(scene["precision"].is_null());
    EXPECT_TRUE(scene["kernel"].is_null());
    EXPECT_GE(scene["cpu_threads"].get<int>(), 1);
    EXPECT_TRUE(scene["fallback_reason"].is_null());
    EXPECT_TRUE(scene["timings_ms"]["render"].is_number());
    EXPECT_TRUE(scene["timings_ms"]["upload"].is_null());
    EXPECT_EQ(readPng(dir_ / "out.png").width, 64u);
}

TEST_F(JsonCliTest, RenderOnTheGpuToStandardOutputIsOnlyTheDocument) {
    const test::RunResult run = hexray("render " + demoScene() + kSmall + " --precision f64 -o gpu.png --json -");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("wrote gpu.png"), std::string::npos) << run.err;  // the report, on stderr
    const json document = keep(run.out, "doc.json");
    expectValid("doc.json");
    EXPECT_EQ(document["exit"]["code"], 0);
    EXPECT_FALSE(document["device"].is_null());
    EXPECT_TRUE(document["timings_ms"]["startup"].is_number());
    const json& scene = document["scenes"].at(0);
    EXPECT_EQ(scene["backend"], "gpu");
    EXPECT_EQ(scene["precision"], "f64");
    EXPECT_EQ(scene["width"], 64);
    EXPECT_EQ(scene["spp"], 1);
    ASSERT_TRUE(scene["kernel"].is_object());
    EXPECT_TRUE(scene["kernel"]["kind"] == "generated" || scene["kernel"]["kind"] == "data-driven");
    EXPECT_TRUE(scene["timings_ms"]["plan"].is_number());
    EXPECT_TRUE(scene["timings_ms"]["render"].is_number());
    EXPECT_TRUE(scene["timings_ms"]["write"].is_number());
    EXPECT_TRUE(scene["cpu_threads"].is_null());
}

TEST_F(JsonCliTest, RenderWithoutADriverRecordsTheFallbackToTheCpu) {
    const test::RunResult run = hexray("render " + demoScene() + kSmall + " -o out.png --json out.json", kNoDriver);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    expectValid("out.json");
    const json document = readJson("out.json");
    EXPECT_EQ(document["requested"]["backend"], "auto");
    EXPECT_TRUE(document["device"].is_null());
    const json& scene = document["scenes"].at(0);
    EXPECT_EQ(scene["backend"], "cpu");
    ASSERT_TRUE(scene["fallback_reason"].is_string());
    EXPECT_NE(run.err.find(scene["fallback_reason"].get<std::string>()), std::string::npos) << run.err;
}

TEST_F(JsonCliTest, RenderOfABadSceneInABatchStillWritesTheDocument) {
    fs::create_directory(dir_ / "scenes");
    fs::copy_file(test::sourcePath("scenes/lecture-demo.json"), dir_ / "scenes/good.json");
    writeScene("scenes/bad.json", "{\"image\": ");
    fs::create_directory(dir_ / "images");
    const test::RunResult run =
        hexray("render scenes" + std::string(kSmall) + " --backend cpu -o images --json out.json");
    ASSERT_EQ(run.exitCode, 2) << run.err;
    expectValid("out.json");
    const json document = readJson("out.json");
    EXPECT_EQ(document["exit"]["code"], run.exitCode);
    EXPECT_EQ(document["exit"]["name"], "bad_input");
    EXPECT_EQ(document["scenes_rendered"], 1);
    EXPECT_EQ(document["scenes_failed"], 1);
    ASSERT_EQ(document["scenes"].size(), 2u);
    const json& bad = document["scenes"][0];
    EXPECT_EQ(bad["scene"], "scenes/bad.json");
    EXPECT_EQ(bad["exit"]["name"], "bad_input");
    ASSERT_EQ(bad["exit"]["messages"].size(), 1u);
    EXPECT_NE(bad["exit"]["messages"][0].get<std::string>().find("bad.json"), std::string::npos);
    EXPECT_TRUE(bad["width"].is_null());
    EXPECT_TRUE(bad["backend"].is_null());
    const json& good = document["scenes"][1];
    EXPECT_EQ(good["exit"]["name"], "success");
    EXPECT_EQ(good["width"], 64);
    EXPECT_TRUE(fs::exists(dir_ / "images/good.png"));
}

TEST_F(JsonCliTest, PixelOnTheCpuHasTheColourOfTheRenderedPng) {
    ASSERT_EQ(hexray("render " + demoScene() + kSmall + " --backend cpu -o cpu.png").exitCode, 0);
    const std::string where = " " + std::to_string(kFloorX) + " " + std::to_string(kFloorY);
    const test::RunResult run = hexray("pixel " + demoScene() + where + kSmall + " --backend cpu --json px.json");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("cpu (reference)"), std::string::npos);  // the table, as without --json
    expectValid("px.json");
    const json document = readJson("px.json");
    EXPECT_EQ(document["exit"]["code"], 0);
    EXPECT_EQ(document["x"], kFloorX);
    EXPECT_EQ(document["y"], kFloorY);
    EXPECT_EQ(document["width"], 64);
    EXPECT_TRUE(document["gpu"].is_null());
    EXPECT_TRUE(document["comparison"].is_null());
    const json& trace = document["cpu"]["trace"];
    EXPECT_EQ(trace["hit"]["node"], 0);
    EXPECT_EQ(trace["hit"]["geometry"], "plane");
    EXPECT_EQ(trace["lights"].at(0)["status"], "lit");
    EXPECT_EQ(trace["pixel_8bit"], pngPixel("cpu.png", kFloorX, kFloorY));
}

TEST_F(JsonCliTest, PixelOnBothBackendsToStandardOutputAgreesWithTheGpuRender) {
    ASSERT_EQ(hexray("render " + demoScene() + kSmall + " --precision f64 -o gpu.png").exitCode, 0);
    const std::string where = " " + std::to_string(kFloorX) + " " + std::to_string(kFloorY);
    const test::RunResult run = hexray("pixel " + demoScene() + where + kSmall + " --precision f64 --json -");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("gpu and cpu agree"), std::string::npos) << run.err;  // the table, on stderr
    const json document = keep(run.out, "px.json");
    expectValid("px.json");
    EXPECT_EQ(document["gpu"]["precision"], "f64");
    EXPECT_FALSE(document["device"].is_null());
    EXPECT_TRUE(document["timings_ms"]["startup"].is_number());
    EXPECT_EQ(document["comparison"]["agree"], true);
    EXPECT_TRUE(document["comparison"]["differing_rows"].empty());
    EXPECT_EQ(document["gpu"]["trace"]["hit"]["node"], document["cpu"]["trace"]["hit"]["node"]);
    EXPECT_EQ(document["gpu"]["trace"]["pixel_8bit"], pngPixel("gpu.png", kFloorX, kFloorY));
}

// f32-naive loses the checker cell ten million units out: the rows the table marks, by name.
TEST_F(JsonCliTest, PixelWhereTheBackendsDisagreeNamesTheDifferingRows) {
    const test::RunResult run = hexray("pixel " + shippedScene("hard/checker-far-1e7.json") + " 6 0" + kSmall +
                                       " --precision f32-naive --json -");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("DIFFERENCE"), std::string::npos) << run.err;
    const json document = keep(run.out, "px.json");
    expectValid("px.json");
    const json& comparison = document["comparison"];
    EXPECT_EQ(comparison["agree"], false);
    EXPECT_EQ(comparison["class_differs"], true);
    const auto& rows = comparison["differing_rows"];
    EXPECT_NE(std::find(rows.begin(), rows.end(), "albedo"), rows.end()) << rows;
    EXPECT_NE(std::find(rows.begin(), rows.end(), "light 0 cos theta"), rows.end()) << rows;
    EXPECT_NE(document["gpu"]["trace"]["hit"]["checker"]["odd"], document["cpu"]["trace"]["hit"]["checker"]["odd"]);
    EXPECT_NE(document["gpu"]["trace"]["pixel_8bit"], document["cpu"]["trace"]["pixel_8bit"]);
}

TEST_F(JsonCliTest, PixelOutsideTheImageStillWritesTheDocument) {
    const test::RunResult run = hexray("pixel " + demoScene() + " 64 3" + kSmall + " --json px.json");
    ASSERT_EQ(run.exitCode, 2) << run.err;
    expectValid("px.json");
    const json document = readJson("px.json");
    EXPECT_EQ(document["exit"]["code"], run.exitCode);
    EXPECT_EQ(document["exit"]["name"], "bad_input");
    ASSERT_EQ(document["exit"]["messages"].size(), 1u);
    EXPECT_NE(document["exit"]["messages"][0].get<std::string>().find("X = 64 is outside the image"),
              std::string::npos);
    EXPECT_EQ(document["width"], 64);
    EXPECT_TRUE(document["gpu"].is_null());
    EXPECT_TRUE(document["cpu"].is_null());
}

TEST_F(JsonCliTest, JsonRefusesToReplaceTheSceneDirectlyOrThroughASymlink) {
    fs::copy_file(test::sourcePath("scenes/lecture-demo.json"), dir_ / "scene.json");
    fs::create_symlink("scene.json", dir_ / "link.json");
    const std::string original = test::readFile(dir_ / "scene.json");
    for (const std::string command : {"render scene.json --backend cpu -o out.png", "pixel scene.json 1 1"}) {
        for (const std::string target : {"scene.json", "link.json"}) {
            const test::RunResult run = hexray(command + kSmall + " --json " + target);
            EXPECT_EQ(run.exitCode, 2) << command << " --json " << target;
            EXPECT_NE(run.err.find("--json " + target + ": the same file as the scene scene.json"), std::string::npos)
                << run.err;
            EXPECT_EQ(test::readFile(dir_ / "scene.json"), original);
            EXPECT_TRUE(fs::is_symlink(dir_ / "link.json"));
        }
    }
    EXPECT_FALSE(fs::exists(dir_ / "out.png"));
}

TEST_F(JsonCliTest, ADocumentPathInAMissingDirectoryIsReportedOnceAndNothingIsWritten) {
    ASSERT_EQ(hexray("render " + demoScene() + kSmall + " --backend cpu -o image.png").exitCode, 0);
    const std::vector<std::string> commands = {"render " + demoScene() + kSmall + " --backend cpu -o out.png",
                                               "compare " + demoScene() + kSmall, "diff image.png image.png",
                                               "pixel " + demoScene() + " 1 1 --backend cpu"};
    for (const std::string& command : commands) {
        const test::RunResult run = hexray(command + " --json missing/doc.json");
        EXPECT_EQ(run.exitCode, 5) << command << "\n" << run.err;
        const std::string message = "missing/doc.json: cannot create output file";
        const std::size_t first = run.err.find(message);
        EXPECT_NE(first, std::string::npos) << command << "\n" << run.err;
        EXPECT_EQ(run.err.find(message, first + 1), std::string::npos) << command << " says it twice:\n" << run.err;
    }
    EXPECT_FALSE(fs::exists(dir_ / "out.png"));
    EXPECT_FALSE(fs::exists(dir_ / "missing"));
}

TEST_F(JsonCliTest, ImageAndDocumentCannotBothGoToStandardOutput) {
    const test::RunResult run = hexray("render " + demoScene() + kSmall + " --backend cpu -o - --json -");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_EQ(run.out, "");
    EXPECT_NE(run.err.find("--json: standard output carries the image (-o -): write the document to a file"),
              std::string::npos)
        << run.err;
    EXPECT_TRUE(createdFiles().empty());
}

}  // namespace
}  // namespace hexray
