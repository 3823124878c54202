#include "compare/error_accumulator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace hexray::inline compare {

void ErrorAccumulator::addPixel(const glm::dvec3& difference) {
    const glm::dvec3 magnitude = glm::abs(difference);
    const double largest = std::max({magnitude.x, magnitude.y, magnitude.z});
    metrics_.maxAbs = std::max(metrics_.maxAbs, largest);
    sumAbs_ += magnitude.x + magnitude.y + magnitude.z;
    sumSquares_ += glm::dot(difference, difference);
    metrics_.pixelsOverOneLevel += largest > oneLevel_ ? 1 : 0;
    ++pixels_;
}

ErrorMetrics ErrorAccumulator::result() const {
    ErrorMetrics metrics = metrics_;
    metrics.pixels = pixels_;
    const double channels = 3.0 * double(std::max<std::uint64_t>(pixels_, 1));
    metrics.meanAbs = sumAbs_ / channels;
    metrics.rmse = std::sqrt(sumSquares_ / channels);
    metrics.psnr =
        metrics.rmse == 0.0 ? std::numeric_limits<double>::infinity() : 20.0 * std::log10(peak_ / metrics.rmse);
    metrics.shareOverOneLevel = double(metrics.pixelsOverOneLevel) / double(std::max<std::uint64_t>(pixels_, 1));
    return metrics;
}

glm::dvec3 displayedDifference(const glm::vec3& reference, const glm::vec3& test) {
    return glm::clamp(glm::dvec3(test), 0.0, 1.0) - glm::clamp(glm::dvec3(reference), 0.0, 1.0);
}

glm::dvec3 levelDifference(const Rgb8Image& reference, const Rgb8Image& test, std::size_t pixel) {
    const auto levels = [pixel](const Rgb8Image& image) {
        return glm::dvec3(image.bytes[3 * pixel], image.bytes[3 * pixel + 1], image.bytes[3 * pixel + 2]);
    };
    return levels(test) - levels(reference);
}

}  // namespace hexray::compare
