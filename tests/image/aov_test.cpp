// AOV sets: every file with its documented values, staged until commit(), and a directory
// that never mixes two renders' AOVs.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "image/aov.h"
#include "image/exr_io.h"
#include "image/image_io.h"
#include "support/temporary_directory_test.h"

namespace hexray {
namespace {

namespace fs = std::filesystem;

using AovTest = test::TemporaryDirectoryTest;

// A 1x1 set with `lights` light masks.
AovSet tinySet(std::size_t lights) {
    return AovSet{1, 1, {2.0f}, {glm::vec3(0, 1, 0)}, {PixelClass{0, PixelClass::litBit(0)}}, lights};
}

std::vector<std::string> namesIn(const fs::path& directory) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(directory)) {
        names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

TEST_F(AovTest, SetWritesEveryFileWithItsDocumentedValues) {
    const float inf = std::numeric_limits<float>::infinity();
    AovSet aovs{2, 1, {inf, 7.5f}, {glm::vec3(0), glm::vec3(0, 1, 0)},
                {PixelClass{}, PixelClass{3, PixelClass::litBit(1)}}, 2};
    const std::vector<float> margins = {inf, 1e-7f};
    aovs.margins = &margins;
    aovs.ambiguityMargin = 1.0 / 131072.0;
    const auto files = StagedAovs(dir_ / "aov", aovs).commit();
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

TEST_F(AovTest, NothingAppearsBeforeCommitAndAnUncommittedSetLeavesNoTrace) {
    fs::create_directories(dir_ / "aov");
    std::ofstream(dir_ / "aov" / "depth.exr") << "an earlier render's";
    {
        StagedAovs staged(dir_ / "aov", tinySet(2));
        // Only the hidden staging directory is new; the earlier file is untouched.
        const std::vector<std::string> names = namesIn(dir_ / "aov");
        ASSERT_EQ(names.size(), 2u);
        EXPECT_EQ(names[0].rfind(".hexray-aov-", 0), 0u) << names[0];
        EXPECT_EQ(names[1], "depth.exr");
    }
    EXPECT_EQ(namesIn(dir_ / "aov"), std::vector<std::string>{"depth.exr"});
    std::ifstream earlier(dir_ / "aov" / "depth.exr");
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(earlier), {}), "an earlier render's");
}

TEST_F(AovTest, ASetThatCannotBeWrittenLeavesNoStagingDirectory) {
    AovSet wrong = tinySet(1);
    wrong.depth.push_back(1.0f);  // one value too many: the EXR writer refuses it
    EXPECT_THROW(StagedAovs(dir_ / "aov", wrong), ImageIoError);
    EXPECT_TRUE(fs::is_empty(dir_ / "aov"));
}

TEST_F(AovTest, CommitReplacesAnEarlierSetAndDropsWhatThisOneLacks) {
    AovSet withMargins = tinySet(3);
    const std::vector<float> margins = {1.0f};
    withMargins.margins = &margins;
    StagedAovs(dir_ / "aov", withMargins).commit();
    for (const char* name : {"notes.txt", "light-extra.png", "depth.txt"}) {
        std::ofstream(dir_ / "aov" / name) << "kept";
    }
    const auto files = StagedAovs(dir_ / "aov", tinySet(1)).commit();
    EXPECT_EQ(files.size(), 8u);
    // light-1, light-2 and margin were the earlier set's only; files hexray does not name stay.
    EXPECT_EQ(namesIn(dir_ / "aov"),
              (std::vector<std::string>{"depth.exr", "depth.png", "depth.txt", "light-0.exr", "light-0.png",
                                        "light-extra.png", "normal.exr", "normal.png", "notes.txt", "object-id.exr",
                                        "object-id.png"}));
}

}  // namespace
}  // namespace hexray
