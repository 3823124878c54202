#include "cli/commands.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <thread>

#include "compare/compare.h"
#include "cpu/cpu_renderer.h"
#include "gpu/gpu_renderer.h"
#include "image/image_io.h"
#include "scene/scene_loader.h"
#include "vulkan/vulkan_context.h"

namespace hexray::cli {
namespace {

void printError(const std::string& message) {
    std::fprintf(stderr, "hexray: error: %s\n", message.c_str());
}

// Runs a command, turning each kind of failure into its message and exit code.
int guarded(const std::function<int()>& command) {
    try {
        return command();
    } catch (const SceneError& error) {
        printError(error.what());
        return kBadInput;
    } catch (const VulkanError& error) {
        printError(error.what());
        return kVulkanUnavailable;
    } catch (const vk::SystemError& error) {
        printError(std::string("Vulkan call failed: ") + error.what());
        return kVulkanUnavailable;
    } catch (const ImageIoError& error) {
        printError(error.what());
        return kOutputFailed;
    }
}

Scene loadScene(const SceneOptions& options) {
    Scene scene = loadSceneFile(options.scenePath);
    if (options.width || options.height) {
        const char* source = !options.height ? "--width" : !options.width ? "--height" : "--width/--height";
        overrideImageSize(scene, options.width.value_or(scene.image.width),
                          options.height.value_or(scene.image.height), source);
    }
    return scene;
}

unsigned threadCount(unsigned requested) {
    return requested ? requested : std::max(1u, std::thread::hardware_concurrency());
}

// Validation messages fail the command: a tester's run must be clean, not merely finish.
int validationVerdict(const ValidationLog& log) {
    const std::uint32_t count = log.messageCount.load();
    if (count == 0) {
        return kSuccess;
    }
    printError("the Vulkan validation layer reported " + std::to_string(count) + " message(s)");
    return kValidationFailed;
}

struct TimedImage {
    Image image;
    std::string how;  // backend, device and timing, for the summary line
    double milliseconds = 0;
};

TimedImage renderWithGpu(const Scene& scene, const VulkanOptions& options, ValidationLog& log) {
    const VulkanContext context({options.validate ? &log : nullptr, options.device});
    GpuRenderer renderer(context);
    GpuRenderResult result = renderer.render(scene);
    char how[512];
    std::snprintf(how, sizeof how, "gpu (%s): render %.2f ms%s, first dispatch %.1f ms incl. shader compile",
                  context.selected().name.c_str(), result.timing.renderMilliseconds,
                  result.timing.fromTimestamps ? "" : " (wall clock)", result.timing.firstDispatchMilliseconds);
    return {std::move(result.image), how, result.timing.renderMilliseconds};
}

TimedImage renderWithCpu(const Scene& scene, unsigned requestedThreads) {
    const unsigned threads = threadCount(requestedThreads);
    const auto start = std::chrono::steady_clock::now();
    Image image = renderOnCpu(scene, threads);
    const double milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    char how[128];
    std::snprintf(how, sizeof how, "cpu reference (%u threads): render %.2f ms", threads, milliseconds);
    return {std::move(image), how, milliseconds};
}

std::string defaultOutputPath(const std::string& scenePath) {
    return std::filesystem::path(scenePath).stem().string() + ".png";
}

void printMetricsRow(const char* label, const ErrorMetrics& m, const char* format) {
    char psnr[32];
    if (std::isinf(m.psnr)) {
        std::snprintf(psnr, sizeof psnr, "inf (identical)");
    } else {
        std::snprintf(psnr, sizeof psnr, "%.2f", m.psnr);
    }
    std::printf(format, label, m.maxAbs, m.meanAbs, m.rmse, psnr,
                static_cast<unsigned long long>(m.pixelsOverOneLevel), 100.0 * m.shareOverOneLevel);
}

}  // namespace

int runRender(const RenderOptions& options) {
    ValidationLog log;
    int code = guarded([&] {
        const Scene scene = loadScene(options.scene);
        const TimedImage rendered =
            options.backend == Backend::Gpu ? renderWithGpu(scene, options.vulkan, log) : renderWithCpu(scene, options.threads);
        const std::string output = options.outputPath.empty() ? defaultOutputPath(options.scene.scenePath) : options.outputPath;
        writePng(output, encodeImage(rendered.image, scene.image.encoding));
        std::printf("wrote %s (%ux%u) — %s\n", output.c_str(), scene.image.width, scene.image.height,
                    rendered.how.c_str());
        return int(kSuccess);
    });
    return code == kSuccess ? validationVerdict(log) : code;
}

int runCompare(const CompareOptions& options) {
    ValidationLog log;
    int code = guarded([&] {
        const Scene scene = loadScene(options.scene);
        const TimedImage gpu = renderWithGpu(scene, options.vulkan, log);
        const TimedImage cpu = renderWithCpu(scene, options.threads);
        const ImageComparison comparison = compareRenders(cpu.image, gpu.image, scene.image.encoding);

        std::printf("scene %s: %ux%u, %s output\n", options.scene.scenePath.c_str(), scene.image.width,
                    scene.image.height, scene.image.encoding == Encoding::Srgb ? "sRGB" : "linear");
        std::printf("  %s\n  %s\n", gpu.how.c_str(), cpu.how.c_str());
        std::printf("  %-16s %10s %10s %10s %16s  %s\n", "GPU vs CPU", "max abs", "mean abs", "RMSE", "PSNR dB",
                    "pixels > 1 level");
        printMetricsRow("linear [0,1]", comparison.linear, "  %-16s %10.6f %10.6f %10.6f %16s  %llu (%.4f%%)\n");
        printMetricsRow("8-bit [levels]", comparison.encoded, "  %-16s %10.0f %10.4f %10.4f %16s  %llu (%.4f%%)\n");

        if (!options.diffPath.empty()) {
            writePng(options.diffPath,
                     diffHeatMap(encodeImage(cpu.image, scene.image.encoding), encodeImage(gpu.image, scene.image.encoding)));
            std::printf("  wrote diff heat map %s\n", options.diffPath.c_str());
        }

        const Verdict verdict = judge(comparison, options.tolerance);
        std::printf("  tolerance: pixels > 1 level %.4f%% <= %.4f%% %s; 8-bit RMSE %.4f <= %.4f levels %s\n",
                    100.0 * comparison.encoded.shareOverOneLevel, options.tolerance.maxSharePercent,
                    verdict.shareOk ? "ok" : "EXCEEDED", comparison.encoded.rmse, options.tolerance.maxRmseLevels,
                    verdict.rmseOk ? "ok" : "EXCEEDED");
        std::printf("%s\n", verdict.passed() ? "PASS" : "FAIL");
        return int(verdict.passed() ? kSuccess : kToleranceExceeded);
    });
    const int validation = validationVerdict(log);
    return code == kSuccess ? validation : code;
}

int runDevices(const VulkanOptions& options) {
    ValidationLog log;
    int code = guarded([&] {
        const VulkanContext context({options.validate ? &log : nullptr, options.device});
        for (const DeviceInfo& device : context.devices()) {
            const bool chosen = device.index == context.selected().index;
            std::printf("%s%u: %s — %s, Vulkan %s, %s%s%s\n", chosen ? "* " : "  ", device.index, device.name.c_str(),
                        deviceTypeName(device.type).c_str(), device.apiVersion.c_str(),
                        device.driver.empty() ? "" : (device.driver + ", ").c_str(),
                        device.hasComputeQueue ? "compute" : "no compute queue",
                        device.hasFloat64 ? ", float64" : "");
        }
        std::printf("(* = the device hexray uses%s)\n", options.device.empty() ? " by default" : " with --device");
        return int(kSuccess);
    });
    return code == kSuccess ? validationVerdict(log) : code;
}

}  // namespace hexray::cli
