#pragma once
// The summary line a rendered image gets ("wrote demo.png (800x600) — gpu f32 (...): render ...;
// kernel ...; 312.4 ms in all (...)"), shared by `render` and `watch`.

#include <optional>
#include <string>

#include "cli/render_record.h"
#include "gpu/gpu_renderer.h"
#include "gpu/render_plan.h"

namespace hexray::cli {

// "generated for the scene, written in 0.12 ms, glslang 9.8 ms", or a prebuilt kernel's name.
std::string describeKernel(const RenderPlan& plan, const KernelBuild& build);

// "gpu f32 (llvmpipe): render 20.1 ms; kernel ...; first dispatch 84.7 ms incl. the driver's compile".
// `tier`, when not empty, names the kernel's tier before it ("kernel data-driven: ...").
std::string describeGpuRender(const RenderPlan& plan, const GpuRenderResult& result, const std::string& device,
                              const std::string& tier = "");

// What the GPU path did, for the record (and the --json document).
GpuSceneRecord gpuSceneRecord(const RenderPlan& plan, const GpuRenderResult& result, double planMilliseconds);

// "; 312.4 ms in all (start-up 150.2, load 1.9, kernel 84.7, render 20.1, write 9.8, other 45.7)":
// where the scene's wall time went. `startup`: Vulkan's, when this scene started it.
std::string describeTimeParts(const SceneRecord& record, std::optional<double> startup, double wallMilliseconds);

// Prints "wrote OUTPUT (SIZE) — HOW; TIME PARTS" on standard output, unless --quiet.
void printWrote(const std::string& outputPath, const std::string& size, const std::string& how,
                const std::string& timeParts);

}  // namespace hexray::cli
