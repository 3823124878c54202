#include "strip/strip_merge.h"

#include <algorithm>
#include <optional>

#include "image/exr_row_writer.h"
#include "image/image_io.h"
#include "io/open_file_limit.h"
#include "strip/strip_provenance.h"
#include "util/printable.h"

namespace hexray::inline strip {
namespace {

// Rows copied at a time: memory grows with the width only.
constexpr std::uint32_t kRowsAtATime = 64;

// Descriptors a merge needs besides its pieces: standard streams, the output and its directory,
// and the libraries'.
constexpr std::uint64_t kSpareDescriptors = 16;

const std::vector<std::string> kExrChannels = {"R", "G", "B"};

std::string formatName(ImageFormat format) {
    return format == ImageFormat::Exr ? "OpenEXR" : "PNG";
}

std::string stripText(const StripStamp& stamp) {
    const RowRange rows = stamp.rows();
    return "strip " + std::to_string(stamp.strip.index) + "/" + std::to_string(stamp.strip.count) + ", rows " +
           std::to_string(rows.first) + "-" + std::to_string(rows.end() - 1);
}

// How `piece` differs from `first`, a strip of the image being merged.
std::string differences(const StripStamp& piece, const StripStamp& first) {
    std::vector<std::string> parts;
    const auto compare = [&](bool same, const std::string& what, const std::string& mine, const std::string& theirs) {
        if (!same)
            parts.push_back(what + " " + mine + " (not " + theirs + ")");
    };
    const auto size = [](const StripStamp& s) { return std::to_string(s.width) + "x" + std::to_string(s.height); };
    compare(piece.strip.count == first.strip.count, "strip count", std::to_string(piece.strip.count),
            std::to_string(first.strip.count));
    compare(piece.width == first.width && piece.height == first.height, "image", size(piece), size(first));
    compare(piece.samplesPerPixel == first.samplesPerPixel, "spp", std::to_string(piece.samplesPerPixel),
            std::to_string(first.samplesPerPixel));
    compare(piece.renderer == first.renderer, "renderer", piece.renderer, first.renderer);
    compare(piece.scene == first.scene, "scene file", piece.scene, first.scene);
    std::string text;
    for (const std::string& part : parts)
        text += (text.empty() ? "" : ", ") + part;
    return text;
}

// Every piece stays open from its check to its copy.
void ensureDescriptorsFor(std::size_t pieces) {
    const std::uint64_t needed = pieces + kSpareDescriptors;
    const std::uint64_t limit = raiseOpenFileLimit(needed);
    if (limit < needed) {
        throw StripError(std::to_string(pieces) + " pieces, but this process may have only " + std::to_string(limit) +
                         " files open (ulimit -n), and merge holds every piece open: raise the limit to at least " +
                         std::to_string(needed));
    }
}

StripPiece openPiece(const std::string& path, ImageFormat format) {
    if (imageFormatFor(path) != format) {
        throw StripError(printable(path) + ": not a " + formatName(format) + " file (" + extensionOf(format) +
                         "), as the merged image is");
    }
    try {
        return StripPiece(ReadOnlyFile(path), format);
    } catch (const InputError& error) {
        throw StripError(printable(error.what()));
    }
}

void mergePngs(const std::string& output, std::vector<StripPiece>& strips) {
    const StripStamp& stamp = strips.front().stamp();
    PngRowWriter writer(output, stamp.width, stamp.height, mergedProvenance(stamp).notes());
    std::vector<std::uint8_t> rows;
    for (StripPiece& piece : strips) {
        for (std::uint32_t done = 0; done < piece.rowCount(); done += kRowsAtATime) {
            rows.resize(std::size_t(std::min(kRowsAtATime, piece.rowCount() - done)) * stamp.width * 3);
            piece.readRgb8Rows(rows);
            writer.writeRows(rows);
        }
        piece.verify();
    }
    writer.finish();
}

void mergeExrs(const std::string& output, std::vector<StripPiece>& strips) {
    const StripStamp& stamp = strips.front().stamp();
    ExrRowWriter writer(output, stamp.width, stamp.height, kExrChannels, mergedProvenance(stamp).notes());
    std::vector<float> red, green, blue;
    for (StripPiece& piece : strips) {
        for (std::uint32_t done = 0; done < piece.rowCount(); done += kRowsAtATime) {
            const std::uint32_t rows = std::min(kRowsAtATime, piece.rowCount() - done);
            for (std::vector<float>* channel : {&red, &green, &blue}) {
                channel->resize(std::size_t(rows) * stamp.width);
            }
            piece.readFloatRows(rows, red, green, blue);
            writer.writeRows(rows, {red, green, blue});
        }
        piece.verify();
    }
    writer.finish();
}

}  // namespace

std::vector<StripPiece> openPieces(const std::vector<std::string>& paths, ImageFormat format) {
    ensureDescriptorsFor(paths.size());
    std::vector<std::optional<StripPiece>> slots;  // sized from a stamp within the renderer's limits
    std::optional<StripStamp> first;
    std::string firstPath;
    for (const std::string& path : paths) {
        StripPiece piece = openPiece(path, format);
        if (!first) {
            first = piece.stamp();
            firstPath = path;
            slots.resize(first->strip.count);
        }
        if (piece.stamp().version != first->version) {
            throw StripError(printable(path) + ": rendered by hexray " + printable(piece.stamp().version) + ", but " +
                             printable(firstPath) + " by hexray " + printable(first->version) +
                             ": pieces of two builds are not merged (another build may render other pixels); "
                             "render them again with one");
        }
        if (!piece.stamp().sameImage(*first)) {
            throw StripError(printable(path) + ": a strip of another image than " + printable(firstPath) + ": " +
                             printable(differences(piece.stamp(), *first)));
        }
        std::optional<StripPiece>& slot = slots[piece.stamp().strip.index];
        if (slot && slot->name() == path) {
            throw StripError(printable(path) + ": given twice");
        }
        if (slot) {
            throw StripError(printable(path) + ": overlaps " + printable(slot->name()) + " (both are " +
                             stripText(piece.stamp()) + ")");
        }
        slot = std::move(piece);
    }
    std::vector<StripPiece> ordered;
    for (std::uint32_t index = 0; index < slots.size(); ++index) {
        if (!slots[index]) {
            StripStamp missing = *first;
            missing.strip.index = index;
            throw StripError("missing " + stripText(missing) + " of the image " + printable(firstPath) + " belongs to");
        }
        ordered.push_back(std::move(*slots[index]));
    }
    return ordered;
}

void mergePieces(const std::string& output, std::vector<StripPiece>& strips) {
    if (strips.empty()) {
        throw StripError("no pieces to merge");
    }
    if (imageFormatFor(output) != strips.front().format()) {
        throw StripError(printable(output) + ": not a " + formatName(strips.front().format()) + " file (" +
                         extensionOf(strips.front().format()) + "), as the pieces are");
    }
    try {
        if (strips.front().format() == ImageFormat::Exr) {
            mergeExrs(output, strips);
        } else {
            mergePngs(output, strips);
        }
    } catch (const ImageIoError& error) {
        throw StripError(printable(error.what()));  // a piece damaged past its header
    }
}

StripStamp mergeStrips(const std::string& output, const std::vector<std::string>& paths) {
    const std::optional<ImageFormat> format = imageFormatFor(output);
    if (!format) {
        throw StripError(printable(output) + ": unknown image format (supported: " + kSupportedImageFormats + ")");
    }
    std::vector<StripPiece> strips = openPieces(paths, *format);
    mergePieces(output, strips);
    return strips.front().stamp();
}

}  // namespace hexray::strip
