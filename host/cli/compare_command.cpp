#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "cli/command_support.h"
#include "cpu/cpu_explain.h"
#include "cpu/cpu_renderer.h"
#include "gpu/gpu_renderer.h"
#include "image/aov.h"
#include "image/image_io.h"
#include "scene/scene_loader.h"

namespace hexray::cli {
namespace {

namespace fs = std::filesystem;

struct SceneFile {
    std::string path;
    std::string name;  // for the table: the path under the directory given, without .json
};

// The scene files named, with directories expanded to the *.json files under them, sorted.
std::vector<SceneFile> sceneFiles(const std::vector<std::string>& paths) {
    std::vector<SceneFile> files;
    for (const std::string& path : paths) {
        std::error_code error;
        if (!fs::is_directory(path, error)) {
            files.push_back({path, fs::path(path).stem().string()});  // a missing file is reported when loaded
            continue;
        }
        std::vector<SceneFile> found;
        for (auto entry = fs::recursive_directory_iterator(path, error); !error && entry != fs::end(entry);
             entry.increment(error)) {
            if (entry->is_regular_file() && entry->path().extension() == ".json") {
                found.push_back({entry->path().string(),
                                 fs::relative(entry->path(), path).replace_extension().string()});
            }
        }
        if (error) {
            throw SceneError(path + ": cannot read the directory: " + error.message());
        }
        if (found.empty()) {
            throw SceneError(path + ": no scene files (*.json) in this directory");
        }
        std::sort(found.begin(), found.end(), [](const SceneFile& a, const SceneFile& b) { return a.name < b.name; });
        files.insert(files.end(), found.begin(), found.end());
    }
    return files;
}

struct Row {
    Precision precision;
    bool chosenByAuto;
    bool judged;  // f32-naive rows in --all are shown, not judged: they exist to fail
    RenderComparison comparison;
    Verdict verdict;
    double gpuMilliseconds;
};

std::string psnrText(double psnr) {
    if (std::isinf(psnr)) {
        return "inf (identical)";
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", psnr);
    return text;
}

void printMetrics(const char* label, const ErrorMetrics& m, int decimalsForMax) {
    std::printf("  %-16s %10.*f %10.6f %10.6f %16s  %llu (%.4f%%)\n", label, decimalsForMax, m.maxAbs, m.meanAbs, m.rmse,
                psnrText(m.psnr).c_str(), static_cast<unsigned long long>(m.pixelsOverOneLevel),
                100.0 * m.shareOverOneLevel);
}

const char* okText(bool ok) {
    return ok ? "ok" : "EXCEEDED";
}

void printDetailed(const std::string& path, const Scene& scene, const Row& row, const std::string& gpuHow,
                   const std::string& cpuHow, const Tolerance& tolerance) {
    const TopologyComparison& t = row.comparison.topology;
    std::printf("scene %s: %ux%u, %s output\n", path.c_str(), scene.image.width, scene.image.height,
                scene.image.encoding == Encoding::Srgb ? "sRGB" : "linear");
    std::printf("  %s\n  %s\n", gpuHow.c_str(), cpuHow.c_str());
    std::printf("  ambiguous pixels (a decision within float32 rounding of flipping): %llu (%.4f%%)\n",
                static_cast<unsigned long long>(t.ambiguous), 100.0 * t.ambiguousShare());
    std::printf("  topology mismatches on unambiguous pixels: %llu (node %llu, checker cell %llu, lights %llu)\n",
                static_cast<unsigned long long>(t.mismatches), static_cast<unsigned long long>(t.nodeMismatches),
                static_cast<unsigned long long>(t.checkerMismatches), static_cast<unsigned long long>(t.lightMismatches));
    std::printf("  %-16s %10s %10s %10s %16s  %s\n", "unambiguous px", "max abs", "mean abs", "RMSE", "PSNR dB",
                "pixels > 1 level");
    printMetrics("linear [0,1]", row.comparison.linear, 6);
    printMetrics("8-bit [levels]", row.comparison.encoded, 0);
    std::printf("  tolerance: topology mismatches %llu <= %llu %s; pixels > 1 level %.4f%% <= %.4f%% %s; "
                "8-bit RMSE %.4f <= %.4f levels %s\n",
                static_cast<unsigned long long>(t.mismatches),
                static_cast<unsigned long long>(tolerance.maxTopologyMismatches), okText(row.verdict.topologyOk),
                100.0 * row.comparison.encoded.shareOverOneLevel, tolerance.maxSharePercent,
                okText(row.verdict.shareOk), row.comparison.encoded.rmse, tolerance.maxRmseLevels,
                okText(row.verdict.rmseOk));
    std::printf("%s\n", row.verdict.passed() ? "PASS" : "FAIL");
}

void printTableHeader() {
    std::printf("| scene | precision | auto | topology mismatches | ambiguous | max abs (levels) | RMSE (levels) "
                "| > 1 level | GPU ms | verdict |\n");
    std::printf("|---|---|:-:|---:|---:|---:|---:|---:|---:|---|\n");
}

void printTableRow(const std::string& scene, const Row& row) {
    const RenderComparison& c = row.comparison;
    std::printf("| %s | %s | %s | %llu | %.3f%% | %.0f | %.3f | %.3f%% | %.2f | %s |\n", scene.c_str(),
                std::string(precisionName(row.precision)).c_str(), row.chosenByAuto ? "✓" : "",
                static_cast<unsigned long long>(c.topology.mismatches), 100.0 * c.topology.ambiguousShare(),
                c.encoded.maxAbs, c.encoded.rmse, 100.0 * c.encoded.shareOverOneLevel, row.gpuMilliseconds,
                !row.judged ? (row.verdict.passed() ? "(pass)" : "(fail, not judged)") : row.verdict.passed() ? "pass" : "FAIL");
}

}  // namespace

int runCompare(const CompareOptions& options) {
    ValidationLog log;
    const int code = guarded([&] {
        const std::vector<SceneFile> files = sceneFiles(options.scenePaths);
        const bool table = options.allPrecisions || files.size() > 1;
        if (!options.diffPath.empty() && table) {
            throw SceneError("--diff: a heat map needs a single scene and a single precision");
        }
        if (!options.maskPath.empty() && table) {
            throw SceneError("--mask: a mismatch mask needs a single scene and a single precision");
        }
        if (!options.aovDirectory.empty() && table) {
            throw SceneError("--aov: AOVs need a single scene and a single precision");
        }
        const bool aov = !options.aovDirectory.empty();
        const VulkanContext context({options.vulkan.validate ? &log : nullptr, options.vulkan.device});
        GpuRenderer renderer(context);
        bool allPassed = true;
        if (table) {
            printTableHeader();
        }
        for (const SceneFile& file : files) {
            const Scene scene = loadScene(file.path, options.image);
            const unsigned threads = cpuThreadCount(options.threads);
            const auto cpuStart = std::chrono::steady_clock::now();
            const CpuRender reference = renderOnCpu(scene, threads, Acceleration::Auto, aov);
            const double cpuMilliseconds = millisecondsSince(cpuStart);
            const PixelMask ambiguous = marginsBelow(reference.margins, kAmbiguityMargin);

            const Precision automatic = renderer.resolve(scene, Precision::Auto);
            std::vector<Precision> precisions = {options.precision};
            if (options.allPrecisions) {
                precisions = {Precision::F32Naive, Precision::F32};
                if (context.selected().hasFloat64) {
                    precisions.push_back(Precision::F64);
                }
            }
            for (const Precision requested : precisions) {
                GpuRenderResult gpu =
                    renderer.render(scene, requested, aov ? GpuOutput::LinearClassesAndAov : GpuOutput::LinearAndClasses);
                Row row{gpu.precision,
                        gpu.precision == automatic,
                        !(options.allPrecisions && gpu.precision == Precision::F32Naive),
                        compareRenders(reference.image, reference.classes, ambiguous, gpu.image, gpu.classes,
                                       scene.image.encoding),
                        {},
                        gpu.timing.renderMilliseconds};
                row.verdict = judge(row.comparison, options.tolerance);
                allPassed = allPassed && (!row.judged || row.verdict.passed());
                if (table) {
                    printTableRow(file.name, row);
                    continue;
                }
                char gpuHow[256];
                std::snprintf(gpuHow, sizeof gpuHow, "gpu %s%s (%s): render %.2f ms",
                              std::string(precisionName(gpu.precision)).c_str(),
                              requested == Precision::Auto ? ", chosen by auto" : "", context.selected().name.c_str(),
                              gpu.timing.renderMilliseconds);
                char cpuHow[128];
                std::snprintf(cpuHow, sizeof cpuHow, "cpu reference (%u threads): render %.2f ms", threads,
                              cpuMilliseconds);
                printDetailed(file.path, scene, row, gpuHow, cpuHow, options.tolerance);
                const bool encodedNeeded = !options.diffPath.empty() || !options.maskPath.empty();
                const Rgb8Image reference8 = encodedNeeded ? encodeImage(reference.image, scene.image.encoding)
                                                           : Rgb8Image{};
                const Rgb8Image gpu8 = encodedNeeded ? encodeImage(gpu.image, scene.image.encoding) : Rgb8Image{};
                if (!options.diffPath.empty()) {
                    writePng(options.diffPath, diffHeatMap(reference8, gpu8));
                    std::printf("wrote diff heat map %s\n", options.diffPath.c_str());
                }
                if (!options.maskPath.empty()) {
                    writePng(options.maskPath, mismatchMask(reference.classes, gpu.classes, ambiguous, reference8, gpu8));
                    std::printf("wrote mismatch mask %s (red topology, yellow colour > 1 level, blue ambiguous)\n",
                                options.maskPath.c_str());
                }
                if (aov) {
                    const fs::path directory(options.aovDirectory);
                    StagedAovs gpuAovs(directory / "gpu", AovSet{scene.image.width, scene.image.height,
                                                                 std::move(gpu.depth), std::move(gpu.normals),
                                                                 gpu.classes, scene.lights.size()});
                    StagedAovs cpuAovs(directory / "cpu",
                                       AovSet{scene.image.width, scene.image.height, reference.depth,
                                              reference.normals, reference.classes, scene.lights.size(),
                                              &reference.margins, kAmbiguityMargin});
                    gpuAovs.commit();
                    cpuAovs.commit();
                    std::printf("wrote AOVs in %s and %s\n", (directory / "gpu").c_str(), (directory / "cpu").c_str());
                }
            }
        }
        if (table) {
            std::printf("%s\n", allPassed ? "PASS" : "FAIL");
        }
        return int(allPassed ? kSuccess : kToleranceExceeded);
    });
    return withValidationVerdict(code, log);
}

}  // namespace hexray::cli
