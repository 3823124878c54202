// hexray: renders scene files with a Vulkan compute shader (or the CPU reference) and compares
// the two. The command line is defined here; the work is in commands.cpp.

#include <CLI/CLI.hpp>

#include "cli/commands.h"

namespace {

using namespace hexray::cli;

constexpr const char* kExitCodes =
    "Exit codes: 0 success; 1 compare tolerance exceeded; 2 bad input (scene file or command line);\n"
    "3 Vulkan unavailable or failed; 4 --validate and the validation layer reported messages;\n"
    "5 the output image could not be written.";

void addSceneOptions(CLI::App& command, SceneOptions& scene) {
    command.add_option("scene", scene.scenePath, "Scene file (JSON), see README.md")->required();
    command.add_option("--width", scene.width, "Override the scene's image width (pixels)");
    command.add_option("--height", scene.height, "Override the scene's image height (pixels)");
}

void addDeviceOption(CLI::App& command, VulkanOptions& vulkan) {
    command.add_option("--device", vulkan.device,
                       "Vulkan device: index or part of the name, as `hexray devices` lists them "
                       "(default: a discrete or integrated GPU if present, else lavapipe)");
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
    CLI::App* renderCommand = app.add_subcommand("render", "Render a scene to a PNG image");
    addSceneOptions(*renderCommand, render.scene);
    renderCommand->add_option("-o,--output", render.outputPath, "Output PNG (default: <scene name>.png here)");
    std::string backend = "gpu";
    renderCommand
        ->add_option("--backend", backend, "gpu: the Vulkan compute shader; cpu: the double-precision reference")
        ->check(CLI::IsMember({"gpu", "cpu"}))
        ->capture_default_str();
    addDeviceOption(*renderCommand, render.vulkan);
    renderCommand->add_option("--threads", render.threads, "CPU backend threads (default: all cores)")
        ->check(CLI::PositiveNumber);

    CompareOptions compare;
    CLI::App* compareCommand = app.add_subcommand(
        "compare", "Render a scene on the GPU and on the CPU reference, print error metrics, and fail when they "
                   "differ by more than the tolerance");
    addSceneOptions(*compareCommand, compare.scene);
    addDeviceOption(*compareCommand, compare.vulkan);
    compareCommand->add_option("--diff", compare.diffPath, "Write a heat map of the 8-bit differences (PNG)");
    compareCommand
        ->add_option("--max-bad-pixels", compare.tolerance.maxSharePercent,
                     "Tolerance: largest share of pixels, in percent, whose 8-bit value may differ by more than "
                     "one level")
        ->check(CLI::Range(0.0, 100.0))
        ->capture_default_str();
    compareCommand
        ->add_option("--max-rmse", compare.tolerance.maxRmseLevels,
                     "Tolerance: largest RMSE of the 8-bit output, in levels")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    compareCommand->add_option("--threads", compare.threads, "CPU reference threads (default: all cores)")
        ->check(CLI::PositiveNumber);

    VulkanOptions devices;
    CLI::App* devicesCommand = app.add_subcommand("devices", "List the Vulkan devices and the one hexray would use");
    addDeviceOption(*devicesCommand, devices);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        const int code = app.exit(error);
        return code == 0 ? kSuccess : kBadInput;
    }

    if (renderCommand->parsed()) {
        render.vulkan.validate = validate;
        render.backend = backend == "cpu" ? Backend::Cpu : Backend::Gpu;
        return runRender(render);
    }
    if (compareCommand->parsed()) {
        compare.vulkan.validate = validate;
        return runCompare(compare);
    }
    devices.validate = validate;
    return runDevices(devices);
}
