#include <cmath>
#include <filesystem>
#include <fstream>
#include <span>
#include <sstream>

#include <gtest/gtest.h>

#include "image/image_io.h"
#include "io/output_error.h"
#include "support/temporary_directory_test.h"

namespace hexray {
namespace {

namespace fs = std::filesystem;

TEST(EncodeChannel, LinearIsClampScaleRound) {
    EXPECT_EQ(encodeChannel(0.0f, Encoding::Linear), 0);
    EXPECT_EQ(encodeChannel(0.5f, Encoding::Linear), 128);  // 127.5 rounds up
    EXPECT_EQ(encodeChannel(1.0f, Encoding::Linear), 255);
    EXPECT_EQ(encodeChannel(-0.3f, Encoding::Linear), 0);
    EXPECT_EQ(encodeChannel(7.0f, Encoding::Linear), 255);
    EXPECT_EQ(encodeChannel(std::nanf(""), Encoding::Linear), 0);
}

TEST(EncodeChannel, SrgbBrightensMidTones) {
    // sRGB(0.5) = 1.055 * 0.5^(1/2.4) - 0.055 = 0.73536 -> 187.5 -> 188
    EXPECT_EQ(encodeChannel(0.5f, Encoding::Srgb), 188);
    // The linear segment: 12.92 * 0.001 = 0.01292 -> 3.29 -> 3
    EXPECT_EQ(encodeChannel(0.001f, Encoding::Srgb), 3);
    EXPECT_EQ(encodeChannel(0.0f, Encoding::Srgb), 0);
    EXPECT_EQ(encodeChannel(1.0f, Encoding::Srgb), 255);
}

using PngFileTest = test::TemporaryDirectoryTest;

Rgb8Image gradient(std::uint32_t width, std::uint32_t height) {
    Rgb8Image image{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 3)};
    for (std::size_t i = 0; i < image.bytes.size(); ++i) {
        image.bytes[i] = std::uint8_t(i * 7);
    }
    return image;
}

TEST_F(PngFileTest, RoundTripsExactly) {
    const Rgb8Image written = gradient(13, 5);
    writePng(dir_ / "g.png", written);
    const Rgb8Image read = readPng(dir_ / "g.png");
    EXPECT_EQ(read.width, 13u);
    EXPECT_EQ(read.height, 5u);
    EXPECT_EQ(read.bytes, written.bytes);
}

TEST_F(PngFileTest, ReplacesAnExistingFileAndLeavesNoTemporary) {
    std::ofstream(dir_ / "g.png") << "old contents";
    writePng(dir_ / "g.png", gradient(4, 4));
    EXPECT_EQ(readPng(dir_ / "g.png").width, 4u);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

TEST_F(PngFileTest, MissingDirectoryIsAnErrorNamingThePath) {
    const fs::path target = dir_ / "no-such-dir" / "g.png";
    try {
        writePng(target, gradient(2, 2));
        FAIL() << "expected OutputError";
    } catch (const OutputError& error) {
        EXPECT_NE(std::string(error.what()).find(target.string()), std::string::npos) << error.what();
    }
    EXPECT_FALSE(fs::exists(target));
}

TEST_F(PngFileTest, RowsWrittenInPiecesMakeTheSameImage) {
    const Rgb8Image image = gradient(7, 9);
    PngRowWriter writer(dir_ / "rows.png", 7, 9);
    const std::span<const std::uint8_t> bytes(image.bytes);
    writer.writeRows(bytes.subspan(0, 7 * 3 * 2));  // rows 0-1
    writer.writeRows(bytes.subspan(7 * 3 * 2));     // rows 2-8
    writer.finish();
    EXPECT_EQ(readPng(dir_ / "rows.png").bytes, image.bytes);
}

TEST_F(PngFileTest, AnUnfinishedWriterLeavesNothingAndKeepsTheOldFile) {
    std::ofstream(dir_ / "g.png") << "old contents";
    {
        PngRowWriter writer(dir_ / "g.png", 4, 4);
        writer.writeRows(gradient(4, 2).bytes);  // interrupted after two of four rows
    }
    std::stringstream kept;
    kept << std::ifstream(dir_ / "g.png").rdbuf();
    EXPECT_EQ(kept.str(), "old contents");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

TEST_F(PngFileTest, FinishingBeforeEveryRowIsInIsAnError) {
    PngRowWriter writer(dir_ / "short.png", 4, 4);
    writer.writeRows(gradient(4, 3).bytes);
    EXPECT_THROW(writer.finish(), OutputError);
}

TEST_F(PngFileTest, ReadingANonPngIsAnError) {
    std::ofstream(dir_ / "x.png") << "not a png";
    EXPECT_THROW(readPng(dir_ / "x.png"), ImageIoError);
}

}  // namespace
}  // namespace hexray
