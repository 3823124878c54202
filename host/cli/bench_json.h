#pragma once
// `hexray bench --json`: the bench's scenes, each with its configurations' speed and error, as the
// document's "scenes" (docs/json-output.md, the schema's $defs/bench).

#include <vector>

#include <nlohmann/json.hpp>

#include "bench/bench_report.h"

namespace hexray::cli {

// [{"name", "spheres", "width", "height", "configurations": [...]}, ...], in the bench's order.
nlohmann::json benchScenesJson(const std::vector<BenchScene>& scenes, const std::vector<BenchRow>& rows,
                               const BenchBackends& backends);

}  // namespace hexray::cli
