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
#include "image/aov.h"
#include "image/image_io.h"

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

// Renders on the GPU into `writer`, band by band; then, with --aov, stages the AOVs in
// `aovs`. Returns how, for the summary line.
std::string renderOnGpu(const RenderOptions& options, const Scene& scene, ValidationLog& log, PngRowWriter& writer,
                        std::optional<StagedAovs>& aovs) {
    const VulkanContext context({options.vulkan.validate ? &log : nullptr, options.vulkan.device});
    GpuRenderer renderer(context);
    Precision precision = options.precision;
    if (const auto problem = float32RangeProblem(scene); problem && precision == Precision::F32) {
        std::fprintf(stderr, "hexray: warning: float32 cannot hold this scene (%s); rendering in f64 instead\n",
                     problem->c_str());
        precision = Precision::F64;
    }
    Progress progress(scene.image.height);
    // Rows go from the device to the PNG encoder band by band: a 16384 x 16384 image never
    // sits whole in memory.
    const GpuRenderResult result = renderer.renderEncodedRows(
        scene, precision, [&](std::uint32_t firstRow, std::span<const std::uint8_t> rgbRows) {
            writer.writeRows(rgbRows);
            progress.rowsDone(firstRow + std::uint32_t(rgbRows.size() / (3 * std::size_t(scene.image.width))));
        });
    char how[512];
    std::snprintf(how, sizeof how, "gpu %s (%s): render %.2f ms%s, first dispatch %.1f ms incl. shader compile",
                  std::string(precisionName(result.precision)).c_str(), context.selected().name.c_str(),
                  result.timing.renderMilliseconds, result.timing.fromTimestamps ? "" : " (wall clock)",
                  result.timing.firstDispatchMilliseconds);
    if (!options.aovDirectory.empty()) {
        // A second pass in the shader's AOV mode, so that the image is the one a render
        // without --aov writes (encoded on the device); the AOVs are held whole, for the EXR files.
        GpuRenderResult pass = renderer.render(scene, result.precision, GpuOutput::LinearClassesAndAov);
        aovs.emplace(options.aovDirectory, AovSet{scene.image.width, scene.image.height, std::move(pass.depth),
                                                  std::move(pass.normals), std::move(pass.classes),
                                                  scene.lights.size()});
    }
    return how;
}

std::string renderWithCpuReference(const RenderOptions& options, const Scene& scene, PngRowWriter& writer,
                                   std::optional<StagedAovs>& aovs) {
    const unsigned threads = cpuThreadCount(options.threads);
    const auto start = std::chrono::steady_clock::now();
    CpuRender render = renderOnCpu(scene, threads, Acceleration::Auto, !options.aovDirectory.empty());
    const Rgb8Image image = encodeImage(render.image, scene.image.encoding);
    char how[128];
    std::snprintf(how, sizeof how, "cpu reference (%u threads): render %.2f ms", threads, millisecondsSince(start));
    writer.writeRows(image.bytes);
    if (!options.aovDirectory.empty()) {
        aovs.emplace(options.aovDirectory, AovSet{scene.image.width, scene.image.height, std::move(render.depth),
                                                  std::move(render.normals), std::move(render.classes),
                                                  scene.lights.size()});
    }
    return how;
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
        const Scene scene = loadScene(options.scenePath, options.image);
        const std::string output = options.outputPath.empty() ? defaultOutputPath(options.scenePath) : options.outputPath;
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
        std::printf("wrote %s (%ux%u) — %s\n", output.c_str(), scene.image.width, scene.image.height, how.c_str());
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
