#pragma once
// Compiled kernels on disk, so a scene structure seen before skips glslang: one file per kernel
// under $XDG_CACHE_HOME/hexray (or ~/.cache/hexray), named by a hash of the key (the compiler
// fingerprint and the kernel's source). Each file holds its key, which a load compares, so a hash
// collision or a corrupt file is a miss, never a wrong kernel. Files are written to a temporary
// name and renamed, so concurrent processes only ever see whole files. A cache that cannot be
// read or written is ignored: the kernel is compiled instead. (Mesa's own disk cache then keeps
// the driver's compile of the SPIR-V.)

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace hexray {

class KernelCache {
public:
    // An empty directory disables the cache.
    explicit KernelCache(std::filesystem::path directory);

    // $XDG_CACHE_HOME/hexray, else $HOME/.cache/hexray, else none.
    static std::filesystem::path defaultDirectory();

    std::optional<std::vector<std::uint32_t>> load(const std::string& key) const;
    void store(const std::string& key, std::span<const std::uint32_t> spirv) const;  // never throws

    const std::filesystem::path& directory() const { return directory_; }

private:
    std::filesystem::path fileFor(const std::string& key) const;
    std::filesystem::path directory_;
};

}  // namespace hexray
