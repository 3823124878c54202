#include "compare/compare.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace hexray {
namespace {

void requireSameSize(std::uint32_t w1, std::uint32_t h1, std::uint32_t w2, std::uint32_t h2) {
    if (w1 != w2 || h1 != h2) {
        throw std::invalid_argument("cannot compare a " + std::to_string(w1) + "x" + std::to_string(h1) +
                                    " image with a " + std::to_string(w2) + "x" + std::to_string(h2) + " one");
    }
}

// Accumulates per-channel differences of one pixel at a time; `oneLevel` and `peak` are in the
// images' units.
class ErrorAccumulator {
public:
    ErrorAccumulator(double oneLevel, double peak) : oneLevel_(oneLevel), peak_(peak) {}

    void addPixel(const glm::dvec3& difference) {
        const glm::dvec3 magnitude = glm::abs(difference);
        const double largest = std::max({magnitude.x, magnitude.y, magnitude.z});
        metrics_.maxAbs = std::max(metrics_.maxAbs, largest);
        sumAbs_ += magnitude.x + magnitude.y + magnitude.z;
        sumSquares_ += glm::dot(difference, difference);
        metrics_.pixelsOverOneLevel += largest > oneLevel_ ? 1 : 0;
        ++pixels_;
    }

    ErrorMetrics result() const {
        ErrorMetrics metrics = metrics_;
        metrics.pixels = pixels_;
        const double channels = 3.0 * double(std::max<std::uint64_t>(pixels_, 1));
        metrics.meanAbs = sumAbs_ / channels;
        metrics.rmse = std::sqrt(sumSquares_ / channels);
        metrics.psnr = metrics.rmse == 0.0 ? std::numeric_limits<double>::infinity()
                                           : 20.0 * std::log10(peak_ / metrics.rmse);
        metrics.shareOverOneLevel = double(metrics.pixelsOverOneLevel) / double(std::max<std::uint64_t>(pixels_, 1));
        return metrics;
    }

private:
    double oneLevel_;
    double peak_;
    ErrorMetrics metrics_;
    double sumAbs_ = 0;
    double sumSquares_ = 0;
    std::uint64_t pixels_ = 0;
};

glm::dvec3 displayable(const glm::vec3& linear) {
    return glm::clamp(glm::dvec3(linear), 0.0, 1.0);
}

glm::dvec3 levelsAt(const Rgb8Image& image, std::size_t pixel) {
    return glm::dvec3(image.bytes[3 * pixel], image.bytes[3 * pixel + 1], image.bytes[3 * pixel + 2]);
}

bool considered(const PixelMask& mask, std::size_t pixel) {
    return mask.empty() || mask[pixel];
}

}  // namespace

PixelMask marginsBelow(const std::vector<float>& margins, double threshold) {
    PixelMask mask(margins.size());
    for (std::size_t i = 0; i < margins.size(); ++i) {
        mask[i] = margins[i] < threshold;
    }
    return mask;
}

ErrorMetrics compareLinear(const Image& reference, const Image& test, const PixelMask& mask) {
    requireSameSize(reference.width, reference.height, test.width, test.height);
    ErrorAccumulator accumulator(1.0 / 255.0, 1.0);
    for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
        if (considered(mask, i)) {
            accumulator.addPixel(displayable(test.pixels[i]) - displayable(reference.pixels[i]));
        }
    }
    return accumulator.result();
}

ErrorMetrics compareEncoded(const Rgb8Image& reference, const Rgb8Image& test, const PixelMask& mask) {
    requireSameSize(reference.width, reference.height, test.width, test.height);
    ErrorAccumulator accumulator(1.0, 255.0);
    const std::size_t pixels = std::size_t(reference.width) * reference.height;
    for (std::size_t i = 0; i < pixels; ++i) {
        if (considered(mask, i)) {
            accumulator.addPixel(levelsAt(test, i) - levelsAt(reference, i));
        }
    }
    return accumulator.result();
}

TopologyComparison compareTopology(const std::vector<PixelClass>& reference, const std::vector<PixelClass>& test,
                                   const PixelMask& ambiguous) {
    if (reference.size() != test.size()) {
        throw std::invalid_argument("cannot compare classifications of different sizes");
    }
    TopologyComparison topology;
    topology.pixels = reference.size();
    for (std::size_t i = 0; i < reference.size(); ++i) {
        if (!ambiguous.empty() && ambiguous[i]) {
            ++topology.ambiguous;
            continue;
        }
        const PixelClass& expected = reference[i];
        const PixelClass& actual = test[i];
        if (expected == actual) {
            continue;
        }
        ++topology.mismatches;
        if (expected.node != actual.node) {
            ++topology.nodeMismatches;
        } else if ((expected.flags ^ actual.flags) & PixelClass::kOddCheckerBit) {
            ++topology.checkerMismatches;
        } else {
            ++topology.lightMismatches;
        }
    }
    return topology;
}

RenderComparison compareRenders(const Image& referenceImage, const std::vector<PixelClass>& referenceClasses,
                                const PixelMask& ambiguous, const Image& testImage,
                                const std::vector<PixelClass>& testClasses, Encoding encoding) {
    PixelMask unambiguous(ambiguous.size());
    for (std::size_t i = 0; i < ambiguous.size(); ++i) {
        unambiguous[i] = !ambiguous[i];
    }
    return {compareTopology(referenceClasses, testClasses, ambiguous),
            compareLinear(referenceImage, testImage, unambiguous),
            compareEncoded(encodeImage(referenceImage, encoding), encodeImage(testImage, encoding), unambiguous)};
}

Verdict judge(const RenderComparison& comparison, const Tolerance& tolerance) {
    return {comparison.topology.mismatches <= tolerance.maxTopologyMismatches,
            100.0 * comparison.encoded.shareOverOneLevel <= tolerance.maxSharePercent,
            comparison.encoded.rmse <= tolerance.maxRmseLevels};
}

Rgb8Image diffHeatMap(const Rgb8Image& reference, const Rgb8Image& test) {
    requireSameSize(reference.width, reference.height, test.width, test.height);
    static constexpr std::array<glm::dvec3, 5> kStops = {
        glm::dvec3(0, 0, 96), glm::dvec3(160, 0, 160), glm::dvec3(255, 0, 0), glm::dvec3(255, 230, 0),
        glm::dvec3(255, 255, 255)};
    const std::size_t pixels = std::size_t(reference.width) * reference.height;
    Rgb8Image map{reference.width, reference.height, std::vector<std::uint8_t>(pixels * 3, 0)};
    for (std::size_t i = 0; i < pixels; ++i) {
        const glm::dvec3 difference = glm::abs(levelsAt(test, i) - levelsAt(reference, i));
        const double levels = std::max({difference.x, difference.y, difference.z});
        if (levels == 0.0) {
            continue;
        }
        // log scale: 1 level -> first stop, 255 levels -> last stop
        const double position = std::log(levels) / std::log(255.0) * double(kStops.size() - 1);
        const std::size_t stop = std::min(std::size_t(position), kStops.size() - 2);
        const glm::dvec3 color = glm::mix(kStops[stop], kStops[stop + 1], position - double(stop));
        for (int c = 0; c < 3; ++c) {
            map.bytes[3 * i + c] = std::uint8_t(std::lround(color[c]));
        }
    }
    return map;
}

Rgb8Image mismatchMask(const std::vector<PixelClass>& referenceClasses, const std::vector<PixelClass>& testClasses,
                       const PixelMask& ambiguous, const Rgb8Image& reference, const Rgb8Image& test) {
    requireSameSize(reference.width, reference.height, test.width, test.height);
    const std::size_t pixels = std::size_t(reference.width) * reference.height;
    if (referenceClasses.size() != pixels || testClasses.size() != pixels ||
        (!ambiguous.empty() && ambiguous.size() != pixels)) {
        throw std::invalid_argument("mismatchMask: classes or mask do not match the image size");
    }
    Rgb8Image mask{reference.width, reference.height, std::vector<std::uint8_t>(pixels * 3, 0)};
    for (std::size_t i = 0; i < pixels; ++i) {
        const std::uint8_t* colour = nullptr;
        if (!ambiguous.empty() && ambiguous[i]) {
            colour = mask_colour::kAmbiguous;
        } else if (referenceClasses[i] != testClasses[i]) {
            colour = mask_colour::kTopology;
        } else {
            const glm::dvec3 difference = glm::abs(levelsAt(test, i) - levelsAt(reference, i));
            if (std::max({difference.x, difference.y, difference.z}) > 1.0) {
                colour = mask_colour::kColour;
            }
        }
        if (colour) {
            std::copy(colour, colour + 3, mask.bytes.begin() + std::ptrdiff_t(3 * i));
        }
    }
    return mask;
}

}  // namespace hexray
