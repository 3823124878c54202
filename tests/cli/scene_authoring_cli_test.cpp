// Writing scenes by hand: hex colours as CSS means them, a scene read from standard input
// (render -), --set overrides, and "did you mean" for a misspelt key, as the executable shows them.

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cli/cli_fixture.h"
#include "image/image_io.h"

namespace hexray {
namespace {

using test::CliTest;
using test::RunResult;
namespace fs = std::filesystem;

// Nothing but the background: every pixel is its colour, sRGB-encoded.
constexpr const char* kBackgroundScene = R"({
  // a comment, as people write them
  "image": {"width": 4, "height": 3},
  "camera": {"position": [0, 0, 0]},
  "background": "#1a2433",
  "nodes": []
})";

// The bytes of the image's top-left pixel.
std::string firstPixel(const fs::path& png) {
    const Rgb8Image image = readPng(png);
    char text[16];
    std::snprintf(text, sizeof text, "%02x%02x%02x", image.bytes[0], image.bytes[1], image.bytes[2]);
    return text;
}

TEST_F(CliTest, HexColoursComeOutAsTheCssColourOnBothBackends) {
    writeScene("background.json", kBackgroundScene);
    for (const std::string backend : {"cpu", "gpu"}) {
        const RunResult run = hexray("render background.json --backend " + backend + " -o " + backend + ".png");
        ASSERT_EQ(run.exitCode, 0) << run.err;
        EXPECT_EQ(firstPixel(dir_ / (backend + ".png")), "1a2433") << backend;
    }
}

TEST_F(CliTest, RenderReadsTheSceneFromStandardInput) {
    writeScene("background.json", kBackgroundScene);
    const RunResult run = shell("\"$HEXRAY\" render - --backend cpu -o out.png < background.json");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(firstPixel(dir_ / "out.png"), "1a2433");
}

TEST_F(CliTest, RenderFromStandardInputNeedsAnOutputName) {
    writeScene("background.json", kBackgroundScene);
    const RunResult run = shell("\"$HEXRAY\" render - --backend cpu < background.json");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_EQ(run.err,
              "hexray: error: the scene comes from standard input (-), so there is no file name to name its image "
              "after: give -o (e.g. -o image.png, or -o - for PNG on standard output)\n");
    EXPECT_TRUE(createdFiles().empty());
}

TEST_F(CliTest, ErrorsInAStandardInputSceneNameStdinLineAndColumn) {
    const RunResult run = shell("printf '// comment\\n{\"image\": {,}}' | \"$HEXRAY\" render - -o out.png");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_EQ(run.err.rfind("hexray: error: <stdin>:2:12: JSON syntax error: ", 0), 0u) << run.err;
    EXPECT_FALSE(fs::exists(dir_ / "out.png"));
    const RunResult twice = shell("\"$HEXRAY\" render - - -o out.png < /dev/null");
    EXPECT_EQ(twice.exitCode, 2);
    EXPECT_EQ(twice.err, "hexray: error: standard input (-) is named more than once: it holds one scene\n");
}

TEST_F(CliTest, SetChangesTheSceneBeforeItIsRead) {
    writeScene("background.json", kBackgroundScene);
    // A string without quotes, a number, and a setting before the scene file.
    const RunResult run = hexray(
        "render --set background=#ff8000 --set image.width=2 background.json --set 'image.height=1' --backend cpu "
        "-o set.png");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Rgb8Image image = readPng(dir_ / "set.png");
    EXPECT_EQ(image.width, 2u);
    EXPECT_EQ(image.height, 1u);
    EXPECT_EQ(firstPixel(dir_ / "set.png"), "ff8000");
    // A new key is allowed where the loader allows it; JSON values go in as JSON.
    const RunResult array = hexray("render background.json --set 'ambient=[0.5, 0.5, 0.5]' --backend cpu -o a.png");
    EXPECT_EQ(array.exitCode, 0) << array.err;
}

TEST_F(CliTest, SetWithABadPathNamesTheOptionForEveryCommand) {
    writeScene("background.json", kBackgroundScene);
    for (const std::string command :
         {"render background.json -o x.png", "compare background.json", "pixel background.json 0 0"}) {
        const RunResult run = hexray(command + " --set 'nodes[2].geometry.radius=1.5'");
        EXPECT_EQ(run.exitCode, 2) << command;
        EXPECT_EQ(run.err, "hexray: error: --set nodes[2].geometry.radius=1.5: nodes has 0 elements\n") << command;
    }
    const RunResult noValue = hexray("render background.json -o x.png --set camera.fov");
    EXPECT_EQ(noValue.exitCode, 2);
    EXPECT_EQ(noValue.err, "hexray: error: --set camera.fov: expected PATH=VALUE, e.g. --set camera.fov=60\n");
    const RunResult deep = hexray("render background.json -o x.png --set camera.lens.focus=2");
    EXPECT_EQ(deep.err, "hexray: error: --set camera.lens.focus=2: camera.lens is not in the scene\n");
    const RunResult typo = hexray("render background.json -o x.png --set camera.fvo=60");
    EXPECT_EQ(typo.exitCode, 2);
    EXPECT_EQ(typo.err,
              "hexray: error: background.json: camera.fvo: unknown key (allowed: aspect, fov, lookAt, pitch, "
              "position, roll, up, yaw); did you mean \"fov\"?\n");
    EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

TEST_F(CliTest, SetWorksForCompareAndPixel) {
    writeScene("background.json", kBackgroundScene);
    const RunResult compare = hexray("compare background.json --set image.width=2");
    EXPECT_EQ(compare.exitCode, 0) << compare.err;
    const RunResult pixel = hexray("pixel background.json 0 0 --backend cpu --set background=#ff8000");
    EXPECT_EQ(pixel.exitCode, 0) << pixel.err;
    EXPECT_NE(pixel.out.find("pixel 8-bit (sRGB)     (255, 128, 0)"), std::string::npos) << pixel.out;
}

}  // namespace
}  // namespace hexray
