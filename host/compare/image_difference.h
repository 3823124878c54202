#pragma once
// How two image files differ, pixel by pixel, on one scale for both formats: a channel's value in
// [0, 1] for 8-bit images (levels / 255), the linear value itself for float ones (not clamped, so
// that an HDR image's highlights count). For `hexray diff`: the thresholds apply to each pixel's
// largest channel difference.

#include <cstdint>
#include <vector>

#include "compare/compare.h"
#include "image/image.h"
#include "image/image_io.h"

namespace hexray::inline compare {

struct ImageDifference {
    ErrorMetrics metrics;  // on the [0, 1] scale, over the pixels whose channels are all finite
    // Each pixel's largest channel difference |test - reference|: +infinity where a channel of
    // either image is not finite (NaN, infinite) and the two are not the same value.
    std::vector<float> pixelDifferences;
    std::uint64_t nonFinitePixels = 0;
    std::uint32_t maxX = 0;  // where the largest finite difference is (the first such pixel)
    std::uint32_t maxY = 0;
};

// Both images must have the same size (checked; throws std::invalid_argument).
ImageDifference differenceOf(const Rgb8Image& reference, const Rgb8Image& test);
ImageDifference differenceOf(const Image& reference, const Image& test);

// How many of `differences` exceed `threshold`.
std::uint64_t pixelsAbove(const std::vector<float>& differences, double threshold);

}  // namespace hexray::compare
