// OpenEXR AOV files: written through OpenEXR a band of rows at a time, atomically, and read back exactly.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "image/exr_io.h"
#include "image/exr_row_reader.h"
#include "image/exr_row_writer.h"
#include "image/image_io.h"
#include "io/output_error.h"
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

TEST_F(ExrTest, RowsWrittenInBandsMakeTheSameFileAndReadBackInBands) {
    std::vector<float> y(4 * 5);
    for (std::size_t i = 0; i < y.size(); ++i) {
        y[i] = 0.5f * float(i) - 3.0f;
    }
    ExrRowWriter writer(dir_ / "b.exr", 4, 5, {"Y"});
    writer.writeRows(2, {std::span<const float>(y).first(8)});
    writer.writeRows(3, {std::span<const float>(y).subspan(8)});
    EXPECT_FALSE(fs::exists(dir_ / "b.exr"));  // not before finish()
    writer.finish();
    EXPECT_EQ(readExr(dir_ / "b.exr").channels.at("Y"), y);
    ExrRowReader reader(dir_ / "b.exr");
    std::vector<float> rows(8);
    reader.readRows("Y", 3, 2, rows);
    EXPECT_EQ(rows, std::vector<float>(y.begin() + 12, y.end()));
}

TEST_F(ExrTest, FinishingBeforeEveryRowIsInFailsAndLeavesNothing) {
    {
        ExrRowWriter writer(dir_ / "short.exr", 2, 2, {"Y"});
        writer.writeRows(1, {std::vector<float>{1.0f, 2.0f}});
        EXPECT_THROW(writer.finish(), OutputError);
    }
    EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(ExrTest, ReadingANonExrFileIsAnErrorNamingIt) {
    std::ofstream(dir_ / "x.exr") << "not an EXR";
    try {
        readExr(dir_ / "x.exr");
        FAIL() << "expected ImageIoError";
    } catch (const ImageIoError& error) {
        EXPECT_NE(std::string(error.what()).find((dir_ / "x.exr").string()), std::string::npos) << error.what();
    }
}

TEST_F(ExrTest, UnwritablePathThrowsAndLeavesNothing) {
    EXPECT_THROW(writeExr(dir_ / "missing" / "a.exr", 1, 1, {{"Y", {1.0f}}}), OutputError);
    EXPECT_TRUE(fs::is_empty(dir_));  // no directory made, no temporary file left
}

}  // namespace
}  // namespace hexray
