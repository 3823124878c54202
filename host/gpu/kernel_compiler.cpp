#include "gpu/kernel_compiler.h"

#include <algorithm>
#include <chrono>

#include "gpu/kernel_generator.h"
#include "gpu/shader_compiler.h"
#include "util/milliseconds_since.h"

namespace hexray {

KernelCompiler::KernelCompiler(KernelCache cache) : cache_(std::move(cache)) {}

std::span<const std::uint32_t> KernelCompiler::spirv(const Kernel& kernel, KernelBuild* build) {
    KernelBuild record;
    if (!kernel.code) {
        if (build) *build = record;
        return kernel.spirv;
    }
    auto start = std::chrono::steady_clock::now();
    const std::string source = generateKernel(*kernel.code);
    record.generateMilliseconds = millisecondsSince(start);
    auto found = compiled_.find(source);
    if (found == compiled_.end()) {
        const std::string key = shaderCompilerFingerprint() + "\n" + source;
        std::optional<std::vector<std::uint32_t>> cached = cache_.load(key);
        record.fromDiskCache = cached.has_value();
        if (!cached) {
            start = std::chrono::steady_clock::now();
            cached = compileComputeShader(source, "generated kernel");
            record.compileMilliseconds = millisecondsSince(start);
            cache_.store(key, *cached);
        }
        found = compiled_.emplace(source, std::move(*cached)).first;
    }
    if (build) *build = record;
    return found->second;
}

bool KernelCompiler::holds(const std::uint32_t* spirv) const {
    return std::ranges::any_of(compiled_, [&](const auto& entry) { return entry.second.data() == spirv; });
}

}  // namespace hexray
