#include "tile/tile_stamp.h"

#include <algorithm>
#include <cstdio>

#include "gpu/stable_hash.h"

namespace hexray {
namespace {

// What sceneTextIdentity writes: 16 hex digits, '/', a decimal size.
bool isSceneIdentity(const std::string& text) {
    const auto hex = [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); };
    const auto digit = [](char c) { return c >= '0' && c <= '9'; };
    return text.size() > 17 && std::all_of(text.begin(), text.begin() + 16, hex) && text[16] == '/' &&
           std::all_of(text.begin() + 17, text.end(), digit);
}

}  // namespace

bool TileStamp::sameImage(const TileStamp& other) const {
    return tile.count == other.tile.count && width == other.width && height == other.height &&
           samplesPerPixel == other.samplesPerPixel && renderer == other.renderer && scene == other.scene;
}

std::string formatTileStamp(const TileStamp& stamp) {
    const RowRange rows = stamp.rows();
    char head[160];
    std::snprintf(head, sizeof head, "%u/%u rows %u-%u of %ux%u; spp %u; ", stamp.tile.index, stamp.tile.count,
                  rows.first, rows.end() - 1, stamp.width, stamp.height, stamp.samplesPerPixel);
    return head + stamp.renderer + "; scene " + stamp.scene;
}

std::optional<TileStamp> parseTileStamp(const std::string& text) {
    TileStamp stamp;
    unsigned first = 0;
    unsigned last = 0;
    int rendererStart = -1;
    const int read = std::sscanf(text.c_str(), "%u/%u rows %u-%u of %ux%u; spp %u; %n", &stamp.tile.index,
                                 &stamp.tile.count, &first, &last, &stamp.width, &stamp.height,
                                 &stamp.samplesPerPixel, &rendererStart);
    const std::size_t sceneAt = text.rfind("; scene ");
    if (read != 7 || rendererStart < 0 || sceneAt == std::string::npos || sceneAt < std::size_t(rendererStart) ||
        stamp.tile.count == 0 || stamp.tile.index >= stamp.tile.count || stamp.tile.count > stamp.height) {
        return std::nullopt;
    }
    stamp.renderer = text.substr(std::size_t(rendererStart), sceneAt - std::size_t(rendererStart));
    stamp.scene = text.substr(sceneAt + 8);
    if (!isSceneIdentity(stamp.scene)) {
        return std::nullopt;
    }
    // Strict: anything formatTileStamp would not write (other rows, extra text) is not a stamp.
    if (formatTileStamp(stamp) != text) {
        return std::nullopt;
    }
    return stamp;
}

std::string sceneTextIdentity(std::string_view text) {
    StableHash hash;
    hash.add(text);
    return hash.hex() + "/" + std::to_string(text.size());
}

}  // namespace hexray
