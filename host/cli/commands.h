#pragma once
// hexray's subcommands. Each returns the process exit code (see ExitCode).

#include <cstdint>
#include <optional>
#include <string>

#include "compare/compare.h"

namespace hexray::cli {

enum ExitCode : int {
    kSuccess = 0,
    kToleranceExceeded = 1,  // compare: the renders differ by more than allowed
    kBadInput = 2,           // scene file or command line
    kVulkanUnavailable = 3,  // no driver or device, or a Vulkan call failed
    kValidationFailed = 4,   // --validate and the validation layer reported something
    kOutputFailed = 5,       // the image could not be written
};

enum class Backend { Gpu, Cpu };

struct SceneOptions {
    std::string scenePath;
    std::optional<std::int64_t> width;
    std::optional<std::int64_t> height;
};

struct VulkanOptions {
    std::string device;  // index or part of a name; empty = best available
    bool validate = false;
};

struct RenderOptions {
    SceneOptions scene;
    VulkanOptions vulkan;
    Backend backend = Backend::Gpu;
    std::string outputPath;  // empty: <scene name>.png in the current directory
    unsigned threads = 0;    // CPU backend; 0 = all cores
};

struct CompareOptions {
    SceneOptions scene;
    VulkanOptions vulkan;
    Tolerance tolerance;
    std::string diffPath;  // empty: no heat map
    unsigned threads = 0;
};

int runRender(const RenderOptions& options);
int runCompare(const CompareOptions& options);
int runDevices(const VulkanOptions& options);

}  // namespace hexray::cli
