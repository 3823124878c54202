#include "kernels/kernel_cache_files.h"

#include <sys/stat.h>

#include <chrono>
#include <string_view>
#include <system_error>

namespace hexray::inline kernels {
namespace {

namespace fs = std::filesystem;

bool endsWith(std::string_view text, std::string_view end) {
    return text.size() > end.size() && text.substr(text.size() - end.size()) == end;
}

fs::file_time_type modificationTime(const struct stat& status) {
    const auto sinceEpoch =
        std::chrono::seconds(status.st_mtim.tv_sec) + std::chrono::nanoseconds(status.st_mtim.tv_nsec);
    return fs::file_time_type::clock::from_sys(std::chrono::system_clock::time_point(
        std::chrono::duration_cast<std::chrono::system_clock::duration>(sinceEpoch)));
}

}  // namespace

KernelCacheFiles listKernelCacheFiles(const fs::path& directory) {
    KernelCacheFiles files;
    std::error_code error;
    for (auto entry = fs::directory_iterator(directory, error); !error && entry != fs::directory_iterator();
         entry.increment(error)) {
        KernelCacheFile file;
        file.name = entry->path().filename().string();
        const bool temporary = file.name.starts_with('.') && file.name.find(".spv.") != std::string::npos;
        if (!temporary && (file.name.starts_with('.') || !endsWith(file.name, ".spv"))) {
            continue;
        }
        struct stat status {};
        if (::lstat(entry->path().c_str(), &status) != 0) {
            continue;  // gone meanwhile
        }
        file.regular = S_ISREG(status.st_mode);
        file.bytes = file.regular ? std::uint64_t(status.st_size) : 0;
        file.lastUsed = modificationTime(status);
        (temporary ? files.temporaries : files.entries).push_back(std::move(file));
    }
    return files;
}

}  // namespace hexray::kernels
