#include "bench/bench_selection.h"

#include <algorithm>

namespace hexray::inline bench {

const std::vector<BenchRowName>& benchRowNames() {
    using K = BenchRowKind;
    static const std::vector<BenchRowName> names = {
        {"gpu", {K::GpuF32, K::GpuF64, K::GpuF32Naive, K::GpuF32Certified}},
        {"gpu-f32", {K::GpuF32}},
        {"gpu-f64", {K::GpuF64}},
        {"gpu-f32-naive", {K::GpuF32Naive}},
        {"gpu-f32-certified", {K::GpuF32Certified}},
        {"hand-written", {K::HandWritten}},
        {"cpu", {K::Cpu}},
        {"embree", {K::Embree}},
        {"embree-f64-packets", {K::EmbreeF64Packets}},
        {"embree-f64-single", {K::EmbreeF64Single}},
        {"all",
         {K::GpuF32, K::GpuF64, K::GpuF32Naive, K::GpuF32Certified, K::HandWritten, K::Cpu, K::Embree,
          K::EmbreeF64Packets, K::EmbreeF64Single}},
    };
    return names;
}

const std::vector<std::string>& defaultBenchRowNames() {
    // Embree's rows that shade in double measure hexray's use of Embree more than Embree: on request.
    static const std::vector<std::string> names = {"gpu", "hand-written", "cpu", "embree"};
    return names;
}

BenchSelection selectBenchRows(const std::vector<std::string>& names) {
    BenchSelection selection;
    for (const std::string& name : names.empty() ? defaultBenchRowNames() : names) {
        const auto& all = benchRowNames();
        const auto found =
            std::find_if(all.begin(), all.end(), [&](const BenchRowName& row) { return row.name == name; });
        if (found != all.end()) {
            selection.insert(found->kinds.begin(), found->kinds.end());
        }
    }
    return selection;
}

}  // namespace hexray::bench
