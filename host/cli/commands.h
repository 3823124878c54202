#pragma once
// hexray's subcommands. Each returns the process exit code (see ExitCode).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "compare/compare.h"
#include "precision/precision.h"
#include "gpu/render_plan.h"
#include "strip/strip.h"

namespace hexray::cli {

enum ExitCode : int {
    kSuccess = 0,
    kToleranceExceeded = 1,  // compare: the renders disagree by more than allowed
    kBadInput = 2,           // scene file or command line
    kVulkanUnavailable = 3,  // no driver or device, no compute queue, no float64 for f64, a failed call, a scene
                             // past the device's loop limit (gpu/loop_budget.h)
    kValidationFailed = 4,   // --validate and the validation layer reported something
    kOutputFailed = 5,       // the image (or CSV) could not be written
    kInternalError = 6,      // anything else: out of memory, a thread that could not start
    kDeviceLost = 7,         // the Vulkan device was lost, or hung, during the render
    kOutOfDeviceMemory = 8,  // the Vulkan driver ran out of device (or host) memory
    kSizeMismatch = 9,       // diff: the two images differ in size
};

// The subcommands, as messages list them.
inline constexpr const char* kCommandNames = "render, watch, merge, compare, diff, bench, pixel, devices, cache";

// Auto: the GPU, or the CPU reference (with a note) when the GPU path cannot render.
enum class Backend { Auto, Gpu, Cpu };

// Command-line replacements for the scene file's image settings, and changes to any of its values.
struct ImageOverride {
    std::optional<std::int64_t> width;
    std::optional<std::int64_t> height;
    std::optional<std::int64_t> samplesPerPixel;
    std::vector<std::string> settings;  // --set PATH=VALUE, applied in order (scene/scene_settings.h)
};

struct VulkanOptions {
    std::string device;  // index or part of a name; empty = best available
    bool validate = false;
};

struct RenderOptions {
    std::vector<std::string> scenePaths;  // scene files or directories of them, each rendered to its own file
    ImageOverride image;
    VulkanOptions vulkan;
    Backend backend = Backend::Auto;
    Precision precision = Precision::Auto;
    Culling culling = Culling::Auto;
    // Empty: <scene name>.png in the current directory. One scene: the file, or a directory to
    // put <scene name>.png in; several: that directory.
    std::string outputPath;
    unsigned threads = 0;        // CPU backend; 0 = all cores
    std::string aovDirectory;    // empty: no AOVs (see image/aov.h)
    std::optional<Strip> strip;  // only these rows, recorded in the file for `hexray merge`
    std::string jsonPath;        // empty: no --json document
};

// Which kernel `hexray watch` renders an edit with. Tiered: at once with the scene's generated kernel
// reading its values from a buffer (Buffered: a value edit needs no new pipeline), then with the
// specialised one (values compiled in, as `render` uses) once a background thread has built it.
// Or only one of them, or the data-driven kernel (the same program for every scene).
enum class WatchKernel { Tiered, Buffered, Specialised, DataDriven };

struct WatchOptions {
    std::string scenePath;
    std::string outputPath;  // empty: <scene name>.png here; else a PNG file, or a directory to put it in
    ImageOverride image;
    VulkanOptions vulkan;
    Precision precision = Precision::Auto;
    WatchKernel kernel = WatchKernel::Tiered;
    std::uint64_t frames = 0;  // stop after writing this many images; 0: at SIGINT or SIGTERM
};

struct MergeOptions {
    std::string outputPath;
    std::vector<std::string> piecePaths;
};

struct CompareOptions {
    std::vector<std::string> scenePaths;  // scene files or directories of them
    ImageOverride image;
    VulkanOptions vulkan;
    Precision precision = Precision::Auto;
    bool allPrecisions = false;  // f32-naive, f32 and f64 for every scene, as one table
    Tolerance tolerance;
    std::string diffPath;  // empty: no heat map (single scene only)
    unsigned threads = 0;
    std::string maskPath;      // empty: no mismatch mask (single scene only)
    std::string aovDirectory;  // empty: no AOVs; else <dir>/gpu, <dir>/cpu (with the margin)
    // The tolerance options given on the command line: they win over the expectations file's.
    ToleranceChanges toleranceGiven;
    std::string expectationsPath;  // empty: each scene's nearest hexray-expectations.json
    bool noExpectations = false;
    std::string jsonPath;         // empty: none; "-": standard output
    std::string junitPath;        // empty: none
    std::string reportDirectory;  // empty: none; else an HTML report and its images (cli/report_layout.h)
};

enum class PixelBackend { Both, Gpu, Cpu };

struct PixelOptions {
    std::string scenePath;
    std::int64_t x = 0;
    std::int64_t y = 0;
    std::int64_t sample = 0;
    ImageOverride image;
    VulkanOptions vulkan;
    PixelBackend backend = PixelBackend::Both;
    Precision precision = Precision::Auto;
    std::string jsonPath;  // empty: no --json document
};

struct BenchOptions {
    std::vector<std::string> scenePaths;
    // The scaling curve: a random-sphere scene (scene/random_spheres.h) for each count.
    std::vector<std::uint32_t> sphereCounts;
    // Curve configurations predicted to take longer per frame are not measured (nor larger N).
    double maxFrameSeconds = 5.0;
    ImageOverride image;
    VulkanOptions vulkan;
    // --backends: the names of the rows to measure (bench/bench_selection.h); empty, the default set.
    std::vector<std::string> backends;
    unsigned rounds = 5;
    std::vector<std::uint32_t> samples = {1, 4};  // spp of the configurations measured
    std::uint32_t referenceSamples = 64;          // spp of the converged CPU reference
    std::string csvPath;                          // empty: no CSV
    std::string jsonPath;                         // --json: empty, none; "-", standard output
};

// `hexray diff TEST REF`: thresholds apply to each pixel's largest channel difference on the
// [0, 1] scale (compare/image_difference.h).
struct DiffOptions {
    std::string testPath;            // "-": standard input
    std::string referencePath;       // "-": standard input (not both)
    double failDifference = 0.004;   // a pixel fails above this (just over one 8-bit level)
    double failPercent = 0.0;        // the command fails when more pixels than this fail
    double warnDifference = 0.0;     // a pixel warns above this
    double warnPercent = 0.0;        // a warning is printed when more pixels than this warn
    std::optional<double> failFlip;  // the command fails when the mean FLIP is above this
    double pixelsPerDegree = 0.0;    // FLIP's viewing condition; 0: compare/flip.h's default
    std::string heatmapPath;         // empty: no heat map
    std::string jsonPath;            // empty: no --json document
};

struct CacheOptions {
    bool clear = false;  // remove every entry
};

int runRender(const RenderOptions& options);
int runCompare(const CompareOptions& options);
int runDevices(const VulkanOptions& options);
int runBench(const BenchOptions& options);
int runPixel(const PixelOptions& options);
int runMerge(const MergeOptions& options);
// `hexray watch`: renders the scene, then again each time its file is saved, until SIGINT or
// SIGTERM (exit 0) or --frames images; a scene that fails to load is reported and waited on.
int runWatch(const WatchOptions& options);
// `hexray diff TEST REF`: exit 0 pass (warnings printed), 1 fail, 2 unreadable, 9 sizes differ.
int runDiff(const DiffOptions& options);
// `hexray cache`: the kernel cache's directory, entries, size and bound; or, with --clear, empties it.
int runCache(const CacheOptions& options);
// `hexray --version`: hexray's version and git revision, the Vulkan loader's version and the
// device hexray would use, with its driver (or why Vulkan is unavailable). Exit code 0 either way.
int runVersion();

}  // namespace hexray::cli
