// OpenEXR AOV files: written through tinyexr, atomically, and read back exactly.

#include <cmath>
#include <filesystem>
#include <limits>

#include <gtest/gtest.h>

#include "image/aov.h"
#include "image/exr_io.h"
#include "image/image_io.h"
#include "support/temporary_directory_test.h"

namespace hexray {
namespace {

namespace fs = std::filesystem;

using ExrTest = test::TemporaryDirectoryTest;

TEST_F(ExrTest, ChannelsRoundTripExactlyIncludingInfinity) {
    const float inf = std::numeric_limits<float>::infinity();
    writeExr(dir_ / "a.exr", 3, 2, {{"Y", {1.5f, -1.0f, inf, 0.0f, 1e-30f, 3.25e7f}}, {"B", {0, 1, 2, 3, 4, 5}}});
    const ExrImage image = readExr(dir_ / "a.exr");
    EXPECT_EQ(image.width, 3u);
    EXPECT_EQ(image.height, 2u);
    ASSERT_EQ(image.channels.size(), 2u);
    EXPECT_EQ(image.channels.at("Y"), (std::vector<float>{1.5f, -1.0f, inf, 0.0f, 1e-30f, 3.25e7f}));
    EXPECT_EQ(image.channels.at("B"), (std::vector<float>{0, 1, 2, 3, 4, 5}));
    // Nothing but the file itself is left behind (no temporary).
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

TEST_F(ExrTest, UnwritablePathThrowsAndLeavesNothing) {
    EXPECT_THROW(writeExr(dir_ / "missing" / "a.exr", 1, 1, {{"Y", {1.0f}}}), ImageIoError);
    EXPECT_TRUE(fs::is_empty(dir_));  // no directory made, no temporary file left
}

TEST_F(ExrTest, AovSetWritesEveryFileWithItsDocumentedValues) {
    const float inf = std::numeric_limits<float>::infinity();
    AovSet aovs{2, 1, {inf, 7.5f}, {glm::vec3(0), glm::vec3(0, 1, 0)},
                {PixelClass{}, PixelClass{3, PixelClass::litBit(1)}}, 2};
    const std::vector<float> margins = {inf, 1e-7f};
    aovs.margins = &margins;
    aovs.ambiguityMargin = 1.0 / 131072.0;
    const auto files = writeAovs(dir_ / "aov", aovs);
    EXPECT_EQ(files.size(), 12u);  // depth, normal, object-id, light-0, light-1, margin: EXR + PNG each
    EXPECT_EQ(readExr(dir_ / "aov" / "depth.exr").channels.at("Y"), (std::vector<float>{inf, 7.5f}));
    EXPECT_EQ(readExr(dir_ / "aov" / "object-id.exr").channels.at("Y"), (std::vector<float>{-1.0f, 3.0f}));
    EXPECT_EQ(readExr(dir_ / "aov" / "normal.exr").channels.at("G"), (std::vector<float>{0.0f, 1.0f}));
    EXPECT_EQ(readExr(dir_ / "aov" / "light-0.exr").channels.at("Y"), (std::vector<float>{0.0f, 0.0f}));
    EXPECT_EQ(readExr(dir_ / "aov" / "light-1.exr").channels.at("Y"), (std::vector<float>{0.0f, 1.0f}));
    EXPECT_EQ(readExr(dir_ / "aov" / "margin.exr").channels.at("Y"), margins);
    const Rgb8Image marginPreview = readPng(dir_ / "aov" / "margin.png");
    EXPECT_EQ(std::vector<std::uint8_t>(marginPreview.bytes.begin() + 3, marginPreview.bytes.end()),
              (std::vector<std::uint8_t>{255, 0, 0}));  // ambiguous: red
}

}  // namespace
}  // namespace hexray
