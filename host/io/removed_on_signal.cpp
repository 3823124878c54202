#include "io/removed_on_signal.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

#include "io/temporary_names.h"

namespace hexray::inline io {
namespace {

// The handler may only make async-signal-safe calls, so the paths sit in fixed buffers that it
// reads without locking. Enough slots for compare's two AOV sets of 31 lights, with every file
// of each being written at once.
constexpr std::size_t kSlots = 256;
constexpr std::size_t kPathBytes = 4096;

struct Slot {
    std::atomic<bool> inUse{false};
    RemovedOnSignal::Kind kind = RemovedOnSignal::Kind::File;
    std::array<char, kPathBytes> path{};
};

std::array<Slot, kSlots> slots;
std::mutex slotsMutex;  // serialises registration, never taken by the handler

// Every catchable signal whose default action ends the process, but the faults (see the header);
// the real-time signals (SIGRTMIN..SIGRTMAX, not constants) are added where handlers are installed.
constexpr std::array kSignals = {SIGHUP,    SIGINT, SIGQUIT, SIGPIPE,   SIGALRM, SIGTERM, SIGUSR1, SIGUSR2,
                                 SIGSTKFLT, SIGIO,  SIGPROF, SIGVTALRM, SIGXCPU, SIGXFSZ, SIGPWR};

// Empties a directory of hexray's flat staging layout and removes it, with system calls only
// (opendir and readdir may allocate).
void removeDirectory(const char* path) {
    const int descriptor = ::open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (descriptor >= 0) {
        alignas(8) char buffer[4096];
        long bytes = 0;
        while ((bytes = ::syscall(SYS_getdents64, descriptor, buffer, sizeof buffer)) > 0) {
            for (long offset = 0; offset < bytes;) {
                // struct linux_dirent64: ino (8), off (8), reclen (2), type (1), name
                unsigned short length = 0;
                std::memcpy(&length, buffer + offset + 16, sizeof length);
                const char* name = buffer + offset + 19;
                if (std::strcmp(name, ".") != 0 && std::strcmp(name, "..") != 0) {
                    ::unlinkat(descriptor, name, 0);
                }
                offset += length;
            }
        }
        ::close(descriptor);
    }
    ::rmdir(path);
}

// Set by the handler: from then on nothing new is registered (see RemovedOnSignal's constructor).
std::atomic<bool> dying{false};

void removeRegistered() {
    for (const RemovedOnSignal::Kind kind : {RemovedOnSignal::Kind::File, RemovedOnSignal::Kind::Directory}) {
        for (Slot& slot : slots) {
            if (!slot.inUse.load(std::memory_order_acquire) || slot.kind != kind) {
                continue;
            }
            if (kind == RemovedOnSignal::Kind::File) {
                ::unlink(slot.path.data());
            } else {
                removeDirectory(slot.path.data());
            }
        }
    }
}

extern "C" void removeAndDie(int signal) {
    dying.store(true);
    // Other threads run on meanwhile: a few passes a millisecond apart also catch a temporary
    // that one of them registered but had not yet created at the first.
    constexpr int kPasses = 3;
    for (int pass = 0; pass < kPasses; ++pass) {
        removeRegistered();
        const timespec millisecond{0, 1000000};
        ::nanosleep(&millisecond, nullptr);
    }
    std::signal(signal, SIG_DFL);
    std::raise(signal);  // blocked until the handler returns, then ends the process
}

// Creates `path` (a file for writing, or a directory) and opens it; -1 with errno set on failure.
int createAndOpen(const char* path, RemovedOnSignal::Kind kind) {
    if (kind == RemovedOnSignal::Kind::File) {
        return ::open(path, O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    }
    if (::mkdir(path, 0700) != 0) {
        return -1;
    }
    const int descriptor = ::open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (descriptor < 0) {
        const int error = errno;
        ::rmdir(path);
        errno = error;
    }
    return descriptor;
}

// Only where the signal's action is the default: one the process ignores stays ignored, and one
// it handles (a profiler's, a library's) is not taken from it.
void installHandler(int signal) {
    struct sigaction previous {};
    if (::sigaction(signal, nullptr, &previous) != 0 || (previous.sa_flags & SA_SIGINFO) != 0 ||
        previous.sa_handler != SIG_DFL) {
        return;
    }
    struct sigaction action {};
    action.sa_handler = removeAndDie;
    sigfillset(&action.sa_mask);  // one handler at a time, whichever signals arrive
    ::sigaction(signal, &action, nullptr);
}

void installHandlers() {
    for (const int signal : kSignals) {
        installHandler(signal);
    }
    for (int signal = SIGRTMIN; signal <= SIGRTMAX; ++signal) {
        installHandler(signal);
    }
}

}  // namespace

RemovedOnSignal::RemovedOnSignal(const std::string& path, Kind kind) {
    static std::once_flag installed;
    std::call_once(installed, installHandlers);
    while (dying.load()) {
        ::pause();  // the handler is removing the temporaries and will end the process
    }
    if (path.size() >= kPathBytes) {
        return;  // still removed on an ordinary failure, only not on a signal
    }
    const std::lock_guard lock(slotsMutex);
    for (std::size_t i = 0; i < kSlots; ++i) {
        if (!slots[i].inUse.load()) {
            slots[i].kind = kind;
            std::memcpy(slots[i].path.data(), path.c_str(), path.size() + 1);
            slots[i].inUse.store(true, std::memory_order_release);
            slot_ = int(i);
            return;
        }
    }
}

RemovedOnSignal::~RemovedOnSignal() {
    if (slot_ >= 0) {
        slots[std::size_t(slot_)].inUse.store(false, std::memory_order_release);
    }
}

namespace {

// The test hook described in the header: read once per process.
std::optional<RemovedOnSignal::Kind> stopAtTemporaryKind() {
    static const std::optional<RemovedOnSignal::Kind> kind = []() -> std::optional<RemovedOnSignal::Kind> {
        const char* value = std::getenv("HEXRAY_TEST_STOP_AT_TEMPORARY");
        const std::string text = value ? value : "";
        if (text.empty())
            return std::nullopt;
        if (text == "file")
            return RemovedOnSignal::Kind::File;
        if (text == "directory")
            return RemovedOnSignal::Kind::Directory;
        throw std::invalid_argument("HEXRAY_TEST_STOP_AT_TEMPORARY: \"" + text + "\" is neither file nor directory");
    }();
    return kind;
}

}  // namespace

RegisteredTemporary createTemporary(const std::string& pattern, RemovedOnSignal::Kind kind) {
    constexpr int kAttempts = 100;
    for (int attempt = 0; attempt < kAttempts; ++attempt) {
        RegisteredTemporary temporary{randomName(pattern), -1, nullptr};
        // Registered first: a signal between the two steps finds the path registered. (Were the
        // name taken, a signal in that instant would remove another's file: with 62^6 names, a
        // risk far below any other.)
        temporary.removal = std::make_unique<RemovedOnSignal>(temporary.path, kind);
        temporary.descriptor = createAndOpen(temporary.path.c_str(), kind);
        if (temporary.descriptor >= 0) {
            if (stopAtTemporaryKind() == kind) {
                std::raise(SIGSTOP);
            }
            return temporary;
        }
        if (errno != EEXIST) {
            break;
        }
    }
    const int error = errno;
    RegisteredTemporary failed;
    errno = error;
    return failed;
}

}  // namespace hexray::io
