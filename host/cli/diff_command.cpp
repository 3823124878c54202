// `hexray diff TEST REF`: two image files compared, in the manner of OpenImageIO's idiff: RMSE,
// PSNR, the largest difference, the share of pixels over one 8-bit level, and FLIP (docs/diff.md).

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "cli/command_support.h"
#include "cli/quiet.h"
#include "cli/commands.h"
#include "cli/json_document.h"
#include "compare/flip.h"
#include "compare/image_difference.h"
#include "image/image_file_reader.h"
#include "image/provenance.h"
#include "io/output_plan.h"
#include "io/standard_input.h"
#include "io/standard_output.h"
#include "util/formatted.h"
#include "util/printable.h"

namespace hexray::cli {

namespace {

struct DiffResult {
    ImageDifference difference;
    FlipMap flip;
    bool hdr = false;  // HDR-FLIP (OpenEXR) rather than LDR-FLIP (PNG)
    FlipExposures exposures;
    double pixelsPerDegree = 0;
    std::uint64_t failing = 0;
    std::uint64_t warning = 0;
    bool failed = false;
    bool warned = false;
};

std::string inputName(const std::string& path) {
    return path == "-" ? "standard input" : printable(path);
}

ImageFile readInput(const std::string& path) {
    const ReadOnlyFile file = path == "-" ? standardInputAsFile() : ReadOnlyFile(path);
    return readImageFile(file);
}

const char* formatName(ImageFormat format) {
    return format == ImageFormat::Png ? "png" : "exr";
}

// The file's record of what made it (image/provenance.h); none for standard input, which is read
// once, or for a file whose record cannot be read (said on standard error).
std::optional<Provenance> recordOf(const std::string& path) {
    if (path == "-") {
        return std::nullopt;
    }
    try {
        return readProvenance(path);
    } catch (const ImageIoError& error) {
        std::fprintf(stderr, "hexray: note: %s\n", printable(error.what()).c_str());
        return std::nullopt;
    }
}

nlohmann::json jsonProvenance(const std::optional<Provenance>& record) {
    if (!record) {
        return nullptr;
    }
    nlohmann::json json = nlohmann::json::object();
    for (const ImageNote& note : record->notes()) {
        json[note.key] = note.text;
    }
    return json;
}

// Both files' records, when they differ in anything: which build, scene, backend or precision
// made each is often the whole explanation of a difference.
void printRecordsIfTheyDiffer(const DiffOptions& options, const std::optional<Provenance>& test,
                              const std::optional<Provenance>& reference) {
    if (!test || !reference || *test == *reference) {
        return;
    }
    std::printf("the files' records of what made them differ:\n");
    for (const auto& [path, record] : {std::pair{&options.testPath, &*test}, {&options.referencePath, &*reference}}) {
        std::printf("  %s:\n", inputName(*path).c_str());
        const std::string described = record->empty() ? "(none)\n" : record->describe();
        std::size_t start = 0;
        while (start < described.size()) {
            const std::size_t end = described.find('\n', start);
            std::printf("    %s\n", described.substr(start, end - start).c_str());
            start = end == std::string::npos ? described.size() : end + 1;
        }
    }
}

nlohmann::json jsonImage(const std::string& path, const std::optional<ImageFile>& image,
                         const std::optional<Provenance>& record) {
    nlohmann::json json = {{"path", path}, {"format", nullptr}, {"width", nullptr}, {"height", nullptr}};
    if (image) {
        json["format"] = formatName(image->format);
        json["width"] = image->width();
        json["height"] = image->height();
    }
    json["provenance"] = jsonProvenance(record);
    return json;
}

double share(std::uint64_t count, std::uint64_t pixels) {
    return pixels == 0 ? 0.0 : double(count) / double(pixels);
}

DiffResult diffImages(const ImageFile& test, const ImageFile& reference, const DiffOptions& options) {
    DiffResult result;
    result.pixelsPerDegree = options.pixelsPerDegree > 0 ? options.pixelsPerDegree : kDefaultPixelsPerDegree;
    if (test.format == ImageFormat::Png) {
        result.difference = differenceOf(reference.encoded, test.encoded);
        result.flip = ldrFlip(reference.encoded, test.encoded, result.pixelsPerDegree);
    } else {
        result.hdr = true;
        result.difference = differenceOf(reference.linear, test.linear);
        result.exposures = hdrFlipExposures(reference.linear);
        result.flip = hdrFlip(reference.linear, test.linear, result.pixelsPerDegree, result.exposures);
    }
    const std::uint64_t pixels = result.difference.pixelDifferences.size();
    result.failing = pixelsAbove(result.difference.pixelDifferences, options.failDifference);
    result.warning = pixelsAbove(result.difference.pixelDifferences, options.warnDifference);
    const bool flipFails = options.failFlip && result.flip.mean() > *options.failFlip;
    result.failed = 100.0 * share(result.failing, pixels) > options.failPercent || flipFails;
    result.warned = 100.0 * share(result.warning, pixels) > options.warnPercent;
    return result;
}

void printRow(const std::string& label, const std::string& value) {
    std::printf("  %-18s %s\n", label.c_str(), value.c_str());
}

void printReport(const DiffResult& result, const ImageFile& test, const DiffOptions& options) {
    const ErrorMetrics& metrics = result.difference.metrics;
    const std::uint64_t pixels = result.difference.pixelDifferences.size();
    const bool png = test.format == ImageFormat::Png;
    const auto count = [](std::uint64_t value) { return static_cast<unsigned long long>(value); };
    std::printf("%s against %s: %ux%u, %s\n", inputName(options.testPath).c_str(),
                inputName(options.referencePath).c_str(), test.width(), test.height(),
                png ? "PNG (8-bit sRGB)" : "OpenEXR (linear float)");
    printRow("RMSE", formatted("%.6g", metrics.rmse) + (png ? formatted(" (%.4g levels)", metrics.rmse * 255.0) : ""));
    printRow("PSNR", std::isfinite(metrics.psnr) ? formatted("%.2f dB", metrics.psnr) : "infinite (identical)");
    printRow("max difference",
             formatted("%.6g at (%u, %u)", metrics.maxAbs, result.difference.maxX, result.difference.maxY));
    printRow("over one level", formatted("%.4g%% of pixels (%llu)", 100.0 * metrics.shareOverOneLevel,
                                         count(metrics.pixelsOverOneLevel)));
    if (result.difference.nonFinitePixels > 0) {
        printRow("not finite",
                 formatted("%llu pixels (NaN or infinite in either image)", count(result.difference.nonFinitePixels)));
    }
    std::string flip = formatted("mean %.6f, max %.6f at %.2f pixels per degree", result.flip.mean(), result.flip.max(),
                                 result.pixelsPerDegree);
    if (result.hdr) {
        flip += formatted(", %d exposures from %.3f to %.3f stops", result.exposures.count, result.exposures.start,
                          result.exposures.stop);
    }
    printRow(result.hdr ? "HDR-FLIP" : "LDR-FLIP", flip);
    printRow(formatted("over --fail %g", options.failDifference),
             formatted("%.4g%% of pixels (%llu), --failpercent %g", 100.0 * share(result.failing, pixels),
                       count(result.failing), options.failPercent));
    if (result.failed) {
        const bool flipFailed = options.failFlip && result.flip.mean() > *options.failFlip;
        std::printf("FAIL%s\n",
                    flipFailed ? formatted(": mean FLIP above --fail-flip %g", *options.failFlip).c_str() : "");
    } else if (result.warned) {
        std::printf("PASS with a warning: %.4g%% of pixels (%llu) differ by more than --warn %g\n",
                    100.0 * share(result.warning, pixels), count(result.warning), options.warnDifference);
    } else {
        std::printf("PASS\n");
    }
}

nlohmann::json jsonMetrics(const DiffResult& result) {
    const ErrorMetrics& metrics = result.difference.metrics;
    nlohmann::json flip = {{"kind", result.hdr ? "hdr" : "ldr"},
                           {"mean", jsonNumber(result.flip.mean())},
                           {"max", jsonNumber(result.flip.max())},
                           {"pixels_per_degree", result.pixelsPerDegree},
                           {"exposures", nullptr}};
    if (result.hdr) {
        flip["exposures"] = {{"start", jsonNumber(result.exposures.start)},
                             {"stop", jsonNumber(result.exposures.stop)},
                             {"count", result.exposures.count}};
    }
    return {{"pixels", result.difference.pixelDifferences.size()},
            {"rmse", jsonNumber(metrics.rmse)},
            {"psnr", jsonNumber(metrics.psnr)},
            {"max_abs", jsonNumber(metrics.maxAbs)},
            {"max_at", {{"x", result.difference.maxX}, {"y", result.difference.maxY}}},
            {"mean_abs", jsonNumber(metrics.meanAbs)},
            {"pixels_over_one_level", metrics.pixelsOverOneLevel},
            {"share_over_one_level", jsonNumber(metrics.shareOverOneLevel)},
            {"nonfinite_pixels", result.difference.nonFinitePixels},
            {"flip", flip}};
}

void recordResult(nlohmann::json& document, const DiffResult& result) {
    const std::uint64_t pixels = result.difference.pixelDifferences.size();
    document["metrics"] = jsonMetrics(result);
    document["failing"] = {{"pixels", result.failing}, {"share", share(result.failing, pixels)}};
    document["warning"] = {{"pixels", result.warning}, {"share", share(result.warning, pixels)}};
    document["verdict"] = result.failed ? "fail" : result.warned ? "warn" : "pass";
}

// Reads both inputs; an unreadable one is bad input, named.
std::optional<int> readInputs(const DiffOptions& options, std::optional<ImageFile>& test,
                              std::optional<ImageFile>& reference) {
    try {
        test = readInput(options.testPath);
        reference = readInput(options.referencePath);
    } catch (const InputError& error) {
        printError(error.what());
        return kBadInput;
    } catch (const ImageIoError& error) {
        printError(error.what());
        return kBadInput;
    }
    return std::nullopt;
}

int diffCommand(const DiffOptions& options, nlohmann::json& document) {
    OutputPlan plan;
    for (const std::string* input : {&options.testPath, &options.referencePath}) {
        if (*input != "-") {
            plan.addInput("the image", *input);
        }
    }
    if (!options.heatmapPath.empty()) {
        plan.addFile("--heatmap", options.heatmapPath);
    }
    if (!options.jsonPath.empty()) {
        plan.addFile("--json", options.jsonPath);
    }
    plan.check();
    std::optional<ImageFile> test;
    std::optional<ImageFile> reference;
    const std::optional<int> unreadable = readInputs(options, test, reference);
    const std::optional<Provenance> testRecord = test ? recordOf(options.testPath) : std::nullopt;
    const std::optional<Provenance> referenceRecord = reference ? recordOf(options.referencePath) : std::nullopt;
    document["test"] = jsonImage(options.testPath, test, testRecord);
    document["reference"] = jsonImage(options.referencePath, reference, referenceRecord);
    if (unreadable) {
        return *unreadable;
    }
    if (test->format != reference->format) {
        printError(inputName(options.testPath) + " is " + (test->format == ImageFormat::Png ? "a PNG" : "OpenEXR") +
                   " and " + inputName(options.referencePath) + " is not: diff compares two PNGs or two OpenEXR files");
        return kBadInput;
    }
    if (test->width() != reference->width() || test->height() != reference->height()) {
        printError(inputName(options.testPath) + " is " + std::to_string(test->width()) + "x" +
                   std::to_string(test->height()) + " pixels, " + inputName(options.referencePath) + " " +
                   std::to_string(reference->width()) + "x" + std::to_string(reference->height()));
        return kSizeMismatch;
    }
    const DiffResult result = diffImages(*test, *reference, options);
    recordResult(document, result);
    if (!options.heatmapPath.empty()) {
        writePng(options.heatmapPath, flipHeatMap(result.flip));
        document["heatmap"] = options.heatmapPath;
    }
    if (!quiet()) {
        printReport(result, *test, options);
        printRecordsIfTheyDiffer(options, testRecord, referenceRecord);
    }
    return result.failed ? kToleranceExceeded : kSuccess;
}

}  // namespace

int runDiff(const DiffOptions& options) {
    nlohmann::json document = jsonDocument("diff");
    document["device"] = nullptr;
    document["timings_ms"]["startup"] = nullptr;
    document["test"] = nullptr;
    document["reference"] = nullptr;
    document["thresholds"] = {{"fail", options.failDifference},
                              {"fail_share", options.failPercent / 100.0},
                              {"warn", options.warnDifference},
                              {"warn_share", options.warnPercent / 100.0},
                              {"fail_flip", options.failFlip ? nlohmann::json(*options.failFlip) : nullptr}};
    document["metrics"] = nullptr;
    document["failing"] = nullptr;
    document["warning"] = nullptr;
    document["verdict"] = nullptr;
    document["heatmap"] = nullptr;
    const int code = guarded([&] { return diffCommand(options, document); });
    return finishJson(options.jsonPath, document, code);
}

}  // namespace hexray::cli
