// Where outputs go and what they never destroy, through the real executable: device nodes,
// FIFOs and standard output written directly, symlinks followed, permissions kept, long names,
// an output that is an input (or another output) refused, every output path checked before the
// work, and no temporary file or directory left by a signal.

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/cli_fixture.h"
#include "image/image_io.h"
#include "support/terminating_signals.h"

namespace hexray {
namespace {

using test::readFile;
using test::RunResult;
namespace fs = std::filesystem;

class OutputCliTest : public test::CliTest {
protected:
    // A small render to `output`: 32x24 on the GPU.
    RunResult renderTo(const std::string& output, const std::string& extra = "") const {
        return hexray("render " + scene("lecture-demo.json") + " --width 32 --height 24 -o " + output + " " + extra);
    }

    // Makes a character device node like /dev/null (1, 3) or /dev/full (1, 7) in the test's
    // directory; skips the test where that is not allowed (GTEST_SKIP here only marks it: the caller
    // returns when IsSkipped()).
    void makeDeviceNode(const std::string& name, unsigned minor) {
        if (::geteuid() != 0) {
            GTEST_SKIP() << "making a device node needs root (CI runs as root)";
        }
        if (::mknod((dir_ / name).c_str(), S_IFCHR | 0666, makedev(1, minor)) != 0) {
            GTEST_SKIP() << "mknod is not permitted here: " << std::strerror(errno);
        }
    }

    static bool isCharacterDevice(const fs::path& path, unsigned minor) {
        struct stat status {};
        return ::lstat(path.c_str(), &status) == 0 && S_ISCHR(status.st_mode) && status.st_rdev == makedev(1, minor);
    }

    static mode_t permissions(const fs::path& path) {
        struct stat status {};
        EXPECT_EQ(::stat(path.c_str(), &status), 0) << path;
        return status.st_mode & 07777;
    }

    // The hidden entries (temporary files and directories) in `directory`.
    static std::vector<std::string> hidden(const fs::path& directory) { return entriesStartingWith(directory, "."); }

    // Starts a render to big.png (or with --aov into aov/) and returns once it has stopped itself
    // with its temporary file (or AOV staging directory) in place: the test hook of
    // io/removed_on_signal.h, so what the test then sends finds the render at that point on any
    // machine, however fast or loaded. -1 if it did not stop there.
    pid_t startStoppedRender(bool aov = false) const {
        std::vector<std::string> arguments = {"render",   test::sourcePath("scenes/lecture-demo.json").string(),
                                              "-o",       "big.png",
                                              "--width",  "64",
                                              "--height", "48"};
        if (aov) {
            arguments.insert(arguments.end(), {"--aov", "aov"});
        }
        const pid_t pid =
            start(arguments, {std::string("HEXRAY_TEST_STOP_AT_TEMPORARY=") + (aov ? "directory" : "file")});
        int status = 0;
        if (pid < 0 || ::waitpid(pid, &status, WUNTRACED) != pid || !WIFSTOPPED(status)) {
            return -1;
        }
        return pid;
    }

    // Sends `signal` to a process stopped by startStoppedRender, lets it go on, and returns how it ended.
    static int signalStopped(pid_t pid, int signal) {
        ::kill(pid, signal);
        ::kill(pid, SIGCONT);
        int status = 0;
        return ::waitpid(pid, &status, 0) == pid ? status : -1;
    }
};

// ---------------------------------------------------------------- not a regular file: written directly

TEST_F(OutputCliTest, ADeviceNodeLikeDevNullIsWrittenNotReplaced) {
    makeDeviceNode("null", 3);
    if (IsSkipped()) {
        return;  // no device node to write to
    }
    const RunResult run = renderTo("null");
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_TRUE(isCharacterDevice(dir_ / "null", 3)) << "the device node was replaced";
    EXPECT_EQ(createdFiles(), std::vector<std::string>{"null"});
}

TEST_F(OutputCliTest, ADeviceNodeLikeDevFullReportsNoSpaceWithExitCode5) {
    makeDeviceNode("full", 7);
    if (IsSkipped()) {
        return;  // no device node to write to
    }
    const RunResult run = renderTo("full");
    EXPECT_EQ(run.exitCode, 5) << run.err;
    EXPECT_NE(run.err.find("full: cannot write: No space left on device"), std::string::npos) << run.err;
    EXPECT_TRUE(isCharacterDevice(dir_ / "full", 7)) << "the device node was replaced";
    EXPECT_EQ(createdFiles(), std::vector<std::string>{"full"});
}

TEST_F(OutputCliTest, AFifoIsWrittenNotReplaced) {
    ASSERT_EQ(::mkfifo((dir_ / "fifo").c_str(), 0644), 0);
    const RunResult run = shell("timeout 60 cat fifo > got.png & \"$HEXRAY\" render " + scene("lecture-demo.json") +
                                " --width 32 --height 24 -o fifo; code=$?; wait; exit $code");
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_TRUE(fs::is_fifo(fs::symlink_status(dir_ / "fifo"))) << "the FIFO was replaced";
    EXPECT_EQ(readPng(dir_ / "got.png").width, 32u);
}

TEST_F(OutputCliTest, DashWritesThePngToStandardOutputAndTheSummaryToStderr) {
    const RunResult run = renderTo("-");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const Rgb8Image image = readPng(dir_ / "stdout.txt");
    EXPECT_EQ(image.width, 32u);
    EXPECT_EQ(image.height, 24u);
    EXPECT_NE(run.err.find("wrote standard output (32x24)"), std::string::npos) << run.err;
    EXPECT_EQ(createdFiles(), std::vector<std::string>{});
}

TEST_F(OutputCliTest, ALinkToStandardOutputIsWrittenThroughNotReplaced) {
    // /dev/stdout itself is a link to /proc/self/fd/1: replacing it would break the system's.
    fs::create_symlink("/proc/self/fd/1", dir_ / "stdout-link");
    const RunResult run = renderTo("stdout-link");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_TRUE(fs::is_symlink(dir_ / "stdout-link"));
    EXPECT_EQ(readPng(dir_ / "stdout.txt").width, 32u);
}

// ---------------------------------------------------------------- regular files: side effects of the replace

TEST_F(OutputCliTest, ASymlinkHasItsTargetWrittenAndStaysALink) {
    fs::create_directories(dir_ / "real");
    std::ofstream(dir_ / "real" / "image.png") << "old";
    fs::create_symlink("real/image.png", dir_ / "link.png");
    fs::create_symlink("real/new.png", dir_ / "dangling.png");
    ASSERT_EQ(renderTo("link.png").exitCode, 0);
    ASSERT_EQ(renderTo("dangling.png").exitCode, 0);
    EXPECT_TRUE(fs::is_symlink(dir_ / "link.png"));
    EXPECT_TRUE(fs::is_symlink(dir_ / "dangling.png"));
    EXPECT_EQ(readPng(dir_ / "real" / "image.png").width, 32u);
    EXPECT_EQ(readPng(dir_ / "real" / "new.png").width, 32u);
    EXPECT_TRUE(hidden(dir_ / "real").empty());
}

TEST_F(OutputCliTest, AReplacedFileKeepsItsPermissions) {
    std::ofstream(dir_ / "private.png") << "old";
    fs::permissions(dir_ / "private.png", fs::perms::owner_read | fs::perms::owner_write);
    std::ofstream(dir_ / "shared.png") << "old";
    fs::permissions(dir_ / "shared.png", fs::perms::owner_all | fs::perms::group_read | fs::perms::others_read);
    ASSERT_EQ(renderTo("private.png").exitCode, 0);
    ASSERT_EQ(renderTo("shared.png").exitCode, 0);
    EXPECT_EQ(permissions(dir_ / "private.png"), 0600u);
    EXPECT_EQ(permissions(dir_ / "shared.png"), 0744u);
    EXPECT_EQ(readPng(dir_ / "private.png").width, 32u);
}

TEST_F(OutputCliTest, AHardLinkedFileIsReplacedUnderItsNameAndTheOtherNameKeepsTheOldContents) {
    // The documented behaviour (docs/command-line.md, "Where outputs go"): an atomic replace of the name given.
    std::ofstream(dir_ / "a.png") << "old";
    fs::create_hard_link(dir_ / "a.png", dir_ / "b.png");
    ASSERT_EQ(renderTo("a.png").exitCode, 0);
    EXPECT_EQ(readPng(dir_ / "a.png").width, 32u);
    EXPECT_EQ(readFile(dir_ / "b.png"), "old");
}

TEST_F(OutputCliTest, NamesUpToTheFileSystemLimitWork) {
    const long nameMax = ::pathconf(dir_.c_str(), _PC_NAME_MAX);
    ASSERT_GT(nameMax, 12);
    for (const std::size_t length : {std::size_t(nameMax) - 10, std::size_t(nameMax) - 4, std::size_t(nameMax)}) {
        const std::string name = std::string(length - 4, 'n') + ".png";
        const RunResult run = renderTo(name);
        EXPECT_EQ(run.exitCode, 0) << length << ": " << run.err;
        EXPECT_TRUE(fs::exists(dir_ / name)) << length;
    }
    EXPECT_TRUE(hidden(dir_).empty());
}

// ---------------------------------------------------------------- an output that is an input

TEST_F(OutputCliTest, AnOutputThatIsTheSceneIsRefusedBeforeAnyWork) {
    const fs::path scenePath = writeScene("my.json", readFile(test::sourcePath("scenes/lecture-demo.json")));
    const std::string original = readFile(scenePath);
    fs::create_hard_link(scenePath, dir_ / "hard.png");
    fs::create_symlink("my.json", dir_ / "soft.png");
    for (const std::string command : {"render my.json -o my.json", "render my.json -o hard.png",
                                      "render my.json -o soft.png", "render my.json -o ./sub/../my.json",
                                      "bench my.json --csv my.json --width 8 --height 8 --rounds 1 --samples 1 "
                                      "--reference-samples 1",
                                      "compare my.json --diff my.json --width 8 --height 8"}) {
        fs::create_directories(dir_ / "sub");
        const RunResult run = hexray(command);
        EXPECT_EQ(run.exitCode, 2) << command << "\n" << run.err;
        EXPECT_NE(run.err.find("the same file as the scene"), std::string::npos) << command << "\n" << run.err;
        EXPECT_EQ(run.out, "") << command;
        EXPECT_EQ(readFile(scenePath), original) << command;
    }
}

TEST_F(OutputCliTest, TwoOutputsOfOneCommandThatAreOneFileAreRefused) {
    RunResult run = hexray("compare " + scene("lecture-demo.json") + " --width 8 --height 8 --diff x.png --mask x.png");
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find("--mask x.png: the same file as --diff x.png"), std::string::npos) << run.err;
    EXPECT_EQ(run.out, "");
    // Aliases by path: the same directory reached two ways.
    fs::create_directories(dir_ / "d");
    fs::create_directory_symlink("d", dir_ / "alias");
    run = hexray("compare " + scene("lecture-demo.json") + " --width 8 --height 8 --diff d/x.png --mask alias/x.png");
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find("the same file as --diff"), std::string::npos) << run.err;
    EXPECT_TRUE(fs::is_empty(dir_ / "d"));
    // An AOV directory that is the image, and an image inside the AOV directory under an AOV's name.
    run = renderTo("l.png", "--aov l.png");
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find("the same"), std::string::npos) << run.err;
    run = renderTo("aov/depth.png", "--aov aov");
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find("aov/depth.png"), std::string::npos) << run.err;
    EXPECT_EQ(createdFiles(), (std::vector<std::string>{"alias", "d"}));
}

// ---------------------------------------------------------------- paths checked before the work

TEST_F(OutputCliTest, AnUnwritableOutputPathFailsBeforeTheWork) {
    struct Case {
        std::string command;
        std::string path;
    };
    const std::string demo = scene("lecture-demo.json");
    for (const Case& c :
         {Case{"bench " + demo +
                   " --width 8 --height 8 --rounds 1 --samples 1 --reference-samples 1 "
                   "--csv nodir/x.csv",
               "nodir/x.csv"},
          Case{"compare " + demo + " --width 8 --height 8 --mask nodir/m.png", "nodir/m.png"},
          Case{"compare " + demo + " --width 8 --height 8 --diff nodir/d.png", "nodir/d.png"},
          Case{"render " + demo + " --width 8 --height 8 -o x.png --aov file.txt/aov", "file.txt/aov"}}) {
        std::ofstream(dir_ / "file.txt") << "a file, not a directory";
        const RunResult run = hexray(c.command);
        EXPECT_EQ(run.exitCode, 5) << c.command << "\n" << run.err;
        EXPECT_NE(run.err.find(c.path), std::string::npos) << run.err;
        EXPECT_EQ(run.out, "") << c.command << ": the work ran before the output failed";
        EXPECT_EQ(createdFiles(), std::vector<std::string>{"file.txt"}) << c.command;
    }
}

TEST_F(OutputCliTest, AnAovSetCannotGoToStandardOutput) {
    const std::string demo = scene("lecture-demo.json") + " --width 8 --height 8";
    for (const std::string& command : {"render " + demo + " -o x.png --aov -", "compare " + demo + " --aov -"}) {
        const RunResult run = hexray(command);
        EXPECT_EQ(run.exitCode, 2) << command << "\n" << run.err;
        EXPECT_NE(run.err.find("--aov: an AOV set is several files"), std::string::npos) << run.err;
        EXPECT_NE(run.err.find("standard output"), std::string::npos) << run.err;
        EXPECT_EQ(createdFiles(), std::vector<std::string>{}) << command;
    }
}

// ---------------------------------------------------------------- signals

class SignalCliTest : public OutputCliTest, public ::testing::WithParamInterface<int> {
protected:
    void SetUp() override {
        OutputCliTest::SetUp();
        const rlimit noCore{0, 0};  // SIGQUIT's default action dumps core; hexray inherits the limit
        ::setrlimit(RLIMIT_CORE, &noCore);
    }
};

TEST_P(SignalCliTest, ARenderEndedBySignalLeavesTheOldImageAndNoTemporaryFile) {
    const int signal = GetParam();
    std::ofstream(dir_ / "big.png") << "keep me";
    const pid_t pid = startStoppedRender();
    ASSERT_GT(pid, 0) << "the render did not stop at its temporary file";
    ASSERT_EQ(hidden(dir_).size(), 1u);
    const int status = signalStopped(pid, signal);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << "status " << status;
    EXPECT_EQ(readFile(dir_ / "big.png"), "keep me");
    EXPECT_EQ(createdFiles(), std::vector<std::string>{"big.png"});
}

// Every one but the real-time signals between the first and the last (the unit test has them all).
std::vector<int> signalsToSend() {
    std::vector<int> signals;
    for (const int signal : test::catchableTerminatingSignals()) {
        if (signal <= SIGRTMIN || signal == SIGRTMAX) {
            signals.push_back(signal);
        }
    }
    return signals;
}

INSTANTIATE_TEST_SUITE_P(CatchableSignals, SignalCliTest, ::testing::ValuesIn(signalsToSend()),
                         [](const auto& info) { return test::signalTestName(info.param); });

TEST_F(OutputCliTest, ASignalDuringAovStagingLeavesNoStagingDirectory) {
    const pid_t pid = startStoppedRender(true);
    ASSERT_GT(pid, 0) << "the render did not stop at its staging directory";
    ASSERT_FALSE(hidden(dir_ / "aov").empty());
    const int status = signalStopped(pid, SIGINT);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) << "status " << status;
    EXPECT_EQ(hidden(dir_ / "aov"), std::vector<std::string>{});
    EXPECT_EQ(hidden(dir_), std::vector<std::string>{});
}

TEST_F(OutputCliTest, WhatSigkillLeavesSaysWhatItIsAndTheNextRunRemovesIt) {
    const pid_t pid = startStoppedRender();
    ASSERT_GT(pid, 0);
    signalStopped(pid, SIGKILL);
    const std::vector<std::string> left = hidden(dir_);
    ASSERT_EQ(left.size(), 1u);
    EXPECT_EQ(left[0].rfind(".hexray-partial-", 0), 0u) << left[0];
    ASSERT_EQ(renderTo("small.png").exitCode, 0);
    EXPECT_EQ(hidden(dir_), std::vector<std::string>{});
    EXPECT_EQ(createdFiles(), std::vector<std::string>{"small.png"});
}

TEST_F(OutputCliTest, AnAovStagingDirectoryLeftBySigkillIsRemovedByTheNextRunIntoIt) {
    const pid_t pid = startStoppedRender(true);
    ASSERT_GT(pid, 0);
    signalStopped(pid, SIGKILL);
    ASSERT_FALSE(hidden(dir_ / "aov").empty());
    std::ofstream(dir_ / "aov" / ".not-hexrays") << "kept";
    const RunResult run = renderTo("small.png", "--aov aov");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(hidden(dir_ / "aov"), std::vector<std::string>{".not-hexrays"});
}

}  // namespace
}  // namespace hexray
