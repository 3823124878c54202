#pragma once
// One piece of a render in strips as `hexray merge` reads it. Its file is opened once, and everything
// is read from that descriptor: a piece renamed or replaced at its path meanwhile is the piece
// that was checked. Opening reads its header and stamp and checks them against each other and
// against the renderer's limits, before anything is sized from them, and keeps only the stamp;
// reading its rows later reads the header again from the same file, checks it is unchanged, and
// hashes every row; verify() then compares the hash with the digest the piece records, which
// covers the stamp and the pixels (strip_stamp.h). A piece that fails any of these is refused with
// a StripError naming it.

#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "image/image_format.h"
#include "io/read_only_file.h"
#include "strip/strip_stamp.h"

namespace hexray::inline strip {

class StripPiece {
public:
    // Checks `file` as a piece in `format`. Throws StripError naming it.
    StripPiece(ReadOnlyFile file, ImageFormat format);
    ~StripPiece();
    StripPiece(StripPiece&&) noexcept;
    StripPiece& operator=(StripPiece&&) noexcept;

    const std::string& name() const { return file_.name(); }
    ImageFormat format() const { return format_; }
    const StripStamp& stamp() const { return stamp_; }
    std::uint32_t rowCount() const { return stamp_.rows().count; }

    // The next rows of a PNG piece, 3 bytes a pixel.
    void readRgb8Rows(std::span<std::uint8_t> rgbRows);
    // The next `rows` rows of an OpenEXR piece, one plane a channel.
    void readFloatRows(std::uint32_t rows, std::span<float> red, std::span<float> green, std::span<float> blue);
    // Once every row is read: throws StripError unless they and the stamp are what the piece's
    // digest says. Releases the decoder.
    void verify();

private:
    struct Reading;
    Reading& reading();

    ReadOnlyFile file_;
    ImageFormat format_;
    std::string stampText_;
    StripStamp stamp_;
    std::unique_ptr<Reading> reading_;
};

}  // namespace hexray::strip
