#pragma once
// What is in a kernel cache directory, by hexray's names: entries `<hex>.spv` and the temporaries
// they are written as, `.<entry name>.XXXXXX`. Anything else there is not the cache's.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace hexray::inline kernels {

struct KernelCacheFile {
    std::string name;
    bool regular = false;                      // a regular file (not a link, directory, FIFO, ...)
    std::uint64_t bytes = 0;                   // regular files only
    std::filesystem::file_time_type lastUsed;  // its modification time
};

struct KernelCacheFiles {
    std::vector<KernelCacheFile> entries;
    std::vector<KernelCacheFile> temporaries;
};

// A directory that cannot be read lists nothing.
KernelCacheFiles listKernelCacheFiles(const std::filesystem::path& directory);

}  // namespace hexray::kernels
