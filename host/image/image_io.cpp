#include "image/image_io.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include <stb_image.h>
#include <stb_image_write.h>
#include <sys/stat.h>
#include <unistd.h>

namespace hexray {
namespace {

float srgbFromLinear(float linear) {
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

std::string systemError() {
    return std::strerror(errno);
}

// Removes the temporary file unless the rename succeeded.
struct TemporaryFile {
    std::string path;
    bool keep = false;
    ~TemporaryFile() {
        if (!keep) {
            ::unlink(path.c_str());
        }
    }
};

void writeAll(int fd, const std::vector<std::uint8_t>& data, const std::filesystem::path& target) {
    std::size_t written = 0;
    while (written < data.size()) {
        const ssize_t n = ::write(fd, data.data() + written, data.size() - written);
        if (n < 0) {
            if (errno == EINTR) {
                continue;
            }
            throw ImageIoError(target.string() + ": cannot write image: " + systemError());
        }
        written += std::size_t(n);
    }
}

}  // namespace

std::uint8_t encodeChannel(float linear, Encoding encoding) {
    const float clamped = std::isnan(linear) ? 0.0f : std::clamp(linear, 0.0f, 1.0f);
    const float encoded = encoding == Encoding::Srgb ? srgbFromLinear(clamped) : clamped;
    return std::uint8_t(std::lround(encoded * 255.0f));
}

Rgb8Image encodeImage(const Image& image, Encoding encoding) {
    Rgb8Image out{image.width, image.height, std::vector<std::uint8_t>(image.pixels.size() * 3)};
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            out.bytes[3 * i + c] = encodeChannel(image.pixels[i][c], encoding);
        }
    }
    return out;
}

void writePng(const std::filesystem::path& path, const Rgb8Image& image) {
    std::vector<std::uint8_t> png;
    const auto append = [](void* context, void* data, int size) {
        auto* bytes = static_cast<std::uint8_t*>(data);
        static_cast<std::vector<std::uint8_t>*>(context)->insert(
            static_cast<std::vector<std::uint8_t>*>(context)->end(), bytes, bytes + size);
    };
    if (!stbi_write_png_to_func(append, &png, int(image.width), int(image.height), 3, image.bytes.data(),
                                int(image.width * 3))) {
        throw ImageIoError(path.string() + ": cannot encode PNG");
    }

    const std::filesystem::path directory = path.has_parent_path() ? path.parent_path() : ".";
    TemporaryFile temporary{(directory / ("." + path.filename().string() + ".XXXXXX")).string()};
    const int fd = ::mkstemp(temporary.path.data());
    if (fd < 0) {
        temporary.keep = true;  // nothing was created
        throw ImageIoError(path.string() + ": cannot create output file: " + systemError());
    }
    try {
        writeAll(fd, png, path);
    } catch (...) {
        ::close(fd);
        throw;
    }
    // mkstemp makes the file 0600; an image should get the usual permissions.
    ::fchmod(fd, 0644);
    if (::close(fd) != 0) {
        throw ImageIoError(path.string() + ": cannot write image: " + systemError());
    }
    if (::rename(temporary.path.c_str(), path.c_str()) != 0) {
        throw ImageIoError(path.string() + ": cannot write image: " + systemError());
    }
    temporary.keep = true;
}

Rgb8Image readPng(const std::filesystem::path& path) {
    int width = 0;
    int height = 0;
    int channels = 0;
    const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(stbi_load(path.c_str(), &width, &height, &channels, 3),
                                                           stbi_image_free);
    if (!pixels) {
        throw ImageIoError(path.string() + ": cannot read image: " + stbi_failure_reason());
    }
    const std::size_t size = std::size_t(width) * std::size_t(height) * 3;
    return Rgb8Image{std::uint32_t(width), std::uint32_t(height),
                     std::vector<std::uint8_t>(pixels.get(), pixels.get() + size)};
}

}  // namespace hexray
