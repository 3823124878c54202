// `hexray render`: each scene named into its own image file, in one process that starts Vulkan
// once (GpuSession); a scene that fails is reported and the others still render.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cli/command_support.h"
#include "cli/gpu_session.h"
#include "cli/json_document.h"
#include "cli/progress.h"
#include "cli/quiet.h"
#include "cli/render_record.h"
#include "cli/render_summary.h"
#include "cli/render_targets.h"
#include "cpu/cpu_renderer.h"
#include "gpu/gpu_renderer.h"
#include "gpu/plan_refused.h"
#include "kernels/shader_compiler.h"
#include "image/aov.h"
#include "image/image_row_writer.h"
#include "image/provenance.h"
#include "io/output_plan.h"
#include "io/standard_output.h"
#include "scene/scene_loader.h"
#include "strip/strip_provenance.h"
#include "strip/strip_stamp.h"
#include "util/build_version.h"
#include "util/formatted.h"
#include "util/printable.h"

namespace hexray::cli {
namespace {

// One scene rendered into one file: what either backend needs.
struct SceneRender {
    const RenderOptions& options;
    const RenderTarget& target;
    Scene scene;
    RowRange rows;              // the whole image, or the strip's rows
    std::string sceneIdentity;  // recorded in the image, and in a strip's stamp

    SceneRender(const RenderOptions& renderOptions, const RenderTarget& renderTarget)
        : options(renderOptions), target(renderTarget) {
        scene = loadScene(target.scenePath, options.image, &sceneIdentity);
        rows = options.strip ? stripRows(*options.strip, scene.image.height) : RowRange{0, scene.image.height};
    }

    // What the image records of how it was made (image/provenance.h).
    Provenance provenance(const std::string& backend, const std::string& device, const std::string& precision) const {
        return Provenance{.version = hexrayVersion(),
                          .gitRevision = hexrayGitRevision(),
                          .image = "render",
                          .scene = sceneIdentity,
                          .backend = backend,
                          .device = device,
                          .precision = precision,
                          .samplesPerPixel = scene.image.samplesPerPixel,
                          .width = scene.image.width,
                          .height = scene.image.height};
    }

    // Opens the output, recording `provenance`; a strip's also records its stamp, since pieces of
    // one image must share it, and the digest of its stamp and pixels, so that merge can prove it
    // reads what was rendered.
    void open(std::optional<ImageRowWriter>& writer, const Provenance& provenance) const {
        std::vector<ImageNote> notes;
        std::optional<DigestNote> digest;
        if (options.strip) {
            const StripStamp stamp{*options.strip,
                                   scene.image.width,
                                   scene.image.height,
                                   scene.image.samplesPerPixel,
                                   stripRenderer(provenance),
                                   sceneIdentity,
                                   buildVersion()};
            const std::string text = formatStripStamp(stamp);
            notes.push_back({kStripStampKey, text});
            digest = DigestNote{kStripDigestKey, text};
        }
        writer.emplace(target.outputPath, *target.format, scene.image.width, rows.count, scene.image.encoding,
                       provenance, notes, digest);
    }

    // With --aov, starts the AOV set.
    void stageAovs(std::optional<StagedAovs>& aovs, const Provenance& provenance) const {
        if (!options.aovDirectory.empty()) {
            aovs.emplace(options.aovDirectory, AovLayout{scene.image.width, scene.image.height, scene.lights.size()},
                         provenance);
        }
    }

    Progress progress() const { return Progress("rendering " + target.scenePath, rows.count); }
};

// The image's rows from the device into `writer`: 8-bit as the shader encodes them, or linear
// for OpenEXR.
GpuRenderResult renderImageOnGpu(const SceneRender& job, GpuSession& gpu, const RenderPlan& plan,
                                 ImageRowWriter& writer) {
    Progress progress = job.progress();
    const auto rowsDone = [&](std::uint32_t firstRow, std::uint32_t rows) {
        progress.update(firstRow + rows - job.rows.first);
    };
    if (writer.wantsLinear()) {
        return gpu.linearRenderer().renderLinearRows(
            job.scene, plan, GpuOutput::LinearAndClasses,
            [&](std::uint32_t firstRow, const GpuRenderResult& band) {
                writer.writeLinear(band.image);
                rowsDone(firstRow, band.image.height);
            },
            job.rows);
    }
    const std::size_t rowBytes = 3 * std::size_t(job.scene.image.width);
    return gpu.renderer().renderEncodedRows(
        job.scene, plan,
        [&](std::uint32_t firstRow, std::span<const std::uint8_t> rgbRows) {
            writer.writeEncoded(rgbRows);
            rowsDone(firstRow, std::uint32_t(rgbRows.size() / rowBytes));
        },
        job.rows);
}

// Renders on the GPU into `writer` (opened here, once the renderer is known), band by band;
// then, with --aov, the AOVs in a second pass in the shader's AOV mode, so that the image is the
// one a render without --aov writes. Returns how, for the summary line.
std::string renderOnGpu(const SceneRender& job, GpuSession& gpu, std::optional<ImageRowWriter>& writer,
                        std::optional<StagedAovs>& aovs, SceneRecord& record) {
    // glslang sets itself up while the Vulkan instance and device are created.
    std::optional<ShaderCompilerWarmUp> compilerWarmUp;
    if (isSmallScene(job.scene) && !gpu.started()) {
        compilerWarmUp.emplace();
    }
    GpuRenderer& renderer = gpu.renderer();  // Vulkan starts here, outside the plan's time
    const auto planStart = std::chrono::steady_clock::now();
    const RenderPlan plan = renderer.plan(job.scene, {job.options.precision, Acceleration::Auto, job.options.culling});
    const double planMilliseconds = millisecondsSince(planStart);
    for (const std::string& warning : plan.warnings) {
        std::fprintf(stderr, "hexray: warning: %s\n", warning.c_str());
    }
    const std::string device = gpu.context().selected().name;
    const std::string precision(precisionName(plan.precision));
    const Provenance provenance = job.provenance("gpu", device, precision);
    job.open(writer, provenance);
    const GpuRenderResult result = renderImageOnGpu(job, gpu, plan, *writer);
    job.stageAovs(aovs, provenance);
    if (aovs) {
        gpu.linearRenderer().renderLinearRows(
            job.scene, plan, GpuOutput::LinearClassesAndAov, [&](std::uint32_t, const GpuRenderResult& band) {
                aovs->writeRows({band.image.height, band.depth, band.normals, band.classes, {}});
            });
    }
    record.gpu = gpuSceneRecord(plan, result, planMilliseconds);
    return describeGpuRender(plan, result, device);
}

// Rows per band of the CPU reference: within the memory budget; on a terminal, also small enough
// that the progress line moves, but never so few that a thread has no row.
std::uint32_t cpuBandRows(const CpuBandRenderer& renderer, std::uint32_t rows) {
    constexpr std::uint32_t kProgressSteps = 64;
    const std::uint32_t withinBudget = renderer.rowsPerBand(kBandBytes);
    if (!Progress::shown()) {
        return withinBudget;
    }
    return std::min(withinBudget, std::max((rows + kProgressSteps - 1) / kProgressSteps, 8 * renderer.threadCount()));
}

std::string renderOnCpu(const SceneRender& job, std::optional<ImageRowWriter>& writer, std::optional<StagedAovs>& aovs,
                        SceneRecord& record) {
    const CpuBandRenderer renderer(job.scene, job.options.threads, Acceleration::Auto,
                                   !job.options.aovDirectory.empty());
    const Provenance provenance = job.provenance("cpu", "cpu reference", std::string(precisionName(Precision::F64)));
    job.open(writer, provenance);
    job.stageAovs(aovs, provenance);
    Progress progress = job.progress();
    const std::uint32_t bandRows = cpuBandRows(renderer, job.rows.count);
    CpuRender band;
    double milliseconds = 0;
    for (std::uint32_t firstRow = job.rows.first; firstRow < job.rows.end(); firstRow += bandRows) {
        const auto start = std::chrono::steady_clock::now();
        renderer.render(firstRow, std::min(bandRows, job.rows.end() - firstRow), band);
        milliseconds += millisecondsSince(start);
        writer->writeLinear(band.image);
        if (aovs) {
            aovs->writeRows({band.image.height, band.depth, band.normals, band.classes, {}});
        }
        progress.update(firstRow + band.image.height - job.rows.first);
    }
    record.cpu = CpuSceneRecord{renderer.threadCount(), milliseconds};
    char how[128];
    std::snprintf(how, sizeof how, "cpu reference (%u threads): render %.2f ms", renderer.threadCount(), milliseconds);
    return how;
}

// With --backend auto, a GPU path that cannot render (anything but a wrong request, such as an
// unknown --device) hands over to the CPU reference, with a note the first time; with
// --backend gpu the failure stands.
class Fallback {
public:
    explicit Fallback(Backend backend) : backend_(backend) {}

    // Whether the CPU takes over after the GPU path gave up for `reason`.
    bool allowed(const std::string& reason) {
        if (backend_ != Backend::Auto) {
            return false;
        }
        if (!noted_) {
            std::fprintf(stderr, "hexray: note: %s; rendering on the CPU reference instead\n", reason.c_str());
            noted_ = true;
        }
        return true;
    }

private:
    Backend backend_;
    bool noted_ = false;
};

// After a Vulkan failure on the GPU path: rethrows it unless the CPU may take over.
void handOver(const VulkanError& failure, GpuSession& gpu, Fallback& fallback) {
    if (failure.failure() == VulkanFailure::DeviceLost) {
        gpu.failed(failure);  // not to be used again
    }
    if (failure.failure() == VulkanFailure::Request || !fallback.allowed(failure.reason())) {
        throw failure;
    }
}

// Renders one scene into its file on the backend asked for; returns how, for the summary line.
std::string renderImage(const SceneRender& job, GpuSession& gpu, Fallback& fallback,
                        std::optional<ImageRowWriter>& writer, std::optional<StagedAovs>& aovs, SceneRecord& record) {
    if (job.options.backend != Backend::Cpu) {
        try {
            return renderOnGpu(job, gpu, writer, aovs, record);
        } catch (const PlanRefused& refusal) {
            if (!fallback.allowed(refusal.reason())) {
                throw;
            }
            record.fallbackReason = refusal.reason();
        } catch (const VulkanError& error) {
            handOver(error, gpu, fallback);
            record.fallbackReason = error.reason();
        } catch (const vk::SystemError& error) {
            const VulkanError failure = classify(error, "rendering");
            handOver(failure, gpu, fallback);
            record.fallbackReason = failure.reason();
        }
        writer.reset();  // drops the GPU's partial rows with their temporary file
        aovs.reset();
        record.gpu.reset();
    }
    return renderOnCpu(job, writer, aovs, record);
}

int renderScene(const RenderOptions& options, const RenderTarget& target, GpuSession& gpu, Fallback& fallback,
                SceneRecord& record) {
    if (!target.problem.empty()) {
        throw SceneError(printable(target.scenePath) + ": " + target.problem);
    }
    const auto loadStart = std::chrono::steady_clock::now();
    const bool startedVulkan = !gpu.startupMilliseconds();  // else an earlier scene did
    const SceneRender job(options, target);
    record.loadMilliseconds = millisecondsSince(loadStart);
    record.image = job.scene.image;
    record.rows = options.strip ? std::optional<RowRange>(job.rows) : std::nullopt;
    std::optional<ImageRowWriter> writer;
    std::optional<StagedAovs> aovs;
    const std::string how = renderImage(job, gpu, fallback, writer, aovs, record);
    const auto writeStart = std::chrono::steady_clock::now();
    writer->finish();
    record.writeMilliseconds = millisecondsSince(writeStart);
    const ImageSettings& image = job.scene.image;
    std::string size = std::to_string(image.width) + "x" + std::to_string(image.height);
    if (options.strip) {
        size = "rows " + std::to_string(job.rows.first) + "-" + std::to_string(job.rows.end() - 1) + " of " + size;
    }
    printWrote(target.outputPath, size, how,
               describeTimeParts(record, startedVulkan ? gpu.startupMilliseconds() : std::nullopt,
                                 millisecondsSince(loadStart)));
    if (aovs) {
        // Only now, so a failed render leaves the directory's earlier AOVs as they were.
        const std::size_t files = aovs->commit().size();
        record.aovFiles = files;
        if (!quiet()) {
            std::printf("wrote %zu AOV files (OpenEXR and PNG previews) in %s\n", files,
                        printable(options.aovDirectory).c_str());
        }
    }
    return int(kSuccess);
}

// Every path the render reads or writes, checked before any work.
void checkPaths(const RenderOptions& options, const std::vector<RenderTarget>& targets) {
    if (targets.size() > 1 && !options.aovDirectory.empty()) {
        throw SceneError("--aov: AOVs need a single scene");
    }
    if (options.strip && !options.aovDirectory.empty()) {
        throw SceneError("--aov: AOVs are of the whole image, not of a strip");
    }
    std::vector<const RenderTarget*> rendered;  // a directory that could not be searched fails alone, later
    for (const RenderTarget& target : targets) {
        if (target.problem.empty()) {
            rendered.push_back(&target);
        }
    }
    OutputPlan plan;
    for (const RenderTarget* target : rendered) {
        plan.addInput("the scene", target->scenePath);
    }
    for (const RenderTarget* target : rendered) {
        plan.addFile("-o", target->outputPath);
    }
    if (!options.aovDirectory.empty()) {
        plan.addDirectory("--aov", options.aovDirectory, isAovFileName);
    }
    if (!options.jsonPath.empty()) {
        plan.addFile("--json", options.jsonPath);
    }
    plan.check();
    for (const RenderTarget* target : rendered) {
        if (!target->format) {
            throw SceneError("-o " + printable(target->outputPath) +
                             ": unknown image format (supported: " + kSupportedImageFormats + ")");
        }
    }
}

// Renders every target, each on its own: one that fails is reported and the rest still render.
// The exit code is the first failure's.
int renderEach(const RenderOptions& options, const std::vector<RenderTarget>& targets, GpuSession& gpu,
               std::vector<SceneRecord>& records) {
    Fallback fallback(options.backend);
    int firstFailure = kSuccess;
    std::vector<std::string> failed;
    for (const RenderTarget& target : targets) {
        SceneRecord& record = records.emplace_back();
        record.scenePath = target.scenePath;
        record.outputPath = target.outputPath;
        const std::size_t earlierErrors = errorsPrinted().size();
        const auto start = std::chrono::steady_clock::now();
        const int code = guarded([&] { return renderScene(options, target, gpu, fallback, record); });
        record.totalMilliseconds = millisecondsSince(start);
        record.exitCode = code;
        record.messages.assign(errorsPrinted().begin() + std::ptrdiff_t(earlierErrors), errorsPrinted().end());
        if (code != kSuccess) {
            firstFailure = firstFailure == kSuccess ? code : firstFailure;
            failed.push_back(target.scenePath);
        }
    }
    if (targets.size() > 1 && !quiet()) {
        std::string names;
        for (const std::string& name : failed)
            names += (names.empty() ? "; failed: " : ", ") + printable(name);
        std::printf("rendered %zu of %zu scenes%s\n", targets.size() - failed.size(), targets.size(), names.c_str());
    }
    return firstFailure;
}

}  // namespace

int runRender(const RenderOptions& options) {
    ValidationLog log;
    std::vector<SceneRecord> records;
    std::optional<DeviceInfo> device;
    std::optional<double> startupMilliseconds;
    bool documentMayBeWritten = true;
    const int code = guarded([&] {
        const std::vector<RenderTarget> targets = renderTargets(options);
        try {
            checkPaths(options, targets);
        } catch (const OutputConflict&) {
            documentMayBeWritten = false;  // its own path may be the one that would destroy a file
            throw;
        }
        GpuSession gpu(options.vulkan, log);
        const int rendered = renderEach(options, targets, gpu, records);
        device = gpu.device();
        startupMilliseconds = gpu.startupMilliseconds();
        return rendered;
    });
    const int verdict = withValidationVerdict(code, log);
    if (options.jsonPath.empty() || !documentMayBeWritten) {
        return verdict;
    }
    nlohmann::json document = renderDocument(options, records, device, startupMilliseconds);
    return finishJson(options.jsonPath, document, verdict);
}

}  // namespace hexray::cli
