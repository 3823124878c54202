#include "cli/comparison_json.h"

#include "cli/json_document.h"

namespace hexray::cli {
namespace {

nlohmann::json metricsJson(const ErrorMetrics& m) {
    return {{"pixels", m.pixels},
            {"max_abs", m.maxAbs},
            {"mean_abs", m.meanAbs},
            {"rmse", m.rmse},
            {"psnr_db", jsonNumber(m.psnr)},
            {"pixels_over_one_level", m.pixelsOverOneLevel},
            {"share_over_one_level", m.shareOverOneLevel}};
}

nlohmann::json topologyJson(const TopologyComparison& t) {
    return {{"pixels", t.pixels},
            {"ambiguous", t.ambiguous},
            {"ambiguous_share", t.ambiguousShare()},
            {"excused", t.excused},
            {"excused_share", t.excusedShare()},
            {"mismatches", t.mismatches},
            {"node_mismatches", t.nodeMismatches},
            {"checker_mismatches", t.checkerMismatches},
            {"light_mismatches", t.lightMismatches}};
}

nlohmann::json toleranceJson(const Tolerance& tolerance) {
    return {{"max_topology_mismatches", tolerance.maxTopologyMismatches},
            {"max_bad_pixels_percent", tolerance.maxSharePercent},
            {"max_rmse_levels", tolerance.maxRmseLevels},
            {"max_ambiguous_percent", tolerance.maxAmbiguousPercent}};
}

nlohmann::json checksJson(const Verdict& v) {
    return {{"invalid_colours", v.valuesOk},
            {"topology_mismatches", v.topologyOk},
            {"ambiguous_share", v.ambiguousOk},
            {"bad_pixels", v.shareOk},
            {"rmse", v.rmseOk}};
}

nlohmann::json expectationJson(const SceneExpectation& expectation) {
    if (expectation.place.empty()) {
        return {{"expect", "pass"}, {"why", nullptr}, {"entry", nullptr}};
    }
    return {{"expect", expectedName(expectation.expect)}, {"why", expectation.why}, {"entry", expectation.place}};
}

nlohmann::json recordJson(const ComparisonRecord& r) {
    nlohmann::json json = {{"scene", r.scenePath},
                           {"name", r.name},
                           {"outcome", outcomeName(r.outcome.outcome)},
                           {"reason", r.outcome.reason}};
    if (!r.loadError.empty()) {
        json["error"] = r.loadError;
        return json;
    }
    json.update({{"width", r.width},
                 {"height", r.height},
                 {"encoding", r.encoding == Encoding::Srgb ? "srgb" : "linear"},
                 {"precision_requested", precisionName(r.requested)},
                 {"precision", precisionName(r.precision)},
                 {"chosen_by_auto", r.chosenByAuto},
                 {"judged", r.judged},
                 {"passed_tolerance", r.verdict.passed()},
                 {"checks", checksJson(r.verdict)},
                 {"tolerance", toleranceJson(r.expectation.tolerance)},
                 {"expectation", expectationJson(r.expectation)},
                 {"topology", topologyJson(r.comparison.topology)},
                 {"linear", metricsJson(r.comparison.linear)},
                 {"encoded", metricsJson(r.comparison.encoded)},
                 {"invalid_colours", r.comparison.invalidColours},
                 {"flip_mean", jsonNumber(r.flipMean)},
                 {"timings_ms", {{"gpu_render", r.gpuMilliseconds}, {"cpu_reference", r.cpuMilliseconds}}},
                 {"cpu_threads", r.cpuThreads}});
    return json;
}

}  // namespace

void addComparisons(nlohmann::json& document, const std::vector<ComparisonRecord>& records) {
    nlohmann::json results = nlohmann::json::array();
    for (const ComparisonRecord& record : records) {
        results.push_back(recordJson(record));
    }
    const OutcomeCounts counts = countOutcomes(records);
    document["results"] = std::move(results);
    document["summary"] = {{"passed", counts.passed},
                           {"expected", counts.expected},
                           {"failed", counts.failed},
                           {"not_judged", counts.notJudged},
                           {"gate", counts.gatePassed() ? "pass" : "fail"}};
}

}  // namespace hexray::cli
