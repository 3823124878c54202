#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>

#include "cli/band_outputs.h"
#include "cli/command_support.h"
#include "cli/compare_expectations.h"
#include "cli/comparison_json.h"
#include "cli/comparison_junit.h"
#include "cli/comparison_record.h"
#include "cli/json_document.h"
#include "cli/progress.h"
#include "cli/quiet.h"
#include "cli/report_directory.h"
#include "cli/report_page.h"
#include "cli/scene_files.h"
#include "precision/decision_roundoff.h"
#include "compare/band_flip.h"
#include "compare/flip.h"
#include "compare/render_comparator.h"
#include "cpu/cpu_renderer.h"
#include "gpu/gpu_renderer.h"
#include "image/aov.h"
#include "image/image_io.h"
#include "image/provenance.h"
#include "io/output_plan.h"
#include "io/standard_output.h"
#include "scene/scene_loader.h"
#include "util/build_version.h"
#include "util/printable.h"

namespace hexray::cli {
namespace {

namespace fs = std::filesystem;

std::string psnrText(double psnr) {
    if (std::isinf(psnr)) {
        return "inf (identical)";
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", psnr);
    return text;
}

void printMetrics(const char* label, const ErrorMetrics& m, int decimalsForMax) {
    std::printf("  %-16s %10.*f %10.6f %10.6f %16s  %llu (%.4f%%)\n", label, decimalsForMax, m.maxAbs, m.meanAbs,
                m.rmse, psnrText(m.psnr).c_str(), static_cast<unsigned long long>(m.pixelsOverOneLevel),
                100.0 * m.shareOverOneLevel);
}

// "0.00123", or "–" where the image was too large to keep whole (compare/band_flip.h).
std::string flipText(const std::optional<double>& mean) {
    if (!mean) {
        return "–";
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.5f", *mean);
    return text;
}

const char* okText(bool ok) {
    return ok ? "ok" : "EXCEEDED";
}

void printDetailed(const ComparisonRecord& record, const std::string& gpuHow, const std::string& cpuHow) {
    const RenderComparison& c = record.comparison;
    const TopologyComparison& t = c.topology;
    const Tolerance& tolerance = record.expectation.tolerance;
    const Verdict& v = record.verdict;
    std::printf("scene %s: %ux%u, %s output\n", printable(record.scenePath).c_str(), record.width, record.height,
                record.encoding == Encoding::Srgb ? "sRGB" : "linear");
    std::printf("  %s\n  %s\n", gpuHow.c_str(), cpuHow.c_str());
    std::printf("  ambiguous pixels (a decision within rounding of flipping): %llu (%.4f%%)\n",
                static_cast<unsigned long long>(t.ambiguous), 100.0 * t.ambiguousShare());
    std::printf("  excused pixels (differ only in near-tied decisions, or colour not comparable): %llu (%.4f%%)\n",
                static_cast<unsigned long long>(t.excused), 100.0 * t.excusedShare());
    std::printf("  topology mismatches in decisions not near-tied: %llu (node %llu, checker cell %llu, lights %llu)\n",
                static_cast<unsigned long long>(t.mismatches), static_cast<unsigned long long>(t.nodeMismatches),
                static_cast<unsigned long long>(t.checkerMismatches),
                static_cast<unsigned long long>(t.lightMismatches));
    std::printf("  colours NaN, infinite or negative (either render, any pixel): %llu\n",
                static_cast<unsigned long long>(c.invalidColours));
    std::printf("  %-16s %10s %10s %10s %16s  %s\n", "compared colours", "max abs", "mean abs", "RMSE", "PSNR dB",
                "pixels > 1 level");
    printMetrics("linear [0,1]", c.linear, 6);
    printMetrics("8-bit [levels]", c.encoded, 0);
    std::printf("  mean LDR-FLIP of the 8-bit outputs (every pixel, %.2f pixels per degree): %s\n",
                kDefaultPixelsPerDegree, flipText(record.flipMean).c_str());
    std::printf(
        "  tolerance: invalid colours %llu <= 0 %s; topology mismatches %llu <= %llu %s; ambiguous pixels "
        "%.4f%% <= %.4f%% %s; pixels > 1 level %.4f%% <= %.4f%% %s; 8-bit RMSE %.4f <= %.4f levels %s\n",
        static_cast<unsigned long long>(c.invalidColours), okText(v.valuesOk),
        static_cast<unsigned long long>(t.mismatches), static_cast<unsigned long long>(tolerance.maxTopologyMismatches),
        okText(v.topologyOk), 100.0 * t.ambiguousShare(), tolerance.maxAmbiguousPercent, okText(v.ambiguousOk),
        100.0 * c.encoded.shareOverOneLevel, tolerance.maxSharePercent, okText(v.shareOk), c.encoded.rmse,
        tolerance.maxRmseLevels, okText(v.rmseOk));
    std::printf("  %s: %s\n", std::string(outcomeName(record.outcome.outcome)).c_str(),
                printable(record.outcome.reason).c_str());
}

// The table's verdict column: what failed, and whether the expectations file expected it.
std::string verdictText(const ComparisonRecord& record) {
    const bool passed = record.verdict.passed();
    const bool onlyAmbiguous = !record.verdict.ambiguousOk && record.verdict.topologyOk && record.verdict.shareOk &&
                               record.verdict.rmseOk && record.verdict.valuesOk;
    switch (record.outcome.outcome) {
        case Outcome::NotJudged:
            return passed ? "(pass)" : "(fail, not judged)";
        case Outcome::Passed:
            return "pass";
        case Outcome::Expected:
            return onlyAmbiguous ? "expected (too ambiguous)" : "expected (fail)";
        default:
            return passed ? "FAIL (passed; expected " + std::string(expectedName(record.expectation.expect)) + ")"
                   : onlyAmbiguous ? "FAIL (too ambiguous)"
                                   : "FAIL";
    }
}

void printTableHeader() {
    std::printf(
        "| scene | precision | auto | topology mismatches | ambiguous | excused | max abs (levels) "
        "| RMSE (levels) | mean FLIP | > 1 level | GPU ms | verdict |\n");
    std::printf("|---|---|:-:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
}

void printTableRow(const ComparisonRecord& record) {
    const RenderComparison& c = record.comparison;
    std::printf("| %s | %s | %s | %llu | %.3f%% | %.3f%% | %.0f | %.3f | %s | %.3f%% | %.2f | %s |\n",
                printable(record.name).c_str(), std::string(precisionName(record.precision)).c_str(),
                record.chosenByAuto ? "✓" : "", static_cast<unsigned long long>(c.topology.mismatches),
                100.0 * c.topology.ambiguousShare(), 100.0 * c.topology.excusedShare(), c.encoded.maxAbs,
                c.encoded.rmse, flipText(record.flipMean).c_str(), 100.0 * c.encoded.shareOverOneLevel,
                record.gpuMilliseconds, verdictText(record).c_str());
}

void printFailedRow(const std::string& scene) {
    std::printf("| %s | – | | – | – | – | – | – | – | – | – | FAIL (cannot load: see the error above) |\n",
                printable(scene).c_str());
}

// The gate's last line: "PASS: 18 passed, 9 expected, 0 failed".
void printCountLine(const OutcomeCounts& counts) {
    std::printf("%s: %llu passed, %llu expected, %llu failed", counts.gatePassed() ? "PASS" : "FAIL",
                static_cast<unsigned long long>(counts.passed), static_cast<unsigned long long>(counts.expected),
                static_cast<unsigned long long>(counts.failed));
    if (counts.notJudged > 0) {
        std::printf(" (%llu shown, not judged)", static_cast<unsigned long long>(counts.notJudged));
    }
    std::printf("\n");
}

// What the GPU render of a comparison records (image/provenance.h); its heat map and mask record
// the backend "gpu vs cpu", the CPU reference's AOVs the CPU's.
Provenance gpuProvenance(const Scene& scene, const std::string& sceneIdentity, const std::string& device,
                         Precision precision) {
    return Provenance{.version = hexrayVersion(),
                      .gitRevision = hexrayGitRevision(),
                      .image = {},  // each file names its own
                      .scene = sceneIdentity,
                      .backend = "gpu",
                      .device = device,
                      .precision = std::string(precisionName(precision)),
                      .samplesPerPixel = scene.image.samplesPerPixel,
                      .width = scene.image.width,
                      .height = scene.image.height};
}

// What one comparison of a scene in one precision found and took.
struct BandedComparison {
    RenderComparison comparison;
    std::optional<double> flipMean;
    Precision precision;
    double gpuMilliseconds;
    double cpuMilliseconds;
    unsigned threads;
};

// Renders `scene` on the GPU a band at a time, the CPU reference for the same rows as each band
// arrives, and compares them; `outputs` (if any) get each band's rows. On a terminal, a progress
// line names the scene by `path`.
BandedComparison compareInBands(GpuRenderer& renderer, const std::string& path, const Scene& scene, Precision requested,
                                unsigned threads, BandOutputs* outputs) {
    const bool aov = outputs && outputs->withAovs();
    Progress progress("comparing " + path, scene.image.height);
    // The CPU reference's rows as they finish, so that the line moves within a band too.
    const auto referenceRowsDone = [&](std::uint32_t firstRow) -> std::function<void(std::uint32_t)> {
        if (!Progress::shown()) {
            return {};
        }
        return [&progress, firstRow](std::uint32_t rows) { progress.update(firstRow + rows); };
    };
    const RenderPlan plan = renderer.plan(scene, {requested});
    // The reference's margins are read against the arithmetic of the render it is compared with.
    const CpuBandRenderer reference(scene, threads, Acceleration::Auto, aov, decisionRoundoff(plan.precision));
    RenderComparator comparator;
    BandFlip flip(scene.image.width, scene.image.height, scene.image.encoding);
    CpuRender cpu;
    double cpuMilliseconds = 0;
    const Encoding encoding = scene.image.encoding;
    const GpuRenderResult gpu = renderer.renderLinearRows(
        scene, plan, aov ? GpuOutput::LinearClassesAndAov : GpuOutput::LinearAndClasses,
        [&](std::uint32_t firstRow, const GpuRenderResult& band) {
            const auto start = std::chrono::steady_clock::now();
            reference.render(firstRow, band.image.height, cpu, referenceRowsDone(firstRow));
            cpuMilliseconds += millisecondsSince(start);
            const Rgb8Image reference8 = encodeImage(cpu.image, encoding);
            const Rgb8Image gpu8 = encodeImage(band.image, encoding);
            comparator.add({cpu.image, cpu.classes, reference8}, {band.image, band.classes, gpu8}, cpu.ambiguity);
            flip.add(reference8, gpu8);
            if (outputs) {
                outputs->writeRows(cpu, band, reference8, gpu8);
            }
            progress.update(firstRow + band.image.height);
        });
    return {comparator.result(),           flip.mean(),     gpu.precision,
            gpu.timing.renderMilliseconds, cpuMilliseconds, reference.threadCount()};
}

// Every path the comparison reads or writes, checked before any work.
void checkPaths(const CompareOptions& options, const std::vector<SceneFile>& files,
                const std::vector<std::string>& expectationFiles) {
    OutputPlan plan;
    for (const std::string& path : expectationFiles) {
        plan.addInput("the expectations file", path);
    }
    if (!options.jsonPath.empty()) {
        plan.addFile("--json", options.jsonPath);
    }
    if (!options.junitPath.empty()) {
        plan.addFile("--junit", options.junitPath);
    }
    for (const SceneFile& file : files) {
        if (file.problem.empty()) {
            plan.addInput("the scene", file.path);
        }
    }
    if (!options.diffPath.empty()) {
        plan.addFile("--diff", options.diffPath);
    }
    if (!options.maskPath.empty()) {
        plan.addFile("--mask", options.maskPath);
    }
    if (!options.aovDirectory.empty()) {
        plan.addDirectory("--aov", fs::path(options.aovDirectory) / "gpu", isAovFileName);
        plan.addDirectory("--aov", fs::path(options.aovDirectory) / "cpu", isAovFileName);
    }
    if (!options.reportDirectory.empty()) {
        ReportDirectory::addToPlan(plan, options.reportDirectory);
    }
    plan.check();
}

// A scene that cannot be loaded is a failed record (and a table's row), not the end of the command.
// `identity`: the scene file's (strip/strip_stamp.h), for the images' provenance.
std::optional<Scene> loadForComparison(const SceneFile& file, const ImageOverride& image, bool table,
                                       std::vector<ComparisonRecord>& records, std::string& identity) {
    try {
        requireReadable(file);
        return loadScene(file.path, image, &identity);
    } catch (const SceneError& error) {
        printError(error.what());
        if (table && !quiet()) {
            printFailedRow(file.name);
        }
        ComparisonRecord failed;
        failed.scenePath = file.path;
        failed.name = file.name;
        failed.loadError = printable(error.what());
        failed.outcome = {Outcome::Failed, "cannot load the scene: " + failed.loadError};
        records.push_back(std::move(failed));
        return std::nullopt;
    }
}

// --diff, --mask and --aov describe one comparison: not a table's.
void requireSingleComparison(const CompareOptions& options, bool table) {
    if (!options.diffPath.empty() && table) {
        throw SceneError("--diff: a heat map needs a single scene and a single precision");
    }
    if (!options.maskPath.empty() && table) {
        throw SceneError("--mask: a mismatch mask needs a single scene and a single precision");
    }
    if (!options.aovDirectory.empty() && table) {
        throw SceneError("--aov: AOVs need a single scene and a single precision");
    }
}

std::vector<Precision> precisionsToCompare(const CompareOptions& options, const VulkanContext& context) {
    if (!options.allPrecisions) {
        return {options.precision};
    }
    std::vector<Precision> precisions = {Precision::F32Naive, Precision::F32};
    if (context.selected().hasFloat64) {
        precisions.push_back(Precision::F64);
        precisions.push_back(Precision::F32Certified);
    }
    return precisions;
}

void printComparison(const ComparisonRecord& record, const BandedComparison& compared, const VulkanContext& context) {
    char gpuHow[256];
    std::snprintf(gpuHow, sizeof gpuHow, "gpu %s%s (%s): render %.2f ms",
                  std::string(precisionName(compared.precision)).c_str(),
                  record.requested == Precision::Auto ? ", chosen by auto" : "", context.selected().name.c_str(),
                  compared.gpuMilliseconds);
    char cpuHow[128];
    std::snprintf(cpuHow, sizeof cpuHow, "cpu reference (%u threads): render %.2f ms", compared.threads,
                  compared.cpuMilliseconds);
    printDetailed(record, gpuHow, cpuHow);
}

// The expectations files that apply: the one named on the command line, or each scene's nearest,
// all read (and checked) before any comparison.
class ExpectationsInUse {
public:
    ExpectationsInUse(const CompareOptions& options, const std::vector<SceneFile>& files)
        : disabled_(options.noExpectations) {
        if (disabled_) {
            return;
        }
        if (!options.expectationsPath.empty()) {
            named_ = readExpectations(options.expectationsPath);
            return;
        }
        for (const SceneFile& file : files) {
            const std::optional<std::string> found = findExpectations(file.path);
            if (found && !byPath_.contains(*found)) {
                byPath_.emplace(*found, readExpectations(*found));
            }
        }
    }

    const Expectations* forScene(const std::string& scenePath) const {
        if (disabled_) {
            return nullptr;
        }
        if (named_) {
            return &*named_;
        }
        const std::optional<std::string> found = findExpectations(scenePath);
        return found ? &byPath_.at(*found) : nullptr;
    }

    // The files read, for the report's header.
    std::vector<std::string> paths() const {
        std::vector<std::string> paths;
        if (named_) {
            paths.push_back(named_->path);
        }
        for (const auto& [path, expectations] : byPath_) {
            paths.push_back(path);
        }
        return paths;
    }

private:
    bool disabled_;
    std::optional<Expectations> named_;
    std::map<std::string, Expectations> byPath_;
};

ComparisonRecord recordFor(const SceneFile& file, const Scene& scene, Precision requested,
                           const BandedComparison& compared, Precision automatic, const CompareOptions& options,
                           const ExpectationsInUse& expectations) {
    ComparisonRecord record;
    record.scenePath = file.path;
    record.name = file.name;
    record.width = scene.image.width;
    record.height = scene.image.height;
    record.encoding = scene.image.encoding;
    record.requested = requested;
    record.precision = compared.precision;
    record.chosenByAuto = compared.precision == automatic;
    record.judged = !(options.allPrecisions && compared.precision == Precision::F32Naive);
    record.comparison = compared.comparison;
    record.flipMean = compared.flipMean;
    record.expectation = expectationFor(expectations.forScene(file.path), file.path, compared.precision,
                                        options.tolerance, options.toleranceGiven);
    record.verdict = judge(compared.comparison, record.expectation.tolerance);
    record.outcome = outcomeOf(record.verdict, record.judged, record.expectation);
    record.gpuMilliseconds = compared.gpuMilliseconds;
    record.cpuMilliseconds = compared.cpuMilliseconds;
    record.cpuThreads = compared.threads;
    return record;
}

// What a comparison command needs on its way through the scenes.
struct CompareSession {
    const CompareOptions& options;
    GpuRenderer& renderer;
    const VulkanContext& context;
    const ExpectationsInUse& expectations;
    bool table;
    std::vector<ComparisonRecord>& records;
    ReportDirectory* report;  // --report, or none
};

// Compares one scene in each precision asked for: a table row, or the detailed report (and its
// files), for each; with --report, its images too.
void compareScene(const CompareSession& session, const SceneFile& file, const Scene& scene,
                  const std::string& sceneIdentity) {
    const Precision automatic = session.renderer.resolve(scene, Precision::Auto);
    for (const Precision requested : precisionsToCompare(session.options, session.context)) {
        std::string reportStem;
        std::optional<std::array<fs::path, 4>> reportImages;
        if (session.report) {
            reportStem =
                reportImageStem(session.records.size() + 1, file.name, session.renderer.resolve(scene, requested));
            reportImages = session.report->stagedImages(reportStem);
        }
        std::optional<BandOutputs> outputs;
        if (!session.table || session.report) {
            outputs.emplace(session.options, !session.table, scene, reportImages,
                            gpuProvenance(scene, sceneIdentity, session.context.selected().name,
                                          session.renderer.resolve(scene, requested)));
        }
        const BandedComparison compared = compareInBands(session.renderer, file.path, scene, requested,
                                                         session.options.threads, outputs ? &*outputs : nullptr);
        session.records.push_back(
            recordFor(file, scene, requested, compared, automatic, session.options, session.expectations));
        if (session.table && !quiet()) {
            printTableRow(session.records.back());
        } else if (!quiet()) {
            printComparison(session.records.back(), compared, session.context);
        }
        if (outputs) {
            outputs->commit();
            session.records.back().reportImages = reportStem;
        }
    }
}

// `code`, or the failure's exit code when --junit's file cannot be written.
int writeJunitIfAsked(const CompareOptions& options, const std::vector<ComparisonRecord>& records,
                      const nlohmann::json& document, int code) {
    if (options.junitPath.empty()) {
        return code;
    }
    const std::string device = document["device"].is_null() ? "" : document["device"]["name"].get<std::string>();
    const int written = guarded([&] {
        writeJunit(options.junitPath, records, device);
        return int(kSuccess);
    });
    return written == kSuccess ? code : written;
}

// `code`, or the failure's exit code when --report's files cannot be written. Records `code` as
// the exit in `document`, which is the report's results.json.
int writeReportIfAsked(const CompareOptions& options, ReportDirectory* report,
                       const std::vector<ComparisonRecord>& records, nlohmann::json& document, int code) {
    if (!report) {
        return code;
    }
    recordExit(document, code);
    const int written = guarded([&] {
        std::vector<std::string> stems;
        for (const ComparisonRecord& record : records) {
            if (!record.reportImages.empty()) {
                stems.push_back(record.reportImages);
            }
        }
        report->commit(reportPage(records, document), document, stems);
        if (!quiet()) {
            std::printf("wrote report %s\n",
                        printable((fs::path(options.reportDirectory) / kReportPage).string()).c_str());
        }
        return int(kSuccess);
    });
    return written == kSuccess ? code : written;
}

// Bands of floats, not the encoded render's larger ones: memory grows with the width only. On a
// terminal, smaller ones, so that the progress line moves.
std::uint64_t comparisonBandBytes() {
    return Progress::shown() ? kBandBytes / 8 : kBandBytes;
}

}  // namespace

int runCompare(const CompareOptions& options) {
    ValidationLog log;
    std::vector<ComparisonRecord> records;
    std::optional<ReportDirectory> report;
    nlohmann::json document = jsonDocument("compare");
    document["device"] = nullptr;
    document["timings_ms"]["startup"] = nullptr;
    document["expectations_files"] = nlohmann::json::array();
    const int code = guarded([&] {
        const std::vector<SceneFile> files = sceneFiles(options.scenePaths);
        const bool table = options.allPrecisions || files.size() > 1;
        requireSingleComparison(options, table);
        const ExpectationsInUse expectations(options, files);
        checkPaths(options, files, expectations.paths());
        document["expectations_files"] = expectations.paths();
        if (!options.reportDirectory.empty()) {
            report.emplace(options.reportDirectory);
            document["report"] = options.reportDirectory;
        }
        const auto startup = std::chrono::steady_clock::now();
        const VulkanContext context({options.vulkan.validate ? &log : nullptr, options.vulkan.device});
        document["timings_ms"]["startup"] = millisecondsSince(startup);
        document["device"] = jsonDevice(context.selected());
        GpuRenderer renderer(context, comparisonBandBytes());
        if (table && !quiet()) {
            printTableHeader();
        }
        const CompareSession session{
            options, renderer, context, expectations, table, records, report ? &*report : nullptr};
        bool allLoaded = true;
        for (const SceneFile& file : files) {
            std::string sceneIdentity;
            const std::optional<Scene> scene = loadForComparison(file, options.image, table, records, sceneIdentity);
            allLoaded = allLoaded && scene.has_value();
            if (scene) {
                compareScene(session, file, *scene, sceneIdentity);
            }
        }
        const OutcomeCounts counts = countOutcomes(records);
        if (!quiet()) {
            printCountLine(counts);
        }
        return !allLoaded ? int(kBadInput) : counts.gatePassed() ? int(kSuccess) : int(kToleranceExceeded);
    });
    const int verdict = withValidationVerdict(code, log);
    addComparisons(document, records);
    const int written = writeJunitIfAsked(options, records, document, verdict);
    return finishJson(options.jsonPath, document,
                      writeReportIfAsked(options, report ? &*report : nullptr, records, document, written));
}

}  // namespace hexray::cli
