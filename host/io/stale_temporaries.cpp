#include "io/stale_temporaries.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <string>
#include <system_error>

#include "io/temporary_names.h"

namespace hexray::inline io {
namespace {

namespace fs = std::filesystem;

// Set while the program loads, before main().
const fs::file_time_type kRunStart = fs::file_time_type::clock::now();

bool startsWith(const std::string& name, std::string_view prefix) {
    return name.size() > prefix.size() && name.compare(0, prefix.size(), prefix) == 0;
}

// Whether `entry` is one of hexray's temporaries, by its name and type.
bool isHexrayTemporary(const fs::directory_entry& entry) {
    std::error_code error;
    const std::string name = entry.path().filename().string();
    if (startsWith(name, kPartialFilePrefix)) {
        return entry.is_regular_file(error) && !entry.is_symlink(error);
    }
    return (startsWith(name, kAovStagingPrefix) || startsWith(name, kReportStagingPrefix)) &&
           entry.is_directory(error) && !entry.is_symlink(error);
}

// Removes `path` if no live run holds it; the lock is held while it goes.
void removeUnlessHeld(const fs::path& path, bool directory) {
    const int descriptor = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC | (directory ? O_DIRECTORY : 0));
    if (descriptor < 0) {
        return;
    }
    if (::flock(descriptor, LOCK_EX | LOCK_NB) == 0) {
        std::error_code ignored;
        fs::remove_all(path, ignored);
    }
    ::close(descriptor);
}

}  // namespace

fs::file_time_type runStart() {
    return kRunStart;
}

void holdAsLive(int descriptor) {
    ::flock(descriptor, LOCK_EX | LOCK_NB);  // a fresh temporary: nobody else can hold it
}

void removeStaleTemporaries(const fs::path& directory, fs::file_time_type before) {
    std::error_code error;
    for (auto entry = fs::directory_iterator(directory, error); !error && entry != fs::directory_iterator();
         entry.increment(error)) {
        std::error_code timeError;
        if (isHexrayTemporary(*entry) && entry->last_write_time(timeError) < before && !timeError) {
            removeUnlessHeld(entry->path(), entry->is_directory(timeError));
        }
    }
}

}  // namespace hexray::io
