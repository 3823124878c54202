#pragma once
// An image file written a band of rows at a time in either output format (image_format.h): an
// 8-bit PNG (PngRowWriter) or a linear float OpenEXR with channels R, G, B (ExrRowWriter). Like
// them, it appears at its path only when finish() succeeds.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "image/exr_row_writer.h"
#include "image/image.h"
#include "image/image_format.h"
#include "image/image_io.h"
#include "image/pixel_digest.h"
#include "image/provenance.h"

namespace hexray::inline image {

// A note whose text is the SHA-256 of the pixels as written (pixel_digest.h), hashed after
// `preamble`. It is known only once every row is written: a PNG has it in a text chunk after the
// pixels; an OpenEXR header, written first, has a placeholder of its length, replaced at finish.
struct DigestNote {
    std::string key;
    std::string preamble;
};

class ImageRowWriter {
public:
    // `encoding`: how linear rows become a PNG's 8 bits; `provenance` is recorded before `notes`.
    // Throws OutputError.
    ImageRowWriter(const std::filesystem::path& path, ImageFormat format, std::uint32_t width, std::uint32_t height,
                   Encoding encoding, const Provenance& provenance, const std::vector<ImageNote>& notes = {},
                   const std::optional<DigestNote>& digest = std::nullopt);

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
    std::optional<std::string> digestKey_;
    std::optional<PixelDigest> digest_;
};

}  // namespace hexray::image
