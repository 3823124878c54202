#pragma once
// The Embree renderers' threads: bands of rows handed out one at a time, so that the costly
// bands are not all one thread's.

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

namespace hexray::inline embree {

// Calls renderBand(top) for each band of `bandHeight` rows of an image `height` rows tall, on
// `threadCount` threads (the caller's among them) that take the next band when done.
template <class RenderBand>
void renderInBands(unsigned threadCount, std::uint32_t height, std::uint32_t bandHeight, const RenderBand& renderBand) {
    const std::uint32_t bands = (height + bandHeight - 1) / bandHeight;
    std::atomic<std::uint32_t> nextBand{0};
    const auto work = [&] {
        for (std::uint32_t band = nextBand++; band < bands; band = nextBand++) {
            renderBand(band * bandHeight);
        }
    };
    std::vector<std::jthread> workers;
    for (unsigned worker = 1; worker < std::min<unsigned>(threadCount, std::max(bands, 1u)); ++worker) {
        workers.emplace_back(work);
    }
    work();
}

}  // namespace hexray::embree
