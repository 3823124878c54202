#include "image/image_format.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "io/standard_output.h"

namespace hexray::inline image {

std::optional<ImageFormat> imageFormatFor(const std::string& path) {
    // The extension the user wrote decides, wherever the path leads: standard output included.
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".png") {
        return ImageFormat::Png;
    }
    if (extension == ".exr") {
        return ImageFormat::Exr;
    }
    if (!extension.empty()) {
        return std::nullopt;
    }
    struct stat status {};
    const bool device = ::stat(path.c_str(), &status) == 0 && !S_ISREG(status.st_mode) && !S_ISDIR(status.st_mode);
    if (device || namesStandardOutput(path)) {
        return ImageFormat::Png;
    }
    return std::nullopt;
}

const char* extensionOf(ImageFormat format) {
    return format == ImageFormat::Exr ? ".exr" : ".png";
}

}  // namespace hexray::image
