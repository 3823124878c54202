#pragma once
// Turns a plan's Kernel into SPIR-V: a generated kernel is written (kernel_generator.h), looked
// up in the disk cache (kernel_cache.h) and compiled only when missing; the most recently used
// are kept in memory (kept_kernels.h); a prebuilt one is used as it is.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernels/kernel_cache.h"
#include "kernels/kept_kernels.h"
#include "kernels/kernel.h"
#include "util/lru_map.h"

namespace hexray::inline kernels {

// What getting a kernel's SPIR-V took, for `render`'s report.
struct KernelBuild {
    double generateMilliseconds = 0;  // writing the GLSL
    double compileMilliseconds = 0;   // glslang (0 when the disk cache or this process had it)
    double loadMilliseconds = 0;      // looking in the disk cache: reading and checking a file
    bool fromDiskCache = false;
    // Which generated kernel's SPIR-V this is: the same number while this compiler keeps it, never
    // reused for another (0 for a prebuilt kernel), so that what is made from it can be keyed by it.
    std::uint64_t generatedId = 0;
};

// The disk cache's key for a generated kernel's source: the source, and everything else that
// decides its SPIR-V: glslang and the shader library (shaderCompilerFingerprint, with the SPIR-V
// target) and this build of hexray (its version and git revision). Not the device or driver:
// SPIR-V is the same for every device, and a driver that refuses it is handled where the
// pipeline is made (KernelCompiler::recompile).
std::string kernelCacheKey(const std::string& source);

class KernelCompiler {
public:
    explicit KernelCompiler(KernelCache cache = KernelCache(KernelCache::defaultDirectory()),
                            std::size_t keptKernels = kKeptGeneratedKernels);

    // A generated kernel's stays valid until the next call (which may drop it), a prebuilt one's as
    // long as its SPIR-V lives.
    std::span<const std::uint32_t> spirv(const Kernel& kernel, KernelBuild* build = nullptr);

    // Whether `spirv` is a generated kernel's, held here.
    bool holds(const std::uint32_t* spirv) const;
    // Whether `spirv` is a generated kernel's that came from the disk cache.
    bool fromDiskCache(const std::uint32_t* spirv) const;
    // The driver refused `kernel`'s SPIR-V from the disk cache for `reason`: the entry is removed
    // (and reported), and the kernel compiled afresh with glslang and stored again.
    std::span<const std::uint32_t> recompile(const Kernel& kernel, const std::string& reason,
                                             KernelBuild* build = nullptr);
    // Drops every generated kernel's SPIR-V (the disk cache keeps them).
    void forgetGenerated() { compiled_.clear(); }
    // How many generated kernels' SPIR-V are held.
    std::size_t keptKernels() const { return compiled_.size(); }

private:
    struct Compiled {
        std::vector<std::uint32_t> spirv;
        bool fromDiskCache = false;
        std::uint64_t id = 0;
    };
    std::vector<std::uint32_t> compileAndStore(const std::string& source, KernelBuild& record);

    KernelCache cache_;
    LruMap<std::string, Compiled> compiled_;  // by generated source
    std::uint64_t lastId_ = 0;
};

}  // namespace hexray::kernels
