// The command line, one function per subcommand; the work is in the *_command.cpp files.

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench/bench_selection.h"
#include "cli/command_line.h"
#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/help_formatter.h"
#include "cli/named_values.h"
#include "cli/option_checks.h"
#include "cli/quiet.h"
#include "cli/terminal_output.h"
#include "cli/usage_errors.h"
#include "cpu/cpu_renderer.h"
#include "kernels/kernel_cache.h"
#include "io/output_plan.h"
#include "io/standard_output.h"
#include "scene/scene.h"
#include "util/closest_name.h"
#include "util/printable.h"

namespace {

using namespace hexray;
using namespace hexray::cli;

constexpr const char* kExitCodes =
    "Exit codes:\n"
    "  0  success\n"
    "  1  compare: the tolerance was exceeded; diff: more pixels differ than allowed\n"
    "  2  bad input: a scene file or the command line, a piece that does not fit a merge, an output that "
    "is an input or another output, or an image to a terminal\n"
    "  3  Vulkan unavailable or failed: no driver or device, no compute queue, no float64 for --precision f64\n"
    "  4  --validate, and the validation layer reported messages\n"
    "  5  an output cannot be written (its directory is checked before any work)\n"
    "  6  any other failure (out of memory: the message names what is too big, the scene or the image)\n"
    "  7  the Vulkan device was lost or hung during the render\n"
    "  8  the Vulkan driver ran out of device (or host) memory\n"
    "  9  diff: the two images differ in size\n"
    "render --backend auto (the default) renders on the CPU reference instead, with a note, after 3 (except "
    "an unknown --device or a missing validation layer), 7 or 8. render of several scenes renders every one it "
    "can and exits with the first failed scene's code.";

// A subcommand's help ends with an example and a pointer to the exit codes (printed once, by
// hexray --help).
void setExample(CLI::App& command, const std::string& example) {
    command.footer("Example:\n  " + example + "\n\nExit codes: hexray --help lists them.");
}

// Every subcommand's options, as parsing fills them in.
struct CommandLine {
    bool validate = false;
    bool quiet = false;
    RenderOptions render;
    std::string renderStrip;
    WatchOptions watch;
    MergeOptions merge;
    CompareOptions compare;
    DiffOptions diff;
    BenchOptions bench;
    PixelOptions pixel;
    VulkanOptions devices;
    CacheOptions cache;
};

void addImageOptions(CLI::App& command, ImageOverride& image) {
    const CLI::Validator size = IntegerBetween<std::int64_t>(1, kMaxImageDimension);
    command.add_option("--width", image.width, "Override the scene's image width (pixels)")->check(size);
    command.add_option("--height", image.height, "Override the scene's image height (pixels)")->check(size);
    command
        .add_option("--spp", image.samplesPerPixel,
                    "Override the scene's samples per pixel (anti-aliasing, 1 to 1024; default: the scene's "
                    "image.spp, itself 1 when the scene does not say)")
        ->check(IntegerBetween<std::int64_t>(1, kMaxSamplesPerPixel));
}

// render, compare and pixel: changes to the scene's JSON before it is read (scene/scene_settings.h).
void addSceneSettingOption(CLI::App& command, ImageOverride& image) {
    command
        .add_option("--set", image.settings,
                    "Change the scene before reading it, e.g. --set camera.fov=60 or --set "
                    "nodes[1].geometry.radius=1.5 (PATH as messages name places; VALUE JSON, else a string); "
                    "repeatable")
        ->type_name("PATH=VALUE")
        ->allow_extra_args(false);  // one setting per --set, so scene files may follow it
}

CLI::Option* addThreadsOption(CLI::App& command, unsigned& threads, const char* what) {
    return command
        .add_option("--threads", threads,
                    std::string(what) + " threads (default: all cores; at most the image's height and " +
                        std::to_string(kMaxCpuThreads) + " are started)")
        ->check(IntegerBetween<unsigned>(1, UINT_MAX));
}

void addDeviceOption(CLI::App& command, VulkanOptions& vulkan) {
    command.add_option("--device", vulkan.device,
                       "Vulkan device: index or part of the name, as `hexray devices` lists them (default: a "
                       "discrete GPU, else an integrated, virtual or CPU one such as lavapipe, with a compute queue)");
}

CLI::Option* addPrecisionOption(CLI::App& command, Precision& precision) {
    return addNamedOption(command, "--precision", precision, precisionNames(),
                          "Shader arithmetic: auto (per scene: f32 when its float32 error stays below 1e-3 of the "
                          "scene's smallest feature, else f64), f32, f64 (needs shaderFloat64), f32-naive (the "
                          "textbook formulas, for comparison), or f32-certified (f32 checking each decision against "
                          "its error bound, the pixels in doubt rendered again in f64: f64's decisions; needs "
                          "shaderFloat64)");
}

void addRenderCommand(CLI::App& app, CommandLine& line) {
    RenderOptions& render = line.render;
    CLI::App* command = app.add_subcommand(
        "render", "Render scenes to images (PNG or OpenEXR), each scene to its own file, in one process");
    command
        ->add_option("scenes", render.scenePaths,
                     "Scene files (JSON: image, camera, lights, shaders and nodes), or directories of them (every "
                     "*.json below)")
        ->required();
    command
        ->add_option("-o,--output", render.outputPath,
                     "Output image, by its extension: .png (8-bit), .exr (linear float RGB, before encoding), or - "
                     "(PNG on standard output). Default: <scene name>.png here. With several scenes, or when it is "
                     "a directory: the directory the images go into, as <scene name>.png")
        ->check(NotEmpty());
    addNamedOption(*command, "--backend", render.backend, kBackendNames,
                   "gpu: the Vulkan compute shader; cpu: the double-precision reference; auto: the GPU, or the CPU "
                   "reference (with a note on stderr) when the GPU path cannot render");
    addPrecisionOption(*command, render.precision);
    addNamedOption(*command, "--culling", render.culling, kCullingNames,
                   "GPU: render screen tiles with kernels that leave out the tests their rays cannot need (the "
                   "same image): on, off, or auto (for renders of at least 32 million samples, where it repays "
                   "compiling the extra kernels)");
    addImageOptions(*command, render.image);
    addSceneSettingOption(*command, render.image);
    addDeviceOption(*command, render.vulkan);
    addThreadsOption(*command, render.threads, "CPU backend");
    command
        ->add_option("--aov", render.aovDirectory,
                     "Also write, from each pixel's first sample, depth.exr, normal.exr, object-id.exr and "
                     "light-<i>.exr (1 where light i reaches the point), with a PNG preview of each, into this "
                     "directory")
        ->check(NotEmpty())
        ->check(AovDirectoryName());
    command
        ->add_option("--strip", line.renderStrip,
                     "Render only strip I of N (0 <= I < N): rows I*H/N to (I+1)*H/N - 1, recorded in the file for "
                     "`hexray merge` (default name <scene name>.strip-I-of-N.png)")
        ->check(StripSpec());
    command
        ->add_option("--json", render.jsonPath,
                     "Also write the results as JSON (- for standard output; the report then goes to standard "
                     "error): per scene its size, backend, precision, kernel, timings and exit (docs/json-output.md)")
        ->check(NotEmpty());
    setExample(*command, "hexray render scenes/lecture-demo.json -o demo.png --width 1920 --height 1080");
}

void addWatchCommand(CLI::App& app, CommandLine& line) {
    WatchOptions& watch = line.watch;
    CLI::App* command = app.add_subcommand(
        "watch",
        "Render a scene on the GPU, then again each time its file is saved, in one process that keeps the "
        "device and its kernels; until Ctrl-C (exit 0). A scene that fails to load is reported and waited on");
    command->add_option("scene", watch.scenePath, "Scene file (JSON)")->required();
    command->add_option("-o,--output", watch.outputPath,
                        "Output PNG, replaced whole at each render (default: <scene name>.png here; a directory: "
                        "<scene name>.png in it)");
    addNamedOption(*command, "--kernel", watch.kernel, kWatchKernelNames,
                   "tiered: each edit at once with the scene's kernel reading its values from a buffer (an edited "
                   "value needs no new pipeline), then again (the same image) with its values compiled in once a "
                   "background thread has built that; buffered, specialised or data-driven: only that kernel");
    command
        ->add_option("--frames", watch.frames,
                     "Stop after writing N images (a tiered edit writes two); default: at SIGINT or SIGTERM")
        ->check(IntegerBetween<std::uint64_t>(1, UINT64_MAX));
    addPrecisionOption(*command, watch.precision);
    addImageOptions(*command, watch.image);
    addSceneSettingOption(*command, watch.image);
    addDeviceOption(*command, watch.vulkan);
    setExample(*command, "hexray watch scenes/lecture-demo.json -o demo.png --frames 2");
}

void addMergeCommand(CLI::App& app, CommandLine& line) {
    CLI::App* command = app.add_subcommand(
        "merge",
        "Assemble the pieces of `render --strip I/N` into the whole image; refuses missing, overlapping "
        "or mismatched pieces");
    command->add_option("output", line.merge.outputPath, "The whole image (.png, .exr as the pieces, or -)")
        ->required()
        ->check(NotEmpty());
    command->add_option("pieces", line.merge.piecePaths, "Every piece, in any order")->required();
    setExample(*command, "hexray merge demo.png lecture-demo.strip-*-of-4.png");
}

// compare's results for CI: the expectations file and the machine-readable outputs.
void addCompareGateOptions(CLI::App& command, CompareOptions& compare) {
    CLI::Option* expectations =
        command
            .add_option("--expectations", compare.expectationsPath,
                        "Read tolerances and expected failures from this file instead of each scene's nearest "
                        "hexray-expectations.json (docs/compare-expectations.md); command-line tolerances win")
            ->check(NotEmpty());
    command.add_flag("--no-expectations", compare.noExpectations, "Ignore every hexray-expectations.json")
        ->excludes(expectations);
    command
        .add_option("--json", compare.jsonPath,
                    "Write the results as JSON (- for standard output; "
                    "docs/json-output.md)")
        ->check(NotEmpty());
    command
        .add_option("--junit", compare.junitPath,
                    "Write the results as JUnit XML: one test case per scene "
                    "and precision")
        ->check(NotEmpty());
    command
        .add_option("--report", compare.reportDirectory,
                    "Write an HTML report into this directory: a summary table and, per scene and precision, "
                    "the GPU image, the CPU reference, the heat map and the mask (docs/compare.md)")
        ->check(NotEmpty());
}

void addCompareCommand(CLI::App& app, CommandLine& line) {
    CompareOptions& compare = line.compare;
    CLI::App* command = app.add_subcommand(
        "compare",
        "Render scenes on the GPU and on the CPU reference and compare them: ambiguous pixels, topology "
        "mismatches in the decisions not near-tied, colour errors where the classes agree. Fails when the "
        "tolerance is exceeded");
    command->add_option("scenes", compare.scenePaths, "Scene files, or directories of them")->required();
    CLI::Option* precisionOption = addPrecisionOption(*command, compare.precision);
    command
        ->add_flag("--all", compare.allPrecisions,
                   "Every precision (f32-naive, f32, f64) for every scene, as one table; f32-naive rows are "
                   "shown but not judged")
        ->excludes(precisionOption);
    addImageOptions(*command, compare.image);
    addSceneSettingOption(*command, compare.image);
    addDeviceOption(*command, compare.vulkan);
    command->add_option("--diff", compare.diffPath, "Write a heat map of the 8-bit differences (PNG)")
        ->check(NotEmpty());
    command
        ->add_option("--max-topology-mismatches", compare.tolerance.maxTopologyMismatches,
                     "Tolerance: pixels whose node, checker cell or lit lights differ in a decision not near-tied")
        ->check(IntegerBetween<std::uint64_t>(0, std::numeric_limits<std::uint64_t>::max()))
        ->capture_default_str();
    command
        ->add_option("--max-bad-pixels", compare.tolerance.maxSharePercent,
                     "Tolerance: share of the pixels whose colours are compared, in percent, whose 8-bit value "
                     "may differ by more than one level")
        ->check(FiniteNumberBetween(0.0, 100.0))
        ->capture_default_str();
    command
        ->add_option("--max-ambiguous", compare.tolerance.maxAmbiguousPercent,
                     "Tolerance: share of pixels, in percent, with a decision within rounding of flipping "
                     "(a comparison of mostly such pixels proves little)")
        ->check(FiniteNumberBetween(0.0, 100.0))
        ->capture_default_str();
    command
        ->add_option("--max-rmse", compare.tolerance.maxRmseLevels,
                     "Tolerance: RMSE of the 8-bit output over the pixels whose colours are compared, in levels")
        ->check(FiniteNumberBetween(0.0, 255.0))
        ->capture_default_str();
    addThreadsOption(*command, compare.threads, "CPU reference");
    command
        ->add_option("--mask", compare.maskPath,
                     "Write a PNG of where the renders disagree: magenta a colour not finite and >= 0, red "
                     "topology mismatch, blue excused (differs only in near-tied decisions), yellow colour more "
                     "than one level off, navy near-tied but agreeing, black agreement")
        ->check(NotEmpty());
    command
        ->add_option("--aov", compare.aovDirectory,
                     "Write both backends' AOVs (as render --aov does) into DIR/gpu and DIR/cpu, and the CPU "
                     "reference's decision margin as DIR/cpu/margin.exr")
        ->check(NotEmpty())
        ->check(AovDirectoryName());
    addCompareGateOptions(*command, compare);
    setExample(*command, "hexray compare scenes/ --json results.json --junit results.xml");
}

// The tolerance options given on compare's command line, which win over an expectations file's.
ToleranceChanges toleranceGiven(const CLI::App& command, const Tolerance& tolerance) {
    ToleranceChanges given;
    if (command.count("--max-topology-mismatches") > 0) {
        given.maxTopologyMismatches = tolerance.maxTopologyMismatches;
    }
    if (command.count("--max-bad-pixels") > 0) {
        given.maxSharePercent = tolerance.maxSharePercent;
    }
    if (command.count("--max-rmse") > 0) {
        given.maxRmseLevels = tolerance.maxRmseLevels;
    }
    if (command.count("--max-ambiguous") > 0) {
        given.maxAmbiguousPercent = tolerance.maxAmbiguousPercent;
    }
    return given;
}

void addDiffCommand(CLI::App& app, CommandLine& line) {
    DiffOptions& diff = line.diff;
    CLI::App* command = app.add_subcommand(
        "diff",
        "Compare two image files (two PNGs or two OpenEXR files) as OpenImageIO's idiff does: RMSE, PSNR, the "
        "largest difference, the share of pixels over one 8-bit level, and FLIP (LDR-FLIP for PNG, HDR-FLIP for "
        "OpenEXR). A pixel's difference is its largest channel's, on a [0, 1] scale (8-bit: levels / 255; OpenEXR: "
        "the linear values). Fails (exit 1) when more than --failpercent of the pixels differ by more than --fail");
    command->add_option("test", diff.testPath, "The image under test (- for standard input)")
        ->required()
        ->check(NotEmpty());
    command->add_option("reference", diff.referencePath, "The reference image (- for standard input)")
        ->required()
        ->check(NotEmpty());
    command->add_option("--fail", diff.failDifference, "A pixel fails when its difference is above this")
        ->check(FiniteNumberBetween(0.0, 1.0e30))
        ->capture_default_str();
    command
        ->add_option("--failpercent", diff.failPercent,
                     "The command fails when more than this percentage of pixels fail")
        ->check(FiniteNumberBetween(0.0, 100.0))
        ->capture_default_str();
    command->add_option("--warn", diff.warnDifference, "A pixel warns when its difference is above this")
        ->check(FiniteNumberBetween(0.0, 1.0e30))
        ->capture_default_str();
    command
        ->add_option("--warnpercent", diff.warnPercent,
                     "A warning is printed (exit 0) when more than this percentage of pixels warn")
        ->check(FiniteNumberBetween(0.0, 100.0))
        ->capture_default_str();
    command->add_option("--fail-flip", diff.failFlip, "Also fail when the mean FLIP is above this (0 to 1)")
        ->check(FiniteNumberBetween(0.0, 1.0));
    command
        ->add_option("--ppd", diff.pixelsPerDegree,
                     "FLIP's viewing condition in pixels per degree (default: a 0.7 m wide 3840-pixel monitor seen "
                     "from 0.7 m, 67.02, as the FLIP papers)")
        ->check(FiniteNumberBetween(1.0, 1000.0));
    command->add_option("--heatmap", diff.heatmapPath, "Write the FLIP map as a heat map PNG (black: no difference)")
        ->check(NotEmpty());
    command
        ->add_option("--json", diff.jsonPath, "Write the results as JSON (docs/json-output.md; - for standard output)")
        ->check(NotEmpty());
    setExample(*command, "hexray diff new.png reference.png --fail 0.01 --failpercent 0.5 --heatmap flip.png");
}

// --backends: each name one of the bench's rows (bench/bench_selection.h), else refused naming them all.
CLI::Validator benchRowName() {
    std::vector<std::string> names;
    std::string list;
    for (const BenchRowName& row : benchRowNames()) {
        names.push_back(row.name);
        list += (list.empty() ? "" : ",") + row.name;
    }
    list = "{" + list + "}";
    return CLI::Validator(
        [names, list](const std::string& input) -> std::string {
            if (std::find(names.begin(), names.end(), input) != names.end()) {
                return {};
            }
            const std::optional<std::string> near = closestName(input, names);
            return input + " not in " + list + (near ? "; did you mean " + *near + "?" : "");
        },
        "");  // the help lists the names, each with its meaning
}

void addBenchCommand(CLI::App& app, CommandLine& line) {
    BenchOptions& bench = line.bench;
    CLI::App* command = app.add_subcommand(
        "bench",
        "Measure speed against error: interleaved rounds of every backend, precision and sample count on each "
        "scene, against a converged CPU reference, and the scaling curve over random-sphere scenes; prints "
        "tables and optionally writes CSV");
    command->add_option("scenes", bench.scenePaths,
                        "Scene files (none, and no --spheres: the shipped demo scene, lecture-demo)");
    command
        ->add_option("--spheres", bench.sphereCounts,
                     "Sphere counts of the scaling curve (e.g. 1,10,100,1000,10000,100000): a random-sphere "
                     "scene each, measured on every backend")
        ->check(IntegerBetween<std::uint32_t>(1, 1000000))
        ->allow_extra_args(false)  // one comma-separated list, so scene files may follow it
        ->delimiter(',');
    command
        ->add_option("--max-frame-seconds", bench.maxFrameSeconds,
                     "Curve only: a backend whose frame a low-resolution probe predicts to take longer is "
                     "not measured at that sphere count (its error columns still use a CPU reference render)")
        ->check(FiniteNumberAbove(0.0))
        ->capture_default_str();
    command
        ->add_option("--backends", bench.backends,
                     "The rows to measure, comma-separated: gpu (gpu-f32, gpu-f64, gpu-f32-naive, gpu-f32-certified), "
                     "hand-written, cpu "
                     "(also the converged reference), embree (the widest packets, shading in float), "
                     "embree-f64-packets, embree-f64-single, all (default: gpu,hand-written,cpu,embree)")
        ->check(benchRowName())
        ->type_name("NAME")
        ->allow_extra_args(false)
        ->delimiter(',');
    addImageOptions(*command, bench.image);
    addDeviceOption(*command, bench.vulkan);
    command->add_option("--rounds", bench.rounds, "Interleaved rounds")
        ->check(IntegerBetween<unsigned>(1, 1000))
        ->capture_default_str();
    command->add_option("--samples", bench.samples, "Samples per pixel to measure (several allowed)")
        ->check(IntegerBetween<std::uint32_t>(1, kMaxSamplesPerPixel))
        ->capture_default_str();
    command
        ->add_option("--reference-samples", bench.referenceSamples, "Samples per pixel of the converged CPU reference")
        ->check(IntegerBetween<std::uint32_t>(1, kMaxSamplesPerPixel))
        ->capture_default_str();
    command->add_option("--csv", bench.csvPath, "Also write the table as CSV (- for standard output)")
        ->check(NotEmpty());
    command
        ->add_option("--json", bench.jsonPath,
                     "Also write every figure as JSON (- for standard output; docs/json-output.md)")
        ->check(NotEmpty());
    setExample(*command, "hexray bench scenes/lecture-demo.json --rounds 3 --csv bench.csv");
}

void addPixelCommand(CLI::App& app, CommandLine& line) {
    PixelOptions& pixel = line.pixel;
    CLI::App* command = app.add_subcommand(
        "pixel",
        "Explain one pixel: its ray, every node's intersection, the hit, the shading terms and the colour, "
        "from the shader and from the CPU reference side by side");
    command->add_option("scene", pixel.scenePath, "Scene file (JSON)")->required();
    command->add_option("x", pixel.x, "Column, 0 at the left")->required()->check(AnInteger<std::int64_t>());
    command->add_option("y", pixel.y, "Row, 0 at the top")->required()->check(AnInteger<std::int64_t>());
    addNamedOption(*command, "--backend", pixel.backend, kPixelBackendNames, "both (side by side), gpu or cpu");
    addPrecisionOption(*command, pixel.precision);
    command->add_option("--sample", pixel.sample, "Which of the pixel's samples to explain (with --spp > 1)")
        ->check(IntegerBetween<std::int64_t>(0, kMaxSamplesPerPixel - 1))
        ->capture_default_str();
    addImageOptions(*command, pixel.image);
    addSceneSettingOption(*command, pixel.image);
    addDeviceOption(*command, pixel.vulkan);
    command
        ->add_option("--json", pixel.jsonPath,
                     "Also write the explanation as JSON (- for standard output; the table then goes to standard "
                     "error): each backend's ray, candidates, hit, lights and colour (docs/json-output.md)")
        ->check(NotEmpty());
    setExample(*command, "hexray pixel scenes/lecture-demo.json 400 300 --backend both");
}

void addDevicesCommand(CLI::App& app, CommandLine& line) {
    CLI::App* command = app.add_subcommand("devices", "List the Vulkan devices and the one hexray would use");
    addDeviceOption(*command, line.devices);
    setExample(*command, "hexray devices --device llvmpipe");
}

void addCacheCommand(CLI::App& app, CommandLine& line) {
    CLI::App* command = app.add_subcommand(
        "cache",
        "Show where the kernel cache is (compiled kernels, $XDG_CACHE_HOME/hexray), its entries, size and "
        "bound (HEXRAY_KERNEL_CACHE_MAX_SIZE, e.g. 256M; default 128M)");
    command->add_flag("--clear", line.cache.clear, "Remove every entry");
    setExample(*command, "hexray cache --clear");
}

void defineCommandLine(CLI::App& app, CommandLine& line) {
    app.formatter(std::make_shared<HelpFormatter>());  // before the subcommands, which share it
    app.footer(kExitCodes);
    app.require_subcommand(1);
    app.fallthrough();  // the global options below are accepted after the subcommand too
    app.add_flag("--validate", line.validate,
                 "Enable the Khronos validation layer; any warning or error it reports fails the command "
                 "(exit code 4). Also accepted after the command, as --version is");
    app.add_flag("-q,--quiet", line.quiet,
                 "No progress and no summary lines (\"wrote …\", compare's and diff's reports); errors, warnings "
                 "and the data asked for still come out. Also accepted after the command");
    app.add_flag_callback(
        "--version", [] { throw CLI::CallForVersion("", 0); },
        "Print hexray's version and git revision, the Vulkan loader's version and the device and driver hexray "
        "would use");
    addRenderCommand(app, line);
    addWatchCommand(app, line);
    addMergeCommand(app, line);
    addCompareCommand(app, line);
    addDiffCommand(app, line);
    addBenchCommand(app, line);
    addPixelCommand(app, line);
    addDevicesCommand(app, line);
    addCacheCommand(app, line);
}

// What CLI11 cannot check on its own; throws CLI::ValidationError.
void checkCombinations(const CLI::App& app, const CommandLine& line) {
    const bool cpuOnlyWithPrecision = (app.got_subcommand("render") && line.render.backend == Backend::Cpu &&
                                       app.get_subcommand("render")->count("--precision") > 0) ||
                                      (app.got_subcommand("pixel") && line.pixel.backend == PixelBackend::Cpu &&
                                       app.get_subcommand("pixel")->count("--precision") > 0);
    if (cpuOnlyWithPrecision) {
        throw CLI::ValidationError("--precision", "applies to the GPU backend only");
    }
    if (app.got_subcommand("diff") && line.diff.testPath == "-" && line.diff.referencePath == "-") {
        throw CLI::ValidationError("diff", "only one of TEST and REF can be standard input (-)");
    }
    const RenderOptions& render = line.render;
    if (app.got_subcommand("render") && !render.jsonPath.empty() && !render.outputPath.empty() &&
        namesStandardOutput(render.jsonPath) && namesStandardOutput(render.outputPath)) {
        throw CLI::ValidationError("--json", "standard output carries the image (-o -): write the document to a file");
    }
}

// An image output that would go to a terminal: the message refusing it.
std::optional<std::string> imageToTerminal(const CommandLine& line) {
    const std::pair<const char*, const std::string*> images[] = {
        {"-o", &line.render.outputPath},    {"-o", &line.watch.outputPath},     {"the output", &line.merge.outputPath},
        {"--diff", &line.compare.diffPath}, {"--mask", &line.compare.maskPath}, {"--heatmap", &line.diff.heatmapPath}};
    for (const auto& [option, path] : images) {
        if (!path->empty() && writesToTerminal(*path)) {
            const std::string file = option[0] == '-' ? std::string(option) + " FILE" : "a file name";
            return std::string(option) + " " + printable(*path) +
                   ": standard output is a terminal, and an image is not text: pipe it (... | display) or give " + file;
        }
    }
    return std::nullopt;
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
        if (!bench.jsonPath.empty()) {
            plan.addFile("--json", bench.jsonPath);
        }
        plan.check();
        return int(kSuccess);
    });
}

int runRenderCommand(CommandLine& line) {
    RenderOptions& render = line.render;
    render.vulkan.validate = line.validate;
    render.strip = parseStrip(line.renderStrip);
    return runRender(render);
}

int runPixelCommand(CommandLine& line) {
    PixelOptions& pixel = line.pixel;
    pixel.vulkan.validate = line.validate;
    return runPixel(pixel);
}

// Runs the subcommand parsed.
int runCommand(const CLI::App& app, CommandLine& line) {
    if (app.got_subcommand("render")) {
        return runRenderCommand(line);
    }
    if (app.got_subcommand("watch")) {
        line.watch.vulkan.validate = line.validate;
        return runWatch(line.watch);
    }
    if (app.got_subcommand("merge")) {
        return runMerge(line.merge);
    }
    if (app.got_subcommand("compare")) {
        line.compare.vulkan.validate = line.validate;
        line.compare.toleranceGiven = toleranceGiven(*app.get_subcommand("compare"), line.compare.tolerance);
        return runCompare(line.compare);
    }
    if (app.got_subcommand("diff")) {
        return runDiff(line.diff);
    }
    if (app.got_subcommand("bench")) {
        line.bench.vulkan.validate = line.validate;
        const int checked = checkBenchPaths(line.bench);
        return checked != kSuccess ? checked : runBench(line.bench);
    }
    if (app.got_subcommand("pixel")) {
        return runPixelCommand(line);
    }
    if (app.got_subcommand("cache")) {
        return runCache(line.cache);
    }
    line.devices.validate = line.validate;
    return runDevices(line.devices);
}

}  // namespace

int hexray::cli::runCommandLine(int argc, char** argv) {
    CLI::App app(
        "hexray: a raytracer whose renderer is a Vulkan compute shader, checked against an "
        "independent CPU reference.",
        "hexray");
    CommandLine line;
    defineCommandLine(app, line);
    if (const std::optional<std::string> message = unknownCommandMessage(argc, argv, app)) {
        printError(*message);
        return kBadInput;
    }
    try {
        app.parse(argc, argv);
        checkCombinations(app, line);
    } catch (const CLI::CallForVersion&) {
        return runVersion();
    } catch (const CLI::ParseError& error) {
        return reportParseError(app, error);
    }
    setQuiet(line.quiet);
    if (const std::optional<std::string> refusal = imageToTerminal(line)) {
        printError(*refusal);
        return kBadInput;
    }
    try {  // refused before any work, whatever the command
        KernelCache::configuredMaxBytes();
    } catch (const KernelCacheSettingError& error) {
        printError(error.what());
        return kBadInput;
    }
    // Standard output carries the data when an output is "-" (or a path to it): what the command
    // prints goes to standard error then.
    const int reserved = guarded([&] {
        reserveStandardOutputForData({line.render.outputPath, line.render.jsonPath, line.merge.outputPath,
                                      line.compare.diffPath, line.compare.maskPath, line.compare.jsonPath,
                                      line.compare.junitPath, line.bench.csvPath, line.bench.jsonPath,
                                      line.diff.heatmapPath, line.diff.jsonPath, line.pixel.jsonPath});
        return int(kSuccess);
    });
    return reserved != kSuccess ? reserved : runCommand(app, line);
}
