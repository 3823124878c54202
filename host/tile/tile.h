#pragma once
// Tiles: an image split into N bands of rows (`render --tile I/N`), each rendered anywhere (one
// process, machine or batch-engine task per tile) and assembled by `hexray merge`. A piece
// records which tile it is, of which image, in its file (tile_stamp.h).

#include <cstdint>
#include <stdexcept>

#include "image/row_range.h"

namespace hexray {

// A piece that cannot be part of a merged image, or a tile the image cannot have. Exit code 2.
class TileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

inline constexpr std::uint32_t kMaxTiles = 16384;  // the tallest image, a row a tile

struct Tile {
    std::uint32_t index = 0;  // 0 .. count - 1, as batch engines number their tasks
    std::uint32_t count = 1;
    bool operator==(const Tile&) const = default;
};

// Tile I of N is rows floor(I*H/N) to floor((I+1)*H/N) - 1: every row in exactly one tile, the
// tiles' heights differing by at most one. Throws TileError when the image has fewer rows than
// tiles.
RowRange tileRows(Tile tile, std::uint32_t height);

}  // namespace hexray
