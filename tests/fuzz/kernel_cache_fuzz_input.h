#pragma once
// How the kernel cache fuzzer (kernel_cache_fuzzer.cpp) reads its input, shared with the unit test
// that checks its seeds (kernel_cache_seeds/). The first byte chooses how the rest is used: even,
// as the cache file's bytes; odd, with the file's checksum made to match whatever follows it, so
// that mutations reach what the checksum guards (the key, the lengths, SPIR-V validation).

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "kernels/kernel_cache_entry.h"
#include "util/sha256.h"

namespace hexray::test {

// The key every fuzzed load asks for, and the seeds were stored under.
inline const std::string kKernelCacheFuzzKey = "kernel cache fuzzer\nvoid main() {}";

inline std::string kernelCacheFileFromFuzzInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) {
        return {};
    }
    std::string file(reinterpret_cast<const char*>(data) + 1, size - 1);
    if (data[0] % 2 == 1 && file.size() >= kKernelCacheBodyOffset) {
        const Sha256Digest digest = sha256(std::string_view(file).substr(kKernelCacheBodyOffset));
        std::memcpy(file.data() + kKernelCacheDigestOffset, digest.data(), digest.size());
    }
    return file;
}

}  // namespace hexray::test
