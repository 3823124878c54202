#include "gpu/kernel_compiler.h"

#include <algorithm>
#include <chrono>

#include "gpu/kernel_generator.h"
#include "gpu/shader_compiler.h"
#include "util/build_version.h"
#include "util/milliseconds_since.h"

namespace hexray {

std::string kernelCacheKey(const std::string& source) {
    return "hexray " + buildVersion() + "\n" +
           shaderCompilerFingerprint() + "\n" + source;
}

KernelCompiler::KernelCompiler(KernelCache cache) : cache_(std::move(cache)) {}

std::vector<std::uint32_t> KernelCompiler::compileAndStore(const std::string& source, KernelBuild& record) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::uint32_t> spirv = compileComputeShader(source, "generated kernel");
    record.compileMilliseconds = millisecondsSince(start);
    cache_.store(kernelCacheKey(source), spirv);
    return spirv;
}

std::span<const std::uint32_t> KernelCompiler::spirv(const Kernel& kernel, KernelBuild* build) {
    KernelBuild record;
    if (!kernel.code) {
        if (build) *build = record;
        return kernel.spirv;
    }
    const auto start = std::chrono::steady_clock::now();
    const std::string source = generateKernel(*kernel.code);
    record.generateMilliseconds = millisecondsSince(start);
    auto found = compiled_.find(source);
    if (found == compiled_.end()) {
        const auto lookup = std::chrono::steady_clock::now();
        std::optional<std::vector<std::uint32_t>> cached = cache_.load(kernelCacheKey(source));
        record.loadMilliseconds = millisecondsSince(lookup);
        record.fromDiskCache = cached.has_value();
        Compiled compiled{cached ? std::move(*cached) : compileAndStore(source, record), record.fromDiskCache};
        found = compiled_.emplace(source, std::move(compiled)).first;
    }
    if (build) *build = record;
    return found->second.spirv;
}

std::span<const std::uint32_t> KernelCompiler::recompile(const Kernel& kernel, const std::string& reason,
                                                         KernelBuild* build) {
    KernelBuild record;
    const auto start = std::chrono::steady_clock::now();
    const std::string source = generateKernel(*kernel.code);
    record.generateMilliseconds = millisecondsSince(start);
    cache_.discard(kernelCacheKey(source), reason);
    Compiled& compiled = compiled_[source];
    compiled = Compiled{compileAndStore(source, record), false};
    if (build) *build = record;
    return compiled.spirv;
}

bool KernelCompiler::holds(const std::uint32_t* spirv) const {
    return std::ranges::any_of(compiled_, [&](const auto& entry) { return entry.second.spirv.data() == spirv; });
}

bool KernelCompiler::fromDiskCache(const std::uint32_t* spirv) const {
    return std::ranges::any_of(compiled_, [&](const auto& entry) {
        return entry.second.spirv.data() == spirv && entry.second.fromDiskCache;
    });
}

}  // namespace hexray
