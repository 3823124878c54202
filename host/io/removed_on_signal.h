#pragma once
// A temporary file or directory that is removed if a catchable signal that ends the process
// (SIGHUP, SIGINT, SIGQUIT, SIGPIPE, SIGTERM, SIGUSR1, SIGUSR2) arrives while this object lives.
// The process then dies of that signal as it would have. A signal the process ignores (nohup, a
// background job) stays ignored. Destroying the object only unregisters the path: the owner
// removes or renames it in the ordinary way.

#include <memory>
#include <string>

namespace hexray {

class RemovedOnSignal {
public:
    enum class Kind { File, Directory };  // a directory is emptied (one level) and removed

    RemovedOnSignal(const std::string& path, Kind kind);
    ~RemovedOnSignal();
    RemovedOnSignal(const RemovedOnSignal&) = delete;
    RemovedOnSignal& operator=(const RemovedOnSignal&) = delete;

private:
    int slot_ = -1;  // -1: not registered (no free slot, or a path too long for one)
};

// A new temporary file or directory, registered for removal on signals before it exists, so
// that no signal finds it unregistered.
struct RegisteredTemporary {
    std::string path;
    int descriptor = -1;  // open for writing (a file) or reading (a directory); -1 on failure, errno set
    std::unique_ptr<RemovedOnSignal> removal;
};

// Creates a file (mode 0600) or directory (0700) named by `pattern`, whose trailing "XXXXXX" is
// randomised (see temporary_names.h), retrying while the name is taken.
RegisteredTemporary createTemporary(const std::string& pattern, RemovedOnSignal::Kind kind);

}  // namespace hexray
