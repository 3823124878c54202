#pragma once
// lavapipe's loop limit, and the light batches that keep the data-driven kernel within it.
//
// Mesa's gallivm (lavapipe's shader compiler; Mesa 22.x, src/gallium/auxiliary/gallivm/
// lp_bld_ir_common.c) gives a shader one loop limiter per SIMD vector of invocations, set to
// LP_MAX_TGSI_LOOP_ITERATIONS (65535) on entry and decremented at the end of every pass through any
// of its loops (lp_exec_endloop); a loop whose pass leaves it at 0 or below ends there, done or
// not, and so does every later loop after its first pass. Every call is inlined, so one invocation
// has 65535 passes for all its loops together, and past them its image is silently wrong. A loop
// makes a pass per iteration and one more that finds its condition false (its break is a mask,
// not a jump), so a loop entered with nothing to do still costs one; a vector of invocations (8 on
// AVX2) makes as many passes of each loop as its busiest lane.
//
// render.comp's loops are bounded here, from the scene and its candidate lists, whatever any pixel
// actually meets; a render whose pixels could pass the limit is split into dispatches that each
// stay within it (shaders/light_batches.glsl): whole samples at a time, or one sample in batches
// of lights. A generated kernel's loops are unrolled (all but the sample loop, which is within any
// limit).

#include <cstdint>
#include <optional>
#include <vector>

#include "scene/scene.h"

namespace hexray::inline accel {
struct CandidateLists;  // accel/candidate_lists.h
}  // namespace hexray::accel

namespace hexray::inline gpu {

// The passes lavapipe runs in one invocation.
inline constexpr std::uint64_t kLavapipeLoopPasses = 65535;

// Upper bounds on the passes render.comp's loops make for one pixel.
struct LoopPasses {
    // Per sample, besides its lights: the camera ray's loops (the planes' and its cell's list, or
    // every node) and the light loop's last pass.
    std::uint64_t sample = 0;
    // Per light: its pass of the light loop and its shadow test's loops (the planes' and the
    // longest list of its grids, or every node).
    std::vector<std::uint64_t> lights;
    // Per sample of a traced pixel (`hexray pixel`): the loop that records every node's distance.
    std::uint64_t traceSample = 0;
};

// The bounds for `scene`, traced through `lists` (null: testing every node).
LoopPasses loopPasses(const Scene& scene, const CandidateLists* lists);

// One dispatch's share of each pixel: samples [firstSample, endSample) and, of each, lights
// [firstLight, endLight).
struct PixelWork {
    std::uint32_t firstSample = 0;
    std::uint32_t endSample = 0;
    std::uint32_t firstLight = 0;
    std::uint32_t endLight = 0;
};

// How a render's pixels are split between dispatches.
struct LightBatches {
    std::uint32_t samplesPerDispatch = 0;  // 0: one dispatch renders every sample and light
    std::vector<std::uint32_t> lightEnds;  // where each batch of lights ends; one batch: whole samples

    bool splits() const { return samplesPerDispatch != 0; }
    // The dispatches in order: sample after sample, each sample's batches of lights in order.
    std::vector<PixelWork> work(std::uint32_t samples, std::uint32_t lights) const;
};

// The passes of a dispatch that renders `samples` samples per pixel with lights [firstLight,
// endLight) of each (the sample loop's own included).
std::uint64_t dispatchPasses(const LoopPasses& passes, std::uint64_t samples, std::uint32_t firstLight,
                             std::uint32_t endLight);

// The passes of the dispatch that traces one pixel with `samples` samples.
std::uint64_t tracePasses(const LoopPasses& passes, std::uint64_t samples);

// The fewest dispatches, batches of lights taken greedily in order, that render `samples` per pixel
// with at most `limit` passes each; nothing when a single sample with a single light would pass it.
std::optional<LightBatches> planLightBatches(const LoopPasses& passes, std::uint32_t samples, std::uint64_t limit);

// The most passes a single sample with its most costly light needs: what planLightBatches could
// not split further.
std::uint64_t smallestDispatchPasses(const LoopPasses& passes);

}  // namespace hexray::gpu
