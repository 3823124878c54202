// Only hexray's own temporaries, older than the run's start and held by no live run, are stale.

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "io/stale_temporaries.h"
#include "support/temporary_directory_test.h"

namespace hexray {
namespace {

namespace fs = std::filesystem;

using StaleTemporariesTest = test::TemporaryDirectoryTest;

// A file written an hour ago.
fs::path oldFile(const fs::path& path) {
    std::ofstream(path) << "partial";
    fs::last_write_time(path, fs::file_time_type::clock::now() - std::chrono::hours(1));
    return path;
}

TEST_F(StaleTemporariesTest, RemovesOnlyHexraysOwnOldUnheldTemporaries) {
    oldFile(dir_ / ".hexray-partial-a.png.AbCdEf");  // stale
    oldFile(dir_ / ".a.png.AbCdEf");                 // the old naming: not recognisably hexray's
    oldFile(dir_ / ".hexray-partial-");              // the prefix alone
    oldFile(dir_ / "hexray-partial-visible.png");    // not hidden
    std::ofstream(dir_ / ".hexray-partial-new.png.123456") << "being written";
    // Newer than the run's start, beyond the file system's timestamp granularity (a tick).
    fs::last_write_time(dir_ / ".hexray-partial-new.png.123456",
                        fs::file_time_type::clock::now() + std::chrono::hours(1));
    fs::create_directories(dir_ / ".hexray-aov-Stale1");
    oldFile(dir_ / ".hexray-aov-Stale1" / "depth.exr");
    fs::last_write_time(dir_ / ".hexray-aov-Stale1", fs::file_time_type::clock::now() - std::chrono::hours(1));
    fs::create_symlink(oldFile(dir_ / "target"), dir_ / ".hexray-partial-link");
    removeStaleTemporaries(dir_);
    EXPECT_FALSE(fs::exists(dir_ / ".hexray-partial-a.png.AbCdEf"));
    EXPECT_FALSE(fs::exists(dir_ / ".hexray-aov-Stale1"));
    for (const char* kept : {".a.png.AbCdEf", ".hexray-partial-", "hexray-partial-visible.png",
                             ".hexray-partial-new.png.123456", ".hexray-partial-link", "target"}) {
        EXPECT_TRUE(fs::exists(fs::symlink_status(dir_ / kept))) << kept;
    }
}

TEST_F(StaleTemporariesTest, ATemporaryALiveRunHoldsStays) {
    const fs::path held = oldFile(dir_ / ".hexray-partial-held.png.AbCdEf");
    const int descriptor = ::open(held.c_str(), O_RDONLY);
    ASSERT_GE(descriptor, 0);
    holdAsLive(descriptor);
    removeStaleTemporaries(dir_);
    EXPECT_TRUE(fs::exists(held));
    ::close(descriptor);  // as the kernel does when the process ends, however it ends
    removeStaleTemporaries(dir_);
    EXPECT_FALSE(fs::exists(held));
}

TEST_F(StaleTemporariesTest, TheCutOffIsTheTimeGiven) {
    const fs::path file = oldFile(dir_ / ".hexray-partial-x.png.AbCdEf");
    removeStaleTemporaries(dir_, fs::file_time_type::clock::now() - std::chrono::hours(2));
    EXPECT_TRUE(fs::exists(file));
    EXPECT_LT(runStart(), fs::file_time_type::clock::now());
}

}  // namespace
}  // namespace hexray
