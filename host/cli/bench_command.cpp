#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <thread>

#include "bench/lecture_demo_ceiling.h"
#include "cli/command_support.h"
#include "compare/compare.h"
#include "cpu/cpu_renderer.h"
#include "gpu/gpu_renderer.h"
#include "image/image_io.h"
#include "io/output_file.h"
#include "scene/random_spheres.h"
#include "scene/scene_loader.h"
#ifdef HEXRAY_WITH_EMBREE
#include "embree/embree_renderer.h"
#endif

namespace hexray::cli {
namespace {

// The random-sphere scenes of the curve: one seed, so every run measures the same scenes.
constexpr std::uint64_t kCurveSeed = 1;

// Before the rounds, each curve configuration renders once at a fraction of the resolution
// (1/kProbeDivisor of width and height, or less, see below), which predicts its full frame, so
// that a backend too slow at some N does not eat the bench's time.
constexpr double kProbeDivisor = 8;
constexpr double kProbeSeconds = 0.5;

std::string formatSeconds(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", seconds);
    return text;
}

// GpuCeiling: the lecture demo scene's hand-written kernel (bench/lecture_demo_ceiling.h),
// the yardstick for the data-driven shader on the same device.
enum class BenchBackend { Gpu, GpuCeiling, Cpu, Embree };

// What every configuration of a scene is judged against. File scenes: the CPU reference at a
// high sample count for colour; for the pixel classes (those of each pixel's first sample) and
// their ambiguity, the CPU reference at the configuration's own sample count. Curve scenes:
// the CPU reference at the configuration's own sample count for both (a converged render of
// 100k spheres at 1080p would take longer than the whole bench may).
struct Reference {
    Rgb8Image colour;  // encoded as the scene asks
    std::map<std::uint32_t, CpuRender> bySamples;
    std::map<std::uint32_t, PixelMask> ambiguousBySamples;
};

struct BenchScene {
    std::string name;                    // file stem, or "random-spheres"
    std::optional<std::uint32_t> spheres;  // set for the curve's scenes
    Scene scene;
    Reference reference;
};

// One thing to measure: a backend, precision and sample count on one scene.
struct Configuration {
    std::size_t scene = 0;  // into the scene list
    BenchBackend backend = BenchBackend::Gpu;
    Precision precision = Precision::F32;  // GPU only
    std::uint32_t samplesPerPixel = 1;
};

struct Measurement {
    std::vector<double> renderMilliseconds;  // see the table's notes for what each backend's covers
    std::vector<double> frameMilliseconds;   // the whole frame in-process
    Image image;                             // CPU reference and Embree: linear
    Rgb8Image encoded;                       // GPU: the 8-bit output `render` writes
    std::vector<PixelClass> classes;         // empty for GpuCeiling, which writes none
    std::vector<float> margins;  // CPU reference only
};

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

// The threads a backend renders with, for the per-pixel cost; 0 for a real GPU.
unsigned lavapipeThreads() {
    if (const char* value = std::getenv("LP_NUM_THREADS")) {  // Mesa's own override
        return unsigned(std::max(1L, std::strtol(value, nullptr, 10)));
    }
    return cpuThreadCount(0);  // llvmpipe's default: one per core
}

class Backends {
public:
    Backends(const BenchOptions& options, ValidationLog& log)
        : context_({options.vulkan.validate ? &log : nullptr, options.vulkan.device}), gpu_(context_) {
        isLavapipe_ = context_.selected().name.find("llvmpipe") != std::string::npos;
        gpuName_ = isLavapipe_ ? "lavapipe" : context_.selected().name;
#ifdef HEXRAY_WITH_EMBREE
        embree_ = std::make_unique<EmbreeRenderer>(cpuThreadCount(0));
#endif
    }

    bool hasFloat64() const { return context_.selected().hasFloat64; }
    bool hasEmbree() const {
#ifdef HEXRAY_WITH_EMBREE
        return true;
#else
        return false;
#endif
    }

    std::string name(BenchBackend backend) const {
        switch (backend) {
            case BenchBackend::Gpu: return gpuName_;
            case BenchBackend::GpuCeiling: return gpuName_ + " hand-written";
            case BenchBackend::Cpu: return "cpu-reference";
            case BenchBackend::Embree: return "embree";
        }
        return "";
    }
    unsigned threads(BenchBackend backend) const {
        switch (backend) {
            case BenchBackend::Gpu:
            case BenchBackend::GpuCeiling: return isLavapipe_ ? lavapipeThreads() : 0;
            case BenchBackend::Cpu: return cpuThreadCount(0);
            case BenchBackend::Embree:
#ifdef HEXRAY_WITH_EMBREE
                return embree_->threadCount();
#endif
                break;
        }
        return 0;
    }

    // Renders once into `measurement` (appending its times). `withClasses`: the GPU also runs
    // the comparison pipeline, untimed, for the pixel classes the render pipeline does not write.
    void measure(const Scene& scene, const Configuration& configuration, bool withClasses, Measurement& measurement) {
        const auto start = std::chrono::steady_clock::now();
        const auto recordDevice = [&](GpuRenderResult&& render) {
            measurement.renderMilliseconds.push_back(render.timing.renderMilliseconds);
            measurement.frameMilliseconds.push_back(millisecondsSince(start));
            measurement.encoded = std::move(render.encoded);
        };
        switch (configuration.backend) {
            case BenchBackend::Gpu:
                recordDevice(gpu_.render(scene, configuration.precision, GpuOutput::Encoded8));
                if (withClasses) {
                    measurement.classes = gpu_.render(scene, configuration.precision).classes;
                }
                return;
            case BenchBackend::GpuCeiling:
                recordDevice(gpu_.render(scene, lectureDemoCeilingPlan(gpu_, scene), GpuOutput::Encoded8));
                return;
            case BenchBackend::Cpu: {
                CpuRender render = renderOnCpu(scene);
                measurement.renderMilliseconds.push_back(millisecondsSince(start));
                measurement.frameMilliseconds.push_back(measurement.renderMilliseconds.back());
                measurement.image = std::move(render.image);
                measurement.classes = std::move(render.classes);
                measurement.margins = std::move(render.margins);
                return;
            }
            case BenchBackend::Embree: {
#ifdef HEXRAY_WITH_EMBREE
                EmbreeRender render = embree_->render(scene);
                measurement.renderMilliseconds.push_back(render.renderMilliseconds);
                measurement.frameMilliseconds.push_back(millisecondsSince(start));
                measurement.image = std::move(render.image);
                measurement.classes = std::move(render.classes);
#endif
                return;
            }
        }
    }

    std::string embreeVersion() const {
#ifdef HEXRAY_WITH_EMBREE
        return embree_->version();
#else
        return "";
#endif
    }

private:
    VulkanContext context_;
    GpuRenderer gpu_;
    bool isLavapipe_ = false;
    std::string gpuName_;
#ifdef HEXRAY_WITH_EMBREE
    std::unique_ptr<EmbreeRenderer> embree_;
#endif
};

std::vector<BenchBackend> curveBackends(const Backends& backends) {
    std::vector<BenchBackend> list{BenchBackend::Gpu, BenchBackend::Cpu};
    if (backends.hasEmbree()) {
        list.push_back(BenchBackend::Embree);
    }
    return list;
}

}  // namespace

int runBench(const BenchOptions& options) {
    ValidationLog log;
    const int code = guarded([&] {
        Backends backends(options, log);
        std::vector<BenchScene> scenes;
        std::vector<Configuration> configurations;
        std::vector<std::string> notes;

        // ---- scene files: every backend and precision at each sample count
        for (const std::string& path : options.scenePaths) {
            BenchScene bench{std::filesystem::path(path).stem().string(), std::nullopt, loadScene(path, options.image),
                             {}};
            std::fprintf(stderr, "bench: converged reference for %s (%u spp on the CPU)...\n", path.c_str(),
                         options.referenceSamples);
            Scene sampled = bench.scene;
            sampled.image.samplesPerPixel = options.referenceSamples;
            bench.reference.colour = encodeImage(renderOnCpu(sampled).image, sampled.image.encoding);
            const std::size_t index = scenes.size();
            for (std::uint32_t spp : options.samples) {
                sampled.image.samplesPerPixel = spp;
                CpuRender& render = bench.reference.bySamples[spp] = renderOnCpu(sampled);
                bench.reference.ambiguousBySamples[spp] = marginsBelow(render.margins, kAmbiguityMargin);
                for (Precision precision : {Precision::F32Naive, Precision::F32, Precision::F64}) {
                    if (precision != Precision::F64 || backends.hasFloat64()) {
                        configurations.push_back({index, BenchBackend::Gpu, precision, spp});
                    }
                }
                if (isLectureDemoScene(sampled)) {
                    configurations.push_back({index, BenchBackend::GpuCeiling, Precision::F32, spp});
                }
                configurations.push_back({index, BenchBackend::Cpu, Precision::F64, spp});
                if (backends.hasEmbree()) {
                    configurations.push_back({index, BenchBackend::Embree, Precision::F32, spp});
                }
            }
            scenes.push_back(std::move(bench));
        }

        // ---- the curve: N random spheres, each backend at its natural precision, N ascending
        const std::size_t firstCurveScene = scenes.size();
        std::vector<std::uint32_t> counts = options.sphereCounts;
        std::sort(counts.begin(), counts.end());
        counts.erase(std::unique(counts.begin(), counts.end()), counts.end());
        for (std::uint32_t count : counts) {
            BenchScene bench{"random-spheres", count, makeRandomSpheresScene(count, kCurveSeed), {}};
            if (options.image.width || options.image.height) {
                overrideImageSize(bench.scene, options.image.width.value_or(bench.scene.image.width),
                                  options.image.height.value_or(bench.scene.image.height), "--width/--height");
            }
            scenes.push_back(std::move(bench));
        }
        for (BenchBackend backend : curveBackends(backends)) {
            for (std::uint32_t spp : options.samples) {
                std::string reason;
                double previousSeconds = 0;  // the prediction at the previous N
                std::uint32_t previousCount = 0;
                for (std::size_t index = firstCurveScene; index < scenes.size(); ++index) {
                    const BenchScene& bench = scenes[index];
                    const Configuration configuration{index, backend, Precision::F32, spp};
                    // The probe's share of the pixels: 1/64, less when the previous N's frame,
                    // scaled as if the cost grew like N (no acceleration structure), says the
                    // probe would otherwise take more than kProbeSeconds.
                    const double pixels = double(bench.scene.image.width) * bench.scene.image.height;
                    double share = 1.0 / (kProbeDivisor * kProbeDivisor);
                    if (previousCount > 0) {
                        const double worstSeconds = previousSeconds * *bench.spheres / previousCount;
                        share = std::min(share, kProbeSeconds / worstSeconds);
                    }
                    const double divisor = std::sqrt(1.0 / share);
                    Scene probe = bench.scene;
                    probe.image.samplesPerPixel = spp;
                    probe.image.width = std::max(1u, std::uint32_t(probe.image.width / divisor));
                    probe.image.height = std::max(1u, std::uint32_t(probe.image.height / divisor));
                    Measurement measurement;
                    backends.measure(probe, configuration, false, measurement);
                    const double predictedSeconds = measurement.renderMilliseconds.back() * 1e-3 * pixels /
                                                    (double(probe.image.width) * probe.image.height);
                    std::fprintf(stderr, "bench: %s, %u spheres, %u spp: a frame should take about %.2f s\n",
                                 backends.name(backend).c_str(), *bench.spheres, spp, predictedSeconds);
                    previousSeconds = predictedSeconds;
                    previousCount = *bench.spheres;
                    if (predictedSeconds > options.maxFrameSeconds) {
                        char text[80];
                        std::snprintf(text, sizeof text, "%u (%.0f s)", *bench.spheres, predictedSeconds);
                        reason += (reason.empty() ? "" : ", ") + std::string(text);
                    } else {
                        configurations.push_back(configuration);
                    }
                }
                if (!reason.empty()) {
                    notes.push_back(backends.name(backend) + " at " + std::to_string(spp) + " spp: not measured at " +
                                    reason + " spheres: a low-resolution probe predicts a frame over " +
                                    "--max-frame-seconds " + formatSeconds(options.maxFrameSeconds) + ".");
                }
            }
        }
        // The curve's reference is the CPU reference at the same sample count: taken from its
        // own row after the rounds (it is deterministic), rendered here only where that row is
        // not measured.
        for (std::size_t index = firstCurveScene; index < scenes.size(); ++index) {
            BenchScene& bench = scenes[index];
            for (std::uint32_t spp : options.samples) {
                const bool measured = std::any_of(configurations.begin(), configurations.end(), [&](const auto& c) {
                    return c.scene == index && c.backend == BenchBackend::Cpu && c.samplesPerPixel == spp;
                });
                if (!measured) {
                    std::fprintf(stderr, "bench: reference for %u random spheres (%u spp on the CPU)...\n",
                                 *bench.spheres, spp);
                    Scene sampled = bench.scene;
                    sampled.image.samplesPerPixel = spp;
                    const auto start = std::chrono::steady_clock::now();
                    bench.reference.bySamples[spp] = renderOnCpu(sampled);
                    char text[160];
                    std::snprintf(text, sizeof text, "cpu-reference at %u spheres, %u spp: its one render (the "
                                  "reference) took %.1f s.", *bench.spheres, spp, millisecondsSince(start) * 1e-3);
                    notes.push_back(text);
                }
            }
        }

        // Interleaved rounds: every configuration once per round, so the machine's drift and
        // noise fall on all of them alike.
        std::vector<Measurement> measurements(configurations.size());
        for (unsigned round = 0; round < options.rounds; ++round) {
            std::fprintf(stderr, "bench: round %u of %u\n", round + 1, options.rounds);
            for (std::size_t i = 0; i < configurations.size(); ++i) {
                const Configuration& configuration = configurations[i];
                Scene scene = scenes[configuration.scene].scene;
                scene.image.samplesPerPixel = configuration.samplesPerPixel;
                backends.measure(scene, configuration, round == 0, measurements[i]);
            }
        }

        for (std::size_t i = 0; i < configurations.size(); ++i) {
            BenchScene& bench = scenes[configurations[i].scene];
            const std::uint32_t spp = configurations[i].samplesPerPixel;
            if (bench.spheres && configurations[i].backend == BenchBackend::Cpu) {
                CpuRender& reference = bench.reference.bySamples[spp];
                reference.image = measurements[i].image;
                reference.classes = measurements[i].classes;
                reference.margins = measurements[i].margins;
            }
        }
        for (BenchScene& bench : scenes) {
            if (bench.spheres) {
                for (const auto& [spp, render] : bench.reference.bySamples) {
                    bench.reference.ambiguousBySamples[spp] = marginsBelow(render.margins, kAmbiguityMargin);
                }
            }
        }

        // ---- results
        struct Row {
            double medianMpix = 0, bestMpix = 0, medianMs = 0, frameMs = 0, coreNsPerPixel = 0;
            std::optional<double> versusEmbree;
            unsigned threads = 0;
            ErrorMetrics error;
            std::optional<TopologyComparison> topology;  // none for a backend without pixel classes
        };
        std::vector<Row> rows(configurations.size());
        std::map<std::pair<std::size_t, std::uint32_t>, double> embreeMpix;  // (scene, spp) -> median
        for (std::size_t i = 0; i < configurations.size(); ++i) {
            const Configuration& configuration = configurations[i];
            const Measurement& measurement = measurements[i];
            const BenchScene& bench = scenes[configuration.scene];
            const double pixels = double(bench.scene.image.width) * bench.scene.image.height;
            Row& row = rows[i];
            row.medianMs = median(measurement.renderMilliseconds);
            const double bestMs =
                *std::min_element(measurement.renderMilliseconds.begin(), measurement.renderMilliseconds.end());
            row.medianMpix = pixels * 1e-6 / row.medianMs * 1e3;
            row.bestMpix = pixels * 1e-6 / bestMs * 1e3;
            row.frameMs = median(measurement.frameMilliseconds);
            row.threads = backends.threads(configuration.backend);
            row.coreNsPerPixel = row.medianMs * 1e6 * std::max(1u, row.threads) / pixels;
            const bool encodedOnDevice =
                configuration.backend == BenchBackend::Gpu || configuration.backend == BenchBackend::GpuCeiling;
            const Rgb8Image encoded = encodedOnDevice ? measurement.encoded
                                          : encodeImage(measurement.image, bench.scene.image.encoding);
            const std::uint32_t spp = configuration.samplesPerPixel;
            const Reference& reference = bench.reference;
            row.error = compareEncoded(bench.spheres ? encodeImage(reference.bySamples.at(spp).image,
                                                                   bench.scene.image.encoding)
                                                     : reference.colour,
                                       encoded);
            if (!measurement.classes.empty()) {
                row.topology = compareTopology(reference.bySamples.at(spp).classes, measurement.classes,
                                               reference.ambiguousBySamples.at(spp));
            }
            if (configuration.backend == BenchBackend::Embree) {
                embreeMpix[{configuration.scene, spp}] = row.medianMpix;
            }
        }
        for (std::size_t i = 0; i < configurations.size(); ++i) {
            const auto found = embreeMpix.find({configurations[i].scene, configurations[i].samplesPerPixel});
            if (found != embreeMpix.end()) {
                rows[i].versusEmbree = rows[i].medianMpix / found->second;
            }
        }

        std::ostringstream csv;
        csv << "scene,width,height,backend,precision,spp,median_mpix_s,best_mpix_s,median_render_ms,"
               "median_frame_ms,rmse_levels,max_abs_levels,pixels_over_one_level,topology_mismatches,"
               "spheres,threads,core_ns_per_pixel,vs_embree\n";
        const auto precisionOf = [&](const Configuration& configuration) {
            switch (configuration.backend) {
                case BenchBackend::Gpu: return std::string(precisionName(configuration.precision));
                case BenchBackend::GpuCeiling: return std::string("f32 textbook");
                case BenchBackend::Cpu: return std::string("f64 (double)");
                case BenchBackend::Embree: return std::string("f32 (Embree)");
            }
            return std::string();
        };
        const auto printTable = [&](bool curve) {
            if (curve) {
                std::printf("| spheres | resolution | backend | precision | spp | Mpix/s median | Mpix/s best | "
                            "frame ms | threads | core-ns per pixel | vs Embree | RMSE (levels) | max abs (levels) | "
                            "> 1 level | topology mismatches |\n");
                std::printf("|---:|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
            } else {
                std::printf("| scene | resolution | backend | precision | spp | Mpix/s median | Mpix/s best | frame ms | "
                            "RMSE (levels) | max abs (levels) | > 1 level | topology mismatches |\n");
                std::printf("|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
            }
            // The curve reads best grouped by N; file scenes keep their configuration order.
            std::vector<std::size_t> order;
            for (std::size_t i = 0; i < configurations.size(); ++i) {
                if (scenes[configurations[i].scene].spheres.has_value() == curve) {
                    order.push_back(i);
                }
            }
            std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
                return std::pair(configurations[a].scene, configurations[a].samplesPerPixel) <
                       std::pair(configurations[b].scene, configurations[b].samplesPerPixel);
            });
            for (std::size_t i : order) {
                const Configuration& configuration = configurations[i];
                const BenchScene& bench = scenes[configuration.scene];
                const Row& row = rows[i];
                const std::string backend = backends.name(configuration.backend);
                const std::string precision = precisionOf(configuration);
                char versus[32] = "–";
                if (row.versusEmbree) {
                    std::snprintf(versus, sizeof versus, "%.2f", *row.versusEmbree);
                }
                const std::string mismatches = row.topology ? std::to_string(row.topology->mismatches) : "–";
                if (curve) {
                    std::printf("| %u | %ux%u | %s | %s | %u | %.1f | %.1f | %.1f | %u | %.0f | %s | %.3f | %.0f | "
                                "%.3f%% | %s |\n",
                                *bench.spheres, bench.scene.image.width, bench.scene.image.height, backend.c_str(),
                                precision.c_str(), configuration.samplesPerPixel, row.medianMpix, row.bestMpix,
                                row.frameMs, row.threads, row.coreNsPerPixel, versus, row.error.rmse, row.error.maxAbs,
                                100.0 * row.error.shareOverOneLevel, mismatches.c_str());
                } else {
                    std::printf("| %s | %ux%u | %s | %s | %u | %.1f | %.1f | %.1f | %.3f | %.0f | %.3f%% | %s |\n",
                                bench.name.c_str(), bench.scene.image.width, bench.scene.image.height, backend.c_str(),
                                precision.c_str(), configuration.samplesPerPixel, row.medianMpix, row.bestMpix,
                                row.frameMs, row.error.rmse, row.error.maxAbs, 100.0 * row.error.shareOverOneLevel,
                                mismatches.c_str());
                }
                csv << bench.name << ',' << bench.scene.image.width << ',' << bench.scene.image.height << ','
                    << backend << ',' << precision << ',' << configuration.samplesPerPixel << ',' << row.medianMpix
                    << ',' << row.bestMpix << ',' << row.medianMs << ',' << row.frameMs << ',' << row.error.rmse
                    << ',' << row.error.maxAbs << ',' << row.error.pixelsOverOneLevel << ','
                    << (row.topology ? std::to_string(row.topology->mismatches) : "") << ','
                    << (bench.spheres ? std::to_string(*bench.spheres) : "") << ',' << row.threads << ','
                    << row.coreNsPerPixel << ','
                    << (row.versusEmbree ? std::to_string(*row.versusEmbree) : "") << '\n';
            }
        };
        if (!options.scenePaths.empty()) {
            printTable(false);
        }
        if (!counts.empty()) {
            if (!options.scenePaths.empty()) {
                std::printf("\n");
            }
            printTable(true);
        }
        if (!backends.hasEmbree()) {
            notes.push_back("Embree rows: none, this hexray was built without Embree 3 (libembree-dev).");
        } else {
            notes.push_back("Embree: " + backends.embreeVersion() + ".");
        }
        std::printf("\n");
        for (const std::string& note : notes) {
            std::printf("%s\n", note.c_str());
        }

        if (!options.csvPath.empty()) {
            OutputFile file(options.csvPath);
            const std::string text = csv.str();
            if (std::fwrite(text.data(), 1, text.size(), file.stream()) != text.size()) {
                file.fail("cannot write", "short write");
            }
            file.commit();
        }
        return int(kSuccess);
    });
    return withValidationVerdict(code, log);
}

}  // namespace hexray::cli
