#pragma once
// Reads a PNG row by row (through libspng), as 8-bit RGB, with its text chunks: the pieces that
// `hexray merge` assembles, never whole in memory.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>

namespace hexray {

class PngRowReader {
public:
    // Throws ImageIoError naming the file when it cannot be opened or is not a PNG.
    explicit PngRowReader(const std::filesystem::path& path);
    ~PngRowReader();
    PngRowReader(const PngRowReader&) = delete;
    PngRowReader& operator=(const PngRowReader&) = delete;

    std::uint32_t width() const { return width_; }
    std::uint32_t height() const { return height_; }

    // The text of the tEXt chunk before the pixels whose keyword is `key`.
    std::optional<std::string> text(const std::string& key) const;

    // The next rows.size() / (3 * width) rows, 3 bytes a pixel. Throws ImageIoError naming the
    // file when it is damaged or has fewer rows left.
    void readRows(std::span<std::uint8_t> rgbRows);

private:
    struct Decoder;
    std::unique_ptr<Decoder> decoder_;
    std::uint32_t width_ = 0;
    std::uint32_t height_ = 0;
};

}  // namespace hexray
