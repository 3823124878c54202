#include "kernels/kernel_compiler.h"

#include <chrono>

#include "kernels/kernel_generator.h"
#include "kernels/shader_compiler.h"
#include "util/build_version.h"
#include "util/milliseconds_since.h"

namespace hexray::inline kernels {

std::string kernelCacheKey(const std::string& source) {
    return "hexray " + buildVersion() + "\n" + shaderCompilerFingerprint() + "\n" + source;
}

KernelCompiler::KernelCompiler(KernelCache cache, std::size_t keptKernels)
    : cache_(std::move(cache)), compiled_(keptKernels) {}

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
        if (build)
            *build = record;
        return kernel.spirv;
    }
    const auto start = std::chrono::steady_clock::now();
    const std::string source = generateKernel(*kernel.code);
    record.generateMilliseconds = millisecondsSince(start);
    Compiled* found = compiled_.find(source);
    if (!found) {
        const auto lookup = std::chrono::steady_clock::now();
        std::optional<std::vector<std::uint32_t>> cached = cache_.load(kernelCacheKey(source));
        record.loadMilliseconds = millisecondsSince(lookup);
        record.fromDiskCache = cached.has_value();
        Compiled compiled{cached ? std::move(*cached) : compileAndStore(source, record), record.fromDiskCache,
                          ++lastId_};
        found = &compiled_.insert(source, std::move(compiled));
    }
    record.generatedId = found->id;
    if (build)
        *build = record;
    return found->spirv;
}

std::span<const std::uint32_t> KernelCompiler::recompile(const Kernel& kernel, const std::string& reason,
                                                         KernelBuild* build) {
    KernelBuild record;
    const auto start = std::chrono::steady_clock::now();
    const std::string source = generateKernel(*kernel.code);
    record.generateMilliseconds = millisecondsSince(start);
    cache_.discard(kernelCacheKey(source), reason);
    // A new id: what was made from the refused SPIR-V is never taken for this.
    Compiled compiled{compileAndStore(source, record), false, ++lastId_};
    Compiled* held = compiled_.find(source);
    held = held ? &(*held = std::move(compiled)) : &compiled_.insert(source, std::move(compiled));
    record.generatedId = held->id;
    if (build)
        *build = record;
    return held->spirv;
}

bool KernelCompiler::holds(const std::uint32_t* spirv) const {
    bool found = false;
    compiled_.forEach([&](const Compiled& compiled) { found = found || compiled.spirv.data() == spirv; });
    return found;
}

bool KernelCompiler::fromDiskCache(const std::uint32_t* spirv) const {
    bool found = false;
    compiled_.forEach(
        [&](const Compiled& compiled) { found = found || (compiled.spirv.data() == spirv && compiled.fromDiskCache); });
    return found;
}

}  // namespace hexray::kernels
