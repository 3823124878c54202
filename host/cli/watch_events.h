#pragma once
// What `hexray watch` waits for: the scene file saved (inotify on its directory, since editors save
// by writing another file and renaming it over the scene), SIGINT or SIGTERM (read from a signalfd,
// so that a signal never interrupts an image half written), and a wake-up from its background
// thread (an eventfd).

#include <chrono>
#include <optional>
#include <string>

namespace hexray::cli {

class WatchEvents {
public:
    enum class Event { SceneSaved, Stop, Woken, TimedOut };

    // Blocks SIGINT and SIGTERM in this thread, and so in every thread started after it (Vulkan's,
    // the driver's): construct it before them. Throws OutputError when the directory of `scenePath`
    // cannot be watched.
    explicit WatchEvents(const std::string& scenePath);
    ~WatchEvents();
    WatchEvents(const WatchEvents&) = delete;
    WatchEvents& operator=(const WatchEvents&) = delete;

    // The next event, waiting at most until `deadline` (none: for ever). Every save already
    // queued is read at once, so a burst of them is one SceneSaved.
    Event next(std::optional<std::chrono::steady_clock::time_point> deadline);

    // Makes next() return Woken; callable from any thread.
    void wake() const;

private:
    bool readSaves();
    std::string fileName_;
    int inotify_ = -1;
    int signals_ = -1;
    int wakeUps_ = -1;
};

}  // namespace hexray::cli
