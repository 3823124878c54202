#include "gpu/loop_budget.h"

#include <algorithm>
#include <numeric>

#include "accel/candidate_lists.h"
#include "scene/scene_contents.h"
#include "shader_interface.h"

namespace hexray::inline gpu {
namespace {

// A loop over `count` items: a pass each and the pass that ends it.
std::uint64_t loopOver(std::uint64_t count) {
    return count + 1;
}

// The longest list a ray looking up grid `grid` can take: one of its cells, or the one it names
// for rays past its reach.
std::uint64_t longestList(const CandidateLists& lists, std::size_t grid) {
    const glm::uvec4 cells = lists.grids[grid].cells;
    const auto length = [&](std::size_t cell) {
        return std::uint64_t(lists.cellStarts[cell + 1] - lists.cellStarts[cell]);
    };
    std::uint64_t longest = length(cells.w);
    const std::size_t end = std::size_t(cells.z) + std::size_t(cells.x) * cells.y;
    for (std::size_t cell = cells.z; cell < end; ++cell) {
        longest = std::max(longest, length(cell));
    }
    return longest;
}

// A light's shadow test through the lists: the planes' loop and the longest list of its cube faces.
std::uint64_t listedShadowTest(const CandidateLists& lists, std::uint64_t planes, std::size_t light) {
    std::uint64_t longest = 0;
    for (std::size_t face = 0; face < gpu::CUBE_FACES; ++face) {
        longest = std::max(longest, longestList(lists, gpu::CAMERA_GRID + 1 + gpu::CUBE_FACES * light + face));
    }
    return loopOver(planes) + loopOver(longest);
}

}  // namespace

LoopPasses loopPasses(const Scene& scene, const CandidateLists* lists) {
    const std::uint64_t nodes = scene.nodes.size();
    const std::uint64_t planes = nodes - countSpheres(scene);
    LoopPasses passes;
    // findNearestHit: the planes' loop and the camera cell's, or every node; then the light loop's
    // last pass.
    const std::uint64_t camera =
        lists ? loopOver(planes) + loopOver(longestList(*lists, gpu::CAMERA_GRID)) : loopOver(nodes);
    passes.sample = camera + 1;
    // shadeLights: a pass of the light loop, and isOccluded's loops.
    passes.lights.resize(scene.lights.size());
    for (std::size_t light = 0; light < scene.lights.size(); ++light) {
        passes.lights[light] = 1 + (lists ? listedShadowTest(*lists, planes, light) : loopOver(nodes));
    }
    passes.traceSample = loopOver(nodes);
    return passes;
}

std::vector<PixelWork> LightBatches::work(std::uint32_t samples, std::uint32_t lights) const {
    if (!splits()) {
        return {PixelWork{0, samples, 0, lights}};
    }
    std::vector<PixelWork> parts;
    for (std::uint32_t first = 0; first < samples; first += samplesPerDispatch) {
        const std::uint32_t end = first + std::min(samplesPerDispatch, samples - first);
        std::uint32_t firstLight = 0;
        for (const std::uint32_t endLight : lightEnds) {
            parts.push_back(PixelWork{first, end, firstLight, endLight});
            firstLight = endLight;
        }
    }
    return parts;
}

std::uint64_t dispatchPasses(const LoopPasses& passes, std::uint64_t samples, std::uint32_t firstLight,
                             std::uint32_t endLight) {
    const std::uint64_t lights =
        std::accumulate(passes.lights.begin() + firstLight, passes.lights.begin() + endLight, std::uint64_t{0});
    return samples * (passes.sample + lights) + loopOver(samples);
}

std::uint64_t tracePasses(const LoopPasses& passes, std::uint64_t samples) {
    const auto lights = std::uint32_t(passes.lights.size());
    return dispatchPasses(passes, samples, 0, lights) + samples * passes.traceSample;
}

std::uint64_t smallestDispatchPasses(const LoopPasses& passes) {
    const std::uint64_t heaviest = passes.lights.empty() ? 0 : std::ranges::max(passes.lights);
    return dispatchPasses(passes, 1, 0, 0) + heaviest;
}

std::optional<LightBatches> planLightBatches(const LoopPasses& passes, std::uint32_t samples, std::uint64_t limit) {
    const auto lights = std::uint32_t(passes.lights.size());
    if (dispatchPasses(passes, samples, 0, lights) <= limit) {
        return LightBatches{};
    }
    if (smallestDispatchPasses(passes) > limit) {
        return std::nullopt;
    }
    if (const std::uint64_t perSample = dispatchPasses(passes, 1, 0, lights); perSample <= limit) {
        // n samples cost n (perSample - 1) + 1 passes: the sample loop's last pass is shared.
        return LightBatches{std::uint32_t((limit - 1) / (perSample - 1)), {lights}};
    }
    // One sample a dispatch, as many lights in each as fit, in order.
    const std::uint64_t alone = dispatchPasses(passes, 1, 0, 0);
    LightBatches batches{1, {}};
    std::uint64_t used = alone;
    for (std::uint32_t light = 0; light < lights; ++light) {
        if (used + passes.lights[light] > limit) {
            batches.lightEnds.push_back(light);
            used = alone;
        }
        used += passes.lights[light];
    }
    batches.lightEnds.push_back(lights);
    return batches;
}

}  // namespace hexray::gpu
