#include "image/exr_io.h"

#include <algorithm>
#include <cstdlib>
#include <memory>

#include <tinyexr.h>

#include "image/atomic_file.h"
#include "image/image_io.h"

namespace hexray {
namespace {

std::string takeError(const char* error) {
    std::string text = error ? error : "unknown error";
    if (error) {
        FreeEXRErrorMessage(error);
    }
    return text;
}

}  // namespace

void writeExr(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
              std::vector<ExrChannel> channels) {
    // Readers expect the channels sorted by name (OpenEXR stores them so).
    std::sort(channels.begin(), channels.end(), [](const ExrChannel& a, const ExrChannel& b) { return a.name < b.name; });
    const int count = int(channels.size());
    std::vector<EXRChannelInfo> infos(channels.size());
    std::vector<int> pixelTypes(channels.size(), TINYEXR_PIXELTYPE_FLOAT);
    std::vector<unsigned char*> planes;
    for (std::size_t i = 0; i < channels.size(); ++i) {
        if (channels[i].values.size() != std::size_t(width) * height) {
            throw ImageIoError(path.string() + ": channel " + channels[i].name + " has the wrong size");
        }
        std::snprintf(infos[i].name, sizeof infos[i].name, "%s", channels[i].name.c_str());
        planes.push_back(reinterpret_cast<unsigned char*>(channels[i].values.data()));
    }
    EXRHeader header;
    InitEXRHeader(&header);
    header.num_channels = count;
    header.channels = infos.data();
    header.pixel_types = pixelTypes.data();
    header.requested_pixel_types = pixelTypes.data();
    header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;
    EXRImage image;
    InitEXRImage(&image);
    image.num_channels = count;
    image.images = planes.data();
    image.width = int(width);
    image.height = int(height);

    AtomicFile file(path);  // before encoding, so an unwritable path fails first
    unsigned char* memory = nullptr;
    const char* error = nullptr;
    const std::size_t size = SaveEXRImageToMemory(&image, &header, &memory, &error);
    if (size == 0) {
        file.fail("cannot encode OpenEXR", takeError(error));
    }
    const std::unique_ptr<unsigned char, decltype(&std::free)> owned(memory, &std::free);
    if (std::fwrite(memory, 1, size, file.stream()) != size) {
        file.fail("cannot write image", "short write");
    }
    file.commit();
}

ExrImage readExr(const std::filesystem::path& path) {
    const std::string name = path.string();
    EXRVersion version;
    if (ParseEXRVersionFromFile(&version, name.c_str()) != TINYEXR_SUCCESS) {
        throw ImageIoError(name + ": not an OpenEXR file");
    }
    EXRHeader header;
    InitEXRHeader(&header);
    const char* error = nullptr;
    if (ParseEXRHeaderFromFile(&header, &version, name.c_str(), &error) != TINYEXR_SUCCESS) {
        throw ImageIoError(name + ": " + takeError(error));
    }
    for (int i = 0; i < header.num_channels; ++i) {
        header.requested_pixel_types[i] = TINYEXR_PIXELTYPE_FLOAT;
    }
    EXRImage image;
    InitEXRImage(&image);
    if (LoadEXRImageFromFile(&image, &header, name.c_str(), &error) != TINYEXR_SUCCESS) {
        FreeEXRHeader(&header);
        throw ImageIoError(name + ": " + takeError(error));
    }
    ExrImage out{std::uint32_t(image.width), std::uint32_t(image.height), {}};
    const std::size_t pixels = std::size_t(image.width) * image.height;
    for (int i = 0; i < header.num_channels; ++i) {
        const float* values = reinterpret_cast<const float*>(image.images[i]);
        out.channels[header.channels[i].name] = std::vector<float>(values, values + pixels);
    }
    FreeEXRImage(&image);
    FreeEXRHeader(&header);
    return out;
}

}  // namespace hexray
