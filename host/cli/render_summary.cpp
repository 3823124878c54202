#include "cli/render_summary.h"

#include <algorithm>
#include <cstdio>

#include "cli/quiet.h"
#include "io/standard_output.h"
#include "util/formatted.h"

namespace hexray::cli {
namespace {

// How the data-driven kernel's work is split to stay within the device's loop limit (loop_budget.h).
std::string describeBatches(const LightBatches& batches) {
    if (!batches.splits()) {
        return "";
    }
    if (batches.lightEnds.size() == 1) {
        return ", " + std::to_string(batches.samplesPerDispatch) + " samples a dispatch (the device's loop limit)";
    }
    return ", " + std::to_string(batches.lightEnds.size()) + " batches of lights a sample (the device's loop limit)";
}

}  // namespace

std::string describeKernel(const RenderPlan& plan, const KernelBuild& build) {
    if (!plan.kernel.code) {
        return plan.kernel.name + " (prebuilt)" + describeBatches(plan.lightBatches);
    }
    const std::size_t classes = plan.tileClasses.kernels.size();
    const std::string name =
        classes ? "generated for each of " + std::to_string(classes) + " tile classes" : plan.kernel.name;
    std::string description = formatted("%s, written in %.2f ms, ", name.c_str(), build.generateMilliseconds);
    if (build.fromDiskCache) {
        description += formatted("SPIR-V from the kernel cache (read and checked in %.1f ms)", build.loadMilliseconds);
    } else {
        description += formatted("glslang %.1f ms", build.compileMilliseconds);
    }
    return description;
}

std::string describeGpuRender(const RenderPlan& plan, const GpuRenderResult& result, const std::string& device,
                              const std::string& tier) {
    const std::string precision(precisionName(plan.precision));
    const std::string kernel = (tier.empty() ? "" : tier + ": ") + describeKernel(plan, result.timing.kernel);
    const CertifiedFallback& pass = result.timing.fallback;
    const std::string f64Pass =
        plan.precision == Precision::F32Certified && pass.totalPixels > 0
            ? formatted(
                  "; %llu pixels in doubt rendered again in f64 (%.3f%% of the pixels, %.3f%% of the 8-lane "
                  "vectors)",
                  static_cast<unsigned long long>(pass.pixels), 100.0 * double(pass.pixels) / double(pass.totalPixels),
                  100.0 * double(pass.vectors) / double(pass.totalVectors))
            : "";
    return formatted("gpu %s (%s): render %.2f ms%s; kernel %s; first dispatch %.1f ms incl. the driver's compile%s",
                     precision.c_str(), device.c_str(), result.timing.renderMilliseconds,
                     result.timing.fromTimestamps ? "" : " (wall clock)", kernel.c_str(),
                     result.timing.firstDispatchMilliseconds, f64Pass.c_str());
}

GpuSceneRecord gpuSceneRecord(const RenderPlan& plan, const GpuRenderResult& result, double planMilliseconds) {
    return GpuSceneRecord{.precision = plan.precision,
                          .kernelName = plan.kernel.name,
                          .generatedKernel = plan.kernel.code != nullptr,
                          .tileClasses = plan.tileClasses.kernels.size(),
                          .candidateLists = result.usedCandidateLists,
                          .warnings = plan.warnings,
                          .planMilliseconds = planMilliseconds,
                          .timing = result.timing};
}

std::string describeTimeParts(const SceneRecord& record, std::optional<double> startup, double wallMilliseconds) {
    std::string parts;
    double accounted = 0;
    const auto add = [&](const char* name, double milliseconds) {
        parts += formatted("%s%s %.1f", parts.empty() ? "" : ", ", name, milliseconds);
        accounted += milliseconds;
    };
    if (startup) {
        add("start-up", *startup);
    }
    add("load", record.loadMilliseconds.value_or(0));
    if (record.gpu) {
        const GpuSceneRecord& gpu = *record.gpu;
        add("kernel", gpu.planMilliseconds + gpu.timing.uploadMilliseconds + gpu.timing.firstDispatchMilliseconds);
    }
    add("render", record.gpu ? record.gpu->timing.renderMilliseconds : record.cpu ? record.cpu->renderMilliseconds : 0);
    add("write", record.writeMilliseconds.value_or(0));
    add("other", std::max(0.0, wallMilliseconds - accounted));
    return formatted("; %.1f ms in all (%s)", wallMilliseconds, parts.c_str());
}

void printWrote(const std::string& outputPath, const std::string& size, const std::string& how,
                const std::string& timeParts) {
    if (!quiet()) {
        std::printf("wrote %s (%s) — %s%s\n", displayName(outputPath).c_str(), size.c_str(), how.c_str(),
                    timeParts.c_str());
        std::fflush(stdout);
    }
}

}  // namespace hexray::cli
