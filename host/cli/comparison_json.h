#pragma once
// `hexray compare --json`: the comparisons as data (docs/json-output.md, "compare").

#include <vector>

#include <nlohmann/json.hpp>

#include "cli/comparison_record.h"

namespace hexray::cli {

// Sets the document's "results" (one object per comparison) and "summary" (the count line's figures).
void addComparisons(nlohmann::json& document, const std::vector<ComparisonRecord>& records);

}  // namespace hexray::cli
