// Registered temporaries go when a catchable signal ends the process, which then dies of it.

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <optional>

#include <gtest/gtest.h>

#include "io/removed_on_signal.h"
#include "support/temporary_directory_test.h"

namespace hexray {
namespace {

namespace fs = std::filesystem;

using RemovedOnSignalTest = test::TemporaryDirectoryTest;

// Runs `body` in a child process, then raises `signal` there; returns the child's wait status.
template <class Body>
int inChildRaising(int signal, Body&& body) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        const rlimit noCore{0, 0};  // SIGQUIT's default action dumps core
        ::setrlimit(RLIMIT_CORE, &noCore);
        body();
        std::raise(signal);
        ::_exit(99);  // not reached: the signal ends the child
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    return status;
}

class EachSignal : public RemovedOnSignalTest, public ::testing::WithParamInterface<int> {};

TEST_P(EachSignal, RemovesTheFilesAndDirectoriesRegisteredAndDiesOfTheSignal) {
    std::ofstream(dir_ / "partial.png") << "partial";
    fs::create_directories(dir_ / ".hexray-aov-x");
    for (const char* name : {"depth.exr", "depth.png", ".hexray-partial-normal.exr.abcdef"}) {
        std::ofstream(dir_ / ".hexray-aov-x" / name) << "partial";
    }
    std::ofstream(dir_ / "kept.png") << "kept";
    const int status = inChildRaising(GetParam(), [&] {
        static RemovedOnSignal file((dir_ / "partial.png").string(), RemovedOnSignal::Kind::File);
        static RemovedOnSignal directory((dir_ / ".hexray-aov-x").string(), RemovedOnSignal::Kind::Directory);
        static std::optional<RemovedOnSignal> released;
        released.emplace((dir_ / "kept.png").string(), RemovedOnSignal::Kind::File);
        released.reset();  // unregistered: the owner has put it in place
    });
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == GetParam()) << "status " << status;
    EXPECT_FALSE(fs::exists(dir_ / "partial.png"));
    EXPECT_FALSE(fs::exists(dir_ / ".hexray-aov-x"));
    EXPECT_TRUE(fs::exists(dir_ / "kept.png"));
}

INSTANTIATE_TEST_SUITE_P(CatchableSignals, EachSignal,
                         ::testing::Values(SIGHUP, SIGINT, SIGQUIT, SIGPIPE, SIGTERM, SIGUSR1, SIGUSR2),
                         [](const auto& info) { return std::string(sigabbrev_np(info.param)); });

}  // namespace
}  // namespace hexray
