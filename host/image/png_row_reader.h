#pragma once
// Reads a PNG row by row (through libspng), as 8-bit RGB, with its text chunks before and after
// the pixels: the pieces that `hexray merge` assembles, never whole in memory. It reads from an
// open file (io/read_only_file.h) and sizes nothing from the file before the caller has seen its
// header: the row buffers only once rows are asked for, ancillary chunks within fixed limits.
// Every colour type and bit depth libspng decodes becomes 8-bit RGB (grey repeated, a palette
// looked up, alpha dropped, 16 bits to their high byte); an interlaced PNG is refused by name,
// since its rows come in seven passes and could not be read in order.

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "io/read_only_file.h"

namespace hexray::inline image {

class PngRowReader {
public:
    // Reads the header and the chunks before the pixels. Throws ImageIoError naming the file when
    // it is not a PNG, is damaged, or is interlaced. `file` must outlive the reader.
    explicit PngRowReader(const ReadOnlyFile& file);
    ~PngRowReader();
    PngRowReader(const PngRowReader&) = delete;
    PngRowReader& operator=(const PngRowReader&) = delete;

    std::uint32_t width() const { return width_; }
    std::uint32_t height() const { return height_; }

    // The text of the text chunk `key` before the pixels. Throws ImageIoError when there are two.
    std::optional<std::string> text(const std::string& key) const;

    // The next rows.size() / (3 * width) rows, 3 bytes a pixel. Throws ImageIoError naming the
    // file when it is damaged or has fewer rows left.
    void readRows(std::span<std::uint8_t> rgbRows);

    // Once every row is read: the text of the text chunk `key` after the pixels, read with the
    // rest of the file. Throws ImageIoError when the file is damaged there or has two.
    std::optional<std::string> textAfterPixels(const std::string& key);

private:
    struct Decoder;
    std::unique_ptr<Decoder> decoder_;
    std::uint32_t width_ = 0;
    std::uint32_t height_ = 0;
};

}  // namespace hexray::image
