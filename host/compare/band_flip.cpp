#include "compare/band_flip.h"

#include "compare/flip.h"

namespace hexray::inline compare {
namespace {

// An 8-bit linear output's levels as the linear colours they stand for.
Image linearOf(const Rgb8Image& encoded) {
    Image image;
    image.width = encoded.width;
    image.height = encoded.height;
    image.pixels.resize(std::size_t(encoded.width) * encoded.height);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        image.pixels[i] = glm::vec3(encoded.bytes[3 * i], encoded.bytes[3 * i + 1], encoded.bytes[3 * i + 2]) / 255.0f;
    }
    return image;
}

}  // namespace

BandFlip::BandFlip(std::uint32_t width, std::uint32_t height, Encoding encoding)
    : kept_(std::uint64_t(width) * height <= kMaxFlipPixels), encoding_(encoding) {
    for (Rgb8Image* image : {&reference_, &test_}) {
        image->width = width;
        image->height = 0;
        if (kept_) {
            image->bytes.reserve(std::size_t(3) * width * height);
        }
    }
}

void BandFlip::add(const Rgb8Image& reference, const Rgb8Image& test) {
    if (!kept_) {
        return;
    }
    reference_.bytes.insert(reference_.bytes.end(), reference.bytes.begin(), reference.bytes.end());
    test_.bytes.insert(test_.bytes.end(), test.bytes.begin(), test.bytes.end());
    reference_.height += reference.height;
    test_.height += test.height;
}

std::optional<double> BandFlip::mean() const {
    if (!kept_ || reference_.height == 0) {
        return std::nullopt;
    }
    if (encoding_ == Encoding::Linear) {
        return ldrFlip(linearOf(reference_), linearOf(test_), kDefaultPixelsPerDegree).mean();
    }
    return ldrFlip(reference_, test_, kDefaultPixelsPerDegree).mean();
}

}  // namespace hexray::compare
