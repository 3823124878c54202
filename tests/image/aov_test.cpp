// AOV sets: every file with its documented values, written band by band, staged until commit(),
// and a directory that never mixes two renders' AOVs.

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "image/aov.h"
#include "image/exr_io.h"
#include "image/image_io.h"
#include "io/output_error.h"
#include "support/temporary_directory_test.h"

namespace hexray {
namespace {

namespace fs = std::filesystem;

using AovTest = test::TemporaryDirectoryTest;

// A whole set's values, written in bands of `rowsPerBand`.
struct AovValues {
    AovLayout layout;
    std::vector<float> depth;
    std::vector<glm::vec3> normals;
    std::vector<PixelClass> classes;
    std::vector<float> margins;

    void writeTo(StagedAovs& staged, std::uint32_t rowsPerBand) const {
        for (std::uint32_t first = 0; first < layout.height; first += rowsPerBand) {
            const std::uint32_t rows = std::min(rowsPerBand, layout.height - first);
            const std::size_t offset = std::size_t(first) * layout.width;
            const std::size_t count = std::size_t(rows) * layout.width;
            const auto band = [&](const auto& values) { return std::span(values).subspan(offset, count); };
            staged.writeRows({rows, band(depth), band(normals), band(classes),
                              margins.empty() ? std::span<const float>() : band(margins)});
        }
    }

    std::vector<fs::path> commitTo(const fs::path& directory, std::uint32_t rowsPerBand) const {
        StagedAovs staged(directory, layout, {});
        writeTo(staged, rowsPerBand);
        return staged.commit();
    }
};

// A 1x1 set with `lights` light masks.
AovValues tinySet(std::size_t lights) {
    return AovValues{{1, 1, lights}, {2.0f}, {glm::vec3(0, 1, 0)}, {PixelClass{0, PixelClass::litBit(0)}}, {}};
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
    const AovValues values{{2, 1, 2, true, 1.0 / 131072.0},
                           {inf, 7.5f},
                           {glm::vec3(0), glm::vec3(0, 1, 0)},
                           {PixelClass{}, PixelClass{3, PixelClass::litBit(1)}},
                           {inf, 1e-7f}};
    const auto files = values.commitTo(dir_ / "aov", 1);
    EXPECT_EQ(files.size(), 12u);  // depth, normal, object-id, light-0, light-1, margin: EXR + PNG each
    EXPECT_EQ(readExr(dir_ / "aov" / "depth.exr").channels.at("Y"), (std::vector<float>{inf, 7.5f}));
    EXPECT_EQ(readExr(dir_ / "aov" / "object-id.exr").channels.at("Y"), (std::vector<float>{-1.0f, 3.0f}));
    EXPECT_EQ(readExr(dir_ / "aov" / "normal.exr").channels.at("G"), (std::vector<float>{0.0f, 1.0f}));
    EXPECT_EQ(readExr(dir_ / "aov" / "light-0.exr").channels.at("Y"), (std::vector<float>{0.0f, 0.0f}));
    EXPECT_EQ(readExr(dir_ / "aov" / "light-1.exr").channels.at("Y"), (std::vector<float>{0.0f, 1.0f}));
    EXPECT_EQ(readExr(dir_ / "aov" / "margin.exr").channels.at("Y"), values.margins);
    const Rgb8Image marginPreview = readPng(dir_ / "aov" / "margin.png");
    EXPECT_EQ(std::vector<std::uint8_t>(marginPreview.bytes.begin() + 3, marginPreview.bytes.end()),
              (std::vector<std::uint8_t>{255, 0, 0}));  // ambiguous: red
    const Rgb8Image depthPreview = readPng(dir_ / "aov" / "depth.png");
    EXPECT_EQ(std::vector<std::uint8_t>(depthPreview.bytes.begin(), depthPreview.bytes.begin() + 3),
              (std::vector<std::uint8_t>{0, 0, 0}));  // the background
}

TEST_F(AovTest, BandsOfAnySizeMakeTheSameFilesAsOneBand) {
    // 3 x 5 pixels with depths over a range, so the depth preview's scale spans the bands.
    AovValues values{{3, 5, 2, true, 0.01}, {}, {}, {}, {}};
    for (std::uint32_t i = 0; i < 15; ++i) {
        values.depth.push_back(i % 4 == 0 ? std::numeric_limits<float>::infinity() : 1.0f + float(i * i));
        values.normals.emplace_back(0.1f * float(i), -1.0f, 0.5f);
        values.classes.push_back(i % 4 == 0 ? PixelClass{} : PixelClass{i % 3, PixelClass::litBit(i % 2)});
        values.margins.push_back(1e-3f * float(i));
    }
    values.commitTo(dir_ / "whole", 5);
    values.commitTo(dir_ / "banded", 2);
    ASSERT_EQ(namesIn(dir_ / "whole"), namesIn(dir_ / "banded"));
    for (const std::string& name : namesIn(dir_ / "whole")) {
        if (name.ends_with(".exr")) {
            EXPECT_EQ(readExr(dir_ / "whole" / name).channels, readExr(dir_ / "banded" / name).channels) << name;
        } else {
            EXPECT_EQ(readPng(dir_ / "whole" / name).bytes, readPng(dir_ / "banded" / name).bytes) << name;
        }
    }
    EXPECT_EQ(readExr(dir_ / "banded" / "depth.exr").channels.at("Y"), values.depth);
}

TEST_F(AovTest, NothingAppearsBeforeCommitAndAnUncommittedSetLeavesNoTrace) {
    fs::create_directories(dir_ / "aov");
    std::ofstream(dir_ / "aov" / "depth.exr") << "an earlier render's";
    {
        StagedAovs staged(dir_ / "aov", tinySet(2).layout, {});
        tinySet(2).writeTo(staged, 1);
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

TEST_F(AovTest, AnUncommittedSetRemovesTheDirectoriesItCreated) {
    {
        StagedAovs staged(dir_ / "new" / "aov", tinySet(1).layout, {});
        EXPECT_TRUE(fs::is_directory(dir_ / "new" / "aov"));
    }
    EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(AovTest, ABandOfTheWrongSizeIsRefusedAndLeavesNoStagingDirectory) {
    {
        StagedAovs staged(dir_ / "aov", tinySet(1).layout, {});
        AovValues wrong = tinySet(1);
        wrong.depth.push_back(1.0f);  // one value too many
        EXPECT_THROW(staged.writeRows({1, wrong.depth, wrong.normals, wrong.classes, {}}), std::invalid_argument);
    }
    EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(AovTest, AStagingDirectoryThatAKilledRunLeftIsRemovedAndAFreshOneIsNot) {
    fs::create_directories(dir_ / "aov" / ".hexray-aov-stale");
    std::ofstream(dir_ / "aov" / ".hexray-aov-stale" / "depth.exr") << "partial";
    fs::last_write_time(dir_ / "aov" / ".hexray-aov-stale", fs::file_time_type::clock::now() - std::chrono::hours(1));
    fs::create_directories(dir_ / "aov" / ".hexray-aov-fresh");  // newer than this run's start: another run's
    fs::last_write_time(dir_ / "aov" / ".hexray-aov-fresh", fs::file_time_type::clock::now() + std::chrono::hours(1));
    fs::create_directories(dir_ / "aov" / ".hexray-aovish");  // not a name hexray gives
    fs::last_write_time(dir_ / "aov" / ".hexray-aovish", fs::file_time_type::clock::now() - std::chrono::hours(1));
    tinySet(1).commitTo(dir_ / "aov", 1);
    EXPECT_FALSE(fs::exists(dir_ / "aov" / ".hexray-aov-stale"));
    EXPECT_TRUE(fs::exists(dir_ / "aov" / ".hexray-aov-fresh"));
    EXPECT_TRUE(fs::exists(dir_ / "aov" / ".hexray-aovish"));
}

TEST_F(AovTest, CommitReplacesAnEarlierSetAndDropsWhatThisOneLacks) {
    AovValues withMargins = tinySet(3);
    withMargins.layout.withMargins = true;
    withMargins.margins = {1.0f};
    withMargins.commitTo(dir_ / "aov", 1);
    for (const char* name : {"notes.txt", "light-extra.png", "depth.txt"}) {
        std::ofstream(dir_ / "aov" / name) << "kept";
    }
    const auto files = tinySet(1).commitTo(dir_ / "aov", 1);
    EXPECT_EQ(files.size(), 8u);
    // light-1, light-2 and margin were the earlier set's only; files hexray does not name stay.
    EXPECT_EQ(namesIn(dir_ / "aov"),
              (std::vector<std::string>{"depth.exr", "depth.png", "depth.txt", "light-0.exr", "light-0.png",
                                        "light-extra.png", "normal.exr", "normal.png", "notes.txt", "object-id.exr",
                                        "object-id.png"}));
}

TEST(AovFileName, NamesOnlyTheFilesASetHolds) {
    for (const char* name : {"depth.exr", "normal.png", "object-id.exr", "margin.png", "light-0.exr", "light-30.png"}) {
        EXPECT_TRUE(isAovFileName(name)) << name;
    }
    for (const char* name : {"depth.txt", "light-.exr", "light-x.png", "scene.json", "depth"}) {
        EXPECT_FALSE(isAovFileName(name)) << name;
    }
}

}  // namespace
}  // namespace hexray
