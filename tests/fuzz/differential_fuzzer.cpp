// Differential fuzzing: generated scenes (scene_generator.h) through the GPU in every precision
// and through the CPU reference, each judged as `hexray compare` judges (differential_check.h),
// for a given time or number of scenes. Every seed is one scene, so a failure is reproduced with
// --seed N. A failing scene is shrunk (scene_shrinker.h) and written to the failures folder,
// ready to become a regression input in tests/fuzz/regressions/. Exit code 1 when any scene failed.

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "fuzz/differential_check.h"
#include "fuzz/near_tie_reasons.h"
#include "fuzz/scene_generator.h"
#include "fuzz/scene_shrinker.h"
#include "gpu/gpu_renderer.h"
#include "scene/scene_writer.h"
#include "vulkan/vulkan_context.h"

namespace fs = std::filesystem;
using namespace hexray;
using namespace hexray::test;

namespace {

struct FuzzOptions {
    double seconds = 120;
    std::uint64_t firstSeed = 0;
    std::uint64_t seedStride = 1;       // the seeds checked: firstSeed, firstSeed + seedStride, ...
    std::uint64_t scenes = 0;           // 0: until the time is up
    std::optional<std::uint64_t> seed;  // one scene only, reported in full
    fs::path failures = HEXRAY_BINARY_DIR "/differential-failures";  // in the build tree, never the source tree
    std::uint32_t maxFailures = 5;
    std::string device;
    std::uint64_t generatedEvery = 8;
    bool shrink = true;
};

// Every so many seeds, the scene moved out of the supported range goes to the loader as well.
constexpr std::uint64_t kOutOfRangeEvery = 8;
// A shrink stops after this many candidate scenes (each is rendered once, in the failing render only).
constexpr std::size_t kShrinkTries = 400;

// SplitMix64's finaliser: the choices below spread evenly over any stride of seeds.
std::uint64_t mixed(std::uint64_t seed) {
    seed = (seed ^ (seed >> 30)) * 0xbf58476d1ce4e5b9ull;
    seed = (seed ^ (seed >> 27)) * 0x94d049bb133111ebull;
    return seed ^ (seed >> 31);
}

// The options for the scene of `seed`. Every scene is rendered by the data-driven kernel, with the
// candidate lists or testing every node; about one in generatedEvery also by the kernel generated
// for it, at one of the sample counts (its compile per scene and sample count costs what a dozen
// scenes through the data-driven kernel do).
DifferentialOptions optionsFor(std::uint64_t seed, std::uint64_t generatedEvery) {
    const std::uint64_t bits = mixed(seed);
    DifferentialOptions options;
    options.dataDrivenAcceleration = bits & 1 ? Acceleration::None : Acceleration::Always;
    options.generatedKernels = generatedEvery != 0 && (bits >> 8) % generatedEvery == 0;
    options.generatedKernelSamples = options.samplesPerPixel[(bits >> 1) % options.samplesPerPixel.size()];
    return options;
}

// Everything wrong with `scene`, the scene of `seed`.
std::vector<Finding> findingsFor(GpuRenderer& renderer, const Scene& scene, std::uint64_t seed,
                                 std::uint64_t generatedEvery) {
    std::vector<Finding> findings;
    if (auto finding = checkLoad(scene, false))
        findings.push_back(*finding);
    if (seed % kOutOfRangeEvery == 0) {
        if (auto finding = checkLoad(generateOutOfRangeScene(seed), true))
            findings.push_back(*finding);
    }
    const DifferentialOptions options = optionsFor(seed, generatedEvery);
    for (const Finding& finding : checkRenders(renderer, scene, options))
        findings.push_back(finding);
    renderer.releaseGeneratedKernels();
    return findings;
}

// The failing scene made small, written as NAME.json with NAME.expected ("accepted") beside it,
// as tests/fuzz/regressions/ holds them. Only the failing render is repeated while shrinking.
fs::path writeShrunk(GpuRenderer& renderer, std::uint64_t seed, const Finding& first, const fs::path& folder) {
    const Scene generated = generateScene(seed);
    DifferentialOptions options = optionsFor(first, optionsFor(seed, 0));
    const auto stillFails = [&](const Scene& candidate) {
        const std::vector<Finding> findings = checkRenders(renderer, candidate, options);
        renderer.releaseGeneratedKernels();
        return std::ranges::any_of(findings, [&](const Finding& finding) { return finding.kind == first.kind; });
    };
    Scene shrunk = first.kind == "load" ? generated : shrinkScene(generated, stillFails, kShrinkTries);
    shrunk.image.width = options.width;
    shrunk.image.height = options.height;
    fs::create_directories(folder);
    const fs::path path = folder / ("differential-seed-" + std::to_string(seed) + ".json");
    std::ofstream(path) << sceneToJson(shrunk);
    std::ofstream(fs::path(path).replace_extension(".expected")) << "accepted\n";
    return path;
}

int run(const FuzzOptions& options) {
    const VulkanContext context({nullptr, options.device});
    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    const std::uint64_t first = options.seed.value_or(options.firstSeed);
    const std::uint64_t limit = options.seed ? 1 : options.scenes;
    // One renderer for the run: the data-driven kernels' pipelines are built once; each scene's
    // generated kernels are released after it.
    GpuRenderer renderer(context, GpuRenderer::kDefaultMaxBandBytes, KernelCache(""));
    std::uint64_t done = 0;
    std::uint32_t failures = 0;
    std::uint64_t nearTied = 0;  // scenes whose ambiguity was not held to the limit
    std::printf("differential fuzzing on %s from seed %llu\n", context.selected().name.c_str(),
                static_cast<unsigned long long>(first));
    for (std::uint64_t seed = first; limit ? done < limit : elapsed() < options.seconds;
         seed += options.seedStride, ++done) {
        const Scene scene = generateScene(seed);
        const std::vector<Finding> findings = findingsFor(renderer, scene, seed, options.generatedEvery);
        const std::vector<std::string> reasons = nearTieReasons(scene);
        nearTied += !reasons.empty();
        if (options.seed) {
            std::printf("%s", sceneToJson(scene).c_str());
            for (const std::string& reason : reasons)
                std::printf("near-tied: %s\n", reason.c_str());
        }
        if (findings.empty())
            continue;
        ++failures;
        std::printf("FAIL seed %llu:\n", static_cast<unsigned long long>(seed));
        for (const Finding& finding : findings)
            std::printf("  %s\n", describe(finding).c_str());
        if (options.shrink) {
            std::printf("  shrunk: %s\n", writeShrunk(renderer, seed, findings.front(), options.failures).c_str());
        }
        if (failures >= options.maxFailures) {
            ++done;
            break;
        }
    }
    const double seconds = elapsed();
    std::printf(
        "%llu scenes (seeds %llu to %llu, every %llu) in %.1f s: %.2f scenes per second; %u failed; %llu with "
        "something on a boundary or below resolution, their ambiguous share not held to the limit\n",
        static_cast<unsigned long long>(done), static_cast<unsigned long long>(first),
        static_cast<unsigned long long>(first + (done - 1) * options.seedStride),
        static_cast<unsigned long long>(options.seedStride), seconds, double(done) / seconds, failures,
        static_cast<unsigned long long>(nearTied));
    return failures ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
    std::setvbuf(stdout, nullptr, _IOLBF, 0);  // a finding shows as it is made, also in a log file
    CLI::App app("Differential fuzzing: generated scenes through the GPU and the CPU reference");
    FuzzOptions options;
    app.add_option("--seconds", options.seconds, "How long to fuzz")->capture_default_str();
    app.add_option("--first-seed", options.firstSeed, "The first scene's seed; the next ones follow")
        ->capture_default_str();
    app.add_option("--seed-stride", options.seedStride, "Check every N-th seed from the first (N processes: one each)")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    app.add_option("--scenes", options.scenes, "How many scenes (instead of --seconds)");
    app.add_option("--seed", options.seed, "Check only this seed's scene, and print it");
    app.add_option("--failures", options.failures, "Where shrunk failing scenes are written")->capture_default_str();
    app.add_option("--max-failures", options.maxFailures, "Stop after this many failing scenes")->capture_default_str();
    app.add_option(
           "--generated-every", options.generatedEvery,
           "Render about one scene in N with its generated kernel too, at one sample count (0: never); every scene "
           "gets the data-driven ones")
        ->capture_default_str();
    app.add_flag("!--no-shrink", options.shrink,
                 "Report failing seeds without shrinking them (replay one with --seed)");
    app.add_option("--device", options.device, "A Vulkan device by index or part of its name");
    CLI11_PARSE(app, argc, argv);
    try {
        return run(options);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "hexray_differential_fuzzer: %s\n", error.what());
        return 2;
    }
}
