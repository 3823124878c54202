#pragma once
// An image file written a band of rows at a time in either output format (image_format.h): an
// 8-bit PNG (PngRowWriter) or a linear float OpenEXR with channels R, G, B (ExrRowWriter). Like
// them, it appears at its path only when finish() succeeds.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <vector>

#include "image/exr_row_writer.h"
#include "image/image.h"
#include "image/image_format.h"
#include "image/image_io.h"

namespace hexray {

class ImageRowWriter {
public:
    // `encoding`: how linear rows become a PNG's 8 bits. Throws OutputError.
    ImageRowWriter(const std::filesystem::path& path, ImageFormat format, std::uint32_t width, std::uint32_t height,
                   Encoding encoding, const std::vector<ImageNote>& notes = {});

    // Whether the format keeps linear colour (OpenEXR): then only writeLinear may be used.
    bool wantsLinear() const { return exr_.has_value(); }

    void writeEncoded(std::span<const std::uint8_t> rgbRows);  // PNG only: whole rows, 3 bytes a pixel
    void writeLinear(const Image& rows);                       // the next rows.height rows
    void finish();

private:
    Encoding encoding_;
    std::optional<PngRowWriter> png_;
    std::optional<ExrRowWriter> exr_;
    std::vector<float> red_, green_, blue_;  // one band's channels, reused
};

}  // namespace hexray
