#pragma once
// The files a comparison writes besides its report, each opened before the renders and written a
// band at a time, so that memory grows with the width only: a single comparison's --diff heat
// map, --mask and --aov sets, and, for every comparison, --report's four images (the GPU render,
// the CPU reference, the heat map and the mask).

#include <array>
#include <filesystem>
#include <optional>

#include "cli/commands.h"
#include "cpu/cpu_renderer.h"
#include "gpu/gpu_renderer.h"
#include "image/aov.h"
#include "image/image_io.h"
#include "image/provenance.h"
#include "scene/scene.h"

namespace hexray::cli {

class BandOutputs {
public:
    // `single`: the options' --diff, --mask and --aov apply (one scene, one precision).
    // `reportImages`: where to write the report's images, in report_layout.h's order, or none.
    // `gpu`: the GPU render's record (image/provenance.h); each file records what it shows.
    BandOutputs(const CompareOptions& options, bool single, const Scene& scene,
                const std::optional<std::array<std::filesystem::path, 4>>& reportImages, const Provenance& gpu);

    bool withAovs() const { return gpuAovs_.has_value(); }

    void writeRows(const CpuRender& reference, const GpuRenderResult& gpu, const Rgb8Image& reference8,
                   const Rgb8Image& gpu8);

    // Finishes every file and puts the single comparison's in place, saying so (the report's wait
    // for the report's commit).
    void commit();

private:
    const CompareOptions& options_;
    std::optional<PngRowWriter> diff_;
    std::optional<PngRowWriter> mask_;
    std::optional<StagedAovs> gpuAovs_;
    std::optional<StagedAovs> cpuAovs_;
    std::array<std::optional<PngRowWriter>, 4> report_;
};

}  // namespace hexray::cli
