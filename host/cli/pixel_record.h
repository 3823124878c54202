#pragma once
// What `hexray pixel` found, kept for its `--json` document (docs/json-output.md, "pixel"): each
// backend's account of the sample as fields rather than the table's text.

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cpu/cpu_explain.h"
#include "gpu/pixel_trace.h"
#include "scene/scene.h"
#include "vulkan/vulkan_context.h"

namespace hexray::cli {

// "sphere" or "plane".
const char* geometryName(const Geometry& geometry);
// "constant", "lambert" or "checker", as the scene file names them.
const char* shaderTypeName(const Shader& shader);

// Where the two backends disagree: the labels of the table's rows marked "<- differs".
struct PixelComparison {
    std::vector<std::string> differingRows;
    bool classDiffers = false;
};

struct PixelRecord {
    std::optional<Scene> scene;  // once loaded, with the command line's overrides
    std::optional<GpuPixelTrace> shader;
    std::optional<DeviceInfo> device;
    std::optional<double> startupMilliseconds;
    std::optional<double> gpuTraceMilliseconds;
    std::optional<CpuPixelExplanation> reference;
    std::optional<double> margin;  // the CPU reference's decision margin (cpu_margins.h)
    std::optional<double> cpuExplainMilliseconds;
    std::optional<PixelComparison> comparison;  // when both backends ran
};

nlohmann::json pixelDocument(const PixelOptions& options, const PixelRecord& record);

}  // namespace hexray::cli
