// hexray: renders scene files with a Vulkan compute shader (or the CPU reference) and compares
// the two. The command line is defined here; the work is in the *_command.cpp files.

#include <CLI/CLI.hpp>

#include "cli/commands.h"

namespace {

using namespace hexray;
using namespace hexray::cli;

constexpr const char* kExitCodes =
    "Exit codes: 0 success; 1 compare tolerance exceeded; 2 bad input (scene file or command line);\n"
    "3 Vulkan unavailable or failed (no driver or device, no compute queue, no float64 for --precision f64);\n"
    "4 --validate and the validation layer reported messages; 5 the output image could not be written;\n"
    "6 any other failure (e.g. out of memory); 7 the Vulkan device was lost or hung during the render;\n"
    "8 the Vulkan driver ran out of device (or host) memory.\n"
    "render --backend auto (the default) renders on the CPU reference instead, with a note, after 3 (except an\n"
    "unknown --device or a missing validation layer), 7 or 8.";

void addImageOptions(CLI::App& command, ImageOverride& image) {
    command.add_option("--width", image.width, "Override the scene's image width (pixels)");
    command.add_option("--height", image.height, "Override the scene's image height (pixels)");
    command.add_option("--spp", image.samplesPerPixel,
                       "Override the scene's samples per pixel (anti-aliasing, 1 to 1024; default 1)");
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
    app.require_subcommand(1);
    bool validate = false;
    app.add_flag("--validate", validate,
                 "Enable the Khronos validation layer; any warning or error it reports fails the command "
                 "(exit code 4)");

    RenderOptions render;
    std::string renderBackend = "auto";
    std::string renderPrecision = "auto";
    CLI::App* renderCommand = app.add_subcommand("render", "Render a scene to a PNG image");
    renderCommand->add_option("scene", render.scenePath, "Scene file (JSON), see README.md")->required();
    renderCommand->add_option("-o,--output", render.outputPath, "Output PNG (default: <scene name>.png here)");
    renderCommand
        ->add_option("--backend", renderBackend,
                     "gpu: the Vulkan compute shader; cpu: the double-precision reference; auto: the GPU, or the "
                     "CPU reference (with a note on stderr) when the GPU path cannot render")
        ->check(CLI::IsMember({"auto", "gpu", "cpu"}))
        ->capture_default_str();
    addPrecisionOption(*renderCommand, renderPrecision);
    addImageOptions(*renderCommand, render.image);
    addDeviceOption(*renderCommand, render.vulkan);
    renderCommand->add_option("--threads", render.threads, "CPU backend threads (default: all cores)")
        ->check(CLI::PositiveNumber);
    renderCommand->add_option("--aov", render.aovDirectory,
                              "Also write depth, normal, object id and per-light shadow masks as OpenEXR files with "
                              "PNG previews into this directory (see README)");

    CompareOptions compare;
    std::string comparePrecision = "auto";
    CLI::App* compareCommand = app.add_subcommand(
        "compare",
        "Render scenes on the GPU and on the CPU reference and compare them: ambiguous pixels, topology "
        "mismatches outside them, colour errors on the rest. Fails when the tolerance is exceeded");
    compareCommand->add_option("scenes", compare.scenePaths, "Scene files, or directories of them")->required();
    CLI::Option* precisionOption = addPrecisionOption(*compareCommand, comparePrecision);
    compareCommand
        ->add_flag("--all", compare.allPrecisions,
                   "Every precision (f32-naive, f32, f64) for every scene, as one table; f32-naive rows are "
                   "shown but not judged")
        ->excludes(precisionOption);
    addImageOptions(*compareCommand, compare.image);
    addDeviceOption(*compareCommand, compare.vulkan);
    compareCommand->add_option("--diff", compare.diffPath, "Write a heat map of the 8-bit differences (PNG)");
    compareCommand
        ->add_option("--max-topology-mismatches", compare.tolerance.maxTopologyMismatches,
                     "Tolerance: unambiguous pixels whose node, checker cell or lit lights differ")
        ->capture_default_str();
    compareCommand
        ->add_option("--max-bad-pixels", compare.tolerance.maxSharePercent,
                     "Tolerance: share of unambiguous pixels, in percent, whose 8-bit value may differ by more "
                     "than one level")
        ->check(CLI::Range(0.0, 100.0))
        ->capture_default_str();
    compareCommand
        ->add_option("--max-rmse", compare.tolerance.maxRmseLevels,
                     "Tolerance: RMSE of the 8-bit output over unambiguous pixels, in levels")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    compareCommand->add_option("--threads", compare.threads, "CPU reference threads (default: all cores)")
        ->check(CLI::PositiveNumber);
    compareCommand->add_option("--mask", compare.maskPath,
                               "Write a PNG of where the renders disagree: red topology mismatch, yellow colour more "
                               "than one level off, blue ambiguous, black agreement");
    compareCommand->add_option("--aov", compare.aovDirectory,
                               "Write both backends' AOVs into DIR/gpu and DIR/cpu, and the CPU reference's decision "
                               "margin as DIR/cpu/margin.exr (see README)");

    BenchOptions bench;
    CLI::App* benchCommand = app.add_subcommand(
        "bench",
        "Measure speed against error: interleaved rounds of every backend, precision and sample count on each "
        "scene, against a converged CPU reference, and the scaling curve over random-sphere scenes; prints "
        "tables and optionally writes CSV");
    benchCommand->add_option("scenes", bench.scenePaths, "Scene files");
    benchCommand->add_option("--spheres", bench.sphereCounts,
                             "Sphere counts of the scaling curve (e.g. 1,10,100,1000,10000,100000): a random-sphere "
                             "scene each, measured on every backend")
        ->check(CLI::Range(1u, 1000000u))
        ->allow_extra_args(false)  // one comma-separated list, so scene files may follow it
        ->delimiter(',');
    benchCommand->add_option("--max-frame-seconds", bench.maxFrameSeconds,
                             "Curve only: a backend whose frame a low-resolution probe predicts to take longer is "
                             "not measured at that sphere count (its error columns still use a CPU reference render)")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    addImageOptions(*benchCommand, bench.image);
    addDeviceOption(*benchCommand, bench.vulkan);
    benchCommand->add_option("--rounds", bench.rounds, "Interleaved rounds")->check(CLI::Range(1u, 1000u))
        ->capture_default_str();
    benchCommand->add_option("--samples", bench.samples, "Samples per pixel to measure (several allowed)")
        ->check(CLI::Range(1u, kMaxSamplesPerPixel))
        ->capture_default_str();
    benchCommand->add_option("--reference-samples", bench.referenceSamples,
                             "Samples per pixel of the converged CPU reference")
        ->check(CLI::Range(1u, kMaxSamplesPerPixel))
        ->capture_default_str();
    benchCommand->add_option("--csv", bench.csvPath, "Also write the table as CSV");

    PixelOptions pixel;
    std::string pixelBackend = "both";
    std::string pixelPrecision = "auto";
    CLI::App* pixelCommand = app.add_subcommand(
        "pixel", "Explain one pixel: its ray, every node's intersection, the hit, the shading terms and the colour, "
                 "from the shader and from the CPU reference side by side");
    pixelCommand->add_option("scene", pixel.scenePath, "Scene file (JSON)")->required();
    pixelCommand->add_option("x", pixel.x, "Column, 0 at the left")->required();
    pixelCommand->add_option("y", pixel.y, "Row, 0 at the top")->required();
    pixelCommand->add_option("--backend", pixelBackend, "both (side by side), gpu or cpu")
        ->check(CLI::IsMember({"both", "gpu", "cpu"}))
        ->capture_default_str();
    addPrecisionOption(*pixelCommand, pixelPrecision);
    pixelCommand->add_option("--sample", pixel.sample, "Which of the pixel's samples to explain (with --spp > 1)")
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
        if (benchCommand->parsed() && bench.scenePaths.empty() && bench.sphereCounts.empty()) {
            throw CLI::ValidationError("bench", "needs scene files, --spheres, or both");
        }
    } catch (const CLI::ParseError& error) {
        const int code = app.exit(error);
        return code == 0 ? kSuccess : kBadInput;
    }

    if (renderCommand->parsed()) {
        render.vulkan.validate = validate;
        render.backend = renderBackend == "cpu" ? Backend::Cpu : renderBackend == "gpu" ? Backend::Gpu : Backend::Auto;
        render.precision = *parsePrecision(renderPrecision);
        return runRender(render);
    }
    if (compareCommand->parsed()) {
        compare.vulkan.validate = validate;
        compare.precision = *parsePrecision(comparePrecision);
        return runCompare(compare);
    }
    if (benchCommand->parsed()) {
        bench.vulkan.validate = validate;
        return runBench(bench);
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
