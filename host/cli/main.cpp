// hexray: renders scene files with a Vulkan compute shader (or the CPU reference) and compares
// the two. The command line is defined here; the work is in the *_command.cpp files.

#include <climits>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/option_checks.h"
#include "cpu/cpu_renderer.h"
#include "io/output_plan.h"
#include "io/standard_output.h"
#include "scene/scene.h"

namespace {

using namespace hexray;
using namespace hexray::cli;

constexpr const char* kExitCodes =
    "Exit codes: 0 success; 1 compare tolerance exceeded; 2 bad input (scene file or command line, or an\n"
    "output that is an input or another output); 3 Vulkan unavailable or failed (no driver or device, no compute\n"
    "queue, no float64 for --precision f64); 4 --validate and the validation layer reported messages; 5 an output\n"
    "cannot be written (its directory is checked before any work); 6 any other failure (out of memory: make the\n"
    "image narrower); 7 the Vulkan device was lost or hung during the render;\n"
    "8 the Vulkan driver ran out of device (or host) memory.\n"
    "render --backend auto (the default) renders on the CPU reference instead, with a note, after 3 (except an\n"
    "unknown --device or a missing validation layer), 7 or 8.";

void addImageOptions(CLI::App& command, ImageOverride& image) {
    const CLI::Validator size = IntegerBetween<std::int64_t>(1, kMaxImageDimension);
    command.add_option("--width", image.width, "Override the scene's image width (pixels)")->check(size);
    command.add_option("--height", image.height, "Override the scene's image height (pixels)")->check(size);
    command
        .add_option("--spp", image.samplesPerPixel,
                    "Override the scene's samples per pixel (anti-aliasing, 1 to 1024; default 1)")
        ->check(IntegerBetween<std::int64_t>(1, kMaxSamplesPerPixel));
}

CLI::Option* addThreadsOption(CLI::App& command, unsigned& threads, const char* what) {
    return command
        .add_option("--threads", threads,
                    std::string(what) + " threads (default: all cores; at most the image's height and " +
                        std::to_string(kMaxCpuThreads) + " are started)")
        ->check(IntegerBetween<unsigned>(1, UINT_MAX));
}

// The bench's paths, checked before its rounds (the bench itself only writes the CSV at the end).
int checkBenchPaths(const BenchOptions& bench) {
    return guarded([&] {
        OutputPlan plan;
        for (const std::string& scene : bench.scenePaths) {
            plan.addInput("the scene", scene);
        }
        if (!bench.csvPath.empty()) {
            plan.addFile("--csv", bench.csvPath);
        }
        plan.check();
        return int(kSuccess);
    });
}

void addDeviceOption(CLI::App& command, VulkanOptions& vulkan) {
    command.add_option("--device", vulkan.device,
                       "Vulkan device: index or part of the name, as `hexray devices` lists them "
                       "(default: a discrete or integrated GPU if present, else lavapipe)");
}

CLI::Option* addPrecisionOption(CLI::App& command, std::string& precision) {
    return command
        .add_option("--precision", precision,
                    "Shader arithmetic: auto (per scene, see README), f32, f64 (needs shaderFloat64), or "
                    "f32-naive (the textbook formulas, for comparison)")
        ->check(CLI::IsMember({"auto", "f32", "f64", "f32-naive"}))
        ->capture_default_str();
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("hexray: a raytracer whose renderer is a Vulkan compute shader, checked against an "
                 "independent CPU reference.",
                 "hexray");
    app.footer(kExitCodes);
    app.failure_message([](const CLI::App*, const CLI::Error& error) {
        return std::string("hexray: error: ") + error.what() + "\nRun with --help for more information.\n";
    });
    app.require_subcommand(1);
    bool validate = false;
    app.add_flag("--validate", validate,
                 "Enable the Khronos validation layer; any warning or error it reports fails the command "
                 "(exit code 4)");

    RenderOptions render;
    std::string renderBackend = "auto";
    std::string renderPrecision = "auto";
    std::string renderCulling = "auto";
    CLI::App* renderCommand = app.add_subcommand("render", "Render a scene to a PNG image");
    renderCommand->add_option("scene", render.scenePath, "Scene file (JSON), see README.md")->required();
    renderCommand
        ->add_option("-o,--output", render.outputPath,
                     "Output PNG (default: <scene name>.png here; - for standard output)")
        ->check(NotEmpty());
    renderCommand
        ->add_option("--backend", renderBackend,
                     "gpu: the Vulkan compute shader; cpu: the double-precision reference; auto: the GPU, or the "
                     "CPU reference (with a note on stderr) when the GPU path cannot render")
        ->check(CLI::IsMember({"auto", "gpu", "cpu"}))
        ->capture_default_str();
    addPrecisionOption(*renderCommand, renderPrecision);
    renderCommand
        ->add_option("--culling", renderCulling,
                     "GPU: render screen tiles with kernels that leave out the tests their rays cannot need "
                     "(the same image): on, off, or auto (for renders of at least 32 million samples, where it "
                     "repays compiling the extra kernels)")
        ->check(CLI::IsMember({"auto", "on", "off"}))
        ->capture_default_str();
    addImageOptions(*renderCommand, render.image);
    addDeviceOption(*renderCommand, render.vulkan);
    addThreadsOption(*renderCommand, render.threads, "CPU backend");
    renderCommand
        ->add_option("--aov", render.aovDirectory,
                     "Also write depth, normal, object id and per-light shadow masks as OpenEXR files with "
                     "PNG previews into this directory (see README)")
        ->check(NotEmpty());

    CompareOptions compare;
    std::string comparePrecision = "auto";
    CLI::App* compareCommand = app.add_subcommand(
        "compare",
        "Render scenes on the GPU and on the CPU reference and compare them: ambiguous pixels, topology "
        "mismatches in the decisions not near-tied, colour errors where the classes agree. Fails when the "
        "tolerance is exceeded");
    compareCommand->add_option("scenes", compare.scenePaths, "Scene files, or directories of them")->required();
    CLI::Option* precisionOption = addPrecisionOption(*compareCommand, comparePrecision);
    compareCommand
        ->add_flag("--all", compare.allPrecisions,
                   "Every precision (f32-naive, f32, f64) for every scene, as one table; f32-naive rows are "
                   "shown but not judged")
        ->excludes(precisionOption);
    addImageOptions(*compareCommand, compare.image);
    addDeviceOption(*compareCommand, compare.vulkan);
    compareCommand->add_option("--diff", compare.diffPath, "Write a heat map of the 8-bit differences (PNG)")
        ->check(NotEmpty());
    compareCommand
        ->add_option("--max-topology-mismatches", compare.tolerance.maxTopologyMismatches,
                     "Tolerance: pixels whose node, checker cell or lit lights differ in a decision not near-tied")
        ->check(IntegerBetween<std::uint64_t>(0, std::numeric_limits<std::uint64_t>::max()))
        ->capture_default_str();
    compareCommand
        ->add_option("--max-bad-pixels", compare.tolerance.maxSharePercent,
                     "Tolerance: share of the pixels whose colours are compared, in percent, whose 8-bit value "
                     "may differ by more than one level")
        ->check(FiniteNumberBetween(0.0, 100.0))
        ->capture_default_str();
    compareCommand
        ->add_option("--max-ambiguous", compare.tolerance.maxAmbiguousPercent,
                     "Tolerance: share of pixels, in percent, with a decision within rounding of flipping "
                     "(a comparison of mostly such pixels proves little)")
        ->check(FiniteNumberBetween(0.0, 100.0))
        ->capture_default_str();
    compareCommand
        ->add_option("--max-rmse", compare.tolerance.maxRmseLevels,
                     "Tolerance: RMSE of the 8-bit output over the pixels whose colours are compared, in levels")
        ->check(FiniteNumberBetween(0.0, 255.0))
        ->capture_default_str();
    addThreadsOption(*compareCommand, compare.threads, "CPU reference");
    compareCommand
        ->add_option("--mask", compare.maskPath,
                     "Write a PNG of where the renders disagree: magenta a colour not finite and >= 0, red "
                     "topology mismatch, blue excused (differs only in near-tied decisions), yellow colour more "
                     "than one level off, navy near-tied but agreeing, black agreement")
        ->check(NotEmpty());
    compareCommand
        ->add_option("--aov", compare.aovDirectory,
                     "Write both backends' AOVs into DIR/gpu and DIR/cpu, and the CPU reference's decision "
                     "margin as DIR/cpu/margin.exr (see README)")
        ->check(NotEmpty());

    BenchOptions bench;
    CLI::App* benchCommand = app.add_subcommand(
        "bench",
        "Measure speed against error: interleaved rounds of every backend, precision and sample count on each "
        "scene, against a converged CPU reference, and the scaling curve over random-sphere scenes; prints "
        "tables and optionally writes CSV");
    benchCommand->add_option("scenes", bench.scenePaths,
                             "Scene files (none, and no --spheres: the shipped demo scene, lecture-demo)");
    benchCommand->add_option("--spheres", bench.sphereCounts,
                             "Sphere counts of the scaling curve (e.g. 1,10,100,1000,10000,100000): a random-sphere "
                             "scene each, measured on every backend")
        ->check(IntegerBetween<std::uint32_t>(1, 1000000))
        ->allow_extra_args(false)  // one comma-separated list, so scene files may follow it
        ->delimiter(',');
    benchCommand->add_option("--max-frame-seconds", bench.maxFrameSeconds,
                             "Curve only: a backend whose frame a low-resolution probe predicts to take longer is "
                             "not measured at that sphere count (its error columns still use a CPU reference render)")
        ->check(FiniteNumberAbove(0.0))
        ->capture_default_str();
    addImageOptions(*benchCommand, bench.image);
    addDeviceOption(*benchCommand, bench.vulkan);
    benchCommand->add_option("--rounds", bench.rounds, "Interleaved rounds")
        ->check(IntegerBetween<unsigned>(1, 1000))
        ->capture_default_str();
    benchCommand->add_option("--samples", bench.samples, "Samples per pixel to measure (several allowed)")
        ->check(IntegerBetween<std::uint32_t>(1, kMaxSamplesPerPixel))
        ->capture_default_str();
    benchCommand->add_option("--reference-samples", bench.referenceSamples,
                             "Samples per pixel of the converged CPU reference")
        ->check(IntegerBetween<std::uint32_t>(1, kMaxSamplesPerPixel))
        ->capture_default_str();
    benchCommand->add_option("--csv", bench.csvPath, "Also write the table as CSV (- for standard output)")
        ->check(NotEmpty());

    PixelOptions pixel;
    std::string pixelBackend = "both";
    std::string pixelPrecision = "auto";
    CLI::App* pixelCommand = app.add_subcommand(
        "pixel", "Explain one pixel: its ray, every node's intersection, the hit, the shading terms and the colour, "
                 "from the shader and from the CPU reference side by side");
    pixelCommand->add_option("scene", pixel.scenePath, "Scene file (JSON)")->required();
    pixelCommand->add_option("x", pixel.x, "Column, 0 at the left")->required()->check(AnInteger<std::int64_t>());
    pixelCommand->add_option("y", pixel.y, "Row, 0 at the top")->required()->check(AnInteger<std::int64_t>());
    pixelCommand->add_option("--backend", pixelBackend, "both (side by side), gpu or cpu")
        ->check(CLI::IsMember({"both", "gpu", "cpu"}))
        ->capture_default_str();
    addPrecisionOption(*pixelCommand, pixelPrecision);
    pixelCommand->add_option("--sample", pixel.sample, "Which of the pixel's samples to explain (with --spp > 1)")
        ->check(IntegerBetween<std::int64_t>(0, kMaxSamplesPerPixel - 1))
        ->capture_default_str();
    addImageOptions(*pixelCommand, pixel.image);
    addDeviceOption(*pixelCommand, pixel.vulkan);

    VulkanOptions devices;
    CLI::App* devicesCommand = app.add_subcommand("devices", "List the Vulkan devices and the one hexray would use");
    addDeviceOption(*devicesCommand, devices);

    try {
        app.parse(argc, argv);
        const bool cpuOnlyWithPrecision =
            (renderCommand->parsed() && renderBackend == "cpu" && renderCommand->count("--precision") > 0) ||
            (pixelCommand->parsed() && pixelBackend == "cpu" && pixelCommand->count("--precision") > 0);
        if (cpuOnlyWithPrecision) {
            throw CLI::ValidationError("--precision", "applies to the GPU backend only");
        }
    } catch (const CLI::ParseError& error) {
        const int code = app.exit(error);
        return code == 0 ? kSuccess : kBadInput;
    }

    // Standard output carries the data when an output is "-" (or a path to it): what the command
    // prints goes to standard error then.
    if (const int code = guarded([&] {
            reserveStandardOutputForData({render.outputPath, compare.diffPath, compare.maskPath, bench.csvPath});
            return int(kSuccess);
        });
        code != kSuccess) {
        return code;
    }
    if (renderCommand->parsed()) {
        render.vulkan.validate = validate;
        render.backend = renderBackend == "cpu" ? Backend::Cpu : renderBackend == "gpu" ? Backend::Gpu : Backend::Auto;
        render.precision = *parsePrecision(renderPrecision);
        render.culling = renderCulling == "on" ? Culling::On : renderCulling == "off" ? Culling::Off : Culling::Auto;
        return runRender(render);
    }
    if (compareCommand->parsed()) {
        compare.vulkan.validate = validate;
        compare.precision = *parsePrecision(comparePrecision);
        return runCompare(compare);
    }
    if (benchCommand->parsed()) {
        bench.vulkan.validate = validate;
        const int checked = checkBenchPaths(bench);
        return checked != kSuccess ? checked : runBench(bench);
    }
    if (pixelCommand->parsed()) {
        pixel.vulkan.validate = validate;
        pixel.backend = pixelBackend == "gpu" ? PixelBackend::Gpu : pixelBackend == "cpu" ? PixelBackend::Cpu
                                                                                        : PixelBackend::Both;
        pixel.precision = *parsePrecision(pixelPrecision);
        return runPixel(pixel);
    }
    devices.validate = validate;
    return runDevices(devices);
}
