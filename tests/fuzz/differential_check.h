#pragma once
// The differential fuzzer's judgement of one scene: rendered small on the GPU in every precision
// and on the CPU reference, at a few sample counts, and held to what `hexray compare` holds a
// render to; plus the loader's side (a scene file outside the supported range is rejected, one
// float32 cannot hold is rendered in f64 with a warning).

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "compare/compare.h"
#include "gpu/gpu_renderer.h"
#include "scene/scene.h"

namespace hexray::test {

// One thing a check found wrong.
struct Finding {
    Finding(std::string kind, std::string where, std::string detail)
        : kind(std::move(kind)), where(std::move(where)), detail(std::move(detail)) {}

    // What kind of wrong, for telling one failure from another while shrinking: "invalid colour",
    // "topology", "colour", "ambiguous", "precision warning", "load".
    std::string kind;
    std::string where;   // e.g. "f32, 4 spp, generated kernel"
    std::string detail;  // the figures
    // The render it was found in (none for "load"): what a shrinker needs to render again.
    std::optional<Precision> precision;
    std::uint32_t samplesPerPixel = 0;
    bool generatedKernel = false;
};

std::string describe(const Finding& finding);

struct DifferentialOptions {
    // One row of pixels is 3 % of the image, under compare's 5 % ambiguity limit: at 16 x 12 (8 %)
    // a single edge running along a row of pixel centres failed it.
    std::uint32_t width = 32;
    std::uint32_t height = 24;
    std::vector<std::uint32_t> samplesPerPixel = {1, 4};
    std::vector<Precision> precisions = {Precision::F32Naive, Precision::F32,
                                         Precision::F64};  // f64 if the device has it
    Tolerance tolerance;                                   // compare's defaults
    // Every render is made by the data-driven kernels (prebuilt: one pipeline per precision and
    // sample count for a whole run), with candidate lists (Always) or testing every node (None).
    // With generatedKernels, also by the kernels the render plan picks by default (for a small
    // scene one generated for it, which the driver compiles per scene and sample count: on
    // lavapipe most of a check's time).
    Acceleration dataDrivenAcceleration = Acceleration::Always;
    bool generatedKernels = true;
    std::optional<std::uint32_t> generatedKernelSamples;  // the generated kernels only at this sample count
};

// The options that render again just the render `finding` came from.
DifferentialOptions optionsFor(const Finding& finding, DifferentialOptions options);

// How the check obtains a GPU render: the renderer's by default; a test substitutes one.
using GpuRenderFunction = std::function<GpuRenderResult(const Scene& scene, const RenderPlan& plan)>;

// Everything wrong with `scene` at the options' size and sample counts: in every precision,
// colours that are NaN, infinite or negative (in either render); in f32 and f64, topology
// mismatches in decisions the reference did not find near-tied and colours beyond compare's
// tolerance; an ambiguous share above the limit in the most precise comparison (f64 where the
// device has it, else the precision auto picks) at the first sample count, unless the scene has a
// reason to be near-tied (near_tie_reasons.h); and for f32 on a scene float32 cannot hold, anything
// but f64 with a warning. Empty when the scene passes.
//
// The ambiguity limit is held by the most precise comparison because it judges the pixels the
// others excuse: a horizon that f32 cannot settle would otherwise fail a scene that f64, with
// bounds 2^29 tighter, checks in full. And at
// the first sample count (1), where a pixel's near-ties are its class's own: with more samples a
// near-tie in any of them makes the pixel ambiguous, though it may excuse only the colour.
std::vector<Finding> checkRenders(GpuRenderer& renderer, const Scene& scene, const DifferentialOptions& options,
                                  const GpuRenderFunction& render = {});

// The scene written as a scene file must load back exactly; `outOfRange` (a value beyond the
// supported range) must instead be rejected with a message naming the supported range.
std::optional<Finding> checkLoad(const Scene& scene, bool outOfRange);

}  // namespace hexray::test
