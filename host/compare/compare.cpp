#include "compare/compare.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include "compare/error_accumulator.h"
#include "compare/render_comparator.h"

namespace hexray {
namespace {

void requireSameSize(std::uint32_t w1, std::uint32_t h1, std::uint32_t w2, std::uint32_t h2) {
    if (w1 != w2 || h1 != h2) {
        throw std::invalid_argument("cannot compare a " + std::to_string(w1) + "x" + std::to_string(h1) +
                                    " image with a " + std::to_string(w2) + "x" + std::to_string(h2) + " one");
    }
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
            accumulator.addPixel(displayedDifference(reference.pixels[i], test.pixels[i]));
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
            accumulator.addPixel(levelDifference(reference, test, i));
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

TopologyComparison& TopologyComparison::operator+=(const TopologyComparison& band) {
    pixels += band.pixels;
    ambiguous += band.ambiguous;
    mismatches += band.mismatches;
    nodeMismatches += band.nodeMismatches;
    checkerMismatches += band.checkerMismatches;
    lightMismatches += band.lightMismatches;
    return *this;
}

RenderComparison compareRenders(const Image& referenceImage, const std::vector<PixelClass>& referenceClasses,
                                const PixelMask& ambiguous, const Image& testImage,
                                const std::vector<PixelClass>& testClasses, Encoding encoding) {
    requireSameSize(referenceImage.width, referenceImage.height, testImage.width, testImage.height);
    RenderComparator comparator;
    comparator.add({referenceImage, referenceClasses, encodeImage(referenceImage, encoding)},
                   {testImage, testClasses, encodeImage(testImage, encoding)}, ambiguous);
    return comparator.result();
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
        const glm::dvec3 difference = glm::abs(levelDifference(reference, test, i));
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
            const glm::dvec3 difference = glm::abs(levelDifference(reference, test, i));
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
