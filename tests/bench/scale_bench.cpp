// Prints how long one scene file takes to load and its sphere BVH to build on each thread
// count (medians of interleaved rounds), and the process's peak memory after loading it. A
// figure for the reader, not a test: see tools/scale-bench.sh, which runs it once per file so that
// the peak belongs to that file.

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "accel/bvh.h"
#include "bench/median.h"
#include "scene/scene_loader.h"
#include "util/milliseconds_since.h"

using namespace hexray;
using bench::median;

namespace {

double peakResidentMiB() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_maxrss) / 1024.0;  // kilobytes on Linux
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Scene loading and BVH building at scale"};
    std::string file;
    int rounds = 3;
    std::vector<unsigned> threadCounts{1, 2};
    app.add_option("scene", file, "a scene file (e.g. from tools/make-spheres-scene.py)")
        ->required()
        ->check(CLI::ExistingFile);
    app.add_option("--rounds", rounds)->check(CLI::Range(1, 100));
    app.add_option("--threads", threadCounts, "BVH builder thread counts")->delimiter(',');
    CLI11_PARSE(app, argc, argv);

    std::vector<double> loadMs;
    std::vector<std::vector<double>> buildMs(threadCounts.size());
    Scene scene;
    double loadedPeak = 0.0;  // after the first load, before any BVH
    for (int round = 0; round < rounds; ++round) {
        const auto loadStart = std::chrono::steady_clock::now();
        scene = loadSceneFile(file);
        loadMs.push_back(millisecondsSince(loadStart));
        if (round == 0)
            loadedPeak = peakResidentMiB();
        for (std::size_t i = 0; i < threadCounts.size(); ++i) {
            const auto buildStart = std::chrono::steady_clock::now();
            const Bvh bvh = buildBvh(scene, threadCounts[i]);
            buildMs[i].push_back(millisecondsSince(buildStart));
        }
    }
    std::printf("%s: %.1f MB, %zu nodes; load %.0f ms, peak %.0f MiB after loading", file.c_str(),
                double(std::filesystem::file_size(file)) / 1e6, scene.nodes.size(), median(loadMs), loadedPeak);
    for (std::size_t i = 0; i < threadCounts.size(); ++i) {
        const unsigned threads = threadCounts[i];
        std::printf("; BVH %.0f ms on %u thread%s", median(buildMs[i]), threads, threads == 1 ? "" : "s");
    }
    std::printf(" (medians of %d rounds)\n", rounds);
    return 0;
}
