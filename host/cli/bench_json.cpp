#include "cli/bench_json.h"

#include <optional>

#include "cli/json_document.h"

namespace hexray::cli {
namespace {

template <typename T>
nlohmann::json orNull(const std::optional<T>& value) {
    return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

nlohmann::json numberOrNull(const std::optional<double>& value) {
    return value ? jsonNumber(*value) : nlohmann::json(nullptr);
}

nlohmann::json errorJson(const ErrorMetrics& error) {
    return {{"pixels", error.pixels},
            {"max_abs_levels", jsonNumber(error.maxAbs)},
            {"mean_abs_levels", jsonNumber(error.meanAbs)},
            {"rmse_levels", jsonNumber(error.rmse)},
            {"psnr_db", jsonNumber(error.psnr)},
            {"pixels_over_one_level", error.pixelsOverOneLevel},
            {"share_over_one_level", jsonNumber(error.shareOverOneLevel)}};
}

nlohmann::json topologyJson(const std::optional<TopologyComparison>& topology) {
    if (!topology) {
        return nullptr;
    }
    return {{"pixels", topology->pixels},
            {"ambiguous", topology->ambiguous},
            {"ambiguous_share", jsonNumber(topology->ambiguousShare())},
            {"excused", topology->excused},
            {"excused_share", jsonNumber(topology->excusedShare())},
            {"mismatches", topology->mismatches},
            {"node_mismatches", topology->nodeMismatches},
            {"checker_mismatches", topology->checkerMismatches},
            {"light_mismatches", topology->lightMismatches}};
}

nlohmann::json speedJson(const BenchRow& row) {
    return {{"median_mpix_s", jsonNumber(row.medianMpix)},
            {"best_mpix_s", jsonNumber(row.bestMpix)},
            {"median_render_ms", jsonNumber(row.medianMs)},
            {"median_frame_ms", jsonNumber(row.frameMs)},
            {"median_plan_ms", numberOrNull(row.planMs)},
            {"median_upload_ms", numberOrNull(row.uploadMs)},
            {"threads", row.threads ? nlohmann::json(row.threads) : nlohmann::json(nullptr)},
            {"core_ns_per_pixel", row.threads ? jsonNumber(row.coreNsPerPixel) : nlohmann::json(nullptr)},
            {"vs_hand_written", numberOrNull(row.versusHandWritten)},
            {"vs_embree", numberOrNull(row.versusEmbree)}};
}

nlohmann::json workJson(const std::optional<WorkPerPixel>& work) {
    if (!work) {
        return nullptr;
    }
    return {
        {"primary_tests", work->primaryTests}, {"shadow_rays", work->shadowRays}, {"shadow_tests", work->shadowTests}};
}

nlohmann::json configurationJson(const BenchRow& row, const BenchBackends& backends) {
    const char* kernel = benchKernelName(row.kernel);
    return {
        {"backend", backends.name(row.configuration.backend)},
        {"kernel", *kernel ? nlohmann::json(kernel) : nlohmann::json(nullptr)},
        {"precision",
         {{"asked", row.precisionAsked ? nlohmann::json(precisionName(*row.precisionAsked)) : nlohmann::json(nullptr)},
          {"used", precisionName(row.precision)},
          {"auto_pick", row.precisionAsked ? nlohmann::json(row.chosenByAuto) : nlohmann::json(nullptr)}}},
        {"culling", {{"asked", orNull(row.cullingAsked)}, {"used", orNull(row.cullingUsed)}}},
        {"spp", row.configuration.samplesPerPixel},
        {"speed", speedJson(row)},
        {"work_per_pixel", workJson(row.work)},
        {"f64_pass",
         {{"pixel_share", numberOrNull(row.fallbackPixelShare)},
          {"vector_share", numberOrNull(row.fallbackVectorShare)}}},
        {"error",
         {{"sampling", row.samplingError ? errorJson(*row.samplingError) : nlohmann::json(nullptr)},
          {"precision", errorJson(row.precisionError)},
          {"flip_mean", numberOrNull(row.flipMean)},
          {"topology", topologyJson(row.topology)}}},
    };
}

}  // namespace

nlohmann::json benchScenesJson(const std::vector<BenchScene>& scenes, const std::vector<BenchRow>& rows,
                               const BenchBackends& backends) {
    nlohmann::json list = nlohmann::json::array();
    for (std::size_t index = 0; index < scenes.size(); ++index) {
        const BenchScene& scene = scenes[index];
        nlohmann::json configurations = nlohmann::json::array();
        for (const BenchRow& row : rows) {
            if (row.configuration.scene == index) {
                configurations.push_back(configurationJson(row, backends));
            }
        }
        list.push_back({{"name", scene.name},
                        {"spheres", orNull(scene.spheres)},
                        {"width", scene.scene.image.width},
                        {"height", scene.scene.image.height},
                        {"configurations", std::move(configurations)}});
    }
    return list;
}

}  // namespace hexray::cli
