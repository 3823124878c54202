// `hexray diff TEST REF`: exit codes, thresholds, the heat map, standard input and --json.

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/cli_fixture.h"
#include "image/exr_io.h"
#include "image/image_io.h"

namespace hexray::test {
namespace {

constexpr std::uint32_t kWidth = 20;
constexpr std::uint32_t kHeight = 10;

Rgb8Image gradient(std::uint32_t width = kWidth, std::uint32_t height = kHeight) {
    Rgb8Image image{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 3)};
    for (std::size_t i = 0; i < image.bytes.size(); ++i) {
        image.bytes[i] = std::uint8_t((i * 7) % 200 + 20);
    }
    return image;
}

// `image` with `pixels` pixels (the first ones) made `levels` brighter in red.
Rgb8Image brighter(Rgb8Image image, std::size_t pixels, int levels) {
    for (std::size_t i = 0; i < pixels; ++i) {
        image.bytes[3 * i] = std::uint8_t(image.bytes[3 * i] + levels);
    }
    return image;
}

class DiffCliTest : public CliTest {
protected:
    void writeImage(const std::string& name, const Rgb8Image& image) const { writePng(dir_ / name, image); }
    nlohmann::json json(const std::string& name) const { return nlohmann::json::parse(readFile(dir_ / name)); }
};

TEST_F(DiffCliTest, IdenticalFilesPassWithFlipZero) {
    writeImage("a.png", gradient());
    writeImage("b.png", gradient());
    const RunResult run = hexray("diff a.png b.png --json out.json");
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("PASS\n"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("infinite (identical)"), std::string::npos) << run.out;
    const RunResult valid = validateJson("out.json");
    EXPECT_EQ(valid.exitCode, 0) << valid.out;
    EXPECT_EQ(valid.out, "");
    const nlohmann::json document = json("out.json");
    EXPECT_EQ(document["exit"]["code"], 0);
    EXPECT_EQ(document["verdict"], "pass");
    EXPECT_EQ(document["metrics"]["flip"]["mean"], 0.0);
    EXPECT_EQ(document["metrics"]["flip"]["kind"], "ldr");
    EXPECT_EQ(document["metrics"]["rmse"], 0.0);
    EXPECT_TRUE(document["metrics"]["psnr"].is_null());
    EXPECT_EQ(document["metrics"]["pixels"], kWidth * kHeight);
    EXPECT_EQ(document["test"]["width"], kWidth);
    EXPECT_EQ(document["test"]["provenance"], nlohmann::json::object());  // written without a record
}

TEST_F(DiffCliTest, OneLevelEverywhereWarnsButPasses) {
    writeImage("ref.png", gradient());
    writeImage("test.png", brighter(gradient(), kWidth * kHeight, 1));
    const RunResult run = hexray("diff test.png ref.png");
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("PASS with a warning: 100% of pixels (200)"), std::string::npos) << run.out;
    const RunResult quiet = hexray("diff test.png ref.png --warn 0.004");
    EXPECT_EQ(quiet.exitCode, 0);
    EXPECT_NE(quiet.out.find("PASS\n"), std::string::npos) << quiet.out;
}

TEST_F(DiffCliTest, FailThresholdsDecideTheExitCode) {
    writeImage("ref.png", gradient());
    writeImage("test.png", brighter(gradient(), 10, 3));  // 10 of 200 pixels (5%) 3 levels off
    const RunResult strict = hexray("diff test.png ref.png --json out.json");
    EXPECT_EQ(strict.exitCode, 1);
    EXPECT_NE(strict.out.find("\nFAIL\n"), std::string::npos) << strict.out;
    EXPECT_NE(strict.out.find("5% of pixels (10)"), std::string::npos) << strict.out;
    EXPECT_EQ(validateJson("out.json").exitCode, 0);
    const nlohmann::json document = json("out.json");
    EXPECT_EQ(document["exit"]["name"], "tolerance_exceeded");
    EXPECT_EQ(document["verdict"], "fail");
    EXPECT_EQ(document["failing"]["pixels"], 10);
    EXPECT_DOUBLE_EQ(document["failing"]["share"].get<double>(), 0.05);
    EXPECT_DOUBLE_EQ(document["metrics"]["max_abs"].get<double>(), 3.0 / 255.0);
    EXPECT_EQ(hexray("diff test.png ref.png --failpercent 5").exitCode, 0);
    EXPECT_EQ(hexray("diff test.png ref.png --failpercent 4.9").exitCode, 1);
    EXPECT_EQ(hexray("diff test.png ref.png --fail 0.012").exitCode, 0);  // 3 levels = 0.01176
    EXPECT_EQ(hexray("diff test.png ref.png --failpercent 5 --fail-flip 0").exitCode, 1);
    EXPECT_EQ(hexray("diff test.png ref.png --failpercent 5 --fail-flip 1").exitCode, 0);
}

TEST_F(DiffCliTest, DifferentSizesHaveTheirOwnExitCode) {
    writeImage("ref.png", gradient());
    writeImage("test.png", gradient(kWidth, kHeight + 1));
    const RunResult run = hexray("diff test.png ref.png --json out.json");
    EXPECT_EQ(run.exitCode, 9);
    EXPECT_NE(run.err.find("test.png is 20x11 pixels, ref.png 20x10"), std::string::npos) << run.err;
    EXPECT_EQ(validateJson("out.json").exitCode, 0);
    const nlohmann::json document = json("out.json");
    EXPECT_EQ(document["exit"]["code"], 9);
    EXPECT_EQ(document["exit"]["name"], "size_mismatch");
    EXPECT_EQ(document["test"]["height"], kHeight + 1);
    EXPECT_TRUE(document["metrics"].is_null());
}

TEST_F(DiffCliTest, UnreadableFilesAreBadInputNamed) {
    writeImage("ref.png", gradient());
    const RunResult missing = hexray("diff missing.png ref.png --json out.json");
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_NE(missing.err.find("missing.png: cannot open"), std::string::npos) << missing.err;
    EXPECT_EQ(validateJson("out.json").exitCode, 0);
    EXPECT_EQ(json("out.json")["exit"]["name"], "bad_input");
    EXPECT_TRUE(json("out.json")["test"]["format"].is_null());
    std::ofstream(dir_ / "text.png") << "not an image at all";
    const RunResult text = hexray("diff ref.png text.png");
    EXPECT_EQ(text.exitCode, 2);
    EXPECT_NE(text.err.find("text.png: neither a PNG nor an OpenEXR file"), std::string::npos) << text.err;
    writeExr(dir_ / "ref.exr", kWidth, kHeight,
             {{"R", std::vector<float>(kWidth * kHeight, 0.5f)},
              {"G", std::vector<float>(kWidth * kHeight, 0.5f)},
              {"B", std::vector<float>(kWidth * kHeight, 0.5f)}});
    const RunResult mixed = hexray("diff ref.png ref.exr");
    EXPECT_EQ(mixed.exitCode, 2);
    EXPECT_NE(mixed.err.find("two PNGs or two OpenEXR files"), std::string::npos) << mixed.err;
    EXPECT_EQ(hexray("diff - - ").exitCode, 2);
    EXPECT_EQ(hexray("diff ref.png").exitCode, 2);
}

TEST_F(DiffCliTest, StandardInputIsEitherImage) {
    writeImage("ref.png", gradient());
    writeImage("test.png", brighter(gradient(), 10, 3));
    const RunResult run = shell("\"$HEXRAY\" diff - ref.png --failpercent 5 < test.png");
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(run.out.find("standard input against ref.png"), std::string::npos) << run.out;
    const RunResult second = shell("\"$HEXRAY\" diff test.png - < ref.png");
    EXPECT_EQ(second.exitCode, 1) << second.err;
    const RunResult empty = shell("\"$HEXRAY\" diff - ref.png < /dev/null");
    EXPECT_EQ(empty.exitCode, 2);
    EXPECT_NE(empty.err.find("standard input: neither a PNG nor an OpenEXR file"), std::string::npos) << empty.err;
}

TEST_F(DiffCliTest, HeatMapIsWrittenAndNeverOverAnInput) {
    writeImage("ref.png", gradient());
    writeImage("test.png", brighter(gradient(), 10, 40));
    const RunResult run = hexray("diff test.png ref.png --failpercent 100 --heatmap heat.png");
    EXPECT_EQ(run.exitCode, 0) << run.err;
    const Rgb8Image heat = readPng(dir_ / "heat.png");
    EXPECT_EQ(heat.width, kWidth);
    EXPECT_EQ(heat.height, kHeight);
    EXPECT_GT(heat.bytes[0], 0);                           // a changed pixel is not black
    EXPECT_EQ(heat.bytes[3 * (kWidth * kHeight - 1)], 0);  // one far from any change is
    const std::string before = readFile(dir_ / "ref.png");
    const RunResult clobber = hexray("diff test.png ref.png --heatmap ref.png");
    EXPECT_EQ(clobber.exitCode, 2);
    EXPECT_EQ(readFile(dir_ / "ref.png"), before);
}

TEST_F(DiffCliTest, JsonOnStandardOutputLeavesTheReportOnStandardError) {
    writeImage("ref.png", gradient());
    writeImage("test.png", brighter(gradient(), 10, 3));
    const RunResult run = hexray("diff test.png ref.png --json -");
    EXPECT_EQ(run.exitCode, 1);
    const nlohmann::json document = nlohmann::json::parse(run.out);
    EXPECT_EQ(document["command"], "diff");
    EXPECT_EQ(document["exit"]["code"], run.exitCode);
    EXPECT_NE(run.err.find("FAIL"), std::string::npos) << run.err;
    std::ofstream(dir_ / "stdout.json") << run.out;
    const RunResult valid = validateJson("stdout.json");
    EXPECT_EQ(valid.exitCode, 0) << valid.out;
}

TEST_F(DiffCliTest, OpenExrPairsUseHdrFlip) {
    const std::size_t pixels = kWidth * kHeight;
    std::vector<float> ramp(pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
        ramp[i] = float(i) / 10.0f;  // up to 20: beyond what a PNG holds
    }
    std::vector<float> off = ramp;
    off[pixels - 1] += 1.0f;
    writeExr(dir_ / "ref.exr", kWidth, kHeight, {{"R", ramp}, {"G", ramp}, {"B", ramp}});
    writeExr(dir_ / "test.exr", kWidth, kHeight, {{"R", off}, {"G", ramp}, {"B", ramp}});
    const RunResult run = hexray("diff test.exr ref.exr --json out.json");
    EXPECT_EQ(run.exitCode, 1) << run.err;
    EXPECT_NE(run.out.find("HDR-FLIP"), std::string::npos) << run.out;
    EXPECT_EQ(validateJson("out.json").exitCode, 0);
    const nlohmann::json document = json("out.json");
    EXPECT_EQ(document["metrics"]["flip"]["kind"], "hdr");
    EXPECT_DOUBLE_EQ(document["metrics"]["max_abs"].get<double>(), 1.0);  // not clamped to [0, 1]
    EXPECT_EQ(document["metrics"]["max_at"]["x"], kWidth - 1);
    EXPECT_GT(document["metrics"]["flip"]["exposures"]["count"].get<int>(), 1);
    EXPECT_EQ(hexray("diff ref.exr ref.exr").exitCode, 0);
}

// Two renders of one scene in two precisions: the report ends with both records, and the JSON
// holds each file's.
TEST_F(DiffCliTest, DifferingRecordsOfWhatMadeTheFilesArePrinted) {
    const std::string scene = test::sourcePath("scenes/constant-debug.json").string();
    ASSERT_EQ(hexray("render '" + scene + "' --width 32 --height 24 --precision f32 -o a.png").exitCode, 0);
    ASSERT_EQ(hexray("render '" + scene + "' --width 32 --height 24 --precision f64 -o b.png").exitCode, 0);
    const RunResult same = hexray("diff a.png a.png");
    EXPECT_EQ(same.out.find("records of what made them differ"), std::string::npos) << same.out;
    const RunResult run = hexray("diff a.png b.png --json out.json");
    EXPECT_NE(run.out.find("the files' records of what made them differ:"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("hexray:precision f32"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("hexray:precision f64"), std::string::npos) << run.out;
    const nlohmann::json document = nlohmann::json::parse(readFile(dir_ / "out.json"));
    EXPECT_EQ(document["test"]["provenance"]["hexray:precision"], "f32");
    EXPECT_EQ(document["reference"]["provenance"]["hexray:precision"], "f64");
    EXPECT_EQ(document["reference"]["provenance"]["hexray:resolution"], "32x24");
    EXPECT_EQ(validateJson("out.json").exitCode, 0);
}

}  // namespace
}  // namespace hexray::test
