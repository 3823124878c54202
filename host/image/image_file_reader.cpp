#include "image/image_file_reader.h"

#include <array>
#include <cstddef>
#include <cstring>
#include <string>

#include "image/exr_rgb_row_reader.h"
#include "image/png_row_reader.h"
#include "scene/scene.h"

namespace hexray::inline image {

namespace {

constexpr std::array<unsigned char, 8> kPngSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
constexpr std::array<unsigned char, 4> kExrMagic = {0x76, 0x2f, 0x31, 0x01};

bool startsWith(const std::array<std::byte, 8>& head, std::size_t length, const unsigned char* magic,
                std::size_t magicLength) {
    return length >= magicLength && std::memcmp(head.data(), magic, magicLength) == 0;
}

void checkSize(const ReadOnlyFile& file, std::uint32_t width, std::uint32_t height) {
    if (width == 0 || height == 0 || width > kMaxImageDimension || height > kMaxImageDimension) {
        throw ImageIoError(file.name() + ": " + std::to_string(width) + "x" + std::to_string(height) +
                           " pixels: hexray reads images of 1 to " + std::to_string(kMaxImageDimension) +
                           " pixels a side");
    }
}

Rgb8Image readPngFile(const ReadOnlyFile& file) {
    PngRowReader reader(file);
    checkSize(file, reader.width(), reader.height());
    Rgb8Image image{reader.width(), reader.height(), {}};
    image.bytes.resize(std::size_t(image.width) * image.height * 3);
    reader.readRows(image.bytes);
    return image;
}

Image readExrFile(const ReadOnlyFile& file) {
    ExrRgbRowReader reader(file);
    checkSize(file, reader.width(), reader.height());
    const std::size_t pixels = std::size_t(reader.width()) * reader.height();
    std::vector<float> red(pixels), green(pixels), blue(pixels);
    reader.readRows(reader.height(), red, green, blue);
    Image image(reader.width(), reader.height());
    for (std::size_t i = 0; i < pixels; ++i) {
        image.pixels[i] = {red[i], green[i], blue[i]};
    }
    return image;
}

}  // namespace

ImageFile readImageFile(const ReadOnlyFile& file) {
    std::array<std::byte, 8> head{};
    const std::size_t length = file.readAt(0, head);
    ImageFile image;
    if (startsWith(head, length, kPngSignature.data(), kPngSignature.size())) {
        image.format = ImageFormat::Png;
        image.encoded = readPngFile(file);
    } else if (startsWith(head, length, kExrMagic.data(), kExrMagic.size())) {
        image.format = ImageFormat::Exr;
        image.linear = readExrFile(file);
    } else {
        throw ImageIoError(file.name() + ": neither a PNG nor an OpenEXR file");
    }
    return image;
}

}  // namespace hexray::image
