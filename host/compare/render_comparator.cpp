#include "compare/render_comparator.h"

#include <stdexcept>

namespace hexray::inline compare {

void RenderComparator::add(const RenderBand& reference, const RenderBand& test, const Ambiguities& ambiguity) {
    const std::size_t pixels = reference.image.pixels.size();
    if (test.image.pixels.size() != pixels || reference.classes.size() != pixels || test.classes.size() != pixels ||
        reference.encoded.bytes.size() != 3 * pixels || test.encoded.bytes.size() != 3 * pixels ||
        (!ambiguity.empty() && ambiguity.size() != pixels)) {
        throw std::invalid_argument("RenderComparator: bands of different sizes");
    }
    for (std::size_t i = 0; i < pixels; ++i) {
        const PixelJudgement judgement =
            judgePixel(reference.classes[i], test.classes[i], ambiguity.empty() ? PixelAmbiguity{} : ambiguity[i]);
        topology_.add(judgement);
        invalidColours_ += !isValidColour(reference.image.pixels[i]) || !isValidColour(test.image.pixels[i]);
        if (judgement.colourCompared) {
            linear_.addPixel(displayedDifference(reference.image.pixels[i], test.image.pixels[i]));
            encoded_.addPixel(levelDifference(reference.encoded, test.encoded, i));
        }
    }
}

RenderComparison RenderComparator::result() const {
    return {topology_, linear_.result(), encoded_.result(), invalidColours_};
}

}  // namespace hexray::compare
