#include "tile/tile_merge.h"

#include <algorithm>
#include <optional>

#include "image/exr_row_reader.h"
#include "image/exr_row_writer.h"
#include "image/image_format.h"
#include "image/image_io.h"
#include "image/png_row_reader.h"
#include "util/printable.h"

namespace hexray {
namespace {

// Rows copied at a time: memory grows with the width only.
constexpr std::uint32_t kRowsAtATime = 64;

const std::vector<std::string> kExrChannels = {"R", "G", "B"};

struct Piece {
    std::string path;
    TileStamp stamp;
};

std::string formatName(ImageFormat format) {
    return format == ImageFormat::Exr ? "OpenEXR" : "PNG";
}

std::string rowsText(const TileStamp& stamp) {
    const RowRange rows = stamp.rows();
    return "rows " + std::to_string(rows.first) + "-" + std::to_string(rows.end() - 1);
}

std::string tileText(const TileStamp& stamp) {
    return "tile " + std::to_string(stamp.tile.index) + "/" + std::to_string(stamp.tile.count) + ", " +
           rowsText(stamp);
}

// What the piece's file says about itself, and its size, checked against each other.
Piece readPiece(const std::string& path, ImageFormat format) {
    const std::optional<ImageFormat> pieceFormat = imageFormatFor(path);
    if (pieceFormat != format) {
        throw TileError(printable(path) + ": not a " + formatName(format) + " file (" + extensionOf(format) +
                        "), as the merged image is");
    }
    std::optional<std::string> text;
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    try {
        if (format == ImageFormat::Png) {
            const PngRowReader reader(path);
            text = reader.text(kTileStampKey);
            width = reader.width();
            height = reader.height();
        } else {
            const ExrRowReader reader(path);
            const std::vector<std::string> channels = reader.channelNames();
            for (const std::string& channel : kExrChannels) {
                if (std::find(channels.begin(), channels.end(), channel) == channels.end()) {
                    throw TileError(printable(path) + ": not an image hexray wrote (no channel " + channel + ")");
                }
            }
            text = reader.stringAttribute(kTileStampKey);
            width = reader.width();
            height = reader.height();
        }
    } catch (const ImageIoError& error) {
        throw TileError(printable(error.what()));
    }
    if (!text) {
        throw TileError(printable(path) + ": not a piece of a tiled render (no " + kTileStampKey +
                        " stamp: render pieces with --tile I/N)");
    }
    const std::optional<TileStamp> stamp = parseTileStamp(*text);
    if (!stamp) {
        throw TileError(printable(path) + ": its " + kTileStampKey + " stamp is damaged (\"" + printable(*text) +
                        "\")");
    }
    if (width != stamp->width || height != stamp->rows().count) {
        throw TileError(printable(path) + ": " + std::to_string(width) + "x" + std::to_string(height) +
                        " pixels, but its stamp says " + rowsText(*stamp) + " of " + std::to_string(stamp->width) +
                        "x" + std::to_string(stamp->height));
    }
    return {path, *stamp};
}

// How `piece` differs from `first`, a tile of the image being merged.
std::string differences(const TileStamp& piece, const TileStamp& first) {
    std::vector<std::string> parts;
    const auto compare = [&](bool same, const std::string& what, const std::string& mine, const std::string& theirs) {
        if (!same) parts.push_back(what + " " + mine + " (not " + theirs + ")");
    };
    const auto size = [](const TileStamp& s) { return std::to_string(s.width) + "x" + std::to_string(s.height); };
    compare(piece.tile.count == first.tile.count, "tile count", std::to_string(piece.tile.count),
            std::to_string(first.tile.count));
    compare(piece.width == first.width && piece.height == first.height, "image", size(piece), size(first));
    compare(piece.samplesPerPixel == first.samplesPerPixel, "spp", std::to_string(piece.samplesPerPixel),
            std::to_string(first.samplesPerPixel));
    compare(piece.renderer == first.renderer, "renderer", piece.renderer, first.renderer);
    compare(piece.scene == first.scene, "scene file", piece.scene, first.scene);
    std::string text;
    for (const std::string& part : parts) text += (text.empty() ? "" : ", ") + part;
    return text;
}

// The pieces in tile order, checked to be every tile of one image exactly once.
std::vector<Piece> tilesInOrder(const std::vector<std::string>& paths, ImageFormat format) {
    std::vector<std::optional<Piece>> slots;
    std::optional<Piece> first;
    for (const std::string& path : paths) {
        Piece piece = readPiece(path, format);
        if (!first) {
            first = piece;
            slots.resize(piece.stamp.tile.count);
        }
        if (!piece.stamp.sameImage(first->stamp)) {
            throw TileError(printable(path) + ": a tile of another image than " + printable(first->path) + ": " +
                            printable(differences(piece.stamp, first->stamp)));
        }
        std::optional<Piece>& slot = slots[piece.stamp.tile.index];
        if (slot && slot->path == path) {
            throw TileError(printable(path) + ": given twice");
        }
        if (slot) {
            throw TileError(printable(path) + ": overlaps " + printable(slot->path) + " (both are " +
                            tileText(piece.stamp) + ")");
        }
        slot = std::move(piece);
    }
    std::vector<Piece> ordered;
    for (std::uint32_t index = 0; index < slots.size(); ++index) {
        if (!slots[index]) {
            TileStamp missing = first->stamp;
            missing.tile.index = index;
            throw TileError("missing " + tileText(missing) + " of the image " + printable(first->path) + " belongs to");
        }
        ordered.push_back(*slots[index]);
    }
    return ordered;
}

void mergePngs(const std::string& output, const std::vector<Piece>& pieces) {
    const TileStamp& stamp = pieces.front().stamp;
    PngRowWriter writer(output, stamp.width, stamp.height);
    std::vector<std::uint8_t> rows;
    for (const Piece& piece : pieces) {
        PngRowReader reader(piece.path);
        for (std::uint32_t done = 0; done < reader.height(); done += kRowsAtATime) {
            rows.resize(std::size_t(std::min(kRowsAtATime, reader.height() - done)) * reader.width() * 3);
            reader.readRows(rows);
            writer.writeRows(rows);
        }
    }
    writer.finish();
}

void mergeExrs(const std::string& output, const std::vector<Piece>& pieces) {
    const TileStamp& stamp = pieces.front().stamp;
    ExrRowWriter writer(output, stamp.width, stamp.height, kExrChannels);
    std::vector<std::vector<float>> channels(kExrChannels.size());
    for (const Piece& piece : pieces) {
        ExrRowReader reader(piece.path);
        for (std::uint32_t done = 0; done < reader.height(); done += kRowsAtATime) {
            const std::uint32_t rows = std::min(kRowsAtATime, reader.height() - done);
            std::vector<std::span<const float>> spans;
            for (std::size_t c = 0; c < kExrChannels.size(); ++c) {
                channels[c].resize(std::size_t(rows) * reader.width());
                reader.readRows(kExrChannels[c], done, rows, channels[c]);
                spans.emplace_back(channels[c]);
            }
            writer.writeRows(rows, spans);
        }
    }
    writer.finish();
}

}  // namespace

TileStamp mergeTiles(const std::string& output, const std::vector<std::string>& pieces) {
    const std::optional<ImageFormat> format = imageFormatFor(output);
    if (!format) {
        throw TileError(printable(output) + ": unknown image format (supported: " + kSupportedImageFormats + ")");
    }
    const std::vector<Piece> ordered = tilesInOrder(pieces, *format);
    try {
        if (*format == ImageFormat::Png) {
            mergePngs(output, ordered);
        } else {
            mergeExrs(output, ordered);
        }
    } catch (const ImageIoError& error) {
        throw TileError(printable(error.what()));  // a piece damaged past its header
    }
    return ordered.front().stamp;
}

}  // namespace hexray
