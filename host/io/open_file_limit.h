#pragma once
// The limit on files a process may have open (RLIMIT_NOFILE, `ulimit -n`), for a command that
// holds many open at once: the soft limit is often far below the hard one (1024 and 4096 or more).

#include <cstdint>

namespace hexray::inline io {

// Raises the soft limit to the hard one when it is below `needed`; returns the soft limit then in
// force (which may still be below `needed`).
std::uint64_t raiseOpenFileLimit(std::uint64_t needed);

}  // namespace hexray::io
