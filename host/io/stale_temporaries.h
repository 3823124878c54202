#pragma once
// Temporaries that a killed process (SIGKILL, a power cut) left behind. A live run holds an
// advisory lock on each of its temporaries, which the kernel drops however the process ends;
// a temporary that is unlocked and older than this run's start is stale.

#include <filesystem>

namespace hexray::inline io {

// When this process started (when the program was loaded).
std::filesystem::file_time_type runStart();

// Marks the open file or directory `descriptor` as a live run's temporary (an flock the kernel
// releases when the process ends, however it ends).
void holdAsLive(int descriptor);

// Removes, from `directory` only, hexray's own temporaries (named as in temporary_names.h) that
// are older than `before` and no live run holds. Anything else is left alone; failures are
// ignored (a temporary that cannot be removed does no harm).
void removeStaleTemporaries(const std::filesystem::path& directory,
                            std::filesystem::file_time_type before = runStart());

}  // namespace hexray::io
