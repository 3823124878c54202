// `hexray bench`: speed against error, every backend in interleaved rounds in one process.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "bench/bench_backends.h"
#include "bench/bench_csv.h"
#include "bench/bench_report.h"
#include "bench/bench_selection.h"
#include "bench/lecture_demo_ceiling.h"
#include "cli/bench_json.h"
#include "cli/command_support.h"
#include "cli/json_document.h"
#include "cli/progress.h"
#include "cli/quiet.h"
#include "cpu/cpu_renderer.h"
#include "demo_scene.h"
#include "gpu/plan_refused.h"
#include "io/output_file.h"
#include "scene/random_spheres.h"
#include "scene/scene_loader.h"
#include "util/milliseconds_since.h"
#include "util/printable.h"

namespace hexray::cli {
namespace {

// ---------------------------------------------------------------- tunables
// The random-sphere scenes of the curve: one seed, so every run measures the same scenes.
constexpr std::uint64_t kCurveSeed = 1;
// Before the rounds, each curve configuration renders once at a fraction of the resolution
// (1/kProbeDivisor of width and height, or less, see probeShare), which predicts its full frame,
// so that a backend too slow at some N does not eat the bench's time.
constexpr double kProbeDivisor = 8;
constexpr double kProbeSeconds = 0.5;

std::string formatSeconds(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", seconds);
    return text;
}

// Everything the bench measures, in the order it is printed.
struct Bench {
    std::vector<BenchScene> scenes;
    std::vector<BenchConfiguration> configurations;
    std::vector<std::string> notes;
};

Scene withSamples(Scene scene, std::uint32_t samplesPerPixel) {
    scene.image.samplesPerPixel = samplesPerPixel;
    return scene;
}

// For a file scene, a converged CPU reference (judging what a viewer sees: mostly sampling error at
// 1 spp); part of the CPU reference's rows, so a bench at scale can leave it out.
void addConvergedReferences(const BenchOptions& options, const BenchSelection& selection, Bench& bench) {
    const bool anyFile = std::any_of(bench.scenes.begin(), bench.scenes.end(), [](auto& s) { return !s.spheres; });
    if (!selection.contains(BenchRowKind::Cpu)) {
        if (anyFile) {
            bench.notes.push_back(
                "Sampling error: not measured, as --backends leaves out cpu (the converged "
                "reference is the CPU reference's).");
        }
        return;
    }
    for (BenchScene& scene : bench.scenes) {
        if (!scene.spheres) {
            std::fprintf(stderr, "bench: converged reference for %s (%u spp on the CPU)...\n", scene.name.c_str(),
                         options.referenceSamples);
            const Scene converged = withSamples(scene.scene, options.referenceSamples);
            scene.reference.converged = encodeImage(renderOnCpu(converged).image, converged.image.encoding);
        }
    }
}

// The scene files named, or the shipped demo scene when neither files nor a curve are asked for.
std::vector<BenchScene> fileScenes(const BenchOptions& options) {
    std::vector<BenchScene> scenes;
    for (const std::string& path : options.scenePaths) {
        scenes.push_back(
            {printable(std::filesystem::path(path).stem().string()), std::nullopt, loadScene(path, options.image), {}});
    }
    if (scenes.empty() && options.sphereCounts.empty()) {
        Scene demo = parseScene(std::string(kDemoSceneJson), "the shipped demo scene");
        applyImageOverride(demo, options.image);
        scenes.push_back({std::string(kDemoSceneName), std::nullopt, std::move(demo), {}});
    }
    return scenes;
}

// The Embree rows chosen, in the order the tables list them.
std::vector<BenchBackend> embreeBackends(const BenchSelection& selection, const BenchBackends& backends) {
    std::vector<BenchBackend> chosen;
    const std::pair<BenchRowKind, BenchBackend> embree[] = {
        {BenchRowKind::Embree, BenchBackend::Embree},
        {BenchRowKind::EmbreeF64Packets, BenchBackend::EmbreeF64Packets},
        {BenchRowKind::EmbreeF64Single, BenchBackend::EmbreeF64Single}};
    for (const auto& [kind, backend] : embree) {
        if (backends.hasEmbree() && selection.contains(kind)) {
            chosen.push_back(backend);
        }
    }
    return chosen;
}

// A file scene's configurations, of those chosen: the GPU in every precision, culled and whole (the
// textbook formulation is never culled), the hand-written kernel where it applies, the CPU reference
// and Embree.
void addFileConfigurations(const BenchOptions& options, const BenchSelection& selection, const BenchBackends& backends,
                           std::size_t index, const Scene& scene, std::vector<BenchConfiguration>& configurations) {
    for (const std::uint32_t spp : options.samples) {
        if (selection.contains(BenchRowKind::GpuF32Naive)) {
            configurations.push_back({index, BenchBackend::Gpu, Precision::F32Naive, Culling::Off, spp});
        }
        const std::pair<Precision, bool> precisions[] = {
            {Precision::F32, selection.contains(BenchRowKind::GpuF32)},
            {Precision::F64, selection.contains(BenchRowKind::GpuF64) && backends.hasFloat64()},
            {Precision::F32Certified, selection.contains(BenchRowKind::GpuF32Certified) && backends.hasFloat64()}};
        for (const auto& [precision, chosen] : precisions) {
            if (chosen) {
                configurations.push_back({index, BenchBackend::Gpu, precision, Culling::Off, spp});
                configurations.push_back({index, BenchBackend::Gpu, precision, Culling::On, spp});
            }
        }
        if (selection.contains(BenchRowKind::HandWritten) && isLectureDemoScene(withSamples(scene, spp))) {
            configurations.push_back({index, BenchBackend::GpuHandWritten, Precision::F32, Culling::Off, spp});
        }
        if (selection.contains(BenchRowKind::Cpu)) {
            configurations.push_back({index, BenchBackend::Cpu, Precision::Auto, Culling::Off, spp});
        }
        for (const BenchBackend embree : embreeBackends(selection, backends)) {
            configurations.push_back({index, embree, Precision::Auto, Culling::Off, spp});
        }
    }
}

// The share of the pixels a curve probe renders: 1/kProbeDivisor^2, less when the previous N's
// frame, scaled as if the cost grew like N (no acceleration structure), says the probe would
// otherwise take more than kProbeSeconds.
double probeShare(double previousSeconds, std::uint32_t previousCount, std::uint32_t count) {
    double share = 1.0 / (kProbeDivisor * kProbeDivisor);
    if (previousCount > 0) {
        share = std::min(share, kProbeSeconds / (previousSeconds * count / previousCount));
    }
    return share;
}

// The seconds a full frame of `configuration` should take, from a probe at a fraction of it.
double predictFrameSeconds(BenchBackends& backends, const BenchScene& bench, const BenchConfiguration& configuration,
                           double share) {
    const double divisor = std::sqrt(1.0 / share);
    Scene probe = withSamples(bench.scene, configuration.samplesPerPixel);
    probe.image.width = std::max(1u, std::uint32_t(probe.image.width / divisor));
    probe.image.height = std::max(1u, std::uint32_t(probe.image.height / divisor));
    BenchMeasurement measurement;
    backends.measure(probe, configuration, false, measurement);
    const double pixels = double(bench.scene.image.width) * bench.scene.image.height;
    return measurement.renderMilliseconds.back() * 1e-3 * pixels / (double(probe.image.width) * probe.image.height);
}

// The curve's rows chosen: each backend at its natural precision, and the GPU in f32-naive.
std::vector<std::pair<BenchBackend, Precision>> curveRows(const BenchSelection& selection,
                                                          const BenchBackends& backends) {
    std::vector<std::pair<BenchBackend, Precision>> rows;
    if (selection.contains(BenchRowKind::GpuF32Naive)) {
        rows.emplace_back(BenchBackend::Gpu, Precision::F32Naive);
    }
    if (selection.contains(BenchRowKind::GpuF32)) {
        rows.emplace_back(BenchBackend::Gpu, Precision::F32);
    }
    if (selection.contains(BenchRowKind::Cpu)) {
        rows.emplace_back(BenchBackend::Cpu, Precision::F32);
    }
    for (const BenchBackend embree : embreeBackends(selection, backends)) {
        rows.emplace_back(embree, Precision::F32);
    }
    return rows;
}

// The curve: a random-sphere scene per count, N ascending, each backend at its natural precision
// (the GPU also in f32-naive when chosen); a row predicted to need more than --max-frame-seconds at
// some N is left out there.
void addCurve(const BenchOptions& options, const BenchSelection& selection, BenchBackends& backends, Bench& bench) {
    std::vector<std::uint32_t> counts = options.sphereCounts;
    std::sort(counts.begin(), counts.end());
    counts.erase(std::unique(counts.begin(), counts.end()), counts.end());
    const std::size_t first = bench.scenes.size();
    for (const std::uint32_t count : counts) {
        Scene scene = makeRandomSpheresScene(count, kCurveSeed);
        applyImageOverride(scene, options.image);
        bench.scenes.push_back({"random-spheres", count, std::move(scene), {}});
    }
    for (const auto& [backend, precision] : curveRows(selection, backends)) {
        const std::string row = backends.name(backend) + (precision == Precision::F32Naive ? " f32-naive" : "");
        for (const std::uint32_t spp : options.samples) {
            std::string skipped;
            double previousSeconds = 0;
            std::uint32_t previousCount = 0;
            for (std::size_t index = first; index < bench.scenes.size(); ++index) {
                const std::uint32_t count = *bench.scenes[index].spheres;
                const BenchConfiguration configuration{index, backend, precision, Culling::Off, spp};
                double seconds = 0;
                try {
                    seconds = predictFrameSeconds(backends, bench.scenes[index], configuration,
                                                  probeShare(previousSeconds, previousCount, count));
                } catch (const PlanRefused& refused) {
                    bench.notes.push_back(row + " at " + std::to_string(spp) + " spp: not measured at " +
                                          std::to_string(count) + " spheres: " + refused.reason() + ".");
                    continue;
                }
                std::fprintf(stderr, "bench: %s, %u spheres, %u spp: a frame should take about %.2f s\n", row.c_str(),
                             count, spp, seconds);
                previousSeconds = seconds;
                previousCount = count;
                if (seconds > options.maxFrameSeconds) {
                    char text[80];
                    std::snprintf(text, sizeof text, "%u (%.0f s)", count, seconds);
                    skipped += (skipped.empty() ? "" : ", ") + std::string(text);
                } else {
                    bench.configurations.push_back(configuration);
                }
            }
            if (!skipped.empty()) {
                bench.notes.push_back(row + " at " + std::to_string(spp) + " spp: not measured at " + skipped +
                                      " spheres: a low-resolution probe predicts a frame over " +
                                      "--max-frame-seconds " + formatSeconds(options.maxFrameSeconds) + ".");
            }
        }
    }
}

// Every scene's references: the CPU reference at each sample count, taken from its own row after
// the rounds (it is deterministic), rendered here only where that row is not measured.
void addMissingReferences(const BenchOptions& options, Bench& bench) {
    for (std::size_t index = 0; index < bench.scenes.size(); ++index) {
        BenchScene& scene = bench.scenes[index];
        for (const std::uint32_t spp : options.samples) {
            const bool measured =
                std::any_of(bench.configurations.begin(), bench.configurations.end(), [&](const auto& c) {
                    return c.scene == index && c.backend == BenchBackend::Cpu && c.samplesPerPixel == spp;
                });
            if (measured) {
                continue;
            }
            const std::string name =
                scene.spheres ? std::to_string(*scene.spheres) + " random spheres" : printable(scene.name);
            std::fprintf(stderr, "bench: reference for %s (%u spp on the CPU)...\n", name.c_str(), spp);
            const auto start = std::chrono::steady_clock::now();
            scene.reference.bySamples[spp] = renderOnCpu(withSamples(scene.scene, spp));
            char text[160];
            std::snprintf(text, sizeof text, "cpu-reference on %s, %u spp: its one render (the reference) took %.1f s.",
                          name.c_str(), spp, millisecondsSince(start) * 1e-3);
            bench.notes.push_back(text);
        }
    }
}

// Interleaved rounds: every configuration once per round, so the machine's drift and noise fall
// on all of them alike.
std::vector<BenchMeasurement> runRounds(const BenchOptions& options, BenchBackends& backends, Bench& bench) {
    std::vector<BenchMeasurement> measurements(bench.configurations.size());
    Progress progress("bench", std::uint64_t(options.rounds) * bench.configurations.size(),
                      Progress::Unit::Measurements);
    std::uint64_t done = 0;
    for (unsigned round = 0; round < options.rounds; ++round) {
        if (!Progress::shown() && !quiet()) {  // a log gets one line a round
            std::fprintf(stderr, "bench: round %u of %u\n", round + 1, options.rounds);
        }
        for (std::size_t i = 0; i < bench.configurations.size(); ++i) {
            const BenchConfiguration& configuration = bench.configurations[i];
            const Scene scene = withSamples(bench.scenes[configuration.scene].scene, configuration.samplesPerPixel);
            backends.measure(scene, configuration, round == 0, measurements[i]);
            progress.update(++done);
        }
    }
    for (std::size_t i = 0; i < bench.configurations.size(); ++i) {
        BenchScene& scene = bench.scenes[bench.configurations[i].scene];
        if (bench.configurations[i].backend == BenchBackend::Cpu) {
            CpuRender& reference = scene.reference.bySamples[bench.configurations[i].samplesPerPixel];
            reference.image = measurements[i].image;
            reference.classes = measurements[i].classes;
            reference.margins = measurements[i].margins;
        }
    }
    return measurements;
}

void writeCsv(const std::string& path, const std::string& text) {
    OutputFile file(path);
    if (std::fwrite(text.data(), 1, text.size(), file.stream()) != text.size()) {
        file.fail("cannot write", "short write");
    }
    file.commit();
}

// What the bench was asked to measure, and the parts of the document filled as it goes.
nlohmann::json startDocument(const BenchOptions& options) {
    nlohmann::json document = jsonDocument("bench");
    document["timings_ms"]["startup"] = nullptr;
    document["device"] = nullptr;
    document["settings"] = {{"rounds", options.rounds},
                            {"samples", options.samples},
                            {"reference_samples", options.referenceSamples},
                            {"spheres", options.sphereCounts},
                            {"max_frame_seconds", options.maxFrameSeconds},
                            {"backends", options.backends.empty() ? defaultBenchRowNames() : options.backends}};
    document["embree"] = nullptr;
    document["scenes"] = nlohmann::json::array();
    document["notes"] = nlohmann::json::array();
    return document;
}

}  // namespace

int runBench(const BenchOptions& options) {
    ValidationLog log;
    nlohmann::json document = startDocument(options);
    const int code = guarded([&] {
        BenchBackends backends({options.vulkan.validate ? &log : nullptr, options.vulkan.device});
        document["timings_ms"]["startup"] = backends.startupMilliseconds();
        document["device"] = jsonDevice(backends.device());
        const BenchSelection selection = selectBenchRows(options.backends);
        Bench bench;
        bench.scenes = fileScenes(options);
        for (std::size_t index = 0; index < bench.scenes.size(); ++index) {
            addFileConfigurations(options, selection, backends, index, bench.scenes[index].scene, bench.configurations);
        }
        addConvergedReferences(options, selection, bench);
        addCurve(options, selection, backends, bench);
        addMissingReferences(options, bench);
        const std::vector<BenchMeasurement> measurements = runRounds(options, backends, bench);
        const std::vector<BenchRow> rows = benchRows(bench.scenes, bench.configurations, measurements, backends);
        bench.notes.push_back(backends.hasEmbree() ? "Embree: " + backends.embreeVersion() + "."
                                                   : "Embree rows: none, this hexray was built without Embree 3 "
                                                     "(libembree-dev).");
        printBenchTables(bench.scenes, rows, backends, bench.notes);
        if (!options.csvPath.empty()) {
            writeCsv(options.csvPath, benchCsv(bench.scenes, rows, backends));
        }
        document["embree"] = backends.hasEmbree() ? nlohmann::json(backends.embreeVersion()) : nullptr;
        document["scenes"] = benchScenesJson(bench.scenes, rows, backends);
        document["notes"] = bench.notes;
        return int(kSuccess);
    });
    return finishJson(options.jsonPath, document, withValidationVerdict(code, log));
}

}  // namespace hexray::cli
