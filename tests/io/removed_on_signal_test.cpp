// Registered temporaries go when a catchable signal ends the process, which then dies of it; a
// handler the process already has is kept, and faults are left to their default action.

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>

#include <gtest/gtest.h>

#include "io/removed_on_signal.h"
#include "support/temporary_directory_test.h"
#include "support/terminating_signals.h"

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

INSTANTIATE_TEST_SUITE_P(CatchableSignals, EachSignal, ::testing::ValuesIn(test::catchableTerminatingSignals()),
                         [](const auto& info) { return test::signalTestName(info.param); });

std::atomic<int> handled{0};
extern "C" void countSignal(int) {
    handled.fetch_add(1);
}

TEST_F(RemovedOnSignalTest, AHandlerTheProcessAlreadyHasIsKept) {
    std::ofstream(dir_ / "partial.png") << "partial";
    // A profiler's SIGPROF, or a program's own SIGUSR1: the signal is theirs, not an end.
    for (const int signal : {SIGUSR1, SIGPROF}) {
        const int status = inChildRaising(SIGKILL, [&] {
            struct sigaction action {};
            action.sa_handler = countSignal;
            ::sigaction(signal, &action, nullptr);
            static RemovedOnSignal file((dir_ / "partial.png").string(), RemovedOnSignal::Kind::File);
            std::raise(signal);
            ::_exit(handled.load() == 1 ? 0 : 1);
        });
        EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << sigabbrev_np(signal) << ": status " << status;
        EXPECT_TRUE(fs::exists(dir_ / "partial.png")) << sigabbrev_np(signal);
    }
}

TEST_F(RemovedOnSignalTest, FaultsKeepTheActionTheyHad) {
    // A fault may come from corrupted memory, where the paths themselves cannot be trusted; a
    // debugger, a sanitizer or a core dump wants it untouched. What it leaves, the next run removes.
    // "Untouched" is the action before registering: the default, or a sanitizer's own handler.
    const int status = inChildRaising(SIGKILL, [&] {
        const int faults[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGSYS, SIGTRAP};
        struct sigaction before[std::size(faults)]{};
        for (std::size_t i = 0; i < std::size(faults); ++i) {
            ::sigaction(faults[i], nullptr, &before[i]);
        }
        static RemovedOnSignal file((dir_ / "partial.png").string(), RemovedOnSignal::Kind::File);
        for (std::size_t i = 0; i < std::size(faults); ++i) {
            struct sigaction after {};
            ::sigaction(faults[i], nullptr, &after);
            if (after.sa_handler != before[i].sa_handler || after.sa_flags != before[i].sa_flags) {
                ::_exit(faults[i]);
            }
        }
        ::_exit(0);
    });
    EXPECT_TRUE(WIFEXITED(status)) << "status " << status;
    EXPECT_EQ(WEXITSTATUS(status), 0) << "registering changed the action of " << sigabbrev_np(WEXITSTATUS(status));
}

}  // namespace
}  // namespace hexray
