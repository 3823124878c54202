#pragma once
// Turning linear images into 8-bit pixels and PNG files, and reading PNGs back (for goldens).

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/image.h"
#include "scene/scene.h"

namespace hexray::inline image {

class ImageIoError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// 8-bit RGB, row-major, 3 bytes per pixel.
struct Rgb8Image {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<std::uint8_t> bytes;
};

// Clamps to [0, 1], applies the transfer function (sRGB or none) and rounds to the nearest level.
std::uint8_t encodeChannel(float linear, Encoding encoding);
Rgb8Image encodeImage(const Image& image, Encoding encoding);

// A key and a text recorded in an image file: a PNG tEXt chunk (Latin-1, key at most 79 bytes),
// an OpenEXR string attribute.
struct ImageNote {
    std::string key;
    std::string text;
};

// Writes a PNG row by row, so an image need never be whole in memory, to an OutputFile (see
// io/output_file.h): a regular file appears at `path` only when finish() succeeds; a writer
// destroyed without finish(), or a catchable signal meanwhile, leaves no partial or clobbered
// image. "-" is standard output. Throws OutputError when the file cannot be written, and
// std::bad_alloc when the encoder runs out of memory. `notes` go before the pixels, the closing
// notes given to finish() after them.
class PngRowWriter {
public:
    PngRowWriter(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                 const std::vector<ImageNote>& notes = {});
    ~PngRowWriter();
    PngRowWriter(const PngRowWriter&) = delete;
    PngRowWriter& operator=(const PngRowWriter&) = delete;

    void writeRows(std::span<const std::uint8_t> rgbRows);  // whole rows, 3 bytes per pixel
    // `closingNotes`: text chunks after the pixels, for what is known only once they are written.
    void finish(const std::vector<ImageNote>& closingNotes = {});

private:
    struct Encoder;
    std::unique_ptr<Encoder> encoder_;
};

// The whole image through a PngRowWriter.
void writePng(const std::filesystem::path& path, const Rgb8Image& image);

Rgb8Image readPng(const std::filesystem::path& path);

}  // namespace hexray::image
