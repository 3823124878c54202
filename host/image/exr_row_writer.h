#pragma once
// Writes a float OpenEXR file (32-bit channels, ZIP-compressed scanlines, through OpenEXR) a band
// of rows at a time, so an image need never be whole in memory. The file is an OutputFile
// (io/output_file.h): it appears at its path only when finish() succeeds. The format's offset
// table is written last, by seeking back: where the output cannot seek (standard output, a pipe,
// a FIFO, a terminal, a device), the file is written to an unnamed scratch file
// (io/anonymous_file.h) and its bytes streamed to the output by finish(). The header, and so
// every note, comes before the pixels; a text known only at the end (a digest of the pixels) is
// given a placeholder of its length, replaced by finish() in place.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "image/image_io.h"

namespace hexray::inline image {

class ExrRowWriter {
public:
    // Throws OutputError when the file cannot be created. `notes` become string attributes.
    ExrRowWriter(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                 const std::vector<std::string>& channelNames, const std::vector<ImageNote>& notes = {});
    ~ExrRowWriter();
    ExrRowWriter(const ExrRowWriter&) = delete;
    ExrRowWriter& operator=(const ExrRowWriter&) = delete;

    // The next `rows` rows: one span of rows × width values per channel, in the order the
    // channels were named. Throws OutputError on a write failure.
    void writeRows(std::uint32_t rows, const std::vector<std::span<const float>>& channels);
    // Throws OutputError unless every row was written and the file is in place. `replacements`:
    // new texts for notes given to the constructor, each of the same length as the old.
    void finish(const std::vector<ImageNote>& replacements = {});

private:
    struct Encoder;
    std::unique_ptr<Encoder> encoder_;
};

}  // namespace hexray::image
