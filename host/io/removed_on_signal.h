#pragma once
// A temporary file or directory that is removed if a signal that would end the process arrives
// while this object lives: every catchable one whose default action is to terminate (SIGHUP,
// SIGINT, SIGQUIT, SIGPIPE, SIGALRM, SIGTERM, SIGUSR1, SIGUSR2, SIGSTKFLT, SIGIO, SIGPROF,
// SIGVTALRM, SIGXCPU, SIGXFSZ, SIGPWR and the real-time signals), sent by a person, a scheduler,
// a timer or a resource limit. The process then dies of that signal as it would have. A signal
// the process ignores (nohup, a background job) stays ignored, and one it already handles (a
// profiler's SIGPROF) keeps its handler.
// Faults the program raises on itself (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGSYS, SIGTRAP)
// keep their default action: they may come from corrupted memory, where the registered paths
// cannot be trusted to name only temporaries, and a debugger, a sanitizer or a core dump wants
// them untouched. What they leave, like what SIGKILL leaves, the next run removes
// (stale_temporaries.h).
// Destroying the object only unregisters the path: the owner removes or renames it in the
// ordinary way.

#include <memory>
#include <string>

namespace hexray::inline io {

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
// Test hook: with HEXRAY_TEST_STOP_AT_TEMPORARY=file (or =directory) the process stops itself
// (SIGSTOP) once such a temporary exists, so a test can signal it at that point whatever the
// machine's speed; any other non-empty value throws std::invalid_argument.
RegisteredTemporary createTemporary(const std::string& pattern, RemovedOnSignal::Kind kind);

}  // namespace hexray::io
