#include <chrono>
#include <cstdio>
#include <filesystem>

#include "cli/command_support.h"
#include "cpu/cpu_renderer.h"
#include "gpu/gpu_renderer.h"
#include "image/image_io.h"

namespace hexray::cli {
namespace {

std::string defaultOutputPath(const std::string& scenePath) {
    return std::filesystem::path(scenePath).stem().string() + ".png";
}

}  // namespace

int runRender(const RenderOptions& options) {
    ValidationLog log;
    const int code = guarded([&] {
        const Scene scene = loadScene(options.scenePath, options.image);
        Rgb8Image image;
        char how[512];
        if (options.backend == Backend::Gpu) {
            const VulkanContext context({options.vulkan.validate ? &log : nullptr, options.vulkan.device});
            GpuRenderer renderer(context);
            GpuRenderResult result = renderer.render(scene, options.precision, GpuOutput::Encoded8);
            std::snprintf(how, sizeof how, "gpu %s (%s): render %.2f ms%s, first dispatch %.1f ms incl. shader compile",
                          std::string(precisionName(result.precision)).c_str(), context.selected().name.c_str(),
                          result.timing.renderMilliseconds, result.timing.fromTimestamps ? "" : " (wall clock)",
                          result.timing.firstDispatchMilliseconds);
            image = std::move(result.encoded);
        } else {
            const unsigned threads = threadCount(options.threads);
            const auto start = std::chrono::steady_clock::now();
            image = encodeImage(renderOnCpu(scene, threads).image, scene.image.encoding);
            std::snprintf(how, sizeof how, "cpu reference (%u threads): render %.2f ms", threads,
                          millisecondsSince(start));
        }
        const std::string output = options.outputPath.empty() ? defaultOutputPath(options.scenePath) : options.outputPath;
        writePng(output, image);
        std::printf("wrote %s (%ux%u) — %s\n", output.c_str(), scene.image.width, scene.image.height, how);
        return int(kSuccess);
    });
    return withValidationVerdict(code, log);
}

}  // namespace hexray::cli
