#pragma once
// `hexray bench`'s results: one row per configuration (speed, the work its kernel does, and its
// errors against two references), printed as markdown tables (bench_csv.h and the command's --json
// write them as data).

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
    // What the configuration asked for and what ran. Asked: the renderer's configurable backend
    // only. Used: the arithmetic of every backend (the CPU reference f64, Embree f32, the
    // hand-written kernel the textbook f32-naive).
    std::optional<Precision> precisionAsked;
    Precision precision = Precision::Auto;  // used
    bool chosenByAuto = false;              // GPU: the precision `auto` picks for the scene
    BenchKernel kernel = BenchKernel::None;
    std::optional<bool> cullingAsked;  // the renderer's configurable backend only
    std::optional<bool> cullingUsed;   // GPU: whether tile classes rendered it
    double medianMpix = 0, bestMpix = 0, medianMs = 0, frameMs = 0;
    std::optional<double> planMs, uploadMs;  // GPU: host-side preparation, medians
    unsigned threads = 0;                    // 0 for a real GPU
    double coreNsPerPixel = 0;
    std::optional<double> versusHandWritten;    // the hand-written kernel's row at the same scene and spp
    std::optional<double> versusEmbree;         // the faster Embree row at the same scene and spp
    std::optional<ErrorMetrics> samplingError;  // against the converged reference (file scenes)
    ErrorMetrics precisionError;                // against the CPU reference at the same sample count
    // Mean LDR-FLIP of the 8-bit output against that reference, every pixel (compare/band_flip.h);
    // none past its size bound.
    std::optional<double> flipMean;
    std::optional<TopologyComparison> topology;  // none for a backend without pixel classes
    std::optional<WorkPerPixel> work;            // GPU kernels generated for the scene
    // f32-certified: the shares of the pixels, and of the 8-pixel vectors (lavapipe's lanes), that a
    // decision in doubt sent to the f64 pass.
    std::optional<double> fallbackPixelShare, fallbackVectorShare;
};

bool isGpu(BenchBackend backend);

std::vector<BenchRow> benchRows(const std::vector<BenchScene>& scenes,
                                const std::vector<BenchConfiguration>& configurations,
                                const std::vector<BenchMeasurement>& measurements, BenchBackends& backends);

// The file scenes' table, the curve's, and the notes, on standard output.
void printBenchTables(const std::vector<BenchScene>& scenes, const std::vector<BenchRow>& rows,
                      const BenchBackends& backends, const std::vector<std::string>& notes);

}  // namespace hexray::bench
