// `hexray cache`: where the kernel cache is, what it holds and its bound; `--clear` empties it.

#include <cstdio>
#include <string>

#include "cli/command_support.h"
#include "kernels/kernel_cache.h"

namespace hexray::cli {
namespace {

std::string mebibytes(std::uint64_t bytes) {
    char text[64];
    if (bytes % (std::uint64_t{1} << 20) == 0) {
        std::snprintf(text, sizeof text, "%llu MiB", static_cast<unsigned long long>(bytes >> 20));
    } else {
        std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / double(1 << 20));
    }
    return text;
}

std::string describe(const KernelCache::Usage& usage) {
    return std::to_string(usage.entries) + (usage.entries == 1 ? " entry, " : " entries, ") + mebibytes(usage.bytes);
}

}  // namespace

int runCache(const CacheOptions& options) {
    return guarded([&] {
        const KernelCache cache(KernelCache::defaultDirectory());
        if (cache.directory().empty()) {
            std::printf("kernel cache: none (neither XDG_CACHE_HOME nor HOME is set)\n");
            return int(kSuccess);
        }
        std::printf("kernel cache: %s\n", cache.directory().c_str());
        if (options.clear) {
            std::printf("removed %s\n", describe(cache.clear()).c_str());
        } else if (!cache.enabled()) {
            std::printf("%s; off (HEXRAY_KERNEL_CACHE_MAX_SIZE=0)\n", describe(cache.usage()).c_str());
        } else {
            std::printf("%s of at most %s (HEXRAY_KERNEL_CACHE_MAX_SIZE sets the bound)\n",
                        describe(cache.usage()).c_str(), mebibytes(cache.maxBytes()).c_str());
        }
        return int(kSuccess);
    });
}

}  // namespace hexray::cli
