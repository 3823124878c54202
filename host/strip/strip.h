#pragma once
// Strips: an image split into N bands of rows (`render --strip I/N`), each rendered anywhere (one
// process, machine or batch-engine task per strip) and assembled by `hexray merge`. A piece
// records which strip it is, of which image, in its file (strip_stamp.h).

#include <cstdint>
#include <stdexcept>

#include "image/row_range.h"

namespace hexray::inline strip {

// A piece that cannot be part of a merged image, or a strip the image cannot have. Exit code 2.
class StripError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

inline constexpr std::uint32_t kMaxStrips = 16384;  // the tallest image, a row a strip

struct Strip {
    std::uint32_t index = 0;  // 0 .. count - 1, as batch engines number their tasks
    std::uint32_t count = 1;
    bool operator==(const Strip&) const = default;
};

// Strip I of N is rows floor(I*H/N) to floor((I+1)*H/N) - 1: every row in exactly one strip, the
// strips' heights differing by at most one. Throws StripError when the image has fewer rows than
// strips.
RowRange stripRows(Strip strip, std::uint32_t height);

}  // namespace hexray::strip
