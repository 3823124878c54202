#include "strip/strip.h"

#include <string>

namespace hexray::inline strip {

RowRange stripRows(Strip strip, std::uint32_t height) {
    if (strip.count > height) {
        throw StripError("--strip " + std::to_string(strip.index) + "/" + std::to_string(strip.count) +
                         ": the image has " + std::to_string(height) + " rows, so at most " + std::to_string(height) +
                         " strips");
    }
    const auto boundary = [&](std::uint64_t index) { return std::uint32_t(index * height / strip.count); };
    const std::uint32_t first = boundary(strip.index);
    return RowRange{first, boundary(strip.index + 1) - first};
}

}  // namespace hexray::strip
