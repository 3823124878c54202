#include "cli/band_outputs.h"

#include <cstdio>

#include "cli/report_layout.h"
#include "compare/compare.h"
#include "cpu/cpu_margins.h"
#include "io/standard_output.h"
#include "util/printable.h"

namespace hexray::cli {
namespace {

namespace fs = std::filesystem;

std::optional<PngRowWriter>& reportImage(std::array<std::optional<PngRowWriter>, 4>& images, ReportImage image) {
    return images[static_cast<std::size_t>(image)];
}

// A comparison's file's record: the GPU render's, saying what the file shows and which backend made
// it ("gpu vs cpu" for the heat map and mask).
Provenance withImage(Provenance provenance, const std::string& image, const std::string& backend) {
    provenance.image = image;
    provenance.backend = backend;
    if (backend == "cpu") {
        provenance.device = "cpu reference";
        provenance.precision = std::string(precisionName(Precision::F64));
    }
    return provenance;
}

}  // namespace

BandOutputs::BandOutputs(const CompareOptions& options, bool single, const Scene& scene,
                         const std::optional<std::array<fs::path, 4>>& reportImages, const Provenance& gpu)
    : options_(options) {
    const std::uint32_t width = scene.image.width;
    const std::uint32_t height = scene.image.height;
    if (single && !options.diffPath.empty()) {
        diff_.emplace(options.diffPath, width, height, withImage(gpu, "diff heat map", "gpu vs cpu").notes());
    }
    if (single && !options.maskPath.empty()) {
        mask_.emplace(options.maskPath, width, height, withImage(gpu, "mismatch mask", "gpu vs cpu").notes());
    }
    if (single && !options.aovDirectory.empty()) {
        const fs::path directory(options.aovDirectory);
        gpuAovs_.emplace(directory / "gpu", AovLayout{width, height, scene.lights.size()}, gpu);
        cpuAovs_.emplace(directory / "cpu", AovLayout{width, height, scene.lights.size(), true, kAmbiguityMargin},
                         withImage(gpu, "", "cpu"));
    }
    if (reportImages) {
        const std::array<Provenance, 4> records = {withImage(gpu, "render", "gpu"), withImage(gpu, "render", "cpu"),
                                                   withImage(gpu, "diff heat map", "gpu vs cpu"),
                                                   withImage(gpu, "mismatch mask", "gpu vs cpu")};
        for (std::size_t i = 0; i < report_.size(); ++i) {
            report_[i].emplace((*reportImages)[i], width, height, records[i].notes());
        }
    }
}

void BandOutputs::writeRows(const CpuRender& reference, const GpuRenderResult& gpu, const Rgb8Image& reference8,
                            const Rgb8Image& gpu8) {
    const bool withReport = report_[0].has_value();
    if (diff_ || withReport) {
        const Rgb8Image heatMap = diffHeatMap(reference8, gpu8);
        if (diff_) {
            diff_->writeRows(heatMap.bytes);
        }
        if (withReport) {
            reportImage(report_, ReportImage::Diff)->writeRows(heatMap.bytes);
        }
    }
    if (mask_ || withReport) {
        const Rgb8Image mask = mismatchMask(reference.classes, gpu.classes, reference.ambiguity, reference8, gpu8,
                                            &reference.image, &gpu.image);
        if (mask_) {
            mask_->writeRows(mask.bytes);
        }
        if (withReport) {
            reportImage(report_, ReportImage::Mask)->writeRows(mask.bytes);
        }
    }
    if (withReport) {
        reportImage(report_, ReportImage::Gpu)->writeRows(gpu8.bytes);
        reportImage(report_, ReportImage::Reference)->writeRows(reference8.bytes);
    }
    if (gpuAovs_) {
        gpuAovs_->writeRows({gpu.image.height, gpu.depth, gpu.normals, gpu.classes, {}});
        cpuAovs_->writeRows(
            {reference.image.height, reference.depth, reference.normals, reference.classes, reference.margins});
    }
}

void BandOutputs::commit() {
    for (std::optional<PngRowWriter>& image : report_) {
        if (image) {
            image->finish();
        }
    }
    if (diff_) {
        diff_->finish();
        std::printf("wrote diff heat map %s\n", displayName(options_.diffPath).c_str());
    }
    if (mask_) {
        mask_->finish();
        std::printf(
            "wrote mismatch mask %s (magenta invalid colour, red topology, blue excused, yellow "
            "colour > 1 level, navy near-tied but agreeing)\n",
            displayName(options_.maskPath).c_str());
    }
    if (gpuAovs_) {
        gpuAovs_->commit();
        cpuAovs_->commit();
        const fs::path directory(options_.aovDirectory);
        std::printf("wrote AOVs in %s and %s\n", printable((directory / "gpu").string()).c_str(),
                    printable((directory / "cpu").string()).c_str());
    }
}

}  // namespace hexray::cli
