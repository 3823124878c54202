#include "compare/render_comparator.h"

#include <stdexcept>

namespace hexray {

void RenderComparator::add(const RenderBand& reference, const RenderBand& test, const PixelMask& ambiguous) {
    const std::size_t pixels = reference.image.pixels.size();
    if (test.image.pixels.size() != pixels || reference.encoded.bytes.size() != 3 * pixels ||
        test.encoded.bytes.size() != 3 * pixels || (!ambiguous.empty() && ambiguous.size() != pixels)) {
        throw std::invalid_argument("RenderComparator: bands of different sizes");
    }
    topology_ += compareTopology(reference.classes, test.classes, ambiguous);
    for (std::size_t i = 0; i < pixels; ++i) {
        if (ambiguous.empty() || !ambiguous[i]) {
            linear_.addPixel(displayedDifference(reference.image.pixels[i], test.image.pixels[i]));
            encoded_.addPixel(levelDifference(reference.encoded, test.encoded, i));
        }
    }
}

RenderComparison RenderComparator::result() const {
    return {topology_, linear_.result(), encoded_.result()};
}

}  // namespace hexray
