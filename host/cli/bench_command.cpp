#include <algorithm>
#include <chrono>
#include <cstdio>
#include <sstream>
#include <functional>
#include <map>

#include "cli/command_support.h"
#include "compare/compare.h"
#include "cpu/cpu_renderer.h"
#include "gpu/gpu_renderer.h"
#include "image/atomic_file.h"
#include "image/image_io.h"
#include "scene/scene_loader.h"

namespace hexray::cli {
namespace {

// One thing to measure: a backend, precision and sample count on one scene.
struct Configuration {
    std::string scene;  // as given on the command line
    std::string backend;  // "lavapipe" (or the device's name) or "cpu-reference"
    Precision precision = Precision::F32;  // GPU only
    std::uint32_t samplesPerPixel = 1;
};

struct Measurement {
    std::vector<double> renderMilliseconds;  // dispatch time (GPU) or render wall time (CPU)
    std::vector<double> frameMilliseconds;   // the whole frame: upload, render, read back
    Image image;
    std::vector<PixelClass> classes;
};

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

// What every configuration of a scene is judged against: the CPU reference at a high sample
// count for colour; for the pixel classes (those of each pixel's first sample) and their
// ambiguity, the CPU reference at the configuration's own sample count.
struct Reference {
    Image converged;
    std::map<std::uint32_t, CpuRender> bySamples;
    std::map<std::uint32_t, PixelMask> ambiguousBySamples;
};

}  // namespace

int runBench(const BenchOptions& options) {
    ValidationLog log;
    const int code = guarded([&] {
        const VulkanContext context({options.vulkan.validate ? &log : nullptr, options.vulkan.device});
        GpuRenderer renderer(context);
        const std::string device = context.selected().name.find("llvmpipe") != std::string::npos
                                       ? "lavapipe"
                                       : context.selected().name;
        std::map<std::string, Scene> scenes;
        std::map<std::string, Reference> references;
        std::vector<Configuration> configurations;
        for (const std::string& path : options.scenePaths) {
            Scene scene = loadScene(path, options.image);
            std::fprintf(stderr, "bench: converged reference for %s (%u spp on the CPU)...\n", path.c_str(),
                         options.referenceSamples);
            Reference& reference = references[path];
            Scene sampled = scene;
            sampled.image.samplesPerPixel = options.referenceSamples;
            reference.converged = renderOnCpu(sampled).image;
            for (std::uint32_t spp : options.samples) {
                sampled.image.samplesPerPixel = spp;
                reference.bySamples[spp] = renderOnCpu(sampled);
                reference.ambiguousBySamples[spp] = marginsBelow(reference.bySamples[spp].margins, kAmbiguityMargin);
                for (Precision precision : {Precision::F32Naive, Precision::F32, Precision::F64}) {
                    if (precision != Precision::F64 || context.selected().hasFloat64) {
                        configurations.push_back({path, device, precision, spp});
                    }
                }
                configurations.push_back({path, "cpu-reference", Precision::F64, spp});
            }
            scenes[path] = std::move(scene);
        }

        // Interleaved rounds: every configuration once per round, so the machine's drift and
        // noise fall on all of them alike.
        std::vector<Measurement> measurements(configurations.size());
        for (unsigned round = 0; round < options.rounds; ++round) {
            std::fprintf(stderr, "bench: round %u of %u\n", round + 1, options.rounds);
            for (std::size_t i = 0; i < configurations.size(); ++i) {
                const Configuration& configuration = configurations[i];
                Scene scene = scenes[configuration.scene];
                scene.image.samplesPerPixel = configuration.samplesPerPixel;
                Measurement& measurement = measurements[i];
                const auto start = std::chrono::steady_clock::now();
                if (configuration.backend == "cpu-reference") {
                    CpuRender render = renderOnCpu(scene);
                    measurement.renderMilliseconds.push_back(millisecondsSince(start));
                    measurement.image = std::move(render.image);
                    measurement.classes = std::move(render.classes);
                } else {
                    GpuRenderResult render = renderer.render(scene, configuration.precision);
                    measurement.renderMilliseconds.push_back(render.timing.renderMilliseconds);
                    measurement.image = std::move(render.image);
                    measurement.classes = std::move(render.classes);
                }
                measurement.frameMilliseconds.push_back(millisecondsSince(start));
            }
        }

        std::ostringstream csv;
        csv << "scene,width,height,backend,precision,spp,median_mpix_s,best_mpix_s,median_render_ms,"
                   "median_frame_ms,rmse_levels,max_abs_levels,pixels_over_one_level,topology_mismatches\n";
        std::printf("| scene | resolution | backend | precision | spp | Mpix/s median | Mpix/s best | frame ms | "
                    "RMSE (levels) | max abs (levels) | > 1 level | topology mismatches |\n");
        std::printf("|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        for (std::size_t i = 0; i < configurations.size(); ++i) {
            const Configuration& configuration = configurations[i];
            const Measurement& measurement = measurements[i];
            const Scene& scene = scenes[configuration.scene];
            const Reference& reference = references[configuration.scene];
            const double megapixels = double(scene.image.width) * scene.image.height * 1e-6;
            const double medianMs = median(measurement.renderMilliseconds);
            const double bestMs = *std::min_element(measurement.renderMilliseconds.begin(),
                                                    measurement.renderMilliseconds.end());
            const ErrorMetrics error = compareEncoded(encodeImage(reference.converged, scene.image.encoding),
                                                      encodeImage(measurement.image, scene.image.encoding));
            const std::uint32_t spp = configuration.samplesPerPixel;
            const TopologyComparison topology = compareTopology(reference.bySamples.at(spp).classes, measurement.classes,
                                                                reference.ambiguousBySamples.at(spp));
            const std::string precision =
                configuration.backend == "cpu-reference" ? "f64 (double)" : std::string(precisionName(configuration.precision));
            const std::string name = std::filesystem::path(configuration.scene).stem().string();
            std::printf("| %s | %ux%u | %s | %s | %u | %.1f | %.1f | %.1f | %.3f | %.0f | %.3f%% | %llu |\n", name.c_str(),
                        scene.image.width, scene.image.height, configuration.backend.c_str(), precision.c_str(),
                        configuration.samplesPerPixel, megapixels / medianMs * 1e3, megapixels / bestMs * 1e3,
                        median(measurement.frameMilliseconds), error.rmse, error.maxAbs, 100.0 * error.shareOverOneLevel,
                        static_cast<unsigned long long>(topology.mismatches));
            csv << name << ',' << scene.image.width << ',' << scene.image.height << ',' << configuration.backend << ','
                << precision << ',' << configuration.samplesPerPixel << ',' << megapixels / medianMs * 1e3 << ','
                << megapixels / bestMs * 1e3 << ',' << medianMs << ',' << median(measurement.frameMilliseconds) << ','
                << error.rmse << ',' << error.maxAbs << ',' << error.pixelsOverOneLevel << ',' << topology.mismatches
                << '\n';
        }
        if (!options.csvPath.empty()) {
            AtomicFile file(options.csvPath);
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
