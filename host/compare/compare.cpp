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

namespace hexray::inline compare {
void requireSameSize(std::uint32_t w1, std::uint32_t h1, std::uint32_t w2, std::uint32_t h2) {
    if (w1 != w2 || h1 != h2) {
        throw std::invalid_argument("cannot compare a " + std::to_string(w1) + "x" + std::to_string(h1) +
                                    " image with a " + std::to_string(w2) + "x" + std::to_string(h2) + " one");
    }
}

namespace {

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

Ambiguities wholePixels(const PixelMask& mask) {
    Ambiguities ambiguity(mask.size());
    for (std::size_t i = 0; i < mask.size(); ++i) {
        if (mask[i]) {
            ambiguity[i] = PixelAmbiguity::everything();
        }
    }
    return ambiguity;
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

PixelJudgement judgePixel(const PixelClass& reference, const PixelClass& test, const PixelAmbiguity& ambiguity) {
    using Mismatch = PixelJudgement::Mismatch;
    PixelJudgement judgement;
    judgement.ambiguous = ambiguity.any();
    bool nearTiedPartDiffers = false;
    if (reference.node != test.node) {
        nearTiedPartDiffers = ambiguity.node;
        judgement.mismatch = ambiguity.node ? Mismatch::None : Mismatch::Node;
    } else {
        const std::uint32_t differing = reference.flags ^ test.flags;
        const std::uint32_t settled = differing & ~ambiguity.flags;
        nearTiedPartDiffers = (differing & ambiguity.flags) != 0;
        judgement.mismatch = (settled & PixelClass::kOddCheckerBit) ? Mismatch::Checker
                             : settled                              ? Mismatch::Lights
                                                                    : Mismatch::None;
    }
    // A near-tied node leaves the colour unchecked too: a ray that grazes a silhouette, or meets a
    // sphere at the limit of the precision, finds a hit point and normal no better than its node.
    judgement.colourCompared = !nearTiedPartDiffers && !ambiguity.colour && !ambiguity.node;
    judgement.excused = judgement.mismatch == Mismatch::None && !judgement.colourCompared;
    return judgement;
}

void TopologyComparison::add(const PixelJudgement& judgement) {
    using Mismatch = PixelJudgement::Mismatch;
    ++pixels;
    ambiguous += judgement.ambiguous;
    excused += judgement.excused;
    mismatches += judgement.mismatch != Mismatch::None;
    nodeMismatches += judgement.mismatch == Mismatch::Node;
    checkerMismatches += judgement.mismatch == Mismatch::Checker;
    lightMismatches += judgement.mismatch == Mismatch::Lights;
}

TopologyComparison compareTopology(const std::vector<PixelClass>& reference, const std::vector<PixelClass>& test,
                                   const Ambiguities& ambiguity) {
    if (reference.size() != test.size() || (!ambiguity.empty() && ambiguity.size() != reference.size())) {
        throw std::invalid_argument("cannot compare classifications of different sizes");
    }
    TopologyComparison topology;
    for (std::size_t i = 0; i < reference.size(); ++i) {
        topology.add(judgePixel(reference[i], test[i], ambiguity.empty() ? PixelAmbiguity{} : ambiguity[i]));
    }
    return topology;
}

TopologyComparison compareTopology(const std::vector<PixelClass>& reference, const std::vector<PixelClass>& test,
                                   const PixelMask& excluded) {
    return compareTopology(reference, test, wholePixels(excluded));
}

TopologyComparison& TopologyComparison::operator+=(const TopologyComparison& band) {
    pixels += band.pixels;
    ambiguous += band.ambiguous;
    excused += band.excused;
    mismatches += band.mismatches;
    nodeMismatches += band.nodeMismatches;
    checkerMismatches += band.checkerMismatches;
    lightMismatches += band.lightMismatches;
    return *this;
}

RenderComparison compareRenders(const Image& referenceImage, const std::vector<PixelClass>& referenceClasses,
                                const Ambiguities& ambiguity, const Image& testImage,
                                const std::vector<PixelClass>& testClasses, Encoding encoding) {
    requireSameSize(referenceImage.width, referenceImage.height, testImage.width, testImage.height);
    RenderComparator comparator;
    comparator.add({referenceImage, referenceClasses, encodeImage(referenceImage, encoding)},
                   {testImage, testClasses, encodeImage(testImage, encoding)}, ambiguity);
    return comparator.result();
}

RenderComparison compareRenders(const Image& referenceImage, const std::vector<PixelClass>& referenceClasses,
                                const PixelMask& excluded, const Image& testImage,
                                const std::vector<PixelClass>& testClasses, Encoding encoding) {
    return compareRenders(referenceImage, referenceClasses, wholePixels(excluded), testImage, testClasses, encoding);
}

bool isValidColour(const glm::vec3& colour) {
    for (int c = 0; c < 3; ++c) {
        if (!(std::isfinite(colour[c]) && colour[c] >= 0.0f)) {
            return false;
        }
    }
    return true;
}

Tolerance ToleranceChanges::appliedTo(Tolerance tolerance) const {
    tolerance.maxTopologyMismatches = maxTopologyMismatches.value_or(tolerance.maxTopologyMismatches);
    tolerance.maxSharePercent = maxSharePercent.value_or(tolerance.maxSharePercent);
    tolerance.maxRmseLevels = maxRmseLevels.value_or(tolerance.maxRmseLevels);
    tolerance.maxAmbiguousPercent = maxAmbiguousPercent.value_or(tolerance.maxAmbiguousPercent);
    return tolerance;
}

void ToleranceChanges::update(const ToleranceChanges& later) {
    maxTopologyMismatches = later.maxTopologyMismatches ? later.maxTopologyMismatches : maxTopologyMismatches;
    maxSharePercent = later.maxSharePercent ? later.maxSharePercent : maxSharePercent;
    maxRmseLevels = later.maxRmseLevels ? later.maxRmseLevels : maxRmseLevels;
    maxAmbiguousPercent = later.maxAmbiguousPercent ? later.maxAmbiguousPercent : maxAmbiguousPercent;
}

Verdict judge(const RenderComparison& comparison, const Tolerance& tolerance) {
    return {comparison.topology.mismatches <= tolerance.maxTopologyMismatches,
            100.0 * comparison.encoded.shareOverOneLevel <= tolerance.maxSharePercent,
            comparison.encoded.rmse <= tolerance.maxRmseLevels,
            100.0 * comparison.topology.ambiguousShare() <= tolerance.maxAmbiguousPercent,
            comparison.invalidColours == 0};
}

Rgb8Image diffHeatMap(const Rgb8Image& reference, const Rgb8Image& test) {
    requireSameSize(reference.width, reference.height, test.width, test.height);
    static constexpr std::array<glm::dvec3, 5> kStops = {glm::dvec3(0, 0, 96), glm::dvec3(160, 0, 160),
                                                         glm::dvec3(255, 0, 0), glm::dvec3(255, 230, 0),
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
                       const Ambiguities& ambiguity, const Rgb8Image& reference, const Rgb8Image& test,
                       const Image* referenceLinear, const Image* testLinear) {
    requireSameSize(reference.width, reference.height, test.width, test.height);
    const std::size_t pixels = std::size_t(reference.width) * reference.height;
    if (referenceClasses.size() != pixels || testClasses.size() != pixels ||
        (!ambiguity.empty() && ambiguity.size() != pixels)) {
        throw std::invalid_argument("mismatchMask: classes or ambiguities do not match the image size");
    }
    Rgb8Image mask{reference.width, reference.height, std::vector<std::uint8_t>(pixels * 3, 0)};
    for (std::size_t i = 0; i < pixels; ++i) {
        const PixelJudgement judgement =
            judgePixel(referenceClasses[i], testClasses[i], ambiguity.empty() ? PixelAmbiguity{} : ambiguity[i]);
        const glm::dvec3 difference = glm::abs(levelDifference(reference, test, i));
        const bool colourOff = std::max({difference.x, difference.y, difference.z}) > 1.0;
        const bool invalid = (referenceLinear && !isValidColour(referenceLinear->pixels.at(i))) ||
                             (testLinear && !isValidColour(testLinear->pixels.at(i)));
        const std::uint8_t* colour = invalid                                                ? mask_colour::kInvalid
                                     : judgement.mismatch != PixelJudgement::Mismatch::None ? mask_colour::kTopology
                                     : judgement.excused                                    ? mask_colour::kExcused
                                     : judgement.colourCompared && colourOff                ? mask_colour::kColour
                                     : judgement.ambiguous                                  ? mask_colour::kNearTied
                                                                                            : nullptr;
        if (colour) {
            std::copy(colour, colour + 3, mask.bytes.begin() + std::ptrdiff_t(3 * i));
        }
    }
    return mask;
}

}  // namespace hexray::compare
