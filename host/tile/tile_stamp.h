#pragma once
// What a piece of a tiled render records about itself (a PNG text chunk or an OpenEXR string
// attribute named kTileStampKey), so that `hexray merge` can check that pieces make one image:
//   3/8 rows 180-239 of 640x480; spp 4; gpu f32 on llvmpipe (LLVM 15.0.6, 256 bits); scene 5f0c3e2a9b1d4c77/1187
// Pieces of one image have the same stamp but for the tile's index and rows.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "tile/tile.h"

namespace hexray {

inline constexpr const char* kTileStampKey = "hexray-tile";

struct TileStamp {
    Tile tile;
    std::uint32_t width = 0;  // the whole image's
    std::uint32_t height = 0;
    std::uint32_t samplesPerPixel = 1;
    std::string renderer;  // "gpu f32 on <device>" or "cpu reference": another renderer, other pixels
    std::string scene;     // the scene file's identity (sceneTextIdentity)

    RowRange rows() const { return tileRows(tile, height); }
    // Whether `other` is a tile of the same image (any index).
    bool sameImage(const TileStamp& other) const;
};

std::string formatTileStamp(const TileStamp& stamp);

// nullopt unless `text` is exactly what formatTileStamp writes for some stamp.
std::optional<TileStamp> parseTileStamp(const std::string& text);

// A scene file's text as "<64-bit FNV-1a in hex>/<size in bytes>".
std::string sceneTextIdentity(std::string_view text);

}  // namespace hexray
