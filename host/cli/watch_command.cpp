// `hexray watch`: one process that keeps the device, its pipelines and its caches, and renders the
// scene again each time its file is saved. A scene's generated kernel with its values as
// specialization constants needs a pipeline of its own (the driver's compile) for every edit; the
// same kernel reading its values from a buffer needs one per structure only. So an edit renders at
// once with the buffered kernel, and the specialised one is built and rendered on a background
// thread, its image (the same) written when it is ready and no newer edit superseded it: the way
// a JIT tiers up. (The data-driven kernel needs no new pipeline at all, but renders a small scene
// about four times slower on lavapipe: as a first tier it would cost value edits more than it
// saves structural ones, docs/performance.md.) Only the main thread writes files and prints.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <functional>
#include <future>
#include <optional>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "cli/command_support.h"
#include "cli/gpu_session.h"
#include "cli/named_values.h"
#include "cli/render_record.h"
#include "cli/render_summary.h"
#include "cli/render_targets.h"
#include "cli/watch_events.h"
#include "gpu/gpu_renderer.h"
#include "image/image_row_writer.h"
#include "image/provenance.h"
#include "io/output_plan.h"
#include "kernels/shader_compiler.h"
#include "scene/scene_loader.h"
#include "util/build_version.h"
#include "util/printable.h"

namespace hexray::cli {
namespace {

// A save may come as a burst of events (a write, then a rename): they are one edit when they
// arrive within this of each other.
constexpr std::chrono::milliseconds kSaveSettle{2};

// The scenes whose generated kernel the background renderer has built, most recent last; fewer
// than the pipelines it keeps, so that one listed here is still there.
constexpr std::size_t kRememberedSpecialisations = kKeptPipelines / 2;

// One edit of the scene, as loaded.
struct Edit {
    std::uint64_t number = 0;  // the edits so far, this one included
    Scene scene;
    std::string identity;  // the scene text's (and the image's provenance)
};

// An edit rendered with its generated kernel on the background thread.
struct TierUp {
    Edit edit;
    RenderPlan plan;
    GpuRenderResult result;
    double planMilliseconds = 0;
    std::chrono::steady_clock::time_point started;
};

std::string imageSize(const ImageSettings& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height);
}

class SceneWatch {
public:
    SceneWatch(const WatchOptions& options, const RenderTarget& target, WatchEvents& events, GpuSession& gpu)
        : options_(options), target_(target), events_(events), gpu_(gpu) {}
    ~SceneWatch() { finishBackground(); }
    SceneWatch(const SceneWatch&) = delete;
    SceneWatch& operator=(const SceneWatch&) = delete;

    // Renders now and after each save, until a stop signal or --frames images; the exit code.
    int run();

private:
    bool framesDone() const { return options_.frames != 0 && written_ >= options_.frames; }
    int renderSaved();
    WatchKernel kernelFor(const Edit& edit) const;
    void renderEdit(Edit edit, std::chrono::steady_clock::time_point start);
    void collectTierUp();
    void startTierUp();
    void finishBackground();
    bool specialisedFor(const std::string& identity) const;
    void rememberSpecialised(const std::string& identity);
    GpuRenderer& specialisedRenderer();
    void write(const Edit& edit, const RenderPlan& plan, const std::function<GpuRenderResult(ImageRowWriter&)>& render,
               SceneRecord& record, const std::string& tier, std::chrono::steady_clock::time_point start);

    const WatchOptions& options_;
    const RenderTarget& target_;
    WatchEvents& events_;
    GpuSession& gpu_;
    std::optional<GpuRenderer> specialised_;  // only the background thread uses it while one runs
    std::uint64_t edits_ = 0;
    std::uint64_t written_ = 0;
    std::optional<Edit> pending_;  // the latest edit waiting for the background thread
    std::thread background_;
    std::future<TierUp> tierUp_;
    std::deque<std::string> specialisedScenes_;
    bool startsVulkan_ = false;  // the next image's summary counts Vulkan's start-up
};

// Whether a failure ends the watch: a scene that cannot be read or an image that cannot be
// written may be fixed by the next save; a device that failed will not.
bool endsWatch(int code) {
    return code != kSuccess && code != kBadInput && code != kOutputFailed;
}

int SceneWatch::run() {
    int code = renderSaved();
    std::optional<std::chrono::steady_clock::time_point> settleUntil;
    while (!endsWatch(code) && !framesDone()) {
        switch (events_.next(settleUntil)) {
            case WatchEvents::Event::Stop:
                return kSuccess;
            case WatchEvents::Event::SceneSaved:
                settleUntil = std::chrono::steady_clock::now() + kSaveSettle;
                break;
            case WatchEvents::Event::TimedOut:
                settleUntil.reset();
                code = renderSaved();
                break;
            case WatchEvents::Event::Woken:
                code = guarded([&] {
                    collectTierUp();
                    return int(kSuccess);
                });
                break;
        }
    }
    return endsWatch(code) ? code : kSuccess;
}

int SceneWatch::renderSaved() {
    const auto start = std::chrono::steady_clock::now();
    return guarded([&] {
        startsVulkan_ = !gpu_.started();
        Edit edit{++edits_, {}, {}};
        edit.scene = loadScene(target_.scenePath, options_.image, &edit.identity);
        renderEdit(std::move(edit), start);
        return int(kSuccess);
    });
}

// The kernel this thread renders an edit with: tiered, the specialised one if the background
// thread built it for exactly this scene (and is idle), else the one reading values from a buffer.
WatchKernel SceneWatch::kernelFor(const Edit& edit) const {
    if (!isSmallScene(edit.scene)) {
        return WatchKernel::DataDriven;  // no kernel is generated for a large scene
    }
    if (options_.kernel != WatchKernel::Tiered) {
        return options_.kernel;
    }
    return !background_.joinable() && specialisedFor(edit.identity) ? WatchKernel::Specialised : WatchKernel::Buffered;
}

// Renders `edit` on this thread, and with the kernel reading values from a buffer, hands the
// specialised one to the background thread.
void SceneWatch::renderEdit(Edit edit, std::chrono::steady_clock::time_point start) {
    SceneRecord record;
    record.loadMilliseconds = millisecondsSince(start);
    const WatchKernel kernel = kernelFor(edit);
    GpuRenderer& renderer = kernel == WatchKernel::Specialised ? specialisedRenderer() : gpu_.renderer();
    const auto planStart = std::chrono::steady_clock::now();
    const RenderPlan plan = renderer.plan(edit.scene, {.precision = options_.precision,
                                                       .generatedKernel = kernel != WatchKernel::DataDriven,
                                                       .valuesInBuffer = kernel == WatchKernel::Buffered});
    const double planMilliseconds = millisecondsSince(planStart);
    for (const std::string& warning : plan.warnings) {
        std::fprintf(stderr, "hexray: warning: %s\n", warning.c_str());
    }
    write(
        edit, plan,
        [&](ImageRowWriter& writer) {
            GpuRenderResult result = renderer.renderEncodedRows(
                edit.scene, plan,
                [&](std::uint32_t, std::span<const std::uint8_t> rows) { writer.writeEncoded(rows); });
            record.gpu = gpuSceneRecord(plan, result, planMilliseconds);
            return result;
        },
        record, nameOf(kWatchKernelNames, kernel), start);
    if (options_.kernel == WatchKernel::Tiered && kernel == WatchKernel::Buffered && !framesDone()) {
        pending_ = std::move(edit);  // replaces an older edit not yet started
        startTierUp();
    }
}

// Writes the image `render` makes into the output, atomically, and prints the summary line.
void SceneWatch::write(const Edit& edit, const RenderPlan& plan,
                       const std::function<GpuRenderResult(ImageRowWriter&)>& render, SceneRecord& record,
                       const std::string& tier, std::chrono::steady_clock::time_point start) {
    const ImageSettings& image = edit.scene.image;
    const std::string device = gpu_.context().selected().name;
    const Provenance provenance{.version = hexrayVersion(),
                                .gitRevision = hexrayGitRevision(),
                                .image = "render",
                                .scene = edit.identity,
                                .backend = "gpu",
                                .device = device,
                                .precision = std::string(precisionName(plan.precision)),
                                .samplesPerPixel = image.samplesPerPixel,
                                .width = image.width,
                                .height = image.height};
    ImageRowWriter writer(target_.outputPath, *target_.format, image.width, image.height, image.encoding, provenance);
    const GpuRenderResult result = render(writer);
    const auto writeStart = std::chrono::steady_clock::now();
    writer.finish();
    record.writeMilliseconds = millisecondsSince(writeStart);
    ++written_;
    const std::optional<double> startup = startsVulkan_ ? gpu_.startupMilliseconds() : std::nullopt;
    startsVulkan_ = false;
    printWrote(target_.outputPath, imageSize(image), describeGpuRender(plan, result, device, tier),
               describeTimeParts(record, startup, millisecondsSince(start)));
}

// The background thread's image, written if no newer edit came meanwhile; then the next edit's.
void SceneWatch::collectTierUp() {
    if (!background_.joinable() || tierUp_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
        return;
    }
    background_.join();
    std::optional<TierUp> done;
    done.emplace(tierUp_.get());  // the background thread's failure, thrown here
    rememberSpecialised(done->edit.identity);
    if (done->edit.number == edits_ && !pending_) {
        SceneRecord record;
        record.gpu = gpuSceneRecord(done->plan, done->result, done->planMilliseconds);
        const auto bytes = std::span<const std::uint8_t>(done->result.encoded.bytes);
        write(
            done->edit, done->plan,
            [&](ImageRowWriter& writer) {
                writer.writeEncoded(bytes);
                return done->result;
            },
            record, "specialised", done->started);
    }
    startTierUp();
}

// Starts the background thread on the pending edit, unless it is busy.
void SceneWatch::startTierUp() {
    if (background_.joinable() || !pending_ || framesDone()) {
        return;
    }
    GpuRenderer& renderer = specialisedRenderer();
    std::promise<TierUp> promise;
    tierUp_ = promise.get_future();
    background_ = std::thread([this, &renderer, edit = std::move(*pending_), promise = std::move(promise)]() mutable {
        try {
            TierUp done{std::move(edit), {}, {}, 0, std::chrono::steady_clock::now()};
            done.plan = renderer.plan(done.edit.scene, {.precision = options_.precision});
            done.planMilliseconds = millisecondsSince(done.started);
            done.result = renderer.render(done.edit.scene, done.plan, GpuOutput::Encoded8);
            promise.set_value(std::move(done));
        } catch (...) {
            promise.set_exception(std::current_exception());
        }
        events_.wake();
    });
    pending_.reset();
}

// Waits for the background thread, dropping its image: at exit, the renderer it uses goes.
void SceneWatch::finishBackground() {
    if (background_.joinable()) {
        background_.join();
    }
}

bool SceneWatch::specialisedFor(const std::string& identity) const {
    return std::find(specialisedScenes_.begin(), specialisedScenes_.end(), identity) != specialisedScenes_.end();
}

void SceneWatch::rememberSpecialised(const std::string& identity) {
    if (!specialisedFor(identity)) {
        specialisedScenes_.push_back(identity);
    }
    if (specialisedScenes_.size() > kRememberedSpecialisations) {
        specialisedScenes_.pop_front();
    }
}

GpuRenderer& SceneWatch::specialisedRenderer() {
    if (!specialised_) {
        specialised_.emplace(gpu_.context());
    }
    return *specialised_;
}

// The output: a PNG file (the background thread's image is 8-bit), checked before any work.
RenderTarget watchTarget(const WatchOptions& options) {
    RenderOptions render;
    render.scenePaths = {options.scenePath};
    render.outputPath = options.outputPath;
    std::vector<RenderTarget> targets = renderTargets(render);
    if (targets.size() != 1 || !targets[0].problem.empty() || options.scenePath == "-") {
        throw SceneError(printable(options.scenePath) + ": watch needs one scene file");
    }
    std::error_code error;
    if (!std::filesystem::is_regular_file(options.scenePath, error)) {  // a typo, not a scene to be written
        throw SceneError(printable(options.scenePath) + ": no such scene file");
    }
    OutputPlan plan;
    plan.addInput("the scene", targets[0].scenePath);
    plan.addFile("-o", targets[0].outputPath);
    plan.check();
    if (targets[0].format != ImageFormat::Png || targets[0].outputPath == "-") {
        throw SceneError("-o " + printable(targets[0].outputPath) + ": watch writes a PNG file");
    }
    return targets[0];
}

}  // namespace

int runWatch(const WatchOptions& options) {
    ValidationLog log;
    const int code = guarded([&] {
        const RenderTarget target = watchTarget(options);
        WatchEvents events(target.scenePath);       // before any thread starts: it blocks the stop signals
        const ShaderCompilerWarmUp compilerWarmUp;  // glslang sets itself up while Vulkan starts
        GpuSession gpu(options.vulkan, log);
        SceneWatch watch(options, target, events, gpu);
        return watch.run();
    });
    return withValidationVerdict(code, log);
}

}  // namespace hexray::cli
