#pragma once
// Which file format an output path asks for, by its extension.

#include <optional>
#include <string>

namespace hexray::inline image {

enum class ImageFormat {
    Png,  // 8-bit RGB, encoded as the scene says (sRGB or linear)
    Exr,  // 32-bit float linear RGB, before any encoding or clamping
};

// For messages: what imageFormatFor accepts.
inline constexpr const char* kSupportedImageFormats =
    ".png (8-bit), .exr (linear float RGB), or - (PNG on standard output)";

// .png or .exr (in any case), wherever the path leads (standard output, a FIFO); a path without
// an extension that is "-", standard output (/dev/stdout) or not a regular file (/dev/null, a
// FIFO) is PNG. nullopt for anything else.
std::optional<ImageFormat> imageFormatFor(const std::string& path);

// ".png" or ".exr".
const char* extensionOf(ImageFormat format);

}  // namespace hexray::image
