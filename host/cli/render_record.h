#pragma once
// What `hexray render` did with each scene, kept as it renders, and the `--json` document made of
// it (docs/json-output.md, "render").

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "gpu/gpu_renderer.h"
#include "image/row_range.h"
#include "scene/scene.h"
#include "vulkan/vulkan_context.h"

namespace hexray::cli {

// A scene the GPU rendered: the plan's choices and the renderer's timings.
struct GpuSceneRecord {
    Precision precision = Precision::F32;  // never Auto
    std::string kernelName;
    bool generatedKernel = false;  // generated for the scene; else the prebuilt data-driven kernel
    std::size_t tileClasses = 0;   // culling: the kernels the image's tiles were split between (0: none)
    bool candidateLists = false;
    std::vector<std::string> warnings;
    double planMilliseconds = 0;
    GpuTiming timing;
};

// A scene the CPU reference rendered.
struct CpuSceneRecord {
    unsigned threads = 0;
    double renderMilliseconds = 0;
};

struct SceneRecord {
    std::string scenePath;
    std::string outputPath;              // empty when none was decided
    std::optional<ImageSettings> image;  // once the scene is loaded, with the command line's overrides
    std::optional<RowRange> rows;        // a strip's rows
    std::string fallbackReason;          // --backend auto: why the CPU rendered instead of the GPU
    std::optional<GpuSceneRecord> gpu;   // the backend that rendered the image: one or the other
    std::optional<CpuSceneRecord> cpu;
    std::optional<std::size_t> aovFiles;
    std::optional<double> loadMilliseconds;
    std::optional<double> writeMilliseconds;  // finishing the image file (its rows are written as they come)
    double totalMilliseconds = 0;
    int exitCode = kSuccess;
    std::vector<std::string> messages;  // the errors printed for this scene
};

// The document: what was asked, the device and Vulkan's start-up, and every scene's record.
nlohmann::json renderDocument(const RenderOptions& options, const std::vector<SceneRecord>& scenes,
                              const std::optional<DeviceInfo>& device, std::optional<double> startupMilliseconds);

}  // namespace hexray::cli
