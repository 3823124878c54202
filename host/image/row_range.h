#pragma once
// A range of an image's rows: what a strip (`render --strip`) renders.

#include <cstdint>

namespace hexray::inline image {

// Rows [first, first + count); the default is every row.
struct RowRange {
    std::uint32_t first = 0;
    std::uint32_t count = UINT32_MAX;  // clipped to the image's last row

    std::uint32_t end() const { return count > UINT32_MAX - first ? UINT32_MAX : first + count; }
};

}  // namespace hexray::image
