#include "strip/strip_piece.h"

#include <optional>
#include <stdexcept>
#include <utility>

#include "image/exr_rgb_row_reader.h"
#include "image/image_io.h"
#include "image/pixel_digest.h"
#include "image/png_row_reader.h"
#include "util/printable.h"

namespace hexray::inline strip {
namespace {

// What a piece's header says about it.
struct PieceHeader {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::optional<std::string> stamp;
};

// Runs `call`, turning a reader's failure (whose message names the file) into a StripError.
template <class Call>
decltype(auto) refusingBadInput(Call&& call) {
    try {
        return call();
    } catch (const ImageIoError& error) {
        throw StripError(printable(error.what()));
    } catch (const InputError& error) {
        throw StripError(printable(error.what()));
    }
}

std::string rowsText(const StripStamp& stamp) {
    const RowRange rows = stamp.rows();
    return "rows " + std::to_string(rows.first) + "-" + std::to_string(rows.end() - 1);
}

// The stamp in `header`, checked: well formed, within the renderer's limits, and of the header's size.
StripStamp checkedStamp(const std::string& name, const PieceHeader& header) {
    if (!header.stamp) {
        throw StripError(printable(name) + ": not a piece of a render in strips (no " + kStripStampKey +
                         " stamp: render pieces with --strip I/N)");
    }
    const std::optional<StripStamp> stamp = parseStripStamp(*header.stamp);
    if (!stamp) {
        throw StripError(printable(name) + ": its " + kStripStampKey + " stamp is damaged (\"" +
                         printable(*header.stamp) + "\")");
    }
    if (const std::optional<std::string> problem = beyondRendererLimits(*stamp)) {
        throw StripError(printable(name) + ": " + *problem);
    }
    if (header.width != stamp->width || header.height != stamp->rows().count) {
        throw StripError(printable(name) + ": " + std::to_string(header.width) + "x" + std::to_string(header.height) +
                         " pixels, but its stamp says " + rowsText(*stamp) + " of " + std::to_string(stamp->width) +
                         "x" + std::to_string(stamp->height));
    }
    return *stamp;
}

}  // namespace

struct StripPiece::Reading {
    std::unique_ptr<PngRowReader> png;
    std::unique_ptr<ExrRgbRowReader> exr;
    PixelDigest digest;
    std::uint32_t rowsLeft = 0;

    Reading(const ReadOnlyFile& file, ImageFormat format, const std::string& stampText, std::uint32_t rows)
        : digest(stampText), rowsLeft(rows) {
        if (format == ImageFormat::Png) {
            png = std::make_unique<PngRowReader>(file);
        } else {
            exr = std::make_unique<ExrRgbRowReader>(file);
        }
    }

    PieceHeader header() const {
        if (png) {
            return {png->width(), png->height(), png->text(kStripStampKey)};
        }
        return {exr->width(), exr->height(), exr->stringAttribute(kStripStampKey)};
    }
};

StripPiece::StripPiece(ReadOnlyFile file, ImageFormat format) : file_(std::move(file)), format_(format) {
    // The reader lives only for the check: thousands of pieces may wait open to be read.
    const PieceHeader header = refusingBadInput([&] { return Reading(file_, format_, "", 0).header(); });
    stamp_ = checkedStamp(name(), header);
    stampText_ = *header.stamp;
}

StripPiece::~StripPiece() = default;
StripPiece::StripPiece(StripPiece&&) noexcept = default;
StripPiece& StripPiece::operator=(StripPiece&&) noexcept = default;

StripPiece::Reading& StripPiece::reading() {
    if (!reading_) {
        reading_ = refusingBadInput([&] { return std::make_unique<Reading>(file_, format_, stampText_, rowCount()); });
        const PieceHeader header = refusingBadInput([&] { return reading_->header(); });
        if (header.stamp != stampText_ || header.width != stamp_.width || header.height != rowCount()) {
            throw StripError(printable(name()) + ": changed while being merged (its header is not the one checked)");
        }
    }
    return *reading_;
}

void StripPiece::readRgb8Rows(std::span<std::uint8_t> rgbRows) {
    Reading& r = reading();
    const std::size_t rowBytes = std::size_t(stamp_.width) * 3;
    if (!r.png || rgbRows.size() % rowBytes != 0 || rgbRows.size() / rowBytes > r.rowsLeft) {
        throw std::logic_error("StripPiece::readRgb8Rows: not a PNG piece, or not whole rows it has left");
    }
    refusingBadInput([&] { r.png->readRows(rgbRows); });
    r.digest.addRgb8Rows(rgbRows);
    r.rowsLeft -= std::uint32_t(rgbRows.size() / rowBytes);
}

void StripPiece::readFloatRows(std::uint32_t rows, std::span<float> red, std::span<float> green,
                               std::span<float> blue) {
    Reading& r = reading();
    if (!r.exr || rows > r.rowsLeft) {
        throw std::logic_error("StripPiece::readFloatRows: not an OpenEXR piece, or more rows than it has left");
    }
    refusingBadInput([&] { r.exr->readRows(rows, red, green, blue); });
    r.digest.addFloatRows(red, green, blue);
    r.rowsLeft -= rows;
}

void StripPiece::verify() {
    Reading& r = reading();
    if (r.rowsLeft != 0) {
        throw std::logic_error("StripPiece::verify: rows left unread");
    }
    const std::optional<std::string> recorded = refusingBadInput(
        [&] { return r.png ? r.png->textAfterPixels(kStripDigestKey) : r.exr->stringAttribute(kStripDigestKey); });
    if (!recorded) {
        throw StripError(printable(name()) + ": no " + kStripDigestKey + " checksum " +
                         (r.png ? "after its pixels" : "in its header") +
                         " (a piece of an older hexray, or cut short): render it again");
    }
    if (*recorded != r.digest.hex()) {
        throw StripError(printable(name()) +
                         ": its pixels are not the ones it was rendered with (their SHA-256 is not the " +
                         kStripDigestKey + " it records): it was changed or damaged; render it again");
    }
    reading_.reset();
}

}  // namespace hexray::strip
