#pragma once
// Turning linear images into 8-bit pixels and PNG files, and reading PNGs back (for goldens).

#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <vector>

#include "image/image.h"
#include "scene/scene.h"

namespace hexray {

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

// Writes atomically: a temporary file beside `path` is renamed over it only once complete, so
// a failure or an interruption never leaves a partial or clobbered image.
void writePng(const std::filesystem::path& path, const Rgb8Image& image);

Rgb8Image readPng(const std::filesystem::path& path);

}  // namespace hexray
