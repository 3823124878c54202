// Prints how fast Embree traces the bench's scenes one ray at a time and in packets
// (EmbreeTracing), in one process on the same threads: the lecture demo and random-sphere
// scenes of the given sizes, one sample per pixel, rounds interleaved, medians. A figure for
// the reader, not a test: see tools/scale-bench.sh.

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench/median.h"
#include "embree/embree_renderer.h"
#include "scene/random_spheres.h"
#include "scene/scene_loader.h"

using namespace hexray;
using bench::median;

namespace {

void measure(const EmbreeRenderer& renderer, const std::string& name, Scene scene, std::uint32_t width,
             std::uint32_t height, int rounds) {
    overrideImageSize(scene, width, height, "bench");
    overrideSamplesPerPixel(scene, 1, "bench");
    const EmbreeTracing tracings[] = {EmbreeTracing::SingleRays, EmbreeTracing::Packets};
    std::vector<double> milliseconds[2];
    for (int round = 0; round < rounds; ++round) {
        for (int way = 0; way < 2; ++way) {
            milliseconds[way].push_back(renderer.render(scene, tracings[way]).renderMilliseconds);
        }
    }
    const double pixels = double(width) * height;
    const double single = pixels / median(milliseconds[0]) / 1e3;
    const double packets = pixels / median(milliseconds[1]) / 1e3;
    std::printf("%-16s %14.2f %20.2f %7.2fx\n", name.c_str(), single, packets, packets / single);
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Embree single rays against packets (Mpix/s, medians)"};
    std::string demo;
    std::vector<std::uint32_t> counts{1, 100, 10000, 100000, 1000000};
    std::uint32_t width = 1920;
    std::uint32_t height = 1080;
    int rounds = 5;
    unsigned threads = 2;
    app.add_option("--demo", demo, "a scene file measured first (e.g. scenes/lecture-demo.json)");
    app.add_option("--spheres", counts, "random-sphere scene sizes")->delimiter(',');
    app.add_option("--width", width)->check(CLI::Range(1u, kMaxImageDimension));
    app.add_option("--height", height)->check(CLI::Range(1u, kMaxImageDimension));
    app.add_option("--rounds", rounds)->check(CLI::Range(1, 100));
    app.add_option("--threads", threads)->check(CLI::Range(1u, 256u));
    CLI11_PARSE(app, argc, argv);

    const EmbreeRenderer renderer(threads);
    std::printf("%s, %u threads, %ux%u, 1 spp, median of %d rounds\n", renderer.version().c_str(), threads, width,
                height, rounds);
    const std::string packetsColumn = tracingName(EmbreeTracing::Packets) + " Mpix/s";
    std::printf("%-16s %14s %20s %8s\n", "scene", "single Mpix/s", packetsColumn.c_str(), "ratio");
    if (!demo.empty()) {
        measure(renderer, std::filesystem::path(demo).stem().string(), loadSceneFile(demo), width, height, rounds);
    }
    for (const std::uint32_t count : counts) {
        measure(renderer, std::to_string(count) + " spheres", makeRandomSpheresScene(count, 1), width, height, rounds);
    }
    return 0;
}
