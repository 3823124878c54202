#pragma once
// `hexray bench`'s results: one row per configuration (speed, the work its kernel does, and its
// errors against two references), printed as markdown tables and written as CSV.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "bench/bench_backends.h"
#include "compare/compare.h"
#include "cpu/cpu_renderer.h"

namespace hexray::inline bench {

// What a scene's configurations are judged against.
struct BenchReference {
    // File scenes: a converged CPU reference (many samples), encoded as the scene asks. The error
    // against it is mostly sampling error (aliasing) at low sample counts. Empty for the curve.
    Rgb8Image converged;
    // The CPU reference at each configuration's own sample count: the error against it is the
    // precision's (and the formulation's); its classes and margins judge the topology.
    std::map<std::uint32_t, CpuRender> bySamples;
};

struct BenchScene {
    std::string name;                      // the file's stem, or "random-spheres"
    std::optional<std::uint32_t> spheres;  // the curve's scenes
    Scene scene;
    BenchReference reference;
};

struct BenchRow {
    BenchConfiguration configuration;
    Precision precision = Precision::Auto;  // GPU: the plan's
    bool chosenByAuto = false;              // GPU: the precision `auto` picks for the scene
    double medianMpix = 0, bestMpix = 0, medianMs = 0, frameMs = 0;
    double planMs = 0, uploadMs = 0;  // GPU: host-side preparation, medians
    unsigned threads = 0;
    double coreNsPerPixel = 0;
    std::optional<double> versusHandWritten;     // the hand-written kernel's row at the same scene and spp
    std::optional<double> versusEmbree;          // the faster Embree row at the same scene and spp
    std::optional<ErrorMetrics> samplingError;   // against the converged reference (file scenes)
    ErrorMetrics precisionError;                 // against the CPU reference at the same sample count
    std::optional<TopologyComparison> topology;  // none for a backend without pixel classes
    std::optional<WorkPerPixel> work;            // GPU kernels generated for the scene
};

std::vector<BenchRow> benchRows(const std::vector<BenchScene>& scenes,
                                const std::vector<BenchConfiguration>& configurations,
                                const std::vector<BenchMeasurement>& measurements, BenchBackends& backends);

// The file scenes' table, the curve's, and the notes, on standard output.
void printBenchTables(const std::vector<BenchScene>& scenes, const std::vector<BenchRow>& rows,
                      const BenchBackends& backends, const std::vector<std::string>& notes);

std::string benchCsv(const std::vector<BenchScene>& scenes, const std::vector<BenchRow>& rows,
                     const BenchBackends& backends);

}  // namespace hexray::bench
