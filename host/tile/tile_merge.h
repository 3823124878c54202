#pragma once
// `hexray merge`: the pieces of a tiled render assembled into the whole image, a band of rows at
// a time, pixel for pixel what a single render writes.

#include <string>
#include <vector>

#include "tile/tile_stamp.h"

namespace hexray {

// Checks that `pieces` are the N tiles of one image (the same stamp but for the index), each
// exactly once, each in `output`'s format (PNG or OpenEXR) and of its stamp's size; then writes
// the image to `output` (atomically, see io/output_file.h). Throws TileError naming the piece
// that does not fit, or the tile that is missing, before `output` is opened. Returns the stamp
// of the first tile.
TileStamp mergeTiles(const std::string& output, const std::vector<std::string>& pieces);

}  // namespace hexray
