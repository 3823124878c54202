#include "kernels/kernel_cache.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "kernels/kernel_cache_entry.h"
#include "kernels/kernel_cache_files.h"
#include "io/remove_without_following.h"
#include "io/untrusted_file.h"
#include "util/sha256.h"

namespace hexray::inline kernels {
namespace {

namespace fs = std::filesystem;

constexpr const char* kMaxSizeVariable = "HEXRAY_KERNEL_CACHE_MAX_SIZE";

// A temporary this old was left by a process that died while storing (a store takes milliseconds).
constexpr auto kAbandonedTemporaryAge = std::chrono::hours(1);

std::uint64_t parseSize(std::string_view text) {
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    const std::string_view suffix(end, text.data() + text.size() - end);
    const int shift = suffix.empty() ? 0 : suffix == "K" ? 10 : suffix == "M" ? 20 : suffix == "G" ? 30 : -1;
    if (error != std::errc() || end == text.data() || shift < 0 ||
        value > (std::numeric_limits<std::uint64_t>::max() >> shift)) {
        throw KernelCacheSettingError(std::string(kMaxSizeVariable) +
                                      ": must be a size in bytes, or with a suffix K, M or G (e.g. 128M; 0 turns "
                                      "the kernel cache off) (got '" +
                                      std::string(text) + "')");
    }
    return value << shift;
}

bool writeAll(int descriptor, const std::string& bytes) {
    std::size_t written = 0;
    while (written < bytes.size()) {
        const ssize_t count = ::write(descriptor, bytes.data() + written, bytes.size() - written);
        if (count <= 0) {
            return false;
        }
        written += std::size_t(count);
    }
    return true;
}

}  // namespace

void KernelCache::reportOnStandardError(const std::string& line) {
    std::fprintf(stderr, "%s\n", line.c_str());
}

KernelCache::KernelCache(std::filesystem::path directory, std::uint64_t maxBytes, Reporter report)
    : directory_(std::move(directory)), maxBytes_(maxBytes), report_(std::move(report)) {}

std::filesystem::path KernelCache::defaultDirectory() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) {
        return fs::path(xdg) / "hexray";
    }
    if (const char* home = std::getenv("HOME"); home && *home) {
        return fs::path(home) / ".cache" / "hexray";
    }
    return {};
}

std::uint64_t KernelCache::configuredMaxBytes() {
    const char* value = std::getenv(kMaxSizeVariable);
    return value && *value ? parseSize(value) : kDefaultMaxBytes;
}

std::string KernelCache::entryName(const std::string& key) const {
    return sha256Hex(key) + ".spv";
}

void KernelCache::remove(const std::string& name, const std::string& reason) const {
    const bool removed = removeWithoutFollowing(directory_, name);
    report_("hexray: note: kernel cache entry '" + (directory_ / name).string() + "' " +
            (removed ? "removed" : "ignored (it could not be removed)") + ": " + reason);
}

std::optional<std::vector<std::uint32_t>> KernelCache::load(const std::string& key) const {
    if (!enabled()) {
        return std::nullopt;
    }
    try {
        const std::string name = entryName(key);
        UntrustedFile file(directory_ / name, kMaxKernelCacheEntryBytes);
        if (file.absent()) {
            return std::nullopt;
        }
        const std::optional<std::string> bytes = file.read();
        KernelCacheEntry entry = bytes ? openKernelCacheEntry(*bytes, key) : KernelCacheEntry{{}, file.problem()};
        if (entry.problem.empty()) {
            file.touch();
            return std::move(entry.spirv);
        }
        if (!bytes || file.stillNamedBy(directory_ / name)) {  // not a good entry stored over it meanwhile
            remove(name, entry.problem);
        }
    } catch (const std::exception& error) {  // out of memory, libcrypto: no cache this time
        report_(std::string("hexray: note: kernel cache not read: ") + error.what());
    }
    return std::nullopt;
}

void KernelCache::store(const std::string& key, std::span<const std::uint32_t> spirv) const {
    if (!enabled()) {
        return;
    }
    try {
        const std::string bytes = sealKernelCacheEntry(key, spirv);
        if (bytes.size() > kMaxKernelCacheEntryBytes) {
            return;
        }
        std::error_code error;
        fs::create_directories(directory_, error);
        const std::string name = entryName(key);
        std::string temporary = (directory_ / ("." + name + ".XXXXXX")).string();
        const int descriptor = ::mkostemp(temporary.data(), O_CLOEXEC);
        if (descriptor < 0) {
            return;  // an unwritable cache is no cache
        }
        const bool written = writeAll(descriptor, bytes);
        const bool closed = ::close(descriptor) == 0;
        if (!written || !closed || std::rename(temporary.c_str(), (directory_ / name).c_str()) != 0) {
            ::unlink(temporary.c_str());
            return;
        }
        evictDownToBound(name);
    } catch (const std::exception&) {
        // Out of memory, libcrypto: the kernel is simply not cached.
    }
}

void KernelCache::discard(const std::string& key, const std::string& reason) const {
    if (enabled()) {
        remove(entryName(key), reason);
    }
}

void KernelCache::evictDownToBound(const std::string& keep) const {
    KernelCacheFiles files = listKernelCacheFiles(directory_);
    const auto abandoned = fs::file_time_type::clock::now() - kAbandonedTemporaryAge;
    for (const KernelCacheFile& temporary : files.temporaries) {
        if (temporary.lastUsed < abandoned) {
            removeWithoutFollowing(directory_, temporary.name);
        }
    }
    std::erase_if(files.entries, [](const KernelCacheFile& file) { return !file.regular; });
    std::uint64_t total = 0;
    for (const KernelCacheFile& entry : files.entries) {
        total += entry.bytes;
    }
    std::ranges::sort(files.entries, {}, &KernelCacheFile::lastUsed);
    for (const KernelCacheFile& entry : files.entries) {
        if (total <= maxBytes_) {
            break;
        }
        if (entry.name != keep && removeWithoutFollowing(directory_, entry.name)) {
            total -= entry.bytes;
        }
    }
}

KernelCache::Usage KernelCache::usage() const {
    Usage usage;
    for (const KernelCacheFile& entry : listKernelCacheFiles(directory_).entries) {
        usage.entries += entry.regular ? 1 : 0;
        usage.bytes += entry.bytes;
    }
    return usage;
}

KernelCache::Usage KernelCache::clear() const {
    Usage removed;
    const KernelCacheFiles files = listKernelCacheFiles(directory_);
    for (const KernelCacheFile& entry : files.entries) {
        if (removeWithoutFollowing(directory_, entry.name) && entry.regular) {
            ++removed.entries;
            removed.bytes += entry.bytes;
        }
    }
    for (const KernelCacheFile& temporary : files.temporaries) {
        removeWithoutFollowing(directory_, temporary.name);
    }
    return removed;
}

}  // namespace hexray::kernels
