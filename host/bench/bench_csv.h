#pragma once
// `hexray bench --csv`: a row per configuration, data for a script. Every dimension of a
// configuration is a column, so (scene, spheres, width, height, backend, kernel, precision_asked,
// precision_used, culling_asked, culling_used, spp) tells every row apart; numbers are written in
// full (shortest round-trip form); a cell that does not apply is empty (docs/performance.md).

#include <string>
#include <vector>

#include "bench/bench_report.h"

namespace hexray::inline bench {

std::string benchCsv(const std::vector<BenchScene>& scenes, const std::vector<BenchRow>& rows,
                     const BenchBackends& backends);

}  // namespace hexray::bench
