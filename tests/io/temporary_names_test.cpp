// Temporary names say what they are and fit the file system's name limit for any target.

#include <unistd.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "io/temporary_names.h"
#include "support/temporary_directory_test.h"

namespace hexray {
namespace {

namespace fs = std::filesystem;

using TemporaryNamesTest = test::TemporaryDirectoryTest;

TEST_F(TemporaryNamesTest, APartialFileNamesItsTarget) {
    const fs::path pattern = partialFilePattern(dir_, "out.png");
    EXPECT_EQ(pattern.parent_path(), dir_);
    EXPECT_EQ(pattern.filename().string(), ".hexray-partial-out.png.XXXXXX");
}

TEST_F(TemporaryNamesTest, ALongTargetIsShortenedToFitTheNameLimit) {
    const std::size_t nameMax = std::size_t(::pathconf(dir_.c_str(), _PC_NAME_MAX));
    const std::string name = std::string(nameMax, 'n');
    const std::string temporary = fs::path(partialFilePattern(dir_, name)).filename().string();
    EXPECT_EQ(temporary.size(), nameMax);
    EXPECT_EQ(temporary.rfind(".hexray-partial-nnnn", 0), 0u);
    EXPECT_TRUE(temporary.ends_with("n.XXXXXX")) << temporary;
}

TEST_F(TemporaryNamesTest, ShorteningNeverSplitsACharacter) {
    const std::size_t nameMax = std::size_t(::pathconf(dir_.c_str(), _PC_NAME_MAX));
    std::string name;
    while (name.size() + 2 <= nameMax) {
        name += "\xC3\xA9";  // é, two bytes
    }
    const std::string temporary = fs::path(partialFilePattern(dir_, name)).filename().string();
    EXPECT_LE(temporary.size(), nameMax);
    const std::string kept = temporary.substr(16, temporary.size() - 16 - 7);  // between prefix and ".XXXXXX"
    EXPECT_EQ(kept.size() % 2, 0u) << "a character was cut";
    EXPECT_EQ(name.compare(0, kept.size(), kept), 0);
}

}  // namespace
}  // namespace hexray
