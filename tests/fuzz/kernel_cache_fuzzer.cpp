// libFuzzer target for the kernel cache's reader (host/kernels/kernel_cache.h): whatever bytes lie at
// an entry's name, a load gives either nothing, with the file removed and one report naming it, or
// exactly the SPIR-V whose stored entry is those very bytes, valid, with the file kept. Anything
// else (an exception, a crash, a leak, a sanitizer report, a broken invariant) traps. The input's
// first byte says how the rest becomes the file (kernel_cache_fuzz_input.h).

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "fuzz/kernel_cache_fuzz_input.h"
#include "kernels/kernel_cache.h"
#include "kernels/spirv_validation.h"

namespace {

namespace fs = std::filesystem;

[[noreturn]] void failWith(const char* what, const std::string& detail) {
    std::fprintf(stderr, "kernel_cache_fuzzer: %s: %s\n", what, detail.c_str());
    __builtin_trap();
}

// This process's directory: empty after each input, removed when libFuzzer exits.
const fs::path& scratchDirectory() {
    static const fs::path directory = [] {
        std::string pattern = (fs::temp_directory_path() / "kernel-cache-fuzzer-XXXXXX").string();
        if (!::mkdtemp(pattern.data())) {
            failWith("cannot create a directory", pattern);
        }
        return fs::path(pattern);
    }();
    return directory;
}

void removeScratchDirectory() {
    std::error_code ignored;
    fs::remove_all(scratchDirectory(), ignored);
}

void checkLoad(const std::string& file) {
    using namespace hexray;
    std::vector<std::string> reports;
    const KernelCache cache(scratchDirectory(), KernelCache::kDefaultMaxBytes,
                            [&](const std::string& line) { reports.push_back(line); });
    const fs::path path = cache.fileFor(test::kKernelCacheFuzzKey);
    std::ofstream(path, std::ios::binary | std::ios::trunc) << file;
    const auto loaded = cache.load(test::kKernelCacheFuzzKey);
    std::error_code error;
    const bool kept = fs::exists(fs::symlink_status(path, error));
    if (loaded) {
        if (sealKernelCacheEntry(test::kKernelCacheFuzzKey, *loaded) != file) {
            failWith("loaded SPIR-V that is not exactly what the file holds", std::to_string(file.size()) + " bytes");
        }
        if (const auto problem = spirvValidationProblem(*loaded)) {
            failWith("loaded SPIR-V that fails validation", *problem);
        }
        if (!kept || !reports.empty()) {
            failWith("a hit removed or reported its file", reports.empty() ? "removed" : reports.front());
        }
        fs::remove(path, error);
    } else if (kept || reports.size() != 1 || reports.front().find(path.string()) == std::string::npos) {
        failWith("a miss must remove its file and report it once, by name",
                 reports.empty() ? "no report" : reports.front());
    }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    scratchDirectory();
    std::atexit(removeScratchDirectory);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        checkLoad(hexray::test::kernelCacheFileFromFuzzInput(data, size));
    } catch (const std::exception& error) {
        failWith("exception", error.what());
    } catch (...) {
        failWith("exception", "(not a std::exception)");
    }
    return 0;
}
