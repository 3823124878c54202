#pragma once
// Turns a plan's Kernel into SPIR-V: a generated kernel is written (kernel_generator.h), looked
// up in the disk cache (kernel_cache.h) and compiled only when missing, at most once per
// process for each source; a prebuilt one is used as it is.

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "gpu/kernel_cache.h"
#include "gpu/render_plan.h"

namespace hexray {

// What getting a kernel's SPIR-V took, for `render`'s report.
struct KernelBuild {
    double generateMilliseconds = 0;  // writing the GLSL
    double compileMilliseconds = 0;   // glslang (0 when the disk cache or this process had it)
    bool fromDiskCache = false;
};

class KernelCompiler {
public:
    explicit KernelCompiler(KernelCache cache = KernelCache(KernelCache::defaultDirectory()));

    // Valid as long as this compiler (or, for a prebuilt kernel, its SPIR-V) lives, until forgetGenerated.
    std::span<const std::uint32_t> spirv(const Kernel& kernel, KernelBuild* build = nullptr);

    // Whether `spirv` is a generated kernel's, held here.
    bool holds(const std::uint32_t* spirv) const;
    // Drops every generated kernel's SPIR-V (the disk cache keeps them).
    void forgetGenerated() { compiled_.clear(); }

private:
    KernelCache cache_;
    std::map<std::string, std::vector<std::uint32_t>> compiled_;  // by generated source
};

}  // namespace hexray
