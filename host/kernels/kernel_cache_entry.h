#pragma once
// One kernel cache file's bytes (kernel_cache.h): "HXKERNL2", the SHA-256 of everything after
// it, then the key's length (8 bytes) and the key, the SPIR-V's word count (8 bytes) and its
// words, in the machine's byte order. A file is used only when its checksum matches, it holds
// exactly the key asked for and nothing after the SPIR-V, and the SPIR-V passes validation
// (spirv_validation.h): any flipped bit, a file spliced from two entries or another build's file
// is a miss, never a wrong kernel.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace hexray::inline kernels {

inline constexpr std::string_view kKernelCacheMagic = "HXKERNL2";
inline constexpr std::size_t kKernelCacheDigestOffset = kKernelCacheMagic.size();
inline constexpr std::size_t kKernelCacheBodyOffset = kKernelCacheDigestOffset + 32;  // after the SHA-256
// No entry is larger: a bigger file is refused before a byte of it is read.
inline constexpr std::uint64_t kMaxKernelCacheEntryBytes = std::uint64_t{16} << 20;

// The file's bytes for `key` and `spirv`.
std::string sealKernelCacheEntry(const std::string& key, std::span<const std::uint32_t> spirv);

// What a file holds for a key: its SPIR-V, or, when `problem` is not empty, why it cannot be used.
struct KernelCacheEntry {
    std::vector<std::uint32_t> spirv;
    std::string problem;
};
KernelCacheEntry openKernelCacheEntry(std::string_view bytes, const std::string& key);

}  // namespace hexray::kernels
