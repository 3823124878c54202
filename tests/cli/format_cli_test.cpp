// Output formats chosen by the output's extension: 8-bit PNG, linear float OpenEXR (the values
// before encoding), PNG on standard output for "-", and an error naming the supported ones. A
// name's extension holds wherever it leads: to standard output, a pipe or a FIFO.

#include <sys/stat.h>

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/cli_fixture.h"
#include "image/exr_io.h"
#include "image/image_io.h"

namespace hexray {
namespace {

using test::CliTest;
using test::RunResult;
namespace fs = std::filesystem;

// A constant shader's colour is the pixel's linear colour exactly, above 1 included: what an
// OpenEXR output must keep and a PNG must clamp.
constexpr const char* kBrightScene = R"({
  "image": {"width": 16, "height": 12},
  "camera": {"position": [0, 0, -10]},
  "background": [0.25, 0.5, 0.75],
  "shaders": {"bright": {"type": "constant", "color": [2, 0.5, 0.125]}},
  "nodes": [{"geometry": {"type": "sphere", "center": [0, 0, 0], "radius": 2}, "shader": "bright"}]
})";

TEST_F(CliTest, AnExrOutputHoldsTheLinearColourBeforeEncodingOnBothBackends) {
    writeScene("bright.json", kBrightScene);
    for (const std::string backend : {"gpu", "cpu"}) {
        const RunResult run = hexray("render bright.json --backend " + backend + " -o " + backend + ".exr");
        ASSERT_EQ(run.exitCode, 0) << run.err;
        const ExrImage image = readExr(dir_ / (backend + ".exr"));
        ASSERT_EQ(image.width, 16u);
        ASSERT_EQ(image.height, 12u);
        const auto at = [&](const char* channel, int x, int y) { return image.channels.at(channel)[y * 16 + x]; };
        EXPECT_EQ(at("R", 8, 6), 2.0f) << backend;  // the sphere, unclamped
        EXPECT_EQ(at("G", 8, 6), 0.5f) << backend;
        EXPECT_EQ(at("B", 8, 6), 0.125f) << backend;
        EXPECT_EQ(at("R", 0, 0), 0.25f) << backend;  // the background
        EXPECT_EQ(at("B", 0, 0), 0.75f) << backend;
    }
    ASSERT_EQ(hexray("render bright.json -o bright.png").exitCode, 0);
    const Rgb8Image png = readPng(dir_ / "bright.png");
    EXPECT_EQ(png.bytes[3 * (6 * 16 + 8)], 255);  // clamped, then sRGB-encoded
}

TEST_F(CliTest, AnUnknownExtensionIsAnErrorNamingTheSupportedOnesAndWritesNothing) {
    for (const char* output : {"x.jpg", "x.tiff", "noextension"}) {
        const RunResult run = hexray("render " + scene("lecture-demo.json") + " -o " + output);
        EXPECT_EQ(run.exitCode, 2) << output;
        EXPECT_NE(run.err.find(std::string("-o ") + output +
                               ": unknown image format (supported: .png (8-bit), .exr (linear float RGB), or - (PNG "
                               "on standard output))"),
                  std::string::npos)
            << run.err;
    }
    EXPECT_EQ(createdFiles(), std::vector<std::string>{});
}

TEST_F(CliTest, ExtensionsAreReadInAnyCaseAndMinusIsAPngOnStandardOutput) {
    ASSERT_EQ(hexray("render " + scene("lecture-demo.json") + " --width 20 --height 10 -o X.PNG").exitCode, 0);
    EXPECT_EQ(readPng(dir_ / "X.PNG").width, 20u);
    ASSERT_EQ(hexray("render " + scene("lecture-demo.json") + " --width 20 --height 10 -o Y.Exr").exitCode, 0);
    EXPECT_EQ(readExr(dir_ / "Y.Exr").width, 20u);
    const RunResult run =
        shell("\"$HEXRAY\" render " + scene("lecture-demo.json") + " --width 20 --height 10 -o - > piped.png");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(readPng(dir_ / "piped.png").height, 10u);
}

// Whether `path` holds the OpenEXR image `expected` does, value for value.
void expectSameExr(const fs::path& path, const fs::path& expected) {
    const ExrImage image = readExr(path);
    const ExrImage reference = readExr(expected);
    EXPECT_EQ(image.width, reference.width) << path;
    EXPECT_EQ(image.height, reference.height) << path;
    EXPECT_EQ(image.channels, reference.channels) << path;
}

TEST_F(CliTest, AnExrNameThatIsStandardOutputGetsOpenExrThroughAFileAPipeOrAFifo) {
    writeScene("bright.json", kBrightScene);
    ASSERT_EQ(hexray("render bright.json -o reference.exr").exitCode, 0);
    // The file standard output is redirected to.
    RunResult run = shell("\"$HEXRAY\" render bright.json -o same.exr > same.exr");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.err.find("wrote same.exr (16x12)"), std::string::npos) << run.err;
    expectSameExr(dir_ / "same.exr", dir_ / "reference.exr");
    // A link to standard output that is a pipe: nothing to seek back in.
    fs::create_symlink("/proc/self/fd/1", dir_ / "link.exr");
    run = shell("(\"$HEXRAY\" render bright.json -o link.exr; echo $? > code.txt) | cat > piped.exr");
    EXPECT_EQ(test::readFile(dir_ / "code.txt"), "0\n") << run.err;
    expectSameExr(dir_ / "piped.exr", dir_ / "reference.exr");
    // A FIFO.
    ASSERT_EQ(::mkfifo((dir_ / "fifo.exr").c_str(), 0644), 0);
    run = shell(
        "timeout 60 cat fifo.exr > from-fifo.exr & \"$HEXRAY\" render bright.json -o fifo.exr; code=$?; wait; "
        "exit $code");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    expectSameExr(dir_ / "from-fifo.exr", dir_ / "reference.exr");
    EXPECT_TRUE(fs::is_fifo(fs::symlink_status(dir_ / "fifo.exr")));
    // merge alike.
    for (const char* strip : {"0", "1"}) {
        ASSERT_EQ(hexray(std::string("render bright.json --strip ") + strip + "/2 -o piece" + strip + ".exr").exitCode,
                  0);
    }
    run = shell("\"$HEXRAY\" merge merged.exr piece0.exr piece1.exr > merged.exr");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    expectSameExr(dir_ / "merged.exr", dir_ / "reference.exr");
}

}  // namespace
}  // namespace hexray
