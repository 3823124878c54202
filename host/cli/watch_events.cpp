#include "cli/watch_events.h"

#include <poll.h>
#include <signal.h>
#include <sys/eventfd.h>
#include <sys/inotify.h>
#include <sys/signalfd.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <climits>
#include <cstdint>
#include <cstring>
#include <filesystem>

#include "scene/scene_loader.h"
#include "util/printable.h"

namespace hexray::cli {
namespace {

sigset_t stopSignals() {
    sigset_t signals;
    sigemptyset(&signals);
    sigaddset(&signals, SIGINT);
    sigaddset(&signals, SIGTERM);
    return signals;
}

[[noreturn]] void cannotWatch(const std::string& scenePath, const char* what) {
    throw SceneError(printable(scenePath) + ": cannot watch it (" + what + ": " + std::strerror(errno) + ")");
}

int millisecondsUntil(std::optional<std::chrono::steady_clock::time_point> deadline) {
    if (!deadline) {
        return -1;
    }
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(*deadline - std::chrono::steady_clock::now());
    return int(std::clamp<std::int64_t>(left.count(), 0, INT_MAX));
}

}  // namespace

WatchEvents::WatchEvents(const std::string& scenePath) {
    const std::filesystem::path path(scenePath);
    fileName_ = path.filename().string();
    const std::string directory = path.has_parent_path() ? path.parent_path().string() : ".";
    const sigset_t signals = stopSignals();
    pthread_sigmask(SIG_BLOCK, &signals, nullptr);
    signals_ = signalfd(-1, &signals, SFD_CLOEXEC | SFD_NONBLOCK);
    wakeUps_ = eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);
    inotify_ = inotify_init1(IN_CLOEXEC | IN_NONBLOCK);
    if (signals_ < 0 || wakeUps_ < 0 || inotify_ < 0) {
        cannotWatch(scenePath, "setting up inotify");
    }
    // A save in place ends with IN_CLOSE_WRITE, a save by rename with IN_MOVED_TO.
    if (inotify_add_watch(inotify_, directory.c_str(), IN_CLOSE_WRITE | IN_MOVED_TO) < 0) {
        cannotWatch(scenePath, "watching its directory");
    }
}

WatchEvents::~WatchEvents() {
    for (const int descriptor : {inotify_, signals_, wakeUps_}) {
        if (descriptor >= 0) {
            ::close(descriptor);
        }
    }
}

// Reads every queued inotify event; whether one was about the scene file.
bool WatchEvents::readSaves() {
    alignas(inotify_event) std::array<char, 16 * (sizeof(inotify_event) + NAME_MAX + 1)> buffer;
    bool saved = false;
    for (;;) {
        const ssize_t length = ::read(inotify_, buffer.data(), buffer.size());
        if (length <= 0) {
            return saved;
        }
        for (ssize_t offset = 0; offset < length;) {
            inotify_event event;
            std::memcpy(&event, buffer.data() + offset, sizeof event);
            const char* name = buffer.data() + offset + sizeof event;
            saved |= event.len > 0 && fileName_ == name;
            saved |= (event.mask & IN_Q_OVERFLOW) != 0;  // events lost: the scene may be among them
            offset += ssize_t(sizeof event + event.len);
        }
    }
}

WatchEvents::Event WatchEvents::next(std::optional<std::chrono::steady_clock::time_point> deadline) {
    for (;;) {
        std::array<pollfd, 3> descriptors{{{signals_, POLLIN, 0}, {wakeUps_, POLLIN, 0}, {inotify_, POLLIN, 0}}};
        const int ready = ::poll(descriptors.data(), descriptors.size(), millisecondsUntil(deadline));
        if (ready < 0 && errno == EINTR) {
            continue;
        }
        if (ready <= 0) {
            return Event::TimedOut;
        }
        if (descriptors[0].revents != 0) {
            return Event::Stop;
        }
        if (descriptors[1].revents != 0) {
            std::uint64_t count = 0;
            [[maybe_unused]] const ssize_t read = ::read(wakeUps_, &count, sizeof count);
            return Event::Woken;
        }
        if (readSaves()) {
            return Event::SceneSaved;
        }
    }
}

void WatchEvents::wake() const {
    const std::uint64_t one = 1;
    [[maybe_unused]] const ssize_t written = ::write(wakeUps_, &one, sizeof one);
}

}  // namespace hexray::cli
