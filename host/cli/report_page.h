#pragma once
// `hexray compare --report DIR`'s page, DIR/index.html: static HTML that works from file:// with
// no network and no framework, after Blender's render-test report. A summary table (one row per
// comparison, carrying its scene, precision, outcome, RMSE and ambiguous share as data- attributes for scripts and
// tests), then per comparison the GPU render, the CPU reference, the heat map and the mask side
// by side; hovering over or clicking the GPU image shows the reference in its place. On load, a
// few lines of script count the images that loaded and those that did not into
// <output id="image-check" data-loaded data-failed>.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/comparison_record.h"

namespace hexray::cli {

// `document`: the command's --json document (for the device, the build and the summary).
std::string reportPage(const std::vector<ComparisonRecord>& records, const nlohmann::json& document);

}  // namespace hexray::cli
