#include "bench/bench_report.h"

#include <algorithm>
#include <cstdio>

#include "compare/band_flip.h"

namespace hexray::inline bench {
namespace {

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

bool isEmbree(BenchBackend backend) {
    return backend == BenchBackend::Embree || backend == BenchBackend::EmbreeF64Packets ||
           backend == BenchBackend::EmbreeF64Single;
}

// What was asked and what ran: the plan's precision and kernel for the GPU, each other backend's
// own arithmetic.
void describeConfiguration(const BenchConfiguration& configuration, const BenchMeasurement& measurement,
                           BenchRow& row) {
    row.kernel = measurement.kernel;
    switch (configuration.backend) {
        case BenchBackend::Gpu:
            row.precisionAsked = configuration.precision;
            row.precision = measurement.precision;
            row.cullingAsked = configuration.culling == Culling::On;
            row.cullingUsed = measurement.culled;
            if (measurement.precision == Precision::F32Certified && measurement.fallback.totalVectors > 0) {
                const CertifiedFallback& fallback = measurement.fallback;
                row.fallbackPixelShare = double(fallback.pixels) / double(fallback.totalPixels);
                row.fallbackVectorShare = double(fallback.vectors) / double(fallback.totalVectors);
            }
            return;
        case BenchBackend::GpuHandWritten:
            row.precision = Precision::F32Naive;
            row.cullingUsed = measurement.culled;
            return;
        case BenchBackend::Cpu:
            row.precision = Precision::F64;
            return;
        case BenchBackend::Embree:
            row.precision = Precision::F32;
            return;
        case BenchBackend::EmbreeF64Packets:
        case BenchBackend::EmbreeF64Single:
            row.precision = Precision::F32;  // the arithmetic that decides the hits
            return;
    }
}

// The row's errors against the references, from its last render: once per row, after the rounds,
// as FLIP (single-threaded, whole images) costs far more than the other metrics.
void addErrors(const BenchScene& bench, const BenchConfiguration& configuration, const BenchMeasurement& measurement,
               BenchRow& row) {
    const Encoding encoding = bench.scene.image.encoding;
    const Rgb8Image encoded =
        isGpu(configuration.backend) ? measurement.encoded : encodeImage(measurement.image, encoding);
    const CpuRender& reference = bench.reference.bySamples.at(configuration.samplesPerPixel);
    const Rgb8Image reference8 = encodeImage(reference.image, encoding);
    // Precision error where the reference's decisions are clear of rounding (compare's rule).
    const PixelMask ambiguous = marginsBelow(reference.margins, kAmbiguityMargin);
    PixelMask unambiguous(ambiguous.size());
    std::transform(ambiguous.begin(), ambiguous.end(), unambiguous.begin(), [](bool a) { return !a; });
    row.precisionError = compareEncoded(reference8, encoded, unambiguous);
    if (encoded.bytes == reference8.bytes) {
        row.flipMean = 0.0;  // as FLIP computes it, without its cost
    } else {
        BandFlip flip(encoded.width, encoded.height, encoding);
        flip.add(reference8, encoded);
        row.flipMean = flip.mean();
    }
    if (!bench.reference.converged.bytes.empty()) {
        row.samplingError = compareEncoded(bench.reference.converged, encoded);
    }
    if (!measurement.classes.empty()) {
        row.topology = compareTopology(reference.classes, measurement.classes, ambiguous);
    }
}

BenchRow rowFor(const BenchScene& bench, const BenchConfiguration& configuration, const BenchMeasurement& measurement,
                BenchBackends& backends) {
    BenchRow row;
    row.configuration = configuration;
    const double pixels = double(bench.scene.image.width) * bench.scene.image.height;
    row.medianMs = median(measurement.renderMilliseconds);
    const double bestMs =
        *std::min_element(measurement.renderMilliseconds.begin(), measurement.renderMilliseconds.end());
    row.medianMpix = pixels * 1e-3 / row.medianMs;
    row.bestMpix = pixels * 1e-3 / bestMs;
    row.frameMs = median(measurement.frameMilliseconds);
    if (isGpu(configuration.backend)) {
        row.planMs = median(measurement.planMilliseconds);
        row.uploadMs = median(measurement.uploadMilliseconds);
    }
    row.threads = backends.threads(configuration.backend);
    row.coreNsPerPixel = row.medianMs * 1e6 * std::max(1u, row.threads) / pixels;
    describeConfiguration(configuration, measurement, row);

    addErrors(bench, configuration, measurement, row);
    Scene sampled = bench.scene;
    sampled.image.samplesPerPixel = configuration.samplesPerPixel;
    row.work = backends.work(sampled, configuration);
    return row;
}

// The ratio of each row's speed to a yardstick row's at the same scene and sample count.
void addRatios(std::vector<BenchRow>& rows) {
    std::map<std::pair<std::size_t, std::uint32_t>, double> handWritten;
    std::map<std::pair<std::size_t, std::uint32_t>, double> embree;  // the faster mode
    for (const BenchRow& row : rows) {
        const auto key = std::pair(row.configuration.scene, row.configuration.samplesPerPixel);
        if (row.configuration.backend == BenchBackend::GpuHandWritten) {
            handWritten[key] = row.medianMpix;
        } else if (isEmbree(row.configuration.backend)) {
            embree[key] = std::max(embree[key], row.medianMpix);
        }
    }
    for (BenchRow& row : rows) {
        const auto key = std::pair(row.configuration.scene, row.configuration.samplesPerPixel);
        if (const auto found = handWritten.find(key); found != handWritten.end()) {
            row.versusHandWritten = row.medianMpix / found->second;
        }
        if (const auto found = embree.find(key); found != embree.end()) {
            row.versusEmbree = row.medianMpix / found->second;
        }
    }
}

std::string format(const char* pattern, double value) {
    char text[32];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

// Mpix/s to three significant digits: a slow backend's figure (the CPU reference on a big scene)
// still reads as more than 0.0.
std::string mpix(double value) {
    return format(value >= 100 ? "%.0f" : "%.3g", value);
}

std::string optional(const std::optional<double>& value, const char* pattern) {
    return value ? format(pattern, *value) : "–";
}

// A share as a percentage, "–" for none.
std::string percent(const std::optional<double>& share) {
    return share ? format("%.3f%%", 100.0 * *share) : "–";
}

std::string precisionText(const BenchRow& row) {
    switch (row.configuration.backend) {
        case BenchBackend::Gpu:
            return std::string(precisionName(row.precision)) + (row.chosenByAuto ? " (auto)" : "");
        case BenchBackend::GpuHandWritten:
            return "f32 textbook";
        case BenchBackend::Cpu:
            return "f64 (double)";
        case BenchBackend::Embree:
            return "f32 (Embree)";
        case BenchBackend::EmbreeF64Packets:
        case BenchBackend::EmbreeF64Single:
            return "f32 hits, f64 shading";
    }
    return "";
}

// As asked; "on (not run)" where the plan could not cull (the data-driven kernel, or no tile class
// less than the whole scene).
std::string cullingText(const BenchRow& row) {
    if (!row.cullingAsked) {
        return "–";
    }
    if (*row.cullingAsked && !row.cullingUsed.value_or(false)) {
        return "on (not run)";
    }
    return *row.cullingAsked ? "on" : "off";
}

// The GPU kernel that ran; "–" for the other backends.
const char* kernelText(const BenchRow& row) {
    return row.kernel == BenchKernel::None ? "–" : benchKernelName(row.kernel);
}

std::string mismatches(const BenchRow& row) {
    return row.topology ? std::to_string(row.topology->mismatches) : "–";
}

// The rows of the file scenes or of the curve, grouped by scene and sample count.
std::vector<const BenchRow*> rowsOf(const std::vector<BenchScene>& scenes, const std::vector<BenchRow>& rows,
                                    bool curve) {
    std::vector<const BenchRow*> selected;
    for (const BenchRow& row : rows) {
        if (scenes[row.configuration.scene].spheres.has_value() == curve) {
            selected.push_back(&row);
        }
    }
    std::stable_sort(selected.begin(), selected.end(), [](const BenchRow* a, const BenchRow* b) {
        return std::pair(a->configuration.scene, a->configuration.samplesPerPixel) <
               std::pair(b->configuration.scene, b->configuration.samplesPerPixel);
    });
    return selected;
}

void printFileTable(const std::vector<BenchScene>& scenes, const std::vector<BenchRow>& rows,
                    const BenchBackends& backends) {
    std::printf(
        "| scene | resolution | backend | kernel | precision | culling | spp | Mpix/s median | Mpix/s best | frame ms "
        "| vs hand-written | primary tests/px | shadow rays/px | shadow tests/px | sampling error: RMSE vs "
        "converged (levels) | precision error: RMSE vs CPU ref, same spp, unambiguous px (levels) | "
        "mean FLIP vs CPU ref, same spp | > 1 level, same spp | topology mismatches | f64 pass: pixels | f64 pass: "
        "8-lane vectors |\n");
    std::printf(
        "|---|---|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const BenchRow* row : rowsOf(scenes, rows, false)) {
        const BenchScene& bench = scenes[row->configuration.scene];
        const auto work = [&](double WorkPerPixel::*field) {
            return row->work ? format("%.2f", (*row->work).*field) : "–";
        };
        std::printf(
            "| %s | %ux%u | %s | %s | %s | %s | %u | %s | %s | %.1f | %s | %s | %s | %s | %s | %.3f | %s | %.3f%% "
            "| %s | %s | %s |\n",
            bench.name.c_str(), bench.scene.image.width, bench.scene.image.height,
            backends.name(row->configuration.backend).c_str(), kernelText(*row), precisionText(*row).c_str(),
            cullingText(*row).c_str(), row->configuration.samplesPerPixel, mpix(row->medianMpix).c_str(),
            mpix(row->bestMpix).c_str(), row->frameMs, optional(row->versusHandWritten, "%.2f").c_str(),
            work(&WorkPerPixel::primaryTests).c_str(), work(&WorkPerPixel::shadowRays).c_str(),
            work(&WorkPerPixel::shadowTests).c_str(),
            optional(row->samplingError ? std::optional(row->samplingError->rmse) : std::nullopt, "%.3f").c_str(),
            row->precisionError.rmse, optional(row->flipMean, "%.5f").c_str(),
            100.0 * row->precisionError.shareOverOneLevel, mismatches(*row).c_str(),
            percent(row->fallbackPixelShare).c_str(), percent(row->fallbackVectorShare).c_str());
    }
}

void printCurveTable(const std::vector<BenchScene>& scenes, const std::vector<BenchRow>& rows,
                     const BenchBackends& backends) {
    std::printf(
        "| spheres | resolution | backend | kernel | precision | culling | spp | Mpix/s median | Mpix/s best | frame "
        "ms | host plan "
        "ms | upload ms | threads | core-ns per pixel | vs Embree (fastest row) | RMSE vs CPU ref, same spp, "
        "unambiguous px (levels) | mean FLIP vs CPU ref | > 1 level | topology mismatches |\n");
    std::printf("|---:|---|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const BenchRow* row : rowsOf(scenes, rows, true)) {
        const BenchScene& bench = scenes[row->configuration.scene];
        std::printf(
            "| %u | %ux%u | %s | %s | %s | %s | %u | %s | %s | %.1f | %s | %s | %u | %.0f | %s | %.3f | %s | %.3f%% | "
            "%s "
            "|\n",
            *bench.spheres, bench.scene.image.width, bench.scene.image.height,
            backends.name(row->configuration.backend).c_str(), kernelText(*row), precisionText(*row).c_str(),
            cullingText(*row).c_str(), row->configuration.samplesPerPixel, mpix(row->medianMpix).c_str(),
            mpix(row->bestMpix).c_str(), row->frameMs, optional(row->planMs, "%.1f").c_str(),
            optional(row->uploadMs, "%.1f").c_str(), row->threads, row->coreNsPerPixel,
            optional(row->versusEmbree, "%.2f").c_str(), row->precisionError.rmse,
            optional(row->flipMean, "%.5f").c_str(), 100.0 * row->precisionError.shareOverOneLevel,
            mismatches(*row).c_str());
    }
}

}  // namespace

bool isGpu(BenchBackend backend) {
    return backend == BenchBackend::Gpu || backend == BenchBackend::GpuHandWritten;
}

std::vector<BenchRow> benchRows(const std::vector<BenchScene>& scenes,
                                const std::vector<BenchConfiguration>& configurations,
                                const std::vector<BenchMeasurement>& measurements, BenchBackends& backends) {
    std::vector<BenchRow> rows;
    for (std::size_t i = 0; i < configurations.size(); ++i) {
        const BenchScene& bench = scenes[configurations[i].scene];
        BenchRow row = rowFor(bench, configurations[i], measurements[i], backends);
        row.chosenByAuto =
            configurations[i].backend == BenchBackend::Gpu && row.precision == backends.autoPrecision(bench.scene);
        rows.push_back(row);
    }
    addRatios(rows);
    return rows;
}

void printBenchTables(const std::vector<BenchScene>& scenes, const std::vector<BenchRow>& rows,
                      const BenchBackends& backends, const std::vector<std::string>& notes) {
    const bool files = std::any_of(scenes.begin(), scenes.end(), [](const BenchScene& s) { return !s.spheres; });
    const bool curve = std::any_of(scenes.begin(), scenes.end(), [](const BenchScene& s) { return s.spheres; });
    if (files) {
        printFileTable(scenes, rows, backends);
    }
    if (curve) {
        std::printf(files ? "\n" : "");
        printCurveTable(scenes, rows, backends);
    }
    std::printf("\n");
    for (const std::string& note : notes) {
        std::printf("%s\n", note.c_str());
    }
}

}  // namespace hexray::bench
