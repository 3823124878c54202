#include "image/image_row_writer.h"

#include <stdexcept>

namespace hexray {

ImageRowWriter::ImageRowWriter(const std::filesystem::path& path, ImageFormat format, std::uint32_t width,
                               std::uint32_t height, Encoding encoding, const std::vector<ImageNote>& notes)
    : encoding_(encoding) {
    if (format == ImageFormat::Exr) {
        exr_.emplace(path, width, height, std::vector<std::string>{"R", "G", "B"}, notes);
    } else {
        png_.emplace(path, width, height, notes);
    }
}

void ImageRowWriter::writeEncoded(std::span<const std::uint8_t> rgbRows) {
    if (!png_) {
        throw std::logic_error("ImageRowWriter::writeEncoded: an OpenEXR file takes linear rows");
    }
    png_->writeRows(rgbRows);
}

void ImageRowWriter::writeLinear(const Image& rows) {
    if (png_) {
        png_->writeRows(encodeImage(rows, encoding_).bytes);
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
}

void ImageRowWriter::finish() {
    if (png_) {
        png_->finish();
    } else {
        exr_->finish();
    }
}

}  // namespace hexray
