#include "compare/image_difference.h"

#include "compare/compare.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/common.hpp>

#include "compare/error_accumulator.h"

namespace hexray::inline compare {

namespace {

// Where the largest finite entry of `differences` is, in an image `width` wide.
void locateMax(ImageDifference& difference, std::uint32_t width) {
    float largest = -1.0f;
    std::size_t at = 0;
    for (std::size_t i = 0; i < difference.pixelDifferences.size(); ++i) {
        const float value = difference.pixelDifferences[i];
        if (std::isfinite(value) && value > largest) {
            largest = value;
            at = i;
        }
    }
    difference.maxX = std::uint32_t(at % width);
    difference.maxY = std::uint32_t(at / width);
}

}  // namespace

ImageDifference differenceOf(const Rgb8Image& reference, const Rgb8Image& test) {
    ImageDifference difference;
    const ErrorMetrics levels = compareEncoded(reference, test);
    difference.metrics = levels;
    difference.metrics.maxAbs = levels.maxAbs / 255.0;
    difference.metrics.meanAbs = levels.meanAbs / 255.0;
    difference.metrics.rmse = levels.rmse / 255.0;
    const std::size_t pixels = std::size_t(reference.width) * reference.height;
    difference.pixelDifferences.resize(pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
        const glm::dvec3 channels = glm::abs(levelDifference(reference, test, i));
        difference.pixelDifferences[i] = float(std::max({channels.x, channels.y, channels.z}) / 255.0);
    }
    locateMax(difference, reference.width);
    return difference;
}

ImageDifference differenceOf(const Image& reference, const Image& test) {
    requireSameSize(reference.width, reference.height, test.width, test.height);
    ImageDifference difference;
    ErrorAccumulator accumulator(1.0 / 255.0, 1.0);
    difference.pixelDifferences.resize(reference.pixels.size());
    for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
        const glm::dvec3 channels = glm::dvec3(test.pixels[i]) - glm::dvec3(reference.pixels[i]);
        if (std::isfinite(channels.x) && std::isfinite(channels.y) && std::isfinite(channels.z)) {
            accumulator.addPixel(channels);
            const glm::dvec3 magnitude = glm::abs(channels);
            difference.pixelDifferences[i] = float(std::max({magnitude.x, magnitude.y, magnitude.z}));
            continue;
        }
        ++difference.nonFinitePixels;
        // The same NaN or infinity in both is no difference; anything else fails every threshold.
        const bool same = std::equal(&reference.pixels[i].x, &reference.pixels[i].x + 3, &test.pixels[i].x,
                                     [](float a, float b) { return a == b || (std::isnan(a) && std::isnan(b)); });
        difference.pixelDifferences[i] = same ? 0.0f : std::numeric_limits<float>::infinity();
    }
    difference.metrics = accumulator.result();
    locateMax(difference, reference.width);
    return difference;
}

std::uint64_t pixelsAbove(const std::vector<float>& differences, double threshold) {
    return std::uint64_t(std::count_if(differences.begin(), differences.end(),
                                       [threshold](float value) { return double(value) > threshold; }));
}

}  // namespace hexray::compare
