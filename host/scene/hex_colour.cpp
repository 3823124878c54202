#include "scene/hex_colour.h"

#include <charconv>
#include <cmath>

namespace hexray::inline scene {

double srgbToLinear(double encoded) {
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

std::optional<Color> parseHexColour(const std::string& text) {
    if (text.size() != 7 || text[0] != '#')
        return std::nullopt;
    Color result;
    for (int channel = 0; channel < 3; ++channel) {
        unsigned byte = 0;
        const char* first = text.data() + 1 + 2 * channel;
        const auto parsed = std::from_chars(first, first + 2, byte, 16);  // accepts either case
        if (parsed.ec != std::errc() || parsed.ptr != first + 2)
            return std::nullopt;
        result[channel] = srgbToLinear(double(byte) / 255.0);
    }
    return result;
}

}  // namespace hexray::scene
