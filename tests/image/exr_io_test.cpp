// OpenEXR AOV files: written through tinyexr, atomically, and read back exactly.

#include <cmath>
#include <filesystem>
#include <limits>

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace hexray
