#pragma once
// An image file read whole, whichever of hexray's formats it is: a PNG (as 8-bit RGB) or a float
// OpenEXR (its R, G and B channels), told apart by their first bytes rather than by a name, so
// that standard input reads as well as a file. For `hexray diff`.

#include "image/image.h"
#include "image/image_format.h"
#include "image/image_io.h"
#include "io/read_only_file.h"

namespace hexray::inline image {

struct ImageFile {
    ImageFormat format = ImageFormat::Png;
    Rgb8Image encoded;  // a PNG's pixels
    Image linear;       // an OpenEXR file's pixels
    std::uint32_t width() const { return format == ImageFormat::Png ? encoded.width : linear.width; }
    std::uint32_t height() const { return format == ImageFormat::Png ? encoded.height : linear.height; }
};

// Throws ImageIoError naming the file when it is neither format, is damaged, or is larger than
// hexray renders (kMaxImageDimension a side); InputError when it cannot be read at all.
ImageFile readImageFile(const ReadOnlyFile& file);

}  // namespace hexray::image
