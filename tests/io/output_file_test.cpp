// OutputFile: atomic for regular files (permissions kept, symlinks followed, any valid name),
// direct for everything else, with write errors reported.

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "io/output_error.h"
#include "io/output_file.h"
#include "support/temporary_directory_test.h"

namespace hexray {
namespace {

namespace fs = std::filesystem;

using OutputFileTest = test::TemporaryDirectoryTest;

std::string contents(const fs::path& path) {
    std::stringstream text;
    text << std::ifstream(path, std::ios::binary).rdbuf();
    return text.str();
}

void write(OutputFile& file, const std::string& text) {
    ASSERT_EQ(std::fwrite(text.data(), 1, text.size(), file.stream()), text.size());
}

std::size_t entries(const fs::path& directory) {
    return std::size_t(std::distance(fs::directory_iterator(directory), fs::directory_iterator()));
}

TEST_F(OutputFileTest, ANewFileAppearsOnlyOnCommitBesideANamedTemporary) {
    OutputFile file((dir_ / "new.png").string());
    write(file, "image");
    std::fflush(file.stream());
    EXPECT_FALSE(fs::exists(dir_ / "new.png"));
    ASSERT_EQ(entries(dir_), 1u);
    EXPECT_EQ(fs::directory_iterator(dir_)->path().filename().string().rfind(".hexray-partial-new.png.", 0), 0u);
    file.commit();
    EXPECT_EQ(contents(dir_ / "new.png"), "image");
    EXPECT_EQ(entries(dir_), 1u);
}

TEST_F(OutputFileTest, AnUncommittedFileLeavesTheOldContentsAndNoTemporary) {
    std::ofstream(dir_ / "old.png") << "old";
    {
        OutputFile file((dir_ / "old.png").string());
        write(file, "half an ima");
    }
    EXPECT_EQ(contents(dir_ / "old.png"), "old");
    EXPECT_EQ(entries(dir_), 1u);
}

TEST_F(OutputFileTest, AReplacedFileKeepsItsPermissions) {
    std::ofstream(dir_ / "private.png") << "old";
    ::chmod((dir_ / "private.png").c_str(), 0640);
    OutputFile file((dir_ / "private.png").string());
    write(file, "new");
    file.commit();
    struct stat status {};
    ASSERT_EQ(::stat((dir_ / "private.png").c_str(), &status), 0);
    EXPECT_EQ(status.st_mode & 07777, 0640u);
    EXPECT_EQ(contents(dir_ / "private.png"), "new");
}

TEST_F(OutputFileTest, ASymlinksTargetIsWrittenAndTheLinkStays) {
    fs::create_directories(dir_ / "real");
    fs::create_symlink("real/target.png", dir_ / "link.png");  // dangling until written
    OutputFile file((dir_ / "link.png").string());
    write(file, "through the link");
    file.commit();
    EXPECT_TRUE(fs::is_symlink(dir_ / "link.png"));
    EXPECT_EQ(contents(dir_ / "real" / "target.png"), "through the link");
}

TEST_F(OutputFileTest, ANameOfTheFileSystemsLongestLengthWorks) {
    const long nameMax = ::pathconf(dir_.c_str(), _PC_NAME_MAX);
    const fs::path target = dir_ / std::string(std::size_t(nameMax), 'x');
    OutputFile file(target.string());
    write(file, "long");
    file.commit();
    EXPECT_EQ(contents(target), "long");
}

TEST_F(OutputFileTest, AFifoIsWrittenDirectly) {
    ASSERT_EQ(::mkfifo((dir_ / "fifo").c_str(), 0600), 0);
    std::string received;
    std::thread reader([&] { received = contents(dir_ / "fifo"); });
    {
        OutputFile file((dir_ / "fifo").string());
        write(file, "streamed");
        file.commit();
    }
    reader.join();
    EXPECT_EQ(received, "streamed");
    EXPECT_TRUE(fs::is_fifo(fs::symlink_status(dir_ / "fifo")));
    EXPECT_EQ(entries(dir_), 1u);
}

TEST_F(OutputFileTest, AFullDeviceReportsNoSpaceAndStaysADevice) {
    if (::geteuid() != 0 || ::mknod((dir_ / "full").c_str(), S_IFCHR | 0666, makedev(1, 7)) != 0) {
        GTEST_SKIP() << "making a device node needs root (CI runs as root)";
    }
    OutputFile file((dir_ / "full").string());
    write(file, "no room");
    try {
        file.commit();
        FAIL() << "expected OutputError";
    } catch (const OutputError& error) {
        EXPECT_NE(std::string(error.what()).find("cannot write: " + std::string(std::strerror(ENOSPC))),
                  std::string::npos)
            << error.what();
    }
    struct stat status {};
    ASSERT_EQ(::lstat((dir_ / "full").c_str(), &status), 0);
    EXPECT_TRUE(S_ISCHR(status.st_mode));
}

TEST_F(OutputFileTest, ADirectoryOrAMissingDirectoryIsRefusedNamingThePath) {
    fs::create_directories(dir_ / "sub");
    for (const fs::path& path : {dir_ / "sub", dir_ / "missing" / "x.png"}) {
        try {
            OutputFile file(path.string());
            FAIL() << "expected OutputError for " << path;
        } catch (const OutputError& error) {
            EXPECT_NE(std::string(error.what()).find(path.string() + ": cannot create output file: "),
                      std::string::npos)
                << error.what();
        }
    }
    EXPECT_EQ(entries(dir_), 1u);
}

}  // namespace
}  // namespace hexray
