#include "image/pixel_digest.h"

#include <bit>
#include <stdexcept>

namespace hexray::inline image {

PixelDigest::PixelDigest(std::string_view preamble) {
    hash_.add(preamble);
    constexpr char kSeparator = '\0';  // ends the preamble: no preamble is a prefix of another
    hash_.add(std::string_view(&kSeparator, 1));
}

void PixelDigest::addRgb8Rows(std::span<const std::uint8_t> rgbRows) {
    hash_.add(std::string_view(reinterpret_cast<const char*>(rgbRows.data()), rgbRows.size()));
}

void PixelDigest::addFloatRows(std::span<const float> red, std::span<const float> green, std::span<const float> blue) {
    if (green.size() != red.size() || blue.size() != red.size()) {
        throw std::invalid_argument("PixelDigest::addFloatRows: channels of different sizes");
    }
    bytes_.resize(red.size() * 12);
    std::uint8_t* out = bytes_.data();
    const auto put = [&out](float value) {
        const auto bits = std::bit_cast<std::uint32_t>(value);
        for (int shift = 0; shift < 32; shift += 8) {
            *out++ = std::uint8_t(bits >> shift);
        }
    };
    for (std::size_t i = 0; i < red.size(); ++i) {
        put(red[i]);
        put(green[i]);
        put(blue[i]);
    }
    hash_.add(std::string_view(reinterpret_cast<const char*>(bytes_.data()), bytes_.size()));
}

std::string PixelDigest::hex() {
    return hexText(hash_.finish());
}

}  // namespace hexray::image
