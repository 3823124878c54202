#include "cli/render_record.h"

#include "cli/json_document.h"
#include "cli/named_values.h"

namespace hexray::cli {
namespace {

using nlohmann::json;

json optionalText(const std::string& text) {
    return text.empty() ? json(nullptr) : json(text);
}

json requested(const RenderOptions& options) {
    return {{"backend", nameOf(kBackendNames, options.backend)},
            {"precision", std::string(precisionName(options.precision))},
            {"culling", nameOf(kCullingNames, options.culling)},
            {"strip",
             options.strip ? json{{"index", options.strip->index}, {"count", options.strip->count}} : json(nullptr)},
            {"threads", options.threads ? json(options.threads) : json(nullptr)},
            {"output", optionalText(options.outputPath)},
            {"aov_directory", optionalText(options.aovDirectory)}};
}

// f32-certified: the pixels a decision in doubt sent to the f64 pass; null for other precisions.
json f64Pass(const GpuSceneRecord& gpu) {
    const CertifiedFallback& pass = gpu.timing.fallback;
    if (gpu.precision != Precision::F32Certified || pass.totalPixels == 0) {
        return nullptr;
    }
    return {{"pixels", pass.pixels},
            {"pixel_share", double(pass.pixels) / double(pass.totalPixels)},
            {"vector_share", double(pass.vectors) / double(pass.totalVectors)}};
}

json kernel(const GpuSceneRecord& gpu) {
    return {{"kind", gpu.generatedKernel ? "generated" : "data-driven"},
            {"name", gpu.kernelName},
            {"tile_classes", gpu.tileClasses},
            {"candidate_lists", gpu.candidateLists},
            {"from_disk_cache", gpu.generatedKernel ? json(gpu.timing.kernel.fromDiskCache) : json(nullptr)},
            {"f64_pass", f64Pass(gpu)}};
}

// Every stage's milliseconds; null for a stage the scene's backend has not, or did not reach.
json timings(const SceneRecord& scene) {
    const GpuSceneRecord* gpu = scene.gpu ? &*scene.gpu : nullptr;
    const auto onGpu = [&](auto stage) { return gpu ? jsonNumber(stage(*gpu)) : json(nullptr); };
    const auto generatedOnly = [&](auto stage) {
        return gpu && gpu->generatedKernel ? jsonNumber(stage(gpu->timing.kernel)) : json(nullptr);
    };
    json render = onGpu([](const GpuSceneRecord& g) { return g.timing.renderMilliseconds; });
    if (scene.cpu) {
        render = jsonNumber(scene.cpu->renderMilliseconds);
    }
    return {{"load", jsonNumber(scene.loadMilliseconds)},
            {"plan", onGpu([](const GpuSceneRecord& g) { return g.planMilliseconds; })},
            {"upload", onGpu([](const GpuSceneRecord& g) { return g.timing.uploadMilliseconds; })},
            {"kernel_generate", generatedOnly([](const KernelBuild& k) { return k.generateMilliseconds; })},
            {"kernel_compile", generatedOnly([](const KernelBuild& k) { return k.compileMilliseconds; })},
            {"kernel_cache_read", generatedOnly([](const KernelBuild& k) { return k.loadMilliseconds; })},
            {"first_dispatch", onGpu([](const GpuSceneRecord& g) { return g.timing.firstDispatchMilliseconds; })},
            {"render", render},
            {"write", jsonNumber(scene.writeMilliseconds)},
            {"total", jsonNumber(scene.totalMilliseconds)}};
}

json renderClock(const SceneRecord& scene) {
    if (scene.cpu) {
        return "host";
    }
    return scene.gpu ? json(scene.gpu->timing.fromTimestamps ? "device_timestamps" : "host") : json(nullptr);
}

json backend(const SceneRecord& scene) {
    return scene.gpu ? json("gpu") : scene.cpu ? json("cpu") : json(nullptr);
}

json sceneJson(const SceneRecord& scene) {
    const std::optional<ImageSettings>& image = scene.image;
    const GpuSceneRecord* gpu = scene.gpu ? &*scene.gpu : nullptr;
    return {
        {"scene", scene.scenePath},
        {"output", optionalText(scene.outputPath)},
        {"exit", {{"code", scene.exitCode}, {"name", exitCodeName(scene.exitCode)}, {"messages", scene.messages}}},
        {"width", image ? json(image->width) : json(nullptr)},
        {"height", image ? json(image->height) : json(nullptr)},
        {"spp", image ? json(image->samplesPerPixel) : json(nullptr)},
        {"rows", scene.rows ? json{{"first", scene.rows->first}, {"count", scene.rows->count}} : json(nullptr)},
        {"backend", backend(scene)},
        {"fallback_reason", optionalText(scene.fallbackReason)},
        {"precision", gpu ? json(std::string(precisionName(gpu->precision))) : json(nullptr)},
        {"culling", gpu ? json(gpu->tileClasses > 0) : json(nullptr)},
        {"kernel", gpu ? kernel(*gpu) : json(nullptr)},
        {"warnings", gpu ? gpu->warnings : std::vector<std::string>{}},
        {"cpu_threads", scene.cpu ? json(scene.cpu->threads) : json(nullptr)},
        {"aov_files", scene.aovFiles ? json(*scene.aovFiles) : json(nullptr)},
        {"render_clock", renderClock(scene)},
        {"timings_ms", timings(scene)},
    };
}

}  // namespace

nlohmann::json renderDocument(const RenderOptions& options, const std::vector<SceneRecord>& scenes,
                              const std::optional<DeviceInfo>& device, std::optional<double> startupMilliseconds) {
    json document = jsonDocument("render");
    document["requested"] = requested(options);
    document["device"] = device ? jsonDevice(*device) : json(nullptr);
    document["timings_ms"]["startup"] = jsonNumber(startupMilliseconds);
    std::size_t failed = 0;
    json entries = json::array();
    for (const SceneRecord& scene : scenes) {
        failed += scene.exitCode != kSuccess ? 1 : 0;
        entries.push_back(sceneJson(scene));
    }
    document["scenes"] = std::move(entries);
    document["scenes_rendered"] = scenes.size() - failed;
    document["scenes_failed"] = failed;
    return document;
}

}  // namespace hexray::cli
