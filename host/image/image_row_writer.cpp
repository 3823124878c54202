#include "image/image_row_writer.h"

#include <stdexcept>

namespace hexray::inline image {

namespace {

// What an OpenEXR header holds for the digest until finish(): not hex, so never taken for one.
const std::string kDigestPlaceholder(kPixelDigestHexLength, '-');

}  // namespace

ImageRowWriter::ImageRowWriter(const std::filesystem::path& path, ImageFormat format, std::uint32_t width,
                               std::uint32_t height, Encoding encoding, const Provenance& provenance,
                               const std::vector<ImageNote>& notes, const std::optional<DigestNote>& digest)
    : encoding_(encoding) {
    if (digest) {
        digestKey_ = digest->key;
        digest_.emplace(digest->preamble);
    }
    std::vector<ImageNote> headerNotes = provenance.notes();
    headerNotes.insert(headerNotes.end(), notes.begin(), notes.end());
    if (format == ImageFormat::Exr) {
        if (digest) {
            headerNotes.push_back({digest->key, kDigestPlaceholder});
        }
        exr_.emplace(path, width, height, std::vector<std::string>{"R", "G", "B"}, headerNotes);
    } else {
        png_.emplace(path, width, height, headerNotes);
    }
}

void ImageRowWriter::writeEncoded(std::span<const std::uint8_t> rgbRows) {
    if (!png_) {
        throw std::logic_error("ImageRowWriter::writeEncoded: an OpenEXR file takes linear rows");
    }
    png_->writeRows(rgbRows);
    if (digest_) {
        digest_->addRgb8Rows(rgbRows);
    }
}

void ImageRowWriter::writeLinear(const Image& rows) {
    if (png_) {
        writeEncoded(encodeImage(rows, encoding_).bytes);
        return;
    }
    red_.resize(rows.pixels.size());
    green_.resize(rows.pixels.size());
    blue_.resize(rows.pixels.size());
    for (std::size_t i = 0; i < rows.pixels.size(); ++i) {
        red_[i] = rows.pixels[i].r;
        green_[i] = rows.pixels[i].g;
        blue_[i] = rows.pixels[i].b;
    }
    exr_->writeRows(rows.height, {red_, green_, blue_});
    if (digest_) {
        digest_->addFloatRows(red_, green_, blue_);
    }
}

void ImageRowWriter::finish() {
    std::vector<ImageNote> digestNotes;
    if (digest_) {
        digestNotes.push_back({*digestKey_, digest_->hex()});
    }
    if (png_) {
        png_->finish(digestNotes);
    } else {
        exr_->finish(digestNotes);
    }
}

}  // namespace hexray::image
