#include "image/atomic_file.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <mutex>

#include <sys/stat.h>
#include <unistd.h>

#include "image/image_io.h"

namespace hexray {
namespace {

// Temporary files the SIGINT/SIGTERM handler removes before the process dies. The handler may
// only use async-signal-safe calls, so the paths sit in fixed buffers.
constexpr std::size_t kSlots = 8;
constexpr std::size_t kPathBytes = 4096;
std::array<std::array<char, kPathBytes>, kSlots> pendingPaths;
std::array<std::atomic<bool>, kSlots> pendingInUse;
std::mutex slotsMutex;

extern "C" void removePendingAndDie(int signal) {
    for (std::size_t i = 0; i < kSlots; ++i) {
        if (pendingInUse[i].load()) {
            ::unlink(pendingPaths[i].data());
        }
    }
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

int registerPending(const std::string& path) {
    static std::once_flag installed;
    std::call_once(installed, [] {
        for (const int signal : {SIGINT, SIGTERM}) {
            struct sigaction previous {};
            ::sigaction(signal, nullptr, &previous);
            if (previous.sa_handler != SIG_IGN) {  // an ignored signal (nohup, background job) stays ignored
                std::signal(signal, removePendingAndDie);
            }
        }
    });
    if (path.size() >= kPathBytes) {
        return -1;
    }
    const std::lock_guard lock(slotsMutex);
    for (std::size_t i = 0; i < kSlots; ++i) {
        if (!pendingInUse[i].load()) {
            std::memcpy(pendingPaths[i].data(), path.c_str(), path.size() + 1);
            pendingInUse[i].store(true);
            return int(i);
        }
    }
    return -1;  // more files at once than slots: still removed on failure, not on a signal
}

void unregisterPending(int slot) {
    if (slot >= 0) {
        pendingInUse[std::size_t(slot)].store(false);
    }
}

std::string systemError() {
    return std::strerror(errno);
}

}  // namespace

AtomicFile::AtomicFile(const std::filesystem::path& target) : target_(target) {
    const std::filesystem::path directory = target.has_parent_path() ? target.parent_path() : ".";
    // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) about "." + string + "...".
    std::string name = ".";
    name += target.filename().string();
    name += ".XXXXXX";
    temporaryPath_ = (directory / name).string();
    const int fd = ::mkstemp(temporaryPath_.data());
    if (fd < 0) {
        temporaryPath_.clear();  // nothing was created
        fail("cannot create output file", systemError());
    }
    signalSlot_ = registerPending(temporaryPath_);
    // mkstemp makes the file 0600; give it what a new file would get under the umask.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
    file_ = ::fdopen(fd, "wb");
    if (!file_) {
        // A throwing constructor runs no destructor: clean up here.
        const std::string why = systemError();
        ::close(fd);
        ::unlink(temporaryPath_.c_str());
        unregisterPending(signalSlot_);
        fail("cannot create output file", why);
    }
}

AtomicFile::~AtomicFile() {
    if (file_) {
        std::fclose(file_);
    }
    if (!temporaryPath_.empty()) {
        ::unlink(temporaryPath_.c_str());
    }
    unregisterPending(signalSlot_);
}

void AtomicFile::commit() {
    std::FILE* file = file_;
    file_ = nullptr;
    const bool written = std::fflush(file) == 0 && ::fsync(::fileno(file)) == 0;
    const std::string why = systemError();
    if (std::fclose(file) != 0 || !written) {
        fail("cannot write", written ? systemError() : why);
    }
    if (::rename(temporaryPath_.c_str(), target_.c_str()) != 0) {
        fail("cannot write", systemError());
    }
    temporaryPath_.clear();
}

void AtomicFile::fail(const std::string& what, const std::string& why) const {
    throw ImageIoError(target_.string() + ": " + what + ": " + why);
}

}  // namespace hexray
