#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <unistd.h>

#include "cli/command_support.h"
#include "cpu/cpu_explain.h"
#include "cpu/cpu_renderer.h"
#include "gpu/gpu_renderer.h"
#include "gpu/shader_compiler.h"
#include "image/aov.h"
#include "image/image_io.h"
#include "io/output_plan.h"
#include "io/standard_output.h"

namespace hexray::cli {
namespace {

std::string defaultOutputPath(const std::string& scenePath) {
    return std::filesystem::path(scenePath).stem().string() + ".png";
}

// A progress line on stderr while a large image renders band by band; silent unless stderr
// is a terminal, and for images that render in one band.
class Progress {
public:
    explicit Progress(std::uint32_t rows) : rows_(rows), shown_(::isatty(STDERR_FILENO) != 0) {}
    ~Progress() {
        if (started_) {
            std::fprintf(stderr, "\r%40s\r", "");
        }
    }
    void rowsDone(std::uint32_t done) {
        if (!shown_ || done >= rows_) {
            return;
        }
        started_ = true;
        std::fprintf(stderr, "\rrendering: %3u%% (%u of %u rows)", unsigned(100.0 * done / rows_), done, rows_);
        std::fflush(stderr);
    }

private:
    std::uint32_t rows_;
    bool shown_;
    bool started_ = false;
};

// "generated for the scene, written in 0.12 ms, glslang 9.8 ms", for the summary line.
std::string describeKernel(const RenderPlan& plan, const KernelBuild& build) {
    if (!plan.kernel.code) {
        return plan.kernel.name + " (prebuilt)";
    }
    const std::size_t classes = plan.tileClasses.kernels.size();
    const std::string name = classes ? "generated for each of " + std::to_string(classes) + " tile classes"
                                     : plan.kernel.name;
    char text[160];
    std::snprintf(text, sizeof text, "%s, written in %.2f ms, %s", name.c_str(), build.generateMilliseconds,
                  build.fromDiskCache ? "SPIR-V from the kernel cache" : "");
    std::string description = text;
    if (!build.fromDiskCache) {
        std::snprintf(text, sizeof text, "glslang %.1f ms", build.compileMilliseconds);
        description += text;
    }
    return description;
}

AovLayout aovLayout(const Scene& scene) {
    return AovLayout{scene.image.width, scene.image.height, scene.lights.size()};
}

// Renders on the GPU into `writer`, band by band; then, with --aov, the AOVs into `aovs`, band
// by band too. Returns how, for the summary line.
std::string renderOnGpu(const RenderOptions& options, const Scene& scene, ValidationLog& log, PngRowWriter& writer,
                        std::optional<StagedAovs>& aovs) {
    // glslang sets itself up while the Vulkan instance and device are created.
    std::optional<ShaderCompilerWarmUp> compilerWarmUp;
    if (isSmallScene(scene)) {
        compilerWarmUp.emplace();
    }
    const VulkanContext context({options.vulkan.validate ? &log : nullptr, options.vulkan.device});
    GpuRenderer renderer(context);
    Progress progress(scene.image.height);
    // Rows go from the device to the PNG encoder band by band: a 16384 x 16384 image never
    // sits whole in memory.
    const RenderPlan plan = renderer.plan(scene, {options.precision, Acceleration::Auto, options.culling});
    for (const std::string& warning : plan.warnings) {
        std::fprintf(stderr, "hexray: warning: %s\n", warning.c_str());
    }
    const GpuRenderResult result = renderer.renderEncodedRows(
        scene, plan, [&](std::uint32_t firstRow, std::span<const std::uint8_t> rgbRows) {
            writer.writeRows(rgbRows);
            progress.rowsDone(firstRow + std::uint32_t(rgbRows.size() / (3 * std::size_t(scene.image.width))));
        });
    char how[512];
    std::snprintf(how, sizeof how, "gpu %s (%s): render %.2f ms%s; kernel %s; first dispatch %.1f ms incl. the driver's "
                  "compile",
                  std::string(precisionName(result.precision)).c_str(), context.selected().name.c_str(),
                  result.timing.renderMilliseconds, result.timing.fromTimestamps ? "" : " (wall clock)",
                  describeKernel(plan, result.timing.kernel).c_str(), result.timing.firstDispatchMilliseconds);
    if (!options.aovDirectory.empty()) {
        // A second pass in the shader's AOV mode, so that the image is the one a render
        // without --aov writes (encoded on the device). Its rows come back as floats: smaller bands.
        aovs.emplace(options.aovDirectory, aovLayout(scene));
        GpuRenderer aovRenderer(context, kBandBytes);
        aovRenderer.renderLinearRows(scene, plan, GpuOutput::LinearClassesAndAov,
                                     [&](std::uint32_t, const GpuRenderResult& band) {
                                         aovs->writeRows({band.image.height, band.depth, band.normals, band.classes, {}});
                                     });
    }
    return how;
}

std::string renderWithCpuReference(const RenderOptions& options, const Scene& scene, PngRowWriter& writer,
                                   std::optional<StagedAovs>& aovs) {
    const bool withAovs = !options.aovDirectory.empty();
    const CpuBandRenderer renderer(scene, options.threads, Acceleration::Auto, withAovs);
    if (withAovs) {
        aovs.emplace(options.aovDirectory, aovLayout(scene));
    }
    Progress progress(scene.image.height);
    const std::uint32_t bandRows = renderer.rowsPerBand(kBandBytes);
    CpuRender band;
    double milliseconds = 0;
    for (std::uint32_t firstRow = 0; firstRow < scene.image.height; firstRow += bandRows) {
        const auto start = std::chrono::steady_clock::now();
        renderer.render(firstRow, std::min(bandRows, scene.image.height - firstRow), band);
        milliseconds += millisecondsSince(start);
        writer.writeRows(encodeImage(band.image, scene.image.encoding).bytes);
        if (aovs) {
            aovs->writeRows({band.image.height, band.depth, band.normals, band.classes, {}});
        }
        progress.rowsDone(firstRow + band.image.height);
    }
    char how[128];
    std::snprintf(how, sizeof how, "cpu reference (%u threads): render %.2f ms", renderer.threadCount(), milliseconds);
    return how;
}

// Every path the render reads or writes, checked before any work.
void checkPaths(const RenderOptions& options, const std::string& output) {
    OutputPlan plan;
    plan.addInput("the scene", options.scenePath);
    plan.addFile("-o", output);
    if (!options.aovDirectory.empty()) {
        plan.addDirectory("--aov", options.aovDirectory, isAovFileName);
    }
    plan.check();
}

// With --backend auto, a GPU path that cannot render (anything but a wrong request, such as an
// unknown --device) hands over to the CPU reference; with --backend gpu the failure stands.
bool fallsBack(const RenderOptions& options, const VulkanError& error) {
    if (options.backend != Backend::Auto || error.failure() == VulkanFailure::Request) {
        return false;
    }
    std::fprintf(stderr, "hexray: note: %s; rendering on the CPU reference instead\n", error.reason().c_str());
    return true;
}

}  // namespace

int runRender(const RenderOptions& options) {
    ValidationLog log;
    const int code = guarded([&] {
        const std::string output = options.outputPath.empty() ? defaultOutputPath(options.scenePath) : options.outputPath;
        checkPaths(options, output);
        const Scene scene = loadScene(options.scenePath, options.image);
        // Opened first, so a bad output path fails before any rendering; renamed into place
        // only once every row is in.
        std::optional<PngRowWriter> writer(std::in_place, output, scene.image.width, scene.image.height);
        std::string how;
        std::optional<StagedAovs> aovs;
        if (options.backend != Backend::Cpu) {
            bool fallBack = false;
            try {
                how = renderOnGpu(options, scene, log, *writer, aovs);
            } catch (const VulkanError& error) {
                if (!fallsBack(options, error)) throw;
                fallBack = true;
            } catch (const vk::SystemError& error) {
                if (!fallsBack(options, classify(error, "rendering"))) throw;
                fallBack = true;
            }
            if (fallBack) {
                writer.reset();  // drops the GPU's partial rows with their temporary file
                writer.emplace(output, scene.image.width, scene.image.height);
            }
        }
        if (how.empty()) {
            how = renderWithCpuReference(options, scene, *writer, aovs);
        }
        writer->finish();
        std::printf("wrote %s (%ux%u) — %s\n", displayName(output).c_str(), scene.image.width, scene.image.height,
                    how.c_str());
        if (aovs) {
            // Only now, so a failed render leaves the directory's earlier AOVs as they were.
            const std::size_t files = aovs->commit().size();
            std::printf("wrote %zu AOV files (OpenEXR and PNG previews) in %s\n", files, options.aovDirectory.c_str());
        }
        return int(kSuccess);
    });
    return withValidationVerdict(code, log);
}

}  // namespace hexray::cli
