#pragma once
// Compiled kernels on disk, so a scene structure seen before skips glslang: one file per kernel
// under $XDG_CACHE_HOME/hexray (or ~/.cache/hexray), named by the SHA-256 of its key (the caller's:
// see KernelCompiler), each holding its key and SPIR-V under a SHA-256 checksum
// (kernel_cache_entry.h). Nothing read back is trusted: a file is opened without following links or
// blocking and read only if it is a regular file of bounded size (untrusted_file.h), and used only
// if its checksum, key and SPIR-V (validated by SPIRV-Tools) all hold. Anything else at an entry's
// name is a miss, reported on stderr in one line naming the file and the reason, and removed (never
// following a link), so the kernel is compiled and stored afresh.
//
// The directory is kept under a size bound (HEXRAY_KERNEL_CACHE_MAX_SIZE, default 128 MiB): a hit
// marks its file as used (its modification time), and after each store the least recently used
// entries go until the entries fit. Files are written to a temporary name and renamed, so
// concurrent processes only ever see whole files. A cache that cannot be read or written is
// ignored: the kernel is compiled instead. (Mesa's own disk cache then keeps the driver's compile
// of the SPIR-V.)

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace hexray::inline kernels {

// HEXRAY_KERNEL_CACHE_MAX_SIZE holds something other than a size.
class KernelCacheSettingError : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

class KernelCache {
public:
    static constexpr std::uint64_t kDefaultMaxBytes = std::uint64_t{128} << 20;

    // Where a problem with a file is told (one line, no newline); by default standard error.
    using Reporter = std::function<void(const std::string& line)>;
    static void reportOnStandardError(const std::string& line);

    // An empty directory, or a bound of 0, disables the cache.
    explicit KernelCache(std::filesystem::path directory, std::uint64_t maxBytes = configuredMaxBytes(),
                         Reporter report = reportOnStandardError);

    // $XDG_CACHE_HOME/hexray, else $HOME/.cache/hexray, else none.
    static std::filesystem::path defaultDirectory();
    // HEXRAY_KERNEL_CACHE_MAX_SIZE: bytes, or with a suffix K, M or G (KiB, MiB, GiB); 0 turns
    // the cache off. kDefaultMaxBytes when unset or empty. Throws KernelCacheSettingError.
    static std::uint64_t configuredMaxBytes();

    // The SPIR-V stored for `key`, checked; nothing on a miss (a bad file is reported and removed).
    std::optional<std::vector<std::uint32_t>> load(const std::string& key) const;
    // Stores `spirv` for `key`, then evicts down to the bound. Never throws.
    void store(const std::string& key, std::span<const std::uint32_t> spirv) const;
    // Removes the entry for `key`, reporting `reason`: the driver refused its SPIR-V.
    void discard(const std::string& key, const std::string& reason) const;

    struct Usage {
        std::uint64_t entries = 0;
        std::uint64_t bytes = 0;
    };
    Usage usage() const;
    // Removes every entry and temporary file (hexray's names only); returns what the entries were.
    Usage clear() const;

    // The file an entry for `key` is stored in.
    std::filesystem::path fileFor(const std::string& key) const { return directory_ / entryName(key); }
    const std::filesystem::path& directory() const { return directory_; }
    std::uint64_t maxBytes() const { return maxBytes_; }
    bool enabled() const { return !directory_.empty() && maxBytes_ > 0; }

private:
    std::string entryName(const std::string& key) const;
    void remove(const std::string& name, const std::string& reason) const;
    void evictDownToBound(const std::string& keep) const;

    std::filesystem::path directory_;
    std::uint64_t maxBytes_;
    Reporter report_;
};

}  // namespace hexray::kernels
