#include "bench/bench_csv.h"

#include <charconv>
#include <cmath>
#include <functional>
#include <optional>
#include <type_traits>

namespace hexray::inline bench {
namespace {

// The shortest text that reads back as the same double; empty for none or a non-finite value.
std::string number(const std::optional<double>& value) {
    if (!value || !std::isfinite(*value)) {
        return "";
    }
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, *value);
    return std::string(text, result.ptr);
}

std::string count(const std::optional<std::uint64_t>& value) {
    return value ? std::to_string(*value) : "";
}

// RFC 4180: a field holding a comma, quote or line break is quoted, its quotes doubled.
std::string text(const std::string& value) {
    if (value.find_first_of(",\"\r\n") == std::string::npos) {
        return value;
    }
    std::string quoted = "\"";
    for (const char c : value) {
        quoted += c == '"' ? "\"\"" : std::string(1, c);
    }
    return quoted + "\"";
}

std::string onOff(const std::optional<bool>& value) {
    return value ? (*value ? "on" : "off") : "";
}

template <typename T, typename F>
auto optionalField(const std::optional<T>& holder, F field)
    -> std::optional<std::remove_cvref_t<std::invoke_result_t<F, const T&>>> {
    if (!holder) {
        return std::nullopt;
    }
    return std::invoke(field, *holder);
}

// A column: its header and its cell for a row.
struct Column {
    const char* name;
    std::function<std::string(const BenchScene&, const BenchRow&)> cell;
};

std::vector<Column> columns(const BenchBackends& backends) {
    using S = const BenchScene&;
    using R = const BenchRow&;
    return {
        {"scene", [](S s, R) { return text(s.name); }},
        {"spheres", [](S s, R) { return count(s.spheres); }},
        {"width", [](S s, R) { return std::to_string(s.scene.image.width); }},
        {"height", [](S s, R) { return std::to_string(s.scene.image.height); }},
        {"backend", [&backends](S, R r) { return text(backends.name(r.configuration.backend)); }},
        {"kernel", [](S, R r) { return std::string(benchKernelName(r.kernel)); }},
        {"precision_asked",
         [](S, R r) { return r.precisionAsked ? std::string(precisionName(*r.precisionAsked)) : ""; }},
        {"precision_used", [](S, R r) { return std::string(precisionName(r.precision)); }},
        {"auto_pick", [](S, R r) { return r.precisionAsked ? std::string(r.chosenByAuto ? "true" : "false") : ""; }},
        {"culling_asked", [](S, R r) { return onOff(r.cullingAsked); }},
        {"culling_used", [](S, R r) { return onOff(r.cullingUsed); }},
        {"spp", [](S, R r) { return std::to_string(r.configuration.samplesPerPixel); }},
        {"median_mpix_s", [](S, R r) { return number(r.medianMpix); }},
        {"best_mpix_s", [](S, R r) { return number(r.bestMpix); }},
        {"median_render_ms", [](S, R r) { return number(r.medianMs); }},
        {"median_frame_ms", [](S, R r) { return number(r.frameMs); }},
        {"plan_ms", [](S, R r) { return number(r.planMs); }},
        {"upload_ms", [](S, R r) { return number(r.uploadMs); }},
        {"threads", [](S, R r) { return r.threads ? std::to_string(r.threads) : ""; }},
        {"core_ns_per_pixel", [](S, R r) { return r.threads ? number(r.coreNsPerPixel) : ""; }},
        {"vs_hand_written", [](S, R r) { return number(r.versusHandWritten); }},
        {"vs_embree", [](S, R r) { return number(r.versusEmbree); }},
        {"primary_tests_per_pixel", [](S, R r) { return number(optionalField(r.work, &WorkPerPixel::primaryTests)); }},
        {"shadow_rays_per_pixel", [](S, R r) { return number(optionalField(r.work, &WorkPerPixel::shadowRays)); }},
        {"shadow_tests_per_pixel", [](S, R r) { return number(optionalField(r.work, &WorkPerPixel::shadowTests)); }},
        {"sampling_rmse_levels", [](S, R r) { return number(optionalField(r.samplingError, &ErrorMetrics::rmse)); }},
        {"f64_pass_pixel_share", [](S, R r) { return number(r.fallbackPixelShare); }},
        {"f64_pass_vector_share", [](S, R r) { return number(r.fallbackVectorShare); }},
        {"precision_rmse_levels", [](S, R r) { return number(r.precisionError.rmse); }},
        {"precision_flip_mean", [](S, R r) { return number(r.flipMean); }},
        {"precision_max_abs_levels", [](S, R r) { return number(r.precisionError.maxAbs); }},
        {"pixels_over_one_level", [](S, R r) { return std::to_string(r.precisionError.pixelsOverOneLevel); }},
        {"share_over_one_level", [](S, R r) { return number(r.precisionError.shareOverOneLevel); }},
        {"ambiguous_share",
         [](S, R r) { return number(r.topology ? std::optional(r.topology->ambiguousShare()) : std::nullopt); }},
        {"topology_mismatches",
         [](S, R r) { return count(optionalField(r.topology, &TopologyComparison::mismatches)); }},
    };
}

}  // namespace

std::string benchCsv(const std::vector<BenchScene>& scenes, const std::vector<BenchRow>& rows,
                     const BenchBackends& backends) {
    const std::vector<Column> all = columns(backends);
    std::string csv;
    for (const Column& column : all) {
        csv += (csv.empty() ? "" : ",") + std::string(column.name);
    }
    csv += '\n';
    for (const BenchRow& row : rows) {
        const BenchScene& scene = scenes[row.configuration.scene];
        for (std::size_t i = 0; i < all.size(); ++i) {
            csv += (i ? "," : "") + all[i].cell(scene, row);
        }
        csv += '\n';
    }
    return csv;
}

}  // namespace hexray::bench
