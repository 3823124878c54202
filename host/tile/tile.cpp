#include "tile/tile.h"

#include <string>

namespace hexray {

RowRange tileRows(Tile tile, std::uint32_t height) {
    if (tile.count > height) {
        throw TileError("--tile " + std::to_string(tile.index) + "/" + std::to_string(tile.count) + ": the image has " +
                        std::to_string(height) + " rows, so at most " + std::to_string(height) + " tiles");
    }
    const auto boundary = [&](std::uint64_t index) { return std::uint32_t(index * height / tile.count); };
    const std::uint32_t first = boundary(tile.index);
    return RowRange{first, boundary(tile.index + 1) - first};
}

}  // namespace hexray
