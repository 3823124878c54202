#pragma once
// Reads the R, G, B channels of a float OpenEXR file a band of rows at a time, in order, from an
// open file (io/read_only_file.h): the pieces that `hexray merge` assembles, written elsewhere.
// It reads through OpenEXRCore, which checks every size in the header against the file's size
// and the image against the largest hexray renders before allocating from them (ExrRowReader,
// OpenEXR's C++ interface, reads the files hexray has just written itself). It reads what hexray
// writes and lossless re-saves of it: one part of scanlines, uncompressed or compressed with RLE
// or ZIP, channels R, G and B of 32-bit floats among at most kMaxExrChannels, each with a value
// for every pixel; anything else is refused by name.

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "io/read_only_file.h"

namespace hexray::inline image {

inline constexpr int kMaxExrChannels = 8;

class ExrRgbRowReader {
public:
    // Reads the header. Throws ImageIoError naming the file when it cannot be read as such an
    // OpenEXR file, or is larger than hexray renders. `file` must outlive the reader.
    explicit ExrRgbRowReader(const ReadOnlyFile& file);
    ~ExrRgbRowReader();
    ExrRgbRowReader(const ExrRgbRowReader&) = delete;
    ExrRgbRowReader& operator=(const ExrRgbRowReader&) = delete;

    std::uint32_t width() const { return width_; }
    std::uint32_t height() const { return height_; }

    // The header's string attribute `name`.
    std::optional<std::string> stringAttribute(const std::string& name) const;

    // The next `rows` rows, one plane a channel (rows x width values each). Throws ImageIoError
    // naming the file when it is damaged or has fewer rows left.
    void readRows(std::uint32_t rows, std::span<float> red, std::span<float> green, std::span<float> blue);

private:
    struct Decoder;
    std::unique_ptr<Decoder> decoder_;
    std::uint32_t width_ = 0;
    std::uint32_t height_ = 0;
};

}  // namespace hexray::image
